// The error analysis the paper announces in its Section 6, as formulas: every bound and identity
// of paper_notes/error_analysis.md (Statements 1-4), each a function of the data (u0, v0, f, COR,
// h, T, and for fb_newton its smoothing eps) so that experiments/error_analysis can check it on
// every run. Gap coordinates (phi = 0); theta in [0, 1) is the fraction of the contact step flown
// before the exact impact, V > 0 the exact impact speed, e the COR.
#pragma once

#include <cstdint>

namespace impact::error_analysis {

// ---- Statement 1: free flight ----

// Lemma 1.2: the schemes' free flight under f(t) = f + a sin(omega t + phase) with the step-mean
// force misses the exact flight from the same anchor by at most
// a h^2 min(2, omega s) / (12 (1 - (omega h / (2 pi))^2)) in u after a time s (0 in v); omega h <
// 2 pi.
double harmonic_flight_bound(double amplitude, double omega, double h, double span);

// Lemma 1.3: the velocity fb_newton's smoothed step adds in free flight when the free flight ends
// at the gap d >= 0: h N = h eps / (s + d), s = sqrt(d^2 + h^2 eps), at most min(sqrt(eps),
// h eps / (2 d)).
double smoothing_kick(double eps, double h, double d);

// ---- Statement 2: one impact ----

// Errors (scheme minus exact) at the end of the scheme's contact step, in u and v.
struct ImpactError {
  double du = 0, dv = 0;
};

// Lemma 2.1, direct with the COR read as v^{l+1} = -e v^l (restitution.md): from the exact state
// at t_l with the impact at t_l + theta h, the exact solution still in its first flight after it:
// du = -(1 - theta) h (e V + f (1 - theta) h / 2), dv = -f h (1 - (1 + e) theta).
ImpactError direct_cor_impact(double V, double theta, double f, double h, double e);
// Its bounds in the data: |du| <= h (e V + |f| h / 2), |dv| <= |f| h.
ImpactError direct_cor_impact_bound(double V, double f, double h, double e);

// Lemma 2.2, direct without COR: the velocity after the contact step,
// v^{l+1} = V (1 - 2 theta) + f theta (1 - theta) h; the particle leaves the floor with
// |v^{l+1}| (at t_{l+2} when v^{l+1} < 0, f <= 0): an effective COR |1 - 2 theta| + O(|f| h / V).
double direct_scheme_rebound(double V, double theta, double f, double h);

// Lemma 2.3, moreau_jean (theta-method 1/2, Newton's law with e): sigma = (t* - t_m) / h for the
// first active step m, in [-1/2 - |f| h / (8 V), 1/2 + |f| h / (8 V)] when V >= |f| h; at t_{m+1}
// dv = f h ((1 + e) sigma - 1), du = (1 + e) V h (sigma - 1/2) + h dv / 2.
ImpactError moreau_jean_impact(double V, double sigma, double f, double h, double e);
ImpactError moreau_jean_impact_bound(double V, double f, double h, double e);
double moreau_jean_sigma_bound(double V, double f, double h);  // 1/2 + |f| h / (8 V)

// The linear floor crossing t_l + g^l / |v^l| of the contact step (error_norms.hpp's first impact
// time) minus t*: -f theta^2 h^2 / (2 |v^l|), |v^l| = V + f theta h.
double linear_crossing_error(double V, double theta, double f, double h);
// Its bound: |f| h^2 / (2 (V - max(0, -f) h)) for V > max(0, -f) h.
double linear_crossing_bound(double V, double f, double h);

// ---- Statement 3: many impacts, f = -g < 0, COR e in [0, 1] ----

// S_e(n) = e + e^2 + ... + e^n (n for e = 1).
double geometric_sum(double e, std::int64_t n);
// Theorem 3.1: t_k^h - t_k lies in [-2 h Sigma_k, (k - 1) h], Sigma_k = sum_{n<k} S_e(n), so
// |t_k^h - t_k| <= h A_k, A_k = max(k - 1, 2 Sigma_k).
double timing_factor(double e, std::int64_t k);
// Theorem 3.1: |W_k - e V_k| <= g h S_e(k) (W_k the scheme's relaunch speed after impact k).
double speed_bound(double g, double h, double e, std::int64_t k);
// The relaunch delay s_k - t_k lies in [-2 h Sigma_k, k h]: |s_k - t_k| <= h B_k,
// B_k = max(k, 2 Sigma_k).
double delay_factor(double e, std::int64_t k);
// Theorem 3.3: the scheme rests after at most K_max = floor(ln(2 V_1 / (g h)) / ln(1/e)) + 1
// impacts (1 when 2 V_1 <= g h or e = 0).
std::int64_t max_impacts(double V1, double g, double h, double e);

// Theorem 3.2: the data for the sup-norm bound on the grid up to time T: the first impact t_1
// with speed V_1 (the exact solution), g, e, h, T.
struct ZenoData {
  double t1 = 0, V1 = 0, g = 0, e = 0, h = 0, T = 0;
};
// max_l |u^l - u(t_l)| over t_l <= T: 0 for e = 0; else the largest over the impacts k <= K_max
// with t_k - h B_k <= T of V_k h B_k (near impact k) and h e V_k (2 S_e(k) + B_k) + g h^2 B_k^2 / 2
// (flight k), and g h^2 (1/2 + S_e(K_max))^2 / 2 (the exact bounces after the scheme rests). For
// e = 1 the scheme keeps bouncing while g h S_1(k) < V_1 - g h / 2 only: past that impact the bound
// is +infinity (not proved).
double sup_bound(const ZenoData& d);
// Theorem 3.3: |s_K - t_inf| <= h max(K_max, 2 Sigma_{K_max} + (1 + 2 S_e(K_max)) / (1 - e)),
// e < 1 (s_K: the scheme's rest, t_inf: the Zeno time).
double rest_bound(const ZenoData& d);

// max_{k >= 1} k e^(k - 1) <= max(1, 1 / (exp(1) e ln(1/e))): how far the sup-norm bound's
// V_k B_k = V_1 e^(k - 1) B_k can grow with k.
double max_k_e_power(double e);

// Conjecture 3.5, moreau_jean: max_l |u^l - u(t_l)| <= B_u + V_1 h (1 + e)(1 + 1/e)
// max(1, 2 e / (1 - e)) max_k k e^(k - 1), B_u Lemma 2.3's bound on du at the first impact, and
// never more than V_1^2 / (2 g) + (1 + e) V_1 h; e < 1.
double moreau_jean_sup_conjecture(const ZenoData& d);

// ---- Statement 4: without COR ----

// Proposition 4.2, f = 0: after one impact at t* off the grid the scheme is at least
// 2 min(theta, 1 - theta) V (t - t*) below the elastic solution at every grid time t >= t_{l+2}.
double no_cor_lower_bound(double V, double theta, double t_star, double t);

// ---- Beyond order one: direct_located ----

// Conjecture L.3's leading term on the period-1 orbit of the vibrating table, f(t) = -g +
// a sin(omega t) with the COR e, from the orbit's state at t = 0 (work_precision's
// table_period1.toml): direct_located's sup error on the grid of [0, T] is C h^2 + O(h^3), and this
// returns C. In each flight from the anchor at t_a the scheme misses the exact flight from the
// anchor's state by (a h^2 / 12)(sin(omega t) - sin(omega t_a)) (Lemma 1.2's leading term); the
// located step carries the state's error (du, dv) through the impact at the speed V_in and the
// force f_* there to (-e du, -e dv - (1 + e) f_* du / V_in) (Newton's law at a landing du / V_in
// late), and the anchor after it is the impact to O(h). The orbit: impacts where cos(omega t) =
// pi (1 - e) / (Gamma (1 + e)), Gamma = a / g (vibrating_table.md (T-6)), at V_in = g (2 pi /
// omega) / (1 + e). C is the largest |error| / h^2 over the flights, each maximum in closed form.
double located_period1_constant(double g, double a, double omega, double e, double T);

}  // namespace impact::error_analysis
