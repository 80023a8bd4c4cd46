// CheckTableFile and IdentifyTable (identify.h): a file's texels against
// lutbake's exact values under a convention, and the search over the
// known conventions.
#include "lutbake/api/identify.h"

#include <tbb/global_control.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <unordered_map>

#include "bake_internal.h"
#include "lutbake/api/names.h"
#include "lutbake/api/numbers.h"
#include "lutbake/core/error.h"
#include "lutbake/formats/image_reader.h"
#include "lutbake/presets/preset.h"

namespace lutbake {

namespace {

const std::vector<std::string> kSmithNames = {"correlated", "separable", "schlick-ggx-ibl",
                                              "smith-joint-approx"};
const std::vector<std::string> kTables = {"dfg", "E", "Eavg", "sheen_E", "f82"};
const std::vector<std::string> kMeanings = {"A", "B", "E", "sheen_E", "f82", "Eavg", "-"};

// The model's G2 named `smith` (one of kSmithNames).
void SetVisibility(const std::string &smith, PresetModel *model) {
  model->smith = smith == "separable" ? SmithForm::kSeparable : SmithForm::kCorrelated;
  model->fitted = smith == "schlick-ggx-ibl"      ? FittedVisibility::kSchlickGgx
                  : smith == "smith-joint-approx" ? FittedVisibility::kSmithJointApprox
                                                  : FittedVisibility::kNone;
}

std::string SmithName(const PresetModel &m) {
  return kSmithNames[static_cast<size_t>(m.fitted == FittedVisibility::kSchlickGgx         ? 2
                                         : m.fitted == FittedVisibility::kSmithJointApprox ? 3
                                         : m.smith == SmithForm::kSeparable                ? 1
                                                                                           : 0)];
}

bool SplitSumChannel(const std::string &meaning) {
  return meaning == "A" || meaning == "B" || meaning == "E" || meaning == "f82" ||
         meaning == "Eavg";
}

// A convention made concrete for one file: the layout in the preset's
// terms (axes in layout order with their counts, channels, model), which
// channels are compared, and how far it departs from its base (ties).
struct Candidate {
  TableConvention convention;
  PresetTexture layout;
  std::vector<bool> compared;
  int departures = 0;
  std::string key;  // the layout and model, which fix the exact values
};

std::string LayoutKey(const PresetTexture &t) {
  std::string key;
  for (const PresetAxis &a : t.axes)
    key += a.quantity + ToString(a.mapping) + ToString(a.placement) + std::to_string(a.count) +
           (a.reversed ? "r" : "") + FormatDouble(a.lowest) + FormatDouble(a.highest) + ";";
  for (const PresetChannel &c : t.channels)
    key +=
        c.meaning + FormatDouble(c.scale) + FormatDouble(c.offset) + FormatDouble(c.clampMax) + ",";
  const PresetModel &m = t.model;
  return key + DescribeVisibility(m) + DescribeAlpha(m.alpha) + FormatDouble(m.alphaMin) +
         std::to_string(static_cast<int>(m.sheenVisibility)) + DescribeAlpha(m.sheenAlpha);
}

int DecodedChannels(const RawImage &image, const std::string &encoding) {
  return encoding == "rgbd" ? (image.channels >= 4 ? 3 : 0) : image.channels;
}

// The layout of `convention` for `image` (its size decides a generic
// layout's counts); throws UsageError when it does not fit.
Candidate Realise(TableConvention convention, const RawImage &image) {
  Candidate c;
  const int fileX = convention.transposed ? image.height : image.width;
  const int fileY = convention.transposed ? image.width : image.height;
  PresetTexture &t = c.layout;
  if (!convention.preset.empty()) {
    const Preset *preset = FindPreset(convention.preset);
    if (!preset)
      throw UsageError("--preset '" + convention.preset +
                       "' is not a preset; accepted: " + PresetNameList());
    const PresetTexture *chosen = nullptr;
    for (const PresetTexture &texture : preset->textures)
      if (texture.file == convention.texture) chosen = &texture;
    if (!convention.texture.empty() && !chosen) {
      std::vector<std::string> files;
      for (const PresetTexture &texture : preset->textures) files.push_back(texture.file);
      throw UsageError("--texture '" + convention.texture + "' is not a texture of preset " +
                       preset->name + "; accepted: " + JoinNames(files));
    }
    // Else the texture of the file's size, or the first.
    for (const PresetTexture &texture : preset->textures)
      if (!chosen && texture.axes.size() <= 2 && texture.axes[0].count == fileX &&
          (texture.axes.size() == 1 ? fileY == 1 : texture.axes[1].count == fileY))
        chosen = &texture;
    t = chosen ? *chosen : preset->textures.front();
    convention.texture = t.file;
    convention.table = t.file.substr(0, t.file.find('.'));
    if (convention.smith.empty()) convention.smith = SmithName(t.model);
    SetVisibility(convention.smith, &t.model);
    convention.texels = ToString(t.axes[0].placement);
    convention.channels.clear();
    for (const PresetChannel &ch : t.channels) convention.channels.push_back(ch.meaning);
  } else {
    if (convention.table.empty()) convention.table = "dfg";
    const bool oneD = convention.table == "Eavg";
    PresetAxis mu, roughness;
    mu.quantity = "mu";
    roughness.quantity = "roughness";
    for (PresetAxis *a : {&mu, &roughness})
      a->placement =
          convention.texels == "edges" ? TexelPlacement::kEdges : TexelPlacement::kCentres;
    mu.mapping = convention.muMapping == "sqrt-mu"             ? PresetMapping::kSquare
                 : convention.muMapping == "sqrt-one-minus-mu" ? PresetMapping::kOneMinusSquare
                                                               : PresetMapping::kLinear;
    mu.count = fileX;
    roughness.count = oneD ? fileX : fileY;
    if (oneD) {
      if (fileY != 1)
        throw UsageError("--as Eavg: a 1D table is one row; the file has " + std::to_string(fileY) +
                         " rows along its roughness axis");
      t.axes = {roughness};
    } else {
      roughness.count = fileY;
      t.axes = {mu, roughness};
    }
    if (convention.channels.empty()) {
      if (convention.table == "dfg")
        convention.channels = {"A", "B"};
      else
        convention.channels = {convention.table};
    }
    for (const std::string &meaning : convention.channels)
      t.channels.push_back({meaning == "-" ? "zero" : meaning});
    if (convention.smith.empty()) convention.smith = "correlated";
    SetVisibility(convention.smith, &t.model);
    t.model.alpha = convention.alpha == "linear" ? AlphaMapping::kLinear : AlphaMapping::kSquared;
    t.model.sheenVisibility = SheenVisibility::kCharlie;
    c.departures = 1;  // lutbake's own layout: a preset's, if equal, wins
  }
  for (const PresetAxis &a : t.axes) convention.axes.push_back(a.quantity);
  if (convention.transposed) std::reverse(convention.axes.begin(), convention.axes.end());
  const std::string size =
      std::to_string(t.axes[0].count) +
      (t.axes.size() > 1 ? " x " + std::to_string(t.axes[1].count) : std::string());
  if (t.axes.size() > 2 || t.axes[0].count != fileX ||
      (t.axes.size() > 1 ? t.axes[1].count != fileY : fileY != 1))
    throw UsageError(image.format + " " + std::to_string(image.width) + " x " +
                     std::to_string(image.height) + " is not the size of " + convention.table +
                     " (" + size + (convention.transposed ? ", transposed" : "") + ")");
  const int decoded = DecodedChannels(image, convention.encoding);
  if (static_cast<int>(t.channels.size()) > decoded)
    throw UsageError(convention.table + " has " + std::to_string(t.channels.size()) +
                     " channels; the file has " + std::to_string(decoded) +
                     (convention.encoding == "rgbd" ? " after RGBD decoding" : ""));
  for (const PresetChannel &ch : t.channels)
    c.compared.push_back(ch.meaning != "zero" && ch.meaning != "one");
  c.departures += convention.transposed + convention.flipX + convention.flipY +
                  std::abs(convention.offsetX) + std::abs(convention.offsetY) +
                  (convention.encoding != "linear");
  c.convention = convention;
  c.key = LayoutKey(t);
  return c;
}

// The exact values of one layout, at memory indices -1 to N on each axis
// (one past each end, for a file one texel off: u clamped to [0, 1], as a
// generator's min(u, 1) or max(u, 0) gives), computed when first asked.
// Where an integral is infinite there (Charlie sheen at mu = 0), the
// evaluation throws and identify passes the candidate over.
class ExactValues {
 public:
  explicit ExactValues(const PresetTexture &layout)
      : layout_(layout),
        n0_(layout.axes[0].count),
        n1_(layout.axes.size() > 1 ? layout.axes[1].count : 1),
        channels_(layout.channels.size()) {}
  size_t Slot(int i0, int i1) const {
    i0 = std::clamp(i0, -1, n0_);
    i1 = layout_.axes.size() > 1 ? std::clamp(i1, -1, n1_) : 0;
    return static_cast<size_t>(i1 + 1) * (n0_ + 2) + static_cast<size_t>(i0 + 1);
  }
  // Computes the slots not yet known, in parallel (each independent of the
  // others and of the thread: the same values for any thread count). Only
  // the slots asked for are held: identify asks a few thousand of each of
  // its layouts, whatever the file's size.
  void Ensure(std::vector<size_t> slots) {
    std::sort(slots.begin(), slots.end());
    slots.erase(std::unique(slots.begin(), slots.end()), slots.end());
    slots.erase(
        std::remove_if(slots.begin(), slots.end(), [&](size_t s) { return row_.count(s) != 0; }),
        slots.end());
    const size_t first = values_.size() / std::max<size_t>(channels_, 1);
    for (size_t k = 0; k < slots.size(); ++k) row_[slots[k]] = first + k;
    values_.resize((first + slots.size()) * channels_);
    errors_.resize(values_.size());
    tbb::parallel_for(size_t{0}, slots.size(), [&](size_t k) {
      const size_t s = slots[k];
      const int index[3] = {static_cast<int>(s % (n0_ + 2)) - 1,
                            static_cast<int>(s / (n0_ + 2)) - 1, 0};
      PresetTexelValues(layout_, index, &values_[(first + k) * channels_],
                        &errors_[(first + k) * channels_]);
    });
  }
  const double *Values(size_t slot) const { return &values_[row_.at(slot) * channels_]; }
  const double *Errors(size_t slot) const { return &errors_[row_.at(slot) * channels_]; }
  // The layout's quantity on axis a at memory index i (clamped).
  double Quantity(size_t a, int i) const {
    if (a >= layout_.axes.size()) return 0.0;
    const PresetAxis &axis = layout_.axes[a];
    const int k = std::clamp(i, -1, axis.count);
    return axis.Quantity(axis.reversed ? axis.count - 1 - k : k);
  }

 private:
  PresetTexture layout_;
  int n0_, n1_;
  size_t channels_;
  std::unordered_map<size_t, size_t> row_;  // slot -> its row in values_, errors_
  std::vector<double> values_, errors_;
};

// File texel (fx, fy) -> the layout's memory indices (i0, i1).
std::pair<int, int> LayoutIndex(const TableConvention &c, const RawImage &image, int fx, int fy) {
  const int x = (c.flipX ? image.width - 1 - fx : fx) + c.offsetX;
  const int y = (c.flipY ? image.height - 1 - fy : fy) + c.offsetY;
  return c.transposed ? std::make_pair(y, x) : std::make_pair(x, y);
}

double SrgbDecode(double s) {
  return s <= 0.04045 ? s / 12.92 : std::pow((s + 0.055) / 1.055, 2.4);
}
double SrgbDecodeSlope(double s) {
  return s <= 0.04045 ? 1.0 / 12.92 : 2.4 / 1.055 * std::pow((s + 0.055) / 1.055, 1.4);
}

// Half a storage step of value i of the image (identify.h's rule).
double HalfStep(const RawImage &image, size_t i) {
  const double v = std::fabs(image.values[i]);
  if (image.storage == "unorm8") return 0.5 / 255.0;
  if (image.storage == "unorm16") return 0.5 / 65535.0;
  if (image.storage == "half") return std::max(v * 0x1p-11, 0x1p-25);
  if (image.storage == "rgbe") {
    const size_t t = i - i % 3;
    return std::max({image.values[t], image.values[t + 1], image.values[t + 2]}) * 0x1p-7;
  }
  const double rounding = std::max(v * 0x1p-24, 0x1p-149);
  return image.storage == "text" ? image.literalHalfUnit[i] + rounding : rounding;
}

// The decoded channel k of texel t and its storage tolerance.
std::pair<double, double> Decoded(const RawImage &image, const std::string &encoding, size_t t,
                                  int k) {
  const size_t i = t * image.channels + k;
  const double f = image.values[i];
  if (encoding == "srgb" && k < 3) return {SrgbDecode(f), HalfStep(image, i) * SrgbDecodeSlope(f)};
  if (encoding == "rgbd") {
    const double d = image.values[t * image.channels + 3];
    if (d <= 0.0) return {0.0, HalfStep(image, i)};
    const double value = f / d;
    return {value, (HalfStep(image, i) + value * HalfStep(image, i - k + 3)) / d};
  }
  return {f, HalfStep(image, i)};
}

struct Score {
  double sumSquares = 0.0, max = 0.0;
  size_t count = 0, above = 0;
  int worstX = 0, worstY = 0, worstChannel = 0;
  double worstStored = 0.0, worstExact = 0.0, worstTolerance = 0.0;
  double rms() const { return count ? std::sqrt(sumSquares / count) : 0.0; }
};

using Texels = std::vector<std::pair<int, int>>;

// The candidate's errors over `texels` (the exact values must be known:
// Ensure). `ratio`, when given, receives each texel's largest error over
// its tolerance (for the picture).
Score Compare(const RawImage &image, const Candidate &c, const ExactValues &exact,
              const Texels &texels, double fixedTolerance, std::vector<double> *ratio) {
  Score s;
  for (const auto &[fx, fy] : texels) {
    const auto [i0, i1] = LayoutIndex(c.convention, image, fx, fy);
    const size_t slot = exact.Slot(i0, i1);
    const size_t t = static_cast<size_t>(fy) * image.width + fx;
    double worstRatio = 0.0;
    for (size_t k = 0; k < c.compared.size(); ++k) {
      if (!c.compared[k]) continue;
      const auto [stored, storageTolerance] =
          Decoded(image, c.convention.encoding, t, static_cast<int>(k));
      const double e = exact.Values(slot)[k];
      const double tolerance =
          fixedTolerance >= 0.0 ? fixedTolerance : storageTolerance + exact.Errors(slot)[k];
      const double error = std::fabs(stored - e);
      s.sumSquares += error * error;
      ++s.count;
      s.above += !(error <= tolerance);
      worstRatio = std::max(worstRatio, tolerance > 0.0 ? error / tolerance : error > 0 ? 1e9 : 0);
      if (error > s.max || s.count == 1) {
        s.max = error;
        s.worstX = fx;
        s.worstY = fy;
        s.worstChannel = static_cast<int>(k);
        s.worstStored = stored;
        s.worstExact = e;
        s.worstTolerance = tolerance;
      }
    }
    if (ratio) (*ratio)[t] = worstRatio;
  }
  return s;
}

// Evaluates what `texels` need of `exact` under the candidate.
void EnsureFor(const RawImage &image, const Candidate &c, ExactValues &exact,
               const Texels &texels) {
  std::vector<size_t> slots;
  slots.reserve(texels.size());
  for (const auto &[fx, fy] : texels) {
    const auto [i0, i1] = LayoutIndex(c.convention, image, fx, fy);
    slots.push_back(exact.Slot(i0, i1));
  }
  exact.Ensure(std::move(slots));
}

// `count` indices spread over [0, n), both ends included; all when n <= count.
std::vector<int> Spread(int n, int count) {
  std::vector<int> out;
  if (n <= count) {
    for (int i = 0; i < n; ++i) out.push_back(i);
    return out;
  }
  for (int k = 0; k < count; ++k)
    out.push_back(static_cast<int>(std::lround(static_cast<double>(k) * (n - 1) / (count - 1))));
  return out;
}

Texels Grid(const RawImage &image, int perAxis) {
  Texels texels;
  for (int y : Spread(image.height, perAxis))
    for (int x : Spread(image.width, perAxis)) texels.emplace_back(x, y);
  return texels;
}

// A source array's shape: `channels` per texel (its innermost braces
// decide, else the caller), then width x height: `size` ("W" or "WxH"),
// else square. Leaves shaped images alone.
RawImage Shaped(const RawImage &image, int channels, const std::string &size) {
  if (!image.flat) return image;
  RawImage out = image;
  out.flat = false;
  out.channels = image.groupSize > 0 ? image.groupSize : channels;
  const size_t texels = image.values.size() / static_cast<size_t>(out.channels);
  if (texels * out.channels != image.values.size())
    throw UsageError(image.format + " of " + std::to_string(image.values.size()) +
                     " values is not texels of " + std::to_string(out.channels) + " channels");
  long w = 0, h = 0;
  if (!size.empty()) {
    if (std::sscanf(size.c_str(), "%ldx%ld", &w, &h) == 1) h = w;
  } else {
    w = h = std::lround(std::sqrt(static_cast<double>(texels)));
  }
  if (w < 1 || h < 1 || static_cast<size_t>(w) * static_cast<size_t>(h) != texels)
    throw UsageError(image.format + " of " + std::to_string(texels) + " texels of " +
                     std::to_string(out.channels) + " channels is not " +
                     (size.empty() ? "square; give its size with --size WxH" : size));
  out.width = static_cast<int>(w);
  out.height = static_cast<int>(h);
  static const char *const kNames[] = {"R", "G", "B", "A"};
  out.channelNames.assign(kNames, kNames + std::min(out.channels, 4));
  out.channelNames.resize(static_cast<size_t>(out.channels), "?");
  return out;
}

// The shape of a source array under `c`: a preset texture's size and
// channels (the one named, or the first whose size holds the values), or
// the convention's channels and `size`; the file's own shape otherwise.
RawImage ShapedFor(const RawImage &raw, const TableConvention &c, const std::string &size) {
  if (!raw.flat) return raw;
  int channels = static_cast<int>(c.channels.size());
  if (channels == 0) channels = c.table == "dfg" || c.table.empty() ? 2 : 1;
  std::string shape = size;
  if (const Preset *p = FindPreset(c.preset))
    for (const PresetTexture &t : p->textures) {
      const bool named = t.file == c.texture;
      const size_t texels = static_cast<size_t>(t.axes[0].count) *
                            (t.axes.size() > 1 ? t.axes[1].count : 1) * t.channels.size();
      if (t.axes.size() > 2 || !(named || (c.texture.empty() && texels == raw.values.size())))
        continue;
      channels = static_cast<int>(t.channels.size());
      const int w = t.axes[0].count, h = t.axes.size() > 1 ? t.axes[1].count : 1;
      if (shape.empty())
        shape = std::to_string(c.transposed ? h : w) + "x" + std::to_string(c.transposed ? w : h);
      break;
    }
  if (c.encoding == "rgbd") channels = 4;
  return Shaped(raw, channels, shape);
}

std::string Sci(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2g", v);
  return text;
}

std::string Fixed(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", v);
  return text;
}

std::string StorageWords(const std::string &storage) {
  if (storage == "unorm8") return "8-bit";
  if (storage == "unorm16") return "16-bit";
  if (storage == "half") return "half float";
  if (storage == "float32") return "float";
  if (storage == "rgbe") return "RGBE";
  return "decimal text";
}

// "LearnOpenGL's layout (preset learnopengl, brdf_lut.ktx2), y = roughness
// flipped, 8-bit, max error 3.7e-2".
std::string Sentence(const RawImage &image, const Candidate &c, const Score &s,
                     const std::string &smithOfLayout) {
  const TableConvention &v = c.convention;
  std::string text;
  if (!v.preset.empty()) {
    const std::string engine = FindPreset(v.preset)->engine;
    text = engine.substr(0, engine.find(" (")) + "'s layout (preset " + v.preset + ", " +
           v.texture + ")";
  } else {
    text = "lutbake's " + v.table + " layout (x = " + v.axes[0] +
           (v.axes.size() > 1 ? ", y = " + v.axes[1] : std::string()) + ", texel " + v.texels +
           ", channels ";
    for (size_t k = 0; k < v.channels.size(); ++k) text += (k ? ", " : "") + v.channels[k];
    text += ")";
  }
  const std::string xName = v.axes[0], yName = v.axes.size() > 1 ? v.axes[1] : "";
  if (v.transposed) text += ", transposed";
  if (v.flipX) text += ", x = " + xName + " flipped";
  if (v.flipY) text += ", y = " + yName + " flipped";
  for (const auto &[axis, offset] :
       {std::make_pair("x", v.offsetX), std::make_pair("y", v.offsetY)})
    if (offset)
      text += std::string(", ") + axis + " " + std::to_string(std::abs(offset)) + " texel" +
              (std::abs(offset) > 1 ? "s" : "") + " off (file texel i holds i " +
              (offset > 0 ? "+ " : "- ") + std::to_string(std::abs(offset)) + ")";
  if (v.encoding == "srgb") text += ", sRGB-encoded";
  if (v.encoding == "rgbd") text += ", RGBD-encoded";
  if (v.smith != smithOfLayout || v.preset.empty()) text += ", Smith " + v.smith;
  text +=
      ", " + StorageWords(image.storage) + ", max error " + Sci(s.max) + ", RMS " + Sci(s.rms());
  return text;
}

TableConvention ConventionOf(const std::map<std::string, std::string> &options) {
  const auto get = [&](const char *name) {
    const auto it = options.find(name);
    return it == options.end() ? std::string() : it->second;
  };
  TableConvention c;
  c.table = get("as");
  c.preset = get("preset");
  c.texture = get("texture");
  if (c.table.empty() && c.preset.empty())
    throw UsageError("check FILE needs the convention to judge it by: --as TABLE (" +
                     JoinNames(kTables) + ") or --preset NAME; 'lutbake identify FILE' finds it");
  if (!c.table.empty() && !c.preset.empty())
    throw UsageError("--as and --preset both name what the file holds; give one");
  if (!c.table.empty() && std::find(kTables.begin(), kTables.end(), c.table) == kTables.end())
    throw UsageError("--as '" + c.table + "' is not accepted; accepted: " + JoinNames(kTables) +
                     DidYouMean(c.table, kTables));
  for (const char *genericOnly : {"channels", "texels", "mu-mapping", "alpha"})
    if (!c.preset.empty() && !get(genericOnly).empty())
      throw UsageError(std::string("--") + genericOnly + " does not apply with --preset " +
                       c.preset + ": the preset states it");
  if (c.preset.empty() && !c.texture.empty())
    throw UsageError("--texture applies to --preset only");
  if (!get("channels").empty()) {
    c.channels.clear();
    std::string list = get("channels") + ",";
    for (size_t at = 0, comma; (comma = list.find(',', at)) != std::string::npos; at = comma + 1) {
      const std::string meaning = list.substr(at, comma - at);
      if (std::find(kMeanings.begin(), kMeanings.end(), meaning) == kMeanings.end())
        throw UsageError("--channels names '" + meaning + "'; accepted: " + JoinNames(kMeanings) +
                         DidYouMean(meaning, kMeanings));
      c.channels.push_back(meaning);
    }
  }
  if (!get("texels").empty()) c.texels = get("texels");
  if (!get("mu-mapping").empty()) c.muMapping = get("mu-mapping");
  c.smith = get("smith");
  if (!get("alpha").empty()) c.alpha = get("alpha");
  if (!get("encoding").empty()) c.encoding = get("encoding");
  const std::string flips = get("flip");
  c.flipX = flips.find('x') != std::string::npos;
  c.flipY = flips.find('y') != std::string::npos;
  for (const auto &[name, target] :
       {std::make_pair("offset-x", &c.offsetX), std::make_pair("offset-y", &c.offsetY)}) {
    const std::string text = get(name);
    if (text.empty()) continue;
    char *end = nullptr;
    const long v = std::strtol(text.c_str(), &end, 10);
    if (*end != '\0' || v < -64 || v > 64)
      throw UsageError(std::string("--") + name + ": '" + text +
                       "' is not accepted; accepted: a whole number of texels from -64 to 64");
    *target = static_cast<int>(v);
  }
  // --axes: the file's order, x first; against the layout's (mu, then
  // roughness; or the preset's) the other order is a transposition.
  if (const std::string axes = get("axes"); !axes.empty()) {
    std::vector<std::string> base = {"mu", "roughness"};
    if (const Preset *p = FindPreset(c.preset)) {
      base.clear();
      for (const PresetAxis &a : p->textures.front().axes) base.push_back(a.quantity);
    }
    c.transposed = base.size() == 2 && axes == base[1] + "," + base[0];
    if (!c.transposed && axes != base[0] + (base.size() > 1 ? "," + base[1] : std::string()))
      throw UsageError("--axes '" + axes + "' is not the layout's axes in either order");
  }
  return c;
}

double ToleranceOf(const std::map<std::string, std::string> &options) {
  const auto it = options.find("tolerance");
  if (it == options.end() || it->second.empty()) return -1.0;
  const std::string problem = RealNumberProblem(it->second, 0.0, 1e3, "a real number in [0, 1000]");
  if (!problem.empty()) throw UsageError("--tolerance: " + problem);
  return std::strtod(it->second.c_str(), nullptr);
}

std::string Get(const std::map<std::string, std::string> &options, const char *name) {
  const auto it = options.find(name);
  return it == options.end() ? std::string() : it->second;
}

// The picture: each texel's error over its tolerance, black at 0 through
// blue (1/3) and green (2/3) to yellow at 1 (the tolerance), then to red
// at 10 and beyond.
void WriteErrorImage(const std::string &path, const RawImage &image,
                     const std::vector<double> &ratio) {
  std::vector<uint8_t> rgb(ratio.size() * 3);
  for (size_t t = 0; t < ratio.size(); ++t) {
    const double r = ratio[t];
    double red, green, blue;
    if (r <= 1.0) {
      const double s = 3.0 * r;
      blue = s < 1.0 ? s : s < 2.0 ? 2.0 - s : 0.0;
      green = s < 1.0 ? 0.0 : s < 2.0 ? s - 1.0 : 1.0;
      red = s < 2.0 ? 0.0 : s - 2.0;
    } else {
      const double s = std::min(std::log10(r), 1.0);
      red = 1.0;
      green = 1.0 - s;
      blue = 0.0;
    }
    rgb[3 * t] = static_cast<uint8_t>(std::lround(255.0 * red));
    rgb[3 * t + 1] = static_cast<uint8_t>(std::lround(255.0 * green));
    rgb[3 * t + 2] = static_cast<uint8_t>(std::lround(255.0 * blue));
  }
  WriteRgb8Png(path, image.width, image.height, rgb);
}

// An outcome that so far says only which file it judged.
TableFileOutcome FileOutcome(const std::string &path, const RawImage &image) {
  TableFileOutcome o;
  o.path = path;
  o.format = image.format;
  o.storage = image.storage;
  o.width = image.width;
  o.height = image.height;
  o.channels = image.channels;
  return o;
}

// The outcome of `candidate` over `texels` (all, or a grid of `gridNote`).
TableFileOutcome Outcome(const std::string &path, const RawImage &image, const Candidate &c,
                         const ExactValues &exact, const Score &s, const std::string &smithOfLayout,
                         const std::string &gridNote) {
  TableFileOutcome o = FileOutcome(path, image);
  o.convention = c.convention;
  o.maxError = s.max;
  o.rmsError = s.rms();
  o.passed = s.above == 0 && s.count > 0;
  o.worstX = s.worstX;
  o.worstY = s.worstY;
  o.worstChannel = s.worstChannel;
  // Named, not a structured binding: C++17 lambdas cannot capture those.
  const auto worstIndex = LayoutIndex(c.convention, image, s.worstX, s.worstY);
  const auto i0 = worstIndex.first, i1 = worstIndex.second;
  const auto quantityNamed = [&](const char *name) {
    for (size_t a = 0; a < c.layout.axes.size(); ++a)
      if (c.layout.axes[a].quantity == name) return exact.Quantity(a, a == 0 ? i0 : i1);
    return 0.0;
  };
  o.worstMu = quantityNamed("mu");
  o.worstRoughness = quantityNamed("roughness");
  o.worstStored = s.worstStored;
  o.worstExact = s.worstExact;
  o.worstTolerance = s.worstTolerance;
  o.valuesCompared = s.count;
  o.valuesAboveTolerance = s.above;
  o.sentence = Sentence(image, c, s, smithOfLayout);
  const TableConvention &v = c.convention;
  const std::string channelName = static_cast<size_t>(s.worstChannel) < image.channelNames.size()
                                      ? image.channelNames[static_cast<size_t>(s.worstChannel)]
                                      : std::to_string(s.worstChannel);
  o.text = path + ": " + image.format + " " + std::to_string(image.width) + " x " +
           std::to_string(image.height) + ", " + std::to_string(image.channels) + " channel(s), " +
           image.storage + "\n  as " + o.sentence + "\n  max error " + Sci(s.max) + " at texel (" +
           std::to_string(s.worstX) + ", " + std::to_string(s.worstY) + ") channel " + channelName +
           " (mu " + Fixed(o.worstMu) + ", roughness " + Fixed(o.worstRoughness) + "): read " +
           Fixed(s.worstStored) + ", exact " + Fixed(s.worstExact) + ", tolerance " +
           Sci(s.worstTolerance) + "\n  RMS error " + Sci(o.rmsError) + " over " +
           std::to_string(s.count) + " values" + gridNote + "; " + std::to_string(s.above) +
           " above their tolerance\n";
  nlohmann::ordered_json j;
  j["file"] = path;
  j["format"] = image.format;
  j["storage"] = image.storage;
  j["width"] = image.width;
  j["height"] = image.height;
  j["channels"] = image.channels;
  j["table"] = v.table;
  j["preset"] =
      v.preset.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(v.preset);
  j["texture"] =
      v.texture.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(v.texture);
  j["axes"] = v.axes;
  j["texels"] = v.texels;
  j["channelMeanings"] = v.channels;
  j["transposed"] = v.transposed;
  j["flipX"] = v.flipX;
  j["flipY"] = v.flipY;
  j["offsetX"] = v.offsetX;
  j["offsetY"] = v.offsetY;
  j["encoding"] = v.encoding;
  j["smith"] = v.smith;
  j["alpha"] = v.alpha;
  j["maxError"] = s.max;
  j["rmsError"] = o.rmsError;
  j["worst"] = {{"x", s.worstX},
                {"y", s.worstY},
                {"channel", s.worstChannel},
                {"mu", o.worstMu},
                {"roughness", o.worstRoughness},
                {"read", s.worstStored},
                {"exact", s.worstExact},
                {"tolerance", s.worstTolerance}};
  j["valuesCompared"] = s.count;
  j["valuesAboveTolerance"] = s.above;
  j["passed"] = o.passed;
  j["sentence"] = o.sentence;
  o.json = j.dump(2);
  return o;
}

void RecordJson(TableFileOutcome *o, const char *key, bool value) {
  nlohmann::ordered_json j = nlohmann::ordered_json::parse(o->json);
  j[key] = value;
  o->json = j.dump(2);
}

}  // namespace

const std::vector<ConventionOption> &ConventionOptions() {
  static const std::vector<ConventionOption> options = {
      {"as", "TABLE", "Judge FILE (any PNG, EXR, DDS, KTX2, HDR or C/C++/JS array) as this table",
       kTables},
      {"preset", "NAME", "Judge FILE as this preset's texture, in the preset's layout and model",
       PresetNames()},
      {"texture",
       "FILE",
       "With --preset: which of its textures (default: the one of FILE's size)",
       {}},
      {"axes",
       "LIST",
       "FILE's axes, x first (the other order of the layout's is a transposition)",
       {"mu,roughness", "roughness,mu", "roughness"}},
      {"mu-mapping",
       "NAME",
       "What the mu axis holds: mu, sqrt-mu (u = sqrt(NdotV), Unity HDRP) or sqrt-one-minus-mu "
       "(EEVEE)",
       {"mu", "sqrt-mu", "sqrt-one-minus-mu"}},
      {"texels",
       "NAME",
       "Texel i of N at u = (i + 0.5) / N (centres) or i / (N - 1) (edges)",
       {"centres", "edges"}},
      {"flip", "LIST", "Axes of FILE that run the other way", {"x", "y"}, true},
      {"offset-x", "N", "File texel i holds the layout's texel i + N along x (after --flip)", {}},
      {"offset-y", "N", "The same along y (Filament's generator: 1)", {}},
      {"channels",
       "LIST",
       "What FILE's channels hold, from the first: A, B, E (= A + B), sheen_E, f82, Eavg, or - "
       "(not compared) (default: dfg A,B; otherwise the table)",
       {}},
      {"encoding",
       "NAME",
       "linear; srgb (FILE holds the sRGB encoding: its decoding is compared); rgbd (RGB = value / "
       "D, A = D)",
       {"linear", "srgb", "rgbd"}},
      {"smith", "NAME",
       "The G2 integrated: exact Smith (correlated, separable), Schlick-GGX k = alpha / 2 "
       "(schlick-ggx-ibl) or Unreal's Vis_SmithJointApprox (default: the preset's, or correlated)",
       kSmithNames},
      {"alpha",
       "NAME",
       "alpha = roughness^2 (squared) or roughness (linear)",
       {"squared", "linear"}},
      {"size", "WxH", "A source array's width and height in texels (default: square)", {}},
      {"tolerance",
       "EPS",
       "Pass when every value is within EPS (default: half a storage step plus the exact value's "
       "bound)",
       {}},
      {"error-image", "PATH", "Write the error picture, an 8-bit RGB PNG of FILE's size", {}}};
  return options;
}

TableFileOutcome CheckTableFile(const TableFileRequest &request) {
  tbb::global_control parallelism(tbb::global_control::max_allowed_parallelism,
                                  static_cast<size_t>(ThreadCount(request.threads)));
  const TableConvention wanted = ConventionOf(request.options);
  const double fixedTolerance = ToleranceOf(request.options);
  const RawImage image =
      ShapedFor(ReadRawImage(request.path), wanted, Get(request.options, "size"));
  const Candidate c = Realise(wanted, image);
  ExactValues exact(c.layout);
  Texels all;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) all.emplace_back(x, y);
  EnsureFor(image, c, exact, all);
  std::vector<double> ratio(all.size(), 0.0);
  const Score s = Compare(image, c, exact, all, fixedTolerance, &ratio);
  TableFileOutcome o = Outcome(request.path, image, c, exact, s, c.convention.smith, "");
  o.matched = o.passed;
  o.text += o.passed ? "pass\n" : "FAIL\n";
  if (const std::string path = Get(request.options, "error-image"); !path.empty()) {
    WriteErrorImage(path, image, ratio);
    o.errorImage = path;
    o.text += "  error picture: " + path + "\n";
  }
  return o;
}

TableFileOutcome IdentifyTable(const TableFileRequest &request) {
  tbb::global_control parallelism(tbb::global_control::max_allowed_parallelism,
                                  static_cast<size_t>(ThreadCount(request.threads)));
  const auto shared = std::make_shared<const RawImage>(ReadRawImage(request.path));
  const RawImage &raw = *shared;
  const std::string onlyPreset = Get(request.options, "preset");
  if (!onlyPreset.empty() && !FindPreset(onlyPreset))
    throw UsageError("--preset '" + onlyPreset + "' is not a preset; accepted: " +
                     PresetNameList() + DidYouMean(onlyPreset, PresetNames()));
  // The bases: every preset texture, and lutbake's layouts at the file's size.
  std::vector<TableConvention> bases;
  for (const Preset *p : AllPresets())
    if (onlyPreset.empty() || p->name == onlyPreset)
      for (const PresetTexture &t : p->textures) {
        // The sheen's Schlick-weighted part (HDRP) costs ~30 ms a texel:
        // tried only when its preset is named.
        bool costly = false;
        for (const PresetChannel &ch : t.channels) costly = costly || ch.meaning == "sheen_B";
        if (costly && onlyPreset.empty()) continue;
        TableConvention c;
        c.smith.clear();  // the preset's own
        c.preset = p->name;
        c.texture = t.file;
        bases.push_back(c);
      }
  if (onlyPreset.empty())
    for (const char *texels : {"centres", "edges"})
      for (const std::vector<std::string> &channels :
           {std::vector<std::string>{"A", "B"}, {"B", "E"}, {"E"}}) {
        TableConvention c;
        c.table = channels.size() == 1 ? "E" : "dfg";
        c.texels = texels;
        c.channels = channels;
        bases.push_back(c);
      }
  struct Tried {
    Candidate candidate;
    std::string smithOfLayout;
    std::shared_ptr<const RawImage> image;  // shaped (a source array), else the file's
    double rms = 0.0;
  };
  std::vector<Tried> tried;
  std::map<std::string, std::unique_ptr<ExactValues>> exacts;
  const auto exactOf = [&](const Candidate &c) -> ExactValues & {
    auto &slot = exacts[c.key];
    if (!slot) slot = std::make_unique<ExactValues>(c.layout);
    return *slot;
  };
  for (const TableConvention &base : bases) {
    for (bool transposed : {false, true}) {
      TableConvention layout = base;
      layout.transposed = transposed;
      for (const char *encoding : {"linear", "srgb", "rgbd"}) {
        layout.encoding = encoding;
        std::shared_ptr<const RawImage> shaped = shared;
        Candidate first;
        try {
          if (raw.flat) shaped = std::make_shared<const RawImage>(ShapedFor(raw, layout, ""));
          first = Realise(layout, *shaped);
        } catch (const UsageError &) {
          continue;  // not this file's size or channels
        }
        bool splitSum = false;
        for (const PresetChannel &ch : first.layout.channels)
          splitSum = splitSum || SplitSumChannel(ch.meaning);
        const std::string own = first.convention.smith;
        const RawImage &image = *shaped;
        for (const std::string &smith : splitSum ? kSmithNames : std::vector<std::string>{own}) {
          TableConvention variant = layout;
          variant.smith = smith;
          const Candidate modelled = Realise(variant, image);
          const Texels grid = Grid(image, 16);
          for (int flips = 0; flips < 4; ++flips)
            for (int offsetX = -1; offsetX <= 1; ++offsetX)
              for (int offsetY = -1; offsetY <= 1; ++offsetY) {
                Candidate c = modelled;
                c.convention.flipX = flips & 1;
                c.convention.flipY = (flips & 2) != 0;
                c.convention.offsetX = image.width > 1 ? offsetX : 0;
                c.convention.offsetY = image.height > 1 ? offsetY : 0;
                if ((image.width == 1 && offsetX) || (image.height == 1 && offsetY)) continue;
                c.departures += c.convention.flipX + c.convention.flipY + std::abs(offsetX) +
                                std::abs(offsetY) + (smith != own);
                try {
                  EnsureFor(image, c, exactOf(c), grid);
                } catch (const std::invalid_argument &) {
                  continue;  // a texel this layout's integrals refuse
                } catch (const std::domain_error &) {
                  continue;
                }
                const Score s = Compare(image, c, exactOf(c), grid, -1.0, nullptr);
                tried.push_back({c, own, shaped, s.rms()});
              }
        }
      }
    }
  }
  if (tried.empty()) {
    TableFileOutcome o = FileOutcome(request.path, raw);
    o.sentence = "no known convention matches: " + raw.format + " " + std::to_string(raw.width) +
                 " x " + std::to_string(raw.height) + " with " + std::to_string(raw.channels) +
                 " channel(s) fits no known layout's size and channels" +
                 (onlyPreset.empty() ? "" : " of preset " + onlyPreset);
    o.text = request.path + ": " + o.sentence + "\n";
    nlohmann::ordered_json j;
    j["file"] = request.path;
    j["matched"] = false;
    j["table"] = nullptr;
    j["preset"] = nullptr;
    j["sentence"] = o.sentence;
    o.json = j.dump(2);
    return o;
  }
  // The closest on the coarse grid, then the best few again on a finer one;
  // within 1% of the best RMS the fewest departures win.
  const auto better = [](const Tried &a, const Tried &b) {
    const double scale = std::max(a.rms, b.rms);
    if (std::fabs(a.rms - b.rms) > 0.01 * scale + 1e-15) return a.rms < b.rms;
    return a.candidate.departures < b.candidate.departures;
  };
  std::stable_sort(tried.begin(), tried.end(),
                   [](const Tried &a, const Tried &b) { return a.rms < b.rms; });
  tried.resize(std::min<size_t>(tried.size(), 12));
  for (Tried &t : tried) {
    const Texels fine = Grid(*t.image, 64);
    EnsureFor(*t.image, t.candidate, exactOf(t.candidate), fine);
    t.rms = Compare(*t.image, t.candidate, exactOf(t.candidate), fine, -1.0, nullptr).rms();
  }
  const Tried *best = &tried.front();
  for (const Tried &t : tried)
    if (better(t, *best)) best = &t;
  // The winner over every texel, or a 256 x 256 grid of a larger file.
  const RawImage &image = *best->image;
  const Texels final = Grid(image, 256);
  ExactValues &exact = exactOf(best->candidate);
  EnsureFor(image, best->candidate, exact, final);
  const Score s = Compare(image, best->candidate, exact, final, -1.0, nullptr);
  const bool every = final.size() == static_cast<size_t>(image.width) * image.height;
  TableFileOutcome o = Outcome(request.path, image, best->candidate, exact, s, best->smithOfLayout,
                               every ? "" : " (a 256 x 256 grid of its texels)");
  o.matched = o.rmsError <= 1e-2 && o.maxError <= 0.1;
  const size_t as = o.text.find("\n  as ");
  o.text.replace(as, 6,
                 o.matched ? "\n  best match: " : "\n  no known convention matches; closest: ");
  o.text += o.passed ? "exact to its storage (every value within its tolerance)\n"
            : o.matched
                ? "a match, though not exact to its storage\n"
                : "no match (a match has RMS error at most 1e-2 and max error at most 0.1)\n";
  RecordJson(&o, "matched", o.matched);
  return o;
}

}  // namespace lutbake
