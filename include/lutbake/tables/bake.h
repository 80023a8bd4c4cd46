// Baking a table: the parallel loop over its texels, each evaluated by the
// table's definition (table_definition.h), and the metadata that goes into
// every file. Also the point evaluators that the microfacet and Fresnel
// tables share.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

#include "lutbake/models/fresnel.h"
#include "lutbake/models/ndf.h"
#include "lutbake/models/smith.h"
#include "lutbake/tables/settings.h"
#include "lutbake/tables/table.h"
#include "lutbake/tables/table_definition.h"

namespace lutbake {

// What a bake spent and achieved, per table.
struct BakeStats {
  uint64_t samples = 0;           // sampled estimator: samples over all texels
  uint64_t maxTexelSamples = 0;   // the most any texel used
  uint64_t quadratureTexels = 0;  // texels integrated by the quadrature
  uint64_t evaluations = 0;       // quadrature integrand evaluations
  uint64_t unconverged = 0;       // texels whose bound is above the tolerance
  double seconds = 0.0;
};

// Reports the fraction done in [0, 1]; called from worker threads, so it
// must be thread-safe. May be empty.
using ProgressFn = std::function<void(double)>;

// Axes that several tables share: view cosine mu and perceptual roughness
// over [0, 1], and the Fresnel parameters of a model.
Axis RoughnessAxis(int count);
Axis MuAxis(int count);
void FresnelAxes(FresnelModel model, int count, Axis *x, Axis *y);

// The axes a table has by default (SPEC sections 2 and 3), with the
// settings' size for it.
void DefaultAxes(const TableDefinition &table, const BakeSettings &settings, Axis *x, Axis *y);
// A 3D table's third axis with the settings' depth (count 1 and no name for
// the others).
Axis DefaultDepthAxis(const TableDefinition &table, const BakeSettings &settings);
// With a 3D table's third axis too (count 1 and no name for the others).
void DefaultAxes(const TableDefinition &table, const BakeSettings &settings, Axis *x, Axis *y,
                 Axis *z);

Table BakeTable(const TableDefinition &table, const BakeSettings &settings,
                const ProgressFn &progress = {}, BakeStats *stats = nullptr);
// The same on given axes (a bake plan's narrowed or listed roughness, its
// IORs): x and y as DefaultAxes would give them, in kind and order.
Table BakeTableOn(const TableDefinition &table, const BakeSettings &settings, const Axis &x,
                  const Axis &y, const ProgressFn &progress = {}, BakeStats *stats = nullptr);
// With the third axis given too (a 3D table; a listed eta axis).
Table BakeTableOn(const TableDefinition &table, const BakeSettings &settings, const Axis &x,
                  const Axis &y, const Axis &z, const ProgressFn &progress = {},
                  BakeStats *stats = nullptr);

// How the values of `definition` are made under `settings`, in words (the
// metadata "estimator" of a baked table, eval's method): the deterministic
// integrator's description (QuadratureDescription) for a table that is not
// sampled or under the quadratures; else the sampler, "vndf with
// Owen-scrambled Sobol points" or "... with independent random points", then
// its SamplerNote, and in a tolerance run that may switch (settings.
// allowQuadratureSwitch), that texels for which the quadrature is cheaper
// switch to it.
std::string DescribeEstimator(const TableDefinition &definition, const BakeSettings &settings);

// The value of a table's texel (ix, iy, iz) on its axes, with the settings'
// estimator: Evaluate at the texel centres, or Evaluate3D for a 3D table.
PointValue EvaluateTexel(const TableDefinition &definition, const BakeSettings &settings,
                         const Table &table, int ix, int iy, int iz);

// E (channel 0) of table E, or the split sum (A, B) of table dfg, at (mu_o,
// alpha), with the settings' estimator (a tolerance run when
// settings.tolerance > 0); `table` chooses the channels and seeds the
// sampled points. mu_o in [0, 1]: mu_o = 0 is the grazing limit, evaluated
// by continuity (the integrands are written in forms that stay finite
// there). alpha = 0 is the mirror, exact. Throws std::domain_error for alpha
// in (0, kMinimumAlpha), alpha > 1 or mu_o outside [0, 1].
PointValue EvaluateAlbedo(const TableDefinition &table, const BakeSettings &settings, double mu_o,
                          double alpha, uint64_t pointSeed);
// E_avg(alpha) = 2 integral_0^1 E(mu) mu dmu, same conventions.
PointValue EvaluateAlbedoAverage(const BakeSettings &settings, double alpha, uint64_t pointSeed);
// F_avg of a Fresnel model at its parameters: x = F0 (Schlick) or eta
// (dielectric, conductor); y = k (conductor only). Deterministic quadrature.
PointValue EvaluateFresnelAverage(FresnelModel model, double x, double y);

const char *LutbakeVersion();

}  // namespace lutbake
