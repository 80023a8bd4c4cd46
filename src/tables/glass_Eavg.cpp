// Table glass_Eavg: the cosine-weighted average of glass_E over the view,
//   glass_Eavg(r, eta) = 2 integral_0^1 glass_E(mu, r, eta) mu dmu,
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

const TableDefinition &GlassAverageAlbedoTable() {
  static const DielectricAverageTable table(
      {"glass_Eavg", 7, DielectricLobes::kReflectionAndTransmission, "glass_E", "spec_Eavg",
       "average albedo of rough glass (reflection + transmission), 2 integral glass_E mu dmu, over "
       "(r, eta)",
       "Average albedo of rough glass (reflection + transmission) at perceptual roughness r and "
       "relative IOR eta.",
       PlanRole::kGlassCompensation});
  return table;
}

}  // namespace lutbake
