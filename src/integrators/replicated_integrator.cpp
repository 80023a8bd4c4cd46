#include "lutbake/integrators/replicated_integrator.h"

namespace lutbake {

double StudentT99(int dof) {
  // Two-sided 99% (one-sided 0.995) quantiles for 1 to 30 degrees of freedom.
  static constexpr double kTable[30] = {63.657, 9.925, 5.841, 4.604, 4.032, 3.707, 3.499, 3.355,
                                        3.250,  3.169, 3.106, 3.055, 3.012, 2.977, 2.947, 2.921,
                                        2.898,  2.878, 2.861, 2.845, 2.831, 2.819, 2.807, 2.797,
                                        2.787,  2.779, 2.771, 2.763, 2.756, 2.750};
  if (dof < 1) return 0.0;
  if (dof <= 30) return kTable[dof - 1];
  // Beyond the table, the Cornish-Fisher expansion around the normal
  // quantile z = 2.5758 (accurate to 1e-3 at 31 degrees of freedom).
  const double z = 2.5758293035489004, nu = dof;
  const double z3 = z * z * z, z5 = z3 * z * z;
  return z + (z3 + z) / (4.0 * nu) + (5.0 * z5 + 16.0 * z3 + 3.0 * z) / (96.0 * nu * nu);
}

}  // namespace lutbake
