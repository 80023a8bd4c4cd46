#include "lutbake/validation/ltc_report.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "lutbake/formats/table_reader.h"
#include "lutbake/integrators/ltc_fit.h"
#include "lutbake/models/ltc.h"
#include "lutbake/tables/lookup.h"

namespace lutbake {

namespace {

// ltc_code's published table: 64 x 64 texels of 4 numbers in each array.
constexpr int kReferenceSize = 64;

void Summarise(const std::vector<double> &errors, double *mean, double *max) {
  double sum = 0.0;
  *max = 0.0;
  for (double e : errors) {
    sum += e;
    *max = std::max(*max, e);
  }
  *mean = errors.empty() ? 0.0 : sum / static_cast<double>(errors.size());
}

// A perceptually ordered colour for t in [0, 1] (dark blue, teal, yellow:
// a few stops of viridis, linearly interpolated).
std::string Colour(double t) {
  static const double stops[5][3] = {
      {68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}};
  t = std::clamp(t, 0.0, 1.0) * 4.0;
  const int k = std::min(static_cast<int>(t), 3);
  const double f = t - k;
  char out[8];
  std::snprintf(out, sizeof out, "#%02x%02x%02x",
                static_cast<int>(std::lround(stops[k][0] + f * (stops[k + 1][0] - stops[k][0]))),
                static_cast<int>(std::lround(stops[k][1] + f * (stops[k + 1][1] - stops[k][1]))),
                static_cast<int>(std::lround(stops[k][2] + f * (stops[k + 1][2] - stops[k][2]))));
  return out;
}

// The colour scale: log10 of the lobe error from 1e-3 to 1.
constexpr double kLogMin = -3.0, kLogMax = 0.0;

}  // namespace

Table ThreejsLtcTexture(const std::vector<float> &mat1, const std::vector<float> &mat2) {
  const int n = kReferenceSize;
  const size_t texels = static_cast<size_t>(n) * n;
  if (mat1.size() != texels * 4 || mat2.size() != texels * 4)
    throw std::invalid_argument("ltc_code's LTC_MAT_1 and LTC_MAT_2 hold 64 x 64 x 4 numbers each");
  // Texel i at i / (n - 1): the linear axis whose texel centres those are.
  const double h = 0.5 / (n - 1);
  Table table;
  table.name = "ltc_code";
  table.x = LinearAxis("perceptualRoughness", -h, 1.0 + h, n);
  table.y = LinearAxis("sqrt(1 - mu)", -h, 1.0 + h, n);
  table.channels = 5;
  table.channelNames = {"m00", "m20", "m02", "m22", "magnitude"};
  table.values.resize(texels * 5);
  for (size_t t = 0; t < texels; ++t) {
    for (size_t c = 0; c < 4; ++c) table.values[t * 5 + c] = mat1[t * 4 + c];
    table.values[t * 5 + 4] = mat2[t * 4];
  }
  table.errors.assign(table.values.size(), 0.0);
  return table;
}

LtcErrorMap MeasureLtcErrorMap(const Table &ltc, NdfKind ndf, SmithForm smith,
                               const std::string &referencePath, int grid) {
  LtcErrorMap map;
  map.grid = grid;
  map.ndf = ndf;
  map.smith = smith;
  map.reference = referencePath;
  const size_t texels = static_cast<size_t>(kReferenceSize) * kReferenceSize * 4;
  Table theirTable;
  if (!referencePath.empty())
    theirTable = ThreejsLtcTexture(ReadThreejsLtcArray(referencePath, "LTC_MAT_1", texels),
                                   ReadThreejsLtcArray(referencePath, "LTC_MAT_2", texels));
  const size_t points = static_cast<size_t>(grid) * grid;
  map.ours.assign(points, 0.0);
  if (!referencePath.empty()) map.theirs.assign(points, 0.0);
  tbb::parallel_for(size_t{0}, points, [&](size_t k) {
    const double mu = (static_cast<double>(k % grid) + 0.5) / grid;
    const double r = (static_cast<double>(k / grid) + 0.5) / grid;
    const LtcLobe lobe = MicrofacetLtcLobe(Ndf{ndf, r * r}, smith);
    double magnitude = 0.0, fresnel = 0.0;
    lobe.moments(mu, &magnitude, &fresnel);
    // The table looked up at (mu, r) as its lookup helpers do: channels
    // m00, m20, m02, m22, magnitude.
    const LtcMatrix ours{Lookup(ltc, mu, r, 0), Lookup(ltc, mu, r, 1), Lookup(ltc, mu, r, 2),
                         Lookup(ltc, mu, r, 3)};
    map.ours[k] = LtcLobeError(lobe, mu, magnitude, Lookup(ltc, mu, r, 4), ours, 1);
    if (referencePath.empty()) return;
    const double x = r, y = std::sqrt(1.0 - mu);
    const LtcMatrix theirs{Lookup(theirTable, x, y, 0), Lookup(theirTable, x, y, 1),
                           Lookup(theirTable, x, y, 2), Lookup(theirTable, x, y, 3)};
    map.theirs[k] = LtcLobeError(lobe, mu, magnitude, Lookup(theirTable, x, y, 4), theirs, 1);
  });
  Summarise(map.ours, &map.meanOurs, &map.maxOurs);
  Summarise(map.theirs, &map.meanTheirs, &map.maxTheirs);
  return map;
}

std::string LtcErrorCsv(const LtcErrorMap &map) {
  std::ostringstream out;
  out.precision(9);
  out << "mu,perceptualRoughness,lutbake_lobe_error,ltc_code_lobe_error\n";
  for (size_t k = 0; k < map.ours.size(); ++k) {
    out << (static_cast<double>(k % map.grid) + 0.5) / map.grid << ','
        << (static_cast<double>(k / map.grid) + 0.5) / map.grid << ',' << map.ours[k] << ',';
    if (!map.theirs.empty()) out << map.theirs[k];
    out << '\n';
  }
  return out.str();
}

std::string LtcErrorSvg(const LtcErrorMap &map) {
  const int cell = 8, side = map.grid * cell, margin = 50, gap = 40;
  const int panels = map.theirs.empty() ? 1 : 2;
  const int width = margin + panels * side + (panels - 1) * gap + 90;
  const int height = side + margin + 60;
  std::ostringstream out;
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
      << "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  out << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  for (int p = 0; p < panels; ++p) {
    const std::vector<double> &errors = p == 0 ? map.ours : map.theirs;
    const double mean = p == 0 ? map.meanOurs : map.meanTheirs;
    const int left = margin + p * (side + gap), top = 30;
    char title[160];
    std::snprintf(title, sizeof title, "%s: mean lobe error %.4f",
                  p == 0 ? "lutbake ltc_ggx" : "ltc_code (as three.js samples it)", mean);
    out << "<text x=\"" << left << "\" y=\"20\">" << title << "</text>\n";
    for (size_t k = 0; k < errors.size(); ++k) {
      const int i = static_cast<int>(k % map.grid), j = static_cast<int>(k / map.grid);
      const double t = (std::log10(std::max(errors[k], 1e-12)) - kLogMin) / (kLogMax - kLogMin);
      // mu to the right, roughness upward.
      out << "<rect x=\"" << left + i * cell << "\" y=\"" << top + (map.grid - 1 - j) * cell
          << "\" width=\"" << cell << "\" height=\"" << cell << "\" fill=\"" << Colour(t)
          << "\"/>\n";
    }
    out << "<text x=\"" << left + side / 2 - 10 << "\" y=\"" << top + side + 18 << "\">mu</text>\n";
    out << "<text x=\"" << left << "\" y=\"" << top + side + 18 << "\">0</text>\n";
    out << "<text x=\"" << left + side - 8 << "\" y=\"" << top + side + 18 << "\">1</text>\n";
    out << "<text x=\"" << left - 14 << "\" y=\"" << top + side << "\">0</text>\n";
    out << "<text x=\"" << left - 14 << "\" y=\"" << top + 10 << "\">1</text>\n";
    out << "<text x=\"" << left - 40 << "\" y=\"" << top + side / 2 << "\">r</text>\n";
  }
  // The colour bar: log10 of the error.
  const int barLeft = margin + panels * side + (panels - 1) * gap + 20, top = 30;
  for (int s = 0; s < 32; ++s)
    out << "<rect x=\"" << barLeft << "\" y=\"" << top + (31 - s) * side / 32 << "\" width=\"16\""
        << " height=\"" << side / 32 + 1 << "\" fill=\"" << Colour((s + 0.5) / 32) << "\"/>\n";
  out << "<text x=\"" << barLeft + 20 << "\" y=\"" << top + 10 << "\">1</text>\n";
  out << "<text x=\"" << barLeft + 20 << "\" y=\"" << top + side << "\">1e-3</text>\n";
  out << "<text x=\"" << margin << "\" y=\"" << height - 12
      << "\">lobe error int |f cos - m D| / E over the upper hemisphere, at " << map.grid << " x "
      << map.grid << " points (mu, r) between the texels</text>\n";
  out << "</svg>\n";
  return out.str();
}

std::string LtcErrorMarkdown(const LtcErrorMap &map) {
  std::ostringstream out;
  char line[256];
  out << "\n## Area-light LTC: lobe error\n\n";
  out << "The lobe error int |f (n.l) - m D(l)| dl / E of the " << ToString(map.ndf) << " "
      << ToString(map.smith) << " ltc_ggx table at " << map.grid << " x " << map.grid
      << " points (mu, r) = ((i + 0.5) / " << map.grid << ", (j + 0.5) / " << map.grid
      << "), each looked up bilinearly (ltc_error.csv, ltc_error.svg).\n\n";
  out << "| table | mean | max |\n|---|---|---|\n";
  // (The reference was fitted to GGX with ltc_code's Smith form.)
  std::snprintf(line, sizeof line, "| lutbake ltc_ggx | %.5f | %.4f |\n", map.meanOurs,
                map.maxOurs);
  out << line;
  if (!map.theirs.empty()) {
    std::snprintf(line, sizeof line,
                  "| ltc_code, as three.js samples it (%s) | %.5f | %.4f |\n\nRatio of the means: "
                  "%.3f.\n",
                  map.reference.c_str(), map.meanTheirs, map.maxTheirs,
                  map.meanOurs / map.meanTheirs);
    out << line;
  }
  return out.str();
}

}  // namespace lutbake
