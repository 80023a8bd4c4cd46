#include "plans/json_input.h"

#include <cmath>

#include "lutbake/tables/table.h"

namespace lutbake::json_input {

Place Place::Child(std::string_view key) const {
  std::string token;
  for (char c : key) {
    if (c == '~')
      token += "~0";
    else if (c == '/')
      token += "~1";
    else
      token += c;
  }
  return Place{file, pointer + "/" + token};
}

Place Place::Child(size_t index) const {
  return Place{file, pointer + "/" + std::to_string(index)};
}

void Place::Fail(const std::string &what) const {
  throw InputError(*file + ": " + Text() + ": " + what);
}

Json Parse(std::string_view text, const std::string &file) {
  try {
    return Json::parse(text.begin(), text.end());
  } catch (const Json::exception &e) {
    // A parse_error, or an out_of_range for a number beyond double (found by
    // fuzzing: 51e308). nlohmann's message starts with
    // "[json.exception.parse_error.101] "; what follows says where.
    std::string message = e.what();
    const size_t bracket = message.find("] ");
    if (message.rfind("[json.exception", 0) == 0 && bracket != std::string::npos)
      message = message.substr(bracket + 2);
    throw InputError(file + ": malformed JSON: " + message);
  }
}

std::string Describe(const Json &value) {
  switch (value.type()) {
    case Json::value_t::null: return "null";
    case Json::value_t::object: return "an object";
    case Json::value_t::array: return "an array";
    case Json::value_t::string: return "the string " + value.dump();
    case Json::value_t::boolean: return value.get<bool>() ? "true" : "false";
    case Json::value_t::number_integer:
    case Json::value_t::number_unsigned:
    case Json::value_t::number_float: return FormatDouble(value.get<double>());
    default: return "a binary value";
  }
}

const Json *Member(const Json &object, const char *key) {
  const auto it = object.find(key);
  return it == object.end() ? nullptr : &*it;
}

void RequireObject(const Json &value, const Place &place) {
  if (!value.is_object()) place.Fail("expected an object, found " + Describe(value));
}

void RequireArray(const Json &value, const Place &place) {
  if (!value.is_array()) place.Fail("expected an array, found " + Describe(value));
}

double Number(const Json &value, const Place &place, double lo, double hi) {
  if (!value.is_number()) place.Fail("expected a number, found " + Describe(value));
  const double v = value.get<double>();
  if (!(std::isfinite(v) && v >= lo && v <= hi))
    place.Fail(FormatDouble(v) + " is outside the accepted range [" + FormatDouble(lo) + ", " +
               FormatDouble(hi) + "]");
  return v;
}

bool Boolean(const Json &value, const Place &place) {
  if (!value.is_boolean()) place.Fail("expected true or false, found " + Describe(value));
  return value.get<bool>();
}

std::string String(const Json &value, const Place &place) {
  if (!value.is_string()) place.Fail("expected a string, found " + Describe(value));
  return value.get<std::string>();
}

void OnlyKeys(const Json &object, const Place &place, std::initializer_list<const char *> allowed) {
  for (auto it = object.begin(); it != object.end(); ++it) {
    bool known = false;
    for (const char *key : allowed) known = known || it.key() == key;
    if (known) continue;
    std::string accepted;
    for (const char *key : allowed) accepted += std::string(accepted.empty() ? "" : ", ") + key;
    place.Child(it.key()).Fail("unknown key \"" + it.key() + "\"; accepted here: " + accepted);
  }
}

}  // namespace lutbake::json_input
