// Closed-loop kinematics of a RobotModel (docs/robots.md, "Kinematics"): Newton on the loop
// closure and task equations with the Jacobians from the joint screws (vjm::jacobians of each leg's
// kinematic chain), continuation from a solved posture, and the branch test by the signs of the
// Jacobians' determinants.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "kinestat/core/small_qr.hpp"
#include "kinestat/mechanisms/robot_model.hpp"
#include "robot_equations.hpp"

namespace kinestat::mechanisms {
namespace {

constexpr double kTolerance = 1e-12;  // scaled residual (m / length scale, rad): ~1e4 eps
constexpr int kMaxNewton = 25;
constexpr double kMaxNewtonStep = 0.3;  // scaled: a larger step is shortened (damped Newton)
// The walk from home: its step (scaled task distance; Newton from the last posture then takes four
// iterations, residuals 1e-1, 3e-2, 1e-3, 4e-7, 1e-13 on the Delta), and the smallest share of it
// tried before the walk gives up. A map's points with no closure each cost a walk that fails: at 0.05
// and 1e-3 they took 62 % of the Delta map's Jacobian factorizations, at 0.1 and 1e-2 51 % of 24 %
// fewer in all, every bundled robot's maps the same (benchmarks/README.md).
constexpr double kContinuationStep = 0.1;
constexpr double kMinContinuationStep = 1e-2;
// No walk longer than this (scaled task distance: 100 times the robot's length scale, 1 000 steps):
// a robot with no reach bound (a first prismatic joint) would walk towards a far task for ever, and a
// step below the start's round-off would never advance.
constexpr double kMaxWalk = 100.0;

int platform_components(const RobotModel& m) { return m.description().planar ? 3 : 6; }
int platform_component(const RobotModel& m, int i) { return m.description().planar ? kPlanarComponents[i] : i; }
// The platform unknown of a pose component (its inverse).
int platform_unknown(const RobotModel& m, int component) {
  return m.description().planar ? (component == 5 ? 2 : component) : component;
}
int closure_count(const RobotModel& m) { return m.closure_offset(m.num_legs()); }
bool is_angle(TaskCoordinate c) { return c >= TaskCoordinate::kRx; }

// Rotation angles (rx, ry, rz) of R = Rz(rz) Ry(ry) Rx(rx) and E with omega = E (rx', ry', rz').
Vec3 angles(const Mat3& R) {
  return {std::atan2(R(2, 1), R(2, 2)), std::atan2(-R(2, 0), std::hypot(R(0, 0), R(1, 0))),
          std::atan2(R(1, 0), R(0, 0))};
}
Mat3 angle_rates(const Vec3& a) {
  const Eigen::AngleAxisd Rz(a.z(), Vec3::UnitZ()), Ry(a.y(), Vec3::UnitY());
  Mat3 E;
  E.col(0) = Rz * (Ry * Vec3::UnitX());
  E.col(1) = Rz * Vec3::UnitY();
  E.col(2) = Vec3::UnitZ();
  return E;
}

// Scale of each unknown / equation: lengths divided by the length scale, angles as they are.
bool unknown_is_length(const RobotModel& m, int u) {
  const int n = m.num_coordinates();
  if (u >= n) return platform_component(m, u - n) < 3;
  const auto& c = m.coordinates()[u];
  return coordinate_is_length(m.joint(c).type, c.index);
}
bool equation_is_length(const RobotModel& m, int r) {
  const int closure = closure_count(m);
  if (r < closure) return m.closure_equations()[r].component < 3;
  return !is_angle(m.description().task[r - closure]);
}

// The task rows of the residual at (posture, task): the closure rows' do not depend on the task.
void task_residual(const RobotModel& m, const RobotPosture& p, const VecX& task, VecX& residual) {
  const auto& d = m.description();
  const int closure = closure_count(m);
  const Vec3 a = angles(p.tool.linear());
  for (std::size_t t = 0; t < d.task.size(); ++t) {
    const int c = static_cast<int>(d.task[t]), row = closure + static_cast<int>(t);
    residual(row) = c < 3 ? p.tool.translation()(c) - task(t) : std::remainder(a(c - 3) - task(t), 2.0 * M_PI);
  }
}

// Residual and inverse Jacobian at (posture, task) into data.residual and data.jacobian.
void evaluate(const RobotModel& m, const RobotPosture& p, const VecX& task, RobotData& data) {
  const int n = m.num_coordinates(), np = platform_components(m);
  const auto& d = m.description();
  // Every row of the residual, and every entry of the Jacobian's structure (make_robot_data zeroes the
  // rest once), is written below.
  data.redundant_residual = 0.0;
  for (int l = 0; l < m.num_legs(); ++l) {
    const int off = m.leg_offset(l), nl = m.leg_coordinates(l);
    data.leg_q[l] = p.q.segment(off, nl);
    vjm::ChainJacobians& J = data.leg_jacobians[l];
    vjm::jacobians(m.kinematic_chain(l), data.leg_q[l], data.no_theta, J);
    const Vec6 diff = vjm::pose_difference(J.pose, p.tool);
    for (int r = m.closure_offset(l); r < m.closure_offset(l + 1); ++r) {
      const int comp = m.closure_equations()[r].component;
      data.residual(r) = diff(comp);
      data.jacobian.row(r).segment(off, nl) = J.Jq.row(comp);
      data.jacobian(r, n + platform_unknown(m, comp)) = -1.0;
    }
    for (const RobotModel::ClosureEquation& c : m.redundant_equations())
      if (c.leg == l)
        data.redundant_residual =
            std::max(data.redundant_residual, std::abs(diff(c.component)) / (c.component < 3 ? m.length_scale() : 1.0));
  }
  task_residual(m, p, task, data.residual);
  const int closure = closure_count(m);
  Mat3 Einv = Mat3::Identity();
  bool need_rates = false;
  for (TaskCoordinate c : d.task) need_rates |= is_angle(c) && !d.planar;
  if (need_rates) Einv = angle_rates(angles(p.tool.linear())).inverse();
  for (std::size_t t = 0; t < d.task.size(); ++t) {
    const int c = static_cast<int>(d.task[t]), row = closure + static_cast<int>(t);
    for (int i = 0; i < np; ++i) {
      const int comp = platform_component(m, i);
      if (c < 3 && comp == c) data.jacobian(row, n + i) = 1.0;
      if (c >= 3 && comp >= 3) data.jacobian(row, n + i) = d.planar ? 1.0 : Einv(c - 3, comp - 3);
    }
  }
}

double scaled_norm(const RobotModel& m, const VecX& v, bool equations) {
  double s = 0.0;
  for (int i = 0; i < v.size(); ++i) {
    const bool length = equations ? equation_is_length(m, i) : unknown_is_length(m, i);
    const double x = length ? v(i) / m.length_scale() : v(i);
    s += x * x;
  }
  return std::sqrt(s);
}

void apply_step(const RobotModel& m, const VecX& dx, RobotPosture& p) {
  const int n = m.num_coordinates();
  p.q += dx.head(n);
  Vec6 twist = Vec6::Zero();
  for (int i = 0; i < platform_components(m); ++i) twist(platform_component(m, i)) = dx(n + i);
  p.tool = vjm::displace(p.tool, twist);
}

// The block factorization of RobotBlockFactors (robot_model.hpp) of a matrix A of its structure.
// Its equations are A's: the same unknowns, the same solution to round-off, a cost linear in the
// legs (a dense LU of the Delta's 21 or the hexapod's 42 unknowns was a quarter of a map's time).
void block_layout(RobotBlockFactors& f, const RobotModel& m, int platform, const std::vector<int>& counts) {
  f.platform = platform;
  f.legs.assign(counts.size(), {});
  int column = 0;
  for (std::size_t l = 0; l < counts.size(); ++l) {
    const int leg = static_cast<int>(l);
    f.legs[l].row = m.closure_offset(leg);
    f.legs[l].equations = m.closure_offset(leg + 1) - m.closure_offset(leg);
    f.legs[l].column = column;
    f.legs[l].count = counts[l];
    column += counts[l];
  }
  f.size = column + platform;
  f.S.setIdentity();
  f.x = f.sign = f.old_sign = VecX::Zero(f.size);
}

// The legs' rows (the task's follow).
int closure_rows(const RobotBlockFactors& f) { return f.legs.back().row + f.legs.back().equations; }

// False (and f.regular false) when a pivot is zero: A is singular (det A = +-prod det R det S).
// Reads A's structure only: each leg's rows in its own and the platform's columns, the task's rows
// in the platform's.
bool block_factor(const MatX& A, RobotBlockFactors& f) {
  const int np = f.platform, pc = f.size - np;
  const int closure = closure_rows(f);
  f.regular = false;
  // ||A||_1, the largest column sum of |A| (PartialPivLU's l1 norm), over the blocks of the structure.
  Vec6 platform_sums = Vec6::Zero();
  f.norm = 0.0;
  int row = 0;
  for (RobotBlockFactors::Leg& g : f.legs) {
    const int k = g.count, r0 = g.row, e = g.equations;
    if (k > e || row + e - k > np) return false;  // not a valid model's structure (refused at home)
    for (int j = 0; j < k; ++j) {
      double sum = 0.0;
      for (int i = 0; i < e; ++i) sum += std::abs(g.R(i, j) = A(r0 + i, g.column + j));
      f.norm = std::max(f.norm, sum);
    }
    g.reflections = householder_qr(g.R, e, k, g.Q);
    for (int i = 0; i < k; ++i)
      if (!(g.R(i, i) != 0.0)) return false;
    // G = Q^T A_p over A_p's non-zeros (a closure row has one platform entry).
    g.G.topLeftCorner(e, np).setZero();
    for (int r = 0; r < e; ++r)
      for (int j = 0; j < np; ++j)
        if (const double a = A(r0 + r, pc + j); a != 0.0) {
          platform_sums(j) += std::abs(a);
          for (int i = 0; i < e; ++i) g.G(i, j) += g.Q(r, i) * a;
        }
    f.S.block(row, 0, e - k, np) = g.G.block(k, 0, e - k, np);
    row += e - k;
  }
  for (int r = closure; r < closure + np - row; ++r)
    for (int j = 0; j < np; ++j) {
      const double a = A(r, pc + j);
      f.S(row + r - closure, j) = a;
      platform_sums(j) += std::abs(a);
    }
  f.norm = std::max(f.norm, platform_sums.head(np).maxCoeff());
  f.lu.compute(f.S);
  const auto& U = f.lu.matrixLU();
  for (int i = 0; i < np; ++i)
    if (!(U(i, i) != 0.0)) return false;
  f.regular = true;
  return true;
}

// A x = b, x into b, in 6 x 6 products: past a leg's e rows and np columns Q is the identity and G
// zero, and the vectors are zero past their lengths.
void block_solve(RobotBlockFactors& f, VecX& b) {
  const int np = f.platform;
  const int closure = closure_rows(f);
  Vec6 rhs = Vec6::Zero();
  int row = 0;
  // Q^T b per leg: the first count rows stay (they become the leg's unknowns), the others are S's
  // right-hand side.
  for (RobotBlockFactors::Leg& g : f.legs) {
    const int k = g.count, e = g.equations;
    Vec6 bl = Vec6::Zero();
    bl.head(e) = b.segment(g.row, e);
    g.t.noalias() = g.Q.transpose() * bl;
    rhs.segment(row, e - k) = g.t.segment(k, e - k);
    row += e - k;
  }
  rhs.segment(row, np - row) = b.segment(closure, np - row);
  const Vec6 xp = f.lu.solve(rhs);
  b.tail(np) = xp.head(np);
  for (RobotBlockFactors::Leg& g : f.legs) {
    const int k = g.count;
    g.t.noalias() -= g.G * xp;  // R x_l = Q1^T b_l - G1 x_p
    for (int i = k - 1; i >= 0; --i) {
      double t = g.t(i);
      for (int j = i + 1; j < k; ++j) t -= g.R(i, j) * b(g.column + j);
      b(g.column + i) = t / g.R(i, i);
    }
  }
}

// A^T y = c, y into c: per leg R^T z1 = c_l, then S^T (z2 per leg, y_task) = c_p - sum G1^T z1,
// and y_l = Q z.
void block_solve_transpose(RobotBlockFactors& f, VecX& c) {
  const int np = f.platform;
  const int closure = closure_rows(f);
  Vec6 cp = Vec6::Zero();
  cp.head(np) = c.tail(np);
  for (RobotBlockFactors::Leg& g : f.legs) {
    const int k = g.count;
    g.t.setZero();
    for (int i = 0; i < k; ++i) {  // R^T z1 = c_l
      double t = c(g.column + i);
      for (int j = 0; j < i; ++j) t -= g.R(j, i) * g.t(j);
      g.t(i) = t / g.R(i, i);
    }
    cp.noalias() -= g.G.transpose() * g.t;
  }
  const Vec6 w = f.lu.transpose().solve(cp);
  int row = 0;
  for (RobotBlockFactors::Leg& g : f.legs) {
    const int k = g.count, e = g.equations;
    g.t.segment(k, e - k) = w.segment(row, e - k);
    row += e - k;
    const Vec6 y = g.Q * g.t;
    c.segment(g.row, e) = y.head(e);
  }
  c.segment(closure, np - row) = w.segment(row, np - row);
}

// The sign of det A: the legs' reflections (det Q = -1 each), the row order that makes the
// transformed A block upper triangular (each leg's e - count Schur rows move past the later legs'
// R rows), det R and det S.
int block_det_sign(const RobotBlockFactors& f) {
  int sign = 1, later = 0;
  for (auto g = f.legs.rbegin(); g != f.legs.rend(); ++g) {
    if (g->reflections % 2) sign = -sign;
    if (((g->equations - g->count) * later) % 2) sign = -sign;
    later += g->count;
    for (int i = 0; i < g->count; ++i)
      if (g->R(i, i) < 0) sign = -sign;
  }
  return f.lu.determinant() < 0 ? -sign : sign;
}

// The reciprocal condition number in the 1-norm of A, by Eigen's estimator of ||A^-1||_1 (Higham
// 1988, algorithms 4.1 and 5.1, as PartialPivLU::rcond) on the block solves; 0 when singular.
double block_rcond(RobotBlockFactors& f) {
  if (!f.regular || !(f.norm > 0.0)) return 0.0;
  const int n = f.size;
  VecX& v = f.x;
  v.setConstant(1.0 / n);
  block_solve(f, v);
  double lower = v.lpNorm<1>();
  if (n == 1) return 1.0 / (f.norm * lower);
  double old_lower = lower;
  Eigen::Index jmax = -1, old_jmax = -1;
  // Ties are broken alike at every posture: a component within 1e-10 (of the largest) of zero
  // counts as zero (sign +), one within 1e-10 of the largest as the largest (the first such). The
  // Jacobians' symmetries (a hexapod's legs) make components that are zero or equal but for
  // round-off, which would otherwise pick the estimate's path: two closures within Newton's
  // tolerance gave measures up to 82 % apart.
  const auto first_largest = [&](const VecX& x) {
    const double top = (1.0 - 1e-10) * x.cwiseAbs().maxCoeff();
    Eigen::Index j = 0;
    while (std::abs(x(j)) < top) ++j;
    return j;
  };
  for (int k = 0; k < 4; ++k) {
    const double tiny = 1e-10 * v.cwiseAbs().maxCoeff();
    for (int i = 0; i < n; ++i) f.sign(i) = v(i) < -tiny ? -1.0 : 1.0;
    if (k > 0 && f.sign == f.old_sign) break;
    v = f.sign;
    block_solve_transpose(f, v);
    jmax = first_largest(v);
    if (jmax == old_jmax) break;
    v.setZero();
    v(jmax) = 1.0;
    block_solve(f, v);
    lower = v.lpNorm<1>();
    if (lower <= old_lower) break;
    f.old_sign = f.sign;
    old_jmax = jmax;
    old_lower = lower;
  }
  double alternating = 1.0;
  for (int i = 0; i < n; ++i) {
    v(i) = alternating * (1.0 + static_cast<double>(i) / (n - 1));
    alternating = -alternating;
  }
  block_solve(f, v);
  const double estimate = std::max(lower, 2.0 * v.lpNorm<1>() / (3.0 * n));
  return 1.0 / (f.norm * estimate);
}

// The inverse Jacobian length-scaled (rows and columns) into data.scaled_inverse, on its structure
// (block_factor's; make_robot_data zeroes the rest once).
void scale_inverse(RobotData& data) {
  const RobotBlockFactors& f = data.inverse_factors;
  const int np = f.platform, pc = f.size - np;
  const auto& rs = data.row_scale;
  const auto& cs = data.column_scale;
  for (const RobotBlockFactors::Leg& g : f.legs)
    for (int j = g.column; j < g.column + g.count; ++j)
      for (int i = g.row; i < g.row + g.equations; ++i) data.scaled_inverse(i, j) = rs(i) * data.jacobian(i, j) * cs(j);
  for (int j = pc; j < pc + np; ++j)
    for (int i = 0; i < data.jacobian.rows(); ++i) data.scaled_inverse(i, j) = rs(i) * data.jacobian(i, j) * cs(j);
}

// Newton's matrix: the inverse Jacobian, length-scaled, factored by blocks.
void factor_scaled_inverse(RobotData& data) {
  scale_inverse(data);
  block_factor(data.scaled_inverse, data.inverse_factors);
}

// Damped Newton from `p` to the target; the scaled inverse Jacobian's factors at the solution stay
// in data.inverse_factors. A residual that does not at least halve after a full (undamped) step,
// from the first on, is not converging (Newton from a good start converges quadratically), nor one
// that has not reached a new low in three iterations: the caller shortens its step instead of
// iterating on. With `from_closed`, p is the walk's last closure, whose residual and factors are in
// data.closed_residual and data.closed_factors: the first step solves with them (its Jacobian is
// the same; only the task rows of the residual change), the same step as from a new evaluation.
bool newton(const RobotModel& m, const VecX& task, RobotPosture& p, RobotData& data, int& iterations,
            bool from_closed = false) {
  double previous = std::numeric_limits<double>::infinity(), best = previous;
  bool damped = true;
  for (int it = 0, stalled = 0; it < kMaxNewton; ++it) {
    bool reuse = false;
    double r = 0.0;
    if (it == 0 && from_closed) {
      data.residual = data.closed_residual;
      task_residual(m, p, task, data.residual);
      r = scaled_norm(m, data.residual, true);
      reuse = r >= kTolerance;  // else the solution's own evaluation and factors, below
    }
    if (!reuse) {
      evaluate(m, p, task, data);
      if (!data.residual.allFinite()) return false;
      r = scaled_norm(m, data.residual, true);
      factor_scaled_inverse(data);
      if (r < kTolerance) return true;
    }
    RobotBlockFactors& factors = reuse ? data.closed_factors : data.inverse_factors;
    if (it >= 1 && !damped && r > 0.5 * previous) return false;
    // Damped steps towards a task beyond the workspace's boundary wander without converging: three
    // iterations in a row without a new smallest residual end the solve (the walk halves its step).
    stalled = r < best ? 0 : stalled + 1;
    if (stalled >= 3) return false;
    best = std::min(best, r);
    previous = r;
    ++iterations;
    if (!factors.regular) return false;
    // (Dr J Dc) y = -Dr r, dx = Dc y.
    data.step = -data.row_scale.cwiseProduct(data.residual);
    block_solve(factors, data.step);
    data.step.array() *= data.column_scale.array();
    if (!data.step.allFinite()) return false;
    const double s = scaled_norm(m, data.step, false);
    damped = s > kMaxNewtonStep;
    if (damped) data.step *= kMaxNewtonStep / s;
    apply_step(m, data.step, p);
  }
  return false;
}

// The sign of det of factored blocks; -1 for a singular matrix (the dense LU's zero determinant).
int sign_of(const RobotBlockFactors& f) { return f.regular ? block_det_sign(f) : -1; }

}  // namespace

RobotData make_robot_data(const RobotModel& model) {
  // Square but while make_robot_model chooses an overconstrained robot's equations.
  const int size = model.num_coordinates() + platform_components(model);
  const int closure = closure_count(model), rows = closure + static_cast<int>(model.description().task.size());
  RobotData d;
  d.residual = VecX::Zero(rows);
  d.step = VecX::Zero(size);
  d.jacobian = MatX::Zero(rows, size);
  std::vector<int> coordinates, passive;
  for (int l = 0; l < model.num_legs(); ++l) {
    d.leg_q.push_back(VecX::Zero(model.leg_coordinates(l)));
    vjm::ChainJacobians J;
    J.Jq = MatX::Zero(6, model.leg_coordinates(l));
    d.leg_jacobians.push_back(std::move(J));
    coordinates.push_back(model.leg_coordinates(l));
    passive.push_back(0);
    for (int k = model.leg_offset(l); k < model.leg_offset(l + 1); ++k)
      if (!model.actuated(model.coordinates()[k])) ++passive.back();
  }
  d.row_scale.resize(rows);
  d.column_scale.resize(size);
  for (int i = 0; i < rows; ++i) d.row_scale(i) = equation_is_length(model, i) ? 1.0 / model.length_scale() : 1.0;
  for (int i = 0; i < size; ++i) {
    d.column_scale(i) = unknown_is_length(model, i) ? model.length_scale() : 1.0;
    if (i >= model.num_coordinates() || !model.actuated(model.coordinates()[i])) d.direct_columns.push_back(i);
  }
  const int direct = static_cast<int>(d.direct_columns.size());
  d.scaled_inverse = MatX::Zero(rows, size);
  d.direct = MatX::Zero(closure, direct);
  block_layout(d.inverse_factors, model, platform_components(model), coordinates);
  block_layout(d.direct_factors, model, platform_components(model), passive);
  const int tasks = static_cast<int>(model.description().task.size());
  d.start = d.delta = d.target = VecX::Zero(tasks);
  d.trial = model.home();
  d.closed_residual = d.residual;
  d.closed_factors = d.inverse_factors;
  return d;
}

VecX task_values(const RobotModel& model, const vjm::Transform& tool) {
  const auto& task = model.description().task;
  VecX v(static_cast<int>(task.size()));
  const Vec3 a = angles(tool.linear());
  for (std::size_t t = 0; t < task.size(); ++t) {
    const int c = static_cast<int>(task[t]);
    v(static_cast<int>(t)) = c < 3 ? tool.translation()(c) : a(c - 3);
  }
  return v;
}

std::string column_name(const RobotModel& model, int unknown) {
  const int n = model.num_coordinates();
  if (unknown < n) return model.coordinate_name(unknown);
  static constexpr const char* kNames[] = {"x", "y", "z", "rx", "ry", "rz"};
  return fmt::format("the platform's {}", kNames[platform_component(model, unknown - n)]);
}

namespace {

// The length-scaled inverse and direct Jacobians at (posture, task) into data.scaled_inverse and
// data.direct (robot_jacobians).
void scaled_jacobians(const RobotModel& model, const RobotPosture& posture, RobotData& data, const VecX& task) {
  evaluate(model, posture, task, data);
  scale_inverse(data);  // length-scaled, so that singular values compare m and rad
  const int closure = closure_count(model);
  for (std::size_t k = 0; k < data.direct_columns.size(); ++k)
    data.direct.col(static_cast<int>(k)) = data.scaled_inverse.col(data.direct_columns[k]).head(closure);
}

}  // namespace

RobotJacobians robot_jacobians(const RobotModel& model, const RobotPosture& posture, RobotData& data,
                               const VecX& task) {
  scaled_jacobians(model, posture, data, task);
  RobotJacobians J;
  J.residual = data.residual;
  J.inverse = data.scaled_inverse;
  J.direct = data.direct;
  for (int i = 0; i < J.inverse.cols(); ++i) J.inverse_columns.push_back(i);
  J.direct_columns = data.direct_columns;
  return J;
}

KinematicsResult solve_posture(const RobotModel& model, const VecX& task, RobotPosture& posture, RobotData& data,
                               bool continuation) {
  KinematicsResult out;
  // Beyond a leg's reach (robot_model.hpp) in the task's position components: no closure exists, and
  // a walk from home would only find that out after many failed Newton solves. The ring's test needs
  // the whole tool point: the task's x, y, z (a planar robot's z is home's).
  Vec3 point = model.home().tool.translation(), in_task = Vec3::Zero();
  for (std::size_t t = 0; t < model.description().task.size(); ++t) {
    const int c = static_cast<int>(model.description().task[t]);
    if (c < 3) {
      point(c) = task(static_cast<int>(t));
      in_task(c) = 1.0;
    }
  }
  const bool whole = in_task(0) > 0 && in_task(1) > 0 && (in_task(2) > 0 || model.description().planar);
  const double slack = 1e-9 * model.length_scale();
  for (int l = 0; l < model.num_legs(); ++l) {
    const RobotModel::Reach& reach = model.leg_reach(l);
    if (!std::isfinite(reach.radius)) continue;
    const double distance = (point - reach.origin).cwiseProduct(in_task).norm();
    if (distance > reach.radius + slack) {
      out.message =
          fmt::format("beyond the reach of {}: its tool point is {:.6g} m from its first joint, at most {:.6g} m",
                      model.description().legs[l].name, distance, reach.radius);
      return out;
    }
    if (!whole || reach.axis.isZero()) continue;
    const double from_ring = reach.ring_distance(point);
    if (from_ring > reach.ring_reach + slack) {
      out.message = fmt::format(
          "beyond the reach of {}: its tool point is {:.6g} m from the circle its first joint turns its second "
          "on, at most {:.6g} m",
          model.description().legs[l].name, from_ring, reach.ring_reach);
      return out;
    }
  }
  auto same_branch = [&] { return sign_of(data.inverse_factors) == model.home_inverse_sign(); };
  if (!continuation) {
    if (!newton(model, task, posture, data, out.iterations) || !same_branch()) {
      out.message = "no closure from the neighbouring posture on its branch";
      return out;
    }
  } else {
    VecX& start = data.start;
    VecX& delta = data.delta;
    start = task_values(model, posture.tool);
    delta = task - start;
    for (int t = 0; t < delta.size(); ++t)
      if (is_angle(model.description().task[t])) delta(t) = std::remainder(delta(t), 2.0 * M_PI);
    double distance = 0.0;
    for (int t = 0; t < delta.size(); ++t) {
      const double x = is_angle(model.description().task[t]) ? delta(t) : delta(t) / model.length_scale();
      distance += x * x;
    }
    distance = std::sqrt(distance);
    if (!(distance <= kMaxWalk)) {
      out.message = fmt::format(
          "{:.3g} times the robot's length scale ({:.6g} m) from the posture to start from: "
          "too far to follow the closure there",
          distance, model.length_scale());
      return out;
    }
    const double max_h = distance > kContinuationStep ? kContinuationStep / distance : 1.0;
    double s = 0.0, h = max_h;
    RobotPosture& trial = data.trial;
    // A step that follows a halving is not doubled: at the workspace's boundary the doubled step
    // fails again (6 % fewer factorizations on the Delta's map, the same postures).
    bool halved = false, closed = false;
    while (s < 1.0) {
      const double next = std::min(1.0, s + h);
      trial = posture;
      data.target = start + next * delta;
      if (newton(model, data.target, trial, data, out.iterations, closed) && same_branch()) {
        posture = trial;
        data.closed_residual = data.residual;
        data.closed_factors = data.inverse_factors;
        closed = true;
        s = next;
        if (!halved) h = std::min(2.0 * h, max_h);
        halved = false;
      } else {
        halved = true;
        h *= 0.5;
        if (h < kMinContinuationStep * max_h) {
          out.message = fmt::format("no closure beyond {:.3g} of the way from the start posture", s);
          return out;
        }
      }
    }
  }
  // Newton's last evaluation is at this posture (a converged Newton returns right after it): its
  // scaled inverse Jacobian and factors are the solution's; the direct Jacobian is its columns.
  // An overconstrained robot's redundant equations hold by its geometry, to the closure's tolerance
  // (the equations solved fix the posture); a geometry that breaks one away from home is reported.
  if (!(data.redundant_residual < 1e3 * kTolerance)) {
    out.message = fmt::format(
        "the legs close here but for their redundant constraints (off by {:.3g}, length-scaled): the robot's "
        "over-constraint does not hold away from the drawing",
        data.redundant_residual);
    return out;
  }
  const int closure = closure_count(model);
  for (std::size_t k = 0; k < data.direct_columns.size(); ++k)
    data.direct.col(static_cast<int>(k)) = data.scaled_inverse.col(data.direct_columns[k]).head(closure);
  block_factor(data.direct, data.direct_factors);
  // The reciprocal condition numbers (LAPACK's 1-norm estimate, O(n^2) solves) of the length-scaled
  // Jacobians: a singular value decomposition per posture would cost more than the rest of the
  // kinematics.
  const double measure = std::min(block_rcond(data.inverse_factors), block_rcond(data.direct_factors));
  out.closed = measure >= 1e-12;
  // Joint limits (coordinates from home) first: a closure beyond them is unreachable, whatever else.
  for (int k = 0; k < model.num_coordinates(); ++k) {
    const auto& c = model.coordinates()[k];
    const RobotJoint& j = model.joint(c);
    if (j.limits.empty()) continue;
    const auto [lo, hi] = j.limits[c.index];
    if (posture.q(k) < lo || posture.q(k) > hi) {
      out.message = fmt::format("{} at {}, outside its limits {}", model.coordinate_name(k),
                                coordinate_text(j.type, c.index, posture.q(k)), limits_text(j.type, c.index, lo, hi));
      return out;
    }
  }
  if (!out.closed) {
    out.status = KinematicsStatus::kSingular;
    out.message = "the closure equations lose rank here";
    return out;
  }
  out.singularity_measure = std::min(1.0, measure / model.home_rcond());
  if (sign_of(data.direct_factors) != model.home_direct_sign()) {
    out.status = KinematicsStatus::kOtherBranch;
    out.message = "the platform is on another assembly mode than at home";
    return out;
  }
  out.status = KinematicsStatus::kOk;
  return out;
}

}  // namespace kinestat::mechanisms
