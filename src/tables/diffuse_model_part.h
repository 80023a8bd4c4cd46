// The model part of a diffuse table (burley_model.h, oren_nayar_model.h):
// one named model with reflectance 1 and no options, recorded as metadata
// model and reflectance, with its roughness parameter described in 'alpha'.
// Private to the tables layer.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "lutbake/tables/table_definition.h"

namespace lutbake {

class DiffuseModel final : public TableModel {
 public:
  DiffuseModel(std::string name, std::string alpha)
      : name_(std::move(name)), alpha_(std::move(alpha)) {}
  const std::string &Name() const { return name_; }
  std::vector<std::string> Options() const override { return {}; }
  Metadata Records(const BakeSettings &) const override {
    return {{"model", name_}, {"reflectance", "1"}};
  }
  std::string Alpha(const BakeSettings &) const override { return alpha_; }
  std::string Describe(const BakeSettings &) const override { return name_; }
  void Read(const Table &table, BakeSettings *, std::vector<std::string> *problems) const override {
    const std::string model = RequiredMetadata(table, "model", problems);
    if (!model.empty() && model != name_)
      problems->push_back("model '" + model + "', expected '" + name_ + "'");
  }
  bool Same(const BakeSettings &, const BakeSettings &) const override { return true; }

 private:
  std::string name_, alpha_;
};

}  // namespace lutbake
