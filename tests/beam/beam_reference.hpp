// Reads tests/data/beam_reference.csv (written by tests/data/gen_beam_reference.py, mpmath at
// 30 digits): rows "name,quantity,value".
#pragma once

#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>

namespace gecko_test {

inline const std::map<std::string, long double>& beam_reference() {
  static const std::map<std::string, long double> table = [] {
    std::map<std::string, long double> t;
    std::ifstream in(std::string(GECKO_TEST_DATA_DIR) + "/beam_reference.csv");
    if (!in) throw std::runtime_error("cannot open beam_reference.csv");
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line)) {
      std::stringstream ss(line);
      std::string name, qty, value;
      std::getline(ss, name, ',');
      std::getline(ss, qty, ',');
      std::getline(ss, value, ',');
      t[name + "." + qty] = std::stold(value);
    }
    return t;
  }();
  return table;
}

inline long double beam_ref(const std::string& key) {
  auto it = beam_reference().find(key);
  if (it == beam_reference().end()) throw std::runtime_error("no reference value " + key);
  return it->second;
}

}  // namespace gecko_test
