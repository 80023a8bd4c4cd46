// Table spec_Eavg: the cosine-weighted average of spec_E over the view,
//   spec_Eavg(r, eta) = 2 integral_0^1 spec_E(mu, r, eta) mu dmu,
// integrated over the half vector first, then the view on circles about it
// (IntegrateDielectricAverage: the critical cosine o.h = c_crit is a
// coordinate line there, the horizons closed-form ends of the azimuths).
// Axes: x = perceptual roughness r (32), y = eta (dielectric_table.h), 2D.
// Between the two sides of an interface the transmitted parts obey
// reciprocity (dielectric.h):
//   glass_Eavg(eta) - spec_Eavg(eta) = eta^2 (glass_Eavg(1/eta) - spec_Eavg(1/eta)),
// which is 1 - F_avg(eta) = eta^2 (1 - F_avg(1/eta)) for a smooth interface.
// The sampled estimators draw mu_o uniformly (weight 2 mu_o w, at most 2).
#include "dielectric_table.h"

namespace lutbake {

const TableDefinition &SpecularAverageAlbedoTable() {
  static const DielectricAverageTable table(
      {"spec_Eavg", 9, DielectricLobes::kReflection, "spec_E", "",
       "average albedo of a rough dielectric's reflection, 2 integral spec_E mu dmu, over (r, eta)",
       "Average albedo of a rough dielectric's reflection at perceptual roughness r and relative "
       "IOR eta.",
       PlanRole::kDielectricLayering});
  return table;
}

}  // namespace lutbake
