#include "sweep/build/serialize.hpp"

#include <cstring>

#include "common/error.hpp"

namespace towdb::sweep {

namespace {
// Format tags: a message from a different build of towdb is refused.
constexpr std::uint8_t kSpecTag = 0x53;     // 'S'
constexpr std::uint8_t kOutcomeTag = 0x4F;  // 'O'
}  // namespace

void ByteWriter::i64(std::int64_t v) {
  std::uint8_t b[sizeof v];
  std::memcpy(b, &v, sizeof v);
  bytes_.insert(bytes_.end(), b, b + sizeof v);
}

void ByteWriter::f64(double v) {
  std::uint8_t b[sizeof v];
  std::memcpy(b, &v, sizeof v);
  bytes_.insert(bytes_.end(), b, b + sizeof v);
}

void ByteWriter::opt_f64(const std::optional<double>& v) {
  u8(v ? 1 : 0);
  if (v) f64(*v);
}

void ByteWriter::str(const std::string& s) {
  i64(static_cast<std::int64_t>(s.size()));
  bytes_.insert(bytes_.end(), s.begin(), s.end());
}

void ByteReader::need(std::size_t n) const {
  if (bytes_.size() - pos_ < n) {
    throw StorageError("malformed case message: " + std::to_string(n) + " more bytes needed at offset " +
                       std::to_string(pos_) + " of " + std::to_string(bytes_.size()));
  }
}

std::uint8_t ByteReader::u8() {
  need(1);
  return bytes_[pos_++];
}

std::int64_t ByteReader::i64() {
  std::int64_t v = 0;
  need(sizeof v);
  std::memcpy(&v, bytes_.data() + pos_, sizeof v);
  pos_ += sizeof v;
  return v;
}

double ByteReader::f64() {
  double v = 0;
  need(sizeof v);
  std::memcpy(&v, bytes_.data() + pos_, sizeof v);
  pos_ += sizeof v;
  return v;
}

std::optional<double> ByteReader::opt_f64() {
  if (u8() == 0) return std::nullopt;
  return f64();
}

std::string ByteReader::str() {
  const std::int64_t n = i64();
  if (n < 0) throw StorageError("malformed case message: negative string length");
  need(static_cast<std::size_t>(n));
  std::string s(reinterpret_cast<const char*>(bytes_.data() + pos_), static_cast<std::size_t>(n));
  pos_ += static_cast<std::size_t>(n);
  return s;
}

void write_spec(ByteWriter& w, const CaseSpec& s) {
  w.u8(kSpecTag);
  w.str(s.tug);
  w.str(s.tow);
  w.f64(s.speed_kt);
  w.f64(s.nominal_speed_kt);
  w.u8(static_cast<std::uint8_t>(s.sea.kind));
  w.opt_f64(s.sea.wind_kt);
  w.opt_f64(s.sea.hs_ft);
  w.opt_f64(s.sea.tp_s);
  w.opt_f64(s.sea.gamma);
  w.u8(s.sea.swell ? 1 : 0);
  if (s.sea.swell) {
    w.f64(s.sea.swell->hs_ft);
    w.f64(s.sea.swell->tp_s);
    w.f64(s.sea.swell->heading_deg);
  }
  w.f64(s.heading_deg);
  w.u8(static_cast<std::uint8_t>(s.line));
  w.f64(s.length_ft);
  w.f64(s.mean_tension_lbf);
  w.str(s.mean_tension_label);
  w.opt_f64(s.calculated_mean_tension_lbf);
  w.i64(s.days);
  w.i64(s.seed);
  w.str(s.sweep_label);
  w.str(s.condition_key);
}

CaseSpec read_spec(ByteReader& r) {
  if (r.u8() != kSpecTag) throw StorageError("malformed case message: not a case specification");
  CaseSpec s;
  s.tug = r.str();
  s.tow = r.str();
  s.speed_kt = r.f64();
  s.nominal_speed_kt = r.f64();
  const std::uint8_t kind = r.u8();
  if (kind > static_cast<std::uint8_t>(SpectrumKind::kJonswap)) throw StorageError("malformed case message: spectrum");
  s.sea.kind = static_cast<SpectrumKind>(kind);
  s.sea.wind_kt = r.opt_f64();
  s.sea.hs_ft = r.opt_f64();
  s.sea.tp_s = r.opt_f64();
  s.sea.gamma = r.opt_f64();
  if (r.u8() != 0) {
    SwellSpec sw;
    sw.hs_ft = r.f64();
    sw.tp_s = r.f64();
    sw.heading_deg = r.f64();
    s.sea.swell = sw;
  }
  s.heading_deg = r.f64();
  const std::uint8_t line = r.u8();
  if (line > static_cast<std::uint8_t>(model::LineKind::kChain)) throw StorageError("malformed case message: line");
  s.line = static_cast<model::LineKind>(line);
  s.length_ft = r.f64();
  s.mean_tension_lbf = r.f64();
  s.mean_tension_label = r.str();
  s.calculated_mean_tension_lbf = r.opt_f64();
  s.days = static_cast<int>(r.i64());
  s.seed = r.i64();
  s.sweep_label = r.str();
  s.condition_key = r.str();
  return s;
}

void write_outcome(ByteWriter& w, const CaseOutcome& o) {
  w.u8(kOutcomeTag);
  const TowlineFitOutcome& f = o.fit;
  w.str(f.towline_model);
  w.f64(f.span_m);
  w.f64(f.sag_m);
  w.f64(f.lowest_elevation_m);
  w.f64(f.end_angle_tug_rad);
  w.f64(f.end_angle_tow_rad);
  w.f64(f.static_stiffness_n_per_m);
  w.f64(f.breaking_strength_n);
  for (double a : f.coefficients_si) w.f64(a);
  w.f64(f.fit_rms_n);
  w.f64(f.fit_max_error_n);
  w.i64(f.fit_samples);
  const CaseStatistics& s = o.statistics;
  for (double v : {s.gumbel_u_n, s.gumbel_alpha_per_n, s.daily_max_mean_n, s.daily_max_variance_n2, s.dynamic_999_n,
                   s.dynamic_99_n}) {
    w.f64(v);
  }
  w.opt_f64(s.empirical_999_n);
  w.opt_f64(s.empirical_99_n);
  w.f64(s.ci_level);
  w.f64(s.ci_low_n);
  w.f64(s.ci_high_n);
  for (const auto& v : {s.gumbel_ml_u_n, s.gumbel_ml_alpha_per_n, s.gev_mu_n, s.gev_sigma_n, s.gev_xi,
                        s.anderson_darling, s.ppcc}) {
    w.opt_f64(v);
  }
  w.f64(s.max_daily_max_n);
  w.f64(s.breaking_strength_n);
  w.u8(s.above_breaking_strength ? 1 : 0);
  w.f64(s.slack_fraction);
  w.f64(s.snatch_events_per_day);
  w.i64(static_cast<std::int64_t>(o.days.size()));
  for (const DayOutcome& d : o.days) {
    w.f64(d.max_dynamic_n);
    w.f64(d.slack_time_s);
    w.i64(d.snatch_events);
  }
}

CaseOutcome read_outcome(ByteReader& r) {
  if (r.u8() != kOutcomeTag) throw StorageError("malformed case message: not a case outcome");
  CaseOutcome o;
  TowlineFitOutcome& f = o.fit;
  f.towline_model = r.str();
  f.span_m = r.f64();
  f.sag_m = r.f64();
  f.lowest_elevation_m = r.f64();
  f.end_angle_tug_rad = r.f64();
  f.end_angle_tow_rad = r.f64();
  f.static_stiffness_n_per_m = r.f64();
  f.breaking_strength_n = r.f64();
  for (double& a : f.coefficients_si) a = r.f64();
  f.fit_rms_n = r.f64();
  f.fit_max_error_n = r.f64();
  f.fit_samples = static_cast<int>(r.i64());
  CaseStatistics& s = o.statistics;
  for (double* v : {&s.gumbel_u_n, &s.gumbel_alpha_per_n, &s.daily_max_mean_n, &s.daily_max_variance_n2,
                    &s.dynamic_999_n, &s.dynamic_99_n}) {
    *v = r.f64();
  }
  s.empirical_999_n = r.opt_f64();
  s.empirical_99_n = r.opt_f64();
  s.ci_level = r.f64();
  s.ci_low_n = r.f64();
  s.ci_high_n = r.f64();
  for (std::optional<double>* v : {&s.gumbel_ml_u_n, &s.gumbel_ml_alpha_per_n, &s.gev_mu_n, &s.gev_sigma_n,
                                   &s.gev_xi, &s.anderson_darling, &s.ppcc}) {
    *v = r.opt_f64();
  }
  s.max_daily_max_n = r.f64();
  s.breaking_strength_n = r.f64();
  s.above_breaking_strength = r.u8() != 0;
  s.slack_fraction = r.f64();
  s.snatch_events_per_day = r.f64();
  const std::int64_t n = r.i64();
  if (n < 0 || n > 100000000) throw StorageError("malformed case message: day count");
  o.days.resize(static_cast<std::size_t>(n));
  for (DayOutcome& d : o.days) {
    d.max_dynamic_n = r.f64();
    d.slack_time_s = r.f64();
    d.snatch_events = static_cast<int>(r.i64());
  }
  return o;
}

}  // namespace towdb::sweep
