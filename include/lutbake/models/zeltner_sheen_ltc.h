// Zeltner, Burley and Chiang's multiple-scattering sheen (SIGGRAPH 2022),
// OpenPBR's fuzz: a linearly transformed cosine whose inverse matrix is
// [[a, 0, b], [0, a, 0], [0, 0, 1]] in the frame of the view, scaled by the
// layer's reflectance R, all three tabulated by the authors over the sheen
// roughness alpha and cos(theta_o) (32 x 32, texel edges) from simulations
// of a volumetric SGGX fibre layer. lutbake has no integrator for that
// model: this is the published table, interpolated as its authors'
// renderer does, for engines (Babylon.js's fuzz texture) that lay it out
// again.
#pragma once

#include <array>

namespace lutbake {

inline constexpr int kZeltnerSheenLtcSize = 32;

// {a, b, R} at (mu_o, alpha), bilinear between the table's edge samples
// alpha = i / 31, mu_o = j / 31 (both clamped to [0, 1]); at a sample, the
// table's own entry.
std::array<double, 3> ZeltnerSheenLtc(double mu_o, double alpha);

}  // namespace lutbake
