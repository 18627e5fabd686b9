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

}  // namespace

PolynomialFit fit_polynomial(const std::vector<TensionSample>& samples,
                             double max_dynamic_tension_n, double min_dynamic_tension_n,
                             SlackFit slack) {
  require_input(!std::isnan(max_dynamic_tension_n), "polynomial fit max dynamic tension [N]",
                max_dynamic_tension_n, "must not be NaN");
  require_input(min_dynamic_tension_n < max_dynamic_tension_n, "polynomial fit min dynamic tension [N]",
                min_dynamic_tension_n, "must be below the max dynamic tension");
  std::vector<const TensionSample*> used;
  used.reserve(samples.size());
  double x_scale = 0.0;
  double v_scale = 0.0;
  for (const auto& s : samples) {
    require_input(std::isfinite(s.xi_m) && std::isfinite(s.xi_dot_m_s) && std::isfinite(s.tau_n),
                  "polynomial fit sample tau [N]", s.tau_n, "samples must be finite");
    if (s.tau_n > max_dynamic_tension_n) continue;
    used.push_back(&s);
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
  std::vector<bool> one_sided(static_cast<std::size_t>(rows));
  for (int i = 0; i < rows; ++i) {
    const TensionSample& s = *used[static_cast<std::size_t>(i)];
    const auto m = monomials(s.xi_m / x_scale, s.xi_dot_m_s / v_scale);
    for (int k = 0; k < kCols; ++k) a(i, k) = m[static_cast<std::size_t>(k)];
    t(i) = s.tau_n;
    one_sided[static_cast<std::size_t>(i)] = slack == SlackFit::kOneSided && s.slack;
  }
  // Active set: every two-sided row, plus the one-sided rows the current
  // polynomial violates (P > tau). Start from the ordinary least squares.
  std::vector<bool> active(static_cast<std::size_t>(rows), true);
  Eigen::VectorXd c;
  constexpr int kMaxActiveSetIterations = 100;
  for (int iteration = 0;; ++iteration) {
    std::vector<int> idx;
    for (int i = 0; i < rows; ++i) {
      if (active[static_cast<std::size_t>(i)]) idx.push_back(i);
    }
    require_input(static_cast<int>(idx.size()) >= kCols, "polynomial fit active samples",
                  static_cast<double>(idx.size()), "need at least 9");
    Eigen::MatrixXd a_act(static_cast<Eigen::Index>(idx.size()), kCols);
    Eigen::VectorXd t_act(static_cast<Eigen::Index>(idx.size()));
    for (std::size_t r = 0; r < idx.size(); ++r) {
      a_act.row(static_cast<Eigen::Index>(r)) = a.row(idx[r]);
      t_act(static_cast<Eigen::Index>(r)) = t(idx[r]);
    }
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(a_act);
    if (qr.rank() < kCols) {
      throw InputError("polynomial fit: the samples determine only " + std::to_string(qr.rank()) +
                       " of 9 coefficients (excitations must span amplitude and phase)");
    }
    c = qr.solve(t_act);
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
