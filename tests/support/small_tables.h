// Small tables for the format tests: every kind baked at a few texels, and
// a 3D table whose slices differ (slice z holds E (1 - 0.25 z)), so that a
// slice mixed up with another shows.
#pragma once

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "lutbake/tables/bake.h"

namespace lutbake::test {

inline std::filesystem::path FormatTempDir(const std::string &name) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("lutbake_fmt_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

inline Table SmallTableOf(const TableDefinition &kind, int size = 6) {
  BakeSettings s;
  s.size = size;
  s.samples = 64;
  s.depthSize = 1;  // 3D tables: one slice here; ThreeSliceTable has three
  s.commandLine = "lutbake bake --test";
  return BakeTable(kind, s);
}

inline Table ThreeSliceTable(const Axis &z = LinearAxis("eta", 1.0, 2.0, 3)) {
  BakeSettings s;
  s.size = 4;
  s.commandLine = "lutbake bake --test3d";
  Table t = BakeTable(TableNamed("E"), s);
  const std::vector<double> values = t.values, errors = t.errors;
  t.z = z;
  t.values.clear();
  t.errors.clear();
  for (int iz = 0; iz < z.count; ++iz)
    for (size_t i = 0; i < values.size(); ++i) {
      t.values.push_back(values[i] * (1.0 - 0.25 * iz));
      t.errors.push_back(errors[i]);
    }
  for (size_t i = 0; i < t.metadata.size(); ++i)
    if (t.metadata[i].first == "axisY") {
      t.metadata.insert(t.metadata.begin() + static_cast<long>(i) + 1, {"axisZ", DescribeAxis(z)});
      break;
    }
  return t;
}

inline std::vector<unsigned char> FileBytes(const std::filesystem::path &path) {
  std::ifstream in(path, std::ios::binary);
  return std::vector<unsigned char>(std::istreambuf_iterator<char>(in), {});
}

}  // namespace lutbake::test
