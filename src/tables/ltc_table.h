// What the LTC tables (ltc_ggx, ltc_sheen, ltc_burley, ltc_oren_nayar)
// share: the six channels of issue 28 and what a fitted table does with
// them, for any lobe. A table states its lobe and its integrals; this part
// fits, bakes, evaluates and measures. Private to the tables layer.
//
// Channels, in this order:
//   m00, m20, m02, m22  M^-1 = [[m00, 0, m02], [0, 1, 0], [m20, 0, m22]]
//                       (normalised so that its middle element is 1), acting
//                       on directions in the frame where n = +z and the view
//                       is v = (sqrt(1 - mu^2), 0, mu); det M^-1 > 0;
//   magnitude           int f (n.l) dl: the lobe's directional albedo, its
//                       albedo table's value at the point;
//   fresnel             int f (n.l) (1 - v.h)^5 dl,
// so that the lobe is approximated by magnitude D(l), D the LTC density, and
// a Schlick F by F0 magnitude + (1 - F0) fresnel.
//
// The fit (integrators/ltc_fit.h) minimises the L1 error on the sphere by
// the lobe's deterministic quadrature, each texel started from its
// neighbour's along a path that keeps neighbours on one branch (FitLtcGrid:
// the largest y first, from the largest mu down, then each mu from the
// largest y down); eval at a point walks the same path through the default
// grid (FitLtcPoint), so that at a texel centre it gives the bake's texel
// bit for bit. The matrix is the fit itself (its bound 0: what it is worth
// is the lobe error); magnitude and fresnel carry their quadrature's
// bounds. Beside the values every texel states (T.fit.exr, and summarised
// in the metadata) its lobe error int_{l.z>0} |f (n.l) - magnitude D| dl /
// magnitude, its worst relative error of the irradiance from
// LtcTestRectangles (clipped at the horizon), and its leakage int_{l.z<0} D
// dl, each for the matrix as stored in float32.
#pragma once

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "lutbake/integrators/ltc_fit.h"
#include "lutbake/tables/table_definition.h"

namespace lutbake {

// A table's lobe family over its y axis (perceptual roughness, sheen
// roughness or sigma).
class LtcLobeFamily {
 public:
  virtual ~LtcLobeFamily() = default;
  // The lobe at y.
  virtual LtcLobe LobeAt(const BakeSettings &s, double y) const = 0;
  // magnitude and fresnel (values and bounds) into channels 4 and 5, with
  // the settings' estimator (the quadrature, or the adaptive reference).
  virtual void Moments(const BakeSettings &s, double mu, double y, PointValue *out) const = 0;
  // Throws std::domain_error outside the accepted point.
  virtual void CheckPoint(const BakeSettings &s, double mu, double y) const = 0;
  // What the stated lobe error's rule is and how close it is (metadata).
  virtual std::string LobeErrorRule() const = 0;
};

// The fitted-table behaviour of TableDefinition for a lobe family, over the
// axes x = mu and y of Model (a TableDefinition with the table's model).
template <class Model>
class LtcTableDefinition : public Model, public LtcLobeFamily {
 public:
  using Model::Model;
  std::vector<std::string> ChannelNames() const override {
    return {"m00", "m20", "m02", "m22", "magnitude", "fresnel"};
  }
  std::vector<std::string> ChannelMeanings() const override { return ChannelNames(); }
  int DefaultSize() const override { return 64; }
  bool Sampled() const override { return false; }
  std::string EstimatorProblem(Estimator e) const override {
    return e == Estimator::kQuadrature
               ? ""
               : std::string(this->Name()) + " is fitted by its deterministic quadrature only";
  }
  ValueClaim Range(const BakeSettings &) const override {
    return {-HUGE_VAL, HUGE_VAL, false, "finite"};
  }
  PointValue Evaluate(const BakeSettings &s, double mu, double y) const override;
  PointValue EvaluateIntegrals(const BakeSettings &s, double mu, double y) const override;
  bool BakedWhole() const override { return true; }
  uint64_t BakeWhole(const BakeSettings &s, Table *table) const override;
  std::vector<std::string> FitMapNames() const override {
    return {"lobeError", "polygonError", "leakage"};
  }
  Metadata FitMetadata(const Table &table) const override;
  std::vector<std::pair<std::string, double>> PointFitErrors(const BakeSettings &s, double mu,
                                                             double y,
                                                             const PointValue &v) const override;
  int FittedChannels() const override { return 4; }
  std::vector<double> FitParameters(const double *v) const override;
  std::string TexelProblem(const double *v) const override;

 protected:
  virtual LtcFitSettings FitSettings() const {
    LtcFitSettings f;
    f.moments = false;  // Moments above
    return f;
  }
  // The header's notes on the LTC layout (after the table's own).
  static void AddLtcNotes(HeaderText *text, const std::string &magnitudeIs);
};

// Below this magnitude a texel carries no light (LtcFitParameters).
inline constexpr double kLtcNoLight = 1e-6;

// The pieces, for any definition and lobe family (ltc_table.cpp).
PointValue LtcEvaluate(const TableDefinition &def, const LtcLobeFamily &lobes,
                       const LtcFitSettings &fit, const BakeSettings &s, double mu, double y);
PointValue LtcEvaluateIntegrals(const LtcLobeFamily &lobes, const BakeSettings &s, double mu,
                                double y);
uint64_t LtcBakeWhole(const LtcLobeFamily &lobes, const LtcFitSettings &fit,
                      const std::vector<std::string> &mapNames, const BakeSettings &s,
                      Table *table);
Metadata LtcFitMetadata(const Table &table, const std::string &lobeErrorRule);
LtcErrors LtcPointErrors(const LtcLobeFamily &lobes, const BakeSettings &s, double mu, double y,
                         const PointValue &v);
std::vector<double> LtcFitParameters(const double *v);
std::string LtcTexelProblem(const double *v);
void AddLtcHeaderNotes(HeaderText *text, const std::string &magnitudeIs);
// fresnel of a lobe smooth over the hemisphere (the diffuse tables) into
// channel 5 with its bound: the light-direction rule at level 2, bounded by
// |level 2 - level 1| + 1e-12; with the adaptive estimator the nested
// Gauss-Kronrod reference (IntegrateLobeMomentsAdaptive) at the settings'
// adaptive tolerance.
void LtcDiffuseFresnel(const LtcLobe &lobe, const BakeSettings &s, double mu, PointValue *out);

template <class Model>
PointValue LtcTableDefinition<Model>::Evaluate(const BakeSettings &s, double mu, double y) const {
  this->CheckPoint(s, mu, y);
  return LtcEvaluate(*this, *this, FitSettings(), s, mu, y);
}
template <class Model>
PointValue LtcTableDefinition<Model>::EvaluateIntegrals(const BakeSettings &s, double mu,
                                                        double y) const {
  this->CheckPoint(s, mu, y);
  return LtcEvaluateIntegrals(*this, s, mu, y);
}
template <class Model>
uint64_t LtcTableDefinition<Model>::BakeWhole(const BakeSettings &s, Table *table) const {
  return LtcBakeWhole(*this, FitSettings(), FitMapNames(), s, table);
}
template <class Model>
Metadata LtcTableDefinition<Model>::FitMetadata(const Table &table) const {
  return LtcFitMetadata(table, this->LobeErrorRule());
}
template <class Model>
std::vector<std::pair<std::string, double>> LtcTableDefinition<Model>::PointFitErrors(
    const BakeSettings &s, double mu, double y, const PointValue &v) const {
  const LtcErrors e = LtcPointErrors(*this, s, mu, y, v);
  return {{"lobeError", e.lobe}, {"polygonError", e.polygon}, {"leakage", e.leakage}};
}
template <class Model>
std::vector<double> LtcTableDefinition<Model>::FitParameters(const double *v) const {
  return LtcFitParameters(v);
}
template <class Model>
std::string LtcTableDefinition<Model>::TexelProblem(const double *v) const {
  return LtcTexelProblem(v);
}
template <class Model>
void LtcTableDefinition<Model>::AddLtcNotes(HeaderText *text, const std::string &magnitudeIs) {
  AddLtcHeaderNotes(text, magnitudeIs);
}

}  // namespace lutbake
