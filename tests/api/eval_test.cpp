// lutbake::Evaluate: values against closed forms, the order of the points,
// independence of the thread count, and the refusals `lutbake eval` prints.
#include "lutbake/api/eval.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "lutbake/core/error.h"

namespace lutbake {
namespace {

std::string UsageMessage(const EvalRequest &request) {
  try {
    Evaluate(request);
  } catch (const UsageError &e) {
    return e.what();
  }
  return "(no UsageError)";
}

TEST(EvalApi, TheMirrorIsExact) {
  // alpha = 0: the mirror reflects everything (E = 1, F = 1), and the
  // split sum of Schlick's F is A = 1 - (1 - mu)^5, B = (1 - mu)^5.
  EvalRequest request;
  request.table = "dfg";
  request.coordinates = {{"mu", {0.2, 0.5}}, {"roughness", {0.0}}};
  const EvalResult result = Evaluate(request);
  ASSERT_EQ(result.points.size(), 2u);
  EXPECT_EQ(result.coordinateNames, (std::vector<std::string>{"mu", "roughness"}));
  ASSERT_EQ(result.channelMeanings.size(), 2u);
  for (const EvalPoint &p : result.points) {
    const double mu = p.coordinates[0];
    ASSERT_EQ(p.values.size(), 2u);
    EXPECT_NEAR(p.values[0], 1.0 - std::pow(1.0 - mu, 5), 1e-15);
    EXPECT_NEAR(p.values[1], std::pow(1.0 - mu, 5), 1e-15);
    EXPECT_EQ(p.estimator, "exact");
    EXPECT_EQ(p.errors[0], 0.0);
  }
  request.table = "E";
  for (const EvalPoint &p : Evaluate(request).points) EXPECT_EQ(p.values[0], 1.0);
}

TEST(EvalApi, PointsAreRowMajorAndDoNotDependOnThreads) {
  EvalRequest request;
  request.table = "E";
  request.coordinates = {{"mu", {0.1, 0.6, 0.9}}, {"roughness", {0.2, 0.7}}};
  request.threads = 1;
  const EvalResult one = Evaluate(request);
  request.threads = 4;
  const EvalResult four = Evaluate(request);
  ASSERT_EQ(one.points.size(), 6u);
  for (size_t i = 0; i < 6; ++i) {
    // mu inner, roughness outer.
    EXPECT_EQ(one.points[i].coordinates[0], request.coordinates["mu"][i % 3]);
    EXPECT_EQ(one.points[i].coordinates[1], request.coordinates["roughness"][i / 3]);
    EXPECT_EQ(one.points[i].values[0], four.points[i].values[0]);  // bit for bit
    EXPECT_EQ(one.points[i].estimator, "quadrature");
    // A directional albedo without Fresnel: in (0, 1], within its bound.
    EXPECT_GT(one.points[i].values[0], 0.0);
    EXPECT_LE(one.points[i].values[0], 1.0 + one.points[i].errors[0]);
    EXPECT_LT(one.points[i].errors[0], 1e-8);
  }
  // The JSON line holds what the point holds.
  const nlohmann::json line = nlohmann::json::parse(one.JsonLine(4));
  EXPECT_EQ(line["table"], "E");
  EXPECT_EQ(line["mu"].get<double>(), 0.6);
  EXPECT_EQ(line["roughness"].get<double>(), 0.7);
  EXPECT_EQ(line["value"].get<double>(), one.points[4].values[0]);
  EXPECT_EQ(line["estimator"], "quadrature");
}

TEST(EvalApi, RefusesWhatTheTableDoesNotTake) {
  EvalRequest request;
  request.table = "E";
  request.coordinates = {{"mu", {0.5}}};
  EXPECT_EQ(UsageMessage(request), "--table E needs --roughness");
  request.coordinates["roughness"] = {0.3};
  request.fresnel = FresnelModel::kDielectric;
  EXPECT_EQ(UsageMessage(request), "--fresnel does not apply to --table E");
  request.fresnel.reset();
  request.coordinates["sigma"] = {0.2};
  EXPECT_NE(UsageMessage(request).find("--sigma does not apply to --table E; it applies only to "
                                       "--table oren_nayar_E"),
            std::string::npos);
  request.coordinates.erase("sigma");
  request.coordinates["roughness"] = {1.5};
  request.spelling["roughness"] = {"1.50"};
  EXPECT_EQ(UsageMessage(request).rfind("--roughness: '1.50' is out of range for --table E", 0), 0u)
      << UsageMessage(request);
  request.spelling.clear();  // quoted as the shortest decimal
  EXPECT_EQ(UsageMessage(request).rfind("--roughness: '1.5' is out of range for --table E", 0), 0u);
  request.coordinates["roughness"] = {0.3};
  request.sampling.samplingOnly = true;
  EXPECT_EQ(UsageMessage(request), "--sampling-only and --max-samples apply only with --tolerance");
  request.sampling = {};
  request.table = "nope";
  EXPECT_EQ(UsageMessage(request).rfind("--table 'nope' is not accepted; accepted: E, Eavg", 0),
            0u);
}

TEST(EvalApi, RefusesMoreThanAMillionPoints) {
  EvalRequest request;
  request.table = "E";
  request.coordinates["mu"] = std::vector<double>(1001, 0.5);
  request.coordinates["roughness"] = std::vector<double>(1000, 0.5);
  EXPECT_EQ(UsageMessage(request),
            "1001000 points (--mu x --roughness); accepted: at most 1000000");
}

const ModelOption &ModelOptionNamed(const std::vector<ModelOption> &options,
                                    const std::string &name) {
  for (const ModelOption &o : options)
    if (o.option == name) return o;
  throw std::runtime_error("no model option " + name);
}

TEST(EvalApi, ModelOptionsCoverEveryTablesModelAndNameItsUsers) {
  const std::vector<ModelOption> options = ModelOptions();
  std::vector<std::string> names;
  for (const ModelOption &o : options) names.push_back(o.option);
  EXPECT_EQ(names, (std::vector<std::string>{"ndf", "smith", "fresnel", "sheen-visibility",
                                             "sheen-alpha"}));
  // Every option a table's model part takes is one of them, and lists it.
  for (const TableDefinition *table : AllTables())
    for (const std::string &option : table->ModelOptions()) {
      const std::vector<std::string> &users = ModelOptionNamed(options, option).tables;
      EXPECT_NE(std::find(users.begin(), users.end(), table->Name()), users.end())
          << option << " does not list " << table->Name();
    }
  EXPECT_EQ(ModelOptionNamed(options, "fresnel").tables, std::vector<std::string>{"Favg"});
  const std::vector<std::string> &ndfUsers = ModelOptionNamed(options, "ndf").tables;
  EXPECT_EQ(std::count(ndfUsers.begin(), ndfUsers.end(), "sheen_E"), 0);
  EXPECT_EQ(std::count(ndfUsers.begin(), ndfUsers.end(), "dfg"), 1);
  const ModelOption &visibility = ModelOptionNamed(options, "sheen-visibility");
  EXPECT_EQ(visibility.accepted, (std::vector<std::string>{"charlie", "ashikhmin", "ospray"}));
  EXPECT_EQ(visibility.defaultValue, "charlie");
  EXPECT_EQ(ModelOptionNamed(options, "sheen-alpha").accepted,
            (std::vector<std::string>{"linear", "squared"}));
}

TEST(EvalApi, ModelsNamedReadsEveryAcceptedValueBack) {
  for (const ModelOption &o : ModelOptions())
    for (const std::string &value : o.accepted) {
      const ModelChoice c = ModelsNamed({{o.option, value}});
      // Exactly the one field is set, to the model of that name.
      const int set = c.ndf.has_value() + c.smith.has_value() + c.fresnel.has_value() +
                      c.sheenVisibility.has_value() + c.sheenAlpha.has_value();
      EXPECT_EQ(set, 1) << o.option << " " << value;
      const std::string read = c.ndf               ? std::string(ToString(*c.ndf))
                               : c.smith           ? std::string(ToString(*c.smith))
                               : c.fresnel         ? std::string(ToString(*c.fresnel))
                               : c.sheenVisibility ? std::string(ToString(*c.sheenVisibility))
                               : c.sheenAlpha      ? std::string(ToString(*c.sheenAlpha))
                                                   : "";
      EXPECT_EQ(read, value) << o.option;
    }
  // A model chosen this way reaches the evaluation: Beckmann's E differs from GGX's.
  EvalRequest request;
  request.table = "E";
  request.coordinates = {{"mu", {0.5}}, {"roughness", {0.5}}};
  const double ggx = Evaluate(request).points[0].values[0];
  ModelsNamed({{"ndf", "beckmann"}}).SetIn(&request);
  EXPECT_GT(std::abs(Evaluate(request).points[0].values[0] - ggx), 1e-4);
}

TEST(EvalApi, ModelsNamedRefusesUnknownOptionsAndValues) {
  const auto message = [](const std::map<std::string, std::string> &values) -> std::string {
    try {
      ModelsNamed(values);
    } catch (const UsageError &e) {
      return e.what();
    }
    return "(no UsageError)";
  };
  EXPECT_EQ(message({{"ndf", "GGX"}}), "--ndf: 'GGX' is not accepted; accepted: ggx, beckmann");
  EXPECT_EQ(message({{"nfd", "ggx"}}),
            "--nfd is not a model option; accepted: ndf, smith, fresnel, sheen-visibility, "
            "sheen-alpha");
}

}  // namespace
}  // namespace lutbake
