// The unity-hdrp-ltc preset (Unity HDRP's LtcData.BRDF_*.cs arrays): the
// four C# files read back by a reader of their own here, in HDRP's layout
// (entry [x + 64 y] = { m00, 0, m20, 0, m11, 0, m02, 0, 1 }, the transpose
// of M^-1 over m22; x = perceptual roughness x / 63, y = sqrt(1 - NdotV) =
// y / 63), against the LTC fit at exactly those points, det > 0, and
// measured against rows of HDRP's own arrays in
// tests/data/presets/hdrp_ltc_rows.csv: lobe error, polygon error and
// leakage of both at HDRP's texels, against the lobe HDRP's shaders
// evaluate. `lutbake check` of the preset directory.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "lutbake/api/bake.h"
#include "lutbake/api/presets.h"
#include "lutbake/integrators/ltc_fit.h"
#include "lutbake/presets/preset.h"
#include "lutbake/tables/storage.h"
#include "support/bake_for_test.h"
#include "support/cli_run.h"
#include "support/csv.h"

namespace lutbake {
namespace {

namespace fs = std::filesystem;
using test::DataPath;
using test::ReadCsv;

constexpr const char *kSlices[4] = {"GGX", "Disney", "Charlie", "OrenNayar"};

// The rows "{ a, b, ... }" after the array's declaration, nine numbers each.
std::vector<std::vector<double>> CsRows(const fs::path &path, const std::string &array) {
  std::ifstream in(path);
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  std::vector<std::vector<double>> rows;
  const size_t declared = text.find("double[,] " + array + " = new double[64 * 64, 3 * 3]");
  if (declared == std::string::npos) return rows;
  for (size_t at = text.find('{', text.find('{', declared) + 1); at != std::string::npos;
       at = text.find('{', at + 1)) {
    const size_t end = text.find('}', at);
    std::string row = text.substr(at + 1, end - at - 1);
    std::replace(row.begin(), row.end(), ',', ' ');
    std::istringstream values(row);
    std::vector<double> r;
    for (double v; values >> v;) r.push_back(v);
    if (r.empty()) break;  // the class's closing braces
    rows.push_back(r);
  }
  return rows;
}

// The lobe HDRP's shader evaluates for a slice at perceptual roughness r,
// with the clamps of HDRP's fitter (alpha >= 0.001; Disney and Charlie
// alpha >= 0.002; Oren-Nayar sigma = max(0.002, pi/2 alpha)).
LtcLobe SliceLobe(int slice, double r) {
  const double alpha = std::max(r * r, 0.001);
  switch (slice) {
    case 1: return BurleyLtcLobe(std::sqrt(std::max(alpha, 0.002)));
    case 2: return SheenLtcLobe(SheenVisibility::kCharlie, std::max(alpha, 0.002));
    case 3:
      return OrenNayarLtcLobe(OrenNayarVariant::kQualitative, std::max(0.002, 0.5 * kPi * alpha));
    default: return MicrofacetLtcLobe(Ndf{NdfKind::kGgx, alpha}, SmithForm::kCorrelated);
  }
}

// NdotV of HDRP's row y (ClampNdotV's 1e-4 for the Charlie slice, whose
// albedo is infinite at 0).
double RowMu(int slice, int y) {
  const double v = y / 63.0, mu = 1.0 - v * v;
  return slice == 2 ? std::max(mu, 1e-4) : mu;
}

// The lobe's albedo: its closed moments where it has them, else its rule at
// level 2 (the diffuse and sheen lobes).
double Magnitude(const LtcLobe &lobe, double mu) {
  double magnitude = 0, fresnel = 0;
  if (lobe.moments)
    lobe.moments(mu, &magnitude, &fresnel);
  else
    IntegrateLobeMoments(lobe, mu, 2, &magnitude, &fresnel);
  return magnitude;
}

// An HDRP entry's (E0, E2, E4, E6) as the LtcMatrix of m11 = 1.
LtcMatrix FromHdrp(double e0, double e2, double e4, double e6) {
  return LtcMatrix{e0 / e4, e2 / e4, e6 / e4, 1.0 / e4};
}

class UnityHdrpLtc : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new fs::path(test::Scratch("preset_unity_hdrp_ltc"));
    BakeRequest request = test::BakeRequestFor(*dir_);
    request.preset = "unity-hdrp-ltc";
    Bake(request);
    for (int s = 0; s < 4; ++s)
      rows_[s] = new std::vector<std::vector<double>>(
          CsRows(*dir_ / (std::string("LtcData.BRDF_") + kSlices[s] + ".cs"),
                 std::string("s_LtcMatrixData_BRDF_") + kSlices[s]));
  }
  static void TearDownTestSuite() {
    fs::remove_all(*dir_);
    delete dir_;
    for (auto *r : rows_) delete r;
  }
  static const std::vector<double> &At(int slice, int x, int y) {
    return (*rows_[slice])[static_cast<size_t>(x) + 64 * static_cast<size_t>(y)];
  }
  static fs::path *dir_;
  static std::vector<std::vector<double>> *rows_[4];
};
fs::path *UnityHdrpLtc::dir_ = nullptr;
std::vector<std::vector<double>> *UnityHdrpLtc::rows_[4] = {};

// Four slices of 64 x 64 entries of nine doubles: { m00, 0, m20, 0, m11, 0,
// m02, 0, 1 }, det M^-1 > 0 and every value finite and below binary16's
// 65504 (HDRP's clamp); at texels of every slice the entry is the LTC fit
// of the slice's lobe at HDRP's (perceptual roughness x / 63, NdotV = 1 -
// (y / 63)^2), over its m22, bit for bit; the transposed texel is not.
TEST_F(UnityHdrpLtc, LayoutAxesAndElementOrder) {
  EXPECT_EQ(FindPreset("unity-hdrp-ltc")->textures.size(), 4u);
  std::vector<double> edges(64), mus(64);
  for (int i = 0; i < 64; ++i) edges[i] = i / 63.0;
  for (int s = 0; s < 4; ++s) {
    ASSERT_EQ(rows_[s]->size(), 64u * 64u) << kSlices[s];
    for (int k = 0; k < 64 * 64; ++k) {
      const std::vector<double> &e = (*rows_[s])[static_cast<size_t>(k)];
      ASSERT_EQ(e.size(), 9u) << kSlices[s] << " " << k;
      for (int c : {1, 3, 5, 7}) EXPECT_EQ(e[c], 0.0) << kSlices[s] << " " << k;
      EXPECT_EQ(e[8], 1.0) << kSlices[s] << " " << k;
      EXPECT_GT(e[4], 0.0) << kSlices[s] << " " << k;
      EXPECT_GT(FromHdrp(e[0], e[2], e[4], e[6]).Determinant(), 0.0) << kSlices[s] << " " << k;
      for (double v : e) EXPECT_TRUE(std::isfinite(v) && std::abs(v) < 65504.0);
    }
    for (int y = 0; y < 64; ++y) mus[y] = RowMu(s, y);
    LtcFitSettings settings;
    settings.moments = false;
    const auto lobeAt = [s](double r) { return SliceLobe(s, r); };
    for (const auto &[x, y] : {std::pair{40, 10}, std::pair{9, 57}, std::pair{25, 63}}) {
      const LtcMatrix m = FitLtcPoint(lobeAt, mus[y], edges[x], mus, edges, settings).minv;
      const std::vector<double> &e = At(s, x, y);
      EXPECT_EQ(e[0], m.m00 / m.m22) << kSlices[s] << " " << x << ", " << y;
      EXPECT_EQ(e[2], m.m20 / m.m22) << kSlices[s] << " " << x << ", " << y;
      EXPECT_EQ(e[4], 1.0 / m.m22) << kSlices[s] << " " << x << ", " << y;
      EXPECT_EQ(e[6], m.m02 / m.m22) << kSlices[s] << " " << x << ", " << y;
      EXPECT_NE(At(s, y, x)[6], e[6]) << kSlices[s] << " " << x << ", " << y;
    }
  }
}

// HDRP's rows (hdrp_ltc_rows.csv, its files' values to 6 digits): both
// tables' lobe error, worst rectangle error and leakage at HDRP's texels of
// roughness > 0 whose lobe carries light, both scaled by the exact albedo (HDRP scales its LTC by
// its FGD texture, not by the LTC array), against the lobe HDRP's shaders evaluate; and this
// preset's entries as HDRP uploads them (binary16). HDRP's entry read with m20 and m02 swapped is
// far worse or not a valid M^-1 (det
// <= 0): the element order read here is HDRP's.
TEST_F(UnityHdrpLtc, AgainstHdrpsRows) {
  const auto rows = ReadCsv(DataPath("presets/hdrp_ltc_rows.csv"));
  ASSERT_GT(rows.size(), 400u);
  std::map<int, std::vector<const test::CsvRow *>> bySlice;
  for (const auto &row : rows) {
    const std::string name = row.Text("slice");
    for (int s = 0; s < 4; ++s)
      if (name == kSlices[s]) bySlice[s].push_back(&row);
  }
  ASSERT_EQ(bySlice.size(), 4u);
  for (const auto &[s, slice] : bySlice) {
    double ours[3] = {0, 0, 0}, theirs[3] = {0, 0, 0}, swapped = 0, texel = 0, half = 0;
    int n = 0, swappedValid = 0;
    for (const test::CsvRow *row : slice) {
      const int x = static_cast<int>(row->Number("x")), y = static_cast<int>(row->Number("y"));
      const double h[4] = {row->Number("hdrp_e0"), row->Number("hdrp_e2"), row->Number("hdrp_e4"),
                           row->Number("hdrp_e6")};
      const std::vector<double> &e = At(s, x, y);
      texel = std::max({texel, std::abs(e[0] - h[0]), std::abs(e[2] - h[1]), std::abs(e[4] - h[2]),
                        std::abs(e[6] - h[3])});
      if (x == 0) continue;
      const double mu = RowMu(s, y);
      const LtcLobe lobe = SliceLobe(s, x / 63.0);
      const double magnitude = Magnitude(lobe, mu);
      // A lobe of albedo under 1e-6 carries no light (the LTC tables' rule,
      // kLtcNoLight): the Charlie lobe at small alpha, nearly all of it below
      // the horizon away from grazing.
      if (!(magnitude >= 1e-6)) continue;
      const std::vector<double> refs = RectangleLobeIntegrals(lobe, mu, 1);
      const LtcErrors a =
          MeasureLtcErrors(lobe, mu, magnitude, FromHdrp(e[0], e[2], e[4], e[6]), refs);
      const LtcErrors b =
          MeasureLtcErrors(lobe, mu, magnitude, FromHdrp(h[0], h[1], h[2], h[3]), refs);
      const LtcMatrix wrong = FromHdrp(h[0], h[3], h[2], h[1]);
      if (wrong.Determinant() > 0.0) {
        swapped += LtcLobeError(lobe, mu, magnitude, magnitude, wrong, 1);
        ++swappedValid;
      }
      const auto f16 = [](double v) { return StoredValue(v, ValueType::kHalf); };
      half += LtcLobeError(lobe, mu, magnitude, magnitude,
                           FromHdrp(f16(e[0]), f16(e[2]), f16(e[4]), f16(e[6])), 1);
      ours[0] += a.lobe, ours[1] += a.polygon, ours[2] += a.leakage;
      theirs[0] += b.lobe, theirs[1] += b.polygon, theirs[2] += b.leakage;
      ++n;
    }
    for (double &v : ours) v /= n;
    for (double &v : theirs) v /= n;
    swapped /= std::max(swappedValid, 1);
    half /= n;
    std::printf(
        "unity-hdrp-ltc %-9s at HDRP's %3d texels: lobe %.4f vs %.4f (%.2f; as binary16 %.4f), "
        "polygon %.4f vs %.4f (%.2f), leakage %.4f vs %.4f; HDRP's swapped %.4f (%d of %d "
        "valid); max |entry difference| %.3g\n",
        kSlices[s], n, ours[0], theirs[0], ours[0] / theirs[0], half, ours[1], theirs[1],
        ours[1] / theirs[1], ours[2], theirs[2], swapped, swappedValid, n, texel);
    EXPECT_TRUE(swapped > 1.5 * theirs[0] || swappedValid < n / 2) << kSlices[s];
    // Measured: lower mean lobe and polygon errors on every slice (0.56 to
    // 0.70 and 0.37 to 0.94 of HDRP's), lower leakage but on the Disney
    // slice, where both leak under 1e-3; binary16 moves the mean lobe error
    // by at most 1e-3.
    EXPECT_LT(ours[0], theirs[0]) << kSlices[s];
    EXPECT_LT(ours[1], theirs[1]) << kSlices[s];
    EXPECT_TRUE(ours[2] < theirs[2] || std::max(ours[2], theirs[2]) < 1e-3) << kSlices[s];
    EXPECT_LT(std::abs(half - ours[0]), 2e-3) << kSlices[s];
  }
}

// `lutbake check` of the preset directory: the files read back (format
// hdrp-ltc-cs) and held to the fit again.
TEST_F(UnityHdrpLtc, Checks) {
  const PresetCheck check = CheckPresetDirectory(dir_->string());
  EXPECT_TRUE(check.pass) << check.json;
  EXPECT_EQ(check.files.size(), 4u);
}

}  // namespace
}  // namespace lutbake
