#include "core/params.hpp"

#include "core/image.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <utility>

#include "core/json.hpp"
#include "core/text.hpp"

namespace shadows {

namespace {

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

bool parseNumber(const std::string& text, double& out) {
  // Plain decimal only: strtod would also take hex ("0x1"), "inf" and "nan".
  if (text.empty() || text.find_first_not_of("0123456789+-.eE") != std::string::npos) {
    return false;
  }
  errno = 0;
  char* end = nullptr;
  out = std::strtod(text.c_str(), &end);
  // Underflow (1e-320) is a number, the nearest one; overflow (1e400) is not.
  const bool range_ok = errno == 0 || (errno == ERANGE && std::abs(out) <= DBL_MIN);
  return range_ok && end == text.c_str() + text.size() && std::isfinite(out);
}

std::string joined(const std::vector<std::string>& items) {
  std::string s;
  for (const auto& item : items) s += (s.empty() ? "" : ", ") + item;
  return s;
}

const char* kindName(ParamKind kind) {
  switch (kind) {
    case ParamKind::Float:
      return "float";
    case ParamKind::Int:
      return "int";
    case ParamKind::Bool:
      return "bool";
    case ParamKind::Vec3:
      return "vec3";
    case ParamKind::Choice:
      return "choice";
    case ParamKind::String:
      return "string";
  }
  return "?";
}

std::string allowed(const Param& p) {
  switch (p.kind) {
    case ParamKind::Float:
      return "a number in [" + number(p.min) + ", " + number(p.max) + "]";
    case ParamKind::Int:
      return "an integer in [" + number(p.min) + ", " + number(p.max) + "]";
    case ParamKind::Bool:
      return "true or false";
    case ParamKind::Vec3:
      return "x,y,z with each in [" + number(p.min) + ", " + number(p.max) + "]";
    case ParamKind::Choice:
      return "one of " + joined(p.choices);
    case ParamKind::String:
      return "text on one line";
  }
  return {};
}

// Ranges are declared as floats: compare in float so "0.001" is inside [0.001f, ...].
// In double precision, against the bounds as the decimals they were written as (addFloat's
// 0.1f is 0.1 here, not 0.100000001): 4.9999999 is below a minimum of 5 even though it
// rounds to 5.0f.
// The bound as the source wrote it: the shortest decimal that reads back as `f`.
double asWritten(float f) {
  return std::strtod(shortestDecimal(f).c_str(), nullptr);
}

bool inRange(const Param& p, double v) {
  return v >= p.min && v <= p.max;
}

// "pcf.early_out" -> PCF_EARLY_OUT: a preprocessor name.
std::string macroName(const std::string& name) {
  std::string m;
  for (const char c : name) {
    m += std::isalnum(static_cast<unsigned char>(c)) ? static_cast<char>(std::toupper(c)) : '_';
  }
  return m;
}

}  // namespace

// Levenshtein distance, for "did you mean".
size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1])});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string Param::text() const {
  switch (kind) {
    case ParamKind::Float:
    case ParamKind::Int:
      return number(value[0]);
    case ParamKind::Bool:
      return b() ? "true" : "false";
    case ParamKind::Vec3:
      return number(value[0]) + "," + number(value[1]) + "," + number(value[2]);
    case ParamKind::Choice:
      return choice();
    case ParamKind::String:
      return string_value;
  }
  return {};
}

std::vector<std::string> choiceDefines(const std::string& macro,
                                       const std::vector<std::string>& choices,
                                       const std::string& current) {
  std::vector<std::string> lines;
  for (size_t i = 0; i < choices.size(); ++i) {
    lines.push_back(macroName(macro + "_" + choices[i]) + " " + std::to_string(i));
  }
  lines.push_back(macroName(macro) + " " + macroName(macro + "_" + current));
  return lines;
}

std::vector<std::string> Param::defines() const {
  if (kind == ParamKind::Choice) return choiceDefines(name, choices, choice());
  if (kind == ParamKind::Bool || kind == ParamKind::Int) {
    return {macroName(name) + " " + std::to_string(i())};
  }
  throw std::logic_error("parameter " + name + " has no #define form (a " + kindName(kind) + ")");
}

void requireKind(const Param& p, ParamKind kind) {
  if (p.kind != kind) {
    throw std::logic_error("parameter " + p.name + " is a " + kindName(p.kind) + ", not a " +
                           kindName(kind));
  }
}

Param& Params::add(Param p) {
  if (find(p.name) != nullptr) throw std::logic_error("parameter declared twice: " + p.name);
  std::copy(std::begin(p.value), std::end(p.value), std::begin(p.fallback));
  p.string_fallback = p.string_value;
  p.shared = p.shared || sharing_;
  params_.push_back(std::move(p));
  dirty_ |= params_.back().affects;
  return params_.back();
}

void Params::claim(const std::string& prefix) {
  for (Param& p : params_) {
    if (p.name.rfind(prefix, 0) == 0) p.shared = false;
  }
}

Param& Params::addFloat(const std::string& name, float def, float min, float max,
                        const std::string& help, std::uint32_t affects) {
  Param p;
  p.name = name, p.help = help, p.kind = ParamKind::Float, p.min = asWritten(min),
  p.max = asWritten(max);
  p.value[0] = def, p.affects = affects;
  return add(std::move(p));
}

Param& Params::addInt(const std::string& name, int def, int min, int max, const std::string& help,
                      std::uint32_t affects) {
  Param p;
  p.name = name, p.help = help, p.kind = ParamKind::Int, p.min = min, p.max = max;
  p.value[0] = def, p.affects = affects;
  return add(std::move(p));
}

Param& Params::addBool(const std::string& name, bool def, const std::string& help,
                       std::uint32_t affects) {
  Param p;
  p.name = name, p.help = help, p.kind = ParamKind::Bool, p.min = 0, p.max = 1;
  p.value[0] = def ? 1 : 0, p.affects = affects;
  return add(std::move(p));
}

Param& Params::addVec3(const std::string& name, glm::vec3 def, float min, float max,
                       const std::string& help, std::uint32_t affects) {
  Param p;
  p.name = name, p.help = help, p.kind = ParamKind::Vec3, p.min = asWritten(min),
  p.max = asWritten(max);
  p.value[0] = def.x, p.value[1] = def.y, p.value[2] = def.z, p.affects = affects;
  return add(std::move(p));
}

Param& Params::addChoice(const std::string& name, const std::vector<std::string>& choices,
                         const std::string& def, const std::string& help, std::uint32_t affects) {
  Param p;
  p.name = name, p.help = help, p.kind = ParamKind::Choice, p.choices = choices;
  p.min = 0, p.max = static_cast<double>(choices.size()) - 1, p.affects = affects;
  const auto it = std::find(choices.begin(), choices.end(), def);
  if (it == choices.end()) throw std::logic_error(name + ": default is not a choice");
  p.value[0] = static_cast<double>(it - choices.begin());
  return add(std::move(p));
}

Param& Params::addString(const std::string& name, const std::string& def, const std::string& help,
                         std::uint32_t affects) {
  Param p;
  p.name = name, p.help = help, p.kind = ParamKind::String, p.string_value = def;
  p.affects = affects;
  return add(std::move(p));
}

Param* Params::find(const std::string& name) {
  return const_cast<Param*>(std::as_const(*this).find(name));
}

const Param* Params::find(const std::string& name) const {
  for (const auto& p : params_) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

Param& Params::at(const std::string& name) {
  return const_cast<Param&>(std::as_const(*this).at(name));
}

const Param& Params::at(const std::string& name) const {
  if (const Param* p = find(name)) return *p;
  throw std::out_of_range("no parameter named " + name);
}

std::string Params::set(const std::string& name, const std::string& text) {
  Param* p = find(name);
  if (p == nullptr) {
    std::string names;
    for (const auto& q : params_) names += (names.empty() ? "" : ", ") + q.name;
    std::string guess;
    size_t best = 4;  // more than 3 edits away is not a typo
    for (const auto& q : params_) {
      if (const size_t d = editDistance(name, q.name); d < best) best = d, guess = q.name;
    }
    return "unknown parameter '" + name + "'" +
           (guess.empty() ? "" : "; did you mean '" + guess + "'?") + " Parameters: " + names;
  }
  const std::string bad =
      name + ": '" + printable(text) + "' is not allowed; expected " + allowed(*p);
  double parsed[3] = {0, 0, 0};
  switch (p->kind) {
    case ParamKind::Float:
    case ParamKind::Int:
      if (!parseNumber(text, parsed[0])) return bad;
      if (p->kind == ParamKind::Int && parsed[0] != std::floor(parsed[0])) return bad;
      if (!inRange(*p, parsed[0])) return bad;
      break;
    case ParamKind::Bool:
      if (text == "true" || text == "1" || text == "on") {
        parsed[0] = 1;
      } else if (text == "false" || text == "0" || text == "off") {
        parsed[0] = 0;
      } else {
        return bad;
      }
      break;
    case ParamKind::Vec3: {
      std::stringstream in(text);
      std::string part;
      int n = 0;
      while (std::getline(in, part, ',')) {
        if (n == 3 || !parseNumber(part, parsed[n])) return bad;
        if (!inRange(*p, parsed[n])) return bad;
        ++n;
      }
      if (n != 3 || text.back() == ',') return bad;
      break;
    }
    case ParamKind::Choice: {
      const auto it = std::find(p->choices.begin(), p->choices.end(), text);
      if (it == p->choices.end()) return bad;
      parsed[0] = static_cast<double>(it - p->choices.begin());
      break;
    }
    case ParamKind::String:
      if (text.find_first_of("\r\n") != std::string::npos) return bad;
      break;
  }
  if (p->check) {
    if (std::string refused = p->check(text); !refused.empty()) return name + ": " + refused;
  }
  if (p->kind == ParamKind::String) {
    if (p->string_value != text) {
      p->string_value = text;
      changed(*p);
    }
    return {};
  }
  if (!std::equal(std::begin(parsed), std::end(parsed), std::begin(p->value))) {
    std::copy(std::begin(parsed), std::end(parsed), std::begin(p->value));
    changed(*p);
  }
  return {};
}

std::string Params::assign(const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) {
    return "--set wants name=value, got '" + assignment + "'";
  }
  return set(assignment.substr(0, eq), assignment.substr(eq + 1));
}

void Params::setFloat(Param& p, double v) {
  v = std::clamp(v, p.min, p.max);
  if (p.kind == ParamKind::Int || p.kind == ParamKind::Choice || p.kind == ParamKind::Bool) {
    v = std::round(v);
  }
  if (p.value[0] != v) {
    p.value[0] = v;
    changed(p);
  }
}

void Params::setVec3(Param& p, glm::vec3 v) {
  for (int k = 0; k < 3; ++k) {
    const double c = std::clamp(static_cast<double>(v[k]), p.min, p.max);
    if (p.value[k] != c) {
      p.value[k] = c;
      changed(p);
    }
  }
}

void Params::setChoice(Param& p, const std::string& choiceName) {
  const auto it = std::find(p.choices.begin(), p.choices.end(), choiceName);
  if (it == p.choices.end()) throw std::logic_error(p.name + ": no choice " + choiceName);
  setFloat(p, static_cast<double>(it - p.choices.begin()));
}

void Params::resetToDefaults() {
  for (auto& p : params_) {
    if (!p.atDefault()) {
      std::copy(std::begin(p.fallback), std::end(p.fallback), std::begin(p.value));
      p.string_value = p.string_fallback;
      changed(p);
    }
  }
}

void Params::setDefaultVec3(Param& p, glm::vec3 v) {
  setVec3(p, v);
  std::copy(std::begin(p.value), std::end(p.value), std::begin(p.fallback));
}

void Params::setDefaultFloat(Param& p, double v) {
  setFloat(p, v);
  p.fallback[0] = p.value[0];
}

void Params::setDefaultChoice(Param& p, const std::string& choiceName) {
  setChoice(p, choiceName);
  p.fallback[0] = p.value[0];
}

std::string Params::listText() const {
  std::string out;
  char line[512];
  for (const auto& p : params_) {
    Param fallback = p;
    std::copy(std::begin(p.fallback), std::end(p.fallback), std::begin(fallback.value));
    fallback.string_value = p.string_fallback;
    // What is allowed goes last, in the words --set's errors use: a long list of choices
    // would push every column after it out of line.
    std::snprintf(line, sizeof line, "%-18s %-6s default %-14s %s; %s\n", p.name.c_str(),
                  kindName(p.kind), fallback.text().c_str(), p.help.c_str(), allowed(p).c_str());
    out += line;
  }
  return out;
}

void Params::writeJson(JsonWriter& json) const {
  json.beginObject("params");
  for (const auto& p : params_) {
    switch (p.kind) {
      case ParamKind::Float:
        json.value(p.name, p.value[0]);
        break;
      case ParamKind::Int:
        json.value(p.name, static_cast<long long>(p.value[0]));
        break;
      case ParamKind::Bool:
        json.value(p.name, p.b());
        break;
      case ParamKind::Vec3:
        json.beginArray(p.name);
        for (double c : p.value) json.value("", c);
        json.endArray();
        break;
      case ParamKind::Choice:
        json.value(p.name, p.choice());
        break;
      case ParamKind::String:
        json.value(p.name, p.string_value);
        break;
    }
  }
  json.endObject();
}

}  // namespace shadows
