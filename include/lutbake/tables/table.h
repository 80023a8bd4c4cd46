// A baked table: its axes (with the texel convention), its values and the
// per-texel error estimate, and the metadata every writer copies into its file.
//
// Texel convention (SPEC section 2): texel x of an axis of N texels holds the
// value at u = (x + 0.5) / N, mapped linearly onto [min, max]. Values are
// stored row-major, y (the second axis) outer, x inner, channels interleaved:
//   values[(y * width + x) * channels + c].
// A 3D table (glass_E(mu, r, eta)) adds a third axis z outermost: its slices
// of constant z follow one another,
//   values[((z * height + y) * width + x) * channels + c],
// which is also how the files store it (EXR: the slices stacked along the
// image's y, slice z = 0 on top; .bin version 2; headers: kDepth).
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace lutbake {

class TableDefinition;  // table_definition.h

struct Axis {
  std::string name;  // the physical quantity: "mu", "perceptualRoughness", "F0", "eta", "k"
  double min = 0.0;
  double max = 1.0;
  int count = 1;
  // A listed axis (bake plans): when not empty, texel i holds the value at
  // exactly nodes[i] (strictly increasing; count = nodes.size(), min and max
  // the first and last), and a lookup interpolates linearly in the axis
  // value between neighbouring nodes. Empty: the linear texel-centre axis.
  std::vector<double> nodes;

  bool listed() const { return !nodes.empty(); }
  // Texel-centre convention: the value of texel i.
  double TexelCenter(int i) const {
    return listed() ? nodes[static_cast<size_t>(i)] : min + (max - min) * ((i + 0.5) / count);
  }
  // The inverse: the continuous texel coordinate of a value (i at centres;
  // a listed axis clamps to [0, count - 1], a linear one does not).
  double TexelCoordinate(double value) const;
};

// A linear axis over [min, max] with `count` texels.
inline Axis LinearAxis(std::string name, double min, double max, int count) {
  Axis axis;
  axis.name = std::move(name);
  axis.min = min;
  axis.max = max;
  axis.count = count;
  return axis;
}
// A listed axis at `nodes` (strictly increasing, not empty).
Axis ListedAxis(std::string name, std::vector<double> nodes);

struct Table {
  // What the table is (table_definition.h); the readers set it from the
  // metadata key 'table'.
  const TableDefinition *definition = nullptr;
  // The file stem and header identifier when it is not the definition's
  // name: a bake plan that needs two variants of a table names them
  // "E_beckmann", "Favg_conductor", ...
  std::string name;
  Axis x;  // width: the first axis (mu, or the Fresnel parameter)
  Axis y;  // height: perceptual roughness, or the second Fresnel axis;
           // a 1D table has y.count = 1 and y.name empty
  Axis z = LinearAxis("", 0.0, 1.0, 1);  // depth: a 3D table's third axis
                                         // (eta); otherwise count 1, name empty
  int channels = 1;
  std::vector<std::string> channelNames;  // EXR channel names: {"Y"} or {"R", "G"}
  std::vector<double> values;             // see the layout above
  std::vector<double> errors;             // same layout: estimated error bound per value
  // Ordered (key, value) pairs: table, ndf, smith, fresnel, estimator, ...
  std::vector<std::pair<std::string, std::string>> metadata;
  // A fitted table's per-texel maps (TableDefinition::FitMapNames: an LTC
  // table's lobeError, polygonError, leakage), texel by texel in the order
  // of the values: fitMaps[texel * fitMapNames.size() + k]. Empty for the
  // integrated tables.
  std::vector<std::string> fitMapNames;
  std::vector<double> fitMaps;

  // name, or the definition's name ("" without either).
  std::string Name() const;
  // The definition's name ("E" for a table named "E_beckmann").
  std::string DefinitionName() const;
  int width() const { return x.count; }
  int height() const { return y.count; }
  int depth() const { return z.count; }
  bool is2D() const { return !y.name.empty(); }
  bool is3D() const { return !z.name.empty(); }
  // Texels in all: width x height x depth.
  size_t texelCount() const { return static_cast<size_t>(x.count) * y.count * z.count; }
  size_t index(int ix, int iy, int c) const {
    return (static_cast<size_t>(iy) * x.count + ix) * channels + c;
  }
  size_t index(int ix, int iy, int iz, int c) const {
    return ((static_cast<size_t>(iz) * y.count + iy) * x.count + ix) * channels + c;
  }
  double value(int ix, int iy, int c = 0) const { return values[index(ix, iy, c)]; }

  double MaxError() const;
  double RmsError() const;
  const std::string *FindMetadata(const std::string &key) const;
};

// A double printed with 17 significant digits: reads back to the same double.
std::string FormatDouble(double v);

// An axis in words, as the metadata key axisX / axisY holds it:
//   "mu linear [0, 1], 32 texels"
//   "perceptualRoughness values [0.25, 0.5], 2 texels"   (a listed axis)
// and the parser of that text (false when it is not of either form).
std::string DescribeAxis(const Axis &axis);
bool ParseAxisDescription(const std::string &text, Axis *axis);

// The error map of a table: a table of the same axes and channels whose
// values are the per-texel error bounds of T.exr's float32 values (rounding
// included, rounded up: storage.h), written as T.err.exr.
Table ErrorMapOf(const Table &table);

// The fit maps of a fitted table (fitMapNames, fitMaps) as a table of the
// same axes whose channels are the maps, written as T.fit.exr; its metadata
// is the table's with 'table' = "T.fit". Its errors are zero (the maps are
// measurements, not bounded values).
Table FitMapOf(const Table &table);

}  // namespace lutbake
