// The white furnace of a reflection model: its directional albedo
//   albedo(mu_o) = int_{hemisphere} f(o, i) mu_i d(omega_i)
// (reflectance 1, a uniform white environment of radiance 1) and its
// cosine-weighted average 2 int_0^1 albedo(mu) mu dmu, each with an error bound.
//
// How. Every model is integrated in the variables that make its lobe smooth:
// - Lambert, Oren-Nayar, EON: over theta_i, the azimuth in closed form
//   (models/oren_nayar.h, eon.h); split at theta_i = theta_o (their kink).
// - Phong: over cones about the mirror direction, u = cos(angle to it), the
//   azimuth about it in closed form (models/phong.h); Blinn-Phong over the
//   half vector's u = cos(theta_h), its azimuth in closed form
//   (models/blinn_phong.h). The weight u^n peaks at u = 1 with width ~1 / n;
//   above u = max(1/2, 1e-16^(1/(n+1))) the variable is t = u^(n+1)
//   (u^n du = dt / (n + 1): the peak is absorbed), with breaks at t =
//   1e-12, 1e-8, 1e-4, 1e-2; below it u itself. Pieces also break where the
//   horizon starts to clip the cone (Phong: u = s_o) or ring (Blinn-Phong:
//   u_none, u_full).
// - Microfacet: f = D G F / (4 mu_o mu_i) over the half vector, as the
//   reference integrator does (reference_integrator.h): azimuth phi in
//   [0, pi] (split at pi/2) outside, the NDF's own CDF inside (GGX: xi =
//   sin^2(psi), tan(theta_h) = alpha tan(psi); Beckmann: tan(theta_h) =
//   alpha t), stopped exactly at the horizon. Exact Smith with F = 1 or
//   Schlick F takes the library's panel quadrature instead (albedo = E, or
//   F0 A + B), whose bound is already proven (albedo_quadrature.h).
// Each 1D integral is globally adaptive Gauss-Kronrod (7/15); a nested one
// carries the inner integral's error estimate as a second channel of the
// outer one. The stated error is 16 x (sum of |K15 - G7| + the integrated
// inner estimates) + 1e-13: the factor is the one the reference integrator
// uses (its plain estimate was measured up to 11.4x too small in G2's
// boundary layer), the floor covers rounding. Everything is a fixed
// sequence of double operations: the same inputs give the same bits on any
// thread.
//
// Kulla-Conty compensation (microfacet, `compensation`): the lobe
//   f_ms(o, i) = F_ms (1 - E(mu_o)) (1 - E(mu_i)) / (pi (1 - E_avg)),
//   F_ms = F_avg^2 E_avg / (1 - F_avg (1 - E_avg))   (Kulla and Conty 2017),
// light scattered k >= 2 times meets the Fresnel k times and leaves with
// probability E_avg per bounce: sum_k F_avg^k E_avg (1 - E_avg)^(k-1) over
// k >= 2 is (1 - E_avg) F_avg^2 E_avg / (1 - F_avg (1 - E_avg)), against
// (1 - E_avg) at F = 1. `msFresnelSquared` false gives F_avg E_avg / (1 -
// F_avg (1 - E_avg)) instead, one factor F_avg fewer (as issue 17 wrote
// it); both are 1 at F = 1.
// is added, E and E_avg the F = 1 albedo of the same NDF and G (exact: the
// library's panel quadrature of E and of E_avg; Schlick-GGX: this
// integrator), F_avg that of the Fresnel model. Its albedo is
//   F_ms (1 - E(mu_o)) I / (1 - E_avg),  I = 2 int_0^1 (1 - E(mu)) mu dmu,
// I computed here by adaptive Gauss-Kronrod over mu with E at every node:
// for exact Smith an independent check that the library's E_avg is the
// average of its E (I = 1 - E_avg); for Schlick-GGX, E_avg is taken as 1 - I.
// At F = 1 the compensated albedo is 1 within the stated error.
#pragma once

#include <string_view>

#include "lutbake/models/blinn_phong.h"
#include "lutbake/models/eon.h"
#include "lutbake/models/ndf.h"
#include "lutbake/models/oren_nayar.h"
#include "lutbake/models/phong.h"

namespace lutbake {

enum class FurnaceModelKind { kLambert, kPhong, kBlinnPhong, kOrenNayar, kEon, kMicrofacet };
// The microfacet G: exact Smith (correlated, separable) or Schlick-GGX
// (schlick_ggx.h) with k = alpha / 2 (ibl) or (r + 1)^2 / 8 (direct).
enum class FurnaceVisibility { kCorrelated, kSeparable, kSchlickGgxIbl, kSchlickGgxDirect };
// F = 1; Schlick with f0 (F90 = 1); exact Fresnel of relative index eta + i k.
enum class FurnaceFresnel { kOne, kSchlick, kExact };

std::string_view ToString(FurnaceModelKind kind);
std::string_view ToString(FurnaceVisibility visibility);
std::string_view ToString(FurnaceFresnel fresnel);

struct FurnaceModel {
  FurnaceModelKind kind = FurnaceModelKind::kLambert;
  PhongNormalisation phong = PhongNormalisation::kNPlus2;
  BlinnPhongNormalisation blinnPhong = BlinnPhongNormalisation::kExact;
  OrenNayarVariant orenNayar = OrenNayarVariant::kFull;
  EonVariant eon = EonVariant::kExact;
  NdfKind ndf = NdfKind::kGgx;
  FurnaceVisibility visibility = FurnaceVisibility::kCorrelated;
  FurnaceFresnel fresnel = FurnaceFresnel::kOne;
  double f0 = 0.04, eta = 1.5, k = 0.0;
  bool compensation = false;
  bool msFresnelSquared = true;  // F_ms with F_avg^2 (Kulla-Conty) or F_avg
};

// The model's parameter: Lambert none (ignored), Phong and Blinn-Phong the
// exponent n >= 0, Oren-Nayar sigma in [0, pi/2] radians, EON r in [0, 1],
// microfacet the perceptual roughness r in [0, 1] (alpha = r^2; r = 0 is the
// mirror, in closed form).
struct FurnaceValue {
  double value = 0, error = 0;
};

struct FurnacePoint {
  FurnaceValue albedo;
  // Compensated microfacet models: the albedo without the f_ms lobe (else
  // equal to albedo).
  FurnaceValue singleScattering;
};

// One model at one parameter value. The constructor does the work shared by
// every mu (the compensation's E_avg, F_avg and I); Albedo and Average are
// const and may be called from several threads.
class FurnaceIntegrator {
 public:
  FurnaceIntegrator(const FurnaceModel &model, double parameter, double tolerance = 1e-9);

  // mu_o in [0, 1] (0 = the grazing limit).
  FurnacePoint Albedo(double mu_o) const;
  // 2 int_0^1 albedo(mu) mu dmu.
  FurnaceValue Average() const;

  // The compensation's constants (0 without compensation).
  double EnergyAverage() const { return eAvg_; }
  double FresnelAverage() const { return fAvg_; }

 private:
  FurnaceValue SingleScattering(double mu_o) const;
  FurnaceValue WhiteMicrofacetAlbedo(double mu_o) const;  // E: F = 1, same D and G

  FurnaceModel model_;
  double parameter_, tolerance_;
  double eAvg_ = 0, eAvgError_ = 0, fAvg_ = 0, fAvgError_ = 0;
  double I_ = 0, IError_ = 0;  // 2 int (1 - E) mu dmu
};

}  // namespace lutbake
