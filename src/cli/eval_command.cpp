#include "eval_command.h"

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <cstdio>
#include <iostream>
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
  double x = 0, y = 0;  // (mu, r) for E and dfg; (r, 0) for Eavg; (F0 or eta, k) for Favg
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
      ->check(OneOf({"E", "Eavg", "Favg", "dfg"}));
  app.add_option("--mu", o.mu, "E, dfg: view cosines, comma-separated (0 = the grazing limit)")
      ->type_name("LIST")
      ->check(RealList({0.0, 1.0, "comma-separated numbers in [0, 1]"}));
  app.add_option("--roughness", o.perceptualRoughness,
                 "E, Eavg, dfg: perceptual roughness r (alpha = r^2), comma-separated; 0 is the "
                 "mirror, exact")
      ->type_name("LIST")
      ->check(RealList({std::sqrt(kMinimumAlpha), 1.0,
                        "comma-separated numbers: 0 (a mirror) or 1e-12 to 1", true}));
  app.add_option("--fresnel", o.fresnel, "Favg: the Fresnel model")
      ->capture_default_str()
      ->check(OneOf({"schlick", "dielectric", "conductor"}));
  app.add_option("--f0", o.f0, "Favg with --fresnel schlick: reflectance at normal incidence")
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
      "  lutbake eval --table Favg --fresnel conductor --eta 0.2 --k 3,10");
}

int RunEval(const EvalOptions &o) {
  const TableKind kind = ParseTable(o.table);
  const bool albedo = kind == TableKind::kE || kind == TableKind::kDfg;
  const auto complain = [](const std::string &message) {
    std::cerr << "lutbake eval: " << message << "\n";
    return 2;
  };
  // Which point options the table takes; the others are refused rather
  // than ignored, so that a typo cannot go unnoticed.
  const FresnelModel fresnel = ParseFresnel(o.fresnel);
  if (albedo && o.mu.empty()) return complain("--table " + o.table + " needs --mu");
  if (!albedo && !o.mu.empty()) return complain("--mu does not apply to --table " + o.table);
  if (kind != TableKind::kFavg && o.perceptualRoughness.empty())
    return complain("--table " + o.table + " needs --roughness");
  if (kind == TableKind::kFavg && !o.perceptualRoughness.empty())
    return complain("--roughness does not apply to --table Favg");
  if (kind != TableKind::kFavg && (!o.f0.empty() || !o.eta.empty() || !o.k.empty()))
    return complain("--f0, --eta and --k apply only to --table Favg");
  if (kind == TableKind::kFavg) {
    if (fresnel == FresnelModel::kSchlick && (o.f0.empty() || !o.eta.empty() || !o.k.empty()))
      return complain("--table Favg --fresnel schlick takes --f0 (and not --eta or --k)");
    if (fresnel == FresnelModel::kDielectric && (o.eta.empty() || !o.f0.empty() || !o.k.empty()))
      return complain("--table Favg --fresnel dielectric takes --eta (and not --f0 or --k)");
    if (fresnel == FresnelModel::kConductor && (o.eta.empty() || !o.f0.empty()))
      return complain("--table Favg --fresnel conductor takes --eta and --k (and not --f0)");
  }

  BakeSettings settings;
  settings.ndf = ParseNdf(o.ndf);
  settings.smith = ParseSmith(o.smith);
  settings.fresnel = fresnel;
  if (const int status = ApplySamplingOptions("eval", o.sampling, &settings)) return status;

  std::vector<Point> points;
  if (kind == TableKind::kFavg) {
    const std::vector<double> xs = Reals(fresnel == FresnelModel::kSchlick ? o.f0 : o.eta);
    const std::vector<double> ys = o.k.empty() ? std::vector<double>{0.0} : Reals(o.k);
    for (double x : xs)
      for (double y : ys) points.push_back({x, y, {}});
  } else {
    const std::vector<double> rs = Reals(o.perceptualRoughness);
    const std::vector<double> mus = albedo ? Reals(o.mu) : std::vector<double>{0.0};
    if (rs.size() * mus.size() > kMaxPoints)
      return complain(std::to_string(rs.size() * mus.size()) +
                      " points (--mu x --roughness); accepted: at most " +
                      std::to_string(kMaxPoints));
    for (double r : rs)
      for (double mu : mus) points.push_back({albedo ? mu : r, albedo ? r : 0.0, {}});
  }

  tbb::global_control parallelism(tbb::global_control::max_allowed_parallelism,
                                  static_cast<size_t>(ThreadCount(o.threads)));
  tbb::parallel_for(size_t{0}, points.size(), [&](size_t i) {
    Point &p = points[i];
    if (kind == TableKind::kFavg) {
      p.result = EvaluateFresnelAverage(fresnel, p.x, p.y);
    } else if (kind == TableKind::kEavg) {
      const double alpha = p.x * p.x;
      p.result = EvaluateAlbedoAverage(settings, alpha, PointSeed(kind, alpha, 0.0, settings.seed));
    } else {
      const double alpha = p.y * p.y;
      p.result =
          EvaluateAlbedo(kind, settings, p.x, alpha, PointSeed(kind, p.x, alpha, settings.seed));
    }
  });

  const int channels = kind == TableKind::kDfg ? 2 : 1;
  for (const Point &p : points) {
    if (o.json) {
      nlohmann::ordered_json line;
      line["table"] = o.table;
      switch (kind) {
        case TableKind::kE:
        case TableKind::kDfg:
          line["mu"] = p.x;
          line["roughness"] = p.y;
          break;
        case TableKind::kEavg: line["roughness"] = p.x; break;
        case TableKind::kFavg:
          line["fresnel"] = o.fresnel;
          if (fresnel == FresnelModel::kSchlick) {
            line["f0"] = p.x;
          } else {
            line["eta"] = p.x;
            if (fresnel == FresnelModel::kConductor) line["k"] = p.y;
          }
          break;
      }
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
    char text[400];
    switch (kind) {
      case TableKind::kE:
        std::snprintf(text, sizeof text, "E   mu %-10.6g roughness %-10.6g E %.17g  error %.2g",
                      p.x, p.y, p.result.value[0], p.result.error[0]);
        break;
      case TableKind::kDfg:
        std::snprintf(
            text, sizeof text, "dfg mu %-10.6g roughness %-10.6g A %.17g  B %.17g  error %.2g %.2g",
            p.x, p.y, p.result.value[0], p.result.value[1], p.result.error[0], p.result.error[1]);
        break;
      case TableKind::kEavg:
        std::snprintf(text, sizeof text, "Eavg roughness %-10.6g Eavg %.17g  error %.2g", p.x,
                      p.result.value[0], p.result.error[0]);
        break;
      case TableKind::kFavg:
        if (fresnel == FresnelModel::kSchlick)
          std::snprintf(text, sizeof text, "Favg schlick f0 %-10.6g Favg %.17g  error %.2g", p.x,
                        p.result.value[0], p.result.error[0]);
        else if (fresnel == FresnelModel::kDielectric)
          std::snprintf(text, sizeof text, "Favg dielectric eta %-10.6g Favg %.17g  error %.2g",
                        p.x, p.result.value[0], p.result.error[0]);
        else
          std::snprintf(text, sizeof text,
                        "Favg conductor eta %-10.6g k %-10.6g Favg %.17g  error %.2g", p.x, p.y,
                        p.result.value[0], p.result.error[0]);
        break;
    }
    std::cout << text << "  (" << EstimatorUsed(p.result, settings);
    if (p.result.samples) std::cout << ", " << p.result.samples << " samples";
    std::cout << ")\n";
  }
  return 0;
}

}  // namespace lutbake::cli
