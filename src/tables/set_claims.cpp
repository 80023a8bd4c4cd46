// The claims several tables make (set_claim.h), and the text pieces every
// claim's verdict is written with.
#include <cstdio>

#include "lutbake/tables/lookup.h"
#include "lutbake/tables/set_claim.h"

namespace lutbake {

namespace claim_text {

std::string Short(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3g", v);
  return buffer;
}

ClaimPlace At(const Table &t, double x, double y, double z) {
  const auto name = [](const std::string &axis) {
    return axis == "perceptualRoughness" ? std::string("roughness") : axis;
  };
  ClaimPlace at{{name(t.x.name), x}};
  if (t.is2D()) at.emplace_back(name(t.y.name), y);
  if (t.is3D()) at.emplace_back(name(t.z.name), z);
  return at;
}

std::string Where(const ClaimPlace &at) {
  std::string s = "(";
  for (size_t i = 0; i < at.size(); ++i)
    s += (i ? ", " : "") + at[i].first + " " + Short(at[i].second);
  return s + ")";
}

}  // namespace claim_text

namespace {

using namespace claim_text;

// E_avg = 2 integral E mu dmu from E's rows, where E's rows and E_avg's
// texels sit at the same roughness: the midpoint rule over E's texel
// centres, within what it gives on exact texels plus both stated bounds.
class AverageOf final : public SetClaim {
 public:
  explicit AverageOf(std::string averaged) : averaged_(std::move(averaged)) {}
  int Order() const override { return 1; }
  void Judge(const CheckedTable &self, ClaimContext &set) const override {
    const std::string &ofName = averaged_;
    const CheckedTable &average = self;

    const CheckedTable *e = set.Usable(ofName), *a = &average;
    if (!e || !a->usable) return;
    const std::string subject = ofName + "+" + a->def->Name() + set.Suffix();
    if (!set.SameModel(*e, *a, subject, "average")) return;
    const Table &te = e->table, &ta = a->table;
    // A 3D E (mu, r, eta) averages to a 2D E_avg (r, eta): E's z is E_avg's y.
    if (DescribeAxis(te.y) != DescribeAxis(ta.x) || te.x.min != 0.0 || te.x.max != 1.0 ||
        (te.is3D() && DescribeAxis(te.z) != DescribeAxis(ta.y))) {
      set.Add(subject, "average", ClaimStatus::kSkipped,
              "E's rows and E_avg's texels are not at the same roughness, or E does not span mu in "
              "[0, 1]");
      return;
    }
    double worst = 0.0, worstExcess = -1.0, excessValue = 0, excessAllowed = 0;
    std::vector<std::pair<std::string, double>> at, atExcess;
    const int n = te.width();
    for (int z = 0; z < te.depth(); ++z)
      for (int y = 0; y < te.height(); ++y) {
        // The midpoint rule over E's texel centres, for the table and for exact texels.
        double rule = 0.0, ruleExact = 0.0, ruleRefError = 0.0;
        for (int x = 0; x < n; ++x) {
          const double w = 2.0 * te.x.TexelCenter(x) / n;
          rule += w * te.values[te.index(x, y, z, 0)];
          ruleExact += w * e->ref[te.index(x, y, z, 0)];
          ruleRefError += w * e->refError[te.index(x, y, z, 0)];
        }
        const size_t k = ta.index(y, z, 0);  // E_avg's texel at E's row y of slice z
        const double eavg = ta.values[k], eavgRef = a->ref[k];
        const double dev = std::abs(rule - eavg);
        const double allowed = std::abs(ruleExact - eavgRef) + e->statedErrorMax +
                               a->statedErrorMax + ruleRefError + a->refError[k] +
                               2.0 * FloatRounding(eavg);
        const double r = ta.x.TexelCenter(y), eta = ta.y.TexelCenter(z);
        if (dev > worst) worst = dev, at = At(ta, r, eta);
        if (dev - allowed > worstExcess)
          worstExcess = dev - allowed, excessValue = dev, excessAllowed = allowed,
          atExcess = At(ta, r, eta);
      }
    if (worstExcess > 0.0)
      set.Add(subject, "average", ClaimStatus::kFail,
              "E_avg differs from 2 sum E mu / N over E's row by " + Short(excessValue) + " at " +
                  Where(atExcess) + ", more than the " + Short(excessAllowed) +
                  " the bounds and the midpoint rule on exact texels allow",
              excessValue, excessAllowed, atExcess);
    else
      set.Add(subject, "average", ClaimStatus::kPass,
              "E_avg against the midpoint rule 2 sum E mu / N over each row of E: max deviation " +
                  Short(worst) + " at " + Where(at),
              worst, 0.0, at);
  }

 private:
  std::string averaged_;
};

// A channel that is another table's value (ltc_ggx's magnitude = E), at
// that table's texel centres, this one interpolated there: within what
// interpolating exact texels gives, the bounds and float rounding.
class ChannelIs final : public SetClaim {
 public:
  ChannelIs(std::string other, int channel) : other_(std::move(other)), channel_(channel) {}
  int Order() const override { return 6; }
  void Judge(const CheckedTable &self, ClaimContext &set) const override {
    const CheckedTable &t = self;

    const CheckedTable *e = set.Usable(other_);
    if (!e || !t.usable || e->table.is3D() || t.table.is3D()) return;
    const std::string subject = std::string(t.def->Name()) + "+" + other_ + set.Suffix();
    if (!set.SameModel(t, *e, subject, "channel")) return;
    const int c = channel_;
    const std::string claim =
        t.def->ChannelMeanings()[static_cast<size_t>(c)] + " = " + e->def->ChannelMeanings()[0];
    const Table &te = e->table, &tt = t.table;
    Worst worst;
    for (int y = 0; y < te.height(); ++y)
      for (int x = 0; x < te.width(); ++x) {
        const double px = te.x.TexelCenter(x), py = te.y.TexelCenter(y);
        const size_t i = te.index(x, y, 0);
        const double v = Lookup(tt, px, py, c);
        const double exactDev = std::abs(Lookup(tt, t.ref, px, py, c) - e->ref[i]);
        const double allowed = exactDev + t.statedErrorMax + e->Bound(i) + e->refError[i] +
                               Lookup(tt, t.refError, px, py, c) + FloatRounding(v) +
                               FloatRounding(te.values[i]);
        worst.Note(std::abs(v - te.values[i]), allowed, At(te, px, py));
      }
    const std::string where = "at " + std::string(e->def->Name()) + "'s " +
                              std::to_string(te.width() * te.height()) + " texel centres (" +
                              t.def->Name() + " interpolated)";
    if (worst.failed())
      set.Add(subject, "channel", ClaimStatus::kFail,
              claim + " fails " + where + ": " + Short(worst.excessDeviation) + " apart at " +
                  Where(worst.atExcess) + ", more than the " + Short(worst.excessAllowed) +
                  " allowed",
              worst.excessDeviation, worst.excessAllowed, worst.atExcess);
    else
      set.Add(subject, "channel", ClaimStatus::kPass,
              claim + " " + where + ": max difference " + Short(worst.deviation) + " at " +
                  Where(worst.at),
              worst.deviation, 0.0, worst.at);
  }

 private:
  std::string other_;
  int channel_;
};

}  // namespace

std::shared_ptr<const SetClaim> AverageOfClaim(std::string averaged) {
  return std::make_shared<AverageOf>(std::move(averaged));
}

std::shared_ptr<const SetClaim> ChannelIsClaim(std::string other, int channel) {
  return std::make_shared<ChannelIs>(std::move(other), channel);
}

}  // namespace lutbake
