// `lutbake report`: error against run time of every estimator.
#pragma once

#include <CLI/CLI.hpp>
#include <map>
#include <string>

namespace lutbake::cli {

struct ReportOptions {
  std::string outDir;
  std::string tables = "E,dfg";
  std::string estimators = "uniform,cosine,ndf,vndf-random,vndf,adaptive,quadrature";
  std::map<std::string, std::string> models;  // --ndf, --smith
  int size = 32;
  double budget = 60;
  uint64_t seed = 0;
  int threads = 0;
  bool quiet = false;
  std::string ltcReference;
};

void SetupReportCommand(CLI::App &app, ReportOptions &options);
int RunReport(const ReportOptions &options);

}  // namespace lutbake::cli
