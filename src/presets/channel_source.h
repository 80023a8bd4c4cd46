// What a preset's channels read, resolved once for a texture: each channel's
// meaning is a record of channel_source.cpp, the one list of them, that
// names a registered table and its channel (read at the point the texel
// gives that table), or one of the few quantities no table holds.
// Private to the presets layer: preset.cpp bakes through it.
#pragma once

#include <array>
#include <vector>

#include "lutbake/integrators/ltc_fit.h"
#include "lutbake/presets/preset.h"

namespace lutbake {

// The quantities of one texel that the channels are read at.
struct PresetTexel {
  const PresetModel *model = nullptr;
  BakeSettings settings;    // model->TableSettings()
  double mu = 0.0;          // the mu axis's quantity (0 without one)
  double roughness = 0.0;   // the engine's roughness (the roughness axis's quantity)
  double alpha = 0.0;       // the model's alpha there, max(alpha, alphaMin)
  double eta = 1.0;         // the relative IOR (1 without an eta axis)
  double u = 0.0, v = 0.0;  // the texel's own texture coordinates on x and y
};

// alpha from the engine's roughness q under the model's mapping and clamp.
double PresetAlpha(const PresetModel &model, double q);

struct PresetQuantity;
struct PresetTableReading;

// A texture's channels resolved, and the axes they read.
class PresetChannelPlan {
 public:
  // Throws std::invalid_argument for an unknown meaning, a table a
  // meaning cannot read, or axes the channels do not find.
  explicit PresetChannelPlan(const PresetTexture &texture);

  // The axes (indices into texture.axes) that hold mu, the roughness and
  // eta ("eta" or "1/eta"), -1 where none does.
  int muAxis = -1, roughnessAxis = -1, etaAxis = -1;

  // Does a channel hold an entry of an LTC fit (fitted over the texture's
  // whole (mu, roughness) grid at once)?
  bool Fitted() const { return fittedTable_ != nullptr; }
  // The lobe of that fit at the engine's roughness q.
  LtcLobe LobeAt(double q) const;
  // The channels that are not entries of the fit (a texture of them alone).
  PresetTexture WithoutFit() const;

  // The channels at `texel` with their bounds; `fit` is the texel's LTC
  // fit where Fitted().
  void Channels(const PresetTexel &texel, const LtcMatrix *fit, double *values,
                double *errors) const;

 private:
  struct Channel {
    const PresetQuantity *quantity = nullptr;
    int reading = -1;  // index into readings_ (a table's value), or -1
    int channel = -1;  // the table's channel, or the fit's entry (-1: m11 = 1)
    int plus = -1;     // a second channel added
    int over = -1;     // the divisor (index into divisors_), or -1
  };
  // `meaning` (of the fit of `table`, where it names one) resolved, the
  // table it reads added to readings_ (or fittedTable_) and its axes to
  // *reads.
  Channel Resolve(const std::string &meaning, const std::string &table, unsigned *reads);
  // A channel's value (its bound into *error) before the divisor.
  double ValueOf(const Channel &c, const PresetTexel &texel, const std::vector<PointValue> &read,
                 const LtcMatrix *fit, double *error) const;

  const PresetTexture *texture_;
  const PresetTableReading *fittedTable_ = nullptr;
  std::vector<const PresetTableReading *> readings_;  // each table read, once
  std::vector<Channel> channels_;
  std::vector<Channel> divisors_;
};

}  // namespace lutbake
