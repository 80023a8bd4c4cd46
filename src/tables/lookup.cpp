#include "lutbake/tables/lookup.h"

#include <algorithm>
#include <cmath>

namespace lutbake {

void LookupCoordinate(const Axis &axis, double value, int *i0, double *w) {
  if (axis.count <= 1) {
    *i0 = 0;
    *w = 0.0;
    return;
  }
  // A NaN coordinate (a NaN value asked for) is read at the first texel:
  // std::clamp passes NaN through, and its cast to int is undefined.
  const double coordinate = axis.TexelCoordinate(value);
  const double t = std::isnan(coordinate) ? 0.0 : std::clamp(coordinate, 0.0, axis.count - 1.0);
  const int i = std::min(static_cast<int>(t), axis.count - 2);
  *i0 = i;
  *w = t - i;
}

double Lookup(const Table &table, const std::vector<double> &values, double x, double y, int c) {
  int x0, y0;
  double wx, wy;
  LookupCoordinate(table.x, x, &x0, &wx);
  LookupCoordinate(table.y, table.is2D() ? y : 0.0, &y0, &wy);
  const int x1 = table.width() > 1 ? x0 + 1 : x0;
  const int y1 = table.height() > 1 ? y0 + 1 : y0;
  const auto at = [&](int ix, int iy) { return values[table.index(ix, iy, c)]; };
  return (1.0 - wy) * ((1.0 - wx) * at(x0, y0) + wx * at(x1, y0)) +
         wy * ((1.0 - wx) * at(x0, y1) + wx * at(x1, y1));
}

double Lookup(const Table &table, const std::vector<double> &values, double x, double y, double z,
              int c) {
  int x0, y0, z0;
  double wx, wy, wz;
  LookupCoordinate(table.x, x, &x0, &wx);
  LookupCoordinate(table.y, y, &y0, &wy);
  LookupCoordinate(table.z, z, &z0, &wz);
  const int x1 = table.width() > 1 ? x0 + 1 : x0;
  const int y1 = table.height() > 1 ? y0 + 1 : y0;
  const int z1 = table.depth() > 1 ? z0 + 1 : z0;
  const auto slice = [&](int iz) {
    const auto at = [&](int ix, int iy) { return values[table.index(ix, iy, iz, c)]; };
    return (1.0 - wy) * ((1.0 - wx) * at(x0, y0) + wx * at(x1, y0)) +
           wy * ((1.0 - wx) * at(x0, y1) + wx * at(x1, y1));
  };
  return (1.0 - wz) * slice(z0) + wz * slice(z1);
}

double LookupMuAverage(const Table &table, const std::vector<double> &values, double y, int c) {
  // The row at y, interpolated between the two nearest rows.
  int y0;
  double wy;
  LookupCoordinate(table.y, y, &y0, &wy);
  const int y1 = table.height() > 1 ? y0 + 1 : y0;
  const int n = table.width();
  const auto row = [&](int ix) {
    return (1.0 - wy) * values[table.index(ix, y0, c)] + wy * values[table.index(ix, y1, c)];
  };
  // integral_a^b 2 mu (p + q mu) dmu = p (b^2 - a^2) + (2/3) q (b^3 - a^3).
  const auto piece = [](double a, double b, double p, double q) {
    return p * (b * b - a * a) + (2.0 / 3.0) * q * (b * b * b - a * a * a);
  };
  double sum = 0.0;
  const double first = table.x.TexelCenter(0), last = table.x.TexelCenter(n - 1);
  sum += piece(table.x.min, first, row(0), 0.0);  // clamped: constant below the first centre
  for (int i = 0; i + 1 < n; ++i) {
    const double a = table.x.TexelCenter(i), b = table.x.TexelCenter(i + 1);
    const double va = row(i), vb = row(i + 1);
    const double q = (vb - va) / (b - a);
    sum += piece(a, b, va - q * a, q);
  }
  sum += piece(last, table.x.max, row(n - 1), 0.0);
  return sum;
}

}  // namespace lutbake
