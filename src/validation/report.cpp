#include "lutbake/validation/report.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <thread>

namespace lutbake {

namespace {

BakeSettings BaseSettings(const ReportSettings &s) {
  BakeSettings b;
  b.ndf = s.ndf;
  b.smith = s.smith;
  b.sheenVisibility = s.sheenVisibility;
  b.sheenAlpha = s.sheenAlpha;
  b.size = s.size;
  b.depthSize = s.depthSize;
  b.seed = s.seed;
  b.replicates = kDefaultReplicates;
  b.cancellation = s.cancellation;
  return b;
}

// Reference values of every texel, [texel][channel]: the table's reference
// integrator (the adaptive Gauss-Kronrod quadrature at its own default
// tolerance, 1e-12 for a point and 1e-11 for an average, independent of the
// panel rule and the samplers), or, for a table whose definition names the
// panel rule instead (sheen_Eavg: the adaptive E_avg takes seconds a texel),
// that rule at 1e-12.
std::vector<std::array<double, 2>> ReferenceValues(const ReportSettings &s,
                                                   const TableDefinition &table,
                                                   const Table &layout) {
  BakeSettings reference = BaseSettings(s);
  reference.estimator = table.ReferenceEstimator();
  if (reference.estimator != Estimator::kAdaptiveQuadrature) reference.tolerance = 1e-12;
  const size_t texels = layout.texelCount(), slice = texels / layout.depth();
  std::vector<std::array<double, 2>> ref(texels);
  tbb::parallel_for(size_t(0), texels, [&](size_t t) {
    if (s.cancellation && s.cancellation->cancelled()) return;
    const int ix = static_cast<int>(t % layout.width());
    const int iy = static_cast<int>((t % slice) / layout.width());
    const int iz = static_cast<int>(t / slice);
    const PointValue v = EvaluateTexel(table, reference, layout, ix, iy, iz);
    ref[t] = {v.value[0], v.value[1]};
  });
  if (s.cancellation) s.cancellation->ThrowIfCancelled();
  return ref;
}

ReportRow Measure(const TableDefinition &table, const BakeSettings &b,
                  const std::vector<std::array<double, 2>> &ref) {
  BakeStats stats;
  const Table t = BakeTable(table, b, {}, &stats);
  ReportRow row;
  row.table = &table;
  row.estimator = b.estimator;
  row.seconds = stats.seconds;
  const size_t texels = ref.size();
  row.samplesPerTexel =
      static_cast<double>(IsQuadrature(b.estimator) ? stats.evaluations : stats.samples) /
      static_cast<double>(texels);
  double sumSq = 0;
  size_t within = 0;
  const size_t slice = static_cast<size_t>(t.width()) * t.height();
  for (size_t i = 0; i < texels; ++i) {
    // Every slice of a 3D table has its grazing column and smoothest row.
    const int ix = static_cast<int>(i % t.width());
    const int iy = static_cast<int>((i % slice) / t.width());
    double e = 0;
    bool ok = true;
    for (int c = 0; c < t.channels; ++c) {
      const double ec = std::abs(t.values[i * t.channels + c] - ref[i][c]);
      const double bound = t.errors[i * t.channels + c];
      e = std::max(e, ec);
      ok = ok && ec <= bound;
      row.maxBound = std::max(row.maxBound, bound);
    }
    within += ok;
    row.maxError = std::max(row.maxError, e);
    sumSq += e * e;
    if (ix == 0) row.grazingColumnMax = std::max(row.grazingColumnMax, e);
    if (iy == 0 && t.is2D()) row.smoothestRowMax = std::max(row.smoothestRowMax, e);
  }
  // A 1D table (E_avg) has no grazing column; its first texel is the smoothest.
  if (!t.is2D()) {
    row.smoothestRowMax = row.grazingColumnMax;
    row.grazingColumnMax = 0;
  }
  row.rmsError = std::sqrt(sumSq / static_cast<double>(texels));
  row.withinBound = static_cast<double>(within) / static_cast<double>(texels);
  return row;
}

std::string Format(const char *format, double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, v);
  return buffer;
}

}  // namespace

std::vector<ReportRow> RunReport(const ReportSettings &s, const ReportProgressFn &progress) {
  std::vector<ReportRow> rows;
  const double share = s.budgetSeconds / static_cast<double>(std::max<size_t>(
                                             1, s.tables.size() * s.estimators.size()));
  for (const TableDefinition *table : s.tables) {
    if (progress) progress(std::string("reference values of ") + table->Name());
    // The layout (axes) of the report table, as BakeTable makes it.
    Table layout;
    DefaultAxes(*table, BaseSettings(s), &layout.x, &layout.y, &layout.z);
    const std::vector<std::array<double, 2>> ref = ReferenceValues(s, *table, layout);
    for (Estimator estimator : s.estimators) {
      // An estimator the table does not offer is left out; the Markdown
      // says why.
      if (!table->EstimatorProblem(estimator).empty()) continue;
      BakeSettings b = BaseSettings(s);
      b.estimator = estimator;
      double spent = 0, last = 0;
      const bool quadrature = IsQuadrature(estimator);
      for (int step = 0;; ++step) {
        if (quadrature) {
          b.tolerance = std::pow(10.0, -2 - step);
          if (b.tolerance < 1e-10) break;
        } else {
          b.samples = uint64_t{4} << step;
          if (b.samples > kDefaultMaxSamples) break;
        }
        // The next run costs about twice the last (half again for the
        // quadrature's next decade); stop when it would overrun the share.
        const double predicted = last * (quadrature ? 1.5 : 2.0);
        if (step > 0 && spent + predicted > share) break;
        if (progress) {
          char line[160];
          std::snprintf(line, sizeof line, "%s %-11s %s %-10.3g spent %6.1f s of %.1f s",
                        table->Name(), std::string(ToString(estimator)).c_str(),
                        quadrature ? "tolerance" : "samples  ",
                        quadrature ? b.tolerance : static_cast<double>(b.samples), spent, share);
          progress(line);
        }
        if (s.cancellation) s.cancellation->ThrowIfCancelled();
        ReportRow row = Measure(*table, b, ref);
        row.tolerance = quadrature ? b.tolerance : 0.0;
        last = row.seconds;
        spent += row.seconds;
        rows.push_back(row);
      }
    }
  }
  return rows;
}

std::string ReportCsv(const std::vector<ReportRow> &rows) {
  std::ostringstream out;
  out << "table,estimator,samples_per_texel,tolerance,seconds,max_error,rms_error,"
         "grazing_column_max,smoothest_row_max,max_bound,within_bound\n";
  for (const ReportRow &r : rows) {
    out << r.table->Name() << ',' << ToString(r.estimator) << ','
        << Format("%.17g", r.samplesPerTexel) << ',' << Format("%.3g", r.tolerance) << ','
        << Format("%.6g", r.seconds) << ',' << Format("%.6e", r.maxError) << ','
        << Format("%.6e", r.rmsError) << ',' << Format("%.6e", r.grazingColumnMax) << ','
        << Format("%.6e", r.smoothestRowMax) << ',' << Format("%.6e", r.maxBound) << ','
        << Format("%.4f", r.withinBound) << '\n';
  }
  return out.str();
}

std::string ReportMarkdown(const ReportSettings &s, const std::vector<ReportRow> &rows) {
  std::ostringstream out;
  out << "# lutbake report\n\n"
      << "lutbake " << LutbakeVersion() << "; NDF " << ToString(s.ndf) << ", Smith "
      << ToString(s.smith) << "; sheen visibility " << ToString(s.sheenVisibility)
      << ", sheen alpha " << ToString(s.sheenAlpha) << "; tables " << s.size
      << " texels per axis; budget " << s.budgetSeconds << " s in total; "
      << std::thread::hardware_concurrency() << " hardware threads.\n\n"
      << "Real error of every texel against the quadrature at 1e-12 (E_avg: 1e-11). "
         "Sampled estimators: 4 replicates; samples per texel as listed. The two quadratures "
         "(quadrature: the default panel rule; adaptive: nested adaptive Gauss-Kronrod): "
         "integrand evaluations per texel at the tolerance listed.\n\n";
  for (const TableDefinition *kind : s.tables) {
    out << "## " << kind->Name() << "\n\n";
    if (kind->ReferenceEstimator() != Estimator::kAdaptiveQuadrature)
      out << "The reference here is the panel rule at 1e-12 (the table's definition names it: "
             "the adaptive quadrature is too slow for every texel), so the quadrature rows "
             "measure that rule against itself at a finer tolerance.\n\n";
    out << "### Time to reach a max error\n\n"
        << "| estimator | 1e-3 | 1e-4 | 1e-5 | 1e-6 | best max error (time) |\n"
        << "|---|---|---|---|---|---|\n";
    for (Estimator e : s.estimators) {
      out << "| " << ToString(e);
      if (const std::string problem = kind->EstimatorProblem(e); !problem.empty()) {
        out << " | not offered: " << problem << " | | | | |\n";
        continue;
      }
      double best = INFINITY, bestTime = 0;
      for (double threshold : {1e-3, 1e-4, 1e-5, 1e-6}) {
        std::string cell = "not reached";
        for (const ReportRow &r : rows)
          if (r.table == kind && r.estimator == e && r.maxError <= threshold) {
            cell = Format("%.3g s", r.seconds);
            break;
          }
        out << " | " << cell;
      }
      for (const ReportRow &r : rows)
        if (r.table == kind && r.estimator == e && r.maxError < best) {
          best = r.maxError;
          bestTime = r.seconds;
        }
      out << " | "
          << (std::isfinite(best) ? Format("%.2e", best) + Format(" (%.3g s)", bestTime)
                                  : std::string("none"))
          << " |\n";
    }
    out << "\n\"not reached\": not within this report's budget.\n\n### All runs\n\n"
        << "| estimator | samples (quadrature: evaluations) per texel | tolerance | seconds | "
           "max error | RMS error | grazing column max | smoothest row max | max bound | "
           "within bound |\n|---|---|---|---|---|---|---|---|---|---|\n";
    for (const ReportRow &r : rows) {
      if (r.table != kind) continue;
      out << "| " << ToString(r.estimator) << " | " << Format("%.0f", r.samplesPerTexel) << " | "
          << (r.tolerance > 0 ? Format("%.0e", r.tolerance) : "") << " | "
          << Format("%.3g", r.seconds) << " | " << Format("%.2e", r.maxError) << " | "
          << Format("%.2e", r.rmsError) << " | " << Format("%.2e", r.grazingColumnMax) << " | "
          << Format("%.2e", r.smoothestRowMax) << " | " << Format("%.2e", r.maxBound) << " | "
          << Format("%.1f%%", 100.0 * r.withinBound) << " |\n";
    }
    out << "\n";
  }
  return out.str();
}

std::string ReportSvg(const ReportSettings &s, const std::vector<ReportRow> &rows) {
  constexpr double kPanelWidth = 520, kPanelHeight = 400;
  constexpr double kLeft = 70, kRight = 150, kTop = 40, kBottom = 50;
  static const char *kColours[] = {"#7f7f7f", "#bcbd22", "#ff7f0e", "#9467bd",
                                   "#1f77b4", "#2ca02c", "#d62728"};
  std::ostringstream out;
  const double width = kPanelWidth * static_cast<double>(s.tables.size());
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\""
      << kPanelHeight << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  for (size_t p = 0; p < s.tables.size(); ++p) {
    const TableDefinition *kind = s.tables[p];
    Axis layoutX, layoutY;
    DefaultAxes(*kind, BaseSettings(s), &layoutX, &layoutY);
    const double x0 = kPanelWidth * static_cast<double>(p) + kLeft;
    const double plotW = kPanelWidth - kLeft - kRight, plotH = kPanelHeight - kTop - kBottom;
    // Decade-aligned log ranges over this table's rows.
    double tMin = INFINITY, tMax = 0, eMin = INFINITY, eMax = 0;
    for (const ReportRow &r : rows)
      if (r.table == kind) {
        tMin = std::min(tMin, std::max(r.seconds, 1e-4));
        tMax = std::max(tMax, std::max(r.seconds, 1e-4));
        eMin = std::min(eMin, std::max(r.maxError, 1e-10));
        eMax = std::max(eMax, std::max(r.maxError, 1e-10));
      }
    if (!(tMax > 0)) continue;
    const double lt0 = std::floor(std::log10(tMin)),
                 lt1 = std::max(lt0 + 1, std::ceil(std::log10(tMax)));
    const double le0 = std::floor(std::log10(eMin)),
                 le1 = std::max(le0 + 1, std::ceil(std::log10(eMax)));
    const auto X = [&](double t) {
      return x0 + plotW * (std::log10(std::max(t, 1e-4)) - lt0) / (lt1 - lt0);
    };
    const auto Y = [&](double e) {
      return kTop + plotH * (le1 - std::log10(std::max(e, 1e-10))) / (le1 - le0);
    };
    out << "<text x=\"" << x0 + plotW / 2 << "\" y=\"20\" text-anchor=\"middle\" "
        << "font-size=\"14\">" << kind->Name() << " (" << ToString(s.ndf) << ", " << s.size << "x"
        << layoutY.count << "): max error against time</text>\n"
        << "<rect x=\"" << x0 << "\" y=\"" << kTop << "\" width=\"" << plotW << "\" height=\""
        << plotH << "\" fill=\"none\" stroke=\"black\"/>\n";
    for (double d = lt0; d <= lt1; d += 1) {
      const double x = X(std::pow(10.0, d));
      out << "<line x1=\"" << x << "\" y1=\"" << kTop << "\" x2=\"" << x << "\" y2=\""
          << kTop + plotH << "\" stroke=\"#dddddd\"/>\n<text x=\"" << x << "\" y=\""
          << kTop + plotH + 16 << "\" text-anchor=\"middle\">1e" << d << "</text>\n";
    }
    for (double d = le0; d <= le1; d += 1) {
      const double y = Y(std::pow(10.0, d));
      out << "<line x1=\"" << x0 << "\" y1=\"" << y << "\" x2=\"" << x0 + plotW << "\" y2=\"" << y
          << "\" stroke=\"#dddddd\"/>\n<text x=\"" << x0 - 6 << "\" y=\"" << y + 4
          << "\" text-anchor=\"end\">1e" << d << "</text>\n";
    }
    out << "<text x=\"" << x0 + plotW / 2 << "\" y=\"" << kPanelHeight - 12
        << "\" text-anchor=\"middle\">wall time of the bake (s)</text>\n"
        << "<text transform=\"translate(" << x0 - 50 << "," << kTop + plotH / 2
        << ") rotate(-90)\" text-anchor=\"middle\">max real error</text>\n";
    int legend = 0;
    for (size_t k = 0; k < std::size(kAllEstimators); ++k) {
      const Estimator e = kAllEstimators[k];
      std::string points;
      for (const ReportRow &r : rows)
        if (r.table == kind && r.estimator == e)
          points += Format("%.1f,", X(r.seconds)) + Format("%.1f ", Y(r.maxError));
      if (points.empty()) continue;
      const char *colour = kColours[k % std::size(kColours)];
      out << "<polyline points=\"" << points << "\" fill=\"none\" stroke=\"" << colour
          << "\" stroke-width=\"2\"/>\n";
      const double ly = kTop + 10 + 18 * legend++;
      out << "<line x1=\"" << x0 + plotW + 10 << "\" y1=\"" << ly << "\" x2=\"" << x0 + plotW + 30
          << "\" y2=\"" << ly << "\" stroke=\"" << colour << "\" stroke-width=\"2\"/>\n<text x=\""
          << x0 + plotW + 35 << "\" y=\"" << ly + 4 << "\">" << ToString(e) << "</text>\n";
    }
  }
  out << "</svg>\n";
  return out.str();
}

}  // namespace lutbake
