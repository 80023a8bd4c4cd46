#include "lutbake/api/names.h"

#include "lutbake/formats/format.h"
#include "lutbake/formats/source_formats.h"
#include "lutbake/presets/preset.h"
#include "lutbake/tables/table_definition.h"

namespace lutbake {

std::vector<std::string> TableNames() {
  std::vector<std::string> names;
  for (const TableDefinition *table : AllTables()) names.push_back(table->Name());
  return names;
}

std::vector<std::string> FormatNames() { return BakeFormatNames(); }

std::vector<std::string> PresetNames() {
  std::vector<std::string> names;
  for (const Preset *preset : AllPresets()) names.push_back(preset->name);
  return names;
}

std::vector<std::string> EstimatorNames() {
  std::vector<std::string> names;
  for (Estimator e : kAllEstimators) names.emplace_back(ToString(e));
  return names;
}

std::vector<std::string> ShaderLanguageNames() {
  std::vector<std::string> names;
  for (ShaderLanguage language :
       {ShaderLanguage::kGlsl, ShaderLanguage::kHlsl, ShaderLanguage::kWgsl, ShaderLanguage::kMsl})
    names.emplace_back(ToString(language));
  return names;
}

std::string JoinNames(const std::vector<std::string> &names) {
  std::string s;
  for (size_t i = 0; i < names.size(); ++i) s += (i ? ", " : "") + names[i];
  return s;
}

}  // namespace lutbake
