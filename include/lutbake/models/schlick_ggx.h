// The Schlick-GGX visibility of the UE4 / LearnOpenGL school: Smith's
// separable G2 = G1(mu_o) G1(mu_i) with Schlick's rational fit
//   G1(mu) = mu / (mu (1 - k) + k),
// and k from the perceptual roughness r (alpha = r^2) in one of two ways:
//   image lighting (ibl):  k = alpha / 2
//   direct lighting:       k = (r + 1)^2 / 8  (Karis 2013's "remapping" for
//                          punctual lights; k = 1/8 even for a mirror)
// Neither is the exact Smith G of GGX: the furnace measures the difference.
#pragma once

#include <string_view>

namespace lutbake {

enum class SchlickGgxK { kIbl, kDirect };

std::string_view ToString(SchlickGgxK kind);

double SchlickGgxKFromRoughness(SchlickGgxK kind, double perceptualRoughness);

// G1(mu) = mu / (mu (1 - k) + k); 1 for k = 0.
inline double SchlickGgxG1(double k, double mu) { return mu / (mu * (1.0 - k) + k); }

}  // namespace lutbake
