// `lutbake furnace`: the white furnace of a classic reflection model (Lambert,
// Phong, Blinn-Phong, Oren-Nayar, EON, microfacet with or without Kulla-Conty
// compensation): directional albedo over (parameter, mu), its average, the
// worst gain and loss, and with --out the files of validation/furnace_report.h.
#pragma once

#include <CLI/CLI.hpp>
#include <string>

namespace lutbake::cli {

struct FurnaceOptions {
  std::string model;
  std::string normalisation;  // phong, blinn-phong
  std::string variant;        // oren-nayar, eon
  std::string ndf = "ggx";
  std::string smith = "correlated";
  std::string f0, eta, k;  // microfacet Fresnel: Schlick or exact; neither: F = 1
  bool compensation = false;
  std::string msFresnel = "kulla-conty";
  std::string parameter, mu;  // comma-separated lists
  std::string out;
  bool json = false;
  int threads = 0;
};

void SetupFurnaceCommand(CLI::App &app, FurnaceOptions &options);
int RunFurnace(const FurnaceOptions &options, CLI::App &app);

}  // namespace lutbake::cli
