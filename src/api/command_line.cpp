// EquivalentCommandLine (bake.h): a request spelled as `lutbake bake`'s
// options, recorded in the files of a request that gives no command line.
#include <sstream>

#include "bake_internal.h"
#include "lutbake/api/bake.h"

namespace lutbake {

namespace {

// As a POSIX shell would need it: bare when safe, else single-quoted.
std::string Quoted(const std::string &arg) {
  if (!arg.empty() && arg.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                            "0123456789-_.,/:=+@%") == std::string::npos)
    return arg;
  std::string quoted = "'";
  for (char c : arg) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

class Line {
 public:
  void Add(const std::string &flag) { text_ += " " + flag; }
  void Add(const std::string &flag, const std::string &value) {
    text_ += " " + flag + " " + Quoted(value);
  }
  template <typename T>
  void AddNumber(const std::string &flag, T value) {
    std::ostringstream number;
    number << value;
    Add(flag, number.str());
  }
  const std::string &text() const { return text_; }

 private:
  std::string text_ = "lutbake bake";
};

void AddModels(const BakeRequest &r, Line &line) {
  if (r.ndf) line.Add("--ndf", std::string(ToString(*r.ndf)));
  if (r.smith) line.Add("--smith", std::string(ToString(*r.smith)));
  if (r.fresnel) line.Add("--fresnel", std::string(ToString(*r.fresnel)));
  if (r.sheenVisibility) line.Add("--sheen-visibility", std::string(ToString(*r.sheenVisibility)));
  if (r.sheenAlpha) line.Add("--sheen-alpha", std::string(ToString(*r.sheenAlpha)));
}

void AddSampling(const SamplingRequest &s, Line &line) {
  if (s.estimator) line.Add("--estimator", std::string(ToString(*s.estimator)));
  if (s.samples) line.AddNumber("--samples", s.samples);
  if (s.replicates) line.AddNumber("--replicates", s.replicates);
  if (s.tolerance > 0.0) line.AddNumber("--tolerance", s.tolerance);
  if (s.samplingOnly) line.Add("--sampling-only");
  if (s.maxSamples) line.AddNumber("--max-samples", *s.maxSamples);
  if (s.seed) line.AddNumber("--seed", *s.seed);
}

void AddPlan(const BakeRequest &r, Line &line) {
  if (!r.scenes.empty()) {
    line.Add("--scene");
    for (const std::string &scene : r.scenes) line.Add(Quoted(scene));
  }
  if (!r.manifests.empty()) {
    line.Add("--manifest");
    for (const std::string &manifest : r.manifests) line.Add(Quoted(manifest));
  }
  if (r.noIbl) line.Add("--no-ibl");
  if (r.noCompensation) line.Add("--no-compensation");
  if (r.skipUnsupported) line.Add("--skip-unsupported");
}

}  // namespace

std::string EquivalentCommandLine(const BakeRequest &r) {
  Line line;
  line.Add("--out", r.outputDirectory);
  if (r.tables) line.Add("--tables", JoinList(*r.tables));
  if (r.formats) line.Add("--format", JoinList(*r.formats));
  AddModels(r, line);
  if (r.size > 0) line.AddNumber("--size", r.size);
  if (r.etaSize > 0) line.AddNumber("--eta-size", r.etaSize);
  AddSampling(r.sampling, line);
  if (r.errorMaps) line.Add("--error-map");
  if (r.threads > 0) line.AddNumber("--threads", r.threads);
  if (!r.shaders.empty()) line.Add("--shader", JoinList(r.shaders));
  if (r.headerNamespace) line.Add("--namespace", *r.headerNamespace);
  if (r.headerType) line.Add("--header-type", *r.headerType);
  if (r.binType) line.Add("--bin-type", *r.binType);
  AddPlan(r, line);
  if (!r.preset.empty()) line.Add("--preset", r.preset);
  if (r.presetFiles) line.Add("--files", JoinList(*r.presetFiles));
  return line.text();
}

}  // namespace lutbake
