// `lutbake furnace` as a library: a model's white furnace over a grid of
// parameter values and view cosines, its summary (the worst gain and loss),
// and the files: furnace.csv, furnace.json, a plot of albedo against mu
// (furnace_plot.svg, furnace_plot.png) and the picture of the test itself
// (furnace_spheres.exr, furnace_spheres.png).
//
// The sphere picture: one unit sphere per parameter value in a row, seen
// orthographically along -z and lit by a uniform white environment, so that
// a pixel shows the directional albedo at its view cosine mu = n.v = the
// normal's z = sqrt(1 - x^2 - y^2) (x, y the pixel centre's position on the
// sphere's disc). The albedo is interpolated linearly in mu between the
// values at mu_k = k / (N - 1), k = 0..N-1 (N = kSphereMuCount), computed
// like the others; background pixels are 1, the albedo of a model that
// conserves energy, which then disappears. The EXR holds the albedo itself
// (channel Y); the PNG shows albedo / 2 in 8 bits (round(255 a / 2),
// clamped), so that the background is mid grey (128), a gain brighter and
// a loss darker.
#pragma once

#include <string>
#include <vector>

#include "lutbake/formats/output_transaction.h"
#include "lutbake/integrators/furnace.h"

namespace lutbake {

inline constexpr int kSphereMuCount = 129;
inline constexpr int kSphereDiameter = 128;  // pixels
inline constexpr int kSphereGap = 16;        // pixels between and around spheres

struct FurnaceSettings {
  FurnaceModel model;
  std::string parameterName;                                 // "n", "sigma", "r" or "" (Lambert)
  std::vector<double> parameters;                            // at least one
  std::vector<double> mus;                                   // view cosines
  std::vector<std::pair<std::string, std::string>> options;  // for the JSON "options"
  double tolerance = 1e-9;
  bool pictures = false;  // also the fine mu grid of the pictures
};

struct FurnaceEntry {
  double parameter = 0, mu = 0;
  FurnacePoint point;
};

struct FurnaceExtreme {
  double amount = 0;  // gain: albedo - 1 (> 0); loss: 1 - albedo (> 0); 0 if none
  double error = 0, parameter = 0, mu = 0;
};

struct FurnaceResult {
  std::vector<FurnaceEntry> albedo;   // parameters outer, mus inner
  std::vector<FurnaceValue> average;  // per parameter
  FurnaceExtreme gain, loss;
  // The pictures' grid: fine[p][k] = albedo at mu = k / (kSphereMuCount - 1).
  std::vector<std::vector<double>> fine;
};

// Every value computed in parallel (on the calling TBB arena), each by a
// fixed sequence of operations: bit-identical for any thread count.
FurnaceResult RunFurnace(const FurnaceSettings &settings);

std::string FurnaceJson(const FurnaceSettings &settings, const FurnaceResult &result);
std::string FurnaceCsv(const FurnaceSettings &settings, const FurnaceResult &result);
std::string FurnacePlotSvg(const FurnaceSettings &settings, const FurnaceResult &result);

struct FurnaceImage {
  int width = 0, height = 0;
  std::vector<float> values;  // albedo, row by row from the top
};
FurnaceImage RenderFurnaceSpheres(const FurnaceResult &result);
// The albedo at mu from a fine row (linear interpolation, as the picture does).
double InterpolateFine(const std::vector<double> &fine, double mu);

// Writes the files through `output` (furnace.csv and furnace.json; with
// the pictures' grid also furnace_plot.svg/.png and furnace_spheres.exr/.png);
// the caller commits.
void WriteFurnaceFiles(OutputTransaction &output, const FurnaceSettings &settings,
                       const FurnaceResult &result);

}  // namespace lutbake
