// kinestat.vjm: chains of the virtual joint method, their kinematics, loaded equilibrium and
// Cartesian stiffness (vjm/chain.hpp, equilibrium.hpp, stiffness.hpp, link_spring.hpp). Rigid
// transforms are 4x4 homogeneous matrices; twists and wrenches 6-vectors (m, rad; N, N m).
#include "kinestat/vjm/chain.hpp"
#include "kinestat/vjm/equilibrium.hpp"
#include "kinestat/vjm/link_spring.hpp"
#include "kinestat/vjm/platform.hpp"
#include "kinestat/vjm/stiffness.hpp"
#include "python/bindings.hpp"

namespace kinestat::python {

namespace {

using namespace vjm;

// q and theta sized for the chain (Eigen does not check sizes in a release build).
void check_coordinates(const Chain& c, const VecX& q, const VecX& theta) {
  if (q.size() != c.num_passive() || theta.size() != c.num_virtual())
    raise_status(Status::Invalid("chain '" + c.name() + "': q needs " + std::to_string(c.num_passive()) +
                                 " and theta " + std::to_string(c.num_virtual()) + " values; got " +
                                 std::to_string(q.size()) + " and " + std::to_string(theta.size())));
}

// A platform state that belongs to these chains.
void check_state(const std::vector<Chain>& chains, const PlatformState& state) {
  if (state.chains.size() != chains.size())
    raise_status(Status::Invalid("platform state of " + std::to_string(state.chains.size()) + " chains given for " +
                                 std::to_string(chains.size()) + " chains"));
  for (size_t i = 0; i < chains.size(); ++i) check_coordinates(chains[i], state.chains[i].q, state.chains[i].theta);
}

// A platform result whose status is singular raises SingularError carrying it (free directions).
CartesianStiffness checked(StatusOr<CartesianStiffness>&& r, bool raise_on_singular) {
  CartesianStiffness k = unwrap(std::move(r));
  if (raise_on_singular && k.status.code() == StatusCode::kSingular) raise_status(k.status, py::cast(k));
  return k;
}

void bind_chain(py::module_& m) {
  py::enum_<JointType>(m, "JointType")
      .value("REVOLUTE", JointType::kRevolute)
      .value("PRISMATIC", JointType::kPrismatic);
  py::enum_<VariableKind>(m, "VariableKind")
      .value("PASSIVE", VariableKind::kPassive)
      .value("VIRTUAL", VariableKind::kVirtual);
  py::class_<VariableRef>(m, "VariableRef")
      .def_readonly("kind", &VariableRef::kind)
      .def_readonly("index", &VariableRef::index)
      .def_readonly("coefficient", &VariableRef::coefficient);
  py::class_<Factor>(m, "Factor", "One factor of the chain's product (eq. 1): a constant transform or a motion.")
      .def_readonly("label", &Factor::label)
      .def_readonly("is_motion", &Factor::is_motion)
      .def_property_readonly(
          "transform", [](const Factor& f) { return to_matrix4(f.transform); }, "4x4")
      .def_readonly("type", &Factor::type)
      .def_readonly("axis", &Factor::axis)
      .def_readonly("offset", &Factor::offset)
      .def_readonly("variable", &Factor::variable);
  py::class_<Spring>(m, "Spring", "A block of K_theta (eq. 6) for virtual coordinates first .. first+size-1.")
      .def_readonly("label", &Spring::label)
      .def_readonly("first", &Spring::first)
      .def_readonly("stiffness", &Spring::stiffness);

  py::class_<Chain>(m, "Chain",
                    "A serial VJM chain (Pashkevich et al. 2009, eq. 1): base transform, actuator, rigid links, "
                    "6-dof virtual springs, passive joints, tool transform. SI units; axes in the current frame.")
      .def(py::init<std::string>(), py::arg("name") = "chain")
      .def(
          "add_transform",
          [](Chain& c, const Eigen::Matrix4d& T, std::string label) {
            c.add_transform(from_matrix4(T), std::move(label));
          },
          py::arg("T"), py::arg("label"), "A constant rigid transform (4x4).")
      .def("add_translation", &Chain::add_translation, py::arg("d"), py::arg("label"))
      .def("add_rotation", &Chain::add_rotation, py::arg("axis"), py::arg("angle"), py::arg("label"))
      .def("add_actuator", &Chain::add_actuator, py::arg("type"), py::arg("axis"), py::arg("value"),
           py::arg("stiffness"), py::arg("label"),
           "Actuated joint at `value` (m or rad) with spring `stiffness` (N/m or N m/rad; inf locks it). Returns the "
           "theta index or -1.")
      .def("add_spring", &Chain::add_spring, py::arg("K"), py::arg("label"),
           "6-dof virtual spring, 6x6 K in the current frame (ux uy uz rx ry rz). Returns the first theta index.")
      .def("add_passive", &Chain::add_passive, py::arg("type"), py::arg("axis"), py::arg("nominal"), py::arg("label"),
           "Passive joint at its nominal coordinate. Returns its q index.")
      .def("add_coupled", &Chain::add_coupled, py::arg("type"), py::arg("axis"), py::arg("index"),
           py::arg("coefficient"), py::arg("label"), "Repeats passive joint `index` scaled by `coefficient`.")
      .def("add_universal", &Chain::add_universal, py::arg("axis1"), py::arg("axis2"), py::arg("q1"), py::arg("q2"),
           py::arg("label"))
      .def("add_spherical", &Chain::add_spherical, py::arg("angles"), py::arg("label"))
      .def_property_readonly("name", &Chain::name)
      .def_property_readonly("factors", &Chain::factors, py::return_value_policy::copy)
      .def_property_readonly("springs", &Chain::springs, py::return_value_policy::copy)
      .def_property_readonly("num_passive", &Chain::num_passive)
      .def_property_readonly("num_virtual", &Chain::num_virtual)
      .def_property(
          "nominal_passive", [](const Chain& c) { return c.nominal_passive(); },
          [](Chain& c, const VecX& q) {
            check_coordinates(c, q, VecX::Zero(c.num_virtual()));
            c.set_nominal_passive(q);
          })
      .def("spring_stiffness", &Chain::spring_stiffness, "K_theta (eq. 6)")
      .def("length_scale", &Chain::length_scale)
      .def(
          "validate", [](const Chain& c) { check(c.validate()); }, "Raises InputError naming the chain and factor.")
      .def(
          "forward",
          [](const Chain& c, const VecX& q, const VecX& theta) {
            check_coordinates(c, q, theta);
            return to_matrix4(c.forward(q, theta));
          },
          py::arg("q"), py::arg("theta"), "Tool pose T(q, theta) (4x4), eq. (1).")
      .def("nominal_pose", [](const Chain& c) { return to_matrix4(c.nominal_pose()); })
      .def("__repr__", [](const Chain& c) {
        return "Chain('" + c.name() + "': " + std::to_string(c.factors().size()) + " factors, " +
               std::to_string(c.num_passive()) + " passive, " + std::to_string(c.num_virtual()) + " virtual)";
      });

  py::class_<ChainJacobians>(m, "ChainJacobians")
      .def_property_readonly("pose", [](const ChainJacobians& j) { return to_matrix4(j.pose); })
      .def_readonly("Jq", &ChainJacobians::Jq, "6 x n, columns are twists")
      .def_readonly("Jtheta", &ChainJacobians::Jtheta, "6 x m");
  m.def(
      "jacobians",
      [](const Chain& c, const VecX& q, const VecX& theta) {
        check_coordinates(c, q, theta);
        return jacobians(c, q, theta);
      },
      py::arg("chain"), py::arg("q"), py::arg("theta"), "Pose and Jacobians, eq. (5).");
  py::class_<ChainHessians>(m, "ChainHessians")
      .def_readonly("Hqq", &ChainHessians::Hqq)
      .def_readonly("Hqtheta", &ChainHessians::Hqtheta)
      .def_readonly("Hthetaq", &ChainHessians::Hthetaq)
      .def_readonly("Hthetatheta", &ChainHessians::Hthetatheta);
  m.def(
      "hessians",
      [](const Chain& c, const VecX& q, const VecX& theta, const Vec6& F) {
        check_coordinates(c, q, theta);
        return hessians(c, q, theta, F);
      },
      py::arg("chain"), py::arg("q"), py::arg("theta"), py::arg("F"),
      "d(J^T F)/d(q, theta) at fixed wrench F, eq. (19)-(20).");
  m.def(
      "pose_difference",
      [](const Eigen::Matrix4d& to, const Eigen::Matrix4d& from) {
        return pose_difference(from_matrix4(to), from_matrix4(from));
      },
      py::arg("to"), py::arg("from_"), "The twist taking pose `from_` to `to`.");
  m.def(
      "displace", [](const Eigen::Matrix4d& T, const Vec6& d) { return to_matrix4(displace(from_matrix4(T), d)); },
      py::arg("T"), py::arg("d"), "T displaced by the twist d.");
  m.def("cantilever_spring", &cantilever_spring, py::arg("material"), py::arg("section"), py::arg("length"),
        py::arg("theory") = BeamTheory::kEulerBernoulli,
        "Free-end 6x6 stiffness of a cantilever of `length` (m) in the beam's local axes.");
  m.def(
      "serial_link_spring", [](const Chain& link) { return unwrap(serial_link_spring(link)); }, py::arg("link"),
      "6x6 stiffness of the end of a chain of springs and rigid transforms, in its end frame.");
}

void bind_equilibrium(py::module_& m) {
  py::class_<EquilibriumOptions>(m, "EquilibriumOptions")
      .def(py::init<>())
      .def_readwrite("max_fixed_point_iterations", &EquilibriumOptions::max_fixed_point_iterations)
      .def_readwrite("max_newton_iterations", &EquilibriumOptions::max_newton_iterations)
      .def_readwrite("newton_fallback", &EquilibriumOptions::newton_fallback)
      .def_readwrite("tolerance", &EquilibriumOptions::tolerance)
      .def_readwrite("rank_tolerance", &EquilibriumOptions::rank_tolerance);
  py::class_<ConvergenceReport>(m, "ConvergenceReport")
      .def_readonly("converged", &ConvergenceReport::converged)
      .def_readonly("method", &ConvergenceReport::method)
      .def_readonly("fixed_point_iterations", &ConvergenceReport::fixed_point_iterations)
      .def_readonly("newton_iterations", &ConvergenceReport::newton_iterations)
      .def_readonly("kinematic_residual", &ConvergenceReport::kinematic_residual)
      .def_readonly("static_residual", &ConvergenceReport::static_residual)
      .def("summary", &ConvergenceReport::summary);
  py::class_<ChainState>(m, "ChainState", "One chain at equilibrium.")
      .def_readonly("q", &ChainState::q, "passive coordinates (m, rad)")
      .def_readonly("theta", &ChainState::theta, "virtual spring coordinates (m, rad)")
      .def_readonly("wrench", &ChainState::wrench, "wrench on the tool carried by this chain (N, N m)")
      .def_property_readonly("pose", [](const ChainState& s) { return to_matrix4(s.pose); })
      .def_readonly("report", &ChainState::report);
  py::class_<PlatformState>(m, "PlatformState", "Chains sharing one platform, at equilibrium.")
      .def_readonly("chains", &PlatformState::chains)
      .def_readonly("displacement", &PlatformState::displacement, "tool point (m, rad)")
      .def_readonly("wrench", &PlatformState::wrench, "total external wrench (N, N m)")
      .def_readonly("report", &PlatformState::report);

  m.def(
      "chain_equilibrium",
      [](const Chain& c, const Vec6& d, const EquilibriumOptions& o, const ChainState* start) {
        if (start) check_coordinates(c, start->q, start->theta);
        return unwrap(without_gil([&] { return chain_equilibrium(c, d, o, start); }));
      },
      py::arg("chain"), py::arg("displacement"), py::arg("options") = EquilibriumOptions{}, py::arg("start") = nullptr,
      "Equilibrium of one chain whose tool is displaced (m, rad), eq. (11).");
  m.def(
      "validate_platform", [](const std::vector<Chain>& chains) { check(validate_platform(chains)); },
      py::arg("chains"), "Raises InputError unless the chains are valid and their tool points coincide.");
  m.def(
      "platform_equilibrium",
      [](const std::vector<Chain>& chains, const Vec6& d, const EquilibriumOptions& o) {
        return unwrap(without_gil([&] { return platform_equilibrium(chains, d, o); }));
      },
      py::arg("chains"), py::arg("displacement"), py::arg("options") = EquilibriumOptions{},
      "Platform displaced by `displacement` (m, rad). Releases the GIL.");
  m.def(
      "platform_equilibrium_under_wrench",
      [](const std::vector<Chain>& chains, const Vec6& w, const EquilibriumOptions& o) {
        return unwrap(without_gil([&] { return platform_equilibrium_under_wrench(chains, w, o); }));
      },
      py::arg("chains"), py::arg("wrench"), py::arg("options") = EquilibriumOptions{},
      "Platform under an external wrench (N, N m about the tool point). Releases the GIL.");
  m.def(
      "load_share_reached",
      [](const std::vector<Chain>& chains, const std::optional<Vec6>& displacement, const std::optional<Vec6>& wrench,
         const EquilibriumOptions& o, double resolution) {
        if (!displacement == !wrench)
          check(Status::Invalid("load_share_reached: give exactly one of displacement= and wrench="));
        const LoadShare s = without_gil([&] {
          return load_share_reached(chains, displacement ? &*displacement : nullptr, wrench ? &*wrench : nullptr, o,
                                    resolution);
        });
        return py::make_tuple(s.found, s.failed);
      },
      py::arg("chains"), py::kw_only(), py::arg("displacement") = py::none(), py::arg("wrench") = py::none(),
      py::arg("options") = EquilibriumOptions{}, py::arg("resolution") = 1.0 / 128,
      "Where a load's equilibrium is not found: (found, failed), the largest share of the load with an equilibrium "
      "(0: none) and the smallest above it without, within `resolution`, by bisection from rest. Releases the GIL.");
}

void bind_stiffness(py::module_& m) {
  py::class_<StiffnessOptions>(m, "StiffnessOptions")
      .def(py::init<>())
      .def_readwrite("rank_tolerance", &StiffnessOptions::rank_tolerance);
  bind_vjm_cartesian_stiffness(m);
  m.def(
      "unloaded_stiffness",
      [](const Chain& c, const StiffnessOptions& o) {
        return unwrap(without_gil([&] { return unloaded_stiffness(c, o); }));
      },
      py::arg("chain"), py::arg("options") = StiffnessOptions{},
      "One chain at its nominal coordinates, eq. (9)-(10); free directions are its passive mobility.");
  m.def(
      "loaded_stiffness",
      [](const Chain& c, const ChainState& s, const StiffnessOptions& o) {
        check_coordinates(c, s.q, s.theta);
        return unwrap(without_gil([&] { return loaded_stiffness(c, s, o); }));
      },
      py::arg("chain"), py::arg("state"), py::arg("options") = StiffnessOptions{},
      "Loaded-mode stiffness dF = K^F dt at an equilibrium, eq. (19)-(21).");
  m.def("aggregate", &aggregate, py::arg("chains"), py::arg("length_scale"), py::arg("options") = StiffnessOptions{},
        "Sum of the chains' stiffness matrices (section 3.3).");
  m.def(
      "platform_unloaded_stiffness",
      [](const std::vector<Chain>& chains, const StiffnessOptions& o, bool raise_on_singular) {
        return checked(without_gil([&] { return platform_unloaded_stiffness(chains, o); }), raise_on_singular);
      },
      py::arg("chains"), py::arg("options") = StiffnessOptions{}, py::kw_only(), py::arg("raise_on_singular") = true,
      "Unloaded platform stiffness. SingularError (with .diagnosis, this CartesianStiffness) when the platform has a "
      "free direction, unless raise_on_singular=False. Releases the GIL.");
  m.def(
      "platform_loaded_stiffness",
      [](const std::vector<Chain>& chains, const PlatformState& state, const StiffnessOptions& o,
         bool raise_on_singular) {
        check_state(chains, state);
        return checked(without_gil([&] { return platform_loaded_stiffness(chains, state, o); }), raise_on_singular);
      },
      py::arg("chains"), py::arg("state"), py::arg("options") = StiffnessOptions{}, py::kw_only(),
      py::arg("raise_on_singular") = true, "Loaded platform stiffness at an equilibrium state. Releases the GIL.");
  m.def("describe_twist", &describe_twist, py::arg("twist"), "A twist in words.");
}

}  // namespace

void bind_vjm(py::module_& m) {
  bind_chain(m);
  bind_equilibrium(m);
  bind_stiffness(m);
}

}  // namespace kinestat::python
