#include "plan_command.h"

#include <iostream>

#include "cli_util.h"
#include "lutbake/api/plan.h"

namespace lutbake::cli {

void AddSceneOptions(CLI::App &app, SceneOptions &o) {
  app.add_option("--scene", o.scenes,
                 "glTF 2.0 scenes (.gltf or .glb; materials only, buffers and images are not "
                 "read). Several: the plan is their union")
      ->type_name("FILE...")
      ->expected(1, -1);
  app.add_option("--manifest", o.manifests,
                 "JSON manifests listing materials and lighting (docs/plans.md)")
      ->type_name("FILE...")
      ->expected(1, -1);
  app.add_flag("--no-ibl", o.noIbl, "No image-based lighting: leave out dfg (and f82)");
  app.add_flag("--no-compensation", o.noCompensation,
               "No energy compensation: leave out E, Eavg and Favg (Kulla-Conty), glass_E and "
               "glass_Eavg (rough transmission), spec_E and spec_Eavg (layering under a coat)");
}

void SetupPlanCommand(CLI::App &app, PlanCommandOptions &o) {
  AddSceneOptions(app, o.scene);
  app.add_option("--size", o.size,
                 "Texels per axis of the full tables, as lutbake bake --size (default: 32 for E, "
                 "Eavg, Favg; 128 for dfg)")
      ->type_name("N")
      ->check(InRange(1, 4096, "texels per axis"));
  app.add_flag("--json", o.json, "Print the plan as one JSON object");
  app.footer(
      "Example:\n  lutbake plan --scene car.gltf --manifest lighting.json\n"
      "  lutbake plan --scene a.glb b.gltf --no-ibl --json");
}

int RunPlan(const PlanCommandOptions &o) {
  PlanRequest request;
  request.scenes = o.scene.scenes;
  request.manifests = o.scene.manifests;
  request.noIbl = o.scene.noIbl;
  request.noCompensation = o.scene.noCompensation;
  request.size = o.size;
  request.estimate = true;
  return RunLibraryCall("plan", "", [&] {
    const BakePlan plan = Plan(request);
    std::cout << (o.json ? PlanJson(plan) + "\n" : DescribePlan(plan));
  });
}

}  // namespace lutbake::cli
