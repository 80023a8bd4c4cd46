// Table glass_E: the directional albedo of a rough dielectric interface,
// reflection plus transmission (Walter et al. 2007), over the view cosine,
// the perceptual roughness and the relative IOR:
//   glass_E(mu, r, eta) = integral over the sphere of (f_r + f_t') |mu_i| d omega_i,
// f_t' the transmission BSDF without the eta^2 radiance factor: the fraction
// of the energy arriving along o that the interface scatters. Over visible
// normals h ~ D_o(h) = G1(o) (o.h)_+ D(h) / mu_o,
//   glass_E = E_h[ F(o.h) G2(o, i_r) / G1(o) + (1 - F(o.h)) G2(o, i_t) / G1(o) ],
// each term 0 when its direction ends on the wrong side (i_r below, i_t
// above the surface); G2 = 1 / (1 + Lambda(o) + Lambda(i)) for both lobes
// (correlated), or G1(o) G1(i). Exact limits: r = 0 gives 1 (F + T = 1);
// eta = 1 gives F = 0 and i_t = -o on every facet, so glass_E = G2(o, -o) /
// G1(o) = (1 + Lambda(mu)) / (1 + 2 Lambda(mu)) (correlated; G1(mu)
// separable): the microfacet model keeps its shadowing when nothing
// refracts. Axes: mu x r (32 x 32) x eta (dielectric_table.h), 3D.
// An engine uses it for the energy rough glass loses to single scattering:
// scaling the lobe by 1 / glass_E restores a white furnace.
#include "dielectric_table.h"
#include "lutbake/tables/bake.h"

namespace lutbake {

namespace {

class GlassAlbedo final : public DielectricAlbedoTable {
 public:
  const char *Name() const override { return "glass_E"; }
  uint64_t SeedId() const override { return 6; }
  std::string Summary() const override {
    return "directional albedo of rough glass, reflection + transmission, over (mu, r, eta)";
  }
  DielectricLobes Lobes() const override { return DielectricLobes::kReflectionAndTransmission; }
  PlanRole Role() const override { return PlanRole::kGlassCompensation; }
  HeaderText Header(const Table &table) const override {
    HeaderText text;
    AddNotes(&text);
    text.lookupComment =
        "Albedo of rough glass (reflection + transmission) at view cosine mu, perceptual "
        "roughness r and relative IOR eta.";
    const std::string name = table.Name();
    text.helpers = [name](const std::string &lookup) {
      return "// The energy compensation of rough glass: single scattering loses 1 - E of\n"
             "// the energy arriving along the view; scaling the BSDF by\n"
             "//   compensation = 1 / E(NdotV, r, eta)\n"
             "// restores it (a white furnace), spread over the lobe as single scattering\n"
             "// spreads it (1 where E is 0, which no texel is).\n"
             "inline float energy_compensation_" +
             name + "(float NdotV, float r, float eta) {\n  const float e = " + lookup +
             "(NdotV, r, eta);\n  return e > 0.0f ? 1.0f / e : 1.0f;\n}\n\n";
    };
    return text;
  }
};

}  // namespace

const TableDefinition &GlassAlbedoTable() {
  static const GlassAlbedo table;
  return table;
}

}  // namespace lutbake
