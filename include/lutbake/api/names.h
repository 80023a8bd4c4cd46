// The closed lists a request's names come from, in the order the command
// line offers them: tables, formats, presets, estimators, shader languages.
// Each comes from its registry (table_definition.h, format.h, preset.h);
// nothing here spells a name.
#pragma once

#include <string>
#include <vector>

namespace lutbake {

std::vector<std::string> TableNames();
std::vector<std::string> FormatNames();  // those bake --format accepts
std::vector<std::string> PresetNames();
std::vector<std::string> EstimatorNames();
std::vector<std::string> ShaderLanguageNames();

// "a, b, c".
std::string JoinNames(const std::vector<std::string> &names);

}  // namespace lutbake
