#include "statistics/distributions.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "common/constants.hpp"
#include "common/error.hpp"

namespace towdb::statistics {
namespace {

void require_probability(double probability) {
  require_input(probability > 0.0 && probability < 1.0, "probability F", probability,
                "must be strictly between 0 and 1");
}

void require_blocks(double blocks) {
  require_input(std::isfinite(blocks) && blocks >= 1.0, "blocks (days D)", blocks,
                "must be a finite number >= 1");
}

// ln(1 - exp(-s)) for s = -ln F >= 0, accurate for s small and large.
double log_one_minus_exp_neg(double s) {
  return s > std::log(2.0) ? std::log1p(-std::exp(-s)) : std::log(-std::expm1(-s));
}

}  // namespace

// ---- Gumbel -----------------------------------------------------------------

void Gumbel::validate() const {
  require_input(std::isfinite(location), "gumbel.location", location, "must be finite");
  require_input(std::isfinite(scale) && scale > 0.0, "gumbel.scale", scale, "must be finite and > 0");
}

double Gumbel::log_cdf(double x) const { return -std::exp(-(x - location) / scale); }
double Gumbel::cdf(double x) const { return std::exp(log_cdf(x)); }
double Gumbel::log_sf(double x) const { return log_one_minus_exp_neg(std::exp(-(x - location) / scale)); }

double Gumbel::pdf(double x) const {
  const double z = (x - location) / scale;
  return std::exp(-z - std::exp(-z)) / scale;
}

double Gumbel::quantile(double probability) const {
  require_probability(probability);
  return location - scale * std::log(-std::log(probability));  // EQ-STAT-2
}

double Gumbel::mean() const { return location + kEulerGamma * scale; }
double Gumbel::variance() const { return kPi * kPi * scale * scale / 6.0; }

Gumbel Gumbel::for_blocks(double blocks) const {
  require_blocks(blocks);
  return Gumbel{location + scale * std::log(blocks), scale};  // EQ-STAT-4
}

// ---- GEV --------------------------------------------------------------------

void Gev::validate() const {
  require_input(std::isfinite(location), "gev.location", location, "must be finite");
  require_input(std::isfinite(scale) && scale > 0.0, "gev.scale", scale, "must be finite and > 0");
  require_input(std::isfinite(shape), "gev.shape", shape, "must be finite");
}

double Gev::upper_end() const {
  return shape < 0.0 ? location - scale / shape : std::numeric_limits<double>::infinity();
}

// -ln F(x) = (1 + xi z)^(-1/xi) = exp(-t), or +inf / 0 outside the support.
double Gev::log_cdf(double x) const {
  const double z = (x - location) / scale;
  if (shape == 0.0) return -std::exp(-z);
  const double y = 1.0 + shape * z;
  if (!(y > 0.0)) return shape > 0.0 ? -std::numeric_limits<double>::infinity() : 0.0;
  return -std::exp(-std::log1p(shape * z) / shape);
}

double Gev::cdf(double x) const { return std::exp(log_cdf(x)); }

double Gev::log_sf(double x) const {
  const double s = -log_cdf(x);
  if (s == 0.0) return -std::numeric_limits<double>::infinity();
  if (std::isinf(s)) return 0.0;
  return log_one_minus_exp_neg(s);
}

double Gev::pdf(double x) const {
  const double z = (x - location) / scale;
  double t = z;
  if (shape != 0.0) {
    const double y = 1.0 + shape * z;
    if (!(y > 0.0)) return 0.0;
    t = std::log1p(shape * z) / shape;
  }
  return std::exp(-(1.0 + shape) * t - std::exp(-t)) / scale;
}

double Gev::quantile(double probability) const {
  require_probability(probability);
  const double s = -std::log(probability);  // -ln F
  if (shape == 0.0) return location - scale * std::log(s);
  // x_F = mu + sigma (s^-xi - 1)/xi = mu + sigma expm1(-xi ln s)/xi (EQ-STAT-5).
  return location + scale * std::expm1(-shape * std::log(s)) / shape;
}

Gev Gev::for_blocks(double blocks) const {
  require_blocks(blocks);
  const double lnd = std::log(blocks);
  if (shape == 0.0) return Gev{location + scale * lnd, scale, 0.0};
  // EQ-STAT-4: mu + sigma (D^xi - 1)/xi, sigma D^xi.
  return Gev{location + scale * std::expm1(shape * lnd) / shape, scale * std::exp(shape * lnd), shape};
}

// ---- Empirical --------------------------------------------------------------

std::vector<EmpiricalPoint> empirical_distribution(std::span<const double> sample) {
  require_input(!sample.empty(), "sample size N", 0.0, "must be at least 1");
  std::vector<double> sorted(sample.begin(), sample.end());
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    require_input(std::isfinite(sorted[i]), "sample[" + std::to_string(i) + "]", sorted[i], "must be finite");
  }
  std::sort(sorted.begin(), sorted.end());
  const double denom = static_cast<double>(sorted.size()) + 1.0;
  std::vector<EmpiricalPoint> points(sorted.size());
  for (std::size_t i = 0; i < sorted.size(); ++i) {
    points[i] = {sorted[i], static_cast<double>(i + 1) / denom};  // EQ-STAT-1
  }
  return points;
}

double empirical_quantile(std::span<const double> sample, double probability) {
  const std::vector<EmpiricalPoint> pts = empirical_distribution(sample);
  const double n = static_cast<double>(pts.size());
  require_input(probability >= 1.0 / (n + 1.0) && probability <= n / (n + 1.0), "probability F", probability,
                "must lie in [1/(N+1), N/(N+1)] = [" + format_value(1.0 / (n + 1.0)) + ", " +
                    format_value(n / (n + 1.0)) + "] for N = " + format_value(n) +
                    " (the sample does not reach further; use a fitted distribution)");
  const double h = probability * (n + 1.0) - 1.0;  // 0-based fractional rank
  const std::size_t lo = std::min(static_cast<std::size_t>(std::floor(h)), pts.size() - 1);
  if (lo + 1 >= pts.size()) return pts[lo].value;
  const double frac = h - static_cast<double>(lo);
  return pts[lo].value + frac * (pts[lo + 1].value - pts[lo].value);
}

void require_fit_sample(std::span<const double> sample, std::size_t min_size, const char* what) {
  const std::string field = std::string(what) + ": sample size N";
  require_input(sample.size() >= min_size, field, static_cast<double>(sample.size()),
                "must be at least " + std::to_string(min_size));
  double lo = std::numeric_limits<double>::infinity();
  double hi = -lo;
  for (std::size_t i = 0; i < sample.size(); ++i) {
    require_input(std::isfinite(sample[i]), std::string(what) + ": sample[" + std::to_string(i) + "]",
                  sample[i], "must be finite");
    lo = std::min(lo, sample[i]);
    hi = std::max(hi, sample[i]);
  }
  require_input(hi > lo, std::string(what) + ": sample range (max - min)", hi - lo,
                "must be > 0 (a constant sample has no spread to fit)");
}

}  // namespace towdb::statistics
