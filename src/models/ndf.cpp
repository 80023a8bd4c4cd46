#include "lutbake/models/ndf.h"

#include "lutbake/models/beckmann.h"
#include "lutbake/models/ggx.h"

namespace lutbake {

std::string_view ToString(NdfKind kind) { return kind == NdfKind::kGgx ? "ggx" : "beckmann"; }

double Ndf::D(const Vec3 &h) const {
  return kind == NdfKind::kGgx ? ggx::D(alpha, h) : beckmann::D(alpha, h);
}

double Ndf::MuLambda(double mu) const {
  return kind == NdfKind::kGgx ? ggx::MuLambda(alpha, mu) : beckmann::MuLambda(alpha, mu);
}

Vec3 Ndf::SampleVisibleNormal(const Vec3 &o, double u1, double u2) const {
  return kind == NdfKind::kGgx ? ggx::SampleVisibleNormal(alpha, o, u1, u2)
                               : beckmann::SampleVisibleNormal(alpha, o, u1, u2);
}

double Ndf::VisibleNormalPdf(const Vec3 &o, const Vec3 &h) const {
  const double oh = Dot(o, h);
  if (oh <= 0.0) return 0.0;
  return oh * D(h) / (o.z + MuLambda(o.z));
}

void Ndf::NormalFromCdf(double xi, double *cosTheta_h, double *sinTheta_h) const {
  if (kind == NdfKind::kGgx)
    ggx::NormalFromCdf(alpha, xi, cosTheta_h, sinTheta_h);
  else
    beckmann::NormalFromCdf(alpha, xi, cosTheta_h, sinTheta_h);
}

double Ndf::CdfFromTheta(double theta_h) const {
  return kind == NdfKind::kGgx ? ggx::CdfFromTheta(alpha, theta_h)
                               : beckmann::CdfFromTheta(alpha, theta_h);
}

Vec3 Ndf::SampleNormal(double u1, double u2) const {
  double cosTheta = 1.0, sinTheta = 0.0;
  NormalFromCdf(u1, &cosTheta, &sinTheta);
  const double phi = 2.0 * kPi * u2;
  return {sinTheta * std::cos(phi), sinTheta * std::sin(phi), cosTheta};
}

}  // namespace lutbake
