#include "lutbake/api/numbers.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace lutbake {

std::string WholeNumberProblem(const std::string &text, uint64_t lo, uint64_t hi,
                               const std::string &accepted) {
  // Signs, spaces and trailing text are refused before converting.
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
    return "'" + text + "' is not a whole number; accepted: " + accepted;
  errno = 0;
  const unsigned long long value = std::strtoull(text.c_str(), nullptr, 10);
  if (errno == ERANGE || value < lo || value > hi)
    return "'" + text + "' is out of range; accepted: " + accepted;
  return "";
}

std::string RealNumberProblem(const std::string &text, double lo, double hi,
                              const std::string &accepted) {
  char *end = nullptr;
  errno = 0;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || std::isnan(value))
    return "'" + text + "' is not a number; accepted: " + accepted;
  if (errno == ERANGE || !(value >= lo && value <= hi))
    return "'" + text + "' is out of range; accepted: " + accepted;
  return "";
}

}  // namespace lutbake
