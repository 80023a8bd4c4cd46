// Table ltc_oren_nayar (issue 28): the LTC of the qualitative Oren-Nayar lobe. The checks every
// diffuse lobe's LTC table passes are in ltc_lobe_table_checks.h: magnitude is oren_nayar_E bit for
// bit, fresnel within its bound of the nested adaptive Gauss-Kronrod reference; det M^-1 > 0,
// finite, bit-identical for 1 and 2 threads, eval at a texel centre is the bake's texel, the stated
// lobe error against the next level of its rule, check passes and catches a texel pushed off its
// branch and a changed magnitude.
#include <gtest/gtest.h>

#include "ltc_lobe_table_checks.h"

namespace lutbake {
namespace {

// Measured at 64 x 64: lobe error mean 0.0325, max 0.084; leakage max 0.017.
const test::LtcLobeTable kTable{
    "ltc_oren_nayar",
    "oren_nayar_E",
    [](double y) { return OrenNayarLtcLobe(OrenNayarVariant::kQualitative, y); },
    0.1,
    0.025,
    0.045};

const Table &Small() {
  static const Table table = BakeTable(TableNamed(kTable.name), test::LtcSized(10));
  return table;
}

TEST(LtcOrenNayar, MagnitudeIsTheAlbedoTableAndFresnelWithinItsBound) {
  test::ExpectMagnitudeAndFresnel(kTable, Small());
}

TEST(LtcOrenNayar, BitIdenticalForOneAndTwoThreads) {
  test::ExpectBitIdenticalForOneAndTwoThreads(kTable);
}

TEST(LtcOrenNayar, EvalAtTexelCentreIsTheBakesTexel) {
  test::ExpectEvalAtTexelCentreIsTheBakesTexel(kTable, Small());
}

TEST(LtcOrenNayar, StatedLobeErrorAgreesWithTheNextLevel) {
  test::ExpectStatedLobeErrorAgreesWithTheNextLevel(kTable, Small());
}

TEST(LtcOrenNayar, CheckPassesAndCatchesBrokenTexels) {
  test::ExpectCheckPassesAndCatchesBrokenTexels(kTable);
}

}  // namespace
}  // namespace lutbake
