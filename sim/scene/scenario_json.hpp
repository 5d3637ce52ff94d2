// A small toolkit for reading the scenario JSON with its path always known,
// so every error names the file, the JSON path, the value and what was allowed.
#pragma once

#include <nlohmann/json.hpp>

#include <initializer_list>
#include <string>

#include "sim/scene/scenario.hpp"

namespace sim::scenario_json {

using Json = nlohmann::json;

// A value in the document and where it is.
struct Node {
  const Json& value;
  std::string path;
  const std::string& file;

  Node at(const std::string& key) const;  // child of an object (must exist)
  Node at(std::size_t index) const;       // element of an array
  bool has(const std::string& key) const;
};

// The document in `text`. A syntax error, a number too large for a double and
// a key given twice in one object are ScenarioErrors naming `file`.
Json parse_text(const std::string& text, const std::string& file);

[[noreturn]] void fail(const Node& node, const std::string& expected);
[[noreturn]] void fail_missing(const Node& parent, const std::string& key, const std::string& why);
[[noreturn]] void fail_at(const std::string& file, const std::string& message);

// The object at node; every key must be one of `allowed`. `owner`, when
// given, says whose keys these are ("a dynamic stage"), for keys that are
// allowed only elsewhere.
void require_object(const Node& node, std::initializer_list<const char*> allowed,
                    const std::string& owner = "");
// The child `key`, which must be present (`why` says what needs it).
Node required(const Node& parent, const std::string& key, const std::string& why = "required");

enum class Bound { Closed, Open };
// A finite number in the given range; +-inf bounds are written as such.
double number(const Node& node, double lo, Bound lo_kind, double hi, Bound hi_kind);
double positive(const Node& node);      // (0, inf)
double non_negative(const Node& node);  // [0, inf)
int integer(const Node& node, int lo, int hi);  // whole number in [lo, hi]
std::string string(const Node& node);
std::string one_of(const Node& node, std::initializer_list<const char*> allowed);
Vec2 vec2(const Node& node);  // [x, y], finite

// Compact JSON text of a value, cut to about 60 characters.
std::string show(const Json& value);

}  // namespace sim::scenario_json
