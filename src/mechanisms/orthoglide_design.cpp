#include "kinestat/mechanisms/orthoglide_design.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include <fmt/format.h>

#include "kinestat/core/input_checks.hpp"

namespace kinestat::mechanisms {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
const double kSqrt15 = std::sqrt(1.5);  // rho on the Q-axis at the parallel singularity chi = -1/2

Vec3 sorted_descending(Vec3 v) {
  std::sort(v.data(), v.data() + 3, std::greater<>());
  return v;
}

// Widens `r` by the factors 1/sigma of singular values sigma.
void include(TransmissionRange& r, const Vec3& sigma) {
  r.min = std::min(r.min, 1.0 / sigma.maxCoeff());
  r.max = std::max(r.max, 1.0 / sigma.minCoeff());
}

constexpr TransmissionRange kEmptyRange{kInf, 0.0};

}  // namespace

double unit_q_axis_position(double chi) { return -chi / std::sqrt(1.0 + 2.0 * chi * chi); }
double unit_q_axis_joint(double chi) { return (1.0 - chi) / std::sqrt(1.0 + 2.0 * chi * chi); }
double unit_q_axis_chi_from_position(double p) { return -p / std::sqrt(1.0 - 2.0 * p * p); }
double unit_q_axis_chi_from_joint(double rho) {
  return (1.0 - rho * rho) / (1.0 + rho * std::sqrt(3.0 - 2.0 * rho * rho));
}

UnitQAxisLimits unit_q_axis_limits(double mu) {
  // Eq. (16) with lambda_min = mu, lambda_max = 1/mu. On the Q-axis J^-1 (eq. 7) has the eigenvalue
  // 1 + 2 chi along the axis and 1 - chi (twice) across it; the factors are their inverses.
  UnitQAxisLimits q;
  q.chi_plus = std::max(1.0 - 1.0 / mu, (mu - 1.0) / 2.0);
  q.chi_minus = std::min(1.0 - mu, (1.0 / mu - 1.0) / 2.0);
  q.rho_plus = unit_q_axis_joint(q.chi_plus);
  q.rho_minus = unit_q_axis_joint(q.chi_minus);
  q.p_plus = unit_q_axis_position(q.chi_plus);
  q.p_minus = unit_q_axis_position(q.chi_minus);
  return q;
}

const char* to_string(CriticalPoint c) {
  switch (c) {
    case CriticalPoint::kQ:
      return "Q";
    case CriticalPoint::kR:
      return "R";
    case CriticalPoint::kS:
      return "S";
  }
  return "?";
}

Vec3 unit_critical_point_position(CriticalPoint c, double rho) {
  switch (c) {
    case CriticalPoint::kQ: {
      const double p = (rho - std::sqrt(3.0 - 2.0 * rho * rho)) / 3.0;  // eq. (17)
      return {p, p, p};
    }
    case CriticalPoint::kR: {
      const double p = (rho - std::sqrt(2.0 - rho * rho)) / 2.0;  // eq. (19)
      return {p, p, 0.0};
    }
    case CriticalPoint::kS:
      return {rho - 1.0, 0.0, 0.0};  // section 5.1, S points
  }
  return Vec3::Zero();
}

Vec3 unit_critical_point_singular_values(CriticalPoint c, double rho) {
  const double p = unit_critical_point_position(c, rho).x();
  switch (c) {
    case CriticalPoint::kQ: {
      const double chi = unit_q_axis_chi_from_position(p);  // eigenvalues of eq. (7), section 4.2
      return sorted_descending({std::abs(1.0 + 2.0 * chi), std::abs(1.0 - chi), std::abs(1.0 - chi)});
    }
    case CriticalPoint::kR: {
      const double chi = -p / std::sqrt(1.0 - p * p);  // eq. (18)-(22)
      const double A = (1.0 + chi) * (1.0 + chi) + (1.0 + chi * chi) / (1.0 - chi * chi);
      const double B = (1.0 + chi) * (1.0 + chi);
      const double root = std::sqrt(A * A - 4.0 * B);
      return sorted_descending(
          {std::abs(1.0 - chi), std::sqrt(0.5 * (A + root)), std::sqrt(std::max(0.0, 0.5 * (A - root)))});
    }
    case CriticalPoint::kS: {
      const double chi = -p / std::sqrt(1.0 - p * p);  // eq. (23)-(26)
      const double a = 1.0 + chi * chi, b = std::abs(chi) * std::sqrt(2.0 + chi * chi);
      return sorted_descending({1.0, std::sqrt(a + b), std::sqrt(std::max(0.0, a - b))});
    }
  }
  return Vec3::Zero();
}

TransmissionRange unit_joint_space_range(double rho_min, double rho_max) {
  TransmissionRange r = kEmptyRange;
  for (CriticalPoint c : {CriticalPoint::kQ, CriticalPoint::kR, CriticalPoint::kS}) {
    include(r, unit_critical_point_singular_values(c, rho_min));
    // Q+ lies beyond the parallel singularity once rho_max >= sqrt(3/2): W_rho is then unbounded in
    // the factors; R+ and S+ still exist (rho_max < sqrt 2) and count for the minimum.
    if (c != CriticalPoint::kQ || rho_max < kSqrt15) include(r, unit_critical_point_singular_values(c, rho_max));
  }
  if (!(rho_max < kSqrt15)) r.max = kInf;
  return r;
}

TransmissionRange unit_cube_range(double p_min, double p_max) {
  TransmissionRange r = kEmptyRange;
  for (double p : {p_min, p_max}) {
    const double chi = unit_q_axis_chi_from_position(p);
    if (!(chi > -0.5 && chi < 1.0)) return {0.0, kInf};  // a vertex beyond a singularity (Table 1)
    include(r, Vec3(1.0 + 2.0 * chi, 1.0 - chi, 1.0 - chi));
  }
  return r;
}

double unit_joint_space_rho_min(double mu) {
  return std::max(unit_q_axis_limits(mu).rho_minus, mu / std::sqrt(mu * mu - 2.0 * mu + 2.0));  // eq. (36b)
}

namespace {

// One sample of a workspace search.
struct Sample {
  enum Kind { kRegular, kParallel, kSerial } kind = kRegular;
  Vec3 p, rho;
  VelocityTransmission v;
};

// Evaluates the factors at joint or Cartesian coordinates q (depending on the search).
using Evaluator = std::function<Sample(const Vec3& q)>;

class SearchState {
 public:
  SearchState(double lo, double hi, double sum_limit, const Evaluator& eval)
      : lo_(lo), hi_(hi), sum_limit_(sum_limit), eval_(eval) {}

  // Samples q unless it breaks the sum limit.
  void visit(const Vec3& q) {
    if (q.sum() > sum_limit_ * (1.0 + 1e-12)) return;
    const Sample s = eval_(q);
    ++out_.evaluations;
    if (s.kind == Sample::kParallel) parallel_ = true;
    if (s.kind == Sample::kSerial) serial_ = true;
    if (s.kind != Sample::kRegular) return;
    if (s.v.mu_min < out_.range.min) {
      out_.range.min = s.v.mu_min;
      q_min_ = q;
      out_.p_at_min = s.p;
      out_.rho_at_min = s.rho;
    }
    if (s.v.mu_max > out_.range.max) {
      out_.range.max = s.v.mu_max;
      q_max_ = q;
      out_.p_at_max = s.p;
      out_.rho_at_max = s.rho;
    }
  }

  // Faces (n x n each, edges and vertices included), the cutting plane of the sum limit, interior grid.
  void sample_grid(int n) {
    auto at = [&](int i, int m) { return lo_ + (hi_ - lo_) * i / (m - 1); };
    for (int axis = 0; axis < 3; ++axis)
      for (double fixed : {lo_, hi_})
        for (int i = 0; i < n; ++i)
          for (int j = 0; j < n; ++j) {
            Vec3 q;
            q[axis] = fixed;
            q[(axis + 1) % 3] = at(i, n);
            q[(axis + 2) % 3] = at(j, n);
            visit(q);
          }
    if (std::isfinite(sum_limit_))
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          const Vec3 q(at(i, n), at(j, n), sum_limit_ - at(i, n) - at(j, n));
          if (q.z() >= lo_ && q.z() <= hi_) visit(q);
        }
    const int m = std::max(3, n / 4);
    for (int i = 1; i + 1 < m; ++i)
      for (int j = 1; j + 1 < m; ++j)
        for (int k = 1; k + 1 < m; ++k) visit(Vec3(at(i, m), at(j, m), at(k, m)));
    step_ = (hi_ - lo_) / (n - 1);
  }

  // Pattern search around the extremes: a 11^3 stencil of half-width `step`, projected into the
  // box and under the sum limit, shrunk five-fold per round.
  void refine(int rounds) {
    for (bool for_max : {false, true}) {
      double h = step_;
      for (int r = 0; r < rounds; ++r, h /= 5.0) {
        const Vec3 centre = for_max ? q_max_ : q_min_;
        for (int a = -5; a <= 5; ++a)
          for (int b = -5; b <= 5; ++b)
            for (int c = -5; c <= 5; ++c) {
              Vec3 q = (centre + Vec3(a, b, c) * (h / 5.0)).cwiseMax(lo_).cwiseMin(hi_);
              if (q.sum() > sum_limit_) q = (q.array() - (q.sum() - sum_limit_) / 3.0).cwiseMax(lo_).cwiseMin(hi_);
              visit(q);
            }
      }
    }
  }

  WorkspaceSearch result() const {
    WorkspaceSearch r = out_;
    r.singular = parallel_ || serial_;
    if (parallel_) r.range.max = kInf;
    if (serial_) r.range.min = 0.0;
    return r;
  }

 private:
  double lo_, hi_, sum_limit_;
  const Evaluator& eval_;
  WorkspaceSearch out_{kEmptyRange};
  Vec3 q_min_ = Vec3::Zero(), q_max_ = Vec3::Zero();
  double step_ = 0.0;
  bool parallel_ = false, serial_ = false;
};

WorkspaceSearch search(double lo, double hi, double sum_limit, int n, const Evaluator& eval) {
  SearchState s(lo, hi, sum_limit, eval);
  s.sample_grid(std::max(n, 2));
  s.refine(4);
  return s.result();
}

// The working-branch posture and its factors at joint coordinates rho: kParallel where no assembly
// exists (outside the reachable region of section 2.3), kSerial where a bar is not on the near side
// of its slider (p_i >= rho_i: a serial singularity was crossed, det J^-1 <= 0).
Sample joint_sample(const OrthoglideGeometry& g, const Vec3& rho) {
  auto p = direct_kinematics(g, rho, kOrthoglideWorkingBranch);
  if (!p.ok()) return {Sample::kParallel, Vec3::Zero(), rho, {}};
  if (((rho - *p).array() <= 0.0).any()) return {Sample::kSerial, *p, rho, {}};
  auto Jinv = inverse_jacobian(*p, rho);
  if (!Jinv.ok()) return {Sample::kSerial, *p, rho, {}};
  return {Sample::kRegular, *p, rho, velocity_transmission(*Jinv)};
}

// The working-mode posture and its factors at a Cartesian point p: kSerial outside the cylinders
// C_L or on their boundary, kParallel beyond the flat singularity (branch m != -1).
Sample cartesian_sample(const OrthoglideGeometry& g, const Vec3& p) {
  auto rho = inverse_kinematics(g, p);
  if (!rho.ok()) return {Sample::kSerial, p, Vec3::Zero(), {}};
  if (direct_kinematics_branch(p, *rho) != kOrthoglideWorkingBranch) return {Sample::kParallel, p, *rho, {}};
  auto Jinv = inverse_jacobian(p, *rho);
  if (!Jinv.ok()) return {Sample::kSerial, p, *rho, {}};
  return {Sample::kRegular, p, *rho, velocity_transmission(*Jinv)};
}

}  // namespace

WorkspaceSearch search_joint_space(const OrthoglideGeometry& g, double rho_min, double rho_max, double joint_sum_limit,
                                   int n) {
  const Evaluator eval = [&g](const Vec3& rho) { return joint_sample(g, rho); };
  return search(rho_min, rho_max, joint_sum_limit, n, eval);
}

WorkspaceSearch search_cube(const OrthoglideGeometry& g, double p_min, double p_max, int n) {
  const Evaluator eval = [&g](const Vec3& p) { return cartesian_sample(g, p); };
  return search(p_min, p_max, kInf, n, eval);
}

DexterousVolumes unit_dexterous_volumes(double mu_low, double mu_high, int n) {
  const OrthoglideGeometry unit{1.0};
  long sphere = 0, w0 = 0, lower = 0, upper = 0, both = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k) {
        const Vec3 p = (Vec3(i, j, k).array() + 0.5) * (2.0 / n) - 1.0;
        if (p.squaredNorm() >= 1.0) continue;
        ++sphere;
        const Sample s = cartesian_sample(unit, p);
        if (s.kind != Sample::kRegular) continue;
        ++w0;
        const bool lo = s.v.mu_min >= mu_low, hi = s.v.mu_max <= mu_high;
        lower += lo;
        upper += hi;
        both += lo && hi;
      }
  DexterousVolumes v;
  if (sphere == 0 || w0 == 0) return v;
  v.singularity_free_of_sphere = static_cast<double>(w0) / sphere;
  v.lower_of_w0 = static_cast<double>(lower) / w0;
  v.two_sided_of_w0 = static_cast<double>(both) / w0;
  v.upper_of_w0 = static_cast<double>(upper) / w0;
  return v;
}

namespace {

// Root of a continuous f with f(lo) and f(hi) of opposite signs, to round-off.
template <class F>
double bisect(F f, double lo, double hi) {
  const bool lo_negative = f(lo) < 0;
  for (int k = 0; k < 200 && hi - lo > 1e-15 * hi; ++k) {
    const double mid = 0.5 * (lo + hi);
    ((f(mid) < 0) == lo_negative ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace

namespace {

// mu_min at joints (r, r, t) of the unit manipulator: the edge of W_rho with two joints at rho_min.
double unit_edge_factor(double r, double t) {
  const Sample s = joint_sample(OrthoglideGeometry{1.0}, Vec3(r, r, t));
  return s.kind == Sample::kRegular ? s.v.mu_min : kInf;
}

// The smallest unit_edge_factor(r, t) for t in [a, b]: a 200-step scan, then golden-section search
// in the best bracket (to round-off).
double unit_edge_minimum(double r, double a, double b) {
  const int n = 200;
  auto t_at = [&](int i) { return a + (b - a) * i / n; };
  int best = 0;
  for (int i = 1; i <= n; ++i)
    if (unit_edge_factor(r, t_at(i)) < unit_edge_factor(r, t_at(best))) best = i;
  double lo = t_at(std::max(best - 1, 0)), hi = t_at(std::min(best + 1, n));
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  for (int k = 0; k < 80; ++k) {
    const double c = hi - g * (hi - lo), d = lo + g * (hi - lo);
    if (unit_edge_factor(r, c) < unit_edge_factor(r, d))
      hi = d;
    else
      lo = c;
  }
  return unit_edge_factor(r, 0.5 * (lo + hi));
}

}  // namespace

MinimumSwitchPoints unit_minimum_switch_points(int n) {
  using C = CriticalPoint;
  auto sigma_max = [](C c, double r) { return unit_critical_point_singular_values(c, r)[0]; };
  MinimumSwitchPoints m;
  // Fig. 9a's vertical lines: the formulas' largest singular values of S- and R-, R- and Q- meet.
  m.rho_sr = bisect([&](double r) { return sigma_max(C::kS, r) - sigma_max(C::kR, r); }, 0.01, 0.2);
  m.rho_rq = bisect([&](double r) { return sigma_max(C::kR, r) - sigma_max(C::kQ, r); }, 0.15, 0.6);
  m.mu_sr = 1.0 / sigma_max(C::kS, m.rho_sr);
  m.mu_rq = 1.0 / sigma_max(C::kQ, m.rho_rq);
  const OrthoglideGeometry unit{1.0};
  m.search_mu_at_rho_sr = search_joint_space(unit, m.rho_sr, 1.0, kInf, n).range.min;
  m.search_mu_at_rho_rq = search_joint_space(unit, m.rho_rq, 1.0, kInf, n).range.min;
  // Along the edge (r, r, t) two local minima compete: the vertex Q- (t = r) and one near t = 0.45,
  // which is lower until the switch. Both are tracked on the edge itself (a search over the whole box
  // refines only the best point and blurs the other by its grid step).
  m.rho_q =
      bisect([&](double r) { return unit_edge_minimum(r, r + 0.1, 1.0) - unit_edge_factor(r, r); }, m.rho_rq, 0.4);
  m.mu_q = 1.0 / sigma_max(C::kQ, m.rho_q);
  return m;
}

StatusOr<OrthoglideDesign> design_orthoglide(int strategy, double mu, double cube_size) {
  if (strategy < 1 || strategy > 3)
    return Status::Invalid(fmt::format("design strategy {}: must be 1, 2 or 3 (Table 3)", strategy));
  if (!(mu > 0.0 && mu < 1.0))
    return Status::Invalid(fmt::format(
        "transmission factor bound mu = {}: must lie in (0, 1); the factors are required to stay in [mu, 1/mu]", mu));
  if (!(std::isfinite(cube_size) && cube_size > 0.0))
    return Status::Invalid(fmt::format("cube size c = {} m: must be positive and finite", cube_size));

  const UnitQAxisLimits q = unit_q_axis_limits(mu);
  double rho_min = q.rho_minus, rho_max = q.rho_plus, p_min = q.p_minus, p_max = q.rho_plus - 1.0;  // strategy 2
  if (strategy == 1) {
    rho_max = 1.0 + q.p_plus;  // Table 3: make the cube vertex Q+ reachable along the x axis
    p_max = q.p_plus;
  } else if (strategy == 3) {
    rho_min = unit_joint_space_rho_min(mu);
    p_min = unit_q_axis_position(unit_q_axis_chi_from_joint(rho_min));
  }

  OrthoglideDesign d;
  d.strategy = strategy;
  d.mu = mu;
  d.cube_size = cube_size;
  d.link_length = cube_size / (p_max - p_min);  // the scaling factor eta of section 6, with L = 1 before
  const double L = d.link_length;
  d.rho_min = rho_min * L;
  d.rho_max = rho_max * L;
  d.p_min = p_min * L;
  d.p_max = p_max * L;
  d.rho_q_plus = q.rho_plus * L;
  if (!(rho_max < kSqrt15)) d.joint_sum_limit = 3.0 * q.rho_plus * L;
  d.joint_space = unit_joint_space_range(rho_min, rho_max);
  d.cube = unit_cube_range(p_min, p_max);
  if (std::isfinite(d.joint_sum_limit)) {
    // The cut corner {y in [0, a]^3 : sum y > t} (y = rho_max - rho, a the stroke, t = 3 rho_max - limit)
    // by inclusion-exclusion over the box faces: sum_k (-1)^k C(3, k) max(0, t - k a)^3 / 6.
    const double a = rho_max - rho_min, t = 3.0 * rho_max - 3.0 * q.rho_plus;
    double cut = 0.0;
    const double binomial[4] = {1, 3, 3, 1};
    for (int k = 0; k < 4; ++k) cut += (k % 2 ? -1.0 : 1.0) * binomial[k] * std::pow(std::max(0.0, t - k * a), 3) / 6.0;
    d.joint_box_kept = 1.0 - cut / (a * a * a);
  }
  return d;
}

WorkspaceSearch search_cube_with_encoder_offset(const OrthoglideGeometry& g, double p_min, double p_max, double offset,
                                                int n) {
  const Evaluator eval = [&g, offset](const Vec3& p) {
    auto rho = inverse_kinematics(g, p);
    if (!rho.ok()) return Sample{Sample::kSerial, p, Vec3::Zero(), {}};
    return joint_sample(g, *rho + Vec3::Constant(offset));
  };
  return search(p_min, p_max, kInf, n, eval);
}

OrthoglideDesignCheck check_design(const OrthoglideDesign& d, int n, const std::vector<double>& encoder_offsets) {
  const OrthoglideGeometry g{d.link_length};
  OrthoglideDesignCheck c{
      search_joint_space(g, d.rho_min, d.rho_max, d.joint_sum_limit, n), search_cube(g, d.p_min, d.p_max, n), {}};
  for (double e : encoder_offsets)
    c.encoder_offsets.push_back({e, search_cube_with_encoder_offset(g, d.p_min, d.p_max, e, n)});
  return c;
}

JointWorkspaceSamples sample_joint_workspace(const OrthoglideDesign& d, int n) {
  n = std::max(n, 2);
  JointWorkspaceSamples s;
  s.n = n;
  const std::size_t count = static_cast<std::size_t>(n) * n * n;
  s.rho.resize(count);
  s.p.assign(count, Vec3::Zero());
  s.factors.resize(count);
  s.valid.assign(count, 0);
  const OrthoglideGeometry g{d.link_length};
  auto at = [&](int i) { return d.rho_min + (d.rho_max - d.rho_min) * i / (n - 1); };
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const std::size_t idx = i + static_cast<std::size_t>(n) * (j + static_cast<std::size_t>(n) * k);
        s.rho[idx] = Vec3(at(i), at(j), at(k));
        if (s.rho[idx].sum() > d.joint_sum_limit * (1.0 + 1e-12)) continue;
        const Sample smp = joint_sample(g, s.rho[idx]);
        if (smp.kind != Sample::kRegular) continue;
        s.p[idx] = smp.p;
        s.factors[idx] = smp.v;
        s.valid[idx] = 1;
      }
  return s;
}

Status check_search_points(int n, double max_points, const std::string& item, const std::string& limit) {
  if (n < 2) return Status::Invalid(fmt::format("{} {}: the search grid needs at least 2 points per edge", item, n));
  const double points = 7.0 * n * n + std::pow(n / 4.0, 3.0);
  return check_size(points, max_points, fmt::format("{} {}", item, n), "points searched (~7 N^2 + N^3/64)",
                    fmt::format("give a smaller {} or raise the limit with {}", item, limit));
}

Status check_grid_points(int n, double max_points, const std::string& item, const std::string& limit) {
  if (n < 2) return Status::Invalid(fmt::format("{} {}: the grid needs at least 2 points per axis", item, n));
  return check_size(std::pow(static_cast<double>(n), 3.0), max_points, fmt::format("{} {}", item, n),
                    "grid points (N^3)", fmt::format("give a smaller {} or raise the limit with {}", item, limit));
}

}  // namespace kinestat::mechanisms
