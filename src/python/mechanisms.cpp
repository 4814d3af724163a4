// kinestat.mechanisms: the five-bar and the Orthoglide (kinematics, design strategies, stiffness
// models, MSA frame, identification) and the posture kernels with evaluate_postures, whose results
// come back as NumPy arrays shaped like the grid of points (mechanisms/*.hpp).
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include <fmt/format.h>
#include <pybind11/operators.h>
#include <Eigen/LU>

#include "kinestat/core/input_checks.hpp"
#include "kinestat/mechanisms/five_bar.hpp"
#include "kinestat/mechanisms/five_bar_kernel.hpp"
#include "kinestat/mechanisms/five_bar_vjm.hpp"
#include "kinestat/mechanisms/orthoglide_design.hpp"
#include "kinestat/mechanisms/orthoglide_frame.hpp"
#include "kinestat/mechanisms/orthoglide_identification.hpp"
#include "kinestat/mechanisms/orthoglide_kernel.hpp"
#include "kinestat/mechanisms/orthoglide_kinematics.hpp"
#include "kinestat/mechanisms/orthoglide_stiffness.hpp"
#include "kinestat/mechanisms/posture_kernel.hpp"
#include "python/bindings.hpp"

namespace kinestat::python {

namespace {

using namespace mechanisms;

void bind_five_bar(py::module_& m) {
  py::class_<FiveBarParams>(m, "FiveBarParams",
                            "Five-bar of Goncalves et al. 2010: link lengths r1, r2, r3 (m, paper: 0.1), link "
                            "material and section, joint stiffness (N/m x3, N m/rad x3; kr_z = 0 the free rotation), "
                            "load (N) of the Fx and Fy load cases.")
      .def(py::init<>())
      .def_readwrite("r1", &FiveBarParams::r1)
      .def_readwrite("r2", &FiveBarParams::r2)
      .def_readwrite("r3", &FiveBarParams::r3)
      .def_readwrite("link_material", &FiveBarParams::link_material)
      .def_readwrite("link_section", &FiveBarParams::link_section)
      .def_readwrite("joint_stiffness", &FiveBarParams::joint_stiffness)
      .def_readwrite("load", &FiveBarParams::load);
  py::class_<WorkingMode>(m, "WorkingMode", "Root of eq. (18) per leg: sign1, sign2 = +1 or -1.")
      .def(py::init([](int s1, int s2) {
             return WorkingMode{s1, s2};
           }),
           py::arg("sign1") = 1, py::arg("sign2") = 1)
      .def_readwrite("sign1", &WorkingMode::sign1)
      .def_readwrite("sign2", &WorkingMode::sign2)
      .def(py::self == py::self)
      .def("__str__", [](WorkingMode w) { return to_string(w); })
      .def("__repr__", [](WorkingMode w) { return "WorkingMode('" + to_string(w) + "')"; });
  py::enum_<Assembly>(m, "Assembly").value("UP", Assembly::kUp).value("DOWN", Assembly::kDown);
  py::class_<FiveBarPosture>(m, "FiveBarPosture", "Input angles (rad), joint centres (m) and mode labels.")
      .def_readonly("theta1", &FiveBarPosture::theta1)
      .def_readonly("theta2", &FiveBarPosture::theta2)
      .def_readonly("A1", &FiveBarPosture::A1)
      .def_readonly("B1", &FiveBarPosture::B1)
      .def_readonly("P", &FiveBarPosture::P)
      .def_readonly("B2", &FiveBarPosture::B2)
      .def_readonly("A2", &FiveBarPosture::A2)
      .def_readonly("working_mode", &FiveBarPosture::working_mode)
      .def_readonly("assembly", &FiveBarPosture::assembly);
  m.def(
      "validate", [](const FiveBarParams& p) { check(validate(p)); }, py::arg("params"));
  m.def(
      "inverse_kinematics",
      [](const FiveBarParams& p, const Vec2& point) { return unwrap(inverse_kinematics(p, point)); }, py::arg("params"),
      py::arg("point"), "Five-bar, eq. (14)-(19): the four postures (++, +-, -+, --) at P (m).");
  m.def(
      "inverse_kinematics",
      [](const FiveBarParams& p, const Vec2& point, WorkingMode mode) {
        return unwrap(inverse_kinematics(p, point, mode));
      },
      py::arg("params"), py::arg("point"), py::arg("mode"));
  m.def(
      "direct_kinematics",
      [](const FiveBarParams& p, double t1, double t2) { return unwrap(direct_kinematics(p, t1, t2)); },
      py::arg("params"), py::arg("theta1"), py::arg("theta2"),
      "Five-bar, eq. (20)-(27): both assembly modes [up, down] for input angles (rad).");
  m.def(
      "direct_kinematics",
      [](const FiveBarParams& p, double t1, double t2, Assembly a) { return unwrap(direct_kinematics(p, t1, t2, a)); },
      py::arg("params"), py::arg("theta1"), py::arg("theta2"), py::arg("assembly"));
  py::class_<FiveBarJacobians>(m, "FiveBarJacobians", "A dP = B dtheta; singularity measures in [0, 1].")
      .def_readonly("A", &FiveBarJacobians::A)
      .def_readonly("B", &FiveBarJacobians::B)
      .def_readonly("parallel_measure", &FiveBarJacobians::parallel_measure)
      .def_readonly("serial_measure", &FiveBarJacobians::serial_measure)
      .def("parallel_singular", &FiveBarJacobians::parallel_singular, py::arg("tol") = 1e-6)
      .def("serial_singular", &FiveBarJacobians::serial_singular, py::arg("tol") = 1e-6);
  m.def("five_bar_jacobians", &five_bar_jacobians, py::arg("posture"));
  m.attr("FIVE_BAR_PLATFORM_NODE") = kFiveBarPlatformNode;
  m.def("make_five_bar_structure",
        py::overload_cast<const FiveBarParams&, const FiveBarPosture&>(&make_five_bar_structure), py::arg("params"),
        py::arg("posture"), "The 8-node MSA model of section 5 (load cases Fx, Fy at node '5', the report node).");
  m.def(
      "make_five_bar_structure",
      [](const FiveBarParams& p, double t1, double t2, Assembly a) {
        return unwrap(make_five_bar_structure(p, t1, t2, a));
      },
      py::arg("params"), py::arg("theta1"), py::arg("theta2"), py::arg("assembly") = Assembly::kUp);
  m.def(
      "make_five_bar_structure",
      [](const FiveBarParams& p, const Vec2& point, WorkingMode mode) {
        return unwrap(make_five_bar_structure(p, point, mode));
      },
      py::arg("params"), py::arg("point"), py::arg("mode"));
  m.def("five_bar_vjm_chains", &five_bar_vjm_chains, py::arg("params"), py::arg("posture"),
        "The five-bar as two VJM chains meeting at P (same stiffness as the MSA model).");
}

void bind_orthoglide_kinematics(py::module_& m) {
  py::class_<OrthoglideGeometry>(m, "OrthoglideGeometry")
      .def(py::init([](double L) { return OrthoglideGeometry{L}; }), py::arg("link_length") = 1.0)
      .def_readwrite("link_length", &OrthoglideGeometry::link_length, "L (m)");
  m.def(
      "validate", [](const OrthoglideGeometry& g) { check(validate(g)); }, py::arg("geometry"));
  m.attr("ORTHOGLIDE_WORKING_SIGNS") = kOrthoglideWorkingSigns;
  m.attr("ORTHOGLIDE_WORKING_BRANCH") = kOrthoglideWorkingBranch;
  m.def(
      "inverse_kinematics",
      [](const OrthoglideGeometry& g, const Vec3& p, const OrthoglideSigns& s) {
        return unwrap(inverse_kinematics(g, p, s));
      },
      py::arg("geometry"), py::arg("point"), py::arg("signs") = kOrthoglideWorkingSigns,
      "Orthoglide, eq. (3): joint coordinates rho (m) at the point p (m).");
  m.def("direct_kinematics_branch", &direct_kinematics_branch, py::arg("p"), py::arg("rho"));
  m.def(
      "direct_kinematics",
      [](const OrthoglideGeometry& g, const Vec3& rho) { return unwrap(direct_kinematics(g, rho)); },
      py::arg("geometry"), py::arg("rho"), "Orthoglide, eq. (4): both solutions [working branch m=-1, m=+1].");
  m.def(
      "direct_kinematics",
      [](const OrthoglideGeometry& g, const Vec3& rho, int branch) {
        return unwrap(direct_kinematics(g, rho, branch));
      },
      py::arg("geometry"), py::arg("rho"), py::arg("branch"));
  m.def(
      "inverse_jacobian", [](const Vec3& p, const Vec3& rho) { return unwrap(inverse_jacobian(p, rho)); }, py::arg("p"),
      py::arg("rho"), "Eq. (5); SingularError at a serial singularity.");
  m.def(
      "inverse_jacobian_determinant",
      [](const Vec3& p, const Vec3& rho) { return unwrap(inverse_jacobian_determinant(p, rho)); }, py::arg("p"),
      py::arg("rho"));
  py::class_<VelocityTransmission>(m, "VelocityTransmission", "Dexterity from the singular values of J^-1.")
      .def_readonly("singular_values", &VelocityTransmission::singular_values)
      .def_readonly("mu_min", &VelocityTransmission::mu_min)
      .def_readonly("mu_max", &VelocityTransmission::mu_max)
      .def_readonly("manipulability", &VelocityTransmission::manipulability)
      .def_readonly("condition_number", &VelocityTransmission::condition_number);
  m.def("velocity_transmission", &velocity_transmission, py::arg("inverse_jacobian"));
  m.def(
      "velocity_transmission_at",
      [](const OrthoglideGeometry& g, const Vec3& p) { return unwrap(velocity_transmission_at(g, p)); },
      py::arg("geometry"), py::arg("point"));
}

void bind_orthoglide_design(py::module_& m) {
  m.def("unit_q_axis_position", &unit_q_axis_position, py::arg("chi"));
  m.def("unit_q_axis_joint", &unit_q_axis_joint, py::arg("chi"));
  m.def("unit_q_axis_chi_from_position", &unit_q_axis_chi_from_position, py::arg("p"));
  m.def("unit_q_axis_chi_from_joint", &unit_q_axis_chi_from_joint, py::arg("rho"));
  py::class_<TransmissionRange>(m, "TransmissionRange")
      .def_readonly("min", &TransmissionRange::min)
      .def_readonly("max", &TransmissionRange::max)
      .def_property_readonly("singular", &TransmissionRange::singular);
  py::class_<UnitQAxisLimits>(m, "UnitQAxisLimits")
      .def_readonly("chi_plus", &UnitQAxisLimits::chi_plus)
      .def_readonly("chi_minus", &UnitQAxisLimits::chi_minus)
      .def_readonly("rho_plus", &UnitQAxisLimits::rho_plus)
      .def_readonly("rho_minus", &UnitQAxisLimits::rho_minus)
      .def_readonly("p_plus", &UnitQAxisLimits::p_plus)
      .def_readonly("p_minus", &UnitQAxisLimits::p_minus);
  m.def("unit_q_axis_limits", &unit_q_axis_limits, py::arg("mu"));
  py::enum_<CriticalPoint>(m, "CriticalPoint")
      .value("Q", CriticalPoint::kQ)
      .value("R", CriticalPoint::kR)
      .value("S", CriticalPoint::kS);
  m.def("unit_critical_point_position", &unit_critical_point_position, py::arg("c"), py::arg("rho"));
  m.def("unit_critical_point_singular_values", &unit_critical_point_singular_values, py::arg("c"), py::arg("rho"));
  m.def("unit_joint_space_range", &unit_joint_space_range, py::arg("rho_min"), py::arg("rho_max"));
  m.def("unit_cube_range", &unit_cube_range, py::arg("p_min"), py::arg("p_max"));
  m.def("unit_joint_space_rho_min", &unit_joint_space_rho_min, py::arg("mu"));
  py::class_<WorkspaceSearch>(m, "WorkspaceSearch")
      .def_readonly("range", &WorkspaceSearch::range)
      .def_readonly("p_at_min", &WorkspaceSearch::p_at_min)
      .def_readonly("rho_at_min", &WorkspaceSearch::rho_at_min)
      .def_readonly("p_at_max", &WorkspaceSearch::p_at_max)
      .def_readonly("rho_at_max", &WorkspaceSearch::rho_at_max)
      .def_readonly("evaluations", &WorkspaceSearch::evaluations)
      .def_readonly("singular", &WorkspaceSearch::singular);
  // The searches' sizes are checked (estimated) before they run, as `kinestat design orthoglide` checks them.
  m.def(
      "search_joint_space",
      [](const OrthoglideGeometry& g, double rho_min, double rho_max, double joint_sum_limit, int n,
         double max_points) {
        check(check_search_points(n, max_points, "n", "max_points"));
        return without_gil([&] { return search_joint_space(g, rho_min, rho_max, joint_sum_limit, n); });
      },
      py::arg("geometry"), py::arg("rho_min"), py::arg("rho_max"),
      py::arg("joint_sum_limit") = std::numeric_limits<double>::infinity(), py::arg("n") = 101,
      py::arg("max_points") = kDefaultMaxSearchPoints, "InputError when ~7 n^2 + n^3/64 points exceed max_points.");
  m.def(
      "search_cube",
      [](const OrthoglideGeometry& g, double p_min, double p_max, int n, double max_points) {
        check(check_search_points(n, max_points, "n", "max_points"));
        return without_gil([&] { return search_cube(g, p_min, p_max, n); });
      },
      py::arg("geometry"), py::arg("p_min"), py::arg("p_max"), py::arg("n") = 101,
      py::arg("max_points") = kDefaultMaxSearchPoints, "InputError when ~7 n^2 + n^3/64 points exceed max_points.");
  py::class_<DexterousVolumes>(m, "DexterousVolumes")
      .def_readonly("singularity_free_of_sphere", &DexterousVolumes::singularity_free_of_sphere)
      .def_readonly("lower_of_w0", &DexterousVolumes::lower_of_w0)
      .def_readonly("two_sided_of_w0", &DexterousVolumes::two_sided_of_w0)
      .def_readonly("upper_of_w0", &DexterousVolumes::upper_of_w0);
  m.def(
      "unit_dexterous_volumes",
      [](double mu_low, double mu_high, int n, double max_points) {
        check(check_grid_points(n, max_points, "n", "max_points"));
        return without_gil([&] { return unit_dexterous_volumes(mu_low, mu_high, n); });
      },
      py::arg("mu_low"), py::arg("mu_high"), py::arg("n"), py::arg("max_points") = kDefaultMaxSearchPoints,
      "InputError when the n^3 grid exceeds max_points.");
  py::class_<OrthoglideDesign>(m, "OrthoglideDesign",
                               "A design of Table 3 (Pashkevich, Wenger, Chablat 2005): lengths in m.")
      .def_readonly("strategy", &OrthoglideDesign::strategy)
      .def_readonly("mu", &OrthoglideDesign::mu)
      .def_readonly("cube_size", &OrthoglideDesign::cube_size)
      .def_readonly("link_length", &OrthoglideDesign::link_length)
      .def_readonly("rho_min", &OrthoglideDesign::rho_min)
      .def_readonly("rho_max", &OrthoglideDesign::rho_max)
      .def_readonly("p_min", &OrthoglideDesign::p_min)
      .def_readonly("p_max", &OrthoglideDesign::p_max)
      .def_readonly("rho_q_plus", &OrthoglideDesign::rho_q_plus)
      .def_readonly("joint_sum_limit", &OrthoglideDesign::joint_sum_limit)
      .def_readonly("joint_space", &OrthoglideDesign::joint_space)
      .def_readonly("cube", &OrthoglideDesign::cube);
  m.def(
      "design_orthoglide",
      [](int strategy, double mu, double cube_size) { return unwrap(design_orthoglide(strategy, mu, cube_size)); },
      py::arg("strategy"), py::arg("mu"), py::arg("cube_size"),
      "Strategy 1, 2 or 3 for factors in [mu, 1/mu] and a cube of edge cube_size (m).");
  py::class_<OrthoglideDesignCheck>(m, "OrthoglideDesignCheck")
      .def_readonly("joint_space", &OrthoglideDesignCheck::joint_space)
      .def_readonly("cube", &OrthoglideDesignCheck::cube);
  m.def(
      "check_design",
      [](const OrthoglideDesign& d, int n, const std::vector<double>& offsets, double max_points) {
        check(check_search_points(n, max_points, "n", "max_points"));
        return without_gil([&] { return check_design(d, n, offsets); });
      },
      py::arg("design"), py::arg("n") = 101, py::arg("encoder_offsets") = std::vector<double>{},
      py::arg("max_points") = kDefaultMaxSearchPoints,
      "Numerical search of the factors over the cube and the joint-bounded workspace; encoder_offsets (m). "
      "InputError when a search of ~7 n^2 + n^3/64 points exceeds max_points (`--max-points` of the CLI).");
  py::class_<JointWorkspaceSamples>(m, "JointWorkspaceSamples", "n^3 joint grid, index i + n (j + n k).")
      .def_readonly("n", &JointWorkspaceSamples::n)
      .def_property_readonly(
          "rho", [](const JointWorkspaceSamples& s) { return rows(s.rho); }, "(n^3, 3) m")
      .def_property_readonly(
          "p", [](const JointWorkspaceSamples& s) { return rows(s.p); }, "(n^3, 3) m")
      .def_readonly("factors", &JointWorkspaceSamples::factors)
      .def_property_readonly(
          "valid",
          [](const JointWorkspaceSamples& s) {
            return py::array_t<bool>(static_cast<py::ssize_t>(s.valid.size()),
                                     reinterpret_cast<const bool*>(s.valid.data()));
          },
          "(n^3,) bool");
  m.def(
      "sample_joint_workspace",
      [](const OrthoglideDesign& d, int n, double max_points) {
        check(check_grid_points(n, max_points, "n", "max_points"));
        return without_gil([&] { return sample_joint_workspace(d, n); });
      },
      py::arg("design"), py::arg("n"), py::arg("max_points") = kDefaultMaxSearchPoints,
      "InputError when the n^3 grid exceeds max_points.");
}

void bind_orthoglide_stiffness(py::module_& m) {
  py::enum_<OrthoglideArchitecture>(m, "OrthoglideArchitecture")
      .value("PUU", OrthoglideArchitecture::kPUU)
      .value("PRPAR", OrthoglideArchitecture::kPRPaR);
  m.def("architecture_from_name", &architecture_from_name, py::arg("name"), "'3-PUU' / '3-PRPaR', else None.");
  py::class_<OrthoglideStiffnessModel>(m, "OrthoglideStiffnessModel",
                                       "Inputs of the Orthoglide VJM models (SI units); foot_spring and bar_spring "
                                       "(6x6 or None) replace the beam-built link springs, e.g. by an FEA result.")
      .def(py::init<>())
      .def_readwrite("link_length", &OrthoglideStiffnessModel::link_length)
      .def_readwrite("parallelogram_width", &OrthoglideStiffnessModel::parallelogram_width)
      .def_readwrite("bar_material", &OrthoglideStiffnessModel::bar_material)
      .def_readwrite("bar_section", &OrthoglideStiffnessModel::bar_section)
      .def_readwrite("actuator_stiffness", &OrthoglideStiffnessModel::actuator_stiffness, "N/m")
      .def_readwrite("foot_material", &OrthoglideStiffnessModel::foot_material)
      .def_readwrite("foot_section", &OrthoglideStiffnessModel::foot_section)
      .def_readwrite("foot_length", &OrthoglideStiffnessModel::foot_length)
      .def_readwrite("platform_offset", &OrthoglideStiffnessModel::platform_offset)
      .def_readwrite("foot_spring", &OrthoglideStiffnessModel::foot_spring)
      .def_readwrite("bar_spring", &OrthoglideStiffnessModel::bar_spring);
  m.def("paper_table_point", &paper_table_point, py::arg("coordinate_mm"),
        "Kinematics-frame point (m) of the tables' 'x, y, z = c' (mm).");
  m.def(
      "validate_stiffness_model", [](const OrthoglideStiffnessModel& s) { check(validate_stiffness_model(s)); },
      py::arg("model"));
  m.def(
      "parallelogram_spring",
      [](const OrthoglideStiffnessModel& s, double q) { return unwrap(parallelogram_spring(s, q)); }, py::arg("model"),
      py::arg("q"));
  m.def(
      "orthoglide_chains",
      [](const OrthoglideStiffnessModel& s, OrthoglideArchitecture a, const Vec3& p) {
        return unwrap(orthoglide_chains(s, a, p));
      },
      py::arg("model"), py::arg("architecture"), py::arg("point"), "The three VJM chains at the point p (m).");
  py::class_<OrthoglideStiffness>(m, "OrthoglideStiffness")
      .def_readonly("unloaded", &OrthoglideStiffness::unloaded)
      .def_readonly("loaded", &OrthoglideStiffness::loaded)
      .def_readonly("loaded_state", &OrthoglideStiffness::loaded_state);
  m.def(
      "orthoglide_stiffness",
      [](const OrthoglideStiffnessModel& s, OrthoglideArchitecture a, const Vec3& p, const Vec6& d) {
        return unwrap(without_gil([&] { return orthoglide_stiffness(s, a, p, d); }));
      },
      py::arg("model"), py::arg("architecture"), py::arg("point"), py::arg("displacement") = Vec6(Vec6::Zero()),
      "Unloaded and loaded (platform displaced by `displacement`, m and rad) stiffness at p (m).");
  m.def(
      "orthoglide_frame",
      [](const OrthoglideStiffnessModel& s, OrthoglideArchitecture a, const Vec3& p) {
        return unwrap(orthoglide_frame(s, a, p));
      },
      py::arg("model"), py::arg("architecture"), py::arg("point"), "The same mechanism as an msa.Structure.");

  py::enum_<OrthoglideInput>(m, "OrthoglideInput")
      .value("ACTUATOR_STIFFNESS", OrthoglideInput::kActuatorStiffness)
      .value("BAR_SCALE", OrthoglideInput::kBarScale)
      .value("PARALLELOGRAM_WIDTH", OrthoglideInput::kParallelogramWidth)
      .value("PLATFORM_OFFSET", OrthoglideInput::kPlatformOffset)
      .value("FOOT_LENGTH", OrthoglideInput::kFootLength);
  m.def("input_name", &input_name, py::arg("input"));
  py::class_<ComplianceTarget>(m, "ComplianceTarget", "One unloaded compliance term C[row, col] (SI) at a point.")
      .def(py::init([](std::string label, OrthoglideArchitecture a, const Vec3& point, int row, int col, double value) {
             return ComplianceTarget{std::move(label), a, point, row, col, value};
           }),
           py::arg("label"), py::arg("architecture"), py::arg("point"), py::arg("row"), py::arg("col"),
           py::arg("value"))
      .def_readwrite("label", &ComplianceTarget::label)
      .def_readwrite("architecture", &ComplianceTarget::architecture)
      .def_readwrite("point", &ComplianceTarget::point)
      .def_readwrite("row", &ComplianceTarget::row)
      .def_readwrite("col", &ComplianceTarget::col)
      .def_readwrite("value", &ComplianceTarget::value);
  py::class_<OrthoglideIdentification>(m, "OrthoglideIdentification")
      .def_readonly("model", &OrthoglideIdentification::model)
      .def_readonly("relative_residual", &OrthoglideIdentification::relative_residual)
      .def_readonly("iterations", &OrthoglideIdentification::iterations)
      .def_readonly("evaluations", &OrthoglideIdentification::evaluations)
      .def_readonly("report", &OrthoglideIdentification::report);
  m.def(
      "identify_orthoglide_inputs",
      [](const OrthoglideStiffnessModel& start, const std::vector<OrthoglideInput>& inputs,
         const std::vector<ComplianceTarget>& targets, double tolerance) {
        return unwrap(without_gil([&] { return identify_orthoglide_inputs(start, inputs, targets, tolerance); }));
      },
      py::arg("start"), py::arg("inputs"), py::arg("targets"), py::arg("tolerance") = 1e-8,
      "Levenberg-Marquardt on the inputs so that the model's compliance matches the targets. Releases the GIL.");
  m.def("paper_calibration_targets", &paper_calibration_targets);
  m.def("paper_calibration_inputs", &paper_calibration_inputs);
  m.def("paper_calibration_start", &paper_calibration_start);
}

// evaluate_postures' results as arrays shaped like the points' grid (shape S = points.shape[:-1]).
struct PostureArrays {
  py::array_t<std::uint8_t> status;               // S, PostureStatus values
  py::array_t<double> stiffness;                  // S + (6, 6)
  py::array_t<double> compliance;                 // S + (6, 6)
  py::array_t<double> eigenvalues;                // S + (6,)
  py::array_t<double> translational_eigenvalues;  // S + (3,)
  py::array_t<double> rotational_eigenvalues;     // S + (3,)
  py::array_t<double> condition_number;           // S
  py::array_t<double> singularity_measure;        // S
  py::array_t<double> deflection;                 // S + (6,)
};

std::vector<py::ssize_t> shape_with(std::vector<py::ssize_t> s, std::initializer_list<py::ssize_t> tail) {
  s.insert(s.end(), tail.begin(), tail.end());
  return s;
}

PostureArrays posture_arrays(const std::vector<PostureResult>& r, const std::vector<py::ssize_t>& grid) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  PostureArrays a{py::array_t<std::uint8_t>(grid),
                  py::array_t<double>(shape_with(grid, {6, 6})),
                  py::array_t<double>(shape_with(grid, {6, 6})),
                  py::array_t<double>(shape_with(grid, {6})),
                  py::array_t<double>(shape_with(grid, {3})),
                  py::array_t<double>(shape_with(grid, {3})),
                  py::array_t<double>(grid),
                  py::array_t<double>(grid),
                  py::array_t<double>(shape_with(grid, {6}))};
  auto copy = [](double* out, const auto& m, bool ok) {
    for (Eigen::Index k = 0; k < m.size(); ++k) out[k] = ok ? m.data()[k] : nan;
  };
  for (size_t i = 0; i < r.size(); ++i) {
    const PostureResult& p = r[i];
    const bool ok = p.status == PostureStatus::kOk;
    a.status.mutable_data()[i] = static_cast<std::uint8_t>(p.status);
    // Row-major 6x6 for NumPy: the transpose's column-major data.
    copy(a.stiffness.mutable_data() + 36 * i, Mat6(p.stiffness.transpose()), ok);
    copy(a.compliance.mutable_data() + 36 * i, Mat6(p.compliance.transpose()), ok);
    copy(a.eigenvalues.mutable_data() + 6 * i, p.indices.eigenvalues, ok);
    copy(a.translational_eigenvalues.mutable_data() + 3 * i, p.indices.translational_eigenvalues, ok);
    copy(a.rotational_eigenvalues.mutable_data() + 3 * i, p.indices.rotational_eigenvalues, ok);
    a.condition_number.mutable_data()[i] = ok ? p.indices.condition_number : nan;
    a.singularity_measure.mutable_data()[i] = p.status == PostureStatus::kUnreachable ? nan : p.singularity_measure;
    copy(a.deflection.mutable_data() + 6 * i, p.deflection, ok);
  }
  return a;
}

// A posture kernel written in Python: a subclass of mechanisms.PostureKernel whose evaluate(point)
// returns a PostureResult (and optionally evaluate_next, description). Sweeps call it from C++ with
// the GIL released, so every call into Python takes the GIL first. Its clones (one per sweep thread)
// are PythonKernelClone: they share the one Python object, and evaluate_postures and
// compute_workspace_map run such a kernel on one thread (is_python_kernel), so that it sees the
// points in the sweep's order, as a C++ kernel's clone would.
class PyPostureKernel : public PostureKernel {
 public:
  PostureResult evaluate(const Vec3& point) override {
    py::gil_scoped_acquire gil;
    PYBIND11_OVERRIDE_PURE(PostureResult, PostureKernel, evaluate, point);
  }
  PostureResult evaluate_next(const Vec3& point) override {
    py::gil_scoped_acquire gil;
    PYBIND11_OVERRIDE(PostureResult, PostureKernel, evaluate_next, point);
  }
  std::unique_ptr<PostureKernel> clone() const override;
  std::string description() const override {
    py::gil_scoped_acquire gil;
    if (py::function f = py::get_override(static_cast<const PostureKernel*>(this), "description"))
      return f().cast<std::string>();
    const py::object self = py::cast(static_cast<const PostureKernel*>(this), py::return_value_policy::reference);
    return fmt::format("{} (Python)", py::type::of(self).attr("__qualname__").cast<std::string>());
  }
};

// A clone of a Python kernel: the same Python object, kept alive (references change under the GIL).
class PythonKernelClone final : public PostureKernel {
 public:
  explicit PythonKernelClone(const PyPostureKernel* kernel) : kernel_(const_cast<PyPostureKernel*>(kernel)) {
    py::gil_scoped_acquire gil;
    self_ = py::cast(static_cast<const PostureKernel*>(kernel), py::return_value_policy::reference);
  }
  PythonKernelClone(const PythonKernelClone&) = delete;
  PythonKernelClone& operator=(const PythonKernelClone&) = delete;
  ~PythonKernelClone() override {
    py::gil_scoped_acquire gil;
    self_ = py::object();
  }
  PostureResult evaluate(const Vec3& point) override { return kernel_->evaluate(point); }
  PostureResult evaluate_next(const Vec3& point) override { return kernel_->evaluate_next(point); }
  std::unique_ptr<PostureKernel> clone() const override { return std::make_unique<PythonKernelClone>(kernel_); }
  std::string description() const override { return kernel_->description(); }

 private:
  PyPostureKernel* kernel_;
  py::object self_;
};

std::unique_ptr<PostureKernel> PyPostureKernel::clone() const { return std::make_unique<PythonKernelClone>(this); }

// A PostureResult from Python (a Python kernel's answer): an OK result needs the stiffness; its
// compliance (when not given) and indices are computed as the C++ kernels compute them.
PostureResult make_posture_result(PostureStatus status, const std::optional<Mat6>& stiffness,
                                  const std::optional<Mat6>& compliance, double singularity_measure,
                                  const std::optional<Vec6>& deflection, int newton_iterations) {
  PostureResult r;
  if (status == PostureStatus::kNearSingular)
    raise_status(
        Status::Invalid("PostureResult: NEAR_SINGULAR is a map's verdict; a kernel returns OK with its "
                        "singularity_measure"));
  r.status = status;
  if (!std::isfinite(singularity_measure))
    raise_status(Status::Invalid("PostureResult: singularity_measure is not finite"));
  r.singularity_measure = singularity_measure;
  r.newton_iterations = newton_iterations;
  if (deflection) {
    if (!deflection->allFinite()) raise_status(Status::Invalid("PostureResult: deflection is not finite"));
    r.deflection = *deflection;
  }
  if (status == PostureStatus::kOk && !stiffness)
    raise_status(Status::Invalid("PostureResult: status OK needs the stiffness (6x6, tool point, base axes, SI)"));
  if (stiffness) {
    if (!stiffness->allFinite()) raise_status(Status::Invalid("PostureResult: stiffness is not finite"));
    r.stiffness = *stiffness;
    r.indices = cartesian_indices(r.stiffness);
  }
  if (compliance) {
    if (!compliance->allFinite()) raise_status(Status::Invalid("PostureResult: compliance is not finite"));
    r.compliance = *compliance;
  } else if (stiffness) {
    const Eigen::FullPivLU<Mat6> lu(r.stiffness);
    if (status == PostureStatus::kOk && !lu.isInvertible())
      raise_status(
          Status::Invalid("PostureResult: the stiffness is singular; give the compliance, or status SINGULAR"));
    if (lu.isInvertible()) r.compliance = lu.inverse();
  }
  return r;
}

void bind_posture_kernels(py::module_& m) {
  py::enum_<PostureStatus>(m, "PostureStatus",
                           "Status of a posture; a map's status arrays hold its value (uint8). NEAR_SINGULAR is "
                           "set by maps only.")
      .value("OK", PostureStatus::kOk)
      .value("UNREACHABLE", PostureStatus::kUnreachable)
      .value("SINGULAR", PostureStatus::kSingular)
      .value("FAILED", PostureStatus::kFailed)
      .value("NEAR_SINGULAR", PostureStatus::kNearSingular);
  py::class_<PostureResult>(m, "PostureResult",
                            "The stiffness at one posture (tool point, global axes, SI units). A Python kernel "
                            "returns PostureResult(status, stiffness=K, singularity_measure=...): compliance (when "
                            "not given) and indices are computed from K.")
      .def(py::init(&make_posture_result), py::arg("status") = PostureStatus::kUnreachable,
           py::arg("stiffness") = py::none(), py::arg("compliance") = py::none(), py::arg("singularity_measure") = 0.0,
           py::arg("deflection") = py::none(), py::arg("newton_iterations") = 0)
      .def_readonly("status", &PostureResult::status)
      .def_readonly("stiffness", &PostureResult::stiffness)
      .def_readonly("compliance", &PostureResult::compliance)
      .def_readonly("indices", &PostureResult::indices)
      .def_readonly("singularity_measure", &PostureResult::singularity_measure, "in [0, 1], 0 at a singularity")
      .def_readonly("deflection", &PostureResult::deflection, "under the kernel's load (m, rad)")
      .def_readonly("newton_iterations", &PostureResult::newton_iterations,
                    "loaded mode: the equilibrium's Newton steps, every chain's summed");
  py::class_<PostureKernel, PyPostureKernel>(
      m, "PostureKernel",
      "The stiffness of a mechanism's tool point at many postures (points in m, kinematics frame). Not "
      "thread-safe: clone() one per thread, or use evaluate_postures. Subclass it in Python (call "
      "super().__init__(), define evaluate(self, point) -> PostureResult, optionally evaluate_next and "
      "description) to map your own kinematics: evaluate_postures and compute_workspace_map run a Python kernel on "
      "one thread, taking the GIL for each call (docs/python.md).")
      .def(py::init<>())
      .def(
          "evaluate",
          [](PostureKernel& k, const Vec3& point) {
            check(check_entries(point, Quantity::kLength, "point"));
            return without_gil([&] { return k.evaluate(point); });
          },
          py::arg("point"), "The stiffness at the point (m); InputError for a point not finite or out of range.")
      .def(
          "evaluate_next",
          [](PostureKernel& k, const Vec3& point) {
            check(check_entries(point, Quantity::kLength, "point"));
            return without_gil([&] { return k.evaluate_next(point); });
          },
          py::arg("point"),
          "The stiffness at a grid neighbour of the last point evaluated (a kernel may start from "
          "that point's solution); evaluate(point) unless the kernel says otherwise.")
      .def("clone", [](const PostureKernel& k) { return without_gil([&] { return k.clone(); }); })
      .def("description", [](const PostureKernel& k) { return without_gil([&] { return k.description(); }); });

  py::enum_<StiffnessMethod>(m, "StiffnessMethod")
      .value("MSA", StiffnessMethod::kMsa)
      .value("VJM", StiffnessMethod::kVjm);
  py::class_<FiveBarKernelOptions>(m, "FiveBarKernelOptions")
      .def(py::init<>())
      .def_readwrite("params", &FiveBarKernelOptions::params)
      .def_readwrite("mode", &FiveBarKernelOptions::mode)
      .def_readwrite("assembly", &FiveBarKernelOptions::assembly)
      .def_readwrite("method", &FiveBarKernelOptions::method)
      .def_readwrite("load", &FiveBarKernelOptions::load, "wrench at P (N, N m) for the deflection");
  m.def(
      "make_five_bar_kernel",
      [](const FiveBarKernelOptions& o) {
        check(validate(o));
        return make_five_bar_kernel(o);
      },
      py::arg("options") = FiveBarKernelOptions{},
      "The five-bar's sweep kernel (what `kinestat map fivebar` uses): the reference's model built once, then "
      "fixed-size algebra per posture; the same values, many times faster (five_bar_kernel.hpp).");
  m.def(
      "make_reference_five_bar_kernel",
      [](const FiveBarKernelOptions& o) {
        check(validate(o));
        return make_reference_five_bar_kernel(o);
      },
      py::arg("options") = FiveBarKernelOptions{},
      "Five-bar stiffness at P over the plane (z ignored), posture by posture through make_five_bar_structure "
      "(MSA) or five_bar_vjm_chains (VJM); singularity measure min(parallel, serial). The reference of tests.");
  py::class_<OrthoglideKernelOptions>(m, "OrthoglideKernelOptions")
      .def(py::init<>())
      .def_readwrite("model", &OrthoglideKernelOptions::model)
      .def_readwrite("architecture", &OrthoglideKernelOptions::architecture)
      .def_readwrite("wrench", &OrthoglideKernelOptions::wrench, "loaded mode: external wrench (N, N m), or None")
      .def_readwrite("displacement", &OrthoglideKernelOptions::displacement,
                     "loaded mode: prescribed tool displacement (m, rad), or None");
  m.def(
      "make_orthoglide_kernel",
      [](const OrthoglideKernelOptions& o) {
        check(validate(o));
        return make_orthoglide_kernel(o);
      },
      py::arg("options") = OrthoglideKernelOptions{},
      "The Orthoglide's sweep kernel (what `kinestat map MODEL.yaml` uses): the same VJM values as the reference, "
      "with the chains' fixed parts computed once.");
  m.def(
      "make_reference_orthoglide_kernel",
      [](const OrthoglideKernelOptions& o) {
        check(validate(o));
        return make_reference_orthoglide_kernel(o);
      },
      py::arg("options") = OrthoglideKernelOptions{},
      "Orthoglide VJM stiffness over its Cartesian workspace, posture by posture through orthoglide_chains. The "
      "reference of tests.");

  py::class_<PostureArrays>(m, "PostureResults",
                            "evaluate_postures' results as arrays of shape S = points.shape[:-1] plus the value's "
                            "own shape; NaN where the status is not OK (singularity_measure: NaN where unreachable).")
      .def_readonly("status", &PostureArrays::status, "S, uint8 PostureStatus values (0 OK)")
      .def_readonly("stiffness", &PostureArrays::stiffness, "S x 6 x 6: N/m, N/rad | N m/m, N m/rad")
      .def_readonly("compliance", &PostureArrays::compliance, "S x 6 x 6: m/N, m/(N m) | rad/N, rad/(N m)")
      .def_readonly("eigenvalues", &PostureArrays::eigenvalues, "S x 6, ascending (mixed units)")
      .def_readonly("translational_eigenvalues", &PostureArrays::translational_eigenvalues, "S x 3, N/m, ascending")
      .def_readonly("rotational_eigenvalues", &PostureArrays::rotational_eigenvalues, "S x 3, N m/rad, ascending")
      .def_readonly("condition_number", &PostureArrays::condition_number, "S")
      .def_readonly("singularity_measure", &PostureArrays::singularity_measure, "S, in [0, 1]")
      .def_readonly("deflection", &PostureArrays::deflection, "S x 6 (m, rad)");
  m.def(
      "evaluate_postures",
      [](const PostureKernel& kernel, const py::array_t<double, py::array::c_style | py::array::forcecast>& points,
         int threads) {
        if (points.ndim() < 1 || points.shape(points.ndim() - 1) != 3)
          raise_status(Status::Invalid("evaluate_postures: points must be an array of shape (..., 3) in m"));
        if (threads < 0)
          raise_status(Status::Invalid(fmt::format("threads = {}: give 0 (all cores) or a positive count", threads)));
        const std::vector<py::ssize_t> grid(points.shape(), points.shape() + points.ndim() - 1);
        std::vector<Vec3> p(static_cast<size_t>(points.size() / 3));
        for (size_t i = 0; i < p.size(); ++i) {
          p[i] = Vec3(points.data() + 3 * i);
          // check_quantity formats its message: called only for a point that fails the quick test.
          // (allFinite first: Eigen's maxCoeff may skip a NaN.)
          if (!p[i].allFinite() || p[i].cwiseAbs().maxCoeff() > quantity_range(Quantity::kLength).max_abs)
            check(check_entries(p[i], Quantity::kLength, fmt::format("points (row {})", i)));
        }
        std::vector<PostureResult> results;
        if (is_python_kernel(kernel)) threads = 1;  // it takes the GIL for every point
        without_gil([&] { evaluate_postures(kernel, p, results, threads); });
        return posture_arrays(results, grid);
      },
      py::arg("kernel"), py::arg("points"), py::arg("threads") = 0,
      "Evaluates the kernel at every point of an (..., 3) array (m) on `threads` threads (0: all cores; a Python "
      "kernel: 1), with the GIL released; returns PostureResults shaped like the grid.");
}

}  // namespace

bool is_python_kernel(const PostureKernel& kernel) {
  return dynamic_cast<const PyPostureKernel*>(&kernel) != nullptr ||
         dynamic_cast<const PythonKernelClone*>(&kernel) != nullptr;
}

void bind_mechanisms(py::module_& m) {
  bind_five_bar(m);
  bind_orthoglide_kinematics(m);
  bind_orthoglide_design(m);
  bind_orthoglide_stiffness(m);
  bind_posture_kernels(m);
}

}  // namespace kinestat::python
