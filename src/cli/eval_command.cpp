#include "eval_command.h"

#include <cstdlib>
#include <iostream>

#include "bake_command.h"
#include "cli_util.h"
#include "lutbake/api/eval.h"

namespace lutbake::cli {

namespace {

// A comma-separated list of reals, each finite and in the option's widest
// range (each table narrows it further: lutbake::Evaluate says so).
CLI::Validator RealList(const EvalCoordinateOption &o) {
  return CLI::Validator(
      [o](std::string &value) -> std::string {
        const std::vector<std::string> items = SplitList(value);
        if (items.empty()) return "empty list; accepted: " + o.accepted;
        if (items.size() > kMaxEvalPoints)
          return std::to_string(items.size()) + " values; accepted: at most " +
                 std::to_string(kMaxEvalPoints);
        for (const std::string &item : items)
          if (std::string problem =
                  RealNumberProblem(item, o.zeroAllowed ? 0.0 : o.min, o.max, o.accepted);
              !problem.empty())
            return problem;
        return {};
      },
      o.accepted);
}

// The request the options describe; `app` tells which options were given.
EvalRequest RequestOf(const EvalOptions &o, CLI::App &app) {
  EvalRequest r;
  r.table = o.table;
  for (const auto &[option, text] : o.coordinates) {
    if (text.empty()) continue;
    r.spelling[option] = SplitList(text);
    for (const std::string &item : r.spelling[option])
      r.coordinates[option].push_back(std::strtod(item.c_str(), nullptr));
  }
  ModelsOf(o.models, app, &r);
  r.sampling = SamplingRequestOf(o.sampling, app);
  r.threads = o.threads;
  return r;
}

}  // namespace

void SetupEvalCommand(CLI::App &app, EvalOptions &o) {
  app.add_option("--table", o.table, "The table to evaluate")
      ->required()
      ->check(OneOf(TableNames()));
  // The coordinates, from the table definitions: each option's widest range
  // here; each table narrows it (its PointCoordinate), and says so.
  for (const EvalCoordinateOption &c : EvalCoordinateOptions())
    app.add_option("--" + c.option, o.coordinates[c.option],
                   c.meaning + ", comma-separated; tables " + JoinNames(c.tables))
        ->type_name("LIST")
        ->check(RealList(c));
  AddModelOptions(app, o.models);
  AddSamplingOptions(app, o.sampling, "point");
  AddThreadsOption(app, o.threads);
  app.add_flag("--json", o.json,
               "One JSON object per point and line: table, the coordinates, value, error "
               "(value and error are [A, B] for dfg), estimator, samples");
  app.add_flag("-v,--verbose", o.verbose, "Also say how the values are made (on stderr)");
  app.footer(
      "Without --samples, --tolerance or --estimator the points are integrated by the\n"
      "quadrature (error ~1e-10). --samples N (or --estimator vndf) evaluates them as a bake\n"
      "does: at a texel centre, with the bake's settings and seed, the value is that texel's.\n"
      "Examples:\n"
      "  lutbake eval --table E --mu 1e-7,0.5 --roughness 0,1e-4,0.3\n"
      "  lutbake eval --table dfg --mu 0 --roughness 0.5 --samples 65536 --json\n"
      "  lutbake eval --table Favg --fresnel conductor --eta 0.2 --k 3,10\n"
      "  lutbake eval --table Favg --fresnel f82 --f0 0.9 --tint 0.8\n"
      "  lutbake eval --table f82 --mu 0.5 --roughness 0.3");
}

int RunEval(const EvalOptions &o, CLI::App &app) {
  const EvalRequest request = RequestOf(o, app);
  return RunLibraryCall("eval", "", [&] {
    const EvalResult result = Evaluate(request);
    if (o.verbose) std::cerr << "lutbake eval: " << result.method << "\n";
    for (size_t i = 0; i < result.points.size(); ++i)
      std::cout << (o.json ? result.JsonLine(i) + "\n" : result.TextLine(i));
  });
}

}  // namespace lutbake::cli
