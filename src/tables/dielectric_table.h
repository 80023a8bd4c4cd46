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

#include <stdexcept>
#include <string>
#include <vector>

#include "lutbake/integrators/dielectric_quadrature.h"
#include "lutbake/tables/table_definition.h"

namespace lutbake {

// Values uniform in s on the default eta axis (before the material nodes).
inline constexpr int kDefaultEtaSize = 17;

// The rough dielectric's model part: the microfacet part's NDF, Smith form
// and alpha (MicrofacetModel, composed), with the exact dielectric Fresnel
// and `lobes` recorded as well (metadata fresnel, lobes, transmission).
const TableModel &DielectricModel(DielectricLobes lobes);

class DielectricTable : public TableDefinition {
 public:
  const TableModel &ModelPart() const override { return DielectricModel(Lobes()); }
  bool ReadModel(const Table &table, BakeSettings *s,
                 std::vector<std::string> *problems) const override;
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
  // `lutbake check` judges every texel by the bake's own panel rule
  // (IntegrateDielectricAlbedo, IntegrateDielectricAverage) at 1/16 of the
  // stated errorMax, not below kPanelReferenceFloor (nor the option, when
  // that is finer), and the random points' truth by it at the default
  // tolerance (the .cpp says why).
  CheckReference ReferenceForCheck(double statedErrorMax, double optionTolerance) const override;

  // The eta axis: `size` values uniform in s, with the material nodes (the
  // default axis, above) or without them (--eta-size N: exactly N slices;
  // one is eta = 1).
  static Axis EtaAxis(int size, bool withMaterials);
  // Which lobes the table integrates.
  virtual DielectricLobes Lobes() const = 0;

  // The index-matched interface (eta = 1): F = 0 and every facet passes o
  // straight through (i_t = -o), so reflection gives 0 and reflection plus
  // transmission G2(o, -o) / G1(o) = (1 + Lambda(mu)) / (1 + 2 Lambda(mu))
  // correlated, G1(mu) separable (dielectric.h). At mu on this table's NDF
  // and Smith form.
  double IndexMatchedAlbedo(const BakeSettings &s, double mu, double r) const;
  // 2 integral_0^1 IndexMatchedAlbedo mu dmu (adaptive Gauss-Kronrod to
  // 1e-13).
  double IndexMatchedAverage(const BakeSettings &s, double r) const;

 protected:
  static PointCoordinate RoughnessCoordinate();
  static PointCoordinate MuCoordinate();
  static PointCoordinate EtaCoordinate();
  // alpha from r, and checks of mu and eta (std::domain_error outside).
  static double AlphaOf(double r);
  static void CheckEta(double eta);
  static PointValue FromIntegral(const DielectricIntegral &q);
  // The directional albedo and its average, with the settings' estimator.
  PointValue EvaluateAlbedo(const BakeSettings &s, double mu, double r, double eta) const;
  PointValue EvaluateAverage(const BakeSettings &s, double r, double eta) const;
  void AddNotes(HeaderText *text) const;
};

// What glass_E and spec_E share: the axes mu x r x eta (32 x 32 x the
// default eta axis), the point coordinates and the evaluation. Each adds its
// name, lobes, role and header.
class DielectricAlbedoTable : public DielectricTable {
 public:
  void Axes(const BakeSettings &, int size, Axis *x, Axis *y) const override;
  int DefaultDepth() const override { return kDefaultEtaSize; }
  void DepthAxis(const BakeSettings &s, int size, Axis *z) const override {
    *z = EtaAxis(size, s.depthSize == 0);
  }
  std::vector<PointCoordinate> Coordinates(const BakeSettings &) const override;
  int PlannedRoughnessAxis() const override { return 1; }
  // A 3D table has no value without eta: callers use Evaluate3D (bake,
  // eval, check and report do, through the table's depth).
  PointValue Evaluate(const BakeSettings &, double, double) const override {
    throw std::logic_error(std::string(Name()) + " is 3D: Evaluate3D takes its eta");
  }
  PointValue Evaluate3D(const BakeSettings &s, double mu, double r, double eta) const override {
    return EvaluateAlbedo(s, mu, r, eta);
  }
  // The eta = 1 slice in closed form, and the smooth limit r -> 0 (the
  // smooth interface's albedo, DielectricSmoothAlbedo) that the integrator
  // reaches at r = 1e-3.
  std::optional<SliceClosedForm> SliceClosed(const BakeSettings &s) const override;
  std::vector<LimitClaim> Limits(const BakeSettings &s) const override;
};

// The averages (glass_Eavg, spec_Eavg) differ only in what they are: each
// file gives its identity, and this class the rest. Axes r x eta.
class DielectricAverageTable final : public DielectricTable {
 public:
  struct Identity {
    const char *name;
    uint64_t seedId;
    DielectricLobes lobes;
    const char *averageOf;  // the 3D table it averages
    // The reflection-only average whose difference from this one is the
    // transmitted part that reciprocity relates between eta and 1/eta ("" for
    // the reflection-only table itself).
    const char *reciprocalMinus;
    const char *summary;
    const char *lookupComment;
    PlanRole role;
  };
  explicit DielectricAverageTable(const Identity &identity) : identity_(identity) {}
  const char *Name() const override { return identity_.name; }
  uint64_t SeedId() const override { return identity_.seedId; }
  std::string Summary() const override { return identity_.summary; }
  DielectricLobes Lobes() const override { return identity_.lobes; }
  PlanRole Role() const override { return identity_.role; }
  void Axes(const BakeSettings &s, int size, Axis *x, Axis *y) const override;
  std::vector<PointCoordinate> Coordinates(const BakeSettings &) const override;
  int PlannedRoughnessAxis() const override { return 0; }
  PointValue Evaluate(const BakeSettings &s, double r, double eta) const override {
    return EvaluateAverage(s, r, eta);
  }
  // As many samples per texel as a whole 32-texel row of the 3D table.
  uint64_t SamplesPerTexel(const BakeSettings &s) const override;
  double ReferenceCost() const override { return 32.0; }
  // No adaptive E_avg: report's reference is the panel rule; check judges
  // the texels with it as the 3D tables' (ReferenceForCheck), and through
  // the average of the 3D table's rows.
  Estimator ReferenceEstimator() const override { return Estimator::kQuadrature; }
  TableRelations Relations() const override;
  std::vector<std::shared_ptr<const SetClaim>> Claims() const override;
  // The eta = 1 slice: 0 for reflection, IndexMatchedAverage for glass.
  std::optional<SliceClosedForm> SliceClosed(const BakeSettings &s) const override;
  HeaderText Header(const Table &) const override;

 private:
  Identity identity_;
};

}  // namespace lutbake
