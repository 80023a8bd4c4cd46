// Table spec_E: the directional albedo of the reflection alone of a rough
// dielectric interface, with the exact dielectric Fresnel (no transmission
// term), over the view cosine, the perceptual roughness and the relative IOR:
//   spec_E(mu, r, eta) = integral over the upper hemisphere of f_r mu_i d omega_i
//                      = E_h[ F(o.h) G2(o, i_r) / G1(o) ]   (h ~ D_o, i_r above)
// (glass_E.cpp has the conventions). It is the albedo of a dielectric coat
// or specular layer: energy-conserving layering (as OpenPBR does it) scales
// the layer beneath by 1 - spec_E. Exact limits: r = 0 gives F(mu); eta = 1
// gives 0 (F = 0 on every facet). Both sides: eta < 1 reflects totally past
// the critical angle. Axes: mu x r (32 x 32) x eta (dielectric_table.h), 3D.
#include "dielectric_table.h"
#include "lutbake/tables/bake.h"

namespace lutbake {

namespace {

class SpecularAlbedo final : public DielectricAlbedoTable {
 public:
  const char *Name() const override { return "spec_E"; }
  uint64_t SeedId() const override { return 8; }
  std::string Summary() const override {
    return "directional albedo of a rough dielectric's reflection (coat layering), over "
           "(mu, r, eta)";
  }
  DielectricLobes Lobes() const override { return DielectricLobes::kReflection; }
  PlanRole Role() const override { return PlanRole::kDielectricLayering; }
  HeaderText Header(const Table &table) const override {
    HeaderText text;
    AddNotes(&text);
    text.lookupComment =
        "Albedo of a rough dielectric's reflection at view cosine mu, perceptual roughness r "
        "and relative IOR eta.";
    const std::string name = table.Name();
    text.helpers = [name](const std::string &lookup) {
      return "// Energy-conserving layering under a dielectric coat (or specular layer):\n"
             "//   result = coat + base_weight * base,\n"
             "//   base_weight = 1 - E(NdotV, r, eta)   (the energy the coat does not reflect;\n"
             "// the view's lookup alone, as OpenPBR's albedo-scaling layering does).\n"
             "inline float base_weight_" +
             name + "(float NdotV, float r, float eta) {\n  return 1.0f - " + lookup +
             "(NdotV, r, eta);\n}\n\n";
    };
    return text;
  }
};

}  // namespace

const TableDefinition &SpecularAlbedoTable() {
  static const SpecularAlbedo table;
  return table;
}

}  // namespace lutbake
