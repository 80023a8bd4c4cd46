// The bake's printed summary (TableSummaryLine, WrittenFilesText): the
// columns line up across tables of different names and sizes, the method
// says what integrated the table (never "0 samples" for the quadrature),
// and the list of files is exactly the directory's content.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "lutbake/api/bake.h"
#include "support/cli_run.h"

namespace lutbake {
namespace {

namespace fs = std::filesystem;

TEST(BakeSummary, ColumnsLineUpAndTheMethodIsNamed) {
  const fs::path dir = test::Scratch("bake_summary_columns");
  BakeRequest request;
  request.tables = {"E", "Eavg", "glass_E", "oren_nayar_full_E"};
  request.formats = {"exr"};
  request.size = 6;
  request.etaSize = 3;
  request.outputDirectory = dir.string();
  const BakeResult result = Bake(request);
  ASSERT_EQ(result.tables.size(), 4u);
  size_t column = std::string::npos;
  for (const BakedTable &t : result.tables) {
    const std::string line = TableSummaryLine(t);
    EXPECT_EQ(line.rfind(t.name + " ", 0), 0u) << line;
    EXPECT_NE(line.find("quadrature"), std::string::npos) << line;
    EXPECT_EQ(line.find("samples"), std::string::npos) << line;
    const size_t at = line.find("error max");
    ASSERT_NE(at, std::string::npos) << line;
    if (column == std::string::npos) column = at;
    EXPECT_EQ(at, column) << line;
  }
  EXPECT_NE(TableSummaryLine(result.tables[2]).find("6 x 6 x 3"), std::string::npos);
  fs::remove_all(dir);
}

TEST(BakeSummary, ASampledTableSaysItsEstimatorAndSamples) {
  const fs::path dir = test::Scratch("bake_summary_sampled");
  BakeRequest request;
  request.tables = {"E"};
  request.formats = {"exr"};
  request.size = 4;
  request.sampling.estimator = Estimator::kVisibleNormal;
  request.sampling.samples = 256;
  request.outputDirectory = dir.string();
  const BakeResult result = Bake(request);
  ASSERT_EQ(result.tables.size(), 1u);
  const std::string line = TableSummaryLine(result.tables[0]);
  EXPECT_NE(line.find(" 256/texel"), std::string::npos) << line;
  EXPECT_EQ(line.find("quadrature"), std::string::npos) << line;
  fs::remove_all(dir);
}

TEST(BakeSummary, TheFilesListedAreTheDirectorysAndForeignOnesAreNamed) {
  const fs::path dir = test::Scratch("bake_summary_files");
  fs::create_directories(dir);
  std::ofstream(dir / "notes.txt") << "mine\n";
  BakeRequest request;
  request.tables = {"E", "dfg"};
  request.formats = {"exr", "header"};
  request.size = 4;
  request.outputDirectory = dir.string();
  const BakeResult result = Bake(request);
  const std::string text = WrittenFilesText(result);
  std::set<std::string> listed, present;
  const std::string head = "wrote " + std::to_string(result.files.size()) + " files to ";
  ASSERT_EQ(text.rfind(head, 0), 0u) << text;
  const std::string names = text.substr(text.find(": ") + 2, text.find('\n') - text.find(": ") - 2);
  for (size_t start = 0; start <= names.size();) {
    const size_t end = std::min(names.find(", ", start), names.size());
    listed.insert(names.substr(start, end - start));
    start = end + 2;
  }
  for (const auto &entry : fs::directory_iterator(dir))
    if (entry.path().filename() != "notes.txt") present.insert(entry.path().filename().string());
  EXPECT_EQ(listed, present) << text;
  EXPECT_NE(text.find("1 file lutbake did not write, left as they were: notes.txt"),
            std::string::npos)
      << text;
  fs::remove_all(dir);
}

}  // namespace
}  // namespace lutbake
