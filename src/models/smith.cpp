#include "lutbake/models/smith.h"

namespace lutbake {

std::string_view ToString(SmithForm form) {
  return form == SmithForm::kCorrelated ? "correlated" : "separable";
}

// Each denominator below vanishes only for a mirror (L = 0) viewed exactly at
// grazing, which the tables evaluate by their closed forms instead; the guard
// returns 0 rather than NaN should it ever be reached.

double SmithG2(SmithForm form, double mu_o, double mu_i, double L_o, double L_i) {
  if (mu_i <= 0.0 || mu_o <= 0.0) return 0.0;
  if (form == SmithForm::kCorrelated) {
    const double denom = mu_o * mu_i + mu_i * L_o + mu_o * L_i;
    return denom > 0.0 ? mu_o * mu_i / denom : 0.0;
  }
  return (mu_o / (mu_o + L_o)) * (mu_i / (mu_i + L_i));
}

double SmithG2OverG1o(SmithForm form, double mu_o, double mu_i, double L_o, double L_i) {
  if (mu_i <= 0.0) return 0.0;
  if (form == SmithForm::kCorrelated) {
    const double denom = mu_o * mu_i + mu_i * L_o + mu_o * L_i;
    return denom > 0.0 ? mu_i * (mu_o + L_o) / denom : 0.0;
  }
  const double denom = mu_i + L_i;
  return denom > 0.0 ? mu_i / denom : 0.0;
}

double SmithG2OverMuO(SmithForm form, double mu_o, double mu_i, double L_o, double L_i) {
  if (mu_i <= 0.0) return 0.0;
  if (form == SmithForm::kCorrelated) {
    const double denom = mu_o * mu_i + mu_i * L_o + mu_o * L_i;
    return denom > 0.0 ? mu_i / denom : 0.0;
  }
  const double denom = (mu_o + L_o) * (mu_i + L_i);
  return denom > 0.0 ? mu_i / denom : 0.0;
}

}  // namespace lutbake
