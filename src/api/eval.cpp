// lutbake::Evaluate: the request's checks in the order the command line
// has always made them (model options, coordinates the table does not take,
// required and out-of-range coordinates, sampling, estimator, the number
// of points), then every point in parallel.
#include "lutbake/api/eval.h"

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "bake_internal.h"
#include "lutbake/api/names.h"
#include "lutbake/core/error.h"
#include "lutbake/tables/bake.h"

namespace lutbake {

namespace {

// The shortest decimal that reads back as v.
std::string ShortestDecimal(double v) {
  char text[40];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(text, sizeof text, "%.*g", digits, v);
    if (std::strtod(text, nullptr) == v) break;
  }
  return text;
}

BakeSettings SettingsOf(const EvalRequest &r) {
  BakeSettings settings;
  ApplyModels(r, &settings);
  return settings;
}

// Options that choose a model the table does not have are refused, so that
// a typo cannot go unnoticed.
void CheckModelOptions(const EvalRequest &r, const TableDefinition &table) {
  const std::vector<std::string> models = table.ModelOptions();
  const std::pair<const char *, bool> given[] = {
      {"ndf", r.ndf.has_value()},
      {"smith", r.smith.has_value()},
      {"fresnel", r.fresnel.has_value()},
      {"sheen-visibility", r.sheenVisibility.has_value()},
      {"sheen-alpha", r.sheenAlpha.has_value()}};
  for (const auto &[option, set] : given)
    if (set && std::find(models.begin(), models.end(), option) == models.end())
      throw UsageError(std::string("--") + option + " does not apply to --table " + table.Name());
}

// The coordinates given that the table does not take with these settings
// are refused rather than ignored.
void CheckCoordinatesApply(const EvalRequest &r, const TableDefinition &table,
                           const std::vector<PointCoordinate> &coordinates,
                           const std::string &variant) {
  const std::string name = table.Name();
  std::string takes;
  for (const PointCoordinate &c : coordinates)
    takes += (takes.empty() ? "--" : " and --") + c.option;
  const std::vector<std::string> variantOptions = table.CoordinateOptions();
  for (const auto &entry : r.coordinates) {
    const std::string &option = entry.first;  // named: lambdas cannot capture bindings in C++17
    if (entry.second.empty()) continue;
    if (std::any_of(coordinates.begin(), coordinates.end(),
                    [&](const PointCoordinate &c) { return c.option == option; }))
      continue;
    if (std::find(variantOptions.begin(), variantOptions.end(), option) != variantOptions.end())
      throw UsageError("--table " + name + variant + " takes " + takes + "; --" + option +
                       " does not apply to it");
    std::string users;
    for (const TableDefinition *other : AllTables()) {
      const std::vector<std::string> options = other->CoordinateOptions();
      if (std::find(options.begin(), options.end(), option) != options.end())
        users += (users.empty() ? "" : ", ") + std::string(other->Name());
    }
    if (users.empty()) {
      std::vector<std::string> accepted;
      for (const EvalCoordinateOption &o : EvalCoordinateOptions()) accepted.push_back(o.option);
      throw UsageError("--" + option +
                       " is not a coordinate of any table; accepted: " + JoinNames(accepted));
    }
    throw UsageError("--" + option + " does not apply to --table " + name +
                     "; it applies only to --table " + users);
  }
}

// Each coordinate's values: given, or 0 for one that is not required.
std::vector<std::vector<double>> CoordinateValues(const EvalRequest &r, const std::string &name,
                                                  const std::vector<PointCoordinate> &coordinates,
                                                  const std::string &variant) {
  std::vector<std::vector<double>> values;
  for (const PointCoordinate &c : coordinates) {
    const auto found = r.coordinates.find(c.option);
    if (found == r.coordinates.end() || found->second.empty()) {
      if (c.required) throw UsageError("--table " + name + variant + " needs --" + c.option);
      values.push_back({0.0});
      continue;
    }
    const std::vector<double> &list = found->second;
    const auto spelled = r.spelling.find(c.option);
    for (size_t i = 0; i < list.size(); ++i) {
      if (c.Accepts(list[i])) continue;
      const bool hasSpelling = spelled != r.spelling.end() && i < spelled->second.size();
      throw UsageError(
          "--" + c.option + ": '" + (hasSpelling ? spelled->second[i] : ShortestDecimal(list[i])) +
          "' is out of range for --table " + name + variant + "; accepted: " + c.accepted);
    }
    values.push_back(list);
  }
  return values;
}

// "exact" for the closed form of the mirror (alpha = 0), else the estimator
// that produced the value (a tolerance run may switch a point to the
// quadrature).
std::string EstimatorUsed(const PointValue &v, const BakeSettings &s) {
  if (v.exact) return "exact";
  return v.quadrature ? "quadrature" : std::string(ToString(s.estimator));
}

// The model options, the one place that spells them: f(option, meaning,
// every value of its enum, the default, the ModelChoice field it sets), in
// the order the command line offers them.
template <typename F>
void ForEachModelOption(F &&f) {
  const BakeSettings unset;
  f("ndf", "Microfacet distribution", kAllNdfKinds, unset.ndf, &ModelChoice::ndf);
  f("smith", "Smith masking-shadowing form", kAllSmithForms, unset.smith, &ModelChoice::smith);
  f("fresnel",
    "Fresnel model: schlick (axis F0 in [0,1]), dielectric (exact, axis eta in [1,3]), "
    "conductor (exact, axes eta in [0,4] x k in [0,10]), f82 (F82 tint, closed form, axes F0 in "
    "[0,1] x tint in [0,1])",
    kAllFresnelModels, unset.fresnel, &ModelChoice::fresnel);
  f("sheen-visibility",
    "Sheen visibility: charlie (Estevez-Kulla's fitted Lambda, as glTF's "
    "KHR_materials_sheen), ashikhmin (1/(4 (mu_i + mu_o - mu_i mu_o))) or ospray",
    kAllSheenVisibilities, unset.sheenVisibility, &ModelChoice::sheenVisibility);
  f("sheen-alpha",
    "The Charlie alpha from the roughness axis r (sheenRoughness): linear alpha = r, squared "
    "alpha = r^2 (Filament's cloth, and the glTF extension's sample code)",
    kAllAlphaMappings, unset.sheenAlpha, &ModelChoice::sheenAlpha);
}

// The names of an enum's values, as ToString spells them.
template <typename Enum, size_t N>
std::vector<std::string> NamesOf(const Enum (&all)[N]) {
  std::vector<std::string> names;
  for (Enum value : all) names.emplace_back(ToString(value));
  return names;
}

}  // namespace

std::vector<ModelOption> ModelOptions() {
  std::vector<ModelOption> options;
  ForEachModelOption([&options](const char *option, const char *meaning, const auto &all,
                                auto unset, auto /*field*/) {
    options.push_back({option, meaning, NamesOf(all), std::string(ToString(unset)), {}});
    for (const TableDefinition *table : AllTables()) {
      const std::vector<std::string> models = table->ModelOptions();
      if (std::find(models.begin(), models.end(), option) != models.end())
        options.back().tables.push_back(table->Name());
    }
  });
  return options;
}

ModelChoice ModelsNamed(const std::map<std::string, std::string> &values) {
  std::vector<std::string> options;
  ForEachModelOption([&options](const char *option, auto &&...) { options.push_back(option); });
  for (const auto &entry : values)
    if (std::find(options.begin(), options.end(), entry.first) == options.end())
      throw UsageError("--" + entry.first +
                       " is not a model option; accepted: " + JoinNames(options));
  ModelChoice choice;
  ForEachModelOption([&](const char *option, const char *, const auto &all, auto, auto field) {
    const auto given = values.find(option);
    if (given == values.end()) return;
    for (const auto value : all)
      if (ToString(value) == given->second) {
        choice.*field = value;
        return;
      }
    throw UsageError("--" + given->first + ": '" + given->second +
                     "' is not accepted; accepted: " + JoinNames(NamesOf(all)));
  });
  return choice;
}

std::vector<EvalCoordinateOption> EvalCoordinateOptions() {
  std::vector<EvalCoordinateOption> options;
  std::vector<std::vector<PointCoordinate>> seen;  // per option, as the tables give it
  for (const TableDefinition *table : AllTables())
    for (FresnelModel model : kAllFresnelModels) {
      BakeSettings settings;
      settings.fresnel = model;
      for (const PointCoordinate &c : table->Coordinates(settings)) {
        size_t i = 0;
        while (i < options.size() && options[i].option != c.option) ++i;
        if (i == options.size()) {
          options.push_back({c.option, c.meaning, {}, c.min, c.max, c.zeroAllowed, ""});
          seen.emplace_back();
        }
        EvalCoordinateOption &o = options[i];
        if (std::find(o.tables.begin(), o.tables.end(), table->Name()) == o.tables.end())
          o.tables.push_back(table->Name());
        o.min = std::min(o.min, c.min);
        o.max = std::max(o.max, c.max);
        o.zeroAllowed = o.zeroAllowed || c.zeroAllowed;
        seen[i].push_back(c);
      }
    }
  // The words of the range: those of a table whose range is the widest
  // (without its table-specific remark in parentheses), else the numbers.
  for (size_t i = 0; i < options.size(); ++i) {
    EvalCoordinateOption &o = options[i];
    for (const PointCoordinate &c : seen[i])
      if (o.accepted.empty() && c.min <= o.min && c.max >= o.max &&
          (!o.zeroAllowed || c.Accepts(0.0)))
        o.accepted = c.accepted.substr(0, c.accepted.find(" ("));
    if (o.accepted.empty())
      o.accepted = "comma-separated numbers from " + ShortestDecimal(o.min) + " to " +
                   ShortestDecimal(o.max);
  }
  return options;
}

EvalResult Evaluate(const EvalRequest &r) {
  const TableDefinition *found = FindTable(r.table);
  if (!found)
    throw UsageError("--table '" + r.table +
                     "' is not accepted; accepted: " + JoinNames(TableNames()));
  const TableDefinition &table = *found;
  const std::string name = table.Name();
  BakeSettings settings = SettingsOf(r);
  CheckModelOptions(r, table);

  EvalResult result;
  result.table = name;
  result.labels = table.PointLabels(settings);
  std::string variant;  // " --fresnel schlick"
  for (const auto &[option, value] : result.labels) variant += " --" + option + " " + value;
  const std::vector<PointCoordinate> coordinates = table.Coordinates(settings);
  for (const PointCoordinate &c : coordinates) result.coordinateNames.push_back(c.option);
  CheckCoordinatesApply(r, table, coordinates, variant);
  const std::vector<std::vector<double>> values = CoordinateValues(r, name, coordinates, variant);
  ApplySampling(r.sampling, &settings);
  if (const std::string problem = table.EstimatorProblem(settings.estimator); !problem.empty())
    throw UsageError("--estimator " + std::string(ToString(settings.estimator)) + ": " + problem);

  // Row-major, as a table stores them: z outer, then y, x inner.
  const std::vector<double> &xs = values[0];
  const std::vector<double> ys = values.size() > 1 ? values[1] : std::vector<double>{0.0};
  const std::vector<double> zs = values.size() > 2 ? values[2] : std::vector<double>{0.0};
  const double count = static_cast<double>(xs.size()) * ys.size() * zs.size();
  if (count > kMaxEvalPoints) {
    std::string options;
    for (const PointCoordinate &c : coordinates)
      options += (options.empty() ? "--" : " x --") + c.option;
    throw UsageError(FormatDouble(count) + " points (" + options + "); accepted: at most " +
                     std::to_string(kMaxEvalPoints));
  }
  std::vector<std::array<double, 3>> at;
  for (double z : zs)
    for (double y : ys)
      for (double x : xs) at.push_back({x, y, z});
  const bool threeD = coordinates.size() > 2;
  std::vector<PointValue> pointValues(at.size());
  std::vector<std::vector<std::pair<std::string, double>>> fitErrors(at.size());
  tbb::global_control parallelism(tbb::global_control::max_allowed_parallelism,
                                  static_cast<size_t>(ThreadCount(r.threads)));
  try {
    tbb::parallel_for(size_t{0}, at.size(), [&](size_t i) {
      const auto &[x, y, z] = at[i];
      pointValues[i] =
          threeD ? table.Evaluate3D(settings, x, y, z) : table.Evaluate(settings, x, y);
      if (!threeD) fitErrors[i] = table.PointFitErrors(settings, x, y, pointValues[i]);
    });
  } catch (const std::domain_error &e) {
    throw UsageError(std::string(e.what()) + " (--table " + name + ")");
  }

  result.channelMeanings = table.ChannelMeanings();
  result.method = DescribeEstimator(table, settings);
  if (IsQuadrature(settings.estimator) || !table.Sampled())
    if (const std::string bound = table.QuadratureBound(settings); !bound.empty())
      result.method += "; error: " + bound;
  const int channels = table.Channels();
  for (size_t i = 0; i < at.size(); ++i) {
    const PointValue &v = pointValues[i];
    EvalPoint p;
    p.coordinates.assign(at[i].begin(), at[i].begin() + coordinates.size());
    p.values.assign(v.value, v.value + channels);
    p.errors.assign(v.error, v.error + channels);
    p.estimator = EstimatorUsed(v, settings);
    p.samples = v.samples;
    p.fitErrors = std::move(fitErrors[i]);
    result.points.push_back(std::move(p));
  }
  return result;
}

std::string EvalResult::TextLine(size_t i) const {
  const EvalPoint &p = points[i];
  char text[512];
  int n = std::snprintf(text, sizeof text, "%-3s ", table.c_str());
  for (const auto &[option, value] : labels)
    n += std::snprintf(text + n, sizeof text - n, "%s ", value.c_str());
  for (size_t c = 0; c < p.coordinates.size(); ++c)
    n += std::snprintf(text + n, sizeof text - n, "%s %-10.6g ", coordinateNames[c].c_str(),
                       p.coordinates[c]);
  for (size_t c = 0; c < p.values.size(); ++c)
    n += std::snprintf(text + n, sizeof text - n, "%s %.17g  ", channelMeanings[c].c_str(),
                       p.values[c]);
  n += std::snprintf(text + n, sizeof text - n, "error");
  for (double error : p.errors) n += std::snprintf(text + n, sizeof text - n, " %.2g", error);
  std::string
      fit;  // a fitted table's errors (ltc_ggx: lobeError, ...), as std::ostream prints them
  for (const auto &[key, value] : p.fitErrors) {
    char number[32];
    std::snprintf(number, sizeof number, "%g", value);
    fit += ", " + key + " " + number;
  }
  return std::string(text) + "  (" + p.estimator +
         (p.samples ? ", " + std::to_string(p.samples) + " samples" : std::string()) + fit + ")\n";
}

std::string EvalResult::JsonLine(size_t i) const {
  const EvalPoint &p = points[i];
  nlohmann::ordered_json line;
  line["table"] = table;
  for (const auto &[option, value] : labels) line[option] = value;
  for (size_t c = 0; c < coordinateNames.size(); ++c) line[coordinateNames[c]] = p.coordinates[c];
  if (p.values.size() >= 2) {
    line["value"] = p.values;
    line["error"] = p.errors;
  } else {
    line["value"] = p.values[0];
    line["error"] = p.errors[0];
  }
  for (const auto &[key, value] : p.fitErrors) line[key] = value;
  line["estimator"] = p.estimator;
  line["samples"] = p.samples;
  return line.dump();
}

}  // namespace lutbake
