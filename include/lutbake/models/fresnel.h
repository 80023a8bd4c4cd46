// Fresnel reflectance models and their hemispherical averages.
//
//   Schlick:    F(mu) = F0 + (1 - F0) (1 - mu)^5
//   exact:      unpolarised reflectance of a smooth interface with relative
//               complex index n = eta + i k (k = 0 for a dielectric), light
//               arriving from the outside medium at cos(theta) = mu:
//                 w   = sqrt(n^2 - sin^2(theta))   (principal branch)
//                 r_s = (mu - w) / (mu + w),  r_p = (n^2 mu - w) / (n^2 mu + w)
//                 F   = (|r_s|^2 + |r_p|^2) / 2
//               The same expression covers eta < 1, k = 0: past the critical
//               angle w is imaginary and F = 1 (total internal reflection).
// Their hemispherical averages F_avg = 2 integral_0^1 F(mu) mu dmu are in
// integrators/fresnel_average.h.
#pragma once

#include <string_view>

namespace lutbake {

enum class FresnelModel { kSchlick, kDielectric, kConductor };

std::string_view ToString(FresnelModel model);

double SchlickFresnel(double f0, double mu);
double ExactFresnel(double eta, double k, double mu);

}  // namespace lutbake
