// tests/elliptic/reference_table.hpp — reads the mpmath tables of tests/data/gen_elliptic.py and
// accumulates the largest relative error (in units of the epsilon of the type under test).
#pragma once

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <stdexcept>
#include <sstream>
#include <string>
#include <vector>

namespace gecko_test {

struct reference_table {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;

  explicit reference_table(const std::string& name) {
    const std::string path = std::string(GECKO_TEST_DATA_DIR) + "/" + name;
    std::ifstream in(path);
    REQUIRE(in.good());
    std::string line;
    std::getline(in, line);
    header = split(line);
    while (std::getline(in, line)) {
      if (line.empty()) continue;
      rows.push_back(split(line));
      REQUIRE(rows.back().size() == header.size());
    }
    REQUIRE(rows.size() > 100);
  }

  std::size_t column(const std::string& name) const {
    for (std::size_t i = 0; i < header.size(); ++i)
      if (header[i] == name) return i;
    FAIL("no column " << name);
    return 0;
  }

  // An input cell: the shortest decimal string of a double, so it must be parsed AS A DOUBLE
  // (strtold of "0.1" is not the double 0.1) and then converted exactly to T.
  template <class T>
  T get(std::size_t row, std::size_t col) const {
    return static_cast<T>(std::strtod(rows[row][col].c_str(), nullptr));
  }
  // A reference value cell: 30 significant digits.
  long double value(std::size_t row, std::size_t col) const {
    return std::strtold(rows[row][col].c_str(), nullptr);
  }
  const std::string& text(std::size_t row, std::size_t col) const { return rows[row][col]; }

 private:
  static std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> out;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) out.push_back(cell);
    return out;
  }
};

// Relative error of `got` against `want` in units of epsilon of T (absolute when want == 0).
template <class T>
long double error_in_eps(T got, long double want) {
  if (std::isnan(static_cast<long double>(got))) return std::numeric_limits<long double>::infinity();
  if (std::isinf(want) || std::isinf(static_cast<long double>(got)))
    return static_cast<long double>(got) == want ? 0.0L : std::numeric_limits<long double>::infinity();
  const long double e = std::fabs(static_cast<long double>(got) - want);
  const long double scale = want == 0 ? 1.0L : std::fabs(want);
  return e / scale / static_cast<long double>(std::numeric_limits<T>::epsilon());
}

// Worst error per region, with the row that produced it, for the test log.
struct error_tally {
  struct entry {
    long double worst = 0;
    std::size_t row = 0;
    std::size_t count = 0;
  };
  std::map<std::string, entry> by_region;
  entry overall;

  void add(const std::string& region, long double err, std::size_t row) {
    auto& e = by_region[region];
    ++e.count;
    ++overall.count;
    if (!(err <= e.worst)) { e.worst = err; e.row = row; }
    if (!(err <= overall.worst)) { overall.worst = err; overall.row = row; }
  }

  std::string report(const std::string& what) const {
    std::ostringstream os;
    os.precision(3);
    os << what << ": max error " << static_cast<double>(overall.worst) << " eps over "
       << overall.count << " rows (table row " << overall.row + 2 << ")";
    for (const auto& kv : by_region)
      os << "\n    " << kv.first << ": " << static_cast<double>(kv.second.worst) << " eps ("
         << kv.second.count << " rows, worst at table row " << kv.second.row + 2 << ")";
    return os.str();
  }
};

}  // namespace gecko_test

namespace gecko_test {

// Runs `eval(row) -> T` against `want(row) -> long double` over every table row accepted by
// `use(row)`, tallies the errors by the table's region column, prints them, and returns them.
template <class T, class Eval, class Want, class Use>
error_tally tally_table(const reference_table& t, const std::string& what, Eval eval, Want want,
                        Use use) {
  error_tally tally;
  const std::size_t region = t.column("region");
  for (std::size_t i = 0; i < t.rows.size(); ++i) {
    if (!use(i)) continue;
    tally.add(t.text(i, region), error_in_eps<T>(eval(i), want(i)), i);
  }
  WARN(tally.report(what));
  return tally;
}

// A float input is usable when rounding the table's double to float keeps it finite and
// normal (or exactly zero), so that the float problem is the double problem up to rounding.
inline bool float_representable(double v) {
  const float f = static_cast<float>(v);
  return std::isfinite(f) && (v == 0 || std::fabs(f) >= std::numeric_limits<float>::min());
}

}  // namespace gecko_test

namespace gecko_test {

// The message of the std::domain_error thrown by f(), or "no exception".
template <class F>
std::string domain_error_message(F f) {
  try {
    f();
  } catch (const std::domain_error& e) {
    return std::string(e.what());
  }
  return std::string("no exception");
}

}  // namespace gecko_test
