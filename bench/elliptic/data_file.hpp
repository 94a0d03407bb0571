// bench/elliptic/data_file.hpp — reads the column files written by bench/elliptic/gen_inputs.py.
//
// Format (see gen_inputs.py): one ASCII header line
//     GECKOBENCH1 n=<rows> columns=<name>:<f8|f4>,...
// then the columns one after the other, little-endian IEEE float64 (f8) or float32 (f4).
// A self-describing header rather than a fixed record layout, so that the generator can add a
// column without silently shifting what the benchmark reads.
#pragma once

#include <cstdint>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace gecko_bench {

class column_file {
 public:
  explicit column_file(const std::string& path) : path_(path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw std::runtime_error("cannot open " + path + " (run bench/elliptic/gen_inputs.py)");
    std::string header;
    std::getline(in, header);
    std::istringstream hs(header);
    std::string magic, n_field, col_field;
    hs >> magic >> n_field >> col_field;
    if (magic != "GECKOBENCH1" || n_field.rfind("n=", 0) != 0 || col_field.rfind("columns=", 0) != 0)
      throw std::runtime_error(path + ": not a GECKOBENCH1 file");
    n_ = std::stoul(n_field.substr(2));
    std::istringstream cs(col_field.substr(8));
    std::string spec;
    while (std::getline(cs, spec, ',')) {
      const auto colon = spec.find(':');
      if (colon == std::string::npos) throw std::runtime_error(path + ": bad column " + spec);
      const std::string name = spec.substr(0, colon), type = spec.substr(colon + 1);
      std::vector<double> values(n_);
      if (type == "f8") {
        read_le<std::uint64_t, double>(in, values);
      } else if (type == "f4") {
        read_le<std::uint32_t, float>(in, values);
      } else {
        throw std::runtime_error(path + ": bad column type " + type);
      }
      columns_[name] = std::move(values);
    }
    if (!in || in.peek() != std::char_traits<char>::eof())
      throw std::runtime_error(path + ": size does not match its header");
  }

  std::size_t rows() const { return n_; }

  const std::vector<double>& operator[](const std::string& name) const {
    const auto it = columns_.find(name);
    if (it == columns_.end()) throw std::runtime_error(path_ + ": no column " + name);
    return it->second;
  }

 private:
  // Decode byte by byte: the files are little-endian whatever the host is.
  template <class UInt, class Float>
  void read_le(std::ifstream& in, std::vector<double>& out) {
    static_assert(sizeof(UInt) == sizeof(Float), "bit pattern and float must have the same size");
    std::vector<unsigned char> bytes(n_ * sizeof(UInt));
    in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    for (std::size_t i = 0; i < n_; ++i) {
      UInt bits = 0;
      for (std::size_t b = 0; b < sizeof(UInt); ++b)
        bits |= static_cast<UInt>(static_cast<UInt>(bytes[i * sizeof(UInt) + b]) << (8 * b));
      Float f;
      std::memcpy(&f, &bits, sizeof f);
      out[i] = static_cast<double>(f);
    }
  }

  std::string path_;
  std::size_t n_ = 0;
  std::map<std::string, std::vector<double>> columns_;
};

}  // namespace gecko_bench
