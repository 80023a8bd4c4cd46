#include "plan_command.h"

#include <filesystem>
#include <iostream>

#include "cli_util.h"
#include "lutbake/plans/manifest.h"
#include "lutbake/plans/scene.h"

namespace lutbake::cli {

void AddSceneOptions(CLI::App &app, SceneOptions &o) {
  app.add_option("--scene", o.scenes,
                 "glTF 2.0 scenes (.gltf or .glb; materials only, buffers and images are not "
                 "read). Several: the plan is their union")
      ->type_name("FILE...")
      ->expected(1, -1);
  app.add_option("--manifest", o.manifests,
                 "JSON manifests listing materials and lighting (README, 'Bake plans')")
      ->type_name("FILE...")
      ->expected(1, -1);
  app.add_flag("--no-ibl", o.noIbl, "No image-based lighting: leave out dfg (and f82)");
  app.add_flag("--no-compensation", o.noCompensation,
               "No energy compensation: leave out E, Eavg and Favg (Kulla-Conty), glass_E and "
               "glass_Eavg (rough transmission), spec_E and spec_Eavg (layering under a coat)");
}

int MakePlanOrComplain(const std::string &command, const SceneOptions &o, PlanOptions planOptions,
                       BakePlan *plan) {
  // A file that is not there is a usage error (2); one that cannot be used
  // is a runtime failure (1).
  for (const auto *list : {&o.scenes, &o.manifests})
    for (const std::string &path : *list) {
      std::error_code ec;
      if (!std::filesystem::exists(path, ec)) {
        std::cerr << "lutbake " << command << ": "
                  << (list == &o.scenes ? "--scene " : "--manifest ") << path
                  << ": no such file; accepted: a readable "
                  << (list == &o.scenes ? ".gltf or .glb file" : "JSON manifest") << "\n";
        return 2;
      }
    }
  try {
    std::vector<MaterialSpec> materials;
    for (const std::string &path : o.manifests) {
      const Manifest m = ReadManifest(path);
      const auto merge = [&](std::optional<bool> *into, const std::optional<bool> &value,
                             const char *key) {
        if (!value) return;
        if (into->has_value() && **into != *value)
          throw InputError(path + ": /lighting/" + key + " is " + (*value ? "true" : "false") +
                           ", another manifest says " + (**into ? "true" : "false"));
        *into = value;
      };
      merge(&planOptions.defaultIbl, m.ibl, "ibl");
      merge(&planOptions.defaultCompensation, m.compensation, "compensation");
      materials.insert(materials.end(), m.materials.begin(), m.materials.end());
    }
    for (const std::string &path : o.scenes) {
      const std::vector<MaterialSpec> scene = ReadSceneMaterials(path);
      materials.insert(materials.end(), scene.begin(), scene.end());
    }
    planOptions.ibl = !o.noIbl;
    planOptions.compensation = !o.noCompensation;
    *plan = MakePlan(materials, planOptions);
  } catch (const InputError &e) {
    std::cerr << "lutbake " << command << ": " << e.what() << "\n";
    return 1;
  }
  return 0;
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
  if (!o.scene.used()) {
    std::cerr << "lutbake plan: give at least one --scene FILE or --manifest FILE\n";
    return 2;
  }
  PlanOptions planOptions;
  if (o.size > 0) planOptions.size = o.size;
  BakePlan plan;
  if (const int status = MakePlanOrComplain("plan", o.scene, planOptions, &plan)) return status;
  std::cout << (o.json ? PlanJson(plan) + "\n" : DescribePlan(plan));
  return 0;
}

}  // namespace lutbake::cli
