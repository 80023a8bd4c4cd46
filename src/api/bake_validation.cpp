// The options of a bake request that do not apply to what it asks for: an
// option set for no table or file of the request is refused (UsageError,
// naming the option, what it applies to and what was asked), never ignored.
#include <algorithm>
#include <set>

#include "bake_internal.h"
#include "lutbake/api/names.h"
#include "lutbake/core/error.h"
#include "lutbake/formats/format.h"
#include "lutbake/tables/bake.h"
#include "lutbake/tables/table_definition.h"

namespace lutbake {

namespace {

// The tables whose definitions satisfy `uses`, as "A, B".
template <typename Uses>
std::string TablesThat(Uses uses) {
  std::vector<std::string> names;
  for (const TableDefinition *table : AllTables())
    if (uses(*table)) names.push_back(table->Name());
  return JoinNames(names);
}

void RequireTableUsing(const std::vector<const TableDefinition *> &asked, const std::string &asText,
                       const std::string &option, const std::string &what,
                       bool (*uses)(const TableDefinition &, const std::string &)) {
  for (const TableDefinition *table : asked)
    if (uses(*table, what)) return;
  throw UsageError("--" + option + " does not apply to --tables " + asText + "; it applies to " +
                   TablesThat([&](const TableDefinition &t) { return uses(t, what); }));
}

bool HasModelOption(const TableDefinition &table, const std::string &option) {
  const std::vector<std::string> options = table.ModelOptions();
  return std::find(options.begin(), options.end(), option) != options.end();
}
// Whether --eta-size changes the table's texels (the 3D tables' z axis, the
// averages' eta axis): its default axes at two eta sizes.
bool HasEtaAxis(const TableDefinition &table, const std::string &) {
  size_t texels[2];
  for (int k = 0; k < 2; ++k) {
    BakeSettings settings;
    settings.size = 2;
    settings.depthSize = 2 + k;
    Axis x, y, z;
    DefaultAxes(table, settings, &x, &y, &z);
    texels[k] = static_cast<size_t>(x.count) * y.count * z.count;
  }
  return texels[0] != texels[1];
}
bool IsSampled(const TableDefinition &table, const std::string &) { return table.Sampled(); }

void RequireFormat(const BakeRequest &r, const std::string &option, const std::string &format) {
  const std::vector<std::string> formats = r.formats.value_or(DefaultFormats());
  if (std::find(formats.begin(), formats.end(), format) == formats.end())
    throw UsageError("--" + option + " applies to the " + format + " format; --format " +
                     JoinList(formats) + " writes none");
}

// C++'s keywords, which no namespace may be called.
bool IsCppKeyword(const std::string &word) {
  static const std::set<std::string> keywords = {"alignas",       "alignof",     "and",
                                                 "and_eq",        "asm",         "auto",
                                                 "bitand",        "bitor",       "bool",
                                                 "break",         "case",        "catch",
                                                 "char",          "char8_t",     "char16_t",
                                                 "char32_t",      "class",       "compl",
                                                 "concept",       "const",       "consteval",
                                                 "constexpr",     "constinit",   "const_cast",
                                                 "continue",      "co_await",    "co_return",
                                                 "co_yield",      "decltype",    "default",
                                                 "delete",        "do",          "double",
                                                 "dynamic_cast",  "else",        "enum",
                                                 "explicit",      "export",      "extern",
                                                 "false",         "float",       "for",
                                                 "friend",        "goto",        "if",
                                                 "inline",        "int",         "long",
                                                 "mutable",       "namespace",   "new",
                                                 "noexcept",      "not",         "not_eq",
                                                 "nullptr",       "operator",    "or",
                                                 "or_eq",         "private",     "protected",
                                                 "public",        "register",    "reinterpret_cast",
                                                 "requires",      "return",      "short",
                                                 "signed",        "sizeof",      "static",
                                                 "static_assert", "static_cast", "struct",
                                                 "switch",        "template",    "this",
                                                 "thread_local",  "throw",       "true",
                                                 "try",           "typedef",     "typeid",
                                                 "typename",      "union",       "unsigned",
                                                 "using",         "virtual",     "void",
                                                 "volatile",      "wchar_t",     "while",
                                                 "xor",           "xor_eq"};
  return keywords.count(word) > 0;
}

}  // namespace

std::string NamespaceProblem(const std::string &name) {
  // Identifiers separated by "::", none of them a keyword.
  bool ok = !name.empty(), start = true;
  for (size_t i = 0; ok && i < name.size(); ++i) {
    const char c = name[i];
    if (c == ':' && i + 1 < name.size() && name[i + 1] == ':' && !start) {
      ++i;
      start = true;
      continue;
    }
    const bool alpha = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
    ok = alpha || (c >= '0' && c <= '9' && !start);
    start = false;
  }
  if (!ok || start) return "'" + name + "' is not a C++ namespace name (e.g. my_engine::luts)";
  size_t begin = 0;
  while (true) {
    const size_t end = name.find("::", begin);
    const std::string part = name.substr(begin, end == std::string::npos ? end : end - begin);
    if (IsCppKeyword(part))
      return "'" + name + "': " + part +
             " is a C++ keyword; accepted: a C++ namespace name (e.g. "
             "my_engine::luts)";
    if (end == std::string::npos) return "";
    begin = end + 2;
  }
}

void ValidateApplicability(const BakeRequest &r) {
  if (r.headerNamespace) {
    if (const std::string problem = NamespaceProblem(*r.headerNamespace); !problem.empty())
      throw UsageError("--namespace " + problem);
    RequireFormat(r, "namespace", "header");
  }
  if (r.headerType) RequireFormat(r, "header-type", "header");
  if (r.binType) RequireFormat(r, "bin-type", "bin");
  const std::vector<std::string> formats = r.formats.value_or(DefaultFormats());
  const auto fitted = std::find_if(formats.begin(), formats.end(), [](const std::string &name) {
    const TableFormat *f = FindFormat(name);
    return f && f->fittedForm;
  });
  if (r.fitTolerance && fitted == formats.end())
    throw UsageError(
        "--fit-tolerance applies to the fit formats (fit, fit-glsl, fit-hlsl, "
        "fit-wgsl, fit-msl); --format " +
        JoinList(formats) + " writes none");
  // With a plan the plan picks the tables (and refuses the model options).
  if (!r.scenes.empty() || !r.manifests.empty()) return;
  const std::vector<std::string> names =
      r.tables.value_or(std::vector<std::string>{"E", "Eavg", "Favg", "dfg"});
  std::vector<const TableDefinition *> asked;
  for (const std::string &name : names) asked.push_back(&TableNamed(name));
  const std::string asText = JoinList(names);
  const std::pair<const char *, bool> models[] = {
      {"ndf", r.ndf.has_value()},
      {"smith", r.smith.has_value()},
      {"fresnel", r.fresnel.has_value()},
      {"sheen-visibility", r.sheenVisibility.has_value()},
      {"sheen-alpha", r.sheenAlpha.has_value()}};
  for (const auto &[option, given] : models)
    if (given) RequireTableUsing(asked, asText, option, option, HasModelOption);
  if (r.etaSize > 0) RequireTableUsing(asked, asText, "eta-size", "", HasEtaAxis);
  const SamplingRequest &s = r.sampling;
  const std::pair<const char *, bool> sampling[] = {{"estimator", s.estimator.has_value()},
                                                    {"samples", s.samples > 0},
                                                    {"replicates", s.replicates > 0},
                                                    {"tolerance", s.tolerance > 0.0},
                                                    {"sampling-only", s.samplingOnly},
                                                    {"max-samples", s.maxSamples.has_value()},
                                                    {"seed", s.seed.has_value()}};
  for (const auto &[option, given] : sampling)
    if (given) RequireTableUsing(asked, asText, option, "", IsSampled);
  // A fitted closed form is made of a 1D or 2D integrated table only.
  if (fitted != formats.end())
    for (const TableDefinition *table : asked) {
      const size_t dims = table->Coordinates(BakeSettings{}).size();
      if (dims > 2 || table->FittedChannels() > 0)
        throw UsageError("--format " + *fitted + " fits a closed form to a 1D or 2D integrated " +
                         "table; " + table->Name() + " is " +
                         (dims > 2 ? std::to_string(dims) + "D" : "itself a fit") +
                         ": use exr, bin or header for it");
    }
  // A table of more than two channels (ltc_ggx) goes only into the formats
  // that hold them; its shader lookups read it as textures of four channels
  // each (shader_code.cpp).
  for (const TableDefinition *table : asked) {
    std::vector<std::string> holding;
    for (const TableFormat &f : AllFormats())
      if (f.bakeFormat && f.maxChannels >= table->Channels()) holding.push_back(f.name);
    for (const std::string &name : r.formats.value_or(DefaultFormats()))
      if (const TableFormat *f = FindFormat(name); f && f->maxChannels < table->Channels())
        throw UsageError("--format " + name + " holds at most " + std::to_string(f->maxChannels) +
                         " channels; " + table->Name() + " has " +
                         std::to_string(table->Channels()) + ": use " + JoinList(holding));
  }
}

}  // namespace lutbake
