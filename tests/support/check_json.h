// The statuses of a `lutbake check --json` report, keyed "subject check"
// ("f82 texels", "f82+dfg at most"): "pass", "fail" or "skipped".
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>

namespace lutbake::test {

inline std::map<std::string, std::string> CheckStatuses(const std::string &jsonReport) {
  const nlohmann::json report = nlohmann::json::parse(jsonReport);
  std::map<std::string, std::string> status;
  for (const auto &r : report["checks"])
    status[std::string(r["subject"]) + " " + std::string(r["check"])] = r["status"];
  return status;
}

}  // namespace lutbake::test
