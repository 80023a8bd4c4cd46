// --format fit and fit-glsl / fit-hlsl / fit-wgsl / fit-msl: a 1D or 2D
// table as a fitted closed form instead of a texture (tables/table_fit.h).
//
//   T_fit.h      C++17, self-contained, namespace lutbake_fit:
//                  std::array<float, C> T(double x[, double y])
//                in the table's own coordinates (mu, roughness, as `lutbake
//                eval` takes them), constexpr double T_max_error (the
//                certified bound over T_domain, the float32 evaluation
//                included) and constexpr int T_coefficients (per channel);
//   T_fit.glsl / .hlsl / .wgsl / .metal
//                the same evaluation as a shader function lutbake_fit_T(x[,
//                y]) returning float or vecC, with its arrays.
// The evaluation is float32 throughout and the same step by step in every
// file and in PiecewiseChebyshev::EvaluateFloat, so the C++ reproduces the
// library bit for bit (no FMA contraction), and the bound covers a shader.
//
// Reading a fit back (`lutbake check`): ReadFitSource parses T_fit.h, our own
// emitted text: the "//   key: value" comment (table, model, fitMap), the
// integer constants kChannels, kPatchesX, kPatchesY, kNx, kNy, the float
// constants kXLo, kXHi, kYLo, kYHi, the arrays kBreaksX, kBreaksY and the
// coefficients between the lines "// lutbake-fit-coefficients-begin" and
// "// lutbake-fit-coefficients-end", and T_max_error and T_coefficients.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "lutbake/formats/source_formats.h"
#include "lutbake/integrators/chebyshev_fit.h"

namespace lutbake {

struct FitSource {
  std::string name;  // T, the file's function
  std::vector<std::pair<std::string, std::string>> metadata;
  PiecewiseChebyshev fit;
  double maxError = 0.0;  // T_max_error
  int coefficients = 0;   // T_coefficients
};

// The text of T_fit.h. `params` are the coordinate names (mu, roughness);
// `metadata` opens its comment; `certificate` states the bound.
std::string FitCppSource(const std::string &name, const std::vector<std::string> &params,
                         const PiecewiseChebyshev &fit, const FitCertificate &certificate,
                         const std::vector<std::pair<std::string, std::string>> &metadata);
// The shader function lutbake_fit_<name> and its arrays in one language.
std::string FitShaderSource(ShaderLanguage language, const std::string &name,
                            const std::vector<std::string> &params, const PiecewiseChebyshev &fit,
                            const FitCertificate &certificate,
                            const std::vector<std::pair<std::string, std::string>> &metadata);

// Reads T_fit.h back; throws IoError naming the path and what is missing.
FitSource ReadFitSource(const std::string &path);

}  // namespace lutbake
