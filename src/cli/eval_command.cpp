#include "eval_command.h"

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "bake_command.h"
#include "cli_util.h"

namespace lutbake::cli {

namespace {

// More points than this in one call is a typo, not a request (each costs
// about a millisecond with the default quadrature).
constexpr size_t kMaxPoints = 1000000;

struct RealRange {
  double lo, hi;
  std::string accepted;
  bool allowZero = false;  // 0 accepted besides [lo, hi]
};

// A comma-separated list of reals, each finite and in range.
CLI::Validator RealList(const RealRange &range) {
  return CLI::Validator(
      [range](std::string &value) -> std::string {
        const std::vector<std::string> items = SplitList(value);
        if (items.empty()) return "empty list; accepted: " + range.accepted;
        if (items.size() > kMaxPoints)
          return std::to_string(items.size()) + " values; accepted: at most " +
                 std::to_string(kMaxPoints);
        for (const std::string &item : items) {
          char *end = nullptr;
          errno = 0;
          const double v = std::strtod(item.c_str(), &end);
          if (item.empty() || end != item.c_str() + item.size() || std::isnan(v))
            return "'" + item + "' is not a number; accepted: " + range.accepted;
          // ERANGE: beyond the doubles (1e400) or below them (1e-400, which
          // strtod rounds to 0 but is not the 0 the user could have typed).
          if (errno == ERANGE ||
              !((v >= range.lo && v <= range.hi) || (range.allowZero && v == 0.0)))
            return "'" + item + "' is out of range; accepted: " + range.accepted;
        }
        return {};
      },
      range.accepted);
}

std::vector<double> Reals(const std::string &list) {
  std::vector<double> values;
  for (const std::string &item : SplitList(list))
    values.push_back(std::strtod(item.c_str(), nullptr));
  return values;
}

// One point of the evaluation: its coordinates as the user gave them.
struct Point {
  double x = 0, y = 0, z = 0;  // the table's axis values: (mu, r) for E, (r, 0) for Eavg,
                               // (mu, r, eta) for a 3D table
  PointValue result;
};

// "exact" for the closed form of the mirror (alpha = 0), else the
// estimator that produced the value (a tolerance run may switch a point to
// the quadrature).
std::string EstimatorUsed(const PointValue &v, const BakeSettings &s) {
  if (v.exact) return "exact";
  return v.quadrature ? "quadrature" : std::string(ToString(s.estimator));
}

}  // namespace

void SetupEvalCommand(CLI::App &app, EvalOptions &o) {
  app.add_option("--table", o.table, "The table to evaluate")
      ->required()
      ->check(OneOf(TableNames()));
  // Each option's widest range here; each table narrows it (its
  // PointCoordinate), and says so.
  app.add_option("--mu", o.mu, "E, dfg: view cosines, comma-separated (0 = the grazing limit)")
      ->type_name("LIST")
      ->check(RealList({0.0, 1.0, "comma-separated numbers in [0, 1]"}));
  app.add_option("--roughness", o.perceptualRoughness,
                 "E, Eavg, dfg: perceptual roughness r (alpha = r^2), comma-separated; 0 is the "
                 "mirror, exact")
      ->type_name("LIST")
      ->check(RealList({0.0, 1.0, "comma-separated numbers in [0, 1]"}));
  app.add_option("--sigma", o.sigma,
                 "oren_nayar_E, oren_nayar_full_E: the facet slope angle's standard deviation, "
                 "radians, comma-separated")
      ->type_name("LIST")
      ->check(RealList({0.0, 0.5 * kPi, "comma-separated numbers in [0, pi/2]"}));
  app.add_option("--fresnel", o.fresnel, "Favg: the Fresnel model")
      ->capture_default_str()
      ->check(OneOf({"schlick", "dielectric", "conductor", "f82"}));
  app.add_option("--f0", o.f0,
                 "Favg with --fresnel schlick or f82: reflectance at normal incidence")
      ->type_name("LIST")
      ->check(RealList({0.0, 1.0, "comma-separated numbers in [0, 1]"}));
  app.add_option("--tint", o.tint,
                 "Favg with --fresnel f82: the F82 tint (F at mu = 1/7 over Schlick's there)")
      ->type_name("LIST")
      ->check(RealList({0.0, 1.0, "comma-separated numbers in [0, 1]"}));
  app.add_option("--eta", o.eta,
                 "Favg with --fresnel dielectric or conductor: relative index of refraction "
                 "(dielectric eta < 1: light inside the denser medium, total internal reflection)")
      ->type_name("LIST")
      ->check(RealList({1e-3, 1e3, "comma-separated numbers from 1e-3 to 1000"}));
  app.add_option("--k", o.k, "Favg with --fresnel conductor: extinction coefficient (default 0)")
      ->type_name("LIST")
      ->check(RealList({0.0, 1e3, "comma-separated numbers from 0 to 1000"}));
  AddModelOptions(app, o.ndf, o.smith);
  AddSheenOptions(app, o.sheenVisibility, o.sheenAlpha);
  AddSamplingOptions(app, o.sampling, "point");
  AddThreadsOption(app, o.threads);
  app.add_flag("--json", o.json,
               "One JSON object per point and line: table, the coordinates, value, error "
               "(value and error are [A, B] for dfg), estimator, samples");
  app.footer(
      "Without --samples, --tolerance or --estimator the points are integrated by the\n"
      "quadrature (error ~1e-10). --samples N (or --estimator vndf) evaluates them as a bake\n"
      "does: at a texel centre, with the bake's settings and seed, the value is that texel's.\n"
      "Examples:\n"
      "  lutbake eval --table E --mu 1e-7,0.5 --roughness 0,1e-4,0.3\n"
      "  lutbake eval --table dfg --mu 0 --roughness 0.5 --samples 65536 --json\n"
      "  lutbake eval --table Favg --fresnel conductor --eta 0.2 --k 3,10\n"
      "  lutbake eval --table Favg --fresnel f82 --f0 0.9 --tint 0.8\n"
      "  lutbake eval --table f82 --mu 0.5 --roughness 0.3");
}

int RunEval(const EvalOptions &o, CLI::App &app) {
  const TableDefinition &table = TableNamed(o.table);
  const std::string name = table.Name();
  const auto complain = [](const std::string &message) {
    std::cerr << "lutbake eval: " << message << "\n";
    return 2;
  };

  BakeSettings settings;
  settings.ndf = ParseNdf(o.ndf);
  settings.smith = ParseSmith(o.smith);
  settings.fresnel = ParseFresnel(o.fresnel);
  ParseSheenVisibility(o.sheenVisibility, &settings.sheenVisibility);
  ParseSheenAlpha(o.sheenAlpha, &settings.sheenAlpha);

  // Options that choose a model the table does not have are refused, so
  // that a typo cannot go unnoticed.
  const std::vector<std::string> models = table.ModelOptions();
  for (const char *option : {"ndf", "smith", "fresnel", "sheen-visibility", "sheen-alpha"})
    if (app.count(std::string("--") + option) > 0 &&
        std::find(models.begin(), models.end(), option) == models.end())
      return complain(std::string("--") + option + " does not apply to --table " + name);

  // The point options: which the table takes with these settings; the
  // others are refused rather than ignored.
  const std::map<std::string, const std::string *> given = {
      {"mu", &o.mu},      {"roughness", &o.perceptualRoughness},
      {"f0", &o.f0},      {"eta", &o.eta},
      {"k", &o.k},        {"tint", &o.tint},
      {"sigma", &o.sigma}};
  const std::vector<PointCoordinate> coordinates = table.Coordinates(settings);
  const Metadata labels = table.PointLabels(settings);
  std::string variant;  // " --fresnel schlick"
  for (const auto &[option, value] : labels) variant += " --" + option + " " + value;
  std::string takes;
  for (const PointCoordinate &c : coordinates)
    takes += (takes.empty() ? "--" : " and --") + c.option;
  const std::vector<std::string> variantOptions = table.CoordinateOptions();
  for (const auto &entry : given) {
    const std::string &option = entry.first;  // named: lambdas cannot capture bindings in C++17
    if (entry.second->empty()) continue;
    const bool applies = std::any_of(coordinates.begin(), coordinates.end(),
                                     [&](const PointCoordinate &c) { return c.option == option; });
    if (applies) continue;
    if (std::find(variantOptions.begin(), variantOptions.end(), option) != variantOptions.end())
      return complain("--table " + name + variant + " takes " + takes + "; --" + option +
                      " does not apply to it");
    std::string users;
    for (const TableDefinition *other : AllTables()) {
      const std::vector<std::string> options = other->CoordinateOptions();
      if (std::find(options.begin(), options.end(), option) != options.end())
        users += (users.empty() ? "" : ", ") + std::string(other->Name());
    }
    return complain("--" + option + " does not apply to --table " + name +
                    "; it applies only to --table " + users);
  }
  std::vector<std::vector<double>> values;  // per coordinate
  for (const PointCoordinate &c : coordinates) {
    const std::string &list = *given.at(c.option);
    if (list.empty()) {
      if (c.required) return complain("--table " + name + variant + " needs --" + c.option);
      values.push_back({0.0});
      continue;
    }
    for (const std::string &item : SplitList(list))
      if (!c.Accepts(std::strtod(item.c_str(), nullptr)))
        return complain("--" + c.option + ": '" + item + "' is out of range for --table " + name +
                        variant + "; accepted: " + c.accepted);
    values.push_back(Reals(list));
  }
  if (const int status = ApplySamplingOptions("eval", o.sampling, &settings)) return status;
  if (const std::string problem = table.EstimatorProblem(settings.estimator); !problem.empty())
    return complain("--estimator " + std::string(ToString(settings.estimator)) + ": " + problem);

  // Row-major, as a table stores them: z outer, then y, x inner.
  const std::vector<double> &xs = values[0];
  const std::vector<double> ys = values.size() > 1 ? values[1] : std::vector<double>{0.0};
  const std::vector<double> zs = values.size() > 2 ? values[2] : std::vector<double>{0.0};
  const double count = static_cast<double>(xs.size()) * ys.size() * zs.size();
  if (count > kMaxPoints) {
    std::string options;
    for (const PointCoordinate &c : coordinates)
      options += (options.empty() ? "--" : " x --") + c.option;
    return complain(FormatDouble(count) + " points (" + options + "); accepted: at most " +
                    std::to_string(kMaxPoints));
  }
  std::vector<Point> points;
  for (double z : zs)
    for (double y : ys)
      for (double x : xs) points.push_back({x, y, z, {}});
  const bool threeD = coordinates.size() > 2;

  tbb::global_control parallelism(tbb::global_control::max_allowed_parallelism,
                                  static_cast<size_t>(ThreadCount(o.threads)));
  try {
    tbb::parallel_for(size_t{0}, points.size(), [&](size_t i) {
      const Point &p = points[i];
      points[i].result =
          threeD ? table.Evaluate3D(settings, p.x, p.y, p.z) : table.Evaluate(settings, p.x, p.y);
    });
  } catch (const std::domain_error &e) {
    return complain(std::string(e.what()) + " (--table " + name + ")");
  }

  const std::vector<std::string> meanings = table.ChannelMeanings();
  const int channels = table.Channels();
  for (const Point &p : points) {
    const double coordinate[3] = {p.x, p.y, p.z};
    if (o.json) {
      nlohmann::ordered_json line;
      line["table"] = o.table;
      for (const auto &[option, value] : labels) line[option] = value;
      for (size_t c = 0; c < coordinates.size(); ++c) line[coordinates[c].option] = coordinate[c];
      if (channels == 2) {
        line["value"] = {p.result.value[0], p.result.value[1]};
        line["error"] = {p.result.error[0], p.result.error[1]};
      } else {
        line["value"] = p.result.value[0];
        line["error"] = p.result.error[0];
      }
      line["estimator"] = EstimatorUsed(p.result, settings);
      line["samples"] = p.result.samples;
      std::cout << line.dump() << "\n";
      continue;
    }
    // "E   mu 0.5        roughness 0.3        E 0.97...  error 1e-10"
    char text[512];
    int n = std::snprintf(text, sizeof text, "%-3s ", name.c_str());
    for (const auto &[option, value] : labels)
      n += std::snprintf(text + n, sizeof text - n, "%s ", value.c_str());
    for (size_t c = 0; c < coordinates.size(); ++c)
      n += std::snprintf(text + n, sizeof text - n, "%s %-10.6g ", coordinates[c].option.c_str(),
                         coordinate[c]);
    for (int c = 0; c < channels; ++c)
      n += std::snprintf(text + n, sizeof text - n, "%s %.17g  ", meanings[c].c_str(),
                         p.result.value[c]);
    n += std::snprintf(text + n, sizeof text - n, "error");
    for (int c = 0; c < channels; ++c)
      n += std::snprintf(text + n, sizeof text - n, " %.2g", p.result.error[c]);
    std::cout << text << "  (" << EstimatorUsed(p.result, settings);
    if (p.result.samples) std::cout << ", " << p.result.samples << " samples";
    std::cout << ")\n";
  }
  return 0;
}

}  // namespace lutbake::cli
