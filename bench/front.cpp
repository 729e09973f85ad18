// The table's CSV form and its Pareto fronts (front.hpp).
#include "front.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

namespace shadows::bench {
namespace {

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char ch : s) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return q + "\"";
}

}  // namespace

int Table::column(const std::string& name) const {
  const auto it = std::find(header.begin(), header.end(), name);
  return it == header.end() ? -1 : static_cast<int>(it - header.begin());
}

size_t Table::addColumn(const std::string& name, bool is_numeric) {
  if (const int c = column(name); c >= 0) return static_cast<size_t>(c);
  header.push_back(name);
  numeric.push_back(is_numeric);
  for (auto& row : rows) row.resize(header.size());
  return header.size() - 1;
}

const std::string& Table::cell(size_t r, const std::string& name) const {
  static const std::string none;
  const int c = column(name);
  return c < 0 || static_cast<size_t>(c) >= rows[r].size() ? none : rows[r][c];
}

double Table::value(size_t r, const std::string& name) const {
  const std::string& s = cell(r, name);
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  return s.empty() || *end != '\0' ? std::nan("") : v;
}

std::string csvLine(const std::vector<std::string>& fields) {
  std::string line;
  for (size_t i = 0; i < fields.size(); ++i) {
    if (i > 0) line += ',';
    line += csvField(fields[i]);
  }
  return line;
}

std::string toCsv(const Table& t) {
  std::string out = csvLine(t.header) + "\n";
  for (const auto& row : t.rows) out += csvLine(row) + "\n";
  return out;
}

std::string readCsv(const std::filesystem::path& path, Table& t) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "cannot read " + path.string();
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::vector<std::vector<std::string>> records;
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char ch = text[i];
    if (quoted) {
      if (ch != '"') {
        fields.back() += ch;
      } else if (i + 1 < text.size() && text[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else {
        quoted = false;
      }
    } else if (ch == '"') {
      quoted = true;
    } else if (ch == ',') {
      fields.emplace_back();
    } else if (ch == '\n') {
      records.push_back(std::move(fields));
      fields.assign(1, {});
    } else if (ch != '\r') {
      fields.back() += ch;
    }
  }
  if (quoted) return path.string() + ": a quoted field does not end";
  if (fields.size() > 1 || !fields[0].empty()) records.push_back(std::move(fields));
  if (records.empty()) return path.string() + ": empty";
  t = Table{};
  t.header = records[0];
  for (size_t r = 1; r < records.size(); ++r) {
    if (records[r].size() != t.header.size()) {
      return path.string() + ": line " + std::to_string(r + 1) + " has " +
             std::to_string(records[r].size()) + " fields, the header " +
             std::to_string(t.header.size());
    }
    t.rows.push_back(std::move(records[r]));
  }
  // Numeric where every non-empty cell is a number ("nan" counts).
  for (size_t c = 0; c < t.header.size(); ++c) {
    bool numeric = true;
    for (size_t r = 0; r < t.rows.size() && numeric; ++r) {
      const std::string& s = t.rows[r][c];
      char* end = nullptr;
      std::strtod(s.c_str(), &end);
      numeric = s.empty() || *end == '\0';
    }
    t.numeric.push_back(numeric);
  }
  return {};
}

std::vector<bool> paretoFront(const std::vector<TimeError>& points) {
  auto valid = [](const TimeError& p) { return std::isfinite(p.time) && std::isfinite(p.error); };
  std::vector<bool> on(points.size(), false);
  for (size_t i = 0; i < points.size(); ++i) {
    const TimeError& p = points[i];
    if (!valid(p)) continue;
    on[i] = std::none_of(points.begin(), points.end(), [&](const TimeError& q) {
      return valid(q) && q.time <= p.time && q.error <= p.error &&
             (q.time < p.time || q.error < p.error);
    });
  }
  return on;
}

double metricValue(const Table& t, size_t row, const std::string& metric) {
  if (metric == "air_rel_rmse_pct") return 100.0 * t.value(row, "air_rel_rmse");
  return t.value(row, metric);
}

void markFronts(Table& t, const std::string& time_column, const std::vector<std::string>& metrics,
                const std::vector<std::string>& axes) {
  const size_t group_col = t.addColumn("front_group", false);
  const size_t time_col = t.addColumn("front_time", false);
  std::vector<size_t> front_cols;
  for (const auto& m : metrics) front_cols.push_back(t.addColumn("on_front." + m, true));

  // Groups in order of first appearance: (scene, truth) -> rows.
  std::vector<std::pair<std::string, std::string>> keys;
  std::map<std::pair<std::string, std::string>, std::vector<size_t>> members;
  for (size_t r = 0; r < t.rows.size(); ++r) {
    t.rows[r][group_col].clear();
    t.rows[r][time_col].clear();
    for (size_t c : front_cols) t.rows[r][c].clear();
    if (t.cell(r, "status") != "ok") continue;
    const auto key = std::make_pair(t.cell(r, "scene"), t.cell(r, "truth"));
    if (!members.contains(key)) keys.push_back(key);
    members[key].push_back(r);
  }

  for (const auto& key : keys) {
    const std::vector<size_t>& rows = members[key];
    // A scene with one truth is named by the scene; otherwise by the swept values that its
    // groups do not share (lesson 05: "torus_pyramid; one truth (area r=0.0345) for pcf.radius=1
    // shadow.size=1024 or pcf.radius=2 shadow.size=2048").
    std::vector<std::pair<std::string, std::string>> siblings;
    for (const auto& k : keys) {
      if (k.first == key.first) siblings.push_back(k);
    }
    std::string name = key.first;
    if (siblings.size() > 1) {
      auto valuesOf = [&](const std::pair<std::string, std::string>& k, const std::string& axis) {
        std::set<std::string> v;
        for (size_t r : members[k]) v.insert(t.cell(r, axis));
        return v;
      };
      std::vector<std::string> telling;  // the axes whose values differ between the groups
      for (const auto& axis : axes) {
        for (const auto& other : siblings) {
          if (other != key && valuesOf(other, axis) != valuesOf(key, axis)) {
            telling.push_back(axis);
            break;
          }
        }
      }
      std::vector<std::string> combos;
      for (size_t r : rows) {
        std::string combo;
        for (const auto& axis : telling) {
          combo += (combo.empty() ? "" : " ") + axis + "=" + t.cell(r, axis);
        }
        if (std::find(combos.begin(), combos.end(), combo) == combos.end()) {
          combos.push_back(combo);
        }
      }
      std::string which;
      for (const auto& c : combos) which += (which.empty() ? "" : " or ") + c;
      name.append("; one truth (").append(key.second).append(")");
      if (!which.empty()) name.append(" for ").append(which);
    }
    for (size_t m = 0; m < metrics.size(); ++m) {
      std::vector<TimeError> points;
      for (size_t r : rows)
        points.push_back({t.value(r, time_column), metricValue(t, r, metrics[m])});
      const std::vector<bool> on = paretoFront(points);
      for (size_t i = 0; i < rows.size(); ++i) {
        const bool measured = std::isfinite(points[i].time) && std::isfinite(points[i].error);
        t.rows[rows[i]][front_cols[m]] = std::string(measured ? (on[i] ? "1" : "0") : "");
      }
    }
    for (size_t r : rows) {
      t.rows[r][group_col] = name;
      t.rows[r][time_col] = time_column;
    }
  }
}

}  // namespace shadows::bench
