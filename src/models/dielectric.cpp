#include "lutbake/models/dielectric.h"

#include <cmath>

namespace lutbake {

std::string_view ToString(DielectricLobes lobes) {
  return lobes == DielectricLobes::kReflection ? "reflection" : "reflection+transmission";
}

DielectricFresnelTerms DielectricFresnel(double eta, double c) {
  c = Clamp(c, 0.0, 1.0);
  // eta^2 - 1 as (eta - 1)(eta + 1): exact near eta = 1.
  const double e2m1 = (eta - 1.0) * (eta + 1.0);
  const double W2 = e2m1 + c * c;
  if (!(W2 > 0.0)) return {1.0, 0.0, 0.0};  // total internal reflection (or c = 0, eta = 1)
  const double W = std::sqrt(W2);
  const double eta2 = eta * eta;
  const double sDen = c + W, pDen = eta2 * c + W;
  const double rs = -e2m1 / (sDen * sDen);
  const double rp = e2m1 * ((eta2 + 1.0) * c * c - 1.0) / (pDen * pDen);
  const double ts = 4.0 * c * W / (sDen * sDen);
  const double tp = 4.0 * eta2 * c * W / (pDen * pDen);
  DielectricFresnelTerms out;
  out.F = Clamp(0.5 * (rs * rs + rp * rp), 0.0, 1.0);
  out.T = Clamp(0.5 * (ts + tp), 0.0, 1.0);
  out.W = W;
  return out;
}

bool Refract(const Vec3 &o, const Vec3 &h, double eta, Vec3 *i) {
  const double c = Dot(o, h);
  const double W2 = (eta - 1.0) * (eta + 1.0) + c * c;
  if (!(W2 > 0.0)) return false;
  const double W = std::sqrt(W2);
  // c - W = (1 - eta^2) / (c + W): exactly 0 at eta = 1.
  const double cmw = c + W > 0.0 ? -(eta - 1.0) * (eta + 1.0) / (c + W) : 0.0;
  *i = {(cmw * h.x - o.x) / eta, (cmw * h.y - o.y) / eta, (cmw * h.z - o.z) / eta};
  return true;
}

Vec3 RefractionHalfVector(const Vec3 &o, const Vec3 &i, double eta) {
  Vec3 h = {o.x + eta * i.x, o.y + eta * i.y, o.z + eta * i.z};
  const double len2 = Dot(h, h);
  // o + eta i = 0 only for eta = 1 and i = -o, where every facet refracts
  // o into i; return the normal rather than NaN.
  if (!(len2 > 0.0)) return {0.0, 0.0, 1.0};
  const double inv = (h.z < 0.0 ? -1.0 : 1.0) / std::sqrt(len2);
  return {h.x * inv, h.y * inv, h.z * inv};
}

double ReflectionJacobian(double c) { return 1.0 / (4.0 * std::abs(c)); }

double RefractionJacobian(double eta, double oh, double ih) {
  const double den = oh + eta * ih;
  return eta * eta * std::abs(ih) / (den * den);
}

double DielectricFacetWeight(const Ndf &ndf, SmithForm smith, DielectricLobes lobes, double eta,
                             double mu_o, double L_o, double c, double cosTheta_h, double mu_r) {
  if (!(c > 0.0)) return 0.0;
  const DielectricFresnelTerms f = DielectricFresnel(eta, c);
  double w = 0.0;
  if (mu_r > 0.0 && f.F > 0.0) {
    const double m = std::min(mu_r, 1.0);
    w += f.F * SmithG2OverG1o(smith, mu_o, m, L_o, ndf.MuLambda(m));
  }
  if (lobes == DielectricLobes::kReflectionAndTransmission && f.T > 0.0) {
    const double cmw = -(eta - 1.0) * (eta + 1.0) / (c + f.W);
    const double mu_t = (cmw * cosTheta_h - mu_o) / eta;
    if (mu_t < 0.0) {
      const double m = std::min(-mu_t, 1.0);
      w += f.T * SmithG2OverG1o(smith, mu_o, m, L_o, ndf.MuLambda(m));
    }
  }
  return std::min(w, 1.0);
}

double DielectricBsdfCosine(const Ndf &ndf, SmithForm smith, DielectricLobes lobes, double eta,
                            const Vec3 &o, const Vec3 &i) {
  const double mu_o = o.z, mu_i = i.z;
  if (!(mu_o > 0.0) || mu_i == 0.0) return 0.0;
  const double L_o = ndf.MuLambda(mu_o);
  if (mu_i > 0.0) {
    // f_r mu_i = F D G2 / (4 mu_o), h = (o + i) / |o + i|.
    const Vec3 h = Normalize({o.x + i.x, o.y + i.y, o.z + i.z});
    const double c = Dot(o, h);
    if (!(c > 0.0)) return 0.0;
    const double F = DielectricFresnel(eta, c).F;
    return F * ndf.D(h) * SmithG2OverMuO(smith, mu_o, mu_i, L_o, ndf.MuLambda(mu_i)) / 4.0;
  }
  if (lobes == DielectricLobes::kReflection) return 0.0;
  const Vec3 h = RefractionHalfVector(o, i, eta);
  const double oh = Dot(o, h), ih = Dot(i, h);
  if (!(oh > 0.0) || !(ih < 0.0) || !(h.z > 0.0)) return 0.0;
  const double T = DielectricFresnel(eta, oh).T;
  const double m = -mu_i;
  // f_t |mu_i| = (o.h) (1 - F) D (G2 / mu_o) J_t, J_t = eta^2 |i.h| / (o.h + eta i.h)^2.
  return oh * T * ndf.D(h) * SmithG2OverMuO(smith, mu_o, m, L_o, ndf.MuLambda(m)) *
         RefractionJacobian(eta, oh, ih);
}

double DielectricSmoothAlbedo(DielectricLobes lobes, double eta, double mu_o) {
  return lobes == DielectricLobes::kReflection ? DielectricFresnel(eta, mu_o).F : 1.0;
}

double DielectricIndexMatchedAlbedo(const Ndf &ndf, SmithForm smith, DielectricLobes lobes,
                                    double mu_o) {
  if (lobes == DielectricLobes::kReflection) return 0.0;
  // G2(o, -o) / G1(o): correlated mu (mu + L) / (mu^2 + 2 mu L) = (mu + L) / (mu + 2 L)
  // (= (1 + Lambda) / (1 + 2 Lambda)); separable G1 = mu / (mu + L). Finite at mu = 0.
  const double L = ndf.MuLambda(mu_o);
  if (smith == SmithForm::kCorrelated)
    return mu_o + 2.0 * L > 0.0 ? (mu_o + L) / (mu_o + 2.0 * L) : 1.0;
  return mu_o + L > 0.0 ? mu_o / (mu_o + L) : 1.0;
}

DielectricSample SampleDielectric(const Ndf &ndf, SmithForm smith, DielectricLobes lobes,
                                  double eta, const Vec3 &o, double u0, double u1, double u2) {
  DielectricSample s;
  const Vec3 h = ndf.SampleVisibleNormal(o, u0, u1);
  const double c = Dot(o, h);
  if (!(c > 0.0)) return s;
  const double L_o = ndf.MuLambda(o.z);
  const DielectricFresnelTerms f = DielectricFresnel(eta, c);
  if (u2 < f.F) {
    s.i = Reflect(o, h);
    s.reflected = true;
    if (s.i.z > 0.0)
      s.weight =
          SmithG2OverG1o(smith, o.z, std::min(s.i.z, 1.0), L_o, ndf.MuLambda(std::min(s.i.z, 1.0)));
    return s;
  }
  s.reflected = false;
  if (!Refract(o, h, eta, &s.i)) return s;
  if (lobes == DielectricLobes::kReflection || !(s.i.z < 0.0)) return s;
  const double m = std::min(-s.i.z, 1.0);
  s.weight = SmithG2OverG1o(smith, o.z, m, L_o, ndf.MuLambda(m));
  return s;
}

}  // namespace lutbake
