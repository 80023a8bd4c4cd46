// Numbers as the command line spells them: whether an option's text is a
// number in the accepted range, and if not, the message that says why.
#pragma once

#include <cstdint>
#include <string>

namespace lutbake {

// "" when `text` is a whole number (decimal digits only: no sign, space or
// exponent) in [lo, hi]; else "'TEXT' is not a whole number; accepted:
// ACCEPTED" or "'TEXT' is out of range; accepted: ACCEPTED".
std::string WholeNumberProblem(const std::string &text, uint64_t lo, uint64_t hi,
                               const std::string &accepted);

// "" when `text` is a real number (decimal or exponent notation, all of
// `text`) in [lo, hi]; else "'TEXT' is not a number; accepted: ACCEPTED"
// (empty, trailing text, nan) or "'TEXT' is out of range; accepted:
// ACCEPTED" (outside [lo, hi], inf, or beyond the doubles either way: 1e400,
// and 1e-400, which would read as a 0 that was not typed).
std::string RealNumberProblem(const std::string &text, double lo, double hi,
                              const std::string &accepted);

}  // namespace lutbake
