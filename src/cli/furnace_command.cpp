#include "furnace_command.h"

#include <iostream>

#include "cli_util.h"
#include "lutbake/api/furnace.h"

namespace lutbake::cli {

void SetupFurnaceCommand(CLI::App &app, FurnaceOptions &o) {
  app.add_option("--model", o.model, "The reflection model")
      ->required()
      ->check(OneOf(FurnaceModelNames()));
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
  app.add_option("-o,--out", o.out,
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
  const auto given = [&app](const char *flag) { return app.count(flag) > 0; };
  FurnaceRequest r;
  r.model = o.model;
  r.normalisation = o.normalisation;
  r.variant = o.variant;
  if (given("--ndf")) r.ndf = o.ndf;
  if (given("--smith")) r.smith = o.smith;
  if (given("--f0")) r.f0 = o.f0;
  if (given("--eta")) r.eta = o.eta;
  if (given("--k")) r.k = o.k;
  if (given("--compensation")) r.compensation = o.compensation;
  if (given("--ms-fresnel")) r.msFresnel = o.msFresnel;
  r.parameters = o.parameter;
  r.mus = o.mu;
  r.outputDirectory = o.out;
  r.threads = o.threads;
  return RunLibraryCall("furnace", o.out, [&] {
    const FurnaceOutcome outcome = Furnace(r);
    std::cout << (o.json ? outcome.json : outcome.text);
  });
}

}  // namespace lutbake::cli
