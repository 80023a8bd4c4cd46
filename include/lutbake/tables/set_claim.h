// What `lutbake check` asserts of a table together with the other tables of
// the set it was baked in: A + B = E (dfg), E_avg the average of E's rows
// (every average), the Kulla-Conty furnace (Eavg), the sheen's
// albedo-scaling furnace (sheen_E), C <= B / 4 (f82), the reciprocity of
// the glass averages, an LTC magnitude that is the albedo table (ltc_*).
// Each is an object its definition lists (TableDefinition::Claims), defined
// in the table's own file or, where several tables make it, here
// (set_claims.cpp); `check` (validation/check.cpp) reads the set, integrates
// every table's reference values, and lets each claim judge itself through
// a ClaimContext. So a new table's relations touch no file but its own.
#pragma once

#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "lutbake/tables/settings.h"
#include "lutbake/tables/table.h"
#include "lutbake/tables/table_definition.h"

namespace lutbake {

// A table of the checked set as `check` read it, with everything the
// checks need.
struct CheckedTable {
  const TableDefinition *def = nullptr;
  size_t index = 0;             // in AllTables(): the order of the checks
  Table table;                  // values of the primary file (EXR, else .bin, else .h)
  std::string primary;          // its path
  bool perTexelErrors = false;  // table.errors holds per-texel bounds (else errorMax)
  double statedErrorMax = 0.0;  // metadata errorMax (+ storageError)
  double storageError = 0.0;    // a half-storage header's stated rounding, when it is primary
  // storageError is half's 2^-12 (a GPU texture or source embedding in
  // half), which holds for values below 1 only: see StorageRounding.
  bool halfStorage = false;
  // The files state bounds of their stored values, rounding included
  // (metadata errorStorage, storage.h): no float rounding is allowed on top.
  bool boundsCoverStorage = false;
  BakeSettings model;                 // the model the files state (ndf, smith, fresnel, ...)
  bool usable = false;                // metadata understood: the numeric checks can run
  std::vector<double> ref, refError;  // the quadrature at every texel, same layout as values
  // Where the reference is the table's own rule: a sample of texels (flat
  // indices) and their values by the independent one (CheckIndependent).
  std::vector<size_t> independentTexels;
  std::vector<PointValue> independent;

  // The bound a texel's value claims: its own, or the stated maximum.
  double Bound(size_t i) const { return perTexelErrors ? table.errors[i] : statedErrorMax; }
  // What the storage may move the value v by: storageError, except that
  // half's rounding grows with the value (half an ulp is 2^(k - 11) at |v|
  // in [2^k, 2^(k + 1)): at most 2^-11 |v| from 1 up; burley_E reaches 1.56).
  double StorageRounding(double v) const {
    return halfStorage && std::abs(v) >= 1.0 ? 0x1p-11 * std::abs(v) : storageError;
  }
};

enum class ClaimStatus { kPass, kFail, kSkipped };

// A point of the report, named by the table's axes: {{"mu", 0.5}, ...}.
using ClaimPlace = std::vector<std::pair<std::string, double>>;

// A point a claim asks `check` to integrate by its reference rule (x, y
// in the table's axes), with the result.
struct ReferencePoint {
  double x = 0, y = 0, z = 0;
  PointValue truth;
};

// The set, as a claim sees it.
class ClaimContext {
 public:
  virtual ~ClaimContext() = default;
  // The usable table of the set whose definition is called `name`, or
  // nullptr.
  virtual const CheckedTable *Usable(const std::string &name) const = 0;
  // The model suffix the set's file names carry: "" (E, dfg, ...) or
  // "_beckmann" (E_beckmann, ...).
  virtual const std::string &Suffix() const = 0;
  // Do a and b state the same model? If not, a failed `check` result of
  // `subject` says that the set mixes models.
  virtual bool SameModel(const CheckedTable &a, const CheckedTable &b, const std::string &subject,
                         const std::string &check) = 0;
  // One result line of the report.
  virtual void Add(const std::string &subject, const std::string &check, ClaimStatus status,
                   const std::string &detail, double worst = 0.0, double allowed = 0.0,
                   ClaimPlace at = {}) = 0;
  // The furnace grid's side (check --furnace-grid).
  virtual int FurnaceGrid() const = 0;
  // The cell centres of `table`'s reference grid (SetClaim::NeedsGrid),
  // with the reference rule's values there.
  virtual const std::vector<ReferencePoint> &Grid(const CheckedTable &table) const = 0;
};

class SetClaim {
 public:
  virtual ~SetClaim() = default;
  // Where its results stand in the report: the claims of all tables by
  // order (sums 0, averages 1, Kulla-Conty furnaces 2, albedo scaling 3,
  // at-most 4, reciprocity 5, channel identities 6), then by table.
  virtual int Order() const = 0;
  // Does it need the reference rule's values on a grid of cell centres of
  // its table (ClaimContext::Grid)?
  virtual bool NeedsGrid() const { return false; }
  // Judges the claim of `self`, a table of the set, adding its results.
  virtual void Judge(const CheckedTable &self, ClaimContext &set) const = 0;
};

// The pieces claims build their verdicts from.
namespace claim_text {
// Half an ulp of float32 at v: what storing a double as float may change.
inline double FloatRounding(double v) { return std::abs(v) * 0x1p-24; }
// v to three significant digits.
std::string Short(double v);
// The point (x, y[, z]) of table t, named by its axes ("roughness" for
// perceptual roughness).
ClaimPlace At(const Table &t, double x, double y, double z = 0.0);
// "(mu 0.5, roughness 0.25)".
std::string Where(const ClaimPlace &at);

// The largest deviation of a claim over its points, and the point that
// exceeds its allowance the most (excess > 0: the claim fails there).
struct Worst {
  double deviation = 0.0, excess = -1.0, excessDeviation = 0.0, excessAllowed = 0.0;
  ClaimPlace at, atExcess;
  void Note(double dev, double allowed, const ClaimPlace &where) {
    if (dev > deviation || at.empty()) deviation = dev, at = where;
    if (dev - allowed > excess)
      excess = dev - allowed, excessDeviation = dev, excessAllowed = allowed, atExcess = where;
  }
  bool failed() const { return excess > 0.0; }
};
}  // namespace claim_text

// Claims several tables make (set_claims.cpp):
// E_avg = 2 integral E mu dmu over the rows of table `averaged`, judged by
// the midpoint rule over its texel centres (the averages: Eavg of E,
// sheen_Eavg of sheen_E, glass_Eavg of glass_E, spec_Eavg of spec_E).
std::shared_ptr<const SetClaim> AverageOfClaim(std::string averaged);
// Channel `channel` of this table is table `other`'s value (an LTC table's
// magnitude is its albedo table), at `other`'s texel centres.
std::shared_ptr<const SetClaim> ChannelIsClaim(std::string other, int channel);

}  // namespace lutbake
