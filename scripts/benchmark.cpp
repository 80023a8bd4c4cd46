// Speed benchmarks (Google Benchmark; run through scripts/benchmark.sh, a
// Release build, never in the test suite):
//   DefaultBake           the four default tables at the default settings
//   ToleranceBake/EPS     the four default tables with --tolerance EPS
//   VndfSamplesPerCore    samples per second of the default estimator on one
//                         thread (one dfg texel, both channels)
//   QuadratureTexel       one dfg texel by the quadrature at EPS / 8
#include <benchmark/benchmark.h>
#include <tbb/global_control.h>

#include <cmath>

#include "lutbake/albedo_estimator.h"
#include "lutbake/bake.h"
#include "lutbake/reference_integrator.h"
#include "lutbake/replicated_integrator.h"

namespace {

using namespace lutbake;

void BakeAll(const BakeSettings &s) {
  for (TableKind kind : kAllTables) benchmark::DoNotOptimize(BakeTable(kind, s).values.data());
}

void DefaultBake(benchmark::State &state) {
  for (auto _ : state) BakeAll(BakeSettings{});
}
BENCHMARK(DefaultBake)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

void ToleranceBake(benchmark::State &state) {
  BakeSettings s;
  s.tolerance = std::pow(10.0, -static_cast<double>(state.range(0)));
  s.samples = kToleranceStartSamples;
  s.replicates = kToleranceReplicates;
  for (auto _ : state) BakeAll(s);
  state.SetLabel("EPS = 1e-" + std::to_string(state.range(0)));
}
BENCHMARK(ToleranceBake)->Arg(5)->Arg(6)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

void VndfSamplesPerCore(benchmark::State &state) {
  tbb::global_control one(tbb::global_control::max_allowed_parallelism, 1);
  const Ndf ndf{NdfKind::kGgx, 0.25};
  const AlbedoEstimator estimator{ndf, SmithForm::kCorrelated, SampleStrategy::kVisibleNormal};
  const Vec3 o = ViewDirection(0.5);
  const double L_o = ndf.MuLambda(0.5);
  const uint64_t samples = 1 << 20;
  for (auto _ : state) {
    const auto e = IntegrateReplicated<2, 2>(
        [&](const double(&u)[2]) {
          const AlbedoSample a = estimator.Sample(o, L_o, u[0], u[1]);
          return std::array<double, 2>{a.weight * a.schlickComplement, a.weight * a.schlickWeight};
        },
        samples, kDefaultReplicates, 1);
    benchmark::DoNotOptimize(e.mean[0]);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * samples));
}
BENCHMARK(VndfSamplesPerCore)->Unit(benchmark::kMillisecond);

void QuadratureTexel(benchmark::State &state) {
  const double tolerance = std::pow(10.0, -static_cast<double>(state.range(0)));
  for (auto _ : state)
    benchmark::DoNotOptimize(IntegrateReferenceAlbedo(Ndf{NdfKind::kGgx, 0.25},
                                                      SmithForm::kCorrelated, 0.5, tolerance / 8)
                                 .A);
}
BENCHMARK(QuadratureTexel)->Arg(5)->Arg(6)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
