// Speed benchmarks (Google Benchmark; run through scripts/benchmark.sh, a
// Release build, never in the test suite). Each new path is beside its
// baseline, measured in the same run, so that the ratio holds on a noisy
// machine:
//   DefaultBake              the four default tables, default settings (panel
//                            quadrature, every integration bound <= 1e-8)
//   AdaptiveBakeSameBound    the same tables by the adaptive Gauss-Kronrod
//                            quadrature (the default before) at --tolerance 1e-8
//   Dfg512                   dfg 512 x 512 at the default settings
//   EvalPoint                one dfg point at the default settings
//   EvalPointAdaptive        the same point by the adaptive quadrature, same bound
//   SampledTexel             samples per second of --samples (visible normals,
//                            SIMD, shared point blocks) on one thread
//   ScalarSamplerBaseline    the plain scalar sampler the bake used before:
//                            per sample two scrambled Sobol coordinates, the
//                            scalar estimator and a compensated sum
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <cmath>

#include "lutbake/core/hash.h"
#include "lutbake/integrators/albedo_estimator.h"
#include "lutbake/integrators/replicated_integrator.h"
#include "lutbake/integrators/sobol.h"
#include "lutbake/tables/bake.h"

namespace {

using namespace lutbake;

void BakeAll(const BakeSettings &s) {
  for (const TableDefinition *kind : AllTables())
    benchmark::DoNotOptimize(BakeTable(*kind, s).values.data());
}

void DefaultBake(benchmark::State &state) {
  for (auto _ : state) BakeAll(BakeSettings{});
}
BENCHMARK(DefaultBake)->Unit(benchmark::kMillisecond)->UseRealTime();

void AdaptiveBakeSameBound(benchmark::State &state) {
  BakeSettings s;
  s.estimator = Estimator::kAdaptiveQuadrature;
  s.tolerance = kDefaultQuadratureTolerance;
  for (auto _ : state) BakeAll(s);
}
BENCHMARK(AdaptiveBakeSameBound)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();

void Dfg512(benchmark::State &state) {
  BakeSettings s;
  s.tableSizes = {{"dfg", 512}};
  for (auto _ : state) benchmark::DoNotOptimize(BakeTable(TableNamed("dfg"), s).values.data());
}
BENCHMARK(Dfg512)->Unit(benchmark::kMillisecond)->Iterations(1)->UseRealTime();

void EvalPointWith(benchmark::State &state, Estimator estimator) {
  BakeSettings s;
  s.estimator = estimator;
  if (estimator == Estimator::kAdaptiveQuadrature) s.tolerance = kDefaultQuadratureTolerance;
  for (auto _ : state)
    benchmark::DoNotOptimize(EvaluateAlbedo(TableNamed("dfg"), s, 0.5, 0.25, 0).value[0]);
}
void EvalPoint(benchmark::State &state) { EvalPointWith(state, Estimator::kQuadrature); }
void EvalPointAdaptive(benchmark::State &state) {
  EvalPointWith(state, Estimator::kAdaptiveQuadrature);
}
BENCHMARK(EvalPoint)->Unit(benchmark::kMicrosecond);
BENCHMARK(EvalPointAdaptive)->Unit(benchmark::kMicrosecond);

constexpr uint64_t kSamples = 1 << 20;

void SampledTexel(benchmark::State &state) {
  tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  BakeSettings s;
  s.estimator = Estimator::kVisibleNormal;
  s.samples = kSamples;
  for (auto _ : state)
    benchmark::DoNotOptimize(EvaluateAlbedo(TableNamed("dfg"), s, 0.5, 0.25, 0).value[0]);
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * kSamples));
}
BENCHMARK(SampledTexel)->Unit(benchmark::kMillisecond);

void ScalarSamplerBaseline(benchmark::State &state) {
  const Ndf ndf{NdfKind::kGgx, 0.25};
  const AlbedoEstimator estimator{ndf, SmithForm::kCorrelated, SampleStrategy::kVisibleNormal};
  const Vec3 o = ViewDirection(0.5);
  const double L_o = ndf.MuLambda(0.5);
  for (auto _ : state) {
    double mean[2] = {0, 0};
    for (int r = 0; r < kDefaultReplicates; ++r) {
      const uint32_t seed0 = static_cast<uint32_t>(HashValues({1, static_cast<uint64_t>(r), 0}));
      const uint32_t seed1 = static_cast<uint32_t>(HashValues({1, static_cast<uint64_t>(r), 1}));
      CompensatedSum sum[2];
      for (uint32_t i = 0; i < kSamples / kDefaultReplicates; ++i) {
        const AlbedoSample a =
            estimator.Sample(o, L_o, ScrambledSobol(i, 0, seed0), ScrambledSobol(i, 1, seed1));
        sum[0].Add(a.weight * a.schlickComplement);
        sum[1].Add(a.weight * a.schlickWeight);
      }
      for (int c = 0; c < 2; ++c) mean[c] += sum[c].Value();
    }
    benchmark::DoNotOptimize(mean[0] + mean[1]);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * kSamples));
}
BENCHMARK(ScalarSamplerBaseline)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
