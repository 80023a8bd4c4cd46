// CheckFitFile: fit_check.h.
#include "lutbake/validation/fit_check.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "lutbake/core/error.h"
#include "lutbake/formats/fit_format.h"
#include "lutbake/tables/table_definition.h"

namespace lutbake {

namespace {

std::string Num(double v) {
  char text[40];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}

std::string Where(std::pair<double, double> p) {
  return "(" + Num(p.first) + ", " + Num(p.second) + ")";
}

}  // namespace

std::vector<CheckResult> CheckFitFile(const std::string &path, const CheckOptions &options,
                                      uint64_t *referenceEvaluations) {
  CheckResult result;
  result.check = "fit";
  result.subject = path;
  FitSource source;
  try {
    source = ReadFitSource(path);
  } catch (const IoError &e) {
    result.status = CheckStatus::kFail;
    result.detail = e.what();
    return {result};
  }
  result.subject = source.name + "_fit";
  const PiecewiseChebyshev &fit = source.fit;
  // The table and its model, from the metadata as a texture's would give them.
  Table shape;
  shape.metadata = source.metadata;
  const std::string *tableName = shape.FindMetadata("table");
  const TableDefinition *def = tableName ? FindTable(*tableName) : nullptr;
  const std::string *ax = shape.FindMetadata("axisX"), *ay = shape.FindMetadata("axisY");
  BakeSettings settings;
  std::vector<std::string> problems;
  // A 1D table's axisY reads "none": one texel, as the header reader takes it.
  if (ay && !ParseAxisDescription(*ay, &shape.y)) shape.y = LinearAxis("", 0.0, 1.0, 1);
  if (!def || !ax || !ParseAxisDescription(*ax, &shape.x)) {
    problems.push_back("its metadata names no table lutbake defines, or no axes");
  } else {
    shape.definition = def;
    def->ReadModel(shape, &settings, &problems);
  }
  if (source.coefficients != fit.CoefficientsPerChannel())
    problems.push_back("T_coefficients " + std::to_string(source.coefficients) +
                       " but its arrays hold " + std::to_string(fit.CoefficientsPerChannel()));
  if (!problems.empty()) {
    result.status = CheckStatus::kFail;
    result.detail = path + ": " + problems.front();
    return {result};
  }
  settings.estimator = def->ReferenceEstimator();
  settings.tolerance = settings.estimator == Estimator::kAdaptiveQuadrature
                           ? 2.0 * kQuadratureErrorFactor * 1e-8
                           : 1e-8;
  // The points: a staggered grid of the domain and random points.
  std::vector<std::pair<double, double>> points;
  const int n = 61;
  const auto inDomain = [&](double x, double y) {
    if (fit.map != FitMap::kCorner) return true;
    const double q = std::sqrt((x - fit.xLo) / (fit.xHi - fit.xLo));
    const double b = (y - fit.yLo) / (fit.yHi - fit.yLo);
    return std::max(q, b) >= fit.breaksY.front();
  };
  for (int j = 0; j < (fit.dims == 2 ? n : 1); ++j)
    for (int i = 0; i < n; ++i) {
      const double x = fit.xLo + (fit.xHi - fit.xLo) * (i + 0.5) / n;
      const double y = fit.dims == 2 ? fit.yLo + (fit.yHi - fit.yLo) * (j + 0.5) / n : 0.0;
      if (inDomain(x, y)) points.emplace_back(x, y);
    }
  std::mt19937_64 random(options.seed ^ 0x66697463686b);  // "fitchk"
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int k = 0; k < options.randomPoints; ++k) {
    double x, y;
    if (k % 2 == 0) {
      x = fit.xLo + (fit.xHi - fit.xLo) * unit(random);
      y = fit.dims == 2 ? fit.yLo + (fit.yHi - fit.yLo) * unit(random) : 0.0;
    } else {
      const double sx =
          fit.breaksX.front() + (fit.breaksX.back() - fit.breaksX.front()) * unit(random);
      const double sy =
          fit.breaksY.front() + (fit.breaksY.back() - fit.breaksY.front()) * unit(random);
      fit.Unmap(sx, sy, &x, &y);
    }
    if (inDomain(x, y)) points.emplace_back(x, y);
  }
  std::vector<PointValue> truth(points.size());
  tbb::parallel_for(size_t(0), points.size(), [&](size_t i) {
    truth[i] = def->Evaluate(settings, points[i].first, points[i].second);
  });
  *referenceEvaluations += points.size();
  double worst = 0.0, worstExcess = -1.0, excessAllowed = 0.0, excessValue = 0.0;
  std::pair<double, double> at{0, 0}, atExcess{0, 0};
  for (size_t i = 0; i < points.size(); ++i)
    for (int c = 0; c < fit.channels; ++c) {
      const double exact = truth[i].value[static_cast<size_t>(c)];
      const double got = fit.EvaluateFloat(c, points[i].first, points[i].second);
      const double d =
          std::isfinite(exact) && std::isfinite(got) ? std::abs(got - exact) : HUGE_VAL;
      const double allowed = source.maxError + truth[i].error[static_cast<size_t>(c)];
      if (d > worst) worst = d, at = points[i];
      if (d - allowed > worstExcess)
        worstExcess = d - allowed, excessAllowed = allowed, excessValue = d, atExcess = points[i];
    }
  result.worst = worst;
  result.allowed = source.maxError;
  result.at = {{"x", at.first}, {"y", at.second}};
  if (worstExcess > 0.0) {
    result.status = CheckStatus::kFail;
    result.detail = path + ": |fit - reference| " + Num(excessValue) + " at " + Where(atExcess) +
                    " exceeds T_max_error + the reference's bound, " + Num(excessAllowed);
    result.at = {{"x", atExcess.first}, {"y", atExcess.second}};
  } else {
    result.detail = std::to_string(points.size()) +
                    " points (staggered grid and random): max |fit - reference| " + Num(worst) +
                    " at " + Where(at) + ", within T_max_error " + Num(source.maxError) + " (" +
                    std::to_string(source.coefficients) + " coefficients per channel)";
  }
  return {result};
}

}  // namespace lutbake
