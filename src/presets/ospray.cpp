// OSPRay (RenderKit/ospray modules/cpu/render/bsdfs/): the albedo tables
// MicrofacetAlbedoTables.ispc computes at start-up (precomputeMicrofacet-
// AlbedoTables) and MicrofacetAlbedoTables.ih reads with interp*DLinear at
// p = coordinate * (size - 1): texel edges, x = cosThetaO fastest, then the
// next axis. GGX with height-correlated Smith (GGXDistribution.ih evalG2),
// alpha = max(roughness^2, 0.001) (roughnessToAlpha); the samplers clamp
// cosThetaO to >= 1e-6 (MicrofacetAlbedo.ih).
//
//   MicrofacetAlbedoTable_dir[32 * 32]   x = cosThetaO, y = roughness     E
//   MicrofacetAlbedoTable_avg[32]        x = roughness                    E_avg
//   MicrofacetDielectricAlbedoTable_dir[16^3]  x = cosThetaO, y = eta in
//       [1/3, 1] (linear), z = roughness: reflection + transmission
//   MicrofacetDielectricAlbedoTable_avg[16^2]  x = eta, y = roughness
//   MicrofacetDielectricRcpEtaAlbedoTable_dir, _avg: the same at eta in
//       [1, 3] (the view inside the denser medium)
//   MicrofacetDielectricReflectionAlbedoTable_dir, _avg: the reflection
//       alone (exact dielectric Fresnel), eta in [1/3, 1]
//
// OSPRay's eta is the IOR outside over inside (1 / 1.5 entering glass);
// lutbake's glass_E and spec_E take the inverse, so the eta axes are
// quantity "1/eta". Its generator: 1024 stratified samples of the visible
// normals per texel, min(mean, 1); its averages a 1025-point trapezoid over
// the linearly interpolated dir table, min(., 1). These are integrated to
// 1e-8 (the averages over mu exactly, not over the interpolated table).
//
//   MicrofacetSheenAlbedoTable_dir[16 * 16]  x = cosThetaO, y = roughness:
//       the Charlie sheen's E (MicrofacetSheenAlbedo_integrate: 1024
//       stratified uniform-hemisphere samples, min(mean, 1)) at the sheen's
//       r = roughnessToAlpha(roughness) = max(roughness^2, 0.001), with
//       OSPRay's visibility (SheenDistribution.ih evalG2: the light's Lambda
//       raised to 1 + 2 (1 - cosThetaI)^8, "a softer light terminator";
//       lutbake's SheenVisibility::kOspray), stored as min(E, 1) as OSPRay
//       clamps it (E exceeds 1 at grazing view: at cosThetaO = 1e-6 it is
//       6.5 at roughness 0 and 1.5 at 1, but 0.9955 at roughness 7/15).
#include <string>

#include "presets.h"

namespace lutbake {

namespace {

constexpr const char *kSource =
    "RenderKit/ospray modules/cpu/render/bsdfs/MicrofacetAlbedoTables.ispc, "
    "MicrofacetAlbedoTables.ih, MicrofacetAlbedo.ih, GGXDistribution.ih, "
    "MicrofacetDistribution.ih (roughnessToAlpha)";
constexpr const char *kSheenSource =
    "RenderKit/ospray modules/cpu/render/bsdfs/MicrofacetAlbedoTables.ispc "
    "(MicrofacetSheenAlbedoTable_precompute), MicrofacetAlbedoTables.ih "
    "(MicrofacetSheenAlbedoTable_eval), MicrofacetAlbedo.ih (MicrofacetSheenAlbedo_integrate), "
    "SheenDistribution.ih (eval, evalLambda, evalLambdaI, evalG2), MicrofacetDistribution.ih "
    "(roughnessToAlpha)";

PresetAxis CosineAxis(int count) {
  PresetAxis axis = EdgesAxis("mu", count);
  axis.lowest = 1e-6;  // cosThetaO = max(cosThetaO, 1e-6f)
  return axis;
}

// OSPRay's eta (outside over inside) from low to high, linear in u; the
// ends as its float arithmetic has them (rcp(3.f)).
PresetAxis EtaAxis(double low, double high) {
  PresetAxis axis = EdgesAxis("1/eta", 16);
  axis.mapping = PresetMapping::kLinearRange;
  axis.lowest = low;
  axis.highest = high;
  return axis;
}

PresetTexture OsprayTable(const std::string &name, std::vector<PresetAxis> axes,
                          const char *meaning, const std::string &sampling) {
  PresetTexture t;
  t.file = name + ".ih";
  t.format = "ispc-array";
  t.axes = std::move(axes);
  t.channels = {{meaning}};
  t.model.smith = SmithForm::kCorrelated;
  t.model.alphaMin = 0.001;
  t.sampling = sampling;
  t.source = kSource;
  return t;
}

}  // namespace

const Preset &OsprayPreset() {
  static const Preset preset = [] {
    Preset p;
    p.name = "ospray";
    p.engine = "OSPRay";
    p.summary =
        "MicrofacetAlbedoTable_dir/_avg (GGX E 32 x 32, E_avg 32) and the dielectric tables "
        "(16^3 and 16^2, eta in [1/3, 1] and [1, 3], reflection alone), the sheen albedo 16^2: "
        "ISPC arrays at texel edges, as MicrofacetAlbedoTables.ispc lays them out";
    const double third = static_cast<double>(1.0f / 3.0f);
    const PresetAxis rough32 = EdgesAxis("roughness", 32), rough16 = EdgesAxis("roughness", 16);
    p.textures.push_back(OsprayTable("MicrofacetAlbedoTable_dir", {CosineAxis(32), rough32}, "E",
                                     "MicrofacetAlbedoTable_eval(cosThetaO, roughness)"));
    p.textures.push_back(OsprayTable("MicrofacetAlbedoTable_avg", {rough32}, "Eavg",
                                     "MicrofacetAlbedoTable_evalAvg(roughness)"));
    struct Dielectric {
      const char *name;
      double low, high;  // OSPRay's eta
      const char *meaning, *eval;
    };
    const Dielectric tables[] = {
        {"MicrofacetDielectricAlbedoTable", third, 1.0, "glass",
         "MicrofacetDielectricAlbedoTable_eval"},
        {"MicrofacetDielectricRcpEtaAlbedoTable", 1.0, 3.0, "glass",
         "MicrofacetDielectricAlbedoTable_eval"},
        {"MicrofacetDielectricReflectionAlbedoTable", third, 1.0, "spec",
         "MicrofacetDielectricReflectionAlbedoTable_eval"},
    };
    for (const Dielectric &d : tables) {
      const std::string meaning = d.meaning, eval = d.eval;
      p.textures.push_back(OsprayTable(
          std::string(d.name) + "_dir", {CosineAxis(16), EtaAxis(d.low, d.high), rough16},
          (meaning + "_E").c_str(), eval + "(cosThetaO, eta, roughness)"));
      p.textures.push_back(OsprayTable(std::string(d.name) + "_avg",
                                       {EtaAxis(d.low, d.high), rough16},
                                       (meaning + "_Eavg").c_str(), eval + "Avg(eta, roughness)"));
    }
    // The sheen albedo, clamped to 1 as OSPRay's generator clamps it.
    PresetChannel sheen{"sheen_E"};
    sheen.clampMax = 1.0;
    sheen.clampIsValue = true;
    PresetTexture sheenTable =
        OsprayTable("MicrofacetSheenAlbedoTable_dir", {CosineAxis(16), rough16}, "sheen_E",
                    "MicrofacetSheenAlbedoTable_eval(cosThetaO, roughness)");
    sheenTable.channels = {sheen};
    sheenTable.model.sheenVisibility = SheenVisibility::kOspray;
    sheenTable.model.sheenAlpha = AlphaMapping::kSquared;
    sheenTable.model.sheenAlphaMin = 0.001;
    sheenTable.source = kSheenSource;
    sheenTable.notes =
        "OSPRay's Charlie visibility softens the light's Lambda (Lambda_i^(1 + 2 (1 - "
        "cosThetaI)^8), SheenDistribution.ih evalLambdaI): lutbake's --sheen-visibility ospray. "
        "E above 1 (grazing view: most texels at cosThetaO = 0, evaluated at 1e-6) is stored as 1, "
        "as OSPRay's generator clamps it (min(E, 1) is the table's value, so the bound is the "
        "integral's own).";
    p.textures.push_back(sheenTable);
    for (PresetTexture &t : p.textures)
      if (t.file.find("RcpEta") != std::string::npos)
        t.notes =
            "OSPRay's eta in [1, 3]: the view is inside the denser medium (lutbake's eta = 1 / "
            "OSPRay's, below 1).";
    return p;
  }();
  return preset;
}

}  // namespace lutbake
