// The one Cartesian stiffness type of the library (kinestat::CartesianStiffness: MSA, VJM and FEA;
// dof order ux uy uz rx ry rz, SI units), bound once and named in msa and vjm too.
#include "kinestat/core/cartesian_stiffness.hpp"
#include "python/bindings.hpp"

namespace kinestat::python {

namespace {

constexpr const char* kStiffnessUnits = "6x6, rows/cols ux uy uz rx ry rz: N/m, N/rad | N m/m, N m/rad";
constexpr const char* kComplianceUnits = "6x6, its inverse: m/N, m/(N m) | rad/N, rad/(N m)";

}  // namespace

void bind_msa_cartesian_stiffness(py::module_& m) {
  py::class_<CartesianStiffness>(m, "CartesianStiffness",
                                 "6x6 stiffness and compliance of one point (SI units) and the directions lost at "
                                 "a singular posture (unit twists as rows of (k, 6) arrays).")
      .def_readonly("point", &CartesianStiffness::point, "the point (m)")
      .def_readonly("frame", &CartesianStiffness::frame, "the axes' name")
      .def_readonly("compliance", &CartesianStiffness::compliance, kComplianceUnits)
      .def_readonly("stiffness", &CartesianStiffness::stiffness, kStiffnessUnits)
      .def_readonly("stiffness_defined", &CartesianStiffness::stiffness_defined)
      .def_readonly("compliance_defined", &CartesianStiffness::compliance_defined)
      .def_property_readonly(
          "free_directions", [](const CartesianStiffness& k) { return rows(k.free_directions); },
          "(k, 6): unit twists with zero stiffness")
      .def_property_readonly(
          "rigid_directions", [](const CartesianStiffness& k) { return rows(k.rigid_directions); },
          "(k, 6): unit twists with infinite stiffness")
      .def_readonly("note", &CartesianStiffness::note, "what else the method found, in words")
      .def_readonly("indices", &CartesianStiffness::indices, "StiffnessIndices of `stiffness` when defined")
      .def_readonly("status", &CartesianStiffness::status, "OK, or SINGULAR with the lost directions in words");
}

void bind_vjm_cartesian_stiffness(py::module_& m) {
  // The same type as msa.CartesianStiffness (bound first, in module.cpp's order).
  m.attr("CartesianStiffness") = py::type::of<CartesianStiffness>();
}

}  // namespace kinestat::python
