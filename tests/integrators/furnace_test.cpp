#include "lutbake/integrators/furnace.h"

#include <gtest/gtest.h>
#include <tbb/parallel_for.h>

#include <cmath>
#include <cstring>
#include <map>
#include <vector>

#include "support/csv.h"

namespace lutbake {
namespace {

FurnaceModel Model(FurnaceModelKind kind) {
  FurnaceModel m;
  m.kind = kind;
  return m;
}

// Every stated error here must also be small enough to mean something.
constexpr double kUsefulError = 1e-8;

TEST(Furnace, LambertIsOne) {
  const FurnaceIntegrator lambert(Model(FurnaceModelKind::kLambert), 0.0);
  for (double mu : {0.0, 1e-6, 0.1, 0.5, 0.99, 1.0}) {
    const FurnaceValue a = lambert.Albedo(mu).albedo;
    EXPECT_NEAR(a.value, 1.0, a.error) << mu;
    EXPECT_LT(a.error, kUsefulError);
  }
  const FurnaceValue avg = lambert.Average();
  EXPECT_NEAR(avg.value, 1.0, avg.error);
}

TEST(Furnace, PhongAtNormalIncidence) {
  // (n+2)/2pi: albedo 1 at mu = 1; (n+1)/2pi: (n+1)/(n+2); none: 2 pi / (n+2).
  for (double n : {0.0, 1.0, 5.5, 50.0, 1000.0, 1e5}) {
    FurnaceModel m = Model(FurnaceModelKind::kPhong);
    m.phong = PhongNormalisation::kNPlus2;
    FurnaceValue a = FurnaceIntegrator(m, n).Albedo(1.0).albedo;
    EXPECT_NEAR(a.value, 1.0, a.error) << n;
    EXPECT_LT(a.error, kUsefulError);
    m.phong = PhongNormalisation::kNPlus1;
    a = FurnaceIntegrator(m, n).Albedo(1.0).albedo;
    EXPECT_NEAR(a.value, (n + 1.0) / (n + 2.0), a.error) << n;
    m.phong = PhongNormalisation::kNone;
    a = FurnaceIntegrator(m, n).Albedo(1.0).albedo;
    EXPECT_NEAR(a.value, 2.0 * kPi / (n + 2.0), a.error) << n;
  }
}

TEST(Furnace, PhongAwayFromGrazingIsTheClippedCosine) {
  // For a narrow lobe well above the horizon the albedo of (n+2)/2pi tends
  // to mu_o (the lobe's mean cosine): at n = 1e5, mu = 0.5 the clipped part
  // is far below 1e-12 and the rest is 1 - O(1/n) of mu_o. A check of the
  // t = u^(n+1) variable far from normal incidence.
  FurnaceModel m = Model(FurnaceModelKind::kPhong);
  const FurnaceValue a = FurnaceIntegrator(m, 1e5).Albedo(0.5).albedo;
  // int (n+2)/2pi cos^n(a) (mu cos a + ...) = mu (n+2)/(n+2) exactly when
  // the cone never clips: the cos(b) term integrates to 0 over full circles.
  EXPECT_NEAR(a.value, 0.5, a.error + 1e-12);
}

TEST(Furnace, BlinnPhongExactNormalisationIsOneAtNormalIncidence) {
  for (double n : {0.0, 1.0, 4.0, 10.0, 100.0, 1e4}) {
    FurnaceModel m = Model(FurnaceModelKind::kBlinnPhong);
    m.blinnPhong = BlinnPhongNormalisation::kExact;
    const FurnaceValue a = FurnaceIntegrator(m, n).Albedo(1.0).albedo;
    EXPECT_NEAR(a.value, 1.0, a.error) << n;
    EXPECT_LT(a.error, kUsefulError);
    // (n+8)/8pi against exact: the ratio of the factors.
    m.blinnPhong = BlinnPhongNormalisation::kNPlus8;
    const FurnaceValue b = FurnaceIntegrator(m, n).Albedo(1.0).albedo;
    EXPECT_NEAR(b.value,
                BlinnPhongNormalisationFactor(BlinnPhongNormalisation::kNPlus8, n) /
                    BlinnPhongNormalisationFactor(BlinnPhongNormalisation::kExact, n),
                b.error)
        << n;
  }
}

TEST(Furnace, BlinnPhongAverageIsFourPiCOverNPlusFour) {
  // Measured, then held: the hemispherical average of c cos^n(theta_h) is
  // 4 pi c / (n + 4) (n = 0: Lambert's 1).
  for (double n : {0.0, 1.0, 7.0, 64.0}) {
    FurnaceModel m = Model(FurnaceModelKind::kBlinnPhong);
    m.blinnPhong = BlinnPhongNormalisation::kNone;
    const FurnaceValue avg = FurnaceIntegrator(m, n).Average();
    EXPECT_NEAR(avg.value, 4.0 * kPi / (n + 4.0), avg.error) << n;
  }
}

TEST(Furnace, EonIsOneAndFonIsItsClosedForm) {
  // At mu = 0, E_F = 1 exactly and the reference implementation's clamp
  // max(1e-7, 1 - E_F(mu_o)) gives the lobe f_ms an albedo of 1e-7 (times
  // (1 - E_avg) / (1 - E_avg) up to where 1 - E_F(mu_i) < 1e-7): EON
  // gains 1e-7 at grazing.
  for (double r : {0.05, 0.3, 1.0})
    for (double mu : {0.0, 0.01, 0.3, 0.8, 1.0}) {
      FurnaceModel m = Model(FurnaceModelKind::kEon);
      m.eon = EonVariant::kExact;
      const FurnaceValue e = FurnaceIntegrator(m, r).Albedo(mu).albedo;
      EXPECT_NEAR(e.value, mu == 0.0 ? 1.0 + 1e-7 : 1.0, e.error + (mu == 0.0 ? 1e-12 : 0.0))
          << r << " " << mu;
      EXPECT_LT(e.error, kUsefulError);
      m.eon = EonVariant::kFon;
      const FurnaceValue f = FurnaceIntegrator(m, r).Albedo(mu).albedo;
      EXPECT_NEAR(f.value, FonAlbedo(r, mu), f.error + 1e-15) << r << " " << mu;
    }
  FurnaceModel m = Model(FurnaceModelKind::kEon);
  m.eon = EonVariant::kFon;
  const FurnaceValue avg = FurnaceIntegrator(m, 0.7).Average();
  EXPECT_NEAR(avg.value, FonAverageAlbedo(0.7), avg.error);
}

TEST(Furnace, CompensatedMicrofacetWithWhiteFresnelIsOne) {
  // E + F_ms (1 - E) I / (1 - E_avg) with F_ms = 1: one, within the errors of
  // E, of I (integrated here over mu) and of E_avg (the library's own
  // average quadrature) -- a real check that the two averages agree.
  for (NdfKind ndf : {NdfKind::kGgx, NdfKind::kBeckmann})
    for (FurnaceVisibility v : {FurnaceVisibility::kCorrelated, FurnaceVisibility::kSeparable,
                                FurnaceVisibility::kSchlickGgxIbl}) {
      if (ndf == NdfKind::kBeckmann && v == FurnaceVisibility::kSchlickGgxIbl) continue;
      for (double r : {0.2, 0.6, 1.0}) {
        FurnaceModel m = Model(FurnaceModelKind::kMicrofacet);
        m.ndf = ndf;
        m.visibility = v;
        m.compensation = true;
        const FurnaceIntegrator furnace(m, r);
        EXPECT_NEAR(1.0 - furnace.EnergyAverage(), 0.0, 1.0);  // sanity: in [0, 1]
        for (double mu : {0.0, 0.05, 0.5, 1.0}) {
          const FurnacePoint p = furnace.Albedo(mu);
          EXPECT_NEAR(p.albedo.value, 1.0, p.albedo.error)
              << ToString(ndf) << " " << ToString(v) << " r " << r << " mu " << mu;
          EXPECT_LT(p.albedo.error, 1e-7);
          // Correlated E climbs back to 1 at grazing; never above.
          EXPECT_LE(p.singleScattering.value, 1.0 + p.singleScattering.error);
        }
      }
    }
}

TEST(Furnace, MicrofacetMirrorIsFresnel) {
  FurnaceModel m = Model(FurnaceModelKind::kMicrofacet);
  m.fresnel = FurnaceFresnel::kSchlick;
  m.f0 = 0.04;
  EXPECT_DOUBLE_EQ(FurnaceIntegrator(m, 0.0).Albedo(0.5).albedo.value, 0.04 + 0.96 / 32.0);
}

TEST(Furnace, MatchesIndependentQuadrature) {
  // tests/data/furnace/reference.csv: brute-force quadrature over the light
  // direction (numpy). Each value within our bound plus the reference's.
  int checked = 0;
  for (const test::CsvRow &row : test::ReadCsv(test::DataPath("furnace/reference.csv"))) {
    const std::string &name = row.Text("model"), &variant = row.Text("variant");
    FurnaceModel m;
    if (name == "phong") {
      m.kind = FurnaceModelKind::kPhong;
      m.phong = PhongNormalisation::kNPlus2;
    } else if (name == "blinn-phong") {
      m.kind = FurnaceModelKind::kBlinnPhong;
      m.blinnPhong = BlinnPhongNormalisation::kExact;
    } else if (name == "oren-nayar") {
      m.kind = FurnaceModelKind::kOrenNayar;
      m.orenNayar = variant == "full" ? OrenNayarVariant::kFull : OrenNayarVariant::kQualitative;
    } else if (name == "eon") {
      m.kind = FurnaceModelKind::kEon;
      m.eon = variant == "fon" ? EonVariant::kFon : EonVariant::kExact;
    } else {
      m.kind = FurnaceModelKind::kMicrofacet;
      const std::map<std::string, FurnaceVisibility> visibility = {
          {"correlated", FurnaceVisibility::kCorrelated},
          {"schlick-ggx-ibl", FurnaceVisibility::kSchlickGgxIbl},
          {"schlick-ggx-direct", FurnaceVisibility::kSchlickGgxDirect}};
      const size_t slash = variant.find('/');
      m.visibility = visibility.at(variant.substr(0, slash));
      const std::string fresnel = variant.substr(slash + 1);
      if (fresnel == "schlick0.04") {
        m.fresnel = FurnaceFresnel::kSchlick;
        m.f0 = 0.04;
      } else if (fresnel == "dielectric1.5") {
        m.fresnel = FurnaceFresnel::kExact;
        m.eta = 1.5;
      }
    }
    const FurnaceValue a =
        FurnaceIntegrator(m, row.Number("parameter")).Albedo(row.Number("mu")).albedo;
    EXPECT_NEAR(a.value, row.Number("value"), a.error + row.Number("error"))
        << name << " " << variant << " p " << row.Text("parameter") << " mu " << row.Text("mu");
    EXPECT_LT(a.error, kUsefulError);
    ++checked;
  }
  EXPECT_EQ(checked, 66);
}

TEST(Furnace, BitIdenticalAcrossThreads) {
  // Each value is a fixed sequence of operations: computed alone or among
  // others on many threads, it has the same bits.
  FurnaceModel m = Model(FurnaceModelKind::kMicrofacet);
  m.visibility = FurnaceVisibility::kSchlickGgxDirect;
  m.fresnel = FurnaceFresnel::kExact;
  const FurnaceIntegrator furnace(m, 0.4);
  std::vector<double> mus;
  for (int k = 0; k <= 32; ++k) mus.push_back(k / 32.0);
  std::vector<double> serial(mus.size()), parallel(mus.size());
  for (size_t k = 0; k < mus.size(); ++k) serial[k] = furnace.Albedo(mus[k]).albedo.value;
  tbb::parallel_for(size_t(0), mus.size(),
                    [&](size_t k) { parallel[k] = furnace.Albedo(mus[k]).albedo.value; });
  EXPECT_EQ(std::memcmp(serial.data(), parallel.data(), serial.size() * sizeof(double)), 0);
}

}  // namespace
}  // namespace lutbake
