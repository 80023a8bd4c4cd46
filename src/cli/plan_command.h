// `lutbake plan --scene FILE... [--manifest FILE...]`: what a scene needs
// (plan.h), in words or as JSON; and the scene options that `lutbake bake`
// shares with it.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "lutbake/plans/plan.h"

namespace lutbake::cli {

struct SceneOptions {
  std::vector<std::string> scenes;
  std::vector<std::string> manifests;
  bool noIbl = false;
  bool noCompensation = false;
};

// --scene, --manifest, --no-ibl, --no-compensation.
void AddSceneOptions(CLI::App &app, SceneOptions &options);

struct PlanCommandOptions {
  SceneOptions scene;
  int size = 0;  // 0: the per-table defaults
  bool json = false;
};

void SetupPlanCommand(CLI::App &app, PlanCommandOptions &options);
int RunPlan(const PlanCommandOptions &options);

}  // namespace lutbake::cli
