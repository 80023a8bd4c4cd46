// An engine-like consumer of lutbake's generated headers. It shades a white
// furnace (a constant environment of radiance 1) two ways and checks every
// number it reads through the header lookups against lutbake's own values:
//
//   1. Split-sum image-based lighting: the specular radiance is
//      L_o = F0 A(mu, r) + F90 B(mu, r). At each texel centre A and B must lie
//      within the table's stated kErrorMax of the library's reference
//      quadrature (IntegrateReferenceAlbedo), and so must E, and E_avg at its
//      texel centres (IntegrateReferenceAlbedoAverage); L_o then within
//      (F0 + F90) kErrorMax of F0 A_ref + F90 B_ref.
//   2. Kulla-Conty compensated direct light: single scattering plus the lobe
//      f_ms of kulla_conty.h reflects E(mu_o) + 2 pi integral_0^1 f_ms mu_i
//      dmu_i, integrated here exactly for the piecewise-linear lookups (two
//      Gauss points per piece). It must equal the library's closed form of
//      the same sum over the same tables (read from the .bin files), and 1 to
//      within what the bilinear interpolation of E costs the mu-average that
//      E_avg stands for (measured 4.9e-3 at 16 texels per axis, worst at
//      grazing mu_o and r near 0.1; the tables' kErrorMax does not cover
//      interpolation, so the bound here is 1e-2).
//   3. Between texel centres, the header lookups must equal the library's
//      bilinear Lookup on the same tables.
//
// Returns 0 when every check passes; prints each failure.
#include <lutbake/formats/binary_format.h>
#include <lutbake/integrators/reference_integrator.h>
#include <lutbake/models/ndf.h>
#include <lutbake/models/smith.h>
#include <lutbake/tables/lookup.h>
#include <lutbake_luts/E.h>
#include <lutbake_luts/Eavg.h>
#include <lutbake_luts/dfg.h>
#include <lutbake_luts/kulla_conty.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace {

int failures = 0;
int checks = 0;

void Expect(bool ok, const char *what, double mu, double r, double got, double expected,
            double bound) {
  ++checks;
  if (ok) return;
  ++failures;
  std::printf("FAIL %s at mu %.6g r %.6g: %.9g, expected %.9g within %.3g\n", what, mu, r, got,
              expected, bound);
}

void ExpectNear(const char *what, double mu, double r, double got, double expected, double bound) {
  Expect(std::fabs(got - expected) <= bound, what, mu, r, got, expected, bound);
}

// A float lookup result carries one float rounding of a value in [0, 1].
constexpr double kFloatRounding = 0x1p-24;

double Furnace(float muO, float r, std::size_t n) {
  double sum = 0.0;
  for (std::size_t k = 0; k <= n; ++k) {
    const double a = k == 0 ? 0.0 : (static_cast<double>(k) - 0.5) / static_cast<double>(n);
    const double b = k == n ? 1.0 : (static_cast<double>(k) + 0.5) / static_cast<double>(n);
    const double half = 0.5 * (b - a), mid = 0.5 * (a + b), g = half / std::sqrt(3.0);
    for (double mu : {mid - g, mid + g})
      sum += half * mu * engine::luts::f_ms(muO, static_cast<float>(mu), r);
  }
  return static_cast<double>(engine::luts::lookup_E(muO, r)) + 2.0 * 3.14159265358979323846 * sum;
}

}  // namespace

int main() {
  namespace E = engine::luts::E_table;
  namespace Eavg = engine::luts::Eavg_table;
  namespace dfg = engine::luts::dfg_table;
  const std::string dir = LUTS_DIR;
  const lutbake::Table eTable = lutbake::ReadBinaryTable(dir + "/E.bin");
  const lutbake::Table eavgTable = lutbake::ReadBinaryTable(dir + "/Eavg.bin");
  const lutbake::Table dfgTable = lutbake::ReadBinaryTable(dir + "/dfg.bin");

  // 1. Texel centres against the reference quadrature.
  double worstE = 0.0, worstA = 0.0, worstB = 0.0, worstIbl = 0.0;
  for (std::size_t y = 0; y < dfg::kHeight; ++y)
    for (std::size_t x = 0; x < dfg::kWidth; ++x) {
      const double mu = (static_cast<double>(x) + 0.5) / static_cast<double>(dfg::kWidth);
      const double r = (static_cast<double>(y) + 0.5) / static_cast<double>(dfg::kHeight);
      const lutbake::Ndf ndf{lutbake::NdfKind::kGgx, r * r};
      const lutbake::ReferenceAlbedo ref =
          lutbake::IntegrateReferenceAlbedo(ndf, lutbake::SmithForm::kCorrelated, mu);
      Expect(ref.converged, "reference converged", mu, r, ref.error, 0.0, 0.0);
      const auto ab = engine::luts::lookup_dfg(static_cast<float>(mu), static_cast<float>(r));
      const double boundDfg = dfg::kErrorMax + kFloatRounding + ref.error;
      ExpectNear("A", mu, r, ab[0], ref.A, boundDfg);
      ExpectNear("B", mu, r, ab[1], ref.B, boundDfg);
      worstA = std::max(worstA, std::fabs(ab[0] - ref.A));
      worstB = std::max(worstB, std::fabs(ab[1] - ref.B));
      for (double f0 : {0.04, 0.5, 1.0}) {
        const double f90 = 1.0;
        const double radiance = f0 * ab[0] + f90 * ab[1];
        const double expected = f0 * ref.A + f90 * ref.B;
        ExpectNear("IBL furnace F0 A + F90 B", mu, r, radiance, expected, (f0 + f90) * boundDfg);
        worstIbl = std::max(worstIbl, std::fabs(radiance - expected));
      }
      if (E::kWidth == dfg::kWidth && E::kHeight == dfg::kHeight) {
        const double e = engine::luts::lookup_E(static_cast<float>(mu), static_cast<float>(r));
        ExpectNear("E", mu, r, e, ref.E, E::kErrorMax + kFloatRounding + ref.error);
        worstE = std::max(worstE, std::fabs(e - ref.E));
      }
    }
  double worstEavg = 0.0;
  for (std::size_t x = 0; x < Eavg::kWidth; ++x) {
    const double r = (static_cast<double>(x) + 0.5) / static_cast<double>(Eavg::kWidth);
    const lutbake::ReferenceAverage ref = lutbake::IntegrateReferenceAlbedoAverage(
        lutbake::Ndf{lutbake::NdfKind::kGgx, r * r}, lutbake::SmithForm::kCorrelated);
    const double got = engine::luts::lookup_Eavg(static_cast<float>(r));
    ExpectNear("E_avg", 0.0, r, got, ref.value, Eavg::kErrorMax + kFloatRounding + ref.error);
    worstEavg = std::max(worstEavg, std::fabs(got - ref.value));
  }

  // 2. The compensated furnace, at every r centre and a spread of mu_o.
  double worstFurnace = 0.0, worstClosedForm = 0.0;
  for (std::size_t y = 0; y < E::kHeight; ++y) {
    const double r = (static_cast<double>(y) + 0.5) / static_cast<double>(E::kHeight);
    const double lost = 1.0 - lutbake::Lookup(eavgTable, r, 0.0);
    const double muAverage = lutbake::LookupMuAverage(eTable, eTable.values, r, 0);
    for (double muO : {0.0, 0.01, 0.1, 0.3, 0.5, 0.7, 0.9, 1.0}) {
      const double got = Furnace(static_cast<float>(muO), static_cast<float>(r), E::kWidth);
      const double eo = lutbake::Lookup(eTable, muO, r);
      const double closedForm = eo + std::max(0.0, 1.0 - eo) * (1.0 - muAverage) / lost;
      ExpectNear("furnace vs the library's closed form", muO, r, got, closedForm, 2e-5);
      ExpectNear("furnace E + integral f_ms cos = 1", muO, r, got, 1.0, 1e-2);
      worstFurnace = std::max(worstFurnace, std::fabs(got - 1.0));
      worstClosedForm = std::max(worstClosedForm, std::fabs(got - closedForm));
    }
  }

  // 3. Off-centre lookups equal the library's bilinear lookup.
  double worstLookup = 0.0;
  for (double mu : {0.0, 0.013, 0.2718, 0.5, 0.77, 0.999, 1.0})
    for (double r : {0.0, 0.05, 0.3141, 0.62, 0.9, 1.0}) {
      const auto ab = engine::luts::lookup_dfg(static_cast<float>(mu), static_cast<float>(r));
      const double mf = static_cast<float>(mu), rf = static_cast<float>(r);
      const double e = engine::luts::lookup_E(static_cast<float>(mu), static_cast<float>(r));
      const double pairs[3][2] = {{ab[0], lutbake::Lookup(dfgTable, mf, rf, 0)},
                                  {ab[1], lutbake::Lookup(dfgTable, mf, rf, 1)},
                                  {e, lutbake::Lookup(eTable, mf, rf, 0)}};
      for (const auto &p : pairs) {
        ExpectNear("lookup vs library Lookup", mu, r, p[0], p[1], 2 * kFloatRounding);
        worstLookup = std::max(worstLookup, std::fabs(p[0] - p[1]));
      }
    }

  std::printf(
      "furnace consumer: %d checks, %d failed. Worst |header - reference| at texel centres: "
      "E %.2e (kErrorMax %.2e), A %.2e, B %.2e (kErrorMax %.2e), IBL %.2e, E_avg %.2e "
      "(kErrorMax %.2e); compensated furnace |sum - 1| %.2e, vs closed form %.2e; "
      "off-centre lookups vs library %.2e\n",
      checks, failures, worstE, E::kErrorMax, worstA, worstB, dfg::kErrorMax, worstIbl, worstEavg,
      Eavg::kErrorMax, worstFurnace, worstClosedForm, worstLookup);
  return failures == 0 ? 0 : 1;
}
