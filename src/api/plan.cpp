#include "lutbake/api/plan.h"

#include <filesystem>
#include <optional>

#include "lutbake/core/error.h"
#include "lutbake/plans/manifest.h"
#include "lutbake/plans/scene.h"

namespace lutbake {

BakePlan Plan(const PlanRequest &request) {
  if (request.scenes.empty() && request.manifests.empty())
    throw UsageError("give at least one --scene FILE or --manifest FILE");
  // A file that is not there is a usage error; one that cannot be used is a
  // runtime failure (InputError).
  for (const auto *list : {&request.scenes, &request.manifests})
    for (const std::string &path : *list) {
      std::error_code ec;
      if (!std::filesystem::exists(path, ec))
        throw UsageError((list == &request.scenes ? "--scene " : "--manifest ") + path +
                         ": no such file; accepted: a readable " +
                         (list == &request.scenes ? ".gltf or .glb file" : "JSON manifest"));
    }
  PlanOptions options;
  if (request.size > 0) options.size = request.size;
  std::vector<MaterialSpec> materials;
  for (const std::string &path : request.manifests) {
    const Manifest m = ReadManifest(path);
    const auto merge = [&](std::optional<bool> *into, const std::optional<bool> &value,
                           const char *key) {
      if (!value) return;
      if (into->has_value() && **into != *value)
        throw InputError(path + ": /lighting/" + key + " is " + (*value ? "true" : "false") +
                         ", another manifest says " + (**into ? "true" : "false"));
      *into = value;
    };
    merge(&options.defaultIbl, m.ibl, "ibl");
    merge(&options.defaultCompensation, m.compensation, "compensation");
    merge(&options.areaLights, m.areaLights, "areaLights");
    materials.insert(materials.end(), m.materials.begin(), m.materials.end());
  }
  for (const std::string &path : request.scenes) {
    const std::vector<MaterialSpec> scene = ReadSceneMaterials(path);
    materials.insert(materials.end(), scene.begin(), scene.end());
  }
  options.ibl = !request.noIbl;
  options.compensation = !request.noCompensation;
  BakePlan plan = MakePlan(materials, options);
  if (request.estimate) {
    std::vector<EstimatedTable> tables;
    for (const PlannedTable &t : plan.tables)
      tables.push_back({t.definition, PlannedSettings(t, BakeSettings{}), t.x, t.y, t.z});
    plan.estimate = EstimateBake(tables);
  }
  return plan;
}

}  // namespace lutbake
