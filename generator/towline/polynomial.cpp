#include "towline/polynomial.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/Dense>

#include "common/error.hpp"

namespace towdb::towline {

namespace {

// The 9 monomials xi^m xi_dot^n in coefficient order.
std::array<double, PolynomialCoefficients::kCount> monomials(double x, double v) {
  return {x, v, x * x, x * v, v * v, x * x * x, x * x * v, x * v * v, v * v * v};
}

// Weighted least squares over the active rows, for the free columns only
// (column 0 left out when a10 is held). `c` gets all 9 scaled coefficients.
Eigen::VectorXd solve_active(const Eigen::MatrixXd& a, const Eigen::VectorXd& t, const Eigen::VectorXd& w,
                             const std::vector<bool>& active, double fixed_c0) {
  constexpr int kCols = PolynomialCoefficients::kCount;
  const bool held = !std::isnan(fixed_c0);
  const int first = held ? 1 : 0;
  const int free_cols = kCols - first;
  std::vector<int> idx;
  for (int i = 0; i < static_cast<int>(active.size()); ++i) {
    if (active[static_cast<std::size_t>(i)]) idx.push_back(i);
  }
  require_input(static_cast<int>(idx.size()) >= free_cols, "polynomial fit active samples",
                static_cast<double>(idx.size()), "need at least " + std::to_string(free_cols));
  Eigen::MatrixXd a_act(static_cast<Eigen::Index>(idx.size()), free_cols);
  Eigen::VectorXd t_act(static_cast<Eigen::Index>(idx.size()));
  for (std::size_t r = 0; r < idx.size(); ++r) {
    const auto row = static_cast<Eigen::Index>(r);
    a_act.row(row) = w(idx[r]) * a.row(idx[r]).tail(free_cols);
    t_act(row) = w(idx[r]) * (t(idx[r]) - (held ? fixed_c0 * a(idx[r], 0) : 0.0));
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a_act);
  if (qr.rank() < free_cols) {
    throw InputError("polynomial fit: the samples determine only " + std::to_string(qr.rank()) + " of " +
                     std::to_string(free_cols) +
                     " free coefficients (excitations must span amplitude and phase)");
  }
  Eigen::VectorXd c(kCols);
  if (held) c(0) = fixed_c0;
  c.tail(free_cols) = qr.solve(t_act);
  return c;
}

}  // namespace

PolynomialFit fit_polynomial(const std::vector<TensionSample>& samples,
                             double max_dynamic_tension_n, double min_dynamic_tension_n,
                             SlackFit slack, const SmallMotionFit& small) {
  require_input(!std::isnan(max_dynamic_tension_n), "polynomial fit max dynamic tension [N]",
                max_dynamic_tension_n, "must not be NaN");
  require_input(min_dynamic_tension_n < max_dynamic_tension_n, "polynomial fit min dynamic tension [N]",
                min_dynamic_tension_n, "must be below the max dynamic tension");
  require_input(small.weights.empty() || small.weights.size() == samples.size(), "polynomial fit weights count",
                static_cast<double>(small.weights.size()), "must be 0 or the number of samples");
  require_input(std::isnan(small.fixed_a10_n_m) || std::isfinite(small.fixed_a10_n_m),
                "polynomial fit fixed a10 [N/m]", small.fixed_a10_n_m, "must be finite or NaN (fitted)");
  std::vector<const TensionSample*> used;
  std::vector<double> used_weights;
  used.reserve(samples.size());
  double x_scale = 0.0;
  double v_scale = 0.0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const TensionSample& s = samples[i];
    require_input(std::isfinite(s.xi_m) && std::isfinite(s.xi_dot_m_s) && std::isfinite(s.tau_n),
                  "polynomial fit sample tau [N]", s.tau_n, "samples must be finite");
    const double weight = small.weights.empty() ? 1.0 : small.weights[i];
    require_input(std::isfinite(weight) && weight > 0.0, "polynomial fit weight", weight, "must be finite and > 0");
    if (s.tau_n > max_dynamic_tension_n) continue;
    used.push_back(&s);
    used_weights.push_back(weight);
    x_scale = std::max(x_scale, std::abs(s.xi_m));
    v_scale = std::max(v_scale, std::abs(s.xi_dot_m_s));
  }
  constexpr int kCols = PolynomialCoefficients::kCount;
  const int rows = static_cast<int>(used.size());
  require_input(rows >= kCols, "polynomial fit samples below breaking strength", rows,
                "need at least 9");
  require_input(x_scale > 0.0 && v_scale > 0.0, "polynomial fit extension range [m]", x_scale,
                "samples must span non-zero extension and extension rate");

  Eigen::MatrixXd a(rows, kCols);
  Eigen::VectorXd t(rows);
  Eigen::VectorXd w(rows);
  std::vector<bool> one_sided(static_cast<std::size_t>(rows));
  for (int i = 0; i < rows; ++i) {
    const TensionSample& s = *used[static_cast<std::size_t>(i)];
    const auto m = monomials(s.xi_m / x_scale, s.xi_dot_m_s / v_scale);
    for (int k = 0; k < kCols; ++k) a(i, k) = m[static_cast<std::size_t>(k)];
    t(i) = s.tau_n;
    w(i) = used_weights[static_cast<std::size_t>(i)];
    one_sided[static_cast<std::size_t>(i)] = slack == SlackFit::kOneSided && s.slack;
  }
  // a10 in the scaled columns: a10 x = (a10 x_scale) (x / x_scale).
  const double fixed_c0 = small.fixed_a10_n_m * x_scale;
  // Active set: every two-sided row, plus the one-sided rows the current
  // polynomial violates (P > tau). Start from the ordinary least squares.
  std::vector<bool> active(static_cast<std::size_t>(rows), true);
  Eigen::VectorXd c;
  constexpr int kMaxActiveSetIterations = 100;
  for (int iteration = 0;; ++iteration) {
    c = solve_active(a, t, w, active, fixed_c0);
    const Eigen::VectorXd p = a * c;
    bool changed = false;
    for (int i = 0; i < rows; ++i) {
      const auto iu = static_cast<std::size_t>(i);
      if (!one_sided[iu]) continue;
      const bool violates = p(i) > t(i);
      if (violates != active[iu]) {
        active[iu] = violates;
        changed = true;
      }
    }
    if (!changed) break;
    if (iteration >= kMaxActiveSetIterations) {
      throw NumericalError("polynomial fit active set (one-sided slack samples) did not settle: iteration " +
                           std::to_string(iteration));
    }
  }

  PolynomialFit fit;
  for (int k = 0; k < kCols; ++k) {
    const auto& pw = PolynomialCoefficients::kPowers[static_cast<std::size_t>(k)];
    fit.coefficients.a[static_cast<std::size_t>(k)] =
        c(k) / (std::pow(x_scale, pw[0]) * std::pow(v_scale, pw[1]));
  }
  if (!std::isnan(small.fixed_a10_n_m)) fit.coefficients.a[0] = small.fixed_a10_n_m;  // exactly, not via scaling
  double sum_e2 = 0.0;
  double sum_t2 = 0.0;
  for (int i = 0; i < rows; ++i) {
    const TensionSample& s = *used[static_cast<std::size_t>(i)];
    double model = fit.coefficients.evaluate_n(s.xi_m, s.xi_dot_m_s);
    if (slack == SlackFit::kOneSided) model = std::max(model, min_dynamic_tension_n);
    const double e = model - s.tau_n;
    sum_e2 += e * e;
    sum_t2 += s.tau_n * s.tau_n;
    fit.max_error_n = std::max(fit.max_error_n, std::abs(e));
  }
  fit.rms_error_n = std::sqrt(sum_e2 / rows);
  fit.rms_tension_n = std::sqrt(sum_t2 / rows);
  fit.samples_used = rows;
  fit.samples_excluded = static_cast<int>(samples.size()) - rows;
  return fit;
}

double first_harmonic_n(const PolynomialCoefficients& c, double amplitude_m, double omega_rad_s) {
  const double a = amplitude_m;
  const double w = omega_rad_s;
  const double a3 = a * a * a;
  const double in_phase = c.a10() * a + 0.75 * c.a30() * a3 + 0.25 * c.a12() * a3 * w * w;
  const double quadrature = c.a01() * a * w + 0.25 * c.a21() * a3 * w + 0.75 * c.a03() * a3 * w * w * w;
  return std::hypot(in_phase, quadrature);
}

EquivalentLinearLine gaussian_equivalent_line(const PolynomialCoefficients& c, double xi_variance_m2,
                                              double xi_dot_variance_m2_s2) {
  const double s2 = xi_variance_m2, v2 = xi_dot_variance_m2_s2;
  return {c.a10() + 3.0 * c.a30() * s2 + c.a12() * v2, c.a01() + c.a21() * s2 + 3.0 * c.a03() * v2};
}

void ExcitationOptions::validate() const {
  require_in_range("excitation.frequencies_rad_s count", static_cast<double>(frequencies_rad_s.size()),
                   2.0, 1000.0);
  require_in_range("excitation.amplitude_fractions count",
                   static_cast<double>(amplitude_fractions.size()), 2.0, 1000.0);
  for (double w : frequencies_rad_s) require_in_range("excitation.frequencies_rad_s", w, 1e-3, 20.0);
  for (double f : amplitude_fractions) require_in_range("excitation.amplitude_fractions", f, 1e-4, 1.0);
  require_in_range("excitation.max_amplitude_m", max_amplitude_m, 1e-3, 100.0);
  require_in_range("excitation.max_velocity_m_s", max_velocity_m_s, 1e-3, 100.0);
}

std::vector<Excitation> excitation_set(const ExcitationOptions& options) {
  options.validate();
  std::vector<Excitation> set;
  for (double w : options.frequencies_rad_s) {
    const double a_max = std::min(options.max_amplitude_m, options.max_velocity_m_s / w);
    for (double f : options.amplitude_fractions) set.push_back({f * a_max, w});
  }
  return set;
}

}  // namespace towdb::towline
