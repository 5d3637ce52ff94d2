#include "sim/scene/scenario_json.hpp"

#include <algorithm>
#include <cctype>
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

namespace {

constexpr std::size_t kShowLimit = 60;
constexpr std::size_t kMaxDepth = 64;

std::string shorten(const std::string& text) {
  return text.size() <= kShowLimit ? text : text.substr(0, kShowLimit - 3) + "...";
}

// Appends `value` to `out` until `out` passes the limit: an error shows only
// the start of a value, so a huge array costs no more than a short one, and
// the recursion is as deep as the text shown, not as the value.
void show_into(const Json& value, std::string& out) {
  if (out.size() > kShowLimit) return;
  switch (value.type()) {
    case Json::value_t::array: {
      out += '[';
      bool first = true;
      for (const Json& element : value) {
        if (out.size() > kShowLimit) return;
        if (!first) out += ',';
        first = false;
        show_into(element, out);
      }
      out += ']';
      return;
    }
    case Json::value_t::object: {
      out += '{';
      bool first = true;
      for (const auto& item : value.items()) {
        if (out.size() > kShowLimit) return;
        if (!first) out += ',';
        first = false;
        show_into(Json(item.key()), out);
        out += ':';
        show_into(item.value(), out);
      }
      out += '}';
      return;
    }
    case Json::value_t::string: {
      const std::string& text = value.get_ref<const std::string&>();
      const std::string head = text.substr(0, kShowLimit + 4);
      out += Json(head).dump(-1, ' ', false, Json::error_handler_t::replace);
      return;
    }
    case Json::value_t::number_float: {
      const double v = value.get<double>();
      // nlohmann writes a non-finite number as null, which would hide the problem.
      if (std::isnan(v)) out += "nan";
      else if (std::isinf(v)) out += v < 0 ? "-inf" : "inf";
      else out += value.dump();
      return;
    }
    default:
      out += value.dump();
  }
}

}  // namespace

std::string show(const Json& value) {
  std::string text;
  show_into(value, text);
  if (text.size() <= kShowLimit) return text;
  std::size_t cut = kShowLimit - 3;
  // Never split a UTF-8 sequence: the message must stay valid text.
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
  return text.substr(0, cut) + "...";
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

void require_object(const Node& node, std::initializer_list<const char*> allowed,
                    const std::string& owner) {
  if (!node.value.is_object()) fail(node, "an object");
  for (const auto& item : node.value.items()) {
    bool known = false;
    for (const char* a : allowed) known = known || item.key() == a;
    if (known) continue;
    std::string list;
    for (const char* a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
    const std::string key = shorten(item.key());
    fail_at(node.file, (node.path.empty() ? key : node.path + "." + key) +
                           ": unknown key" + (owner.empty() ? "" : " for " + owner) +
                           " (allowed: " + list + ")");
  }
}

Node required(const Node& parent, const std::string& key, const std::string& why) {
  if (!parent.has(key)) fail_missing(parent, key, why);
  return parent.at(key);
}

namespace {

// The library's reason without its prefix: "[json.exception.parse_error.101]
// parse error at line 3, column 7: syntax error ..." gives "syntax error ...".
std::string syntax_reason(const std::string& what) {
  std::string rest = what;
  const std::size_t tag = rest.find("] ");
  if (rest.rfind("[json.exception.", 0) == 0 && tag != std::string::npos) rest.erase(0, tag + 2);
  if (rest.rfind("parse error", 0) == 0) {
    const std::size_t colon = rest.find(": ");
    rest.erase(0, colon == std::string::npos ? rest.size() : colon + 2);
  }
  // The library quotes the token read so far, which can be a whole file.
  return rest.size() > 240 ? rest.substr(0, 237) + "..." : rest;
}

// "line L, column C" of byte `offset` in `text`, both from 1, columns in
// characters. The library's own count places a token that ends a line at
// column 0 of the next one.
std::string location(const std::string& text, std::size_t offset) {
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < offset && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80) {
      ++column;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

// Follows the parser through the document as a JSON path, so a number that
// overflows a double and a repeated key are reported where they are (the DOM
// parser would reject the first without a place and silently keep the last
// of the second).
class PathTracker : public nlohmann::json_sax<Json> {
 public:
  explicit PathTracker(const std::string& text) : text_(text) {}
  std::string error;  // why the parse stopped

  bool null() override { return value(); }
  bool boolean(bool) override { return value(); }
  bool number_integer(number_integer_t) override { return value(); }
  bool number_unsigned(number_unsigned_t) override { return value(); }
  bool number_float(number_float_t, const string_t&) override { return value(); }
  bool string(string_t&) override { return value(); }
  bool binary(binary_t&) override { return value(); }
  bool start_object(std::size_t) override { return open(true); }
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
  bool start_array(std::size_t) override { return open(false); }
  bool end_array() override {
    frames_.pop_back();
    return value();
  }
  bool parse_error(std::size_t position, const std::string& token,
                   const Json::exception& e) override {
    const std::string where = frames_.empty() ? std::string("(top level)") : path();
    std::size_t start = 0;
    const std::string literal = non_finite_literal(position, start);
    if (e.id == 406)  // number overflow
      error = where + " = " + shorten(token) +
              ": expected a finite number (this one is too large for a double)";
    else if (!literal.empty())
      error = where + " = " + literal + " at " + location(text_, start) +
              ": expected a finite number (JSON has no NaN or Infinity; every number of a "
              "scenario must be finite)";
    else {
      // `position` counts the characters read: the last of them is where
      // the parser gave up.
      error = "invalid JSON at " + location(text_, position > 0 ? position - 1 : 0) + ": " +
              syntax_reason(e.what());
    }
    return false;
  }

 private:
  struct Frame {
    bool object;
    std::set<std::string> keys;
    std::string key;
    std::size_t index;
  };

  // No scenario nests deeper than 5 levels; refusing deep junk early keeps
  // every later pass over the document (and its error text) shallow.
  bool open(bool object) {
    if (frames_.size() >= kMaxDepth) {
      error = shorten(path()) + ": arrays and objects nested deeper than " +
              std::to_string(kMaxDepth) + " levels (a scenario needs at most 5)";
      return false;
    }
    frames_.push_back(Frame{object, {}, {}, 0});
    return true;
  }

  // NaN, Infinity, inf (with a sign or not: what Python's json module and
  // printf write) where the parser gave up at `position`, or "". The parser
  // stops a character or two into the word, so the whole word is looked up.
  std::string non_finite_literal(std::size_t position, std::size_t& start) const {
    auto part = [](char c) {
      return std::isalpha(static_cast<unsigned char>(c)) || c == '-' || c == '+';
    };
    start = std::min(position > 0 ? position - 1 : 0, text_.size());
    while (start > 0 && part(text_[start - 1])) --start;
    std::size_t end = start;
    while (end < text_.size() && part(text_[end])) ++end;
    const std::string word = text_.substr(start, end - start);
    std::string bare = word.substr(!word.empty() && (word[0] == '-' || word[0] == '+'));
    for (char& c : bare) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return bare == "nan" || bare == "inf" || bare == "infinity" ? word : "";
  }

  // A value ended: the next one in an array has the next index.
  bool value() {
    if (!frames_.empty() && !frames_.back().object) ++frames_.back().index;
    return true;
  }

  std::string path() const {
    std::string p;
    for (const Frame& f : frames_) {
      const std::string key = shorten(f.key);
      p += f.object ? (p.empty() ? key : "." + key) : "[" + std::to_string(f.index) + "]";
    }
    return p;
  }

  const std::string& text_;
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
  PathTracker tracker(text);
  try {
    if (!Json::sax_parse(text, &tracker)) fail_at(file, tracker.error);
    return Json::parse(text);
  } catch (const Json::exception& e) {  // not expected once the tracker has passed the text
    fail_at(file, "invalid JSON: " + syntax_reason(e.what()));
  }
}

double number(const Node& node, double lo, Bound lo_kind, double hi, Bound hi_kind) {
  const std::string range = (lo_kind == Bound::Closed ? "[" : "(") + format_bound(lo) + ", " +
                            format_bound(hi) + (hi_kind == Bound::Closed ? "]" : ")");
  if (std::isinf(lo) && std::isinf(hi)) {  // any coordinate
    if (!node.value.is_number() || !std::isfinite(node.value.get<double>()))
      fail(node, "a finite number");
    return node.value.get<double>();
  }
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
