// lutbake::Furnace: the white furnace of a classic reflection model, as
// `lutbake furnace` runs it: directional albedo over (parameter, mu), its
// average, the worst gain and loss, and optionally the files of
// validation/furnace_report.h written into a directory (all or nothing,
// OutputTransaction).
//
//   lutbake::FurnaceRequest request;
//   request.model = "microfacet";
//   request.f0 = "0.04";
//   request.compensation = true;
//   std::cout << lutbake::Furnace(request).text;
//
// The numbers are given as the command line spells them (a list is
// comma-separated), and the messages quote them so. Throws UsageError for
// an option the model does not take, a value it does not accept, or an
// --out that is not a directory; IoError when the files cannot be written.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "lutbake/validation/furnace_report.h"

namespace lutbake {

// lambert, phong, blinn-phong, oren-nayar, eon, microfacet.
std::vector<std::string> FurnaceModelNames();

struct FurnaceRequest {
  std::string model;
  // phong: none, n+1, n+2 (default); blinn-phong: none, n+2, n+8, exact
  // (default). oren-nayar: full (default), qualitative; eon: exact
  // (default), approx, fon. Empty: the default; set for another model: an
  // error.
  std::string normalisation, variant;
  // microfacet only (set for another model: an error). ndf: ggx (default),
  // beckmann; smith: correlated (default), separable, schlick-ggx-ibl,
  // schlick-ggx-direct.
  std::optional<std::string> ndf, smith;
  // Schlick's F0 in [0, 1], or the exact Fresnel's eta in [0.001, 1000] and
  // k in [0, 1000]; none: F = 1. One number each; empty: not given.
  std::optional<std::string> f0, eta, k;
  std::optional<bool> compensation;  // the Kulla-Conty lobe
  // With compensation: kulla-conty (default: F_avg^2 E_avg / (1 - F_avg
  // (1 - E_avg))) or single (F_avg E_avg / (1 - F_avg (1 - E_avg))).
  std::optional<std::string> msFresnel;
  // The model's parameter (n, sigma or r) and the view cosines; empty: the
  // model's default grid, and mu = 0, 1/16, ..., 1.
  std::string parameters, mus;
  std::string outputDirectory;  // empty: no files
  int threads = 0;              // 0: all cores; the values do not depend on it
};

struct FurnaceOutcome {
  FurnaceSettings settings;
  FurnaceResult result;
  std::vector<std::string> files;  // written into outputDirectory
  std::string json;                // `furnace --json`'s object (furnace.json)
  std::string text;                // the table `furnace` prints
};

FurnaceOutcome Furnace(const FurnaceRequest &request);

}  // namespace lutbake
