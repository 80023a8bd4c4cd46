#include "lutbake/api/text.h"

#include <sstream>
#include <vector>

namespace lutbake {

namespace {

// `word` as pieces to lay out without spaces between them: whole when it
// fits in `room`, else cut after each comma ("a,b,c" as "a," "b," "c").
std::vector<std::string> Pieces(const std::string &word, size_t room) {
  if (word.size() <= room) return {word};
  std::vector<std::string> pieces;
  for (size_t start = 0; start < word.size();) {
    const size_t comma = word.find(',', start);
    const size_t end = comma == std::string::npos ? word.size() : comma + 1;
    pieces.push_back(word.substr(start, end - start));
    start = end;
  }
  return pieces;
}

}  // namespace

std::string WrapText(const std::string &text, size_t width, size_t indent) {
  const size_t room = width > indent ? width - indent : 1;
  const std::string newLine = "\n" + std::string(indent, ' ');
  std::string out;
  std::stringstream lines(text);
  bool firstLine = true;
  for (std::string line; std::getline(lines, line);) {
    if (!firstLine) out += newLine;
    firstLine = false;
    const size_t lead = line.find_first_not_of(' ');
    if (lead == std::string::npos) continue;
    if (lead > 0 && line.size() <= room) {  // an example, laid out by hand
      out += line;
      continue;
    }
    std::string current(lead, ' ');
    bool empty = true;  // nothing but the leading spaces on `current`
    std::stringstream words(line.substr(lead));
    for (std::string word; words >> word;) {
      const std::vector<std::string> pieces = Pieces(word, room);
      for (size_t k = 0; k < pieces.size(); ++k) {
        const std::string space = empty || k > 0 ? "" : " ";
        if (!empty && current.size() + space.size() + pieces[k].size() > room) {
          out += current + newLine;
          current.clear();
        }
        current += (current.empty() ? "" : space) + pieces[k];
        empty = false;
      }
    }
    out += current;
  }
  return out;
}

}  // namespace lutbake
