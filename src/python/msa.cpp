// kinestat.msa: the structure model, solve() and its Solution, the workspace for sweeps
// (msa/structure.hpp, msa/static_analysis.hpp). Lists of per-node or per-element vectors are NumPy
// arrays with one row per node or element.
#include <optional>

#include "kinestat/msa/static_analysis.hpp"
#include "kinestat/msa/structure.hpp"
#include "python/bindings.hpp"

namespace kinestat::python {

namespace {

// Lists of a mutable object's items are returned as copies: a reference into a vector that grows
// would dangle.
constexpr auto copy = py::return_value_policy::copy;

void bind_model(py::module_& m) {
  using namespace msa;
  m.attr("RIGID") = kRigid;
  py::class_<Node>(m, "Node", "A node: id and position (m).")
      .def(py::init([](std::string id, const Vec3& p) {
             return Node{std::move(id), p};
           }),
           py::arg("id"), py::arg("position"))
      .def_readwrite("id", &Node::id)
      .def_readwrite("position", &Node::position);

  py::class_<Beam>(m, "Beam",
                   "A beam between nodes node1 and node2 (indices), with a material and a section (indices). "
                   "orientation: a vector in the local x-y plane (zero: the default); releases: 12 booleans freeing "
                   "local dofs at the ends.")
      .def(py::init([](std::string id, int node1, int node2, int material, int section, const Vec3& orientation,
                       BeamTheory theory, const BeamReleases& releases) {
             return Beam{std::move(id), node1, node2, material, section, orientation, theory, releases};
           }),
           py::arg("id"), py::arg("node1"), py::arg("node2"), py::arg("material"), py::arg("section"),
           py::arg("orientation") = Vec3(Vec3::Zero()), py::arg("theory") = BeamTheory::kEulerBernoulli,
           py::arg("releases") = BeamReleases{})
      .def_readwrite("id", &Beam::id)
      .def_readwrite("node1", &Beam::node1)
      .def_readwrite("node2", &Beam::node2)
      .def_readwrite("material", &Beam::material)
      .def_readwrite("section", &Beam::section)
      .def_readwrite("orientation", &Beam::orientation)
      .def_readwrite("theory", &Beam::theory)
      .def_readwrite("releases", &Beam::releases);

  py::class_<Joint>(m, "Joint",
                    "A 6-dof spring between two coincident nodes; stiffness (kt N/m x3, kr N m/rad x3) in `frame` "
                    "(columns: local axes in global). 0 releases a component, msa.RIGID makes it an exact constraint. "
                    "`coupling`: the off-diagonal terms of a spring that couples its components in `frame` (6x6, "
                    "symmetric, zero diagonal; a link's 6x6 from FEA).")
      .def(
          py::init([](std::string id, int node1, int node2, const Mat3& frame, const Vec6& stiffness,
                      const Mat6& coupling) { return Joint{std::move(id), node1, node2, frame, stiffness, coupling}; }),
          py::arg("id"), py::arg("node1"), py::arg("node2"), py::arg("frame") = Mat3(Mat3::Identity()),
          py::arg("stiffness") = Vec6(Vec6::Zero()), py::arg("coupling") = Mat6(Mat6::Zero()))
      .def_readwrite("id", &Joint::id)
      .def_readwrite("node1", &Joint::node1)
      .def_readwrite("node2", &Joint::node2)
      .def_readwrite("frame", &Joint::frame)
      .def_readwrite("stiffness", &Joint::stiffness)
      .def_readwrite("coupling", &Joint::coupling);

  py::class_<RigidLink>(m, "RigidLink",
                        "`slave` follows `master` as a rigid body in the dofs of `mask` (6 booleans, in `frame`).")
      .def(py::init([](std::string id, int master, int slave, const DofMask& mask, const Mat3& frame) {
             return RigidLink{std::move(id), master, slave, mask, frame};
           }),
           py::arg("id"), py::arg("master"), py::arg("slave"), py::arg("mask") = kAllDofs,
           py::arg("frame") = Mat3(Mat3::Identity()))
      .def_readwrite("id", &RigidLink::id)
      .def_readwrite("master", &RigidLink::master)
      .def_readwrite("slave", &RigidLink::slave)
      .def_readwrite("mask", &RigidLink::mask)
      .def_readwrite("frame", &RigidLink::frame);

  py::class_<Support>(m, "Support", "Fixed dofs (6 booleans ux..rz) of a node, in `frame` (identity: global).")
      .def(py::init([](int node, const DofMask& fixed, const Mat3& frame) {
             return Support{node, fixed, frame};
           }),
           py::arg("node"), py::arg("fixed") = kAllDofs, py::arg("frame") = Mat3(Mat3::Identity()))
      .def_readwrite("node", &Support::node)
      .def_readwrite("fixed", &Support::fixed)
      .def_readwrite("frame", &Support::frame);

  py::class_<NodalLoad>(m, "NodalLoad", "A wrench (Fx Fy Fz in N, Mx My Mz in N m, global axes) on a node.")
      .def(py::init([](int node, const Vec6& wrench) {
             return NodalLoad{node, wrench};
           }),
           py::arg("node"), py::arg("wrench"))
      .def_readwrite("node", &NodalLoad::node)
      .def_readwrite("wrench", &NodalLoad::wrench);

  py::class_<PrescribedDisplacement>(m, "PrescribedDisplacement",
                                     "A displacement (m or rad) of a supported dof, in the support's frame.")
      .def(py::init([](int node, int dof, double value) {
             return PrescribedDisplacement{node, dof, value};
           }),
           py::arg("node"), py::arg("dof"), py::arg("value"))
      .def_readwrite("node", &PrescribedDisplacement::node)
      .def_readwrite("dof", &PrescribedDisplacement::dof)
      .def_readwrite("value", &PrescribedDisplacement::value);

  py::enum_<MemberLoadType>(m, "MemberLoadType")
      .value("UNIFORM", MemberLoadType::kUniform)
      .value("TRAPEZOIDAL", MemberLoadType::kTrapezoidal)
      .value("POINT", MemberLoadType::kPoint)
      .value("TEMPERATURE", MemberLoadType::kTemperature);

  py::class_<MemberLoad>(m, "MemberLoad",
                         "A load on a beam's span (docs/structure-format.md): uniform w1 (N/m); trapezoidal w1 at a "
                         "to w2 at b (m from the first node); point force (N) and moment (N m) at a; temperature. "
                         "Vectors in the beam's local axes, or global when global_axes.")
      .def(py::init([](int beam, MemberLoadType type, bool global_axes, const Vec3& w1, const Vec3& w2, double a,
                       double b, const Vec3& force, const Vec3& moment, const ThermalLoad& thermal) {
             return MemberLoad{.beam = beam,
                               .type = type,
                               .global_axes = global_axes,
                               .w1 = w1,
                               .w2 = w2,
                               .a = a,
                               .b = b,
                               .force = force,
                               .moment = moment,
                               .thermal = thermal};
           }),
           py::arg("beam"), py::arg("type"), py::arg("global_axes") = false, py::arg("w1") = Vec3(Vec3::Zero()),
           py::arg("w2") = Vec3(Vec3::Zero()), py::arg("a") = 0.0, py::arg("b") = 0.0,
           py::arg("force") = Vec3(Vec3::Zero()), py::arg("moment") = Vec3(Vec3::Zero()),
           py::arg("thermal") = ThermalLoad{})
      .def_readwrite("beam", &MemberLoad::beam)
      .def_readwrite("type", &MemberLoad::type)
      .def_readwrite("global_axes", &MemberLoad::global_axes)
      .def_readwrite("w1", &MemberLoad::w1)
      .def_readwrite("w2", &MemberLoad::w2)
      .def_readwrite("a", &MemberLoad::a)
      .def_readwrite("b", &MemberLoad::b)
      .def_readwrite("force", &MemberLoad::force)
      .def_readwrite("moment", &MemberLoad::moment)
      .def_readwrite("thermal", &MemberLoad::thermal);

  py::class_<LoadCase>(m, "LoadCase")
      .def(py::init([](std::string name, std::vector<NodalLoad> loads, std::vector<PrescribedDisplacement> prescribed,
                       const Vec3& gravity, std::vector<MemberLoad> member_loads) {
             return LoadCase{.name = std::move(name),
                             .loads = std::move(loads),
                             .prescribed = std::move(prescribed),
                             .gravity = gravity,
                             .member_loads = std::move(member_loads)};
           }),
           py::arg("name"), py::arg("loads") = std::vector<NodalLoad>{},
           py::arg("prescribed") = std::vector<PrescribedDisplacement>{}, py::arg("gravity") = Vec3(Vec3::Zero()),
           py::arg("member_loads") = std::vector<MemberLoad>{})
      .def_readwrite("name", &LoadCase::name)
      .def_readwrite("loads", &LoadCase::loads, copy)
      .def_readwrite("prescribed", &LoadCase::prescribed, copy)
      .def_readwrite("gravity", &LoadCase::gravity, "self-weight acceleration (m/s^2), global axes")
      .def_readwrite("member_loads", &LoadCase::member_loads, copy);

  py::enum_<GeometricStiffnessConvention>(m, "GeometricStiffnessConvention",
                                          "How K_G is formed (docs/stability-and-modes.md): KINESTAT (mean axial "
                                          "force, axial term) or FRAME3DD (first end's force, no axial term; what "
                                          "the .3dd reader sets)")
      .value("KINESTAT", GeometricStiffnessConvention::kKinestat)
      .value("FRAME3DD", GeometricStiffnessConvention::kFrame3dd);

  py::class_<Structure>(m, "Structure",
                        "The MSA model (SI units): nodes, materials, sections, beams, joints, rigid links, supports, "
                        "load cases. Each add_* returns the new item's index, used to refer to it. Build it, then "
                        "solve it (validate() checks it as a structure file is checked). The list properties are "
                        "copies.")
      .def(py::init<>())
      .def("add_node", &Structure::add_node, py::arg("id"), py::arg("position"), py::arg("source") = std::string{},
           "Adds a node; source (e.g. \"FILE:LINE\") is named by the messages about it.")
      .def("add_material", &Structure::add_material, py::arg("material"))
      .def("add_section", &Structure::add_section, py::arg("section"))
      .def("add_beam", &Structure::add_beam, py::arg("beam"))
      .def("add_joint", &Structure::add_joint, py::arg("joint"))
      .def("add_rigid_link", &Structure::add_rigid_link, py::arg("rigid_link"))
      .def("add_support", &Structure::add_support, py::arg("support"))
      .def("add_load_case", &Structure::add_load_case, py::arg("load_case"))
      .def("set_report_node", &Structure::set_report_node, py::arg("node"),
           "The node whose 6x6 Cartesian stiffness solve() reports.")
      .def("set_title", &Structure::set_title, py::arg("title"))
      .def(
          "validate", [](const Structure& s) { check(s.validate()); },
          "Raises InputError naming the item and the fix (bad index, duplicate id, zero length, ...).")
      .def_property_readonly("title", &Structure::title)
      .def_property_readonly("nodes", &Structure::nodes, copy)
      .def_property_readonly("materials", &Structure::materials, copy)
      .def_property_readonly("sections", &Structure::sections, copy)
      .def_property_readonly("beams", &Structure::beams, copy)
      .def_property_readonly("joints", &Structure::joints, copy)
      .def_property_readonly("rigid_links", &Structure::rigid_links, copy)
      .def_property_readonly("supports", &Structure::supports, copy)
      .def_property_readonly("load_cases", &Structure::load_cases, copy)
      .def_property_readonly("report_node", &Structure::report_node)
      .def_property("geometric_stiffness_convention", &Structure::geometric_stiffness_convention,
                    &Structure::set_geometric_stiffness_convention,
                    "GeometricStiffnessConvention of buckling, the second-order solve and the modal prestress")
      .def("find_node", &Structure::find_node, py::arg("id"), "Index of the node with this id, or None.")
      .def("find_material", &Structure::find_material, py::arg("id"))
      .def("find_section", &Structure::find_section, py::arg("id"))
      .def_property_readonly("num_dofs", &Structure::num_dofs)
      .def("length_scale", &Structure::length_scale)
      .def(
          "beam_axes",
          [](const Structure& s, const Beam& b) {
            const long n = static_cast<long>(s.nodes().size());
            check_index(b.node1, n, "beam_axes: node1");
            check_index(b.node2, n, "beam_axes: node2");
            return s.beam_axes(b);
          },
          py::arg("beam"), "Local axes (columns) of a beam.")
      .def("__repr__", [](const Structure& s) {
        return "Structure('" + s.title() + "': " + std::to_string(s.nodes().size()) + " nodes, " +
               std::to_string(s.beams().size()) + " beams, " + std::to_string(s.joints().size()) + " joints, " +
               std::to_string(s.load_cases().size()) + " load cases)";
      });
}

void bind_solution(py::module_& m) {
  using namespace msa;
  py::class_<SolveOptions>(m, "SolveOptions")
      .def(py::init<>())
      .def_readwrite("cholesky", &SolveOptions::cholesky)
      .def_readwrite("regularize", &SolveOptions::regularize,
                     "for a singular structure, solve K + eps D and mark the Solution as regularized")
      .def_readwrite("mechanism_ratio", &SolveOptions::mechanism_ratio,
                     "a motion with u'Ku / u'Du below this is free (default 1e-13)")
      .def_readwrite("regularization", &SolveOptions::regularization)
      .def_readwrite("max_dofs_for_global_indices", &SolveOptions::max_dofs_for_global_indices)
      .def_readwrite("progress", &SolveOptions::progress,
                     "callable(stage: str) before each stage of the solve (the factorization's included), or None");

  py::class_<SecondOrderOptions>(m, "SecondOrderOptions")
      .def(py::init<>())
      .def_readwrite("tolerance", &SecondOrderOptions::tolerance,
                     "relative change of the displacements that ends the iterations (default 1e-9)")
      .def_readwrite("max_iterations", &SecondOrderOptions::max_iterations, "most solves of K + K_G(N) per case")
      .def_readwrite("torsion_term", &SecondOrderOptions::torsion_term, "the Wagner term of K_G");

  py::class_<SecondOrderReport>(m, "SecondOrderReport", "How a second-order (P-Delta) solve went.")
      .def_readonly("tolerance", &SecondOrderReport::tolerance)
      .def_readonly("max_iterations", &SecondOrderReport::max_iterations)
      .def_readonly("iterations", &SecondOrderReport::iterations, "per load case")
      .def_readonly("relative_change", &SecondOrderReport::relative_change, "per load case: the last change")
      .def_readonly("axial_force", &SecondOrderReport::axial_force,
                    "[case][beam], N (tension positive): the converged axial forces");

  py::class_<FreeMotion>(m, "FreeMotion", "One free motion (null-space mode) of a singular structure.")
      .def_property_readonly(
          "node_motion", [](const FreeMotion& f) { return rows(f.node_motion); },
          "(nodes, 6) array: ux uy uz (scaled so the largest translation is 1) and rx ry rz (rad per unit)")
      .def_readonly("rayleigh_ratio", &FreeMotion::rayleigh_ratio, "u'Ku / u'Du: ~1e-16 for a mechanism")
      .def_readonly("description", &FreeMotion::description, "which nodes move and how, in words");

  py::class_<SingularityDiagnosis>(m, "SingularityDiagnosis",
                                   "Why a structure is singular: weak dofs of the pivot check and the free motions.")
      .def_readonly("singular", &SingularityDiagnosis::singular)
      .def_property_readonly(
          "weak_dofs",
          [](const SingularityDiagnosis& d) {
            std::vector<std::pair<int, int>> v;
            for (const auto& w : d.weak_dofs) v.emplace_back(w.node, w.dof);
            return v;
          },
          "(node, dof) pairs whose pivot failed")
      .def_readonly("modes", &SingularityDiagnosis::modes, "the free motions (FreeMotion)")
      .def_readonly("message", &SingularityDiagnosis::message, "the diagnosis in words (as the CLI prints it)")
      .def("__str__", [](const SingularityDiagnosis& d) { return d.message; });

  py::class_<LoadCaseResult>(m, "LoadCaseResult", "Results of one load case, SI units, as NumPy arrays.")
      .def_readonly("name", &LoadCaseResult::name)
      .def_property_readonly(
          "displacement", [](const LoadCaseResult& r) { return rows(r.displacement); },
          "(nodes, 6): ux uy uz (m), rx ry rz (rad), global axes")
      .def_property_readonly(
          "reaction", [](const LoadCaseResult& r) { return rows(r.reaction); },
          "(nodes, 6): forces (N) and moments (N m), global axes; zero off supports")
      .def_property_readonly(
          "beam_end_forces", [](const LoadCaseResult& r) { return rows(r.beam_end_forces); },
          "(beams, 12): N1 Vy1 Vz1 T1 My1 Mz1 N2 ... (N, N m), local axes, force on the beam")
      .def_property_readonly(
          "joint_forces", [](const LoadCaseResult& r) { return rows(r.joint_forces); },
          "(joints, 6): spring force (N) and moment (N m) on node2, joint frame")
      .def_readonly("resultant", &LoadCaseResult::resultant, "sum of loads and reactions (N, N m about the origin): ~0")
      .def_readonly("equilibrium_error", &LoadCaseResult::equilibrium_error, "|resultant| / (|loads| + |reactions|)")
      .def_readonly("free_dof_residual", &LoadCaseResult::free_dof_residual, "||C'(K u - f)|| / ||C' f||")
      .def_readonly("max_translation", &LoadCaseResult::max_translation, "m")
      .def_readonly("max_translation_node", &LoadCaseResult::max_translation_node);

  bind_msa_cartesian_stiffness(m);

  py::class_<Solution>(m, "Solution",
                       "What one solve produced. Singular (status.code == SINGULAR): see `singularity`; `cases` "
                       "is empty unless regularized.")
      .def_readonly("status", &Solution::status)
      .def_readonly("regularized", &Solution::regularized)
      .def_readonly("num_dofs", &Solution::num_dofs)
      .def_readonly("num_free_dofs", &Solution::num_free_dofs)
      .def_readonly("factorization", &Solution::factorization)
      .def_readonly("softest_mode_ratio", &Solution::softest_mode_ratio)
      .def_readonly("mechanism_ratio", &Solution::mechanism_ratio)
      .def_readonly("backend", &Solution::backend)
      .def_readonly("singularity", &Solution::singularity)
      .def_readonly("cases", &Solution::cases, "one LoadCaseResult per load case (a list of copies)")
      .def_readonly("cartesian", &Solution::cartesian, "msa.CartesianStiffness of the report node, or None")
      .def_readonly("global_indices", &Solution::global_indices, "indices of the reduced global matrix, or None")
      .def_readonly("assembly_seconds", &Solution::assembly_seconds)
      .def_readonly("solve_seconds", &Solution::solve_seconds)
      .def_readonly("second_order", &Solution::second_order,
                    "SecondOrderReport of solve_second_order, None for a linear solve")
      .def_property_readonly(
          "structure",
          [](const Solution& s) -> py::object {
            if (!s.structure) return py::none();
            py::dict d;
            d["nodes"] = s.structure->nodes;
            d["beams"] = s.structure->beams;
            d["joints"] = s.structure->joints;
            d["load_cases"] = s.structure->load_cases;
            return d;
          },
          "{'nodes', 'beams', 'joints', 'load_cases'}: the counts of the structure solve() solved, checked by the "
          "functions that read the solution with a structure; None for a hand-made solution")
      .def(
          "case",
          [](const Solution& s, const std::string& name) {
            for (const auto& c : s.cases)
              if (c.name == name) return c;
            throw py::key_error("no load case '" + name + "'");
          },
          py::arg("name"), "The load case result named `name`.");

  py::class_<Workspace>(m, "Workspace",
                        "Reused across solves of structures with the same topology (a posture sweep): the sparse "
                        "Cholesky object keeps its symbolic analysis. Not for two threads at once: one per thread.")
      .def(py::init<const solver::LinearSolverOptions&>(), py::arg("options") = solver::LinearSolverOptions{})
      .def_property_readonly("num_symbolic_analyses", &Workspace::num_symbolic_analyses);

  m.def(
      "solve",
      [](const Structure& s, Workspace* ws, const std::optional<SolveOptions>& options, bool raise_on_singular) {
        const SolveOptions o = options.value_or(SolveOptions{});
        Solution sol = without_gil([&] { return ws ? msa::solve(s, *ws, o) : msa::solve(s, o); });
        const bool singular = sol.status.code() == StatusCode::kSingular;
        if (!sol.status.ok() && !(singular && (sol.regularized || !raise_on_singular)))
          raise_status(sol.status, singular ? py::cast(sol.singularity) : py::none());
        return sol;
      },
      py::arg("structure"), py::arg("workspace") = nullptr, py::arg("options") = py::none(), py::kw_only(),
      py::arg("raise_on_singular") = true,
      "Solves every load case (one factorization) and the report node's Cartesian stiffness. Raises InputError for "
      "an invalid structure and SingularError (with .diagnosis, an msa.SingularityDiagnosis) for a singular one, "
      "unless options.regularize or raise_on_singular=False. Releases the GIL.");
  m.def(
      "solve_second_order",
      [](const Structure& s, const std::optional<SecondOrderOptions>& second,
         const std::optional<SolveOptions>& options) {
        const SecondOrderOptions so = second.value_or(SecondOrderOptions{});
        const SolveOptions o = options.value_or(SolveOptions{});
        Solution sol = without_gil([&] { return msa::solve_second_order(s, so, o); });
        if (!sol.status.ok())
          raise_status(sol.status, sol.status.code() == StatusCode::kSingular ? py::cast(sol.singularity) : py::none());
        return sol;
      },
      py::arg("structure"), py::arg("second_order") = py::none(), py::arg("options") = py::none(),
      "Second-order (P-Delta) analysis: (K + K_G(N)) u = F iterated on the beams' axial forces "
      "(docs/stability-and-modes.md); .second_order says how it went. Raises InputError (bad model, end releases), "
      "SingularError for a singular structure, NotConvergedError for loads at or above the critical load or no "
      "convergence. Releases "
      "the GIL.");
  m.def(
      "cartesian_stiffness",
      [](const Structure& s, int node, Workspace* ws, const std::optional<SolveOptions>& options) {
        const SolveOptions o = options.value_or(SolveOptions{});
        Workspace local;
        Workspace& w = ws ? *ws : local;
        return unwrap(without_gil([&] { return msa::cartesian_stiffness(s, w, node, o); }));
      },
      py::arg("structure"), py::arg("node"), py::arg("workspace") = nullptr, py::arg("options") = py::none(),
      "Compliance and stiffness of one node by static condensation, without load cases. Releases the GIL.");
  m.def(
      "full_report", [](const Structure& s, const Solution& sol) { return unwrap(full_report(s, sol)); },
      py::arg("structure"), py::arg("solution"),
      "The human-readable report the CLI prints. InputError for a solution of another structure.");
  m.def("indices_report", &indices_report, py::arg("indices"));
}

}  // namespace

void bind_msa(py::module_& m) {
  bind_model(m);
  bind_solution(m);
  bind_msa_buckling(m);
  bind_msa_modes(m);
}

}  // namespace kinestat::python
