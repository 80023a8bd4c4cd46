// `lutbake check` on fitted closed forms (fit_check.h): a shipped fit passes,
// and the same file with one coefficient changed, with T_max_error lowered
// below what the fit reaches, or with T_coefficients off fails.
#include "lutbake/validation/fit_check.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "lutbake/formats/fit_format.h"
#include "support/small_tables.h"

namespace lutbake {
namespace {

namespace fs = std::filesystem;

std::string Text(const fs::path &path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// A directory holding f82_fit.h as shipped, with `edit` applied.
fs::path Directory(const std::string &name, const std::function<void(std::string *)> &edit) {
  const fs::path dir = test::FormatTempDir("fit_check_" + name);
  std::string text = Text(std::string(LUTBAKE_TEST_DATA) + "/fits/f82_fit.h");
  edit(&text);
  std::ofstream(dir / "f82_fit.h") << text;
  return dir;
}

CheckOptions Options() {
  CheckOptions o;
  o.randomPoints = 64;
  return o;
}

const CheckResult *FitResult(const CheckReport &report) {
  for (const CheckResult &r : report.results)
    if (r.check == "fit") return &r;
  return nullptr;
}

TEST(FitCheck, ShippedFitPasses) {
  const CheckReport report =
      CheckBakedSet(Directory("good", [](std::string *) {}).string(), Options());
  const CheckResult *r = FitResult(report);
  ASSERT_NE(r, nullptr);
  EXPECT_EQ(r->status, CheckStatus::kPass) << r->detail;
  EXPECT_TRUE(report.passed());
  EXPECT_GT(r->worst, 0.0);
  EXPECT_LE(r->worst, r->allowed);
}

TEST(FitCheck, OneCoefficientChangedFails) {
  const fs::path dir = Directory("coefficient", [](std::string *text) {
    // The leading coefficient of the first patch (its mean), moved by 0.002.
    const size_t at = text->find("\n", text->find("// lutbake-fit-coefficients-begin")) + 1;
    const size_t end = text->find("f,", at);
    const double v = std::strtod(text->substr(at, end - at).c_str(), nullptr);
    char moved[40];
    std::snprintf(moved, sizeof moved, "%.9g", v + 0.002);
    text->replace(at, end - at, moved);
  });
  EXPECT_NE(ReadFitSource((dir / "f82_fit.h").string()).fit.coefficients,
            ReadFitSource(std::string(LUTBAKE_TEST_DATA) + "/fits/f82_fit.h").fit.coefficients);
  const CheckReport report = CheckBakedSet(dir.string(), Options());
  const CheckResult *r = FitResult(report);
  ASSERT_NE(r, nullptr);
  EXPECT_EQ(r->status, CheckStatus::kFail) << r->detail;
  EXPECT_FALSE(report.passed());
}

TEST(FitCheck, OverstatedBoundAndWrongCountFail) {
  const FitSource shipped = ReadFitSource(std::string(LUTBAKE_TEST_DATA) + "/fits/f82_fit.h");
  const fs::path tight = Directory("bound", [&](std::string *text) {
    const size_t at = text->find("f82_max_error = ") + 16;
    text->replace(at, text->find(';', at) - at, "1e-6");
  });
  const CheckResult *r = FitResult(CheckBakedSet(tight.string(), Options()));
  ASSERT_NE(r, nullptr);
  EXPECT_EQ(r->status, CheckStatus::kFail) << r->detail;
  const fs::path count = Directory("count", [&](std::string *text) {
    const size_t at = text->find("f82_coefficients = ") + 19;
    text->replace(at, text->find(';', at) - at, std::to_string(shipped.coefficients - 1));
  });
  r = FitResult(CheckBakedSet(count.string(), Options()));
  ASSERT_NE(r, nullptr);
  EXPECT_EQ(r->status, CheckStatus::kFail) << r->detail;
}

}  // namespace
}  // namespace lutbake
