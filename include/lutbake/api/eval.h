// lutbake::Evaluate: any table at any points (not only texel centres), with
// the error bound of each value, as `lutbake eval` prints them.
//
//   lutbake::EvalRequest request;
//   request.table = "E";
//   request.coordinates = {{"mu", {1e-7, 0.5}}, {"roughness", {0.3}}};
//   for (const lutbake::EvalPoint &p : lutbake::Evaluate(request).points)
//     std::cout << p.values[0] << " +- " << p.errors[0] << "\n";
//
// The points are every combination of the coordinates' values, row-major
// as a table stores them (the first coordinate inner). Throws UsageError
// (its message names the option as the command line spells it) for a
// model option or coordinate the table does not take, a value outside the
// table's range, a required coordinate left out, more than a million
// points, an estimator the table has not, or a point the table cannot
// evaluate.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "lutbake/api/sampling.h"
#include "lutbake/tables/table_definition.h"

namespace lutbake {

// More points than this in one request is a typo, not a request (each
// costs about a millisecond with the default quadrature).
inline constexpr size_t kMaxEvalPoints = 1000000;

struct EvalRequest {
  std::string table;  // TableNames()
  // The coordinates by option name ("mu", "roughness", "sigma", "f0", "eta",
  // "k", "tint"): which a table takes depends on it and its model
  // (TableDefinition::Coordinates); an empty list is one not given.
  std::map<std::string, std::vector<double>> coordinates;
  // How the caller spelled each value ("1e-7"), for the messages; a value
  // without one is quoted as the shortest decimal that reads back.
  std::map<std::string, std::vector<std::string>> spelling;
  // Models; each must be one the table has (TableDefinition::ModelOptions).
  // Unset: GGX, height-correlated Smith, Schlick, Charlie, alpha = r.
  std::optional<NdfKind> ndf;
  std::optional<SmithForm> smith;
  std::optional<FresnelModel> fresnel;
  std::optional<SheenVisibility> sheenVisibility;
  std::optional<SheenAlpha> sheenAlpha;
  // Unset: the quadrature. Sampled: the value at a texel centre is the
  // texel's of a bake with the same settings and seed.
  SamplingRequest sampling;
  int threads = 0;  // 0: all cores; the values do not depend on it
};

// One coordinate option of eval (--mu, --roughness, ...), gathered from
// every table definition's coordinates (under every Fresnel model): what it
// is, the tables that take it, and its widest range (each table narrows it,
// and Evaluate says so). The command line's options and help are these.
struct EvalCoordinateOption {
  std::string option;   // "mu"
  std::string meaning;  // the first table's (registry order) meaning
  std::vector<std::string> tables;
  double min = 0.0, max = 1.0;
  bool zeroAllowed = false;
  std::string accepted;  // the widest range in words
  bool Accepts(double v) const { return (v >= min && v <= max) || (zeroAllowed && v == 0.0); }
};
std::vector<EvalCoordinateOption> EvalCoordinateOptions();

// One model option of bake and eval (--ndf, --smith, --fresnel,
// --sheen-visibility, --sheen-alpha): what it chooses, the values it
// accepts (the models' own names: ToString of each), its default (that of
// a request that leaves it unset: BakeSettings'), and the tables whose model
// it chooses (each definition's ModelOptions(), in registry order). The
// command line's options and help are these.
struct ModelOption {
  std::string option;                 // "ndf"
  std::string meaning;                // "Microfacet distribution"
  std::vector<std::string> accepted;  // "ggx", "beckmann"
  std::string defaultValue;           // "ggx"
  std::vector<std::string> tables;    // "E", "Eavg", "dfg", ...
};
std::vector<ModelOption> ModelOptions();

// The models that option values choose; an option not given stays unset.
struct ModelChoice {
  std::optional<NdfKind> ndf;
  std::optional<SmithForm> smith;
  std::optional<FresnelModel> fresnel;
  std::optional<SheenVisibility> sheenVisibility;
  std::optional<SheenAlpha> sheenAlpha;
  // Sets a request's models (BakeRequest, EvalRequest) to these.
  template <typename Request>
  void SetIn(Request *request) const {
    request->ndf = ndf;
    request->smith = smith;
    request->fresnel = fresnel;
    request->sheenVisibility = sheenVisibility;
    request->sheenAlpha = sheenAlpha;
  }
};
// `values`: option -> value, as ModelOptions spells them ({"ndf",
// "beckmann"}). Throws UsageError for an option or a value it does not
// accept.
ModelChoice ModelsNamed(const std::map<std::string, std::string> &values);

struct EvalPoint {
  std::vector<double> coordinates;     // in EvalResult::coordinateNames' order
  std::vector<double> values, errors;  // per channel
  // "exact" (the closed form of the mirror), "quadrature" (also where a
  // tolerance run switched to it), else the sampled estimator's name.
  std::string estimator;
  uint64_t samples = 0;
  // A fitted table's measures of its fit at the point, as the definition
  // states them (ltc_ggx: lobeError, polygonError, leakage); empty for
  // integrated tables.
  std::vector<std::pair<std::string, double>> fitErrors;
};

struct EvalResult {
  std::string table;
  Metadata labels;                           // the variant: {"fresnel", "schlick"}, ...
  std::vector<std::string> coordinateNames;  // "mu", "roughness", ...
  std::vector<std::string> channelMeanings;  // "E"; "A", "B"
  // How the values were made and what their errors are, in words: the
  // quadrature's description and bound (TableDefinition), or the sampler's.
  std::string method;
  std::vector<EvalPoint> points;
  // `eval --json`'s line for points[i]: table, labels, coordinates, value,
  // error (arrays for two channels or more: [A, B]), the fit's measures of a
  // fitted table (lobeError, ...), estimator, samples.
  std::string JsonLine(size_t i) const;
  // Point i as `eval` prints it: "E   mu 0.5        roughness 0.3        E
  // 0.97...  error 1e-10  (quadrature)", with its newline.
  std::string TextLine(size_t i) const;
};

EvalResult Evaluate(const EvalRequest &request);

}  // namespace lutbake
