#include "sim/io/json_fields.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <vector>

#include "sim/scene/input_error.h"

namespace vascsim::io {

using nlohmann::json;

std::string format_number(double value) {
  std::ostringstream s;
  s.precision(10);
  s << value;
  return s.str();
}

std::string utf8_prefix(const std::string& text, std::size_t max) {
  if (text.size() <= max) return text;
  std::size_t cut = max;
  while (cut > 0 && (static_cast<unsigned char>(text[cut]) & 0xC0) == 0x80) --cut;
  return text.substr(0, cut);
}

std::string describe(const json& value) {
  if (value.is_object()) return value.empty() ? "an empty object" : "an object";
  // Never dump what may be large or deep: a message quotes at most a short flat array.
  if (value.is_array()) {
    bool flat = value.size() <= 6;
    // Short strings too: ["0.6", 0.6] says more than "an array of 2" (the dump is capped below).
    for (const auto& item : value)
      flat = flat && item.is_primitive() && (!item.is_string() || item.get_ref<const std::string&>().size() <= 20);
    if (!flat) return "an array of " + std::to_string(value.size());
  }
  if (value.is_string() && value.get_ref<const std::string&>().size() > 60)
    return json(utf8_prefix(value.get_ref<const std::string&>(), 57)).dump() + "...";
  std::string s = value.dump();
  if (s.size() > 60) s = utf8_prefix(s, 57) + "...";
  return s;
}

std::string escape_pointer_token(const std::string& key) {
  if (key.find_first_of("~/") == std::string::npos) return key;
  std::string out;
  for (char c : key) out += c == '~' ? std::string("~0") : c == '/' ? std::string("~1") : std::string(1, c);
  return out;
}

namespace {

// Where the parser is, for the messages of parse_json_strictly: one entry per open object or
// array.
struct OpenContainer {
  bool is_array = false;
  std::size_t index = 0;           // arrays: the element being read
  std::string key;                 // objects: the member being read
  std::set<std::string> keys;      // objects: the members seen
};

std::string pointer_of_stack(const std::vector<OpenContainer>& stack) {
  std::string p;
  for (std::size_t i = 0; i + 1 < stack.size(); ++i)
    p += "/" + (stack[i].is_array ? std::to_string(stack[i].index) : escape_pointer_token(stack[i].key));
  return p.empty() ? "/" : p;
}

}  // namespace

json parse_json_strictly(const std::string& text, const std::string& label) {
  if (const auto nul = text.find('\0'); nul != std::string::npos)
    throw InputError(label + ": not valid JSON (a NUL byte at offset " + std::to_string(nul) + ")");
  std::vector<OpenContainer> stack;
  auto next_element = [&] {
    if (!stack.empty() && stack.back().is_array) ++stack.back().index;
  };
  const json::parser_callback_t check = [&](int depth, json::parse_event_t event, json& parsed) {
    if (depth > kMaxJsonDepth)
      throw InputError(label + ": " + pointer_of_stack(stack) + ": nested deeper than " + std::to_string(kMaxJsonDepth) +
                       " levels");
    switch (event) {
      case json::parse_event_t::object_start:
      case json::parse_event_t::array_start:
        stack.push_back({event == json::parse_event_t::array_start, 0, "", {}});
        break;
      case json::parse_event_t::object_end:
      case json::parse_event_t::array_end:
        stack.pop_back();
        next_element();
        break;
      case json::parse_event_t::key: {
        OpenContainer& object = stack.back();
        object.key = parsed.get<std::string>();
        if (!object.keys.insert(object.key).second) {
          stack.push_back({});  // so the pointer names the repeated member
          throw InputError(label + ": " + pointer_of_stack(stack) + ": the key appears twice in one object");
        }
        break;
      }
      case json::parse_event_t::value:
        next_element();
        break;
    }
    return true;
  };
  try {
    return json::parse(text, check);
  } catch (const json::parse_error& e) {
    // nlohmann reports the byte offset; that is enough to find the mistake.
    throw InputError(label + ": not valid JSON (" + std::string(e.what()) + ")");
  } catch (const json::out_of_range& e) {
    // nlohmann names the number ("number overflow parsing '1e400'") but not where it is: its
    // first occurrence gives the line and column.
    const std::string what = e.what();
    const std::size_t open = what.find('\''), close = what.rfind('\'');
    std::string where;
    if (open != std::string::npos && close > open + 1) {
      const std::size_t at = text.find(what.substr(open + 1, close - open - 1));
      if (at != std::string::npos) {
        const std::size_t line_start = text.rfind('\n', at);
        const std::size_t line = 1 + static_cast<std::size_t>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
        const std::size_t column = at - (line_start == std::string::npos ? 0 : line_start + 1) + 1;
        where = " at line " + std::to_string(line) + ", column " + std::to_string(column);
      }
    }
    throw InputError(label + ": a number out of the double range" + where + " (" + what + ")");
  }
}

namespace {

// A JSON number as sign, significant digits (no leading or trailing zeros) and the exponent of
// the first digit's place: "-0.0120e3" and "-12.0" both become {true, "12", 2}.
struct Decimal {
  bool negative = false;
  std::string digits;
  long exponent = 0;
  bool operator==(const Decimal& o) const { return negative == o.negative && digits == o.digits && exponent == o.exponent; }
};

Decimal decimal_of(const std::string& number) {
  Decimal d;
  std::size_t i = 0;
  if (i < number.size() && number[i] == '-') d.negative = true, ++i;
  long point = 0;
  bool after_point = false;
  for (; i < number.size() && number[i] != 'e' && number[i] != 'E'; ++i) {
    if (number[i] == '.') after_point = true;
    else d.digits += number[i], point += !after_point;
  }
  if (i < number.size()) point += std::stol(number.substr(i + 1));  // JSON exponents are short digits
  const std::size_t first = d.digits.find_first_not_of('0');
  if (first == std::string::npos) return Decimal{};  // zero, whatever its sign
  d.digits = d.digits.substr(first, d.digits.find_last_not_of('0') - first + 1);
  d.exponent = point - static_cast<long>(first);
  return d;
}

// Reads the text as events and keeps the first number whose value as held differs from the text.
class InexactNumberFinder : public nlohmann::json_sax<json> {
 public:
  std::string found;

  bool number_float(number_float_t value, const string_t& text) override {
    if (found.empty() && !(decimal_of(json(value).dump()) == decimal_of(text))) found = pointer() + ": " + text;
    return value_read();
  }
  bool null() override { return value_read(); }
  bool boolean(bool) override { return value_read(); }
  bool number_integer(number_integer_t) override { return value_read(); }
  bool number_unsigned(number_unsigned_t) override { return value_read(); }
  bool string(string_t&) override { return value_read(); }
  bool binary(binary_t&) override { return value_read(); }
  bool start_object(std::size_t) override { return open(false); }
  bool key(string_t& name) override {
    stack_.back().key = name;
    return true;
  }
  bool end_object() override { return close(); }
  bool start_array(std::size_t) override { return open(true); }
  bool end_array() override { return close(); }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override { return false; }

 private:
  bool value_read() {
    if (!stack_.empty() && stack_.back().is_array) ++stack_.back().index;
    return found.empty();  // stop at the first
  }
  bool open(bool is_array) {
    stack_.push_back({is_array, 0, "", {}});
    return true;
  }
  bool close() {
    stack_.pop_back();
    return value_read();
  }
  std::string pointer() const {
    std::string p;
    for (const auto& c : stack_) p += "/" + (c.is_array ? std::to_string(c.index) : escape_pointer_token(c.key));
    return p.empty() ? "/" : p;
  }
  std::vector<OpenContainer> stack_;
};

}  // namespace

std::string first_inexact_number(const std::string& text) {
  InexactNumberFinder finder;
  try {
    json::sax_parse(text, &finder);
  } catch (const json::exception&) {
  }
  return finder.found;
}

FieldReader::FieldReader(const json& object, std::string file, std::string pointer, UnknownKeys unknown_keys)
    : object_(&object), file_(std::move(file)), pointer_(std::move(pointer)), unknown_keys_(unknown_keys) {
  if (!object.is_object())
    throw InputError(file_ + ": " + (pointer_.empty() ? "/" : pointer_) + ": expected an object, got " + describe(object));
}

void FieldReader::fail(const std::string& key, const std::string& expected, const json& got) const {
  throw InputError(file_ + ": " + pointer_of(key) + ": expected " + expected + ", got " + describe(got));
}

bool FieldReader::has(const std::string& key) const {
  known_.insert(key);  // asked about, so known: an "unknown key" error lists it among the valid ones
  return object_ && object_->contains(key);
}

const json* FieldReader::lookup(const std::string& key) {
  known_.insert(key);
  if (!object_) return nullptr;
  auto it = object_->find(key);
  return it == object_->end() ? nullptr : &*it;
}

const json* FieldReader::raw(const std::string& key) { return lookup(key); }

double FieldReader::number(const std::string& key, double fallback, double min, double max) {
  const json* v = lookup(key);
  if (!v) return fallback;
  const std::string expected = "a number in [" + format_number(min) + ", " + format_number(max) + "]";
  if (!v->is_number()) fail(key, expected, *v);
  const double x = v->get<double>();
  if (!std::isfinite(x) || x < min || x > max) fail(key, expected, *v);
  return x;
}

double FieldReader::positive(const std::string& key, double fallback, double max) {
  const json* v = lookup(key);
  if (!v) return fallback;
  const std::string expected =
      max >= 1e300 ? std::string("a number > 0") : "a number in (0, " + format_number(max) + "]";
  if (!v->is_number()) fail(key, expected, *v);
  const double x = v->get<double>();
  if (!std::isfinite(x) || x <= 0.0 || x > max) fail(key, expected, *v);
  return x;
}

long long FieldReader::integer(const std::string& key, long long fallback, long long min, long long max) {
  const json* v = lookup(key);
  if (!v) return fallback;
  const std::string expected = "an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "]";
  if (v->is_number_integer()) {
    const long long x = v->get<long long>();
    if (v->is_number_unsigned() && v->get<unsigned long long>() > static_cast<unsigned long long>(max))
      fail(key, expected, *v);
    if (x < min || x > max) fail(key, expected, *v);
    return x;
  }
  // 50.0 and 5e1 are JSON floats: "expected an integer, got 50.0" read as a contradiction.
  if (v->is_number_float() && std::isfinite(v->get<double>()) && std::floor(v->get<double>()) == v->get<double>())
    fail(key, expected + " written without a decimal point or exponent", *v);
  fail(key, expected, *v);
}

bool FieldReader::boolean(const std::string& key, bool fallback) {
  const json* v = lookup(key);
  if (!v) return fallback;
  if (!v->is_boolean()) fail(key, "true or false", *v);
  return v->get<bool>();
}

std::string FieldReader::choice(const std::string& key, const std::string& fallback,
                                const std::vector<std::string>& allowed) {
  const json* v = lookup(key);
  if (!v) return fallback;
  std::string expected = "one of";
  for (std::size_t i = 0; i < allowed.size(); ++i) expected += (i ? ", \"" : " \"") + allowed[i] + "\"";
  if (!v->is_string()) fail(key, expected, *v);
  const std::string s = v->get<std::string>();
  for (const auto& a : allowed)
    if (s == a) return s;
  fail(key, expected, *v);
}

std::string FieldReader::text(const std::string& key, const std::string& fallback) {
  const json* v = lookup(key);
  if (!v) return fallback;
  if (!v->is_string()) fail(key, "a string", *v);
  return v->get<std::string>();
}

Vec2 FieldReader::vec2(const std::string& key, const Vec2& fallback, double max_abs) {
  const json* v = lookup(key);
  if (!v) return fallback;
  const std::string expected =
      max_abs < 1e300 ? "an array of 2 numbers [x, y] in [-" + format_number(max_abs) + ", " + format_number(max_abs) + "]"
                      : "an array of 2 finite numbers [x, y]";
  if (!v->is_array() || v->size() != 2 || !(*v)[0].is_number() || !(*v)[1].is_number()) fail(key, expected, *v);
  Vec2 p((*v)[0].get<double>(), (*v)[1].get<double>());
  if (!p.allFinite() || p.cwiseAbs().maxCoeff() > max_abs) fail(key, expected, *v);
  return p;
}

FieldReader FieldReader::object(const std::string& key) {
  const json* v = lookup(key);
  if (!v) {
    static const json kEmpty = json::object();
    return nested(kEmpty, key);
  }
  if (!v->is_object()) fail(key, "an object", *v);
  return nested(*v, key);
}

FieldReader FieldReader::nested(const json& value, const std::string& key) const {
  return FieldReader(value, file_, pointer_of(key), unknown_keys_);
}

void FieldReader::finish() const {
  if (!object_ || unknown_keys_ == UnknownKeys::kIgnore) return;
  for (auto it = object_->begin(); it != object_->end(); ++it) {
    if (known_.count(it.key())) continue;
    std::string keys;
    for (const auto& k : known_) keys += (keys.empty() ? "" : ", ") + k;
    throw InputError(file_ + ": " + pointer_ + "/" + escape_pointer_token(it.key()) + ": unknown key (known keys here: " + keys + ")");
  }
}

}  // namespace vascsim::io
