// The piecewise Chebyshev fit and its certificate (chebyshev_fit.h) on
// closed forms whose values are exact: the certified bound holds at dense
// and random points, the float32 evaluation stays within its a-priori
// rounding bound, and the fit is bit-identical for any thread count.
#include "lutbake/integrators/chebyshev_fit.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <cmath>
#include <random>
#include <stdexcept>

namespace lutbake {
namespace {

// A smooth 2D form with a square-root edge at x = 0 (as albedos have at
// mu = 0), values exact (bound 0).
FitExactValue Smooth(double x, double y) {
  FitExactValue v;
  v.value[0] = std::exp(-x) * std::cos(3.0 * y) + 0.3 * std::sqrt(x) * y;
  v.value[1] = 1.0 / (1.2 + x + y * y);
  return v;
}

FitRequest SmoothRequest(double tolerance) {
  FitRequest r;
  r.dims = 2;
  r.channels = 2;
  r.exact = Smooth;
  r.tolerance = tolerance;
  r.maxCoefficients = 256;
  return r;
}

TEST(ChebyshevFit, CertifiedBoundHoldsAtRandomPoints) {
  const FitResult fit = FitPiecewiseChebyshev(SmoothRequest(1e-4));
  ASSERT_TRUE(fit.met) << fit.certificate.maxError;
  EXPECT_LE(fit.fit.CoefficientsPerChannel(), 256);
  EXPECT_LE(fit.certificate.maxError, 1e-4);
  EXPECT_EQ(fit.fit.map, FitMap::kSqrtX);  // the square-root edge needs it
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst = 0.0;
  for (int i = 0; i < 20000; ++i) {
    const double x = i % 2 ? unit(random) : std::pow(unit(random), 6.0), y = unit(random);
    const FitExactValue e = Smooth(x, y);
    for (int c = 0; c < 2; ++c) {
      const double got = fit.fit.EvaluateFloat(c, x, y);
      worst = std::max(worst, std::abs(got - e.value[static_cast<size_t>(c)]));
    }
  }
  EXPECT_LE(worst, fit.certificate.maxError);
  // Not vacuous: the bound is within 20x of what the points see.
  EXPECT_GT(worst, fit.certificate.maxError / 20.0);
}

TEST(ChebyshevFit, FloatEvaluationWithinItsRoundingBound) {
  const FitResult fit = FitPiecewiseChebyshev(SmoothRequest(1e-5));
  const PiecewiseChebyshev &f = fit.fit;
  std::mt19937_64 random(3);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int i = 0; i < 20000; ++i) {
    // float inputs, so that only the evaluation rounds
    const double x = static_cast<float>(unit(random)), y = static_cast<float>(unit(random));
    double sx, sy;
    f.Map(x, y, &sx, &sy);
    int kx = 0, ky = 0;
    while (kx + 2 < static_cast<int>(f.breaksX.size()) && sx >= f.breaksX[kx + 1]) ++kx;
    while (ky + 2 < static_cast<int>(f.breaksY.size()) && sy >= f.breaksY[ky + 1]) ++ky;
    for (int c = 0; c < 2; ++c) {
      // EvaluateFloat is IEEE binary32 (correctly rounded / and sqrt); a
      // shader's looser / and sqrt only widen the bound.
      const double bound = FitRoundingBound(f, c, kx, ky, FitPrecision::kIeee);
      ASSERT_LE(bound, FitRoundingBound(f, c, kx, ky, FitPrecision::kShader));
      ASSERT_LE(std::abs(f.EvaluateFloat(c, x, y) - f.Evaluate(c, x, y)), bound) << x << " " << y;
    }
  }
}

// kLogXY: a form ~ y^-1/2 toward y = 0.01 and log-like toward x = 1e-4
// (as sheen_E), fitted in log(x + c) and log(y); the bound holds at random
// points crowded toward the low edges, the map inverts, and the float32
// evaluation (two logs) stays within its rounding bound.
TEST(ChebyshevFit, LogarithmicMapsInBothCoordinates) {
  const auto exact = [](double x, double y) {
    FitExactValue v;
    v.value[0] = 0.2 * std::exp(-2.0 * x) / std::sqrt(y) + 0.05 * std::log(x + 1e-3);
    return v;
  };
  FitRequest r;
  r.dims = 2;
  r.channels = 1;
  r.xLo = 1e-4, r.yLo = 0.01;
  r.exact = exact;
  r.tolerance = 2e-4;
  r.maxCoefficients = 256;
  r.maps = {FitMap::kLogXY};
  r.xShift = 7e-4;
  const FitResult fit = FitPiecewiseChebyshev(r);
  const PiecewiseChebyshev &f = fit.fit;
  ASSERT_TRUE(fit.met) << fit.certificate.maxError;
  EXPECT_EQ(f.map, FitMap::kLogXY);
  EXPECT_EQ(f.xShift, static_cast<double>(7e-4f));
  std::mt19937_64 random(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  double worst = 0.0;
  for (int i = 0; i < 20000; ++i) {
    const double x = 1e-4 * std::pow(1e4, unit(random)), y = 0.01 * std::pow(100.0, unit(random));
    double sx, sy, bx, by;
    f.Map(x, y, &sx, &sy);
    f.Unmap(sx, sy, &bx, &by);
    // Map's constants are float32 values, Unmap's exact: a few float ulps
    // of the logs' span (9.3 and 4.6) apart.
    ASSERT_NEAR(bx, x, 1e-6 * (x + 7e-4));
    ASSERT_NEAR(by, y, 1e-6 * y);
    worst = std::max(worst, std::abs(f.EvaluateFloat(0, x, y) - exact(x, y).value[0]));
    const float xf = static_cast<float>(x), yf = static_cast<float>(y);
    int kx = 0, ky = 0;
    f.Map(xf, yf, &sx, &sy);
    while (kx + 2 < static_cast<int>(f.breaksX.size()) && sx >= f.breaksX[kx + 1]) ++kx;
    while (ky + 2 < static_cast<int>(f.breaksY.size()) && sy >= f.breaksY[ky + 1]) ++ky;
    ASSERT_LE(std::abs(f.EvaluateFloat(0, xf, yf) - f.Evaluate(0, xf, yf)),
              FitRoundingBound(f, 0, kx, ky, FitPrecision::kIeee))
        << x << " " << y;
  }
  EXPECT_LE(worst, fit.certificate.maxError);
  EXPECT_GT(worst, fit.certificate.maxError / 20.0);
  // log(r) at r = 0 would be -infinity: refused, not fitted to NaN.
  r.yLo = 0.0;
  EXPECT_THROW(FitPiecewiseChebyshev(r), std::invalid_argument);
}

TEST(ChebyshevFit, OneDimensionalAndBitIdenticalForAnyThreadCount) {
  FitRequest r;
  r.dims = 1;
  r.channels = 1;
  r.exact = [](double x, double) {
    FitExactValue v;
    v.value[0] = std::atan(8.0 * (x - 0.3));
    v.error[0] = 1e-9;
    return v;
  };
  r.tolerance = 1e-4;
  r.maxCoefficients = 256;
  FitResult one, two;
  {
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 1);
    one = FitPiecewiseChebyshev(r);
  }
  {
    tbb::global_control threads(tbb::global_control::max_allowed_parallelism, 2);
    two = FitPiecewiseChebyshev(r);
  }
  ASSERT_TRUE(one.met) << one.certificate.maxError;
  EXPECT_EQ(one.fit.coefficients, two.fit.coefficients);
  EXPECT_EQ(one.fit.breaksX, two.fit.breaksX);
  EXPECT_EQ(one.certificate.maxError, two.certificate.maxError);
  // The exact values' bound is part of the certificate.
  EXPECT_GE(one.certificate.maxError, 1e-9);
  for (int i = 0; i <= 10000; ++i) {
    const double x = i / 10000.0;
    EXPECT_LE(std::abs(one.fit.EvaluateFloat(0, x, 0.0) - std::atan(8.0 * (x - 0.3))),
              one.certificate.maxError);
  }
}

}  // namespace
}  // namespace lutbake
