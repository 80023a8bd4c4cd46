// Prose laid out for a terminal: the help of the command line, wrapped at
// a column.
#pragma once

#include <cstddef>
#include <string>

namespace lutbake {

// `text` with its words wrapped so that no line passes column `width`,
// every line set after `indent` columns: the first line is assumed to start
// there already (the caller wrote its label), the next ones begin with
// `indent` spaces. A line break in `text` is kept; a line of `text` that
// begins with spaces (an example command) and fits is kept as it is. A word
// wider than the room is cut after its commas ("a,b,c" as a list), else
// stays whole on a line of its own.
std::string WrapText(const std::string &text, size_t width, size_t indent);

}  // namespace lutbake
