// The model a table is integrated under, as a part the table holds
// (TableDefinition::ModelPart(): a TableModel) instead of methods each family of tables
// inherits and copies: which options choose it, the metadata that records
// it, its words, reading it back from a file, and when two settings give the
// same model. Tables of one family hold one part: E, Eavg, dfg, f82 and
// ltc_ggx the microfacet part; glass_* and spec_* a dielectric part, which
// is the microfacet part with the Fresnel and lobes added; the sheen tables
// the sheen part; Favg the Fresnel part; the diffuse tables a diffuse part
// named by their model. The parts live in src/tables/model_parts.h.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "lutbake/tables/settings.h"
#include "lutbake/tables/table.h"

namespace lutbake {

using Metadata = std::vector<std::pair<std::string, std::string>>;

class TableModel {
 public:
  virtual ~TableModel() = default;
  // The options that choose the model: "ndf", "smith", "sheen-visibility",
  // ... (eval and bake refuse the others for this table).
  virtual std::vector<std::string> Options() const = 0;
  // The metadata that records it, before the axes (ndf, smith, fresnel,
  // ...), and the value of the key 'alpha' after them.
  virtual Metadata Records(const BakeSettings &settings) const = 0;
  virtual std::string Alpha(const BakeSettings &settings) const = 0;
  // In words: "ggx correlated", "fresnel schlick".
  virtual std::string Describe(const BakeSettings &settings) const = 0;
  // Reads the model from a file's metadata into `settings`, adding to
  // `problems` what is not a model lutbake writes (the table checks its
  // own axes).
  virtual void Read(const Table &table, BakeSettings *settings,
                    std::vector<std::string> *problems) const = 0;
  // Do two settings give the same model?
  virtual bool Same(const BakeSettings &a, const BakeSettings &b) const = 0;
};

}  // namespace lutbake
