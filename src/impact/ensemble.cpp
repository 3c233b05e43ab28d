#include "impact/ensemble.hpp"

#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

// FMA stays off in the vector code: contracting a * b + c into one rounding would make the lanes
// differ from the single-particle solver, which the baseline x86-64 build never contracts. GCC
// takes it per function (IMPACT_NO_CONTRACT below). Clang contracts within an expression by
// default and decides it where the expression is written, so its pragma comes before the
// kernels' headers.
#if defined(__clang__)
#pragma clang fp contract(off)
#define IMPACT_NO_CONTRACT
#else
#define IMPACT_NO_CONTRACT gnu::optimize("fp-contract=off")
#endif

#include "impact/direct.hpp"
#include "impact/moreau_jean.hpp"

namespace impact {
namespace {

// GCC/Clang vector types: arithmetic and comparisons apply lane by lane, and `mask ? a : b` selects
// lane by lane, which is what lets direct_step and moreau_jean_step, written for double, run on
// them unchanged.
template <int Lanes>
struct LaneTypes {
  typedef double Real __attribute__((vector_size(Lanes * sizeof(double))));
  typedef std::int64_t Mask __attribute__((vector_size(Lanes * sizeof(double))));
};

// By reference, not by value: a vector returned from a function compiled without AVX would change
// the ABI (GCC's -Wpsabi).
template <class T, class Scalar>
[[gnu::always_inline]] inline void load(T& x, const Scalar* p) {
  std::memcpy(&x, p, sizeof x);
}

template <class T>
[[gnu::always_inline]] inline void store(double* p, const T& x) {
  std::memcpy(p, &x, sizeof x);
}

// The columns of the ensemble, each at its first particle.
struct Columns {
  const double *f, *cor;
  const std::int64_t* has_cor;
  double *gap, *v, *force, *anchor_gap, *anchor_v, *since;
};

// A block of Vectors vectors of Lanes particles is loaded into registers, stepped `steps` times and
// stored back: the step is latency-bound (each step's contact test depends on the last), so several
// independent vectors are interleaved to keep the SIMD units busy.
template <int Lanes, int Vectors>
[[gnu::always_inline]] inline void direct_blocks(const Columns& c, Eigen::Index padded,
                                                 std::int64_t steps, double h) {
  using Real = typename LaneTypes<Lanes>::Real;
  using Mask = typename LaneTypes<Lanes>::Mask;
  for (Eigen::Index first = 0; first < padded; first += Lanes * Vectors) {
    DirectLanes<Real> s[Vectors];
    Real f[Vectors], cor[Vectors];
    Mask has_cor[Vectors];
    for (int b = 0; b < Vectors; ++b) {
      const Eigen::Index i = first + b * Lanes;
      load(f[b], c.f + i);
      load(cor[b], c.cor + i);
      load(has_cor[b], c.has_cor + i);
      load(s[b].gap, c.gap + i);
      load(s[b].v, c.v + i);
      load(s[b].contact_force, c.force + i);
      load(s[b].anchor_gap, c.anchor_gap + i);
      load(s[b].anchor_v, c.anchor_v + i);
      load(s[b].since, c.since + i);
    }
    for (std::int64_t l = 0; l < steps; ++l)
      for (int b = 0; b < Vectors; ++b) direct_step(s[b], f[b], cor[b], has_cor[b], h);
    for (int b = 0; b < Vectors; ++b) {
      const Eigen::Index i = first + b * Lanes;
      store(c.gap + i, s[b].gap);
      store(c.v + i, s[b].v);
      store(c.force + i, s[b].contact_force);
      store(c.anchor_gap + i, s[b].anchor_gap);
      store(c.anchor_v + i, s[b].anchor_v);
      store(c.since + i, s[b].since);
    }
  }
}

template <int Lanes, int Vectors>
[[gnu::always_inline]] inline void moreau_jean_blocks(const Columns& c, Eigen::Index padded,
                                                      std::int64_t steps, double theta, double h) {
  using Real = typename LaneTypes<Lanes>::Real;
  for (Eigen::Index first = 0; first < padded; first += Lanes * Vectors) {
    Real gap[Vectors], v[Vectors], force[Vectors], f[Vectors], e[Vectors];
    for (int b = 0; b < Vectors; ++b) {
      const Eigen::Index i = first + b * Lanes;
      load(f[b], c.f + i);
      load(e[b], c.cor + i);
      load(gap[b], c.gap + i);
      load(v[b], c.v + i);
      load(force[b], c.force + i);
    }
    for (std::int64_t l = 0; l < steps; ++l)
      for (int b = 0; b < Vectors; ++b)
        moreau_jean_step(gap[b], v[b], force[b], f[b], e[b], theta, h);
    for (int b = 0; b < Vectors; ++b) {
      const Eigen::Index i = first + b * Lanes;
      store(c.gap + i, gap[b]);
      store(c.v + i, v[b]);
      store(c.force + i, force[b]);
    }
  }
}

// One entry point per instruction set, each compiled for it with the kernels inlined. The block
// shapes (lanes x vectors) were the fastest of 2..8 vectors on an AMD EPYC (Zen 4): direct keeps
// 10 values per vector in registers, moreau_jean 6 (experiments/performance/README.md).
void baseline_direct(const Columns& c, Eigen::Index n, std::int64_t steps, double h) {
  direct_blocks<2, 6>(c, n, steps, h);
}
void baseline_moreau_jean(const Columns& c, Eigen::Index n, std::int64_t steps, double theta,
                          double h) {
  moreau_jean_blocks<2, 8>(c, n, steps, theta, h);
}
#if defined(__x86_64__) && defined(__GNUC__)
[[gnu::target("avx2"), IMPACT_NO_CONTRACT]] void avx2_direct(const Columns& c, Eigen::Index n,
                                                             std::int64_t steps, double h) {
  direct_blocks<4, 6>(c, n, steps, h);
}
[[gnu::target("avx2"), IMPACT_NO_CONTRACT]] void avx2_moreau_jean(const Columns& c, Eigen::Index n,
                                                                  std::int64_t steps, double theta,
                                                                  double h) {
  moreau_jean_blocks<4, 8>(c, n, steps, theta, h);
}
[[gnu::target("avx512f"), IMPACT_NO_CONTRACT]] void avx512_direct(const Columns& c, Eigen::Index n,
                                                                  std::int64_t steps, double h) {
  direct_blocks<8, 6>(c, n, steps, h);
}
[[gnu::target("avx512f"), IMPACT_NO_CONTRACT]] void avx512_moreau_jean(const Columns& c,
                                                                       Eigen::Index n,
                                                                       std::int64_t steps,
                                                                       double theta, double h) {
  moreau_jean_blocks<8, 8>(c, n, steps, theta, h);
}
#endif

enum Level { kBaseline, kAvx2, kAvx512 };
constexpr std::string_view kLevelNames[] = {"baseline", "avx2", "avx512f"};
// The lanes of one block of every level and method (direct: 2, 4, 8 lanes x 6 vectors;
// moreau_jean: x 8) divide this.
constexpr Eigen::Index kPadding = 192;

bool supported(int level) {
#if defined(__x86_64__) && defined(__GNUC__)
  __builtin_cpu_init();
  if (level == kAvx512) return __builtin_cpu_supports("avx512f");
  if (level == kAvx2) return __builtin_cpu_supports("avx2");
#endif
  return level == kBaseline;
}

int best_level() {
  for (int level : {kAvx512, kAvx2})
    if (supported(level)) return level;
  return kBaseline;
}

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
  phi_.setZero(padded_);
  f_.setZero(padded_);
  cor_.setZero(padded_);
  has_cor_.setZero(padded_);
  gap_.setZero(padded_);
  v_.setZero(padded_);
  force_.setZero(padded_);
  since_.setZero(padded_);
  for (Eigen::Index i = 0; i < size_; ++i) {
    const Model& m = models[static_cast<std::size_t>(i)];
    if (m.cor && !(*m.cor >= 0 && *m.cor <= 1))
      throw std::invalid_argument("Ensemble: particle " + std::to_string(i) + ": COR " +
                                  std::to_string(*m.cor) + " is outside [0, 1]");
    phi_[i] = m.phi;
    f_[i] = m.f;
    // As Direct and MoreauJean read their Model.
    cor_[i] = method == EnsembleMethod::direct ? m.cor.value_or(0.0) : m.cor.value_or(1.0);
    has_cor_[i] = m.cor ? -1 : 0;
    gap_[i] = initial[static_cast<std::size_t>(i)].u - m.phi;
    v_[i] = initial[static_cast<std::size_t>(i)].v;
  }
  // Direct starts its free flight at the initial state (DirectLanes).
  anchor_gap_ = gap_;
  anchor_v_ = v_;
  u_ = phi_ + gap_;
}

std::string_view Ensemble::instruction_set() const {
  return kLevelNames[level_];
}

std::vector<std::string_view> Ensemble::supported_instruction_sets() {
  std::vector<std::string_view> names;
  for (int level : {kAvx512, kAvx2, kBaseline})
    if (supported(level)) names.push_back(kLevelNames[level]);
  return names;
}

void Ensemble::use(std::string_view instruction_set) {
  for (int level : {kAvx512, kAvx2, kBaseline})
    if (kLevelNames[level] == instruction_set && supported(level)) {
      level_ = level;
      return;
    }
  throw std::invalid_argument("Ensemble: instruction set \"" + std::string(instruction_set) +
                              "\" is unknown or not supported by this processor");
}

void Ensemble::advance(std::int64_t steps) {
  if (steps <= 0) return;
  const Columns c{f_.data(),     cor_.data(),        has_cor_.data(),  gap_.data(),  v_.data(),
                  force_.data(), anchor_gap_.data(), anchor_v_.data(), since_.data()};
  const bool direct = method_ == EnsembleMethod::direct;
  switch (level_) {
#if defined(__x86_64__) && defined(__GNUC__)
    case kAvx512:
      direct ? avx512_direct(c, padded_, steps, h_)
             : avx512_moreau_jean(c, padded_, steps, theta_, h_);
      break;
    case kAvx2:
      direct ? avx2_direct(c, padded_, steps, h_) : avx2_moreau_jean(c, padded_, steps, theta_, h_);
      break;
#endif
    default:
      direct ? baseline_direct(c, padded_, steps, h_)
             : baseline_moreau_jean(c, padded_, steps, theta_, h_);
  }
  u_ = phi_ + gap_;  // as the single-particle solvers return u = phi + gap
  steps_done_ += steps;
}

}  // namespace impact
