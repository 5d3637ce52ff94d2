#include "sim/scenario_json.hpp"

#include <cmath>
#include <limits>
#include <set>
#include <sstream>
#include <vector>

namespace sim::scenario_json {

Node Node::at(const std::string& key) const {
  return Node{value.at(key), path.empty() ? key : path + "." + key, file};
}

Node Node::at(std::size_t index) const {
  return Node{value.at(index), path + "[" + std::to_string(index) + "]", file};
}

bool Node::has(const std::string& key) const { return value.is_object() && value.contains(key); }

std::string show(const Json& value) {
  std::string text = value.dump(-1, ' ', false, Json::error_handler_t::replace);
  if (text.size() > 60) text = text.substr(0, 57) + "...";
  return text;
}

void fail_at(const std::string& file, const std::string& message) {
  throw ScenarioError(file + ": " + message);
}

void fail(const Node& node, const std::string& expected) {
  fail_at(node.file, (node.path.empty() ? std::string("(top level)") : node.path) + " = " +
                         show(node.value) + ": expected " + expected);
}

void fail_missing(const Node& parent, const std::string& key, const std::string& why) {
  fail_at(parent.file, (parent.path.empty() ? key : parent.path + "." + key) + ": missing (" +
                           why + ")");
}

void require_object(const Node& node, std::initializer_list<const char*> allowed) {
  if (!node.value.is_object()) fail(node, "an object");
  for (const auto& item : node.value.items()) {
    bool known = false;
    for (const char* a : allowed) known = known || item.key() == a;
    if (known) continue;
    std::string list;
    for (const char* a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
    fail_at(node.file, (node.path.empty() ? item.key() : node.path + "." + item.key()) +
                           ": unknown key (allowed: " + list + ")");
  }
}

Node required(const Node& parent, const std::string& key, const std::string& why) {
  if (!parent.has(key)) fail_missing(parent, key, why);
  return parent.at(key);
}

namespace {

// Follows the parser through the document as a JSON path, so a number that
// overflows a double and a repeated key are reported where they are (the DOM
// parser would reject the first without a place and silently keep the last
// of the second).
class PathTracker : public nlohmann::json_sax<Json> {
 public:
  std::string error;  // why the parse stopped

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override {
    frames_.push_back(Frame{true, {}, {}, 0});
    return true;
  }
  bool key(string_t& key) override {
    Frame& f = frames_.back();
    f.key = key;
    if (f.keys.insert(key).second) return true;
    error = path() + ": key given twice in one object (each key at most once)";
    return false;
  }
  bool end_object() override {
    frames_.pop_back();
    return value();
  }
  bool start_array(std::size_t) override {
    frames_.push_back(Frame{false, {}, {}, 0});
    return true;
  }
  bool end_array() override {
    frames_.pop_back();
    return value();
  }
  bool parse_error(std::size_t, const std::string& token, const Json::exception& e) override {
    if (e.id == 406)  // number overflow
      error = (frames_.empty() ? std::string("(top level)") : path()) + " = " + token +
              ": expected a finite number (this one is too large for a double)";
    else
      error = std::string("invalid JSON: ") + e.what();
    return false;
  }

 private:
  struct Frame {
    bool object;
    std::set<std::string> keys;
    std::string key;
    std::size_t index;
  };

  // A value ended: the next one in an array has the next index.
  bool value() {
    if (!frames_.empty() && !frames_.back().object) ++frames_.back().index;
    return true;
  }

  std::string path() const {
    std::string p;
    for (const Frame& f : frames_)
      p += f.object ? (p.empty() ? f.key : "." + f.key) : "[" + std::to_string(f.index) + "]";
    return p;
  }

  std::vector<Frame> frames_;
};

std::string format_bound(double v) {
  if (std::isinf(v)) return v < 0 ? "-inf" : "inf";
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

Json parse_text(const std::string& text, const std::string& file) {
  PathTracker tracker;
  try {
    if (!Json::sax_parse(text, &tracker)) fail_at(file, tracker.error);
    return Json::parse(text);
  } catch (const Json::exception& e) {  // not expected once the tracker has passed the text
    fail_at(file, std::string("invalid JSON: ") + e.what());
  }
}

double number(const Node& node, double lo, Bound lo_kind, double hi, Bound hi_kind) {
  const std::string range = (lo_kind == Bound::Closed ? "[" : "(") + format_bound(lo) + ", " +
                            format_bound(hi) + (hi_kind == Bound::Closed ? "]" : ")");
  if (!node.value.is_number()) fail(node, "a number in " + range);
  const double v = node.value.get<double>();
  if (!std::isfinite(v)) fail(node, "a finite number in " + range);
  const bool low_ok = lo_kind == Bound::Closed ? v >= lo : v > lo;
  const bool high_ok = hi_kind == Bound::Closed ? v <= hi : v < hi;
  if (!low_ok || !high_ok) fail(node, "a number in " + range);
  return v;
}

double positive(const Node& node) {
  return number(node, 0, Bound::Open, std::numeric_limits<double>::infinity(), Bound::Open);
}

double non_negative(const Node& node) {
  return number(node, 0, Bound::Closed, std::numeric_limits<double>::infinity(), Bound::Open);
}

int integer(const Node& node, int lo, int hi) {
  const std::string what = "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  if (!node.value.is_number()) fail(node, what);
  const double v = node.value.get<double>();
  if (!std::isfinite(v) || v != std::floor(v) || v < lo || v > hi) fail(node, what);
  return static_cast<int>(v);
}

std::string string(const Node& node) {
  if (!node.value.is_string()) fail(node, "a string");
  return node.value.get<std::string>();
}

std::string one_of(const Node& node, std::initializer_list<const char*> allowed) {
  std::string list;
  for (const char* a : allowed) list += (list.empty() ? "" : ", ") + std::string("\"") + a + "\"";
  if (!node.value.is_string()) fail(node, "one of " + list);
  const std::string v = node.value.get<std::string>();
  for (const char* a : allowed)
    if (v == a) return v;
  fail(node, "one of " + list);
}

Vec2 vec2(const Node& node) {
  if (!node.value.is_array() || node.value.size() != 2) fail(node, "a pair of numbers [x, y]");
  const double inf = std::numeric_limits<double>::infinity();
  return {number(node.at(0), -inf, Bound::Open, inf, Bound::Open),
          number(node.at(1), -inf, Bound::Open, inf, Bound::Open)};
}

}  // namespace sim::scenario_json
