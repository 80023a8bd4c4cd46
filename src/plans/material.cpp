#include "lutbake/plans/material.h"

#include "lutbake/tables/bake.h"

namespace lutbake {

double SnapToMirror(double perceptualRoughness, MaterialSpec &material, const std::string &what) {
  if (perceptualRoughness > 0.0 && perceptualRoughness * perceptualRoughness < kMinimumAlpha) {
    material.notes.push_back(what + " " + FormatDouble(perceptualRoughness) +
                             " is below 1e-12: baked as the mirror, r = 0");
    return 0.0;
  }
  return perceptualRoughness;
}

}  // namespace lutbake
