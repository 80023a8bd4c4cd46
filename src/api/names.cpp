#include "lutbake/api/names.h"

#include <algorithm>
#include <cctype>

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

namespace {

std::string Lower(std::string s) {
  for (char &c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Optimal string alignment distance: the fewest insertions, deletions,
// substitutions and swaps of two adjacent characters that turn `a` into `b`
// ("vdnf" is one swap from "vndf"), without editing a character twice.
size_t EditDistance(const std::string &a, const std::string &b) {
  // d[i][j]: the distance between a's first i characters and b's first j.
  std::vector<std::vector<size_t>> d(a.size() + 1, std::vector<size_t>(b.size() + 1));
  for (size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (size_t i = 1; i <= a.size(); ++i)
    for (size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min(
          {d[i - 1][j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1), d[i - 1][j] + 1, d[i][j - 1] + 1});
      if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1])
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

}  // namespace

std::vector<std::string> Suggest(const std::string &name,
                                 const std::vector<std::string> &candidates) {
  constexpr size_t kMaxSuggestions = 4;
  const std::string typed = Lower(name);
  std::vector<std::string> sameIgnoringCase;
  for (const std::string &candidate : candidates)
    if (Lower(candidate) == typed) sameIgnoringCase.push_back(candidate);
  if (!sameIgnoringCase.empty()) return sameIgnoringCase;
  // (edits, position in candidates) of each near candidate.
  std::vector<std::pair<size_t, size_t>> near;
  for (size_t i = 0; i < candidates.size(); ++i) {
    const std::string candidate = Lower(candidates[i]);
    const size_t edits = EditDistance(typed, candidate);
    const size_t allowed = typed.size() >= 6 ? 2 : 1;
    const bool close = edits <= allowed && edits < typed.size();
    const bool prefix = typed.size() >= 2 && candidate.compare(0, typed.size(), typed) == 0;
    if (close || prefix) near.emplace_back(edits, i);
  }
  std::sort(near.begin(), near.end());
  std::vector<std::string> names;
  for (size_t i = 0; i < near.size() && i < kMaxSuggestions; ++i)
    names.push_back(candidates[near[i].second]);
  return names;
}

std::string DidYouMean(const std::string &name, const std::vector<std::string> &candidates) {
  const std::vector<std::string> names = Suggest(name, candidates);
  if (names.empty()) return "";
  std::string text = "; did you mean " + names[0];
  for (size_t i = 1; i < names.size(); ++i)
    text += (i + 1 == names.size() ? " or " : ", ") + names[i];
  return text + "?";
}

}  // namespace lutbake
