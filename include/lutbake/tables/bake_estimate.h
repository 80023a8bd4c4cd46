// How long a bake will take, from a timed sample of its texels: a few texels
// of each table, spread over its axes as a Latin hypercube (an evenly
// spread flat index would put them all in one column), are
// evaluated one at a time on the calling thread, and their mean cost times the table's texel count,
// summed over the tables and divided by the threads, is the estimate. The texels timed are fixed;
// the time is this machine's now (an estimate, not a result: it is never written into a table).
//
// The default split-sum and Kulla-Conty bakes share work between texels
// (one set of points, SIMD over texels), so a texel alone costs more than
// its share of the whole bake: for them the estimate is an upper bound.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "lutbake/tables/settings.h"
#include "lutbake/tables/table.h"
#include "lutbake/tables/table_definition.h"

namespace lutbake {

// One table of a bake: its definition, settings and axes.
struct EstimatedTable {
  const TableDefinition *definition = nullptr;
  BakeSettings settings;
  Axis x, y, z = LinearAxis("", 0.0, 1.0, 1);
};

struct BakeEstimate {
  double seconds = 0.0;     // wall time on `threads` threads
  double cpuSeconds = 0.0;  // the work summed over the tables
  size_t texels = 0;        // texels of all the tables
  size_t timedTexels = 0;   // of which were timed
  int threads = 1;
};

// At most kEstimateTexelsPerTable texels of each table are timed, and no
// more once a table's timed texels have taken secondsPerTable (one is
// always timed).
inline constexpr int kEstimateTexelsPerTable = 8;
BakeEstimate EstimateBake(const std::vector<EstimatedTable> &tables, double secondsPerTable = 0.25);

// The same for any texel loop (a preset's textures): counts[0] x counts[1]
// x counts[2] texels, of which evaluateTexel(i, j, k) computes
// texelsPerCall (1, or a small grid where the work is a fit over the whole
// grid at once).
// timeTexel, where set, replaces evaluateTexel: it returns the seconds one
// texel costs, measured by itself (an LTC texel: the fit warm-started from
// its neighbour's, which it computes first, untimed, as the bake has it).
struct EstimatedWork {
  int counts[3] = {1, 1, 1};
  std::function<void(int i, int j, int k)> evaluateTexel;
  size_t texelsPerCall = 1;
  std::function<double(int i, int j, int k)> timeTexel;
};
BakeEstimate EstimateWork(const std::vector<EstimatedWork> &work, double secondsPerItem = 0.25);

// "about 12 s on 2 threads (16 of 5120 texels timed)", or "under a second
// on 2 threads (...)".
std::string DescribeEstimate(const BakeEstimate &estimate);

}  // namespace lutbake
