// Judging a table file lutbake did not write: `lutbake check FILE --as
// TABLE` (CheckTableFile) compares every texel of any PNG, EXR, DDS, KTX2,
// Radiance HDR or source array (formats/image_reader.h) with lutbake's exact
// values under a convention the caller states; `lutbake identify FILE`
// (IdentifyTable) tries the known conventions and names the best.
//
// A convention says, for the texel (x, y) of the file (row y = 0 first in
// the file):
//   - the layout: which quantity each axis holds (mu = n.v, or the
//     engine's roughness), through which mapping (mu, sqrt(mu) as Unity
//     HDRP, sqrt(1 - mu) as EEVEE), at texel centres u = (i + 0.5) / N or
//     edges u = i / (N - 1), and what each channel holds (A, B, E = A + B,
//     sheen_E, f82, Eavg; "-" for a channel not compared); or a preset's
//     texture, which states all of that (presets/preset.h);
//   - the model: Smith correlated, separable, Schlick-GGX with k = alpha /
//     2 (schlick-ggx-ibl) or Unreal's smith-joint-approx; alpha = r^2
//     (squared) or r (linear);
//   - the defects: transposed (the file's x holds the layout's y axis),
//     flipX / flipY (the file's axis runs the other way), offsetX / offsetY
//     (after the flips, file texel i holds the layout's texel i + offset; an
//     index past the end holds the axis's end, as Filament's generator's
//     one-texel-too-rough rows do, one before the start u = 0),
//     and the encoding: linear, srgb (the file
//     holds the sRGB encoding of the value: its sRGB decoding is compared)
//     or rgbd (RGB = value / D, A = D: RGB / A is compared).
//
// Exact values are PresetTexelValues's (the preset's integrators, with
// their bounds). The tolerance of a texel, unless stated: half a storage
// step (unorm: 0.5 / (2^b - 1); half: |v| 2^-11; float32: |v| 2^-24; RGBE:
// 2^-8 of the texel's largest channel; decimal text: half a unit in the
// literal's last digit plus the float32 rounding), carried through the
// encoding's decoding, plus the exact value's bound. A file passes `check`
// when every compared value is within its tolerance.
//
// Throws UnreadableError when the file cannot be read as an image or array,
// UsageError for a convention that does not fit the file (3 channels named
// for a 2-channel file, a preset texture of another size).
#pragma once

#include <map>
#include <string>
#include <vector>

namespace lutbake {

// The options that state a convention, as `check FILE --as` takes them:
// name ("--as"), the value's type name, help, and the accepted values of a
// closed list (empty: any; `list`: a comma-separated subset).
struct ConventionOption {
  std::string name, typeName, help;
  std::vector<std::string> accepted;
  bool list = false;
};
const std::vector<ConventionOption> &ConventionOptions();

struct TableConvention {
  // What is compared: "dfg", "E", "sheen_E", "f82", "Eavg", or a preset
  // texture's stem; the preset ("" for none) and its texture's file name.
  std::string table, preset, texture;
  // The layout's axes as the file holds them, x first: "mu", "roughness".
  std::vector<std::string> axes;
  std::string muMapping = "mu";       // "mu", "sqrt-mu", "sqrt-one-minus-mu"
  std::string texels = "centres";     // "centres", "edges"
  std::vector<std::string> channels;  // per file channel, from the first
  // "correlated", "separable", "schlick-ggx-ibl", "smith-joint-approx"
  // ("" with a preset: the preset's).
  std::string smith = "correlated";
  std::string alpha = "squared";  // "squared" (alpha = r^2), "linear"
  bool transposed = false, flipX = false, flipY = false;
  int offsetX = 0, offsetY = 0;
  std::string encoding = "linear";  // "linear", "srgb", "rgbd"
};

struct TableFileRequest {
  std::string path;
  // The convention options as given (ConventionOptions' names without the
  // dashes: "as", "preset", ...); an empty value is not given.
  std::map<std::string, std::string> options;
  int threads = 0;  // 0: all cores
};

struct TableFileOutcome {
  std::string path, format, storage;  // "PNG", "unorm8"
  int width = 0, height = 0, channels = 0;
  TableConvention convention;
  bool matched = false;  // identify: some convention matches
  bool passed = false;   // every value within its tolerance
  double maxError = 0.0, rmsError = 0.0;
  // The worst value: file texel, channel, the layout's quantities there,
  // the value as read (decoded) and the exact one, and its tolerance.
  int worstX = 0, worstY = 0, worstChannel = 0;
  double worstMu = 0.0, worstRoughness = 0.0, worstStored = 0.0, worstExact = 0.0;
  double worstTolerance = 0.0;
  size_t valuesCompared = 0, valuesAboveTolerance = 0;
  std::string sentence;    // "LearnOpenGL's layout, ..., max error 3.7e-2"
  std::string text;        // what the command prints
  std::string json;        // one object (--json)
  std::string errorImage;  // the error picture written, if asked
};

// `check FILE --as TABLE` / `--preset NAME` and the other options; writes
// the error picture to options["error-image"] when given (an 8-bit RGB PNG,
// one pixel per texel: black at zero error, through blue and green, to
// yellow at the tolerance and red at ten times it or more).
TableFileOutcome CheckTableFile(const TableFileRequest &request);

// `identify FILE`: every preset texture whose size and channels fit the
// file, and lutbake's own dfg / E layouts at the file's size, each under
// every model variant, transposition, flip, offset of -1, 0, 1 texel and
// encoding; the best by RMS error (fewer departures from the layout win a
// tie within 1%). `matched` when the best has RMS error at most 1e-2 and
// max error at most 0.1 (wide enough for a Monte Carlo generator's noise).
// options: "preset" restricts the search to one preset.
TableFileOutcome IdentifyTable(const TableFileRequest &request);

}  // namespace lutbake
