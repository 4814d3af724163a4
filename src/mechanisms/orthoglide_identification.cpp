#include "kinestat/mechanisms/orthoglide_identification.hpp"

#include <fmt/format.h>

#include <cmath>
#include <unsupported/Eigen/NonLinearOptimization>
#include <unsupported/Eigen/NumericalDiff>

#include "kinestat/core/input_checks.hpp"
#include "kinestat/elements/section.hpp"
#include "kinestat/vjm/stiffness.hpp"

namespace kinestat::mechanisms {

const char* input_name(OrthoglideInput input) {
  switch (input) {
    case OrthoglideInput::kActuatorStiffness:
      return "actuator stiffness (N/m)";
    case OrthoglideInput::kBarScale:
      return "bar section scale (-)";
    case OrthoglideInput::kParallelogramWidth:
      return "parallelogram width (m)";
    case OrthoglideInput::kPlatformOffset:
      return "platform offset (m)";
    case OrthoglideInput::kFootLength:
      return "foot length (m)";
  }
  return "?";
}

namespace {

// Relative size below which a Jacobian column or singular value counts as zero. The forward
// differences' noise reaches ~2e-6 (two symmetric targets, identical in exact arithmetic); the
// paper's five-target calibration has its smallest relative singular value near 0.1.
constexpr double kNoEffect = 1e-4;

// The value of an input in the start model (the bar scale is relative to its section: 1).
double start_value(const OrthoglideStiffnessModel& m, OrthoglideInput input) {
  switch (input) {
    case OrthoglideInput::kActuatorStiffness:
      return m.actuator_stiffness;
    case OrthoglideInput::kBarScale:
      return 1.0;
    case OrthoglideInput::kParallelogramWidth:
      return m.parallelogram_width;
    case OrthoglideInput::kPlatformOffset:
      return m.platform_offset;
    case OrthoglideInput::kFootLength:
      return m.foot_length;
  }
  return 0.0;
}

OrthoglideStiffnessModel with_inputs(const OrthoglideStiffnessModel& start, const std::vector<OrthoglideInput>& inputs,
                                     const Eigen::VectorXd& log_values) {
  OrthoglideStiffnessModel m = start;
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    const double v = std::exp(log_values[static_cast<Eigen::Index>(k)]);
    switch (inputs[k]) {
      case OrthoglideInput::kActuatorStiffness:
        m.actuator_stiffness = v;
        break;
      case OrthoglideInput::kBarScale:
        m.bar_section = scaled_section(start.bar_section, v);
        break;
      case OrthoglideInput::kParallelogramWidth:
        m.parallelogram_width = v;
        break;
      case OrthoglideInput::kPlatformOffset:
        m.platform_offset = v;
        break;
      case OrthoglideInput::kFootLength:
        m.foot_length = v;
        break;
    }
  }
  return m;
}

// "SOURCE: target 'LABEL': message"
Status target_status(const ComplianceTarget& t, const Status& s) {
  return Status(s.code(), at_source(t.source, fmt::format("target '{}': {}", t.label, s.message())));
}

StatusOr<double> model_compliance(const OrthoglideStiffnessModel& m, const ComplianceTarget& t) {
  StatusOr<std::vector<vjm::Chain>> chains = orthoglide_chains(m, t.architecture, t.point);
  if (!chains.ok()) return target_status(t, chains.status());
  StatusOr<CartesianStiffness> K = vjm::platform_unloaded_stiffness(*chains);
  if (!K.ok()) return target_status(t, K.status());
  if (!K->compliance_defined) return target_status(t, Status::Singular(K->status.message()));
  return K->compliance(t.row, t.col);
}

// Eigen's NumericalDiff / LevenbergMarquardt functor interface.
struct Residuals {
  using Scalar = double;
  using InputType = Eigen::VectorXd;
  using ValueType = Eigen::VectorXd;
  using JacobianType = Eigen::MatrixXd;
  enum { InputsAtCompileTime = Eigen::Dynamic, ValuesAtCompileTime = Eigen::Dynamic };

  const OrthoglideStiffnessModel* start_model;
  const std::vector<OrthoglideInput>* free_inputs;
  const std::vector<ComplianceTarget>* target_terms;
  Status* failure;  // the last failed evaluation (the functor is copied by NumericalDiff)

  int inputs() const { return static_cast<int>(free_inputs->size()); }
  int values() const { return static_cast<int>(target_terms->size()); }

  int operator()(const Eigen::VectorXd& x, Eigen::VectorXd& r) const {
    const OrthoglideStiffnessModel m = with_inputs(*start_model, *free_inputs, x);
    for (std::size_t k = 0; k < target_terms->size(); ++k) {
      const ComplianceTarget& t = (*target_terms)[k];
      StatusOr<double> c = model_compliance(m, t);
      if (!c.ok()) {
        // A trial step outside the model's domain (e.g. a spring too soft to be positive definite in
        // double precision): a large residual makes the minimizer reject it and shorten the step.
        *failure = c.status();
        r.setConstant(1e6);
        return 0;
      }
      // Diagonal terms are positive: their log ratio keeps the minimizer away from the degenerate
      // corner where one compliance vanishes (its relative error would stay bounded by 1 there).
      const double ratio = *c / t.value;
      r[static_cast<Eigen::Index>(k)] = t.row == t.col && ratio > 0 ? std::log(ratio) : ratio - 1.0;
    }
    return 0;
  }
};

// The targets determine the inputs when the Jacobian of the residuals (d r / d log x) has full column
// rank: a zero column is an input that changes no target, a dependent set of columns a combination
// of inputs that changes none (the targets repeat each other's information). Checked at the start;
// LM would otherwise stop anywhere along the undetermined direction and report success.
Status check_identifiable(Eigen::NumericalDiff<Residuals>& df, const Eigen::VectorXd& x,
                          const std::vector<OrthoglideInput>& inputs, const Status& failure) {
  Eigen::MatrixXd J(df.values(), df.inputs());
  df.df(x, J);
  if (!failure.ok()) return failure;  // a target cannot be evaluated next to the start
  const double largest = J.colwise().norm().maxCoeff();
  for (Eigen::Index k = 0; k < J.cols(); ++k)
    if (!(J.col(k).norm() > kNoEffect * largest))
      return Status::Invalid(
          fmt::format("identification: the {} has no effect on the targets; remove it from the "
                      "inputs or add a target that depends on it",
                      input_name(inputs[static_cast<std::size_t>(k)])));
  const Eigen::MatrixXd Jn = J * J.colwise().norm().cwiseInverse().asDiagonal();
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(Jn, Eigen::ComputeThinV);
  const Eigen::VectorXd& sv = svd.singularValues();
  if (sv[sv.size() - 1] > kNoEffect * sv[0]) return Status::Ok();
  const Eigen::VectorXd v = svd.matrixV().col(sv.size() - 1);
  std::string combination;
  for (Eigen::Index k = 0; k < v.size(); ++k)
    if (std::abs(v[k]) > 0.05)
      combination += fmt::format("{}{:+.2f} log({})", combination.empty() ? "" : " ", v[k],
                                 input_name(inputs[static_cast<std::size_t>(k)]));
  return Status::Invalid(
      fmt::format("identification: the targets cannot determine the inputs: changing {} changes "
                  "no target (condition {:.1e}); give targets that tell these inputs apart",
                  combination, sv[0] / sv[sv.size() - 1]));
}

}  // namespace

StatusOr<OrthoglideIdentification> identify_orthoglide_inputs(const OrthoglideStiffnessModel& start,
                                                              const std::vector<OrthoglideInput>& inputs,
                                                              const std::vector<ComplianceTarget>& targets,
                                                              double tolerance) {
  if (Status s = validate_stiffness_model(start); !s.ok()) return s;
  if (!(tolerance > 0.0 && tolerance < 1.0))
    return Status::Invalid(
        fmt::format("identification tolerance {:g}: give a relative residual in (0, 1), e.g. 1e-8", tolerance));
  if (inputs.empty() || targets.size() < inputs.size())
    return Status::Invalid(
        fmt::format("identification: {} target(s) for {} input(s); give at least as many "
                    "targets as inputs",
                    targets.size(), inputs.size()));
  for (std::size_t k = 0; k < targets.size(); ++k) {
    const ComplianceTarget& t = targets[k];
    if (t.row < 0 || t.row > 5 || t.col < 0 || t.col > 5 || !std::isfinite(t.value) || t.value == 0.0)
      return target_status(t, Status::Invalid("needs row and col in 0..5 and a finite, non-zero value"));
    if (t.row == t.col && !(t.value > 0.0))
      return target_status(t, Status::Invalid(fmt::format("the diagonal compliance C({},{}) = {:g} is negative: a "
                                                          "compliance matrix is positive definite, its diagonal "
                                                          "positive; check the sign",
                                                          t.row, t.col, t.value)));
    for (std::size_t j = 0; j < k; ++j) {
      const ComplianceTarget& o = targets[j];
      const bool same_term = (o.row == t.row && o.col == t.col) || (o.row == t.col && o.col == t.row);  // C symmetric
      if (o.architecture == t.architecture && same_term && (o.point - t.point).norm() <= 1e-12)
        return target_status(t, Status::Invalid(fmt::format("the same term as target '{}'{}: a repeated target adds "
                                                            "no information, so the inputs are not determined; "
                                                            "give another term",
                                                            o.label, o.source.empty() ? "" : " (" + o.source + ")")));
    }
  }
  Eigen::VectorXd x(static_cast<Eigen::Index>(inputs.size()));
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    const double v = start_value(start, inputs[k]);
    if (!(v > 0))
      return Status::Invalid(fmt::format("identification: the start value of the {} must be positive (got {:g})",
                                         input_name(inputs[k]), v));
    x[static_cast<Eigen::Index>(k)] = std::log(v);
    if ((inputs[k] == OrthoglideInput::kBarScale && start.bar_spring) ||
        (inputs[k] == OrthoglideInput::kFootLength && start.foot_spring))
      return Status::Invalid(
          fmt::format("identification: the start model overrides the {} spring with a 6x6 "
                      "matrix, so the {} has no effect; remove the override or that input",
                      inputs[k] == OrthoglideInput::kBarScale ? "bar" : "foot", input_name(inputs[k])));
  }

  Status failure = Status::Ok();
  Residuals f{&start, &inputs, &targets, &failure};
  Eigen::VectorXd r0(static_cast<Eigen::Index>(targets.size()));
  f(x, r0);
  if (!failure.ok()) return failure;  // the start itself cannot be evaluated
  Eigen::NumericalDiff<Residuals> df(f);
  if (Status s = check_identifiable(df, x, inputs, failure); !s.ok()) return s;
  Eigen::LevenbergMarquardt<Eigen::NumericalDiff<Residuals>> lm(df);
  lm.parameters.ftol = lm.parameters.xtol = 1e-14;
  lm.parameters.maxfev = 400 * static_cast<Eigen::Index>(inputs.size() + 1);
  lm.minimize(x);

  OrthoglideIdentification out;
  out.model = with_inputs(start, inputs, x);
  out.iterations = static_cast<int>(lm.iter);
  out.evaluations = static_cast<int>(lm.nfev);
  std::string r = "Identified inputs (start -> identified):\n";
  for (std::size_t k = 0; k < inputs.size(); ++k) {
    out.start_values.push_back(start_value(start, inputs[k]));
    out.values.push_back(std::exp(x[static_cast<Eigen::Index>(k)]));
    r += fmt::format("  {:<28} {:>12.6g} -> {:.6g}\n", input_name(inputs[k]), out.start_values[k], out.values[k]);
  }
  r += "Targets (SI) and the identified model:\n";
  double worst = 0.0;
  std::string worst_label;
  for (const ComplianceTarget& t : targets) {
    StatusOr<double> c = model_compliance(out.model, t);
    if (!c.ok()) return c.status();
    const double rel = (*c - t.value) / std::abs(t.value);
    out.relative_residual.push_back(rel);
    if (std::abs(rel) >= worst) worst = std::abs(rel), worst_label = t.label;
    r += fmt::format("  {:<36} C({},{}) target {:.6e} model {:.6e} (relative {:+.1e})\n", t.label, t.row, t.col,
                     t.value, *c, rel);
  }
  r += fmt::format("Levenberg-Marquardt: {} iterations, {} evaluations, largest relative residual {:.2e} ({})\n",
                   out.iterations, out.evaluations, worst, worst_label);
  out.report = std::move(r);
  if (!(worst <= tolerance))
    return Status::NotConverged(
        fmt::format("identification did not reach the tolerance {:g}: from this start, no "
                    "values of the inputs make the model meet these targets (inconsistent "
                    "targets, or a start too far away); the closest model found:\n{}",
                    tolerance, out.report));
  return out;
}

std::vector<ComplianceTarget> paper_calibration_targets() {
  using A = OrthoglideArchitecture;
  constexpr double tran = 1e-7, rot = 1e-4;  // the tables' 1e-4 mm/N and 1e-7 rad/(N mm) in SI
  auto target = [](std::string label, A a, double c, int index, double value) {
    return ComplianceTarget{std::move(label), a, paper_table_point(c), index, index, value};
  };
  return {target("Tables 1-2, Q0, k_tran", A::kPUU, 0.0, 0, 2.78 * tran),
          target("Table 1, Q0, k_rot", A::kPUU, 0.0, 3, 20.9 * rot),
          target("Table 2, Q0, k_rot", A::kPRPaR, 0.0, 3, 1.94 * rot),
          target("Table 1, Q2, k_tran", A::kPUU, 126.35, 0, 71.3 * tran),
          target("Table 2, Q2, k_tran", A::kPRPaR, 126.35, 0, 21.2 * tran)};
}

OrthoglideStiffnessModel paper_calibration_start() {
  OrthoglideStiffnessModel m;
  m.platform_offset = 0.05;
  return m;
}

std::vector<OrthoglideInput> paper_calibration_inputs() {
  return {OrthoglideInput::kActuatorStiffness, OrthoglideInput::kBarScale, OrthoglideInput::kParallelogramWidth,
          OrthoglideInput::kPlatformOffset, OrthoglideInput::kFootLength};
}

}  // namespace kinestat::mechanisms
