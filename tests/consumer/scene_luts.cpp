// The tables of a scene (tests/data/plans/listed.gltf: roughness 0.25 and
// 0.5, no textures), baked at build time by lutbake_add_luts with SCENE and
// TABLES E dfg. The plan lists exactly those two roughness rows; at each,
// lookups at every mu texel centre must lie within the table's kErrorMax of
// the library's reference quadrature. No Eavg was asked for, so no
// kulla_conty.h is written (checked by run.sh).
#include <lutbake/integrators/reference_integrator.h>
#include <lutbake/models/ndf.h>
#include <lutbake/models/smith.h>
#include <lutbake_luts/E.h>
#include <lutbake_luts/dfg.h>

#include <cmath>
#include <cstdio>

int main() {
  namespace E = lutbake_luts::E_table;
  namespace dfg = lutbake_luts::dfg_table;
  int failures = 0;
  static_assert(E::kHeight == 2 && dfg::kHeight == 2, "one row per listed roughness");
  failures += E::kYNodes[0] != 0.25 || E::kYNodes[1] != 0.5;
  for (const float r : {0.25f, 0.5f})
    for (std::size_t x = 0; x < dfg::kWidth; ++x) {
      const double mu = (static_cast<double>(x) + 0.5) / static_cast<double>(dfg::kWidth);
      const lutbake::ReferenceAlbedo ref = lutbake::IntegrateReferenceAlbedo(
          lutbake::Ndf{lutbake::NdfKind::kGgx, static_cast<double>(r) * r},
          lutbake::SmithForm::kCorrelated, mu);
      const auto ab = lutbake_luts::lookup_dfg(static_cast<float>(mu), r);
      const double e = lutbake_luts::lookup_E(static_cast<float>(mu), r);
      const double slack = 0x1p-24 + ref.error;
      const bool ok = std::fabs(ab[0] - ref.A) <= dfg::kErrorMax + slack &&
                      std::fabs(ab[1] - ref.B) <= dfg::kErrorMax + slack &&
                      std::fabs(e - ref.E) <= E::kErrorMax + slack;
      if (!ok)
        std::printf("FAIL at mu %.6g r %.6g: A %.9g B %.9g E %.9g, reference %.9g %.9g %.9g\n", mu,
                    static_cast<double>(r), static_cast<double>(ab[0]), static_cast<double>(ab[1]),
                    e, ref.A, ref.B, ref.E);
      failures += !ok;
    }
  std::printf("scene consumer: %d failures\n", failures);
  return failures == 0 ? 0 : 1;
}
