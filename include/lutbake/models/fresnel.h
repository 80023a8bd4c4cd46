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
//   F82 tint:   the metal Fresnel of the Adobe Standard Material (Kutz et
//               al. 2021) and OpenPBR, per colour channel: Schlick with
//               F90 = 1 minus a bump that brings F at mu_bar = 1/7 (the
//               angle of 82 degrees, where real metals dip) to tint times
//               Schlick's value there:
//                 F(mu) = Schlick(F0, mu) - a mu (1 - mu)^6,
//                 a     = Schlick(F0, mu_bar) (1 - tint) / (mu_bar (1 - mu_bar)^6).
//               F(1) = F0, F(0) = 1, F(mu_bar) = tint Schlick(F0, mu_bar).
//               Not clamped: for small F0 and tint F dips below 0 at some
//               mu (F0 = tint = 0: -0.127 at mu = 0.26; it does somewhere
//               for tint below 0.51 at F0 = 0, 0.13 at F0 = 0.2, 0.02 at
//               F0 = 0.5, never from F0 = 0.7 on). OpenPBR 1.2 clamps F
//               at 0; real metals (F0 >= 0.5, tint near 1) never reach it.
// Their hemispherical averages F_avg = 2 integral_0^1 F(mu) mu dmu are in
// integrators/fresnel_average.h.
#pragma once

#include <string_view>

namespace lutbake {

enum class FresnelModel { kSchlick, kDielectric, kConductor, kF82 };
// Every model, in the order the command line offers them.
inline constexpr FresnelModel kAllFresnelModels[] = {FresnelModel::kSchlick,
                                                     FresnelModel::kDielectric,
                                                     FresnelModel::kConductor, FresnelModel::kF82};

std::string_view ToString(FresnelModel model);

double SchlickFresnel(double f0, double mu);
double ExactFresnel(double eta, double k, double mu);
// The F82-tint coefficient a of (f0, tint), and F of the model at mu.
double F82TintCoefficient(double f0, double tint);
double F82TintFresnel(double f0, double tint, double mu);

}  // namespace lutbake
