// Reading a table the way an engine does (SPEC section 4): bilinear
// interpolation between texel centres, clamped at the edges, so that at a
// texel centre the lookup returns exactly that texel. In double, for
// `lutbake check` and the tests; the generated headers do the same in their
// own code.
#pragma once

#include "lutbake/tables/table.h"

namespace lutbake {

// The texel interval of `value` on `axis`: lower texel *i0 and the weight
// *w of texel i0 + 1, clamped to the centres of the first and last texel.
void LookupCoordinate(const Axis &axis, double value, int *i0, double *w);

// Bilinear lookup of channel c at (x, y) in axis units (y ignored for a 1D
// table), over `values` laid out as table.values (the table's own values,
// or a same-shaped array such as its errors or reference values).
double Lookup(const Table &table, const std::vector<double> &values, double x, double y, int c);
inline double Lookup(const Table &table, double x, double y, int c = 0) {
  return Lookup(table, table.values, x, y, c);
}

// Trilinear lookup of channel c at (x, y, z) in a 3D table (the same
// texel-centre rule on each axis; listed axes interpolate in their values).
double Lookup(const Table &table, const std::vector<double> &values, double x, double y, double z,
              int c);

// 2 integral_0^1 L(mu, y) mu dmu for the lookup L of channel c of a table
// whose x axis is mu on [0, 1]: exact, because L is piecewise linear in mu
// (constant outside the first and last centre).
double LookupMuAverage(const Table &table, const std::vector<double> &values, double y, int c);

}  // namespace lutbake
