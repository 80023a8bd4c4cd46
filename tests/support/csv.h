// A minimal reader for the reference CSV files in tests/data: '#' lines are
// comments, the first other line is the header.
#pragma once

#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace lutbake::test {

struct CsvRow {
  std::map<std::string, std::string> fields;
  double Number(const std::string &column) const {
    return std::strtod(fields.at(column).c_str(), nullptr);
  }
  const std::string &Text(const std::string &column) const { return fields.at(column); }
};

inline std::vector<CsvRow> ReadCsv(const std::string &path) {
  std::ifstream file(path);
  std::vector<CsvRow> rows;
  std::vector<std::string> header;
  for (std::string line; std::getline(file, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells;
    std::stringstream stream(line);
    for (std::string cell; std::getline(stream, cell, ',');) cells.push_back(cell);
    if (header.empty()) {
      header = cells;
      continue;
    }
    CsvRow row;
    for (size_t i = 0; i < header.size() && i < cells.size(); ++i) row.fields[header[i]] = cells[i];
    rows.push_back(row);
  }
  return rows;
}

inline std::string DataPath(const std::string &name) {
  return std::string(LUTBAKE_TEST_DATA) + "/" + name;
}

}  // namespace lutbake::test
