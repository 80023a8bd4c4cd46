// Real error of a baked directory against the quadrature reference: reads
// DIR/E.bin, DIR/dfg.bin and DIR/Eavg.bin (those present), integrates every
// texel (or every stride-th along each axis) with the quadrature at 1e-13,
// and prints the real error, where it is worst, and how often the per-texel
// bound written in the file holds. Usage: lutbake_verify DIR [stride]
#include <tbb/parallel_for.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "lutbake/formats/binary_format.h"
#include "lutbake/formats/writer.h"
#include "lutbake/integrators/reference_integrator.h"

namespace {

using namespace lutbake;

std::string Meta(const Table &t, const std::string &key) {
  const std::string *v = t.FindMetadata(key);
  return v ? *v : std::string();
}

void Verify(const std::string &path, int stride) {
  Table t = ReadBinaryTable(path);
  for (const TableDefinition *k : AllTables())
    if (Meta(t, "table") == k->Name()) t.definition = k;
  const NdfKind ndf = Meta(t, "ndf") == "beckmann" ? NdfKind::kBeckmann : NdfKind::kGgx;
  const SmithForm smith =
      Meta(t, "smith") == "separable" ? SmithForm::kSeparable : SmithForm::kCorrelated;
  struct Point {
    int x, y;
  };
  std::vector<Point> points;
  for (int y = 0; y < t.height(); ++y)
    for (int x = 0; x < t.width(); ++x)
      if ((x % stride == 0 && y % stride == 0) || x == 0 || y == 0) points.push_back({x, y});
  // err: the worst channel's real error; excess: the largest (real error -
  // allowed) over the channels, > 0 when the file's bound fails.
  std::vector<double> err(points.size()), excessOf(points.size());
  tbb::parallel_for(size_t(0), points.size(), [&](size_t i) {
    const auto [x, y] = points[i];
    double ref[2] = {0, 0};
    if (t.definition == &TableNamed("Eavg")) {
      const double r = t.x.TexelCenter(x);
      ref[0] = IntegrateReferenceAlbedoAverage(Ndf{ndf, r * r}, smith, 1e-12).value;
    } else {
      const double r = t.y.TexelCenter(y);
      const ReferenceAlbedo a =
          IntegrateReferenceAlbedo(Ndf{ndf, r * r}, smith, t.x.TexelCenter(x), 1e-13);
      ref[0] = t.definition == &TableNamed("dfg") ? a.A : a.E;
      ref[1] = a.B;
    }
    double e = 0, excess = -1;
    for (int c = 0; c < t.channels; ++c) {
      const double v = t.value(x, y, c), ec = std::abs(v - ref[c]);
      // The file holds float32: allow its rounding (half an ulp) on top of the bound.
      const double allowed = t.errors[t.index(x, y, c)] + std::abs(v) * 0x1p-24;
      excess = std::max(excess, ec - allowed);
      e = std::max(e, ec);
      if (std::getenv("SHOW") && ec > allowed)
        std::printf("  over: %s (%d,%d) c%d value %.9g ref %.9g err %.3e allowed %.3e\n",
                    t.definition->Name(), x, y, c, v, ref[c], ec, allowed);
    }
    err[i] = e;
    excessOf[i] = excess;
  });
  double maxErr = 0, sumSq = 0, col = 0, row = 0;
  size_t worst = 0, over = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    if (err[i] > maxErr) maxErr = err[i], worst = i;
    sumSq += err[i] * err[i];
    if (excessOf[i] > 0) ++over;
    if (points[i].x == 0) col = std::max(col, err[i]);
    if (points[i].y == 0) row = std::max(row, err[i]);
  }
  std::printf(
      "%-6s %zu texels checked: real error max %.3e (texel %d,%d) rms %.3e; grazing column %.3e, "
      "smoothest row %.3e; within the file's bound: %.2f%% (%zu over)\n",
      t.definition->Name(), points.size(), maxErr, points[worst].x, points[worst].y,
      std::sqrt(sumSq / points.size()), col, row, 100.0 * (points.size() - over) / points.size(),
      over);
}

}  // namespace

int main(int argc, char **argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: lutbake_verify DIR [stride]\n");
    return 2;
  }
  const int stride = argc > 2 ? std::max(1, std::atoi(argv[2])) : 1;
  try {
    for (const char *name : {"E", "Eavg", "dfg"}) {
      const std::string path = std::string(argv[1]) + "/" + name + ".bin";
      if (std::filesystem::exists(path)) Verify(path, stride);
    }
  } catch (const IoError &e) {
    std::fprintf(stderr, "lutbake_verify: %s\n", e.what());
    return 1;
  }
  return 0;
}
