// lutbake::Furnace: the request's checks in the order the command line has
// always made them (normalisation and variant, the microfacet options, the
// grids, the output directory), the furnace, its files and its summary.
#include "lutbake/api/furnace.h"

#include <tbb/global_control.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>

#include "bake_internal.h"
#include "lutbake/api/names.h"
#include "lutbake/core/error.h"
#include "lutbake/formats/output_transaction.h"

namespace lutbake {

namespace {

// Per model: the parameter's name, range, default grid, and which of the
// model options apply.
struct ModelSpec {
  FurnaceModelKind kind;
  std::string parameterName, parameterHelp;
  double lo, hi;
  std::string defaults;
  std::vector<std::string> normalisations, variants;
  std::string defaultNormalisation, defaultVariant;
  bool microfacet;
};

const std::vector<std::pair<std::string, ModelSpec>> &Specs() {
  using K = FurnaceModelKind;
  static const std::vector<std::pair<std::string, ModelSpec>> specs = {
      {"lambert", {K::kLambert, "", "none", 0, 0, "0", {}, {}, "", "", false}},
      {"phong",
       {K::kPhong,
        "n",
        "the exponent n in [0, 100000]",
        0,
        1e5,
        "1,4,16,64,256",
        {"none", "n+1", "n+2"},
        {},
        "n+2",
        "",
        false}},
      {"blinn-phong",
       {K::kBlinnPhong,
        "n",
        "the exponent n in [0, 100000]",
        0,
        1e5,
        "1,4,16,64,256",
        {"none", "n+2", "n+8", "exact"},
        {},
        "exact",
        "",
        false}},
      {"oren-nayar",
       {K::kOrenNayar,
        "sigma",
        "sigma in radians in [0, pi/2]",
        0,
        kPi / 2,
        "0,0.25,0.5,1,1.5",
        {},
        {"full", "qualitative"},
        "",
        "full",
        false}},
      {"eon",
       {K::kEon,
        "r",
        "the roughness r in [0, 1]",
        0,
        1,
        "0,0.25,0.5,0.75,1",
        {},
        {"exact", "approx", "fon"},
        "",
        "exact",
        false}},
      {"microfacet",
       {K::kMicrofacet,
        "r",
        "the perceptual roughness r in [0, 1] (alpha = r^2)",
        0,
        1,
        "0.1,0.25,0.5,0.75,1",
        {},
        {},
        "",
        "",
        true}},
  };
  return specs;
}

std::vector<std::string> SplitList(const std::string &list) {
  std::vector<std::string> items;
  size_t start = 0;
  if (list.empty()) return items;
  for (size_t comma; (comma = list.find(',', start)) != std::string::npos; start = comma + 1)
    items.push_back(list.substr(start, comma - start));
  items.push_back(list.substr(start));
  return items;
}

// Parses a comma-separated list of finite reals; "" on success, else the reason.
std::string ParseList(const std::string &text, std::vector<double> *values) {
  values->clear();
  const std::vector<std::string> items = SplitList(text);
  if (items.empty()) return "empty list";
  if (items.size() > 10000) return std::to_string(items.size()) + " values (at most 10000)";
  for (const std::string &item : items) {
    char *end = nullptr;
    errno = 0;
    const double v = std::strtod(item.c_str(), &end);
    if (item.empty() || end != item.c_str() + item.size() || !std::isfinite(v) || errno == ERANGE)
      return "'" + item + "' is not a number";
    values->push_back(v);
  }
  return {};
}

std::string Format(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.10g", v);
  return buffer;
}

// `given` checked against the names a closed option accepts.
const std::string &OneOf(const std::string &option, const std::string &given,
                         const std::vector<std::string> &accepted) {
  if (std::find(accepted.begin(), accepted.end(), given) == accepted.end())
    throw UsageError("--" + option + " '" + given +
                     "' is not accepted; accepted: " + JoinNames(accepted));
  return given;
}

// --normalisation and --variant: the accepted values depend on the model.
std::string Choose(const std::string &model, const std::string &option, const std::string &given,
                   const std::vector<std::string> &accepted, const std::string &fallback) {
  if (given.empty()) return fallback;
  if (accepted.empty()) throw UsageError("--" + option + " does not apply to --model " + model);
  if (std::find(accepted.begin(), accepted.end(), given) == accepted.end())
    throw UsageError("--" + option + " '" + given + "' is not accepted for --model " + model +
                     "; accepted: " + JoinNames(accepted));
  return given;
}

void ApplyNormalisationAndVariant(const FurnaceRequest &r, const ModelSpec &spec,
                                  FurnaceSettings *settings) {
  const std::string normalisation = Choose(r.model, "normalisation", r.normalisation,
                                           spec.normalisations, spec.defaultNormalisation);
  const std::string variant =
      Choose(r.model, "variant", r.variant, spec.variants, spec.defaultVariant);
  if (!normalisation.empty()) settings->options.push_back({"normalisation", normalisation});
  if (!variant.empty()) settings->options.push_back({"variant", variant});
  FurnaceModel &m = settings->model;
  if (normalisation == "none") m.phong = PhongNormalisation::kNone;
  if (normalisation == "n+1") m.phong = PhongNormalisation::kNPlus1;
  if (normalisation == "n+2") m.phong = PhongNormalisation::kNPlus2;
  m.blinnPhong = normalisation == "none"  ? BlinnPhongNormalisation::kNone
                 : normalisation == "n+2" ? BlinnPhongNormalisation::kNPlus2
                 : normalisation == "n+8" ? BlinnPhongNormalisation::kNPlus8
                                          : BlinnPhongNormalisation::kExact;
  m.orenNayar = variant == "qualitative" ? OrenNayarVariant::kQualitative : OrenNayarVariant::kFull;
  m.eon = variant == "approx" ? EonVariant::kApprox
          : variant == "fon"  ? EonVariant::kFon
                              : EonVariant::kExact;
}

// One number of an option in [lo, hi].
double OneNumber(const std::string &option, const std::string &text, double lo, double hi,
                 const std::string &accepted) {
  std::vector<double> v;
  const std::string problem = ParseList(text, &v);
  if (!problem.empty() || v.size() != 1 || v[0] < lo || v[0] > hi)
    throw UsageError("--" + option + " '" + text + "': accepted: one number " + accepted);
  return v[0];
}

void ApplyFresnel(const FurnaceRequest &r, FurnaceSettings *settings) {
  FurnaceModel &m = settings->model;
  const std::string f0 = r.f0.value_or(""), eta = r.eta.value_or(""), k = r.k.value_or("");
  if (!f0.empty() && !eta.empty())
    throw UsageError("--f0 (Schlick) and --eta (exact Fresnel) exclude each other");
  if (!k.empty() && eta.empty()) throw UsageError("--k needs --eta");
  if (!f0.empty()) {
    m.f0 = OneNumber("f0", f0, 0.0, 1.0, "in [0, 1]");
    m.fresnel = FurnaceFresnel::kSchlick;
    settings->options.push_back({"fresnel", "schlick"});
    settings->options.push_back({"f0", Format(m.f0)});
  } else if (!eta.empty()) {
    m.eta = OneNumber("eta", eta, 1e-3, 1e3, "in [0.001, 1000]");
    if (!k.empty()) m.k = OneNumber("k", k, 0.0, 1e3, "in [0, 1000]");
    m.fresnel = FurnaceFresnel::kExact;
    settings->options.push_back({"fresnel", "exact"});
    settings->options.push_back({"eta", Format(m.eta)});
    settings->options.push_back({"k", Format(m.k)});
  } else {
    settings->options.push_back({"fresnel", "one"});
  }
}

void ApplyMicrofacetOptions(const FurnaceRequest &r, const ModelSpec &spec,
                            FurnaceSettings *settings) {
  const std::pair<const char *, bool> given[] = {{"--ndf", r.ndf.has_value()},
                                                 {"--smith", r.smith.has_value()},
                                                 {"--f0", r.f0.has_value()},
                                                 {"--eta", r.eta.has_value()},
                                                 {"--k", r.k.has_value()},
                                                 {"--compensation", r.compensation.has_value()},
                                                 {"--ms-fresnel", r.msFresnel.has_value()}};
  for (const auto &[option, set] : given)
    if (!spec.microfacet && set)
      throw UsageError(std::string(option) + " does not apply to --model " + r.model +
                       "; it applies only to --model microfacet");
  if (!spec.microfacet) return;
  FurnaceModel &m = settings->model;
  const std::string ndf = OneOf("ndf", r.ndf.value_or("ggx"), {"ggx", "beckmann"});
  const std::string smith = r.smith.value_or("correlated");
  const std::map<std::string, FurnaceVisibility> visibility = {
      {"correlated", FurnaceVisibility::kCorrelated},
      {"separable", FurnaceVisibility::kSeparable},
      {"schlick-ggx-ibl", FurnaceVisibility::kSchlickGgxIbl},
      {"schlick-ggx-direct", FurnaceVisibility::kSchlickGgxDirect}};
  OneOf("smith", smith, {"correlated", "separable", "schlick-ggx-ibl", "schlick-ggx-direct"});
  m.ndf = ndf == "beckmann" ? NdfKind::kBeckmann : NdfKind::kGgx;
  m.visibility = visibility.at(smith);
  settings->options.push_back({"ndf", ndf});
  settings->options.push_back({"smith", smith});
  ApplyFresnel(r, settings);
  const bool compensation = r.compensation.value_or(false);
  const std::string msFresnel =
      OneOf("ms-fresnel", r.msFresnel.value_or("kulla-conty"), {"kulla-conty", "single"});
  m.compensation = compensation;
  settings->options.push_back({"compensation", compensation ? "kulla-conty" : "none"});
  if (r.msFresnel && !compensation)
    throw UsageError("--ms-fresnel '" + msFresnel + "' needs --compensation");
  if (compensation) {
    m.msFresnelSquared = msFresnel == "kulla-conty";
    settings->options.push_back({"msFresnel", m.msFresnelSquared
                                                  ? "F_avg^2 E_avg / (1 - F_avg (1 - E_avg))"
                                                  : "F_avg E_avg / (1 - F_avg (1 - E_avg))"});
  }
}

void ApplyGrids(const FurnaceRequest &r, const ModelSpec &spec, FurnaceSettings *settings) {
  if (!r.parameters.empty() && spec.parameterName.empty())
    throw UsageError("--parameter does not apply to --model lambert (it has none)");
  std::string problem =
      ParseList(r.parameters.empty() ? spec.defaults : r.parameters, &settings->parameters);
  if (problem.empty())
    for (double p : settings->parameters)
      if (p < spec.lo || p > spec.hi) problem = "'" + Format(p) + "' is out of range";
  if (!problem.empty())
    throw UsageError("--parameter: " + problem + "; accepted for --model " + r.model + ": " +
                     spec.parameterHelp + ", comma-separated");
  std::string mus = r.mus;
  if (mus.empty())
    for (int k = 0; k <= 16; ++k) mus += (k ? "," : "") + Format(k / 16.0);
  problem = ParseList(mus, &settings->mus);
  if (problem.empty())
    for (double mu : settings->mus)
      if (mu < 0.0 || mu > 1.0) problem = "'" + Format(mu) + "' is out of range";
  if (!problem.empty())
    throw UsageError("--mu: " + problem + "; accepted: view cosines in [0, 1], comma-separated");
}

// The table `furnace` prints: every (parameter, mu), the averages, the
// worst gain and loss.
std::string FurnaceText(const FurnaceRequest &r, const FurnaceSettings &settings,
                        const FurnaceResult &result) {
  std::string text = "white furnace of " + r.model;
  for (size_t i = 1; i < settings.options.size(); ++i)
    text += ", " + settings.options[i].first + " " + settings.options[i].second;
  char line[400];
  const char *parameterName = settings.parameterName.empty() ? "-" : settings.parameterName.c_str();
  std::snprintf(line, sizeof line, "\n%12s %10s %20s %10s\n", parameterName, "mu", "albedo",
                "error");
  text += line;
  for (const FurnaceEntry &e : result.albedo) {
    std::snprintf(line, sizeof line, "%12.6g %10.6g %20.15f %10.2e\n", e.parameter, e.mu,
                  e.point.albedo.value, e.point.albedo.error);
    text += line;
  }
  text += "average 2 int albedo mu dmu:\n";
  for (size_t p = 0; p < settings.parameters.size(); ++p) {
    std::snprintf(line, sizeof line, "%12.6g %31.15f %10.2e\n", settings.parameters[p],
                  result.average[p].value, result.average[p].error);
    text += line;
  }
  const auto extreme = [&](const char *what, const FurnaceExtreme &x, const char *none) {
    if (x.amount > x.error)
      std::snprintf(line, sizeof line, "worst %s %.6g +- %.2g at (%s, mu) = (%.6g, %.6g)", what,
                    x.amount, x.error, parameterName, x.parameter, x.mu);
    else if (x.amount > 0.0)
      std::snprintf(line, sizeof line, "no %s beyond the stated error (at most %.2g, error %.2g)",
                    what, x.amount, x.error);
    else
      std::snprintf(line, sizeof line, "no %s (%s)", what, none);
    return std::string(line);
  };
  text += extreme("gain", result.gain, "the albedo is never above 1") + "; " +
          extreme("loss", result.loss, "the albedo is never below 1") + "\n";
  if (!r.outputDirectory.empty())
    text += "wrote " + r.outputDirectory + "/furnace.{csv,json}, plots and sphere images\n";
  return text;
}

}  // namespace

std::vector<std::string> FurnaceModelNames() {
  std::vector<std::string> names;
  for (const auto &entry : Specs()) names.push_back(entry.first);
  return names;
}

FurnaceOutcome Furnace(const FurnaceRequest &r) {
  OneOf("model", r.model, FurnaceModelNames());
  const ModelSpec &spec = std::find_if(Specs().begin(), Specs().end(), [&](const auto &e) {
                            return e.first == r.model;
                          })->second;
  FurnaceOutcome outcome;
  FurnaceSettings &settings = outcome.settings;
  settings.model.kind = spec.kind;
  settings.parameterName = spec.parameterName;
  settings.options.push_back({"model", r.model});
  ApplyNormalisationAndVariant(r, spec, &settings);
  ApplyMicrofacetOptions(r, spec, &settings);
  ApplyGrids(r, spec, &settings);

  std::unique_ptr<OutputTransaction> output;
  if (!r.outputDirectory.empty()) output = std::make_unique<OutputTransaction>(r.outputDirectory);
  settings.pictures = output != nullptr;
  {
    tbb::global_control parallelism(tbb::global_control::max_allowed_parallelism,
                                    static_cast<size_t>(ThreadCount(r.threads)));
    outcome.result = RunFurnace(settings);
  }
  if (output) {
    WriteFurnaceFiles(*output, settings, outcome.result);
    output->Commit();
    outcome.files = output->files();
  }
  outcome.json = FurnaceJson(settings, outcome.result);
  outcome.text = FurnaceText(r, settings, outcome.result);
  return outcome;
}

}  // namespace lutbake
