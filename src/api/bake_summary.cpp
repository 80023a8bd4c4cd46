// The text the command line prints about a bake (include/lutbake/api/bake.h):
// kept in the library so that every front end words it the same way.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "lutbake/api/bake.h"
#include "lutbake/api/names.h"

namespace lutbake {
namespace {

std::string Format(const char *format, double value) {
  char text[64];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

// How the texels were integrated: "quadrature" (every texel by the
// deterministic rule), "vndf-random 1024/texel", or both for a table that
// switched some texels to the quadrature.
std::string Method(const BakedTable &t) {
  const double texels = static_cast<double>(t.width) * t.height * t.depth;
  if (t.samples == 0 || static_cast<double>(t.quadratureTexels) >= texels) return "quadrature";
  const double mean = static_cast<double>(t.samples) / (texels - t.quadratureTexels);
  // The estimator's name: the first word of its description in the metadata.
  std::string method =
      t.estimator.substr(0, t.estimator.find_first_of(" ;")) + " " + Format("%.4g", mean);
  if (t.maxTexelSamples > static_cast<uint64_t>(mean))
    method += " (max " + Format("%.4g", static_cast<double>(t.maxTexelSamples)) + ")";
  method += "/texel";
  if (t.quadratureTexels > 0)
    method += ", " + std::to_string(t.quadratureTexels) + " by quadrature";
  return method;
}

std::string Padded(std::string text, size_t width) {
  if (text.size() < width) text.resize(width, ' ');
  return text + " ";
}

}  // namespace

std::string TableSummaryLine(const BakedTable &t) {
  if (!t.closedForm.empty())  // Favg of a scene whose materials all use Schlick
    return Padded(t.name, 17) + "closed form, no table: " + t.closedForm;
  std::string size = std::to_string(t.width) + " x " + std::to_string(t.height);
  if (t.depth > 1) size += " x " + std::to_string(t.depth);
  if (!t.storage.empty())  // a preset's texture
    return Padded(t.name, 28) + Padded(size, 14) +
           Padded(std::to_string(t.channels) + (t.channels == 1 ? " channel" : " channels"), 10) +
           Padded(t.storage, 8) + Format("%7.3f s", t.seconds) +
           Format("  error max %.2e (as stored)", t.errorMax);
  return Padded(t.name, 17) + Padded(size, 14) + Padded(Method(t), 24) +
         Format("%7.3f s", t.seconds) + Format("  error max %.2e", t.errorMax) +
         Format("  rms %.2e", t.errorRms) +
         Format("  (float32 as stored; integration %.1e)", t.integrationErrorMax);
}

std::string WrittenFilesText(const BakeResult &result, bool perFile) {
  std::string text;
  if (result.tolerance > 0.0) {
    double worst = 0.0;
    for (const BakedTable &t : result.tables) worst = std::max(worst, t.integrationErrorMax);
    text += Format("tolerance %.3g reached on every texel: ", result.tolerance) +
            Format("max integration bound %.2e, ", worst) +
            Format("%.2f s in all (the files add the rounding of their storage)\n", result.seconds);
  }
  std::vector<std::string> names;
  for (const WrittenFile &f : result.files)
    names.push_back(std::filesystem::path(f.path).filename().string());
  text += "wrote " + std::to_string(names.size()) + (names.size() == 1 ? " file" : " files") +
          " to " + result.outputDirectory + (perFile ? ":\n" : ": " + JoinNames(names) + "\n");
  for (size_t i = 0; perFile && i < names.size(); ++i) {
    const WrittenFile &f = result.files[i];
    text += "  " + Padded(names[i], 40) + Padded(f.format, 10);
    if (f.errorMax > 0.0)
      text += Format("error max %.2e", f.errorMax) + Format("  rms %.2e (as stored)", f.errorRms);
    text += "\n";
  }
  if (!result.removedFiles.empty())
    text += "removed the previous set's " + JoinNames(result.removedFiles) + "\n";
  if (!result.foreignFiles.empty())
    text += result.outputDirectory + " also holds " + std::to_string(result.foreignFiles.size()) +
            (result.foreignFiles.size() == 1 ? " file" : " files") +
            " lutbake did not write, left as they were: " + JoinNames(result.foreignFiles) + "\n";
  return text;
}

}  // namespace lutbake
