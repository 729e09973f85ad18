// A small streaming JSON writer for reports: enough for objects, arrays, numbers, strings.
#pragma once

#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/text.hpp"

namespace shadows {

// A figure over no pixel: NaN, which a report writes as null (never a zero that reads "none").
inline constexpr double kNoFigure = std::numeric_limits<double>::quiet_NaN();

// A JSON string. Bytes that are not UTF-8 (a file name in another encoding) cannot be
// JSON text: each is written as the four characters \xNN, as printable() shows it.
inline std::string jsonQuote(const std::string& s) {
  std::string q = "\"";
  for (size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    const size_t length = utf8SequenceLength(s, i);
    char buf[8];
    if (c == '"' || c == '\\') {
      q += '\\';
      q += static_cast<char>(c);
    } else if (c < 0x20) {
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      q += buf;
    } else if (length == 0) {
      std::snprintf(buf, sizeof buf, "\\\\x%02X", c);
      q += buf;
    } else {
      q.append(s, i, length);
      i += length;
      continue;
    }
    ++i;
  }
  return q + "\"";
}

class JsonWriter {
 public:
  JsonWriter& beginObject(const std::string& key = {}) { return open(key, '{'); }
  JsonWriter& endObject() { return close('}'); }
  JsonWriter& beginArray(const std::string& key = {}) { return open(key, '['); }
  JsonWriter& endArray() { return close(']'); }
  JsonWriter& value(const std::string& key, double v) {
    item(key);
    record(key, v);
    if (!std::isfinite(v)) {
      out_ += "null";  // JSON has no NaN; a non-finite number reads as null
    } else {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.6g", v);
      out_ += buf;
    }
    return *this;
  }
  JsonWriter& value(const std::string& key, long long v) {
    item(key);
    record(key, static_cast<double>(v));
    out_ += std::to_string(v);
    return *this;
  }
  JsonWriter& value(const std::string& key, int v) { return value(key, static_cast<long long>(v)); }
  JsonWriter& value(const std::string& key, bool v) {
    item(key);
    record(key, v ? 1.0 : 0.0);
    out_ += v ? "true" : "false";
    return *this;
  }
  JsonWriter& value(const std::string& key, const std::string& v) {
    item(key);
    out_ += jsonQuote(v);
    return *this;
  }
  JsonWriter& value(const std::string& key, const char* v) { return value(key, std::string(v)); }
  // A number this context cannot count (Caps): null, never a wrong number.
  JsonWriter& value(const std::string& key, const std::optional<long long>& v) {
    if (v) return value(key, *v);
    item(key);
    record(key, kNoFigure);
    out_ += "null";
    return *this;
  }
  // A figure over nothing (no fragment filtered, no pixel compared, no live frame): null,
  // never a zero that reads "none", and `<key>_not_counted` beside it saying why. A goal on it
  // is not met (exercise.hpp), and the grader and the panel give this reason.
  JsonWriter& notCounted(const std::string& key, const std::string& why) {
    value(key, std::optional<long long>());
    if (!path_.empty() && path_.back() != "#") reasons_[path_.back() + "/" + key] = why;
    return value(key + "_not_counted", why);
  }
  // A number, or where it is not one, the reason notCounted gave (otherwise null).
  JsonWriter& figure(const std::string& key, std::optional<double> v, const std::string& why) {
    return v && std::isfinite(*v) ? value(key, *v) : notCounted(key, why);
  }
  // Why the figure at `pointer` is null, where notCounted said so.
  std::optional<std::string> whyNotCounted(const std::string& pointer) const {
    const auto it = reasons_.find(pointer);
    if (it == reasons_.end()) return std::nullopt;
    return it->second;
  }
  const std::string& str() const { return out_; }
  // A number written so far, by its JSON pointer ("/error/false_lit_pct"; members of objects
  // only, not of arrays): what an exercise's goal reads (lesson/exercise.hpp). Null is NaN;
  // a name not written is empty.
  std::optional<double> number(const std::string& pointer) const {
    const auto it = numbers_.find(pointer);
    if (it == numbers_.end()) return std::nullopt;
    return it->second;
  }

 private:
  JsonWriter& open(const std::string& key, char bracket) {
    item(key);
    out_ += bracket;
    first_.push_back(true);
    // The path of what is inside: "" for the top object, "#" (recorded nowhere) in arrays.
    const bool inArray = !path_.empty() && path_.back() == "#";
    path_.push_back(bracket == '[' || inArray
                        ? "#"
                        : (path_.empty() ? "" : path_.back()) + (key.empty() ? "" : "/" + key));
    return *this;
  }
  JsonWriter& close(char bracket) {
    first_.pop_back();
    path_.pop_back();
    out_ += '\n' + std::string(2 * first_.size(), ' ') + bracket;
    return *this;
  }
  void item(const std::string& key) {
    if (!first_.empty()) {
      if (!first_.back()) out_ += ',';
      first_.back() = false;
      out_ += '\n' + std::string(2 * first_.size(), ' ');
    }
    if (!key.empty()) out_ += jsonQuote(key) + ": ";
  }
  void record(const std::string& key, double v) {
    if (!path_.empty() && path_.back() != "#" && !key.empty())
      numbers_[path_.back() + "/" + key] = v;
  }
  std::string out_;
  std::vector<bool> first_;
  std::vector<std::string> path_;
  std::map<std::string, double> numbers_;
  std::map<std::string, std::string> reasons_;
};

}  // namespace shadows
