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

// The names of `candidates` that `name` was probably meant to be, best
// first, at most four: those equal to it ignoring case (only these, when
// there are any); else, ignoring case, those a few edits away (Damerau
// distance: one edit for a name of up to five characters, two from six on,
// and always fewer than it has characters) and those it begins (when it has
// two characters or more: "png" for png8, png16), the fewest edits first,
// then in the order of `candidates`.
std::vector<std::string> Suggest(const std::string &name,
                                 const std::vector<std::string> &candidates);

// "; did you mean a?" or "; did you mean a or b?" ("a, b or c"), or "" when
// Suggest finds nothing: the tail of a message refusing `name`.
std::string DidYouMean(const std::string &name, const std::vector<std::string> &candidates);

}  // namespace lutbake
