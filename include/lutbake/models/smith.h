// Smith masking-shadowing G2 and the ratios the estimators need, all written
// with L = mu Lambda(mu) (Ndf::MuLambda) so that they stay finite at mu_o = 0.
//
//   correlated: G2 = 1 / (1 + Lambda(o) + Lambda(i))
//             = mu_o mu_i / (mu_o mu_i + mu_i L_o + mu_o L_i)
//   separable:  G2 = G1(o) G1(i),  G1(mu) = mu / (mu + L)
#pragma once

#include <string_view>

namespace lutbake {

enum class SmithForm { kCorrelated, kSeparable };
// Every form, in the order the command line offers them.
inline constexpr SmithForm kAllSmithForms[] = {SmithForm::kCorrelated, SmithForm::kSeparable};

std::string_view ToString(SmithForm form);

// All functions return 0 when the light is at or below the horizon (mu_i <= 0).
// L_o, L_i: mu Lambda(mu) at mu_o and mu_i.

// G2 itself.
double SmithG2(SmithForm form, double mu_o, double mu_i, double L_o, double L_i);

// G2 / G1(o): the whole weight of the E estimator under visible-normal sampling.
//   correlated: mu_i (mu_o + L_o) / (mu_o mu_i + mu_i L_o + mu_o L_i)
//   separable:  mu_i / (mu_i + L_i)
double SmithG2OverG1o(SmithForm form, double mu_o, double mu_i, double L_o, double L_i);

// G2 / mu_o, finite at mu_o = 0 (where Lambda(o) grows like 1 / mu_o):
//   correlated: mu_i / (mu_o mu_i + mu_i L_o + mu_o L_i)
//   separable:  mu_i / ((mu_o + L_o) (mu_i + L_i))
double SmithG2OverMuO(SmithForm form, double mu_o, double mu_i, double L_o, double L_i);

}  // namespace lutbake
