// The Cartesian stiffness results of the methods: msa::CartesianStiffness and vjm::CartesianStiffness
// (same dof order ux uy uz rx ry rz, global axes, SI units). Kept in this one file because the
// library is merging them into one core type; the Python names stay msa.CartesianStiffness and
// vjm.CartesianStiffness.
#include "kinestat/msa/static_analysis.hpp"
#include "kinestat/vjm/stiffness.hpp"
#include "python/bindings.hpp"

namespace kinestat::python {

namespace {

constexpr const char* kStiffnessUnits = "6x6, rows/cols ux uy uz rx ry rz: N/m, N/rad | N m/m, N m/rad";
constexpr const char* kComplianceUnits = "6x6, its inverse: m/N, m/(N m) | rad/N, rad/(N m)";

}  // namespace

void bind_msa_cartesian_stiffness(py::module_& m) {
  using msa::CartesianStiffness;
  py::class_<CartesianStiffness>(m, "CartesianStiffness",
                                 "6x6 stiffness and compliance of one node (global axes, SI units).")
      .def_readonly("node", &CartesianStiffness::node)
      .def_readonly("compliance", &CartesianStiffness::compliance, kComplianceUnits)
      .def_readonly("stiffness", &CartesianStiffness::stiffness, kStiffnessUnits)
      .def_readonly("stiffness_defined", &CartesianStiffness::stiffness_defined)
      .def_readonly("note", &CartesianStiffness::note, "why the stiffness is undefined")
      .def_readonly("indices", &CartesianStiffness::indices, "StiffnessIndices of `stiffness` when defined");
}

void bind_vjm_cartesian_stiffness(py::module_& m) {
  using vjm::CartesianStiffness;
  py::class_<CartesianStiffness>(m, "CartesianStiffness",
                                 "VJM 6x6 stiffness of the tool point (global axes, SI units) and the directions "
                                 "lost at a singular posture (unit twists as rows of (k, 6) arrays).")
      .def_readonly("stiffness", &CartesianStiffness::stiffness, kStiffnessUnits)
      .def_readonly("compliance", &CartesianStiffness::compliance, kComplianceUnits)
      .def_readonly("compliance_defined", &CartesianStiffness::compliance_defined)
      .def_property_readonly(
          "free_directions", [](const CartesianStiffness& k) { return rows(k.free_directions); },
          "(k, 6): unit twists with zero stiffness")
      .def_property_readonly(
          "rigid_directions", [](const CartesianStiffness& k) { return rows(k.rigid_directions); },
          "(k, 6): unit twists with infinite stiffness")
      .def_readonly("self_motions", &CartesianStiffness::self_motions,
                    "passive-joint combinations that do not move the tool")
      .def_readonly("status", &CartesianStiffness::status, "OK, or SINGULAR with the lost directions in words");
}

}  // namespace kinestat::python
