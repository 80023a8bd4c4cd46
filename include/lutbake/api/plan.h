// lutbake::Plan: what glTF scenes and manifests need (plan.h), as
// `lutbake plan` prints it and `lutbake bake --scene` bakes it.
#pragma once

#include <string>
#include <vector>

#include "lutbake/plans/plan.h"

namespace lutbake {

struct PlanRequest {
  std::vector<std::string> scenes;     // .gltf or .glb
  std::vector<std::string> manifests;  // JSON manifests
  bool noIbl = false;                  // leave out dfg (and f82)
  bool noCompensation = false;         // leave out the energy-compensation tables
  int size = 0;                        // texels per axis of the full tables; 0: defaults
  bool estimate = false;               // time a sample of texels: BakePlan::estimate
};

// Reads every scene and manifest and makes the plan. Throws UsageError when
// none is given or a file does not exist, InputError (a lutbake::Error)
// naming the file and the JSON pointer when one cannot be used.
BakePlan Plan(const PlanRequest &request);

}  // namespace lutbake
