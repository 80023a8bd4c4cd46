// What the rough-dielectric tables (glass_E, glass_Eavg, spec_E, spec_Eavg)
// share: the model (NDF and Smith form as for E, the exact unpolarised
// dielectric Fresnel at o.h, alpha = perceptualRoughness^2), the relative
// IOR axis, reading both back from a file, and the estimators. Private to
// the tables layer.
//
// The relative IOR eta = (IOR on the far side) / (IOR on the side of o):
// eta > 1 enters a denser medium, eta < 1 leaves it (total internal
// reflection past the critical angle). The default eta axis is listed: the
// values uniform in s = (eta - 1) / (eta + 1) over [-1/2, 1/2] (eta from 1/3
// to 3; s is the signed square root of the normal-incidence reflectance
// F0 = s^2, so the slices are as dense in Fresnel as in IOR, and eta and
// 1/eta sit at -s and s), with eta = 1 and the IORs of water (1.33), glass
// (1.5) and diamond (2.42) and their inverses added as nodes of their own:
// at those materials a lookup returns a texel, with no interpolation error.
#pragma once

#include <string>
#include <vector>

#include "lutbake/integrators/dielectric_quadrature.h"
#include "lutbake/tables/table_definition.h"

namespace lutbake {

class DielectricTable : public TableDefinition {
 public:
  std::vector<std::string> ModelOptions() const override { return {"ndf", "smith"}; }
  Metadata ModelMetadata(const BakeSettings &s) const override;
  std::string AlphaMetadata(const BakeSettings &) const override {
    return "alpha = perceptualRoughness^2";
  }
  std::string DescribeModel(const BakeSettings &s) const override;
  bool ReadModel(const Table &table, BakeSettings *s,
                 std::vector<std::string> *problems) const override;
  bool SameModel(const BakeSettings &a, const BakeSettings &b) const override {
    return a.ndf == b.ndf && a.smith == b.smith;
  }
  std::string QuadratureDescription(const BakeSettings &s) const override;
  std::string QuadratureBound(const BakeSettings &s) const override;
  std::string UnseenEventTerm() const override {
    return "4.6 W / N (W = 1 for E, 2 for E_avg: the largest weight the sampler returns)";
  }
  std::string SamplerNote(const BakeSettings &) const override {
    return "visible normals, the weight the expected value over reflection and refraction "
           "(F w_r + (1 - F) w_t: no branch is drawn)";
  }
  int DefaultSize() const override { return 32; }
  // Only the visible-normal sampler (vndf, vndf-random) and the quadratures.
  std::string EstimatorProblem(Estimator e) const override;

  // The default eta axis (above) with `size` values uniform in s.
  static Axis EtaAxis(int size);
  // Which lobes the table integrates.
  virtual DielectricLobes Lobes() const = 0;

 protected:
  static PointCoordinate RoughnessCoordinate();
  static PointCoordinate MuCoordinate();
  static PointCoordinate EtaCoordinate();
  // alpha from r, and checks of mu and eta (std::domain_error outside).
  static double AlphaOf(double r);
  static void CheckEta(double eta);
  static PointValue FromIntegral(const DielectricIntegral &q);
  static double PanelTolerance(const BakeSettings &s);
  static double AdaptiveTolerance(const BakeSettings &s);
  // The directional albedo and its average, with the settings' estimator.
  PointValue EvaluateAlbedo(const BakeSettings &s, double mu, double r, double eta) const;
  PointValue EvaluateAverage(const BakeSettings &s, double r, double eta) const;
  void AddNotes(HeaderText *text) const;
};

}  // namespace lutbake
