// FitTable: a table's point evaluator fitted by chebyshev_fit.h.
#include "lutbake/tables/table_fit.h"

#include <map>
#include <mutex>
#include <stdexcept>

namespace lutbake {

FitExact ExactValuesOf(const TableDefinition &table, const BakeSettings &settings) {
  BakeSettings exact;
  exact.ndf = settings.ndf;
  exact.smith = settings.smith;
  exact.fresnel = settings.fresnel;
  exact.sheenVisibility = settings.sheenVisibility;
  exact.sheenAlpha = settings.sheenAlpha;
  exact.estimator = Estimator::kQuadrature;
  const int channels = table.Channels();
  return [&table, exact, channels](double x, double y) {
    const PointValue v = table.Evaluate(exact, x, y);
    FitExactValue out;
    for (int c = 0; c < channels; ++c) {
      out.value[static_cast<size_t>(c)] = v.value[static_cast<size_t>(c)];
      out.error[static_cast<size_t>(c)] = v.error[static_cast<size_t>(c)];
    }
    return out;
  };
}

int FitCoefficientBudget(double tolerance) {
  return tolerance >= kDefaultFitTolerance ? kDefaultFitCoefficients : kTightFitCoefficients;
}

FitResult FitTable(const TableDefinition &table, const BakeSettings &settings, double tolerance) {
  const int dims = static_cast<int>(table.Coordinates(settings).size());
  if (dims < 1 || dims > 2 || table.FittedChannels() > 0 || table.Channels() > kMaxFitChannels)
    throw std::invalid_argument(std::string("--format fit: table ") + table.Name() +
                                " is not a 1D or 2D integrated table");
  if (!(tolerance > 0.0)) throw std::invalid_argument("--fit-tolerance must be positive");
  static std::mutex mutex;
  static std::map<std::string, FitResult> cache;
  std::string key = std::string(table.Name()) + "|" + std::to_string(tolerance);
  for (const auto &[k, v] : table.ModelMetadata(settings)) key += "|" + k + "=" + v;
  key += "|" + table.AlphaMetadata(settings);
  std::lock_guard<std::mutex> lock(mutex);
  const auto found = cache.find(key);
  if (found != cache.end()) return found->second;
  FitRequest request;
  request.dims = dims;
  request.channels = table.Channels();
  const std::array<double, 4> domain = table.FitDomain(settings);
  request.xLo = domain[0], request.xHi = domain[1], request.yLo = domain[2],
  request.yHi = domain[3];
  request.exact = ExactValuesOf(table, settings);
  request.tolerance = tolerance;
  request.maxCoefficients = FitCoefficientBudget(tolerance);
  if (const TableDefinition::FitCoordinates maps = table.FitCoordinateMaps(settings);
      maps.logarithmic) {
    request.maps = {FitMap::kLogXY};
    request.xShift = maps.logShift;
  }
  // Where the domain stops short of mu = 0, r = 0, its corner is a regular
  // point: the corner map needs no box left out there (every ray of s_y = 0
  // meets the corner's one value).
  if (dims == 2 && !(domain[0] == 0.0 && domain[2] == 0.0)) request.cornerExclusion = 0.0;
  return cache.emplace(key, FitPiecewiseChebyshev(request)).first->second;
}

}  // namespace lutbake
