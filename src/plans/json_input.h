// Reading user-written JSON (glTF scenes, manifests) with messages that name
// the file, the JSON pointer of the value, what was found and what is
// accepted. Internal to the library: scene.cpp and manifest.cpp.
#pragma once

#include <initializer_list>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "lutbake/plans/material.h"

namespace lutbake::json_input {

using Json = nlohmann::json;

// A JSON value and where it sits: the file and its JSON pointer ("" is the root).
struct Place {
  const std::string *file;
  std::string pointer;

  Place Child(std::string_view key) const;  // escapes '~' and '/' as RFC 6901 says
  Place Child(size_t index) const;
  std::string Text() const { return pointer.empty() ? "/" : pointer; }
  [[noreturn]] void Fail(const std::string &what) const;
};

// Parses JSON text; malformed text throws InputError naming the line and column.
Json Parse(std::string_view text, const std::string &file);

// "a string", "an object", ...: the type of a value in words, for messages.
std::string Describe(const Json &value);
const Json *Member(const Json &object, const char *key);  // nullptr when absent
void RequireObject(const Json &value, const Place &place);
void RequireArray(const Json &value, const Place &place);
// A number in [lo, hi] (NaN and infinities excluded).
double Number(const Json &value, const Place &place, double lo, double hi);
bool Boolean(const Json &value, const Place &place);
std::string String(const Json &value, const Place &place);
// Every key of `object` must be one of `allowed`; else "unknown key", with the accepted ones.
void OnlyKeys(const Json &object, const Place &place, std::initializer_list<const char *> allowed);

}  // namespace lutbake::json_input
