// towdb::sea -- wave spectra and one-day random sea records in the encounter
// frame, for the long-time towing simulation (thesis 3.7, program sapc97;
// docs/physics.md section 1).
//
// ============================================================================
// GOVERNING EQUATIONS
// ============================================================================
// Units: w, w_e [rad/s]; S [m^2 s/rad]; Hs [m]; periods [s]; U, V [m/s];
// headings [rad]; amplitudes [m]; k [rad/m]; g = kGravity_m_s2.
//
// EQ-SEA-1  Pierson-Moskowitz (1964), fully developed sea, wind U at 19.5 m:
//             S(w) = alpha g^2 w^-5 exp(-beta (g / (U w))^4),  alpha = 0.0081, beta = 0.74
//           so A = alpha g^2, B = beta (g/U)^4 in the base shape S0 below, and
//             Hs = 4 sqrt(m0) = 2 sqrt(alpha/beta) U^2/g = 0.2092 U^2/g,
//             w_p = (4 beta / 5)^(1/4) g/U = 0.877 g/U.
// EQ-SEA-2  Bretschneider / ITTC two-parameter spectrum (thesis eq. 6.1-6.3):
//             S0(w) = A w^-5 exp(-B w^-4),   m0 = A/(4B) = Hs^2/16  =>  A = Hs^2 B / 4.
//           Derived here (EQ-SEA-4 with n = 0, 1; dS0/dw = 0):
//             w_p^4 = 4B/5,   T1 = 2 pi m0/m1 = 2 pi B^(-1/4) / Gamma(3/4),
//             T2 = 2 pi sqrt(m0/m2) = 2 pi (pi B)^(-1/4).
//           By mean period:  B = (2 pi / Gamma(3/4))^4 / T1^4 = 691.0 / T1^4,
//                            A = Hs^2 B / 4 = 172.8 Hs^2 / T1^4
//           (the ITTC's 173 and 691 are these, rounded to 3 digits).
//           By peak period:  B = (5/4) w_p^4, hence
//             T1 = Tp / ((5/4)^(1/4) Gamma(3/4)) = 0.7718 Tp,
//             T2 = Tp / (5 pi / 4)^(1/4)         = 0.7104 Tp.
//           (The OCR of the thesis prints another factor next to T_M: not used.)
// EQ-SEA-3  JONSWAP (Hasselmann et al. 1973), peak enhancement gamma in [1, 10]:
//             S(w) = C(gamma) S0(w) gamma^r,  r = exp(-(w - w_p)^2 / (2 sigma^2 w_p^2)),
//             sigma = 0.07 (w <= w_p), 0.09 (w > w_p),  B = (5/4) w_p^4,  A = Hs^2 B / 4,
//           C(gamma) computed by quadrature so that m0 = Hs^2/16 exactly
//           (DNV-RP-C205 3.5.5.2 approximates it by 1 - 0.287 ln gamma).
//           gamma = 1 is EQ-SEA-2 by peak period.
// EQ-SEA-4  Moments of S0 (substitute x = B/w^4):
//             m_n = int_0^inf w^n S0 dw = (A/4) B^((n-4)/4) Gamma(1 - n/4),  n < 4
//             int_0^w S0 dw' = (A / 4B) exp(-B / w^4)      (cumulative energy)
//           (m4 diverges: zero-crossing period T2 exists, crest period does not).
// EQ-SEA-5  Sea state = independent wave systems (wind sea + swell, thesis 7.1):
//             S(w, mu) = sum_s S_s(w) delta(mu - mu_s),  Hs = 4 sqrt(sum_s m0_s).
// EQ-SEA-6  Encounter frequency for forward speed V and heading mu (deep water):
//             w_e = w - k V cos(mu) = w - kappa w^2,  k = w^2/g,  kappa = V cos(mu)/g.
//           Derivation (re-derived here): an earth-fixed wave
//             zeta = a cos(w t - k (X cos mu + Y sin mu) + phi)
//           travels in direction mu; with ship axes x = X - V t, y = Y,
//             zeta = Re{ a exp(-i k (x cos mu + y sin mu)) exp(i (w_e t + phi)) }.
//           kappa <= 0 (beam to head seas): w_e rises monotonically with w.
//           kappa > 0 (following quartering seas) the map folds: three branches
//             w in [0, w*]   : w_e rises 0 -> 1/(4 kappa),        w* = 1/(2 kappa)
//             w in [w*, 2w*] : w_e falls 1/(4 kappa) -> 0
//             w > 2 w*       : w_e < 0 (waves overtaken by the ship)
//           and several absolute frequencies share one |w_e|.
// EQ-SEA-7  Discretisation (deterministic amplitudes, thesis 3.7): a record of
//           period T has the encounter-frequency grid dw = 2 pi / T (bins m).
//           Each branch b (of each system) owns the bins m = c W + r_b,
//           r_b = 1..n_branches, W = max(bins_per_component, n_branches), and a
//           cell of |w_e| in [m - W/2, m + W/2) dw (the first starts at 0).
//           Component j of that cell:
//             a_j = sqrt(2 E_j),  E_j = int over {w on branch b : |w_e| in cell} S(w) dw,
//             w_j = the branch frequency with |w_e| = m dw (clipped to the cell),
//             phi_j uniform on [0, 2 pi) (2^24 levels), drawn from RandomStream(seed, day).
//           No two components share a bin (folded branches interleave), so the
//           record's variance is exactly sum E_j for every phase draw, and
//           sum_j E_j = int S dw over all kept cells (>= (1 - f) m0 with the
//           automatic cutoff). Cutoff w_c: bins m <= floor(w_c / dw) are kept;
//           N >= 2 floor(w_c/dw) + 2 samples, dt = T/N <= pi / w_c (thesis eq. 3-22).
// EQ-SEA-8  First-order record of transfer function H (per unit wave amplitude,
//           time factor exp(+i w_e t), phase referred to the vessel origin):
//             x(t) = sum_j Re{ H(w_j) a_j exp(i (w_e,j t + phi_j)) }
//           computed by one c2r inverse FFT of size N with
//             X[m_j] = (1/2) a_j H(w_j) exp(i phi_j)                 (w_e,j >= 0)
//             X[m_j] = (1/2) a_j conj(H(w_j)) exp(-i phi_j)          (w_e,j < 0)
//           since x[n] = sum_{m} 2 Re(X[m] exp(2 pi i m n / N)) (FFTW backward).
//           Parseval: mean of x^2 over the record = sum_j a_j^2 |H_j|^2 / 2.
//           A point of the hull at (x, y) sees H = exp(-i k (x cos mu + y sin mu)):
//           the tow, G metres astern of the tug, sees exp(+i k G cos mu) relative to
//           the tug's origin. The caller puts that lag into its H (thesis eq. 3-21).
// EQ-SEA-9  Second-order slowly varying force, Newman (1974) approximation
//           T_jl = sqrt(T_jj T_ll), with D(w) = R_aw(w)/zeta_a^2 >= 0:
//             E(t)  = sum_j a_j sqrt(D(w_j)) exp(i (w_e,j t + phi_j))   (signed w_e)
//             f2(t) = -|E(t)|^2 + sum_j a_j^2 D(w_j)
//           |E|^2 holds difference frequencies w_e,j - w_e,l only. The removed mean
//           sum_j a_j^2 D_j = 2 int D S dw is the mean added resistance (thesis
//           eq. 2.2), already inside the mean tension. E = p + i q is built from
//           two c2r transforms (p = Re E, q = Im E): cheaper than one c2c here.
//           Where D changes sign (added resistance that is a thrust in part of
//           following seas, EQ-AR-4 when kept aft of beam), the components with
//           D < 0 form a second envelope E- from sqrt(-D) and
//             f2(t) = -|E+(t)|^2 + |E-(t)|^2 + sum_j a_j^2 D(w_j);
//           cross terms between the two signs are left out (sqrt(D_j D_l) is
//           not real). With D >= 0 everywhere E- is empty and f2 is unchanged.
//           A series that acts at a point other than the reference origin
//           (the tow, G astern of the tug) uses the envelope there:
//             E(t)  = sum_j a_j sqrt(D(w_j)) exp(i (w_e,j t + phi_j + theta_j)),
//           theta_j = k_j G cos mu, the phase of EQ-SEA-8's H of that point
//           (thesis eq. 3-21); conjugated with phi_j when w_e,j < 0.
//
// NOTES FOR CALLERS
//   * Cost: per case, RecordPlan + DaySynthesizer (O(J) spectrum integrals, one
//     FFTW plan: the stored wisdom's for N = 86,400, else FFTW_ESTIMATE's,
//     fft_wisdom.hpp); per day, J phasors and one c2r of size N per linear
//     series, two per drift series (N = 55296 for a 2 rad/s cutoff and a day).
//   * A record sampled at dt = pi / w_c under-reads its peaks by about
//     (w dt)^2 / 24 (2% for wave elevation at dt = 0.63 s): set
//     max_time_step_s when maxima of the records themselves matter.
//   * FFTW planning is serialised by a lock inside this module only; any other
//     module that makes FFTW plans concurrently must not race with it.
//
// SOURCES
//   Pierson & Moskowitz (1964) J. Geophys. Res. 69(24); ITTC (1978) 15th ITTC,
//   Seakeeping Committee; Hasselmann et al. (1973) Dtsch. Hydrogr. Z. A8(12);
//   DNV-RP-C205 (2010) 3.5.5; Newman (1974) Int. Symp. Dynamics of Marine
//   Vehicles and Structures in Waves, London;
//   Desroches (1997) MIT thesis, 3.7 and 6.1 (eq. 3-21, 3-22, 6.1-6.3);
//   Tucker, Challenor & Carter (1984) Appl. Ocean Res. 6(2) on deterministic
//   vs random amplitudes; Frigo & Johnson (2005) Proc. IEEE 93(2) (FFTW).
//
// CONVENTIONS
//   Heading mu: angle from the vessel's course to the direction the waves travel:
//   0 = following (trailing) seas, pi/2 = beam seas, pi = head seas (MIT 5D
//   convention). Only cos(mu) enters here; the side matters only to the caller's H.
//   Time factor exp(+i w_e t); a component's phase phi is that of the wave
//   elevation at the vessel origin. A transfer function from a solver that uses
//   exp(-i w t) must be conjugated before it is passed here.
#ifndef TOWDB_SEA_SEA_HPP
#define TOWDB_SEA_SEA_HPP

#include "sea/record.hpp"
#include "sea/spectrum.hpp"

#endif  // TOWDB_SEA_SEA_HPP
