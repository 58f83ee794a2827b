#include "sim/io/json_fields.h"

#include <cmath>
#include <sstream>

#include "sim/scene/input_error.h"

namespace vascsim::io {

using nlohmann::json;

std::string format_number(double value) {
  std::ostringstream s;
  s.precision(10);
  s << value;
  return s.str();
}

std::string describe(const json& value) {
  if (value.is_object()) return "an object";
  std::string s = value.dump();
  if (value.is_array() && s.size() > 40) return "an array of " + std::to_string(value.size());
  if (s.size() > 60) s = s.substr(0, 57) + "...";
  return s;
}

FieldReader::FieldReader(const json& object, std::string file, std::string pointer)
    : object_(&object), file_(std::move(file)), pointer_(std::move(pointer)) {
  if (!object.is_object())
    throw InputError(file_ + ": " + (pointer_.empty() ? "/" : pointer_) + ": expected an object, got " + describe(object));
}

void FieldReader::fail(const std::string& key, const std::string& expected, const json& got) const {
  throw InputError(file_ + ": " + pointer_of(key) + ": expected " + expected + ", got " + describe(got));
}

bool FieldReader::has(const std::string& key) const { return object_ && object_->contains(key); }

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

Vec2 FieldReader::vec2(const std::string& key, const Vec2& fallback) {
  const json* v = lookup(key);
  if (!v) return fallback;
  const std::string expected = "an array of 2 finite numbers [x, y]";
  if (!v->is_array() || v->size() != 2 || !(*v)[0].is_number() || !(*v)[1].is_number()) fail(key, expected, *v);
  Vec2 p((*v)[0].get<double>(), (*v)[1].get<double>());
  if (!p.allFinite()) fail(key, expected, *v);
  return p;
}

FieldReader FieldReader::object(const std::string& key) {
  const json* v = lookup(key);
  if (!v) {
    static const json kEmpty = json::object();
    return FieldReader(kEmpty, file_, pointer_of(key));
  }
  if (!v->is_object()) fail(key, "an object", *v);
  return FieldReader(*v, file_, pointer_of(key));
}

void FieldReader::finish() const {
  if (!object_) return;
  for (auto it = object_->begin(); it != object_->end(); ++it) {
    if (known_.count(it.key())) continue;
    std::string keys;
    for (const auto& k : known_) keys += (keys.empty() ? "" : ", ") + k;
    throw InputError(file_ + ": " + pointer_of(it.key()) + ": unknown key (known keys here: " + keys + ")");
  }
}

}  // namespace vascsim::io
