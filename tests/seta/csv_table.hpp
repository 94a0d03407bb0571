// tests/seta/csv_table.hpp — reads the reference tables of tests/data/*.py (comma-separated, one
// header line) for the seta tests: one reader instead of one per test file.
#pragma once

#include <catch2/catch.hpp>

#include <cstddef>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "gecko/seta/two_level_seta.hpp"

namespace gecko_test {

// A number cell: the generators write doubles by repr, "inf" for an infinite rigidity, and leave a
// cell empty where the quantity does not exist (no minimum, no fold): that reads as NaN.
inline double parse(const std::string& s) {
  if (s == "inf") return std::numeric_limits<double>::infinity();
  if (s.empty()) return std::numeric_limits<double>::quiet_NaN();
  return std::stod(s);
}

// One line's cells; a trailing comma is a trailing empty cell.
inline std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream ss(line);
  std::string cell;
  while (std::getline(ss, cell, ',')) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.push_back("");
  return cells;
}

struct csv_table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;

  std::size_t col(const std::string& name) const {
    for (std::size_t i = 0; i < header.size(); ++i)
      if (header[i] == name) return i;
    FAIL("missing column " << name);
    return 0;
  }
};

// The table at `path` (an empty table when the file cannot be read: callers REQUIRE their row count).
inline csv_table read_csv_table(const std::string& path) {
  csv_table out;
  std::ifstream in(path);
  std::string line;
  if (!std::getline(in, line)) return out;
  out.header = split_csv_line(line);
  while (std::getline(in, line))
    if (!line.empty()) out.rows.push_back(split_csv_line(line));
  return out;
}

// The design of a row of a table with the columns EI1 ... w (the reference tables' design columns).
inline gecko::TwoLevelSeta<double> design_of(const csv_table& t, const std::vector<std::string>& r) {
  gecko::TwoLevelSeta<double> s;
  s.EI1 = parse(r[t.col("EI1")]);
  s.EI2 = parse(r[t.col("EI2")]);
  s.EA1 = parse(r[t.col("EA1")]);
  s.EA2 = parse(r[t.col("EA2")]);
  s.l1 = parse(r[t.col("l1")]);
  s.l2 = parse(r[t.col("l2")]);
  s.alpha1 = parse(r[t.col("alpha1")]);
  s.alpha2 = parse(r[t.col("alpha2")]);
  s.w = parse(r[t.col("w")]);
  return s;
}

}  // namespace gecko_test
