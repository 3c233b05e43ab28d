#include "impact/ensemble/ensemble.hpp"

#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

// FMA stays off in the vector code: one rounding for a * b + c would make the lanes differ from the
// single-particle solver, which the baseline x86-64 build never contracts. GCC takes it per
// function (IMPACT_NO_CONTRACT); clang decides it where the expression is written: its pragma comes
// first.
#if defined(__clang__)
#pragma clang fp contract(off)
#define IMPACT_NO_CONTRACT
#else
#define IMPACT_NO_CONTRACT gnu::optimize("fp-contract=off")
#endif

#include "impact/ensemble/ensemble_isa.hpp"
#include "impact/ensemble/ensemble_tally.hpp"
#include "impact/steppers/direct.hpp"
#include "impact/steppers/moreau_jean.hpp"

namespace impact {
namespace {

using namespace ensemble_isa;
using namespace ensemble_tally;

// GCC/Clang vector types: arithmetic, comparisons and `mask ? a : b` apply lane by lane, which lets
// direct_step and moreau_jean_step, written for double, run on them unchanged.
template <int Lanes>
struct LaneTypes {
  typedef double Real __attribute__((vector_size(Lanes * sizeof(double))));
  typedef std::int64_t Mask __attribute__((vector_size(Lanes * sizeof(double))));
};

// The columns of the ensemble, each at its first particle.
struct Columns {
  const double *f, *cor;
  const std::int64_t *has_cor, *fixed_point;
  double *gap, *v, *force, *anchor_gap, *anchor_v, *since;
  SummaryColumns summary;
};

// A block of Vectors vectors of Lanes particles is loaded into registers, stepped `steps` times and
// stored back: the step is latency-bound (each step's contact test depends on the last), so several
// independent vectors are interleaved to keep the SIMD units busy. With Summarize, each step also
// updates the summary on u = phi + gap, the u the single-particle solvers return (u^l is carried
// from the step before, so that u^0 is the initial u as given); `first_step` is the index l of the
// first of the steps.
template <int Lanes, int Vectors, Tally Summarize>
[[gnu::always_inline]] inline void direct_blocks(const Columns& c, Eigen::Index padded,
                                                 std::int64_t first_step, std::int64_t steps,
                                                 double h) {
  using Real = typename LaneTypes<Lanes>::Real;
  using Mask = typename LaneTypes<Lanes>::Mask;
  for (Eigen::Index first = 0; first < padded; first += Lanes * Vectors) {
    DirectLanes<Real> s[Vectors];
    Real f[Vectors], cor[Vectors];
    Mask has_cor[Vectors], fixed_point[Vectors];
    [[maybe_unused]] SummaryLanes<Real> summary[Vectors];
    [[maybe_unused]] Real phi[Vectors], u[Vectors], poison[Vectors];
    for (int b = 0; b < Vectors; ++b) {
      const Eigen::Index i = first + b * Lanes;
      load(f[b], c.f + i);
      load(cor[b], c.cor + i);
      load(has_cor[b], c.has_cor + i);
      load(fixed_point[b], c.fixed_point + i);
      load(s[b].gap, c.gap + i);
      load(s[b].v, c.v + i);
      load(s[b].contact_force, c.force + i);
      load(s[b].anchor_gap, c.anchor_gap + i);
      load(s[b].anchor_v, c.anchor_v + i);
      load(s[b].since, c.since + i);
      if constexpr (Summarize != Tally::none)
        load_summary<Summarize>(summary[b], phi[b], u[b], poison[b], c.summary, i);
    }
    if constexpr (Summarize != Tally::none) {
      Real l = Real{} + static_cast<double>(first_step);
      tally_steps<Summarize>(
          steps, l, summary, [&]<Tally T>(int b, const Real& at) __attribute__((always_inline)) {
            const Real u_before = u[b], v_before = s[b].v;
            direct_step(s[b], f[b], cor[b], has_cor[b], fixed_point[b], h);
            u[b] = phi[b] + s[b].gap;
            tally_step<T>(summary[b], poison[b], at, phi[b], u_before, v_before, u[b],
                          s[b].contact_force);
          });
    } else {
      for (std::int64_t k = 1; k < steps; ++k)  // gap and N on the last step only (Outputs)
        for (int b = 0; b < Vectors; ++b)
          direct_step<false>(s[b], f[b], cor[b], has_cor[b], fixed_point[b], h);
      for (int b = 0; b < Vectors; ++b)
        direct_step(s[b], f[b], cor[b], has_cor[b], fixed_point[b], h);
    }
    for (int b = 0; b < Vectors; ++b) {
      const Eigen::Index i = first + b * Lanes;
      store(c.gap + i, s[b].gap);
      store(c.v + i, s[b].v);
      store(c.force + i, s[b].contact_force);
      store(c.anchor_gap + i, s[b].anchor_gap);
      store(c.anchor_v + i, s[b].anchor_v);
      store(c.since + i, s[b].since);
      if constexpr (Summarize != Tally::none)
        store_summary<Summarize>(c.summary, i, summary[b], u[b], poison[b]);
    }
  }
}

template <int Lanes, int Vectors, Tally Summarize>
[[gnu::always_inline]] inline void moreau_jean_blocks(const Columns& c, Eigen::Index padded,
                                                      std::int64_t first_step, std::int64_t steps,
                                                      double theta, double h) {
  using Real = typename LaneTypes<Lanes>::Real;
  for (Eigen::Index first = 0; first < padded; first += Lanes * Vectors) {
    Real gap[Vectors], v[Vectors], force[Vectors], f[Vectors], e[Vectors];
    [[maybe_unused]] SummaryLanes<Real> summary[Vectors];
    [[maybe_unused]] Real phi[Vectors], u[Vectors], poison[Vectors];
    for (int b = 0; b < Vectors; ++b) {
      const Eigen::Index i = first + b * Lanes;
      load(f[b], c.f + i);
      load(e[b], c.cor + i);
      load(gap[b], c.gap + i);
      load(v[b], c.v + i);
      load(force[b], c.force + i);
      if constexpr (Summarize != Tally::none)
        load_summary<Summarize>(summary[b], phi[b], u[b], poison[b], c.summary, i);
    }
    if constexpr (Summarize != Tally::none) {
      Real l = Real{} + static_cast<double>(first_step);
      tally_steps<Summarize>(
          steps, l, summary, [&]<Tally T>(int b, const Real& at) __attribute__((always_inline)) {
            const Real u_before = u[b], v_before = v[b];
            moreau_jean_step(gap[b], v[b], force[b], f[b], e[b], theta, h);
            u[b] = phi[b] + gap[b];
            tally_step<T>(summary[b], poison[b], at, phi[b], u_before, v_before, u[b], force[b]);
          });
    } else {
      for (std::int64_t k = 0; k < steps; ++k)
        for (int b = 0; b < Vectors; ++b)
          moreau_jean_step(gap[b], v[b], force[b], f[b], e[b], theta, h);
    }
    for (int b = 0; b < Vectors; ++b) {
      const Eigen::Index i = first + b * Lanes;
      store(c.gap + i, gap[b]);
      store(c.v + i, v[b]);
      store(c.force + i, force[b]);
      if constexpr (Summarize != Tally::none)
        store_summary<Summarize>(c.summary, i, summary[b], u[b], poison[b]);
    }
  }
}

// The lanes of one block of every level, method and kernel (below) divide this.
constexpr Eigen::Index kPadding = 192;

// One entry point per instruction set, each compiled for it with the kernels inlined. The block
// shapes (lanes x vectors) were the fastest of 2..8 vectors on an AMD EPYC (Zen 4): direct keeps
// 10 values per vector in registers, moreau_jean 6 (experiments/performance/README.md); direct's
// also on an Intel Xeon family 6 model 167 (of 3, 4, 6, 8). The summary adds 8 values per vector
// that change at every step; with them, 3 vectors for direct and 4 for moreau_jean were the
// fastest of 2, 3, 4 and 6 (docs/sweeps.md). The finite check alone (a sweep of the final state)
// adds 3: 3 vectors for direct (of 3, 4, 6) and 6 for moreau_jean (of 4, 6, 8) on an AMD EPYC
// family 26 model 2.
template <int Lanes, int Vectors, int SummaryVectors, int FiniteVectors>
[[gnu::always_inline]] inline void direct_entry(const Columns& c, Eigen::Index n,
                                                std::int64_t first_step, std::int64_t steps,
                                                double h, Tally tally) {
  static_assert(kPadding % (Lanes * Vectors) == 0 && kPadding % (Lanes * SummaryVectors) == 0 &&
                kPadding % (Lanes * FiniteVectors) == 0);
  if (tally == Tally::full)
    direct_blocks<Lanes, SummaryVectors, Tally::full>(c, n, first_step, steps, h);
  else if (tally == Tally::finite)
    direct_blocks<Lanes, FiniteVectors, Tally::finite>(c, n, first_step, steps, h);
  else
    direct_blocks<Lanes, Vectors, Tally::none>(c, n, first_step, steps, h);
}
template <int Lanes, int Vectors, int SummaryVectors, int FiniteVectors>
[[gnu::always_inline]] inline void moreau_jean_entry(const Columns& c, Eigen::Index n,
                                                     std::int64_t first_step, std::int64_t steps,
                                                     double theta, double h, Tally tally) {
  static_assert(kPadding % (Lanes * Vectors) == 0 && kPadding % (Lanes * SummaryVectors) == 0 &&
                kPadding % (Lanes * FiniteVectors) == 0);
  if (tally == Tally::full)
    moreau_jean_blocks<Lanes, SummaryVectors, Tally::full>(c, n, first_step, steps, theta, h);
  else if (tally == Tally::finite)
    moreau_jean_blocks<Lanes, FiniteVectors, Tally::finite>(c, n, first_step, steps, theta, h);
  else
    moreau_jean_blocks<Lanes, Vectors, Tally::none>(c, n, first_step, steps, theta, h);
}

constexpr int kDirectSummaryVectors = 3, kMoreauJeanSummaryVectors = 4;
constexpr int kDirectFiniteVectors = 3, kMoreauJeanFiniteVectors = 6;

void baseline_direct(const Columns& c, Eigen::Index n, std::int64_t l, std::int64_t steps, double h,
                     Tally tally) {
  direct_entry<2, 6, kDirectSummaryVectors, kDirectFiniteVectors>(c, n, l, steps, h, tally);
}
void baseline_moreau_jean(const Columns& c, Eigen::Index n, std::int64_t l, std::int64_t steps,
                          double theta, double h, Tally tally) {
  moreau_jean_entry<2, 8, kMoreauJeanSummaryVectors, kMoreauJeanFiniteVectors>(c, n, l, steps,
                                                                               theta, h, tally);
}
#if defined(__x86_64__) && defined(__GNUC__)
[[gnu::target("avx2"), IMPACT_NO_CONTRACT]] void avx2_direct(const Columns& c, Eigen::Index n,
                                                             std::int64_t l, std::int64_t steps,
                                                             double h, Tally tally) {
  direct_entry<4, 6, kDirectSummaryVectors, kDirectFiniteVectors>(c, n, l, steps, h, tally);
}
[[gnu::target("avx2"), IMPACT_NO_CONTRACT]] void avx2_moreau_jean(const Columns& c, Eigen::Index n,
                                                                  std::int64_t l,
                                                                  std::int64_t steps, double theta,
                                                                  double h, Tally tally) {
  moreau_jean_entry<4, 8, kMoreauJeanSummaryVectors, kMoreauJeanFiniteVectors>(c, n, l, steps,
                                                                               theta, h, tally);
}
[[gnu::target("avx512f"), IMPACT_NO_CONTRACT]] void avx512_direct(const Columns& c, Eigen::Index n,
                                                                  std::int64_t l,
                                                                  std::int64_t steps, double h,
                                                                  Tally tally) {
  direct_entry<8, 6, kDirectSummaryVectors, kDirectFiniteVectors>(c, n, l, steps, h, tally);
}
[[gnu::target("avx512f"), IMPACT_NO_CONTRACT]] void avx512_moreau_jean(
    const Columns& c, Eigen::Index n, std::int64_t l, std::int64_t steps, double theta, double h,
    Tally tally) {
  moreau_jean_entry<8, 8, kMoreauJeanSummaryVectors, kMoreauJeanFiniteVectors>(c, n, l, steps,
                                                                               theta, h, tally);
}
#endif

}  // namespace

#undef IMPACT_NO_CONTRACT

Ensemble::Ensemble(EnsembleMethod method, std::span<const Model> models,
                   std::span<const State> initial, double h, double theta)
    : method_(method), h_(h), theta_(theta), level_(best_level()) {
  if (models.size() != initial.size())
    throw std::invalid_argument("Ensemble: " + std::to_string(models.size()) + " models but " +
                                std::to_string(initial.size()) + " initial states");
  if (!(h > 0) || !std::isfinite(h)) throw std::invalid_argument("Ensemble: h must be > 0");
  if (!(theta >= 0 && theta <= 1)) throw std::invalid_argument("Ensemble: theta must be in [0, 1]");
  size_ = static_cast<Eigen::Index>(models.size());
  padded_ = (size_ + kPadding - 1) / kPadding * kPadding;
  // The padding particles rest on a floor at 0 without force: finite whatever the method.
  for (Eigen::ArrayXd* column : {&phi_, &f_, &cor_, &gap_, &v_, &force_, &since_})
    column->setZero(padded_);
  has_cor_.setZero(padded_);
  fixed_point_.setConstant(padded_, -1);
  for (Eigen::Index i = 0; i < size_; ++i) {
    const Model& m = models[static_cast<std::size_t>(i)];
    if (!constant_force(m))  // the kernels take one constant f per particle
      throw std::invalid_argument("Ensemble: particle " + std::to_string(i) +
                                  " has a time-dependent body force; only a constant f is stepped");
    // The contact law as Direct and MoreauJean read it (contact_law.hpp): moreau_jean's kernel
    // reads e = cor_ alone.
    const RestitutionRule law = restitution_rule(contact_law(
        m, method == EnsembleMethod::direct ? ContactLaw{SchemeLaw{}} : kElasticReading));
    if (!(law.cor >= 0 && law.cor <= 1))
      throw std::invalid_argument("Ensemble: particle " + std::to_string(i) + ": COR " +
                                  std::to_string(law.cor) + " is outside [0, 1]");
    phi_[i] = m.phi;
    f_[i] = m.f;
    cor_[i] = law.cor;
    has_cor_[i] = law.has_cor ? -1 : 0;
    fixed_point_[i] = law.fixed_point;
    gap_[i] = initial[static_cast<std::size_t>(i)].u - m.phi;
    v_[i] = initial[static_cast<std::size_t>(i)].v;
  }
  // Direct starts its free flight at the initial state (DirectLanes).
  anchor_gap_ = gap_;
  anchor_v_ = v_;
  // The state at t_0 is the initial state as given (phi + (u0 - phi) may round away from u0).
  u_.setZero(padded_);
  for (Eigen::Index i = 0; i < size_; ++i) u_[i] = initial[static_cast<std::size_t>(i)].u;
}

std::string_view Ensemble::instruction_set() const {
  return kLevelNames[level_];
}

std::vector<std::string_view> Ensemble::supported_instruction_sets() {
  return supported_names();
}

void Ensemble::use(std::string_view instruction_set) {
  level_ = supported_level(instruction_set);
}

void Ensemble::keep_summary(SummaryDepth depth) {
  if (steps_done_ != 0)
    throw std::logic_error("Ensemble::keep_summary: call it before the first advance()");
  summarize_ = true;
  per_step_ = depth == SummaryDepth::per_step;
  for (Eigen::ArrayXd* column :
       {&steps_, &episodes_, &run_, &first_l_, &first_u_, &first_v_, &poison_})
    column->setZero(padded_);
  max_u_ = u_;  // as start_summary(): the highest position so far is u^0
}

SummaryLanes<double> Ensemble::summary(Eigen::Index i) const {
  SummaryLanes<double> s;
  s.contacts = {steps_[i], episodes_[i], run_[i]};
  s.max_u = max_u_[i];
  s.first_l = first_l_[i];
  s.first_u = first_u_[i];
  s.first_v = first_v_[i];
  return s;
}

void Ensemble::advance(std::int64_t steps) {
  if (steps <= 0) return;
  const SummaryColumns summary{phi_.data(),     u_.data(),     steps_.data(),   episodes_.data(),
                               run_.data(),     max_u_.data(), first_l_.data(), first_u_.data(),
                               first_v_.data(), poison_.data()};
  const Columns c{f_.data(),        cor_.data(),   has_cor_.data(), fixed_point_.data(),
                  gap_.data(),      v_.data(),     force_.data(),   anchor_gap_.data(),
                  anchor_v_.data(), since_.data(), summary};
  const bool direct = method_ == EnsembleMethod::direct;
  const std::int64_t l = steps_done_;
  const Tally tally = !summarize_ ? Tally::none : per_step_ ? Tally::full : Tally::finite;
  switch (level_) {
#if defined(__x86_64__) && defined(__GNUC__)
    case kAvx512:
      direct ? avx512_direct(c, padded_, l, steps, h_, tally)
             : avx512_moreau_jean(c, padded_, l, steps, theta_, h_, tally);
      break;
    case kAvx2:
      direct ? avx2_direct(c, padded_, l, steps, h_, tally)
             : avx2_moreau_jean(c, padded_, l, steps, theta_, h_, tally);
      break;
#endif
    default:
      direct ? baseline_direct(c, padded_, l, steps, h_, tally)
             : baseline_moreau_jean(c, padded_, l, steps, theta_, h_, tally);
  }
  u_ = phi_ + gap_;  // as the single-particle solvers return u = phi + gap
  steps_done_ += steps;
}

}  // namespace impact
