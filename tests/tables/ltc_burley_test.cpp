// Table ltc_burley (issue 28): the LTC of Burley's diffuse lobe. The checks every diffuse
// lobe's LTC table passes are in ltc_lobe_table_checks.h: magnitude is
// burley_E bit for bit, fresnel within its bound of the nested adaptive
// Gauss-Kronrod reference; det M^-1 > 0, finite, bit-identical for 1 and 2
// threads, eval at a texel centre is the bake's texel, the stated lobe
// error against the next level of its rule, check passes and catches a
// texel pushed off its branch and a changed magnitude.
#include <gtest/gtest.h>

#include "ltc_lobe_table_checks.h"

namespace lutbake {
namespace {

// Measured at 64 x 64: lobe error mean 0.0157, max 0.039; leakage max 0.011.
const test::LtcLobeTable kTable{"ltc_burley", "burley_E", [](double y) { return BurleyLtcLobe(y); },
                                0.05,         0.02,       0.025};

const Table &Small() {
  static const Table table = BakeTable(TableNamed(kTable.name), test::LtcSized(10));
  return table;
}

TEST(LtcBurley, MagnitudeIsTheAlbedoTableAndFresnelWithinItsBound) {
  test::ExpectMagnitudeAndFresnel(kTable, Small());
}

TEST(LtcBurley, BitIdenticalForOneAndTwoThreads) {
  test::ExpectBitIdenticalForOneAndTwoThreads(kTable);
}

TEST(LtcBurley, EvalAtTexelCentreIsTheBakesTexel) {
  test::ExpectEvalAtTexelCentreIsTheBakesTexel(kTable, Small());
}

TEST(LtcBurley, StatedLobeErrorAgreesWithTheNextLevel) {
  test::ExpectStatedLobeErrorAgreesWithTheNextLevel(kTable, Small());
}

TEST(LtcBurley, CheckPassesAndCatchesBrokenTexels) {
  test::ExpectCheckPassesAndCatchesBrokenTexels(kTable);
}

}  // namespace
}  // namespace lutbake
