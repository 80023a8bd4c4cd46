#include "lutbake/tables/bake_estimate.h"

#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numeric>
#include <sstream>

#include "lutbake/tables/bake.h"

namespace lutbake {

BakeEstimate EstimateWork(const std::vector<EstimatedWork> &work, double secondsPerItem) {
  using Clock = std::chrono::steady_clock;
  BakeEstimate estimate;
  estimate.threads = std::max(1, tbb::this_task_arena::max_concurrency());
  // A Latin hypercube of the `wanted` texels: along each axis, sample k
  // falls in stratum (m k + c) mod wanted, with multipliers m coprime to
  // wanted (each axis then visits every stratum once) and differing between
  // the axes (so that the axes do not move together).
  constexpr size_t kMultiplier[3] = {1, 3, 5}, kShift[3] = {0, 1, 3};
  for (const EstimatedWork &w : work) {
    const size_t texels = static_cast<size_t>(w.counts[0]) * w.counts[1] * w.counts[2];
    if (texels == 0) continue;
    estimate.texels += texels;
    const size_t wanted = std::min<size_t>(texels, kEstimateTexelsPerTable);
    double spent = 0.0;
    size_t timed = 0;
    for (size_t k = 0; k < wanted && (timed == 0 || spent < secondsPerItem); ++k) {
      int index[3];
      for (int a = 0; a < 3; ++a) {
        const size_t m = std::gcd(kMultiplier[a], wanted) == 1 ? kMultiplier[a] : 1;
        const size_t stratum = (m * k + kShift[a]) % wanted;
        index[a] =
            static_cast<int>((2 * stratum + 1) * static_cast<size_t>(w.counts[a]) / (2 * wanted));
      }
      const Clock::time_point start = Clock::now();
      double seconds = 0.0;
      try {
        if (w.timeTexel)
          seconds = w.timeTexel(index[0], index[1], index[2]);
        else
          w.evaluateTexel(index[0], index[1], index[2]);
      } catch (const std::exception &) {
        // A texel the bake would refuse costs nothing here; the bake says why.
      }
      spent += w.timeTexel ? seconds : std::chrono::duration<double>(Clock::now() - start).count();
      ++timed;
    }
    estimate.timedTexels += timed;
    estimate.cpuSeconds += spent /
                           static_cast<double>(timed * std::max<size_t>(1, w.texelsPerCall)) *
                           static_cast<double>(texels);
  }
  estimate.seconds = estimate.cpuSeconds / estimate.threads;
  return estimate;
}

BakeEstimate EstimateBake(const std::vector<EstimatedTable> &tables, double secondsPerTable) {
  std::vector<EstimatedWork> work;
  for (const EstimatedTable &t : tables) {
    Table shape;
    shape.x = t.x;
    shape.y = t.y;
    shape.z = t.z;
    EstimatedWork w;
    w.counts[0] = t.x.count;
    w.counts[1] = t.y.count;
    w.counts[2] = t.z.count;
    w.evaluateTexel = [&t, shape](int i, int j, int k) {
      (void)EvaluateTexel(*t.definition, t.settings, shape, i, j, k);
    };
    work.push_back(std::move(w));
  }
  return EstimateWork(work, secondsPerTable);
}

std::string DescribeEstimate(const BakeEstimate &e) {
  std::ostringstream s;
  if (e.seconds < 1.0) {
    s << "under a second";
  } else if (e.seconds < 120.0) {
    s << "about " << static_cast<long>(std::lround(e.seconds)) << " s";
  } else {
    s << "about " << static_cast<long>(std::lround(e.seconds / 60.0)) << " min";
  }
  s << " on " << e.threads << " thread" << (e.threads == 1 ? "" : "s") << " (" << e.timedTexels
    << " of " << e.texels << " texel" << (e.texels == 1 ? "" : "s") << " timed)";
  return s.str();
}

}  // namespace lutbake
