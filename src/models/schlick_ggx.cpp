#include "lutbake/models/schlick_ggx.h"

namespace lutbake {

std::string_view ToString(SchlickGgxK kind) {
  return kind == SchlickGgxK::kIbl ? "schlick-ggx-ibl" : "schlick-ggx-direct";
}

double SchlickGgxKFromRoughness(SchlickGgxK kind, double perceptualRoughness) {
  const double r = perceptualRoughness;
  return kind == SchlickGgxK::kIbl ? 0.5 * r * r : (r + 1.0) * (r + 1.0) / 8.0;
}

}  // namespace lutbake
