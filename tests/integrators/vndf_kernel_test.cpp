// The SIMD visible-normal kernel gives, sample for sample, the very weights
// of the scalar estimator (albedo_estimator.h), on every instruction set
// this build has and the processor runs.
#include "integrators/vndf_kernel.h"

#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <cmath>

#include "lutbake/core/hash.h"
#include "lutbake/integrators/albedo_estimator.h"

namespace lutbake {
namespace {

TEST(VndfKernel, WeightsAreTheScalarEstimatorsBitForBit) {
  const std::vector<int64_t> targets = hwy::SupportedAndGeneratedTargets();
  for (int64_t target : targets) {
    hwy::SetSupportedTargetsForTest(target);
    RandomStream random(7);
    for (int trial = 0; trial < 200; ++trial) {
      const double alpha = std::pow(10.0, -6.0 * random.NextDouble());
      const double mu_o = trial % 17 == 0 ? 0.0 : trial % 19 == 0 ? 1.0 : random.NextDouble();
      const SmithForm smith = trial % 2 ? SmithForm::kSeparable : SmithForm::kCorrelated;
      const Ndf ndf{NdfKind::kGgx, alpha};
      const AlbedoEstimator estimator{ndf, smith, SampleStrategy::kVisibleNormal};
      const size_t n = 37;  // not a multiple of any vector width
      std::vector<double> u0(n), u1(n), u2(n), cosPhi(n), sinPhi(n), a(n), b(n), e(n), avg(n);
      for (size_t k = 0; k < n; ++k) {
        u0[k] = random.NextDouble();
        u1[k] = random.NextDouble();
        u2[k] = random.NextDouble();
        cosPhi[k] = std::cos(2.0 * kPi * u1[k]);
        sinPhi[k] = std::sin(2.0 * kPi * u1[k]);
      }
      const double L_o = ndf.MuLambda(mu_o);
      kernel::GgxVisibleNormalWeights(alpha, smith, mu_o, L_o, n, cosPhi.data(), sinPhi.data(),
                                      u2.data(), nullptr, a.data(), b.data());
      kernel::GgxVisibleNormalWeights(alpha, smith, mu_o, L_o, n, cosPhi.data(), sinPhi.data(),
                                      u2.data(), nullptr, e.data(), nullptr);
      kernel::GgxVisibleNormalWeights(alpha, smith, 0.0, 0.0, n, cosPhi.data(), sinPhi.data(),
                                      u2.data(), u0.data(), avg.data(), nullptr);
      const Vec3 o = ViewDirection(mu_o);
      for (size_t k = 0; k < n; ++k) {
        const AlbedoSample s = estimator.Sample(o, L_o, u1[k], u2[k]);
        const std::string where = std::string(hwy::TargetName(target)) + " trial " +
                                  std::to_string(trial) + " sample " + std::to_string(k);
        EXPECT_EQ(a[k], s.weight * s.schlickComplement) << where;
        EXPECT_EQ(b[k], s.weight * s.schlickWeight) << where;
        EXPECT_EQ(e[k], s.weight) << where;
        // E_avg's estimator: the view at mu = sqrt(u0).
        const double mu = std::sqrt(u0[k]);
        EXPECT_EQ(avg[k],
                  estimator.Sample(ViewDirection(mu), ndf.MuLambda(mu), u1[k], u2[k]).weight)
            << where;
      }
    }
  }
  hwy::SetSupportedTargetsForTest(0);
}

}  // namespace
}  // namespace lutbake
