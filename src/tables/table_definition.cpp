#include "lutbake/tables/table_definition.h"

#include <algorithm>
#include <cstring>

#include "lutbake/core/hash.h"

namespace lutbake {

std::vector<std::string> TableDefinition::CoordinateOptions() const {
  std::vector<std::string> options;
  for (const PointCoordinate &c : Coordinates(BakeSettings{})) options.push_back(c.option);
  return options;
}

std::array<double, 4> TableDefinition::FitDomain(const BakeSettings &settings) const {
  std::array<double, 4> domain = {0.0, 1.0, 0.0, 1.0};
  const std::vector<PointCoordinate> coordinates = Coordinates(settings);
  for (size_t i = 0; i < coordinates.size() && i < 2; ++i) {
    domain[2 * i] = coordinates[i].zeroAllowed ? 0.0 : coordinates[i].min;
    domain[2 * i + 1] = coordinates[i].max;
  }
  return domain;
}

uint64_t TableDefinition::SamplesPerTexel(const BakeSettings &s) const {
  return !Sampled() || IsQuadrature(s.estimator) ? 0 : s.samples;
}

std::string TableDefinition::QuadratureDescription(const BakeSettings &s) const {
  return s.estimator == Estimator::kAdaptiveQuadrature
             ? "adaptive Gauss-Kronrod quadrature"
             : "panel Gauss-Legendre quadrature over the half vector, two orders";
}

std::string TableDefinition::QuadratureBound(const BakeSettings &s) const {
  if (s.estimator == Estimator::kAdaptiveQuadrature)
    return FormatDouble(kQuadratureErrorFactor) + " x the Gauss-Kronrod estimate + 1e-10";
  return "quadrature texels: |V_k - V_(k-1)| + 1e-10 of the panel rule at two orders";
}

TableDefinition::CheckReference TableDefinition::ReferenceForCheck(double statedErrorMax,
                                                                   double optionTolerance) const {
  // Far below what the table claims (1/64 of its errorMax), but not below
  // the option (float32 storage rounds at 6e-8 anyway) nor above 1e-6.
  CheckReference r;
  r.estimator = ReferenceEstimator();
  r.tolerance = std::clamp(statedErrorMax / 64.0, optionTolerance, 1e-6);
  return r;
}

std::string RequiredMetadata(const Table &table, const std::string &key,
                             std::vector<std::string> *problems) {
  const std::string *v = table.FindMetadata(key);
  if (!v) problems->push_back("key '" + key + "' missing");
  return v ? *v : std::string();
}

uint64_t PointSeed(uint64_t tableSeedId, double x, double y, uint64_t seed) {
  uint64_t xBits, yBits;
  std::memcpy(&xBits, &x, sizeof x);
  std::memcpy(&yBits, &y, sizeof y);
  return HashValues({tableSeedId, xBits, yBits, seed});
}

const TableDefinition *FindRole(const std::vector<Table> &set, PlanRole role) {
  for (const Table &t : set)
    if (t.definition && t.definition->Role() == role) return t.definition;
  return nullptr;
}

}  // namespace lutbake
