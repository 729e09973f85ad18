// The table behind <lesson>.csv, and its Pareto fronts: the configurations no other one beats
// in both time and error. Computed here once and written into the table (on_front.<metric>,
// front_group), so the plot and bench/tables.py read the same front. No GL, no lessons:
// bench_front_test checks it on a hand-made CSV.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace shadows::bench {

struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::vector<bool> numeric;  // per column: written unquoted in JSON

  // The column's index, or -1.
  int column(const std::string& name) const;
  // The column's index, appended (empty in every row) if it is not there yet.
  size_t addColumn(const std::string& name, bool numeric);
  // Row `r`'s cell of column `name`, "" where there is no such column.
  const std::string& cell(size_t r, const std::string& name) const;
  // The cell as a number; NaN where it is empty, "nan" or no number.
  double value(size_t r, const std::string& name) const;
};

// One CSV line (no newline), fields quoted where they need it.
std::string csvLine(const std::vector<std::string>& fields);
std::string toCsv(const Table& t);
// Reads a CSV as toCsv writes it (RFC 4180 quoting); "" or what is wrong.
std::string readCsv(const std::filesystem::path& path, Table& t);

struct TimeError {
  double time = 0.0, error = 0.0;
};

// Per point: is it on the front? A point is off when another is at least as fast and at least
// as accurate and strictly better in one of the two. Points with equal time and equal error do
// not beat each other, so tied points are on the front together. NaN is never on it.
std::vector<bool> paretoFront(const std::vector<TimeError>& points);

// A plot metric's value in a row: the CSV column it comes from, scaled
// (air_rel_rmse_pct = 100 x air_rel_rmse); NaN where it was not measured.
double metricValue(const Table& t, size_t row, const std::string& metric);

// Fills, for every row whose status is ok:
//   front_group       the rows whose errors compare: the same scene and the same truth (lesson
//                     05's area light grows with pcf.radius / shadow.size, and an error against
//                     another truth is another question); named by the scene, and where a scene
//                     has several, by the truth and what tells them apart in `axes`:
//                     "torus_pyramid; one truth (area r=0.0345) for pcf.radius=1 ..."
//   front_time        `time_column`, the time the front was taken on (the plot's x)
//   on_front.<metric> 1 or 0 within the row's group, for each metric
// Columns already there are overwritten; rows that did not run get empty cells.
void markFronts(Table& t, const std::string& time_column, const std::vector<std::string>& metrics,
                const std::vector<std::string>& axes);

}  // namespace shadows::bench
