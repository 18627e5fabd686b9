// Bit-exact byte encoding of CaseSpec and CaseOutcome for the messages
// between MPI ranks (doubles are copied as their 8 bytes, never as text).
// Little-endian host layout: every rank runs the same binary on the same
// kind of machine (the one-cluster case); a header byte guards the format.
#ifndef TOWDB_SWEEP_SERIALIZE_HPP
#define TOWDB_SWEEP_SERIALIZE_HPP

#include <cstdint>
#include <string>
#include <vector>

#include "sweep/spec/case.hpp"

namespace towdb::sweep {

using Bytes = std::vector<std::uint8_t>;

class ByteWriter {
 public:
  void u8(std::uint8_t v) { bytes_.push_back(v); }
  void i64(std::int64_t v);
  void f64(double v);
  void opt_f64(const std::optional<double>& v);
  void str(const std::string& s);
  Bytes take() { return std::move(bytes_); }

 private:
  Bytes bytes_;
};

class ByteReader {
 public:
  explicit ByteReader(const Bytes& bytes) : bytes_(bytes) {}
  std::uint8_t u8();
  std::int64_t i64();
  double f64();
  std::optional<double> opt_f64();
  std::string str();
  bool at_end() const { return pos_ == bytes_.size(); }

 private:
  void need(std::size_t n) const;
  const Bytes& bytes_;
  std::size_t pos_ = 0;
};

void write_spec(ByteWriter& w, const CaseSpec& spec);
CaseSpec read_spec(ByteReader& r);
void write_outcome(ByteWriter& w, const CaseOutcome& outcome);
CaseOutcome read_outcome(ByteReader& r);

}  // namespace towdb::sweep

#endif  // TOWDB_SWEEP_SERIALIZE_HPP
