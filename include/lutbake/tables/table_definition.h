// What a table is, in one place. Every table lutbake bakes is one
// TableDefinition (src/tables/<name>.cpp), listed once in the registry
// (src/tables/registry.cpp). The baker, the readers and writers, `eval`,
// `check`, `report`, `plan` and the command line ask the definitions; none
// of them knows a table by name.
//
// A definition states:
//   identity     its name (command line, file stems, metadata 'table') and a
//                seed number that no other table uses;
//   what it is   the integral (Formula), its channels and what each holds;
//   axes         the default axes, the point coordinates `eval` takes for
//                them, and the accepted range of each;
//   model        the options that choose its model, the metadata that
//                records it, and how to read that back from a file;
//   integration  Evaluate(settings, x, y): the value and its bound at any
//                point of its axes, with the settings' estimator;
//   claims       what `check` asserts: the value range, monotonicity, a
//                closed form, and claims about it with other tables of its
//                set (set_claim.h: channels that sum to another table, an
//                average over another's rows, a furnace);
//   uses         the role a bake plan needs it for, the header's notes and
//                helper functions, and the shader helpers (lutbake.<ext>)
//                that use its texture lookups.
// To add a table: write its definition (one .cpp under src/tables/, using
// the integrators below), add it to the registry, and test it.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "lutbake/tables/model_part.h"
#include "lutbake/tables/settings.h"
#include "lutbake/tables/table.h"

namespace lutbake {

// One coordinate of a point of a table: the `lutbake eval` option that
// gives it (without the dashes; also its JSON key and its label in eval's
// text output) and the values it accepts.
struct PointCoordinate {
  std::string option;  // "mu", "roughness", "f0", "eta", "k"
  double min = 0.0, max = 1.0;
  bool zeroAllowed = false;  // 0 accepted besides [min, max]
  std::string accepted;      // the accepted values in words, for messages
  // What the coordinate is, for eval's help ("view cosine mu = n.v"); the
  // first table (registry order) with the option gives its help.
  std::string meaning;
  bool required = true;  // false: 0 when not given (a conductor's k)
  bool Accepts(double v) const { return (v >= min && v <= max) || (zeroAllowed && v == 0.0); }
};

// What `lutbake check` asserts of every value of a table.
struct ValueClaim {
  double lower = 0.0;
  double upper = 1.0;         // HUGE_VAL: no upper limit
  bool sumAtMostOne = false;  // the channels add up to at most 1
  std::string text;           // the claim in words: "in [0, 1]"
};

// A monotonicity `check` asserts along the x axis (every row), from x = from
// on: direction +1 non-decreasing, -1 non-increasing; 0 claims nothing and
// says why in `skipped`.
struct MonotonicClaim {
  int direction = 0;
  double from = -1e300;
  std::string claim;    // "E_avg non-increasing in roughness"
  std::string skipped;  // direction 0: why nothing is claimed
};

// A closed form every texel must equal to float rounding.
struct ClosedForm {
  std::string subject;  // "Schlick F_avg"
  std::string formula;  // "20/21 F0 + 1/21"
  std::function<double(double x, double y)> value;
};

// A closed form a table takes where one of its axes sits at one value (the
// rough-dielectric tables at eta = 1): every texel of that slice must equal
// it within the texel's own bound. `value` takes the other coordinates in
// axis order (x, then y or z; a 2D table's second is 0).
struct SliceClosedForm {
  std::string subject;  // "glass_E at eta = 1"
  std::string formula;  // "(1 + Lambda(mu)) / (1 + 2 Lambda(mu))"
  int axis = 2;         // 1 = y, 2 = z
  double at = 1.0;      // the axis value of the slice
  std::function<double(double a, double b)> value;
};

// A limit the table's integrator reaches where its axes hold no texel (the
// smooth interface, r -> 0): `check` evaluates the definition at `near`
// on that axis, at the texel centres of the other axes, and compares with
// `value` there within the value's bound plus `slack`; points where
// `excluded` is true (a branch point of the closed form) are left out.
struct LimitClaim {
  std::string subject;  // "glass_E as r -> 0"
  std::string formula;  // "1 (a smooth interface scatters everything)"
  int axis = 1;         // the axis that goes to the limit
  double near = 1e-3;   // the coordinate evaluated
  double slack = 0.0;   // what the distance from the limit may add
  std::string slackText;
  std::function<double(double a, double b)> value;
  std::function<bool(double a, double b)> excluded;
};

// How a table stands to another of its set, for what a bake writes beside
// them (the Kulla-Conty helpers of kulla_conty.h and lutbake.<ext>). What
// `check` asserts of the two is a claim (Claims, set_claim.h).
struct TableRelations {
  // This table is 2 integral_0^1 T(mu) mu dmu over the rows of table T
  // (Eavg of E): its x axis is T's y axis.
  std::string averageOf;
  // With averageOf: the Kulla-Conty lobe of T and this table, whose helpers
  // a header or shader bake of both writes.
  bool kullaConty = false;
};

class SetClaim;  // set_claim.h

// Why a bake plan (plans/plan.h) needs a table.
enum class PlanRole {
  kNone,                // never planned
  kImageBasedLighting,  // split-sum IBL of the specular lobe (dfg)
  kEnergyCompensation,  // Kulla-Conty multiple scattering (E, Eavg)
  kFresnelAverage,      // F_avg of compensated non-Schlick Fresnel (Favg)
  kSheenAlbedoScaling,  // KHR_materials_sheen's albedo scaling (sheen_E)
  kGlassCompensation,   // energy compensation of rough transmission (glass_E, glass_Eavg)
  // Energy-conserving layering under a dielectric coat or specular layer:
  // the base is scaled by 1 - E of the coat (spec_E, spec_Eavg).
  kDielectricLayering,
  // The F82-tint metal's third split-sum term, specular albedo
  // F0 A + F90 B - a C (f82's C, beside dfg's A and B).
  kF82ImageBasedLighting,
  // Rectangular area lights by linearly transformed cosines: the LTC fit of
  // each lobe a lit material uses (ltc_ggx), when a manifest asks for them.
  kAreaLights,
  // The same for the sheen lobe (ltc_sheen), where a lit material has a
  // sheen layer.
  kSheenAreaLights,
};

// What a generated C++ header says about the table besides its axes.
struct HeaderText {
  std::vector<std::string> notes;      // comment lines (without "// ")
  std::vector<std::string> constants;  // declarations, one per line
  // What follows "// Layout: kValues[(y * kWidth + x) * kChannels + c]",
  // line ends included.
  std::string layout = "; one channel.\n";
  std::string lookupComment;  // the line above lookup_<name>, without "// "
  // Inline functions after lookup_<name>; `lookup` is that function's name.
  std::function<std::string(const std::string &lookup)> helpers;
};

// A piece of the shader code file lutbake.<ext> (--shader): helper
// functions of a table, in one of the four languages (source_text::Dialect).
// The file holds every table's texture lookup, then the pieces of all its
// tables ordered by `order` (the split sum 0, the F82 term 1, Kulla-Conty 2,
// sheen 3, area lights 4), tables in the set's order within one `order`;
// a piece whose `key` an earlier piece had is left out, so that functions
// several tables share (the Kulla-Conty core, the LTC polygon integral) are
// written once.
struct ShaderPiece {
  int order = 0;
  std::string key;
  std::string code;
};

namespace source_text {
class Dialect;
}

// The first table of `set` whose definition has `role`, or nullptr.
const TableDefinition *FindRole(const std::vector<Table> &set, PlanRole role);

class TableDefinition {
 public:
  virtual ~TableDefinition() = default;

  // ---- identity -------------------------------------------------------
  // "E", "dfg", "sheen_E": the command line's name, the file stem and the
  // metadata key 'table'.
  virtual const char *Name() const = 0;
  // Hashed into the seeds of its sampled points (PointSeed): unique, and
  // never changed, so that a table's samples stay the same.
  virtual uint64_t SeedId() const = 0;
  // One line: what the table holds, for --help and `lutbake tables`.
  virtual std::string Summary() const = 0;

  // ---- channels -------------------------------------------------------
  // EXR channel names ({"Y"}, {"R", "G"}) and what each holds ({"E"},
  // {"A", "B"}: the names eval and the headers use).
  virtual std::vector<std::string> ChannelNames() const { return {"Y"}; }
  virtual std::vector<std::string> ChannelMeanings() const { return {Name()}; }
  // The metadata key channelLayout: "Y = E".
  virtual std::string ChannelLayout() const { return "Y = " + std::string(Name()); }
  int Channels() const { return static_cast<int>(ChannelNames().size()); }

  // ---- axes -----------------------------------------------------------
  virtual int DefaultSize() const { return 32; }
  // The default axes with `size` texels on each (a 1D table: y.count = 1,
  // y.name empty).
  virtual void Axes(const BakeSettings &settings, int size, Axis *x, Axis *y) const = 0;
  // A 3D table's third axis (z, outermost in the files) with `size` texels,
  // and its default size; the default leaves *z as it is for 1D and 2D
  // tables (count 1, no name).
  virtual int DefaultDepth() const { return 1; }
  virtual void DepthAxis(const BakeSettings &, int /*size*/, Axis *z) const {
    *z = LinearAxis("", 0.0, 1.0, 1);
  }
  // The point coordinates: x, then y for a 2D table, then z for a 3D one,
  // as eval takes them.
  virtual std::vector<PointCoordinate> Coordinates(const BakeSettings &settings) const = 0;
  // Every eval option any variant of the table takes (Favg: f0, eta, k).
  virtual std::vector<std::string> CoordinateOptions() const;
  // The axis (0 = x, 1 = y) a bake plan narrows to the roughness its
  // materials use, or -1 (plans/plan.h).
  virtual int PlannedRoughnessAxis() const { return -1; }

  // ---- model ----------------------------------------------------------
  // The part that states its model (model_part.h); the five questions
  // below ask it.
  virtual const TableModel &ModelPart() const = 0;
  // The command-line options that choose its model: "ndf", "smith", ...
  std::vector<std::string> ModelOptions() const { return ModelPart().Options(); }
  // The metadata that records the model, before the axes (ndf, smith,
  // fresnel, ...), and the key 'alpha' after them.
  Metadata ModelMetadata(const BakeSettings &settings) const {
    return ModelPart().Records(settings);
  }
  std::string AlphaMetadata(const BakeSettings &settings) const {
    return ModelPart().Alpha(settings);
  }
  // The model in words ("ggx correlated", "fresnel schlick").
  std::string DescribeModel(const BakeSettings &settings) const {
    return ModelPart().Describe(settings);
  }
  // Do two settings give this table the same model?
  bool SameModel(const BakeSettings &a, const BakeSettings &b) const {
    return ModelPart().Same(a, b);
  }
  // Labels of a point besides its coordinates (eval's text and JSON):
  // Favg's {"fresnel", "schlick"}.
  virtual Metadata PointLabels(const BakeSettings &) const { return {}; }
  // Reads the model from a file's metadata (ModelPart().Read) and checks
  // the axes (lutbake check) into `settings`; returns false, with the
  // reasons, when the file does not describe a table lutbake writes.
  virtual bool ReadModel(const Table &table, BakeSettings *settings,
                         std::vector<std::string> *problems) const = 0;

  // ---- integration ----------------------------------------------------
  // Does it take the sampled estimators and --tolerance? (F_avg is always
  // integrated by its deterministic rule.)
  virtual bool Sampled() const { return true; }
  // Its value (up to kMaxTableChannels channels) and error bound at axis values (x, y),
  // with the settings' estimator. Throws std::domain_error outside the
  // accepted coordinates.
  virtual PointValue Evaluate(const BakeSettings &settings, double x, double y) const = 0;
  // The same at (x, y, z) for a 3D table; the default (1D and 2D tables)
  // ignores z.
  virtual PointValue Evaluate3D(const BakeSettings &settings, double x, double y,
                                double /*z*/) const {
    return Evaluate(settings, x, y);
  }
  // Samples per texel of a fixed-sample bake (0: deterministic).
  virtual uint64_t SamplesPerTexel(const BakeSettings &settings) const;
  // The metadata words for the deterministic integrators: the estimator
  // key, and the errorBound key of quadrature texels.
  virtual std::string QuadratureDescription(const BakeSettings &settings) const;
  virtual std::string QuadratureBound(const BakeSettings &settings) const;
  // Relative cost of one reference value, for scheduling (E_avg
  // integrates a whole row: high).
  virtual double ReferenceCost() const { return 1.0; }
  // The estimator `lutbake check` judges the table's texels and points
  // with: the adaptive quadrature, an independent method, unless the
  // definition says why not (and what judges it instead).
  virtual Estimator ReferenceEstimator() const { return Estimator::kAdaptiveQuadrature; }
  // What `lutbake check` computes a texel's reference with, given the
  // table's stated errorMax and --reference-tolerance: the estimator, the
  // tolerance (what the panel rule is asked; check asks the adaptive one for
  // 2 kQuadratureErrorFactor x it), and the panel rule's tolerance for the
  // random points' truth, which judges nothing (0: check's own choice). The
  // default: ReferenceEstimator() at 1/64 of errorMax, not below the option
  // nor above 1e-6.
  struct CheckReference {
    Estimator estimator = Estimator::kAdaptiveQuadrature;
    double tolerance = 1e-8;
    double pointTolerance = 0.0;
  };
  virtual CheckReference ReferenceForCheck(double statedErrorMax, double optionTolerance) const;
  // Why the table cannot use an estimator ("" when it can): sheen has no
  // cosine-weighted sampler, for one.
  virtual std::string EstimatorProblem(Estimator) const { return ""; }
  // What the sampled estimators sample, when their names do not say it
  // (metadata 'estimator'), and the unseen-event term of their bound.
  virtual std::string SamplerNote(const BakeSettings &) const { return ""; }
  virtual std::string UnseenEventTerm() const { return "4.6 / N"; }

  // ---- fitted tables ----------------------------------------------------
  // A table whose texels depend on one another (an LTC fit, each texel
  // started from its neighbour's so that neighbours stay on one branch) is
  // baked whole: BakeWhole fills table->values and table->errors (its axes,
  // channels and sizes are set, the values zero) and the per-texel maps of
  // FitMapNames (table->fitMaps), bit-identically for any thread count, and
  // returns the integrand evaluations it spent. FitMetadata summarises the
  // maps for every file's metadata. The default (every integrated table):
  // not baked whole; the baker evaluates each texel alone with Evaluate.
  virtual bool BakedWhole() const { return false; }
  virtual uint64_t BakeWhole(const BakeSettings &, Table *) const { return 0; }
  virtual std::vector<std::string> FitMapNames() const { return {}; }
  virtual Metadata FitMetadata(const Table &) const { return {}; }
  // The same measures at a point for the channel values v (what Evaluate
  // gave, or a texel as stored: eval prints them beside the values, check
  // recomputes them): {"lobeError", e}, ...; none for an integrated table.
  virtual std::vector<std::pair<std::string, double>> PointFitErrors(
      const BakeSettings &, double /*x*/, double /*y*/, const PointValue & /*v*/) const {
    return {};
  }
  // The fit's own parameters of a texel's channels, in which the fit varies
  // smoothly over a branch and jumps where neighbours lie on different
  // branches (ltc_ggx: theta*, log A, log rho, beta of ltc_fit.h): check
  // looks for a step between neighbours far larger than the steps beside it.
  // Empty for a texel whose matrix does not matter (an LTC texel that
  // carries no light): it takes part in no step.
  virtual std::vector<double> FitParameters(const double * /*channels*/) const { return {}; }
  // How many leading channels are the fit (ltc_ggx's four entries of M^-1),
  // not integrals: check judges them by the measures above, not against a
  // quadrature, and TexelProblem says what makes a texel's fit unusable
  // ("det M^-1 = -0.1 <= 0"; "" when it is usable).
  virtual int FittedChannels() const { return 0; }
  virtual std::string TexelProblem(const double * /*channels*/) const { return ""; }
  // The integrated channels alone at (x, y) (check's reference and random
  // points), the fitted ones NaN; the default (every integrated table):
  // Evaluate.
  virtual PointValue EvaluateIntegrals(const BakeSettings &settings, double x, double y) const {
    return Evaluate(settings, x, y);
  }

  // ---- fitted closed forms (--format fit) --------------------------------
  // The domain {xLo, xHi, yLo, yHi} of a fitted closed form of the table, in
  // its point coordinates (a 1D table: y ignored); the default: each
  // coordinate's accepted range (0 where 0 is accepted). A table whose
  // value is unbounded at an edge narrows it (sheen_E's Charlie albedo
  // grows as 1 / mu).
  virtual std::array<double, 4> FitDomain(const BakeSettings &settings) const;
  // The coordinate maps a fit tries: by default those the fitter knows for
  // the table's dimension; a table that changes by about as much per decade
  // of both coordinates asks for logarithms of x + logShift and of y
  // (FitMap::kLogXY; the domain's low ends then above 0).
  struct FitCoordinates {
    bool logarithmic = false;
    double logShift = 0.0;
  };
  virtual FitCoordinates FitCoordinateMaps(const BakeSettings &) const { return {}; }

  // ---- claims ---------------------------------------------------------
  virtual ValueClaim Range(const BakeSettings &) const { return {0.0, 1.0, false, "in [0, 1]"}; }
  virtual std::optional<MonotonicClaim> Monotonic(const BakeSettings &) const { return {}; }
  virtual std::optional<ClosedForm> Closed(const BakeSettings &) const { return {}; }
  virtual std::optional<SliceClosedForm> SliceClosed(const BakeSettings &) const { return {}; }
  virtual std::vector<LimitClaim> Limits(const BakeSettings &) const { return {}; }
  virtual TableRelations Relations() const { return {}; }
  // What `check` asserts of it together with other tables of its set (A +
  // B = E, an average of another table's rows, a furnace, ...): objects
  // that judge themselves (set_claim.h), defined in the table's file or,
  // where several tables make one, in set_claims.cpp.
  virtual std::vector<std::shared_ptr<const SetClaim>> Claims() const { return {}; }

  // ---- uses -----------------------------------------------------------
  virtual PlanRole Role() const { return PlanRole::kNone; }
  virtual HeaderText Header(const Table &table) const = 0;
  // The shader helpers of `table` (this definition's) in a file that holds
  // the tables `set`, this one among them: a helper that needs another
  // table (Kulla-Conty's E beside Eavg, the F82 term beside dfg) is given
  // only when that table is in the set. None by default.
  virtual std::vector<ShaderPiece> ShaderHelpers(const source_text::Dialect &,
                                                 const Table & /*table*/,
                                                 const std::vector<Table> & /*set*/) const {
    return {};
  }
};

// Every table, in the order the command line lists them.
const std::vector<const TableDefinition *> &AllTables();
// The table called `name`, or nullptr.
const TableDefinition *FindTable(std::string_view name);
// The table called `name`; throws std::invalid_argument for an unknown name.
const TableDefinition &TableNamed(std::string_view name);
// "E, Eavg, Favg, dfg, ...": every name, for messages.
std::string TableNameList();

// The value of a metadata key; a missing key adds "key 'K' missing" to
// `problems` and gives "" (for ReadModel).
std::string RequiredMetadata(const Table &table, const std::string &key,
                             std::vector<std::string> *problems);

// The seed of a sampled point's independent random points (vndf-random,
// cosine, uniform): a hash of the table's seed number, the point's
// coordinates (their bit patterns) and the user's seed. A bake seeds each
// texel with the seed of its centre; scrambled Sobol points are shared by a
// whole table instead (point_blocks.h). Either way `lutbake eval` at a texel
// centre with the bake's settings reproduces that texel bit for bit.
uint64_t PointSeed(uint64_t tableSeedId, double x, double y, uint64_t seed);

}  // namespace lutbake
