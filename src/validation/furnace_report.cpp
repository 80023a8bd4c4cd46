#include "lutbake/validation/furnace_report.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "lutbake/formats/atomic_output.h"
#include "lutbake/formats/image_writer.h"
#include "lutbake/formats/writer.h"

namespace lutbake {

namespace {

std::string Number(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", v);
  return buffer;
}

// Distinct colours for the plot's lines (Okabe-Ito, without yellow).
const std::array<std::array<uint8_t, 3>, 7> kPalette = {{{0, 114, 178},
                                                         {213, 94, 0},
                                                         {0, 158, 115},
                                                         {204, 121, 167},
                                                         {86, 180, 233},
                                                         {230, 159, 0},
                                                         {0, 0, 0}}};

struct PlotFrame {
  int width = 640, height = 400, left = 60, right = 150, top = 20, bottom = 50;
  double yMin = 0, yMax = 1.2;
  double X(double mu) const { return left + mu * (width - left - right); }
  double Y(double a) const { return top + (yMax - a) / (yMax - yMin) * (height - top - bottom); }
};

PlotFrame Frame(const FurnaceResult &r) {
  PlotFrame f;
  double lo = 1.0, hi = 1.0;
  for (const auto &row : r.fine)
    for (double v : row) lo = std::min(lo, v), hi = std::max(hi, v);
  f.yMin = std::floor(std::min(0.0, lo) * 10.0) / 10.0;
  f.yMax = std::ceil(std::max(1.2, hi + 0.05) * 10.0) / 10.0;
  return f;
}

std::string ParameterLabel(const FurnaceSettings &s, double p) {
  return s.parameterName.empty() ? "albedo" : s.parameterName + " = " + Number(p);
}

}  // namespace

double InterpolateFine(const std::vector<double> &fine, double mu) {
  const double x = Clamp(mu, 0.0, 1.0) * (static_cast<double>(fine.size()) - 1.0);
  const size_t k = std::min(static_cast<size_t>(x), fine.size() - 2);
  const double t = x - static_cast<double>(k);
  return fine[k] + t * (fine[k + 1] - fine[k]);
}

FurnaceResult RunFurnace(const FurnaceSettings &s) {
  const size_t P = s.parameters.size(), M = s.mus.size();
  std::vector<std::unique_ptr<FurnaceIntegrator>> integrators(P);
  tbb::parallel_for(size_t(0), P, [&](size_t p) {
    integrators[p] = std::make_unique<FurnaceIntegrator>(s.model, s.parameters[p], s.tolerance);
  });
  FurnaceResult r;
  r.albedo.resize(P * M);
  r.average.resize(P);
  const size_t F = s.pictures ? kSphereMuCount : 0;
  r.fine.assign(s.pictures ? P : 0, std::vector<double>(F));
  // One task per value; each writes only its own slot.
  const size_t tasks = P * M + P + P * F;
  tbb::parallel_for(size_t(0), tasks, [&](size_t t) {
    if (t < P * M) {
      const size_t p = t / M, m = t % M;
      r.albedo[t] = {s.parameters[p], s.mus[m], integrators[p]->Albedo(s.mus[m])};
    } else if (t < P * M + P) {
      r.average[t - P * M] = integrators[t - P * M]->Average();
    } else {
      const size_t u = t - P * M - P, p = u / F, k = u % F;
      r.fine[p][k] = integrators[p]->Albedo(static_cast<double>(k) / (F - 1)).albedo.value;
    }
  });
  for (const FurnaceEntry &e : r.albedo) {
    const double d = e.point.albedo.value - 1.0;
    if (d > r.gain.amount) r.gain = {d, e.point.albedo.error, e.parameter, e.mu};
    if (-d > r.loss.amount) r.loss = {-d, e.point.albedo.error, e.parameter, e.mu};
  }
  return r;
}

std::string FurnaceJson(const FurnaceSettings &s, const FurnaceResult &r) {
  nlohmann::ordered_json j;
  j["model"] = std::string(ToString(s.model.kind));
  nlohmann::ordered_json options = nlohmann::ordered_json::object();
  for (const auto &[key, value] : s.options) options[key] = value;
  j["options"] = options;
  j["parameter_name"] = s.parameterName;
  nlohmann::ordered_json albedo = nlohmann::ordered_json::array();
  for (const FurnaceEntry &e : r.albedo) {
    nlohmann::ordered_json a{{"parameter", e.parameter},
                             {"mu", e.mu},
                             {"value", e.point.albedo.value},
                             {"error", e.point.albedo.error}};
    if (s.model.compensation) {
      a["single_scattering"] = e.point.singleScattering.value;
      a["single_scattering_error"] = e.point.singleScattering.error;
    }
    albedo.push_back(a);
  }
  j["albedo"] = albedo;
  nlohmann::ordered_json average = nlohmann::ordered_json::array();
  for (size_t p = 0; p < s.parameters.size(); ++p)
    average.push_back(nlohmann::ordered_json{{"parameter", s.parameters[p]},
                                             {"value", r.average[p].value},
                                             {"error", r.average[p].error}});
  j["average"] = average;
  // No gain (or loss) at all: null, not a point of the grid.
  const auto extreme = [](const FurnaceExtreme &x) {
    if (!(x.amount > 0.0)) return nlohmann::ordered_json(nullptr);
    return nlohmann::ordered_json{
        {"amount", x.amount}, {"error", x.error}, {"parameter", x.parameter}, {"mu", x.mu}};
  };
  j["worst"] = {{"gain", extreme(r.gain)}, {"loss", extreme(r.loss)}};
  return j.dump(2) + "\n";
}

std::string FurnaceCsv(const FurnaceSettings &s, const FurnaceResult &r) {
  std::ostringstream out;
  out << "# lutbake furnace --model " << ToString(s.model.kind);
  for (const auto &[key, value] : s.options) out << " " << key << "=" << value;
  out << "\n# average rows: mu empty, value = 2 int albedo mu dmu\n";
  out << "kind,parameter,mu,value,error"
      << (s.model.compensation ? ",single_scattering,single_scattering_error" : "") << "\n";
  for (const FurnaceEntry &e : r.albedo) {
    out << "albedo," << Number(e.parameter) << "," << Number(e.mu) << ","
        << Number(e.point.albedo.value) << "," << Number(e.point.albedo.error);
    if (s.model.compensation)
      out << "," << Number(e.point.singleScattering.value) << ","
          << Number(e.point.singleScattering.error);
    out << "\n";
  }
  for (size_t p = 0; p < s.parameters.size(); ++p) {
    out << "average," << Number(s.parameters[p]) << ",," << Number(r.average[p].value) << ","
        << Number(r.average[p].error) << (s.model.compensation ? ",," : "") << "\n";
  }
  return out.str();
}

std::string FurnacePlotSvg(const FurnaceSettings &s, const FurnaceResult &r) {
  const PlotFrame f = Frame(r);
  std::ostringstream out;
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << f.width << "\" height=\""
      << f.height << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n"
      << "<text x=\"" << f.left << "\" y=\"14\">white furnace: " << ToString(s.model.kind)
      << "</text>\n";
  // Axes, ticks and the line albedo = 1.
  for (int k = 0; k <= 4; ++k) {
    const double mu = k / 4.0;
    out << "<line x1=\"" << f.X(mu) << "\" y1=\"" << f.Y(f.yMin) << "\" x2=\"" << f.X(mu)
        << "\" y2=\"" << f.Y(f.yMax) << "\" stroke=\"#ddd\"/>\n<text x=\"" << f.X(mu) - 8
        << "\" y=\"" << f.Y(f.yMin) + 16 << "\">" << mu << "</text>\n";
  }
  for (double a = f.yMin; a <= f.yMax + 1e-9; a += 0.2) {
    out << "<line x1=\"" << f.X(0) << "\" y1=\"" << f.Y(a) << "\" x2=\"" << f.X(1) << "\" y2=\""
        << f.Y(a) << "\" stroke=\"#ddd\"/>\n<text x=\"" << f.left - 34 << "\" y=\"" << f.Y(a) + 4
        << "\">" << std::round(a * 10) / 10 << "</text>\n";
  }
  out << "<line x1=\"" << f.X(0) << "\" y1=\"" << f.Y(1) << "\" x2=\"" << f.X(1) << "\" y2=\""
      << f.Y(1) << "\" stroke=\"#888\" stroke-dasharray=\"4 3\"/>\n";
  out << "<text x=\"" << f.X(0.5) - 30 << "\" y=\"" << f.height - 12
      << "\">mu = cos(theta_o)</text>\n<text x=\"12\" y=\"" << f.Y(f.yMax) - 6
      << "\">albedo</text>\n";
  for (size_t p = 0; p < r.fine.size(); ++p) {
    const auto &c = kPalette[p % kPalette.size()];
    out << "<polyline fill=\"none\" stroke-width=\"2\" stroke=\"rgb(" << int(c[0]) << ","
        << int(c[1]) << "," << int(c[2]) << ")\" points=\"";
    for (size_t k = 0; k < r.fine[p].size(); ++k)
      out << f.X(k / (r.fine[p].size() - 1.0)) << "," << f.Y(r.fine[p][k]) << " ";
    out << "\"/>\n<text x=\"" << f.width - f.right + 10 << "\" y=\"" << f.top + 20 + 18 * p
        << "\" fill=\"rgb(" << int(c[0]) << "," << int(c[1]) << "," << int(c[2]) << ")\">"
        << ParameterLabel(s, s.parameters[p]) << "</text>\n";
  }
  out << "</svg>\n";
  return out.str();
}

namespace {

// The same plot rasterised (without its text): white background, grey grid,
// the dashed line at 1, each curve 2 pixels wide, a colour swatch per curve
// where the SVG has its label.
std::vector<uint8_t> RasterPlot(const FurnaceResult &r, int *width, int *height) {
  const PlotFrame f = Frame(r);
  *width = f.width;
  *height = f.height;
  std::vector<uint8_t> px(static_cast<size_t>(f.width) * f.height * 3, 255);
  const auto put = [&](int x, int y, const std::array<uint8_t, 3> &c) {
    if (x < 0 || y < 0 || x >= f.width || y >= f.height) return;
    std::copy(c.begin(), c.end(), px.begin() + (static_cast<size_t>(y) * f.width + x) * 3);
  };
  const auto line = [&](double x0, double y0, double x1, double y1, const std::array<uint8_t, 3> &c,
                        int thickness) {
    const int steps =
        std::max(1, static_cast<int>(std::ceil(std::max(std::abs(x1 - x0), std::abs(y1 - y0)))));
    for (int i = 0; i <= steps; ++i) {
      const double t = static_cast<double>(i) / steps;
      const int x = static_cast<int>(std::lround(x0 + t * (x1 - x0)));
      const int y = static_cast<int>(std::lround(y0 + t * (y1 - y0)));
      for (int dx = 0; dx < thickness; ++dx)
        for (int dy = 0; dy < thickness; ++dy) put(x + dx, y + dy, c);
    }
  };
  const std::array<uint8_t, 3> grid{221, 221, 221}, axis{136, 136, 136};
  for (int k = 0; k <= 4; ++k) line(f.X(k / 4.0), f.Y(f.yMin), f.X(k / 4.0), f.Y(f.yMax), grid, 1);
  for (double a = f.yMin; a <= f.yMax + 1e-9; a += 0.2)
    line(f.X(0), f.Y(a), f.X(1), f.Y(a), grid, 1);
  for (double x = 0; x < 1.0; x += 0.02) line(f.X(x), f.Y(1), f.X(x + 0.012), f.Y(1), axis, 1);
  for (size_t p = 0; p < r.fine.size(); ++p) {
    const auto &c = kPalette[p % kPalette.size()];
    for (size_t k = 0; k + 1 < r.fine[p].size(); ++k) {
      const double n = r.fine[p].size() - 1.0;
      line(f.X(k / n), f.Y(r.fine[p][k]), f.X((k + 1) / n), f.Y(r.fine[p][k + 1]), c, 2);
    }
    const int y = f.top + 14 + 18 * static_cast<int>(p);
    for (int dy = 0; dy < 8; ++dy)
      line(f.width - f.right + 10, y + dy, f.width - f.right + 40, y + dy, c, 1);
  }
  return px;
}

}  // namespace

FurnaceImage RenderFurnaceSpheres(const FurnaceResult &r) {
  FurnaceImage image;
  const int count = static_cast<int>(r.fine.size());
  image.width = kSphereGap + count * (kSphereDiameter + kSphereGap);
  image.height = kSphereDiameter + 2 * kSphereGap;
  image.values.assign(static_cast<size_t>(image.width) * image.height, 1.0f);
  const double radius = 0.5 * kSphereDiameter;
  for (int p = 0; p < count; ++p) {
    const int x0 = kSphereGap + p * (kSphereDiameter + kSphereGap), y0 = kSphereGap;
    for (int y = 0; y < kSphereDiameter; ++y)
      for (int x = 0; x < kSphereDiameter; ++x) {
        // The pixel centre on the disc, in units of the radius.
        const double dx = (x + 0.5 - radius) / radius, dy = (y + 0.5 - radius) / radius;
        const double rho2 = dx * dx + dy * dy;
        if (rho2 >= 1.0) continue;
        const double mu = std::sqrt(1.0 - rho2);
        image.values[static_cast<size_t>(y0 + y) * image.width + x0 + x] =
            static_cast<float>(InterpolateFine(r.fine[p], mu));
      }
  }
  return image;
}

void WriteFurnaceFiles(OutputTransaction &output, const FurnaceSettings &s,
                       const FurnaceResult &r) {
  output.WriteText("furnace.csv", FurnaceCsv(s, r));
  output.WriteText("furnace.json", FurnaceJson(s, r));
  if (r.fine.empty()) return;
  output.WriteText("furnace_plot.svg", FurnacePlotSvg(s, r));
  int w = 0, h = 0;
  const std::vector<uint8_t> plot = RasterPlot(r, &w, &h);
  output.Write("furnace_plot.png", [&](const std::string &path) { WritePng(path, w, h, 3, plot); });
  const FurnaceImage spheres = RenderFurnaceSpheres(r);
  output.Write("furnace_spheres.exr", [&](const std::string &path) {
    WriteExrImage(path, spheres.width, spheres.height, {"Y"}, spheres.values);
  });
  std::vector<uint8_t> grey(spheres.values.size());
  for (size_t i = 0; i < grey.size(); ++i) grey[i] = ToByte(0.5 * spheres.values[i]);
  output.Write("furnace_spheres.png", [&](const std::string &path) {
    WritePng(path, spheres.width, spheres.height, 1, grey);
  });
}

}  // namespace lutbake
