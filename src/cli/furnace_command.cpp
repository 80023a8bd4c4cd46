#include "furnace_command.h"

#include <tbb/global_control.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>

#include "cli_util.h"
#include "lutbake/validation/furnace_report.h"

namespace lutbake::cli {

namespace {

const std::vector<std::string> kModels = {"lambert",    "phong", "blinn-phong",
                                          "oren-nayar", "eon",   "microfacet"};

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

const std::map<std::string, ModelSpec> &Specs() {
  static const std::map<std::string, ModelSpec> specs = {
      {"lambert", {FurnaceModelKind::kLambert, "", "none", 0, 0, "0", {}, {}, "", "", false}},
      {"phong",
       {FurnaceModelKind::kPhong,
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
       {FurnaceModelKind::kBlinnPhong,
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
       {FurnaceModelKind::kOrenNayar,
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
       {FurnaceModelKind::kEon,
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
       {FurnaceModelKind::kMicrofacet,
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

}  // namespace

void SetupFurnaceCommand(CLI::App &app, FurnaceOptions &o) {
  app.add_option("--model", o.model, "The reflection model")->required()->check(OneOf(kModels));
  app.add_option("--normalisation", o.normalisation,
                 "phong: none, n+1, n+2 (default); blinn-phong: none, n+2, n+8, exact (default)");
  app.add_option("--variant", o.variant,
                 "oren-nayar: full (default), qualitative; eon: exact (default), approx, fon");
  app.add_option("--ndf", o.ndf, "microfacet: the distribution")
      ->capture_default_str()
      ->check(OneOf({"ggx", "beckmann"}));
  app.add_option("--smith", o.smith,
                 "microfacet: exact Smith (correlated, separable) or Schlick-GGX with k = alpha/2 "
                 "(schlick-ggx-ibl) or (r+1)^2/8 (schlick-ggx-direct)")
      ->capture_default_str()
      ->check(OneOf({"correlated", "separable", "schlick-ggx-ibl", "schlick-ggx-direct"}));
  app.add_option("--f0", o.f0,
                 "microfacet: Schlick Fresnel with this F0 in [0, 1] (default F = 1)");
  app.add_option("--eta", o.eta,
                 "microfacet: exact Fresnel of relative index eta in [0.001, 1000] (with --k)");
  app.add_option("--k", o.k, "microfacet with --eta: extinction coefficient in [0, 1000]");
  app.add_flag("--compensation", o.compensation,
               "microfacet: add the Kulla-Conty multiple-scattering lobe");
  app.add_option("--ms-fresnel", o.msFresnel,
                 "microfacet with --compensation: the lobe's Fresnel term, kulla-conty "
                 "(F_avg^2 E_avg / (1 - F_avg (1 - E_avg)): at least two bounces, each "
                 "through F) or single (F_avg E_avg / (1 - F_avg (1 - E_avg)))")
      ->capture_default_str()
      ->check(OneOf({"kulla-conty", "single"}));
  app.add_option("--parameter", o.parameter,
                 "The model's parameter, comma-separated: n (phong, blinn-phong), sigma in "
                 "radians (oren-nayar), r (eon, microfacet)")
      ->type_name("LIST");
  app.add_option("--mu", o.mu, "View cosines in [0, 1], comma-separated (default 0, 1/16, ..., 1)")
      ->type_name("LIST");
  app.add_option("--out", o.out,
                 "Write furnace.csv, furnace.json, furnace_plot.svg/.png and "
                 "furnace_spheres.exr/.png into DIR")
      ->type_name("DIR");
  app.add_flag("--json", o.json, "Print one JSON object instead of the table");
  AddThreadsOption(app, o.threads);
  app.footer(
      "Examples:\n"
      "  lutbake furnace --model blinn-phong --normalisation n+8 --parameter 1,10,100\n"
      "  lutbake furnace --model microfacet --parameter 1 --mu 0.5 --json\n"
      "  lutbake furnace --model microfacet --compensation --f0 0.04 --out furnace");
}

int RunFurnace(const FurnaceOptions &o, CLI::App &app) {
  const auto complain = [](const std::string &message) {
    std::cerr << "lutbake furnace: " << message << "\n";
    return 2;
  };
  const ModelSpec &spec = Specs().at(o.model);
  FurnaceSettings settings;
  FurnaceModel &m = settings.model;
  m.kind = spec.kind;
  settings.parameterName = spec.parameterName;
  settings.options.push_back({"model", o.model});

  // --normalisation and --variant: accepted values depend on the model.
  const auto choose = [&](const std::string &option, const std::string &given,
                          const std::vector<std::string> &accepted, const std::string &fallback,
                          std::string *chosen) -> int {
    if (given.empty()) {
      *chosen = fallback;
      return 0;
    }
    if (accepted.empty()) return complain("--" + option + " does not apply to --model " + o.model);
    if (std::find(accepted.begin(), accepted.end(), given) == accepted.end())
      return complain("--" + option + " '" + given + "' is not accepted for --model " + o.model +
                      "; accepted: " + JoinNames(accepted));
    *chosen = given;
    return 0;
  };
  std::string normalisation, variant;
  if (int rc = choose("normalisation", o.normalisation, spec.normalisations,
                      spec.defaultNormalisation, &normalisation))
    return rc;
  if (int rc = choose("variant", o.variant, spec.variants, spec.defaultVariant, &variant))
    return rc;
  if (!normalisation.empty()) settings.options.push_back({"normalisation", normalisation});
  if (!variant.empty()) settings.options.push_back({"variant", variant});
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

  // Microfacet options.
  for (const char *option :
       {"--ndf", "--smith", "--f0", "--eta", "--k", "--compensation", "--ms-fresnel"})
    if (!spec.microfacet && app.count(option) > 0)
      return complain(std::string(option) + " does not apply to --model " + o.model +
                      "; it applies only to --model microfacet");
  if (spec.microfacet) {
    m.ndf = o.ndf == "beckmann" ? NdfKind::kBeckmann : NdfKind::kGgx;
    const std::map<std::string, FurnaceVisibility> visibility = {
        {"correlated", FurnaceVisibility::kCorrelated},
        {"separable", FurnaceVisibility::kSeparable},
        {"schlick-ggx-ibl", FurnaceVisibility::kSchlickGgxIbl},
        {"schlick-ggx-direct", FurnaceVisibility::kSchlickGgxDirect}};
    m.visibility = visibility.at(o.smith);
    settings.options.push_back({"ndf", o.ndf});
    settings.options.push_back({"smith", o.smith});
    if (!o.f0.empty() && !o.eta.empty())
      return complain("--f0 (Schlick) and --eta (exact Fresnel) exclude each other");
    if (!o.k.empty() && o.eta.empty()) return complain("--k needs --eta");
    const auto real = [&](const std::string &option, const std::string &text, double lo, double hi,
                          const std::string &accepted, double *value) -> int {
      std::vector<double> v;
      const std::string problem = ParseList(text, &v);
      if (!problem.empty() || v.size() != 1 || v[0] < lo || v[0] > hi)
        return complain("--" + option + " '" + text + "': accepted: one number " + accepted);
      *value = v[0];
      return 0;
    };
    if (!o.f0.empty()) {
      if (int rc = real("f0", o.f0, 0.0, 1.0, "in [0, 1]", &m.f0)) return rc;
      m.fresnel = FurnaceFresnel::kSchlick;
      settings.options.push_back({"fresnel", "schlick"});
      settings.options.push_back({"f0", Format(m.f0)});
    } else if (!o.eta.empty()) {
      if (int rc = real("eta", o.eta, 1e-3, 1e3, "in [0.001, 1000]", &m.eta)) return rc;
      if (!o.k.empty())
        if (int rc = real("k", o.k, 0.0, 1e3, "in [0, 1000]", &m.k)) return rc;
      m.fresnel = FurnaceFresnel::kExact;
      settings.options.push_back({"fresnel", "exact"});
      settings.options.push_back({"eta", Format(m.eta)});
      settings.options.push_back({"k", Format(m.k)});
    } else {
      settings.options.push_back({"fresnel", "one"});
    }
    m.compensation = o.compensation;
    settings.options.push_back({"compensation", o.compensation ? "kulla-conty" : "none"});
    if (app.count("--ms-fresnel") > 0 && !o.compensation)
      return complain("--ms-fresnel '" + o.msFresnel + "' needs --compensation");
    if (o.compensation) {
      m.msFresnelSquared = o.msFresnel == "kulla-conty";
      settings.options.push_back({"msFresnel", m.msFresnelSquared
                                                   ? "F_avg^2 E_avg / (1 - F_avg (1 - E_avg))"
                                                   : "F_avg E_avg / (1 - F_avg (1 - E_avg))"});
    }
  }

  // The grids.
  if (!o.parameter.empty() && spec.parameterName.empty())
    return complain("--parameter does not apply to --model lambert (it has none)");
  const std::string parameterText = o.parameter.empty() ? spec.defaults : o.parameter;
  std::string problem = ParseList(parameterText, &settings.parameters);
  if (problem.empty())
    for (double p : settings.parameters)
      if (p < spec.lo || p > spec.hi) problem = "'" + Format(p) + "' is out of range";
  if (!problem.empty())
    return complain("--parameter: " + problem + "; accepted for --model " + o.model + ": " +
                    spec.parameterHelp + ", comma-separated");
  std::string muText = o.mu;
  if (muText.empty())
    for (int k = 0; k <= 16; ++k) muText += (k ? "," : "") + Format(k / 16.0);
  problem = ParseList(muText, &settings.mus);
  if (problem.empty())
    for (double mu : settings.mus)
      if (mu < 0.0 || mu > 1.0) problem = "'" + Format(mu) + "' is out of range";
  if (!problem.empty())
    return complain("--mu: " + problem + "; accepted: view cosines in [0, 1], comma-separated");

  if (!o.out.empty()) {
    bool created = false;
    if (int rc = PrepareOutputOrComplain("furnace", o.out, &created)) return rc;
  }
  settings.pictures = !o.out.empty();
  tbb::global_control parallelism(tbb::global_control::max_allowed_parallelism,
                                  static_cast<size_t>(ThreadCount(o.threads)));
  const FurnaceResult result = lutbake::RunFurnace(settings);
  if (!o.out.empty()) WriteFurnaceFiles(o.out, settings, result);

  if (o.json) {
    std::cout << FurnaceJson(settings, result);
    return 0;
  }
  std::printf("white furnace of %s", o.model.c_str());
  for (size_t i = 1; i < settings.options.size(); ++i)
    std::printf(", %s %s", settings.options[i].first.c_str(), settings.options[i].second.c_str());
  std::printf("\n%12s %10s %20s %10s\n",
              spec.parameterName.empty() ? "-" : spec.parameterName.c_str(), "mu", "albedo",
              "error");
  for (const FurnaceEntry &e : result.albedo)
    std::printf("%12.6g %10.6g %20.15f %10.2e\n", e.parameter, e.mu, e.point.albedo.value,
                e.point.albedo.error);
  std::printf("average 2 int albedo mu dmu:\n");
  for (size_t p = 0; p < settings.parameters.size(); ++p)
    std::printf("%12.6g %31.15f %10.2e\n", settings.parameters[p], result.average[p].value,
                result.average[p].error);
  const char *parameterName = spec.parameterName.empty() ? "-" : spec.parameterName.c_str();
  const auto extreme = [&](const char *what, const FurnaceExtreme &x, const char *none) {
    if (x.amount > x.error)
      std::printf("worst %s %.6g +- %.2g at (%s, mu) = (%.6g, %.6g)", what, x.amount, x.error,
                  parameterName, x.parameter, x.mu);
    else if (x.amount > 0.0)
      std::printf("no %s beyond the stated error (at most %.2g, error %.2g)", what, x.amount,
                  x.error);
    else
      std::printf("no %s (%s)", what, none);
  };
  extreme("gain", result.gain, "the albedo is never above 1");
  std::printf("; ");
  extreme("loss", result.loss, "the albedo is never below 1");
  std::printf("\n");
  if (!o.out.empty())
    std::printf("wrote %s/furnace.{csv,json}, plots and sphere images\n", o.out.c_str());
  return 0;
}

}  // namespace lutbake::cli
