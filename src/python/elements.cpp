// kinestat elements: materials, sections, beam and joint element matrices (elements/*.hpp).
#include "kinestat/elements/beam_element.hpp"
#include "kinestat/elements/joint_element.hpp"
#include "kinestat/elements/material.hpp"
#include "kinestat/elements/member_loads.hpp"
#include "kinestat/elements/section.hpp"
#include "python/bindings.hpp"

namespace kinestat::python {

void bind_elements(py::module_& m) {
  py::class_<Material>(m, "Material", "Linear elastic isotropic material: E and G in Pa, density in kg/m^3.")
      .def(py::init([](std::string id, double E, double G, double density) {
             return Material{std::move(id), E, G, density};
           }),
           py::arg("id") = "", py::arg("E") = 0.0, py::arg("G") = 0.0, py::arg("density") = 0.0)
      .def_static("from_E_nu", &Material::from_E_nu, py::arg("id"), py::arg("E"), py::arg("nu"),
                  "From Young's modulus E (Pa) and Poisson's ratio nu.")
      .def_readwrite("id", &Material::id)
      .def_readwrite("E", &Material::E, "Young's modulus (Pa)")
      .def_readwrite("G", &Material::G, "shear modulus (Pa)")
      .def_readwrite("density", &Material::density, "mass per volume (kg/m^3), for self-weight; 0: weightless")
      .def_property_readonly("nu", &Material::nu, "Poisson's ratio E / 2G - 1")
      .def("__repr__", [](const Material& x) {
        return "Material(id='" + x.id + "', E=" + std::to_string(x.E) + ", G=" + std::to_string(x.G) + ")";
      });

  py::class_<Section>(m, "Section",
                      "Cross-section of a prismatic beam in its local axes (x along the beam): areas in m^2, second "
                      "moments and torsion constant in m^4. Shear areas 0 = no shear deformation.")
      .def(py::init([](std::string id, double A, double Iy, double Iz, double J, double Asy, double Asz, double Ip) {
             return Section{std::move(id), A, Iy, Iz, J, Asy, Asz, Ip};
           }),
           py::arg("id") = "", py::arg("A") = 0.0, py::arg("Iy") = 0.0, py::arg("Iz") = 0.0, py::arg("J") = 0.0,
           py::arg("Asy") = 0.0, py::arg("Asz") = 0.0, py::arg("Ip") = 0.0)
      .def_readwrite("id", &Section::id)
      .def_readwrite("A", &Section::A, "area (m^2)")
      .def_readwrite("Iy", &Section::Iy, "second moment about local y (m^4)")
      .def_readwrite("Iz", &Section::Iz, "second moment about local z (m^4)")
      .def_readwrite("J", &Section::J, "Saint-Venant torsion constant (m^4)")
      .def_readwrite("Asy", &Section::Asy, "shear area along local y (m^2)")
      .def_readwrite("Asz", &Section::Asz, "shear area along local z (m^2)")
      .def_readwrite("Ip", &Section::Ip,
                     "polar second moment of the twist: rotary mass and K_G's Wagner term (m^4); 0 = Iy + Iz")
      .def("__repr__", [](const Section& s) {
        return "Section(id='" + s.id + "', A=" + std::to_string(s.A) + ", Iy=" + std::to_string(s.Iy) +
               ", Iz=" + std::to_string(s.Iz) + ", J=" + std::to_string(s.J) + ")";
      });
  m.def("circle_section", &circle_section, py::arg("diameter"), "Solid circle of diameter (m); id is empty.");
  m.def("tube_section", &tube_section, py::arg("outer_diameter"), py::arg("wall"), "Tube (m).");
  m.def("rectangle_section", &rectangle_section, py::arg("b"), py::arg("h"),
        "Solid rectangle, b along local y, h along local z (m); exact Saint-Venant J.");
  m.def("hollow_rectangle_section", &hollow_rectangle_section, py::arg("b"), py::arg("h"), py::arg("t"),
        "Hollow rectangle b x h with wall t (m); Bredt's J.");
  m.def("scaled_section", &scaled_section, py::arg("section"), py::arg("factor"),
        "Every dimension times factor: areas x factor^2, moments x factor^4.");
  m.def("rectangle_torsion_constant", &rectangle_torsion_constant, py::arg("b"), py::arg("h"));

  py::class_<ThermalLoad>(m, "ThermalLoad",
                          "A temperature change of a beam: alpha (1/K), uniform dT, differences across the section "
                          "dTy = T(+y) - T(-y) over the depth hy (m), dTz over hz (K).")
      .def(py::init([](double alpha, double hy, double hz, double dT, double dTy, double dTz) {
             return ThermalLoad{alpha, hy, hz, dT, dTy, dTz};
           }),
           py::arg("alpha") = 0.0, py::arg("hy") = 0.0, py::arg("hz") = 0.0, py::arg("dT") = 0.0, py::arg("dTy") = 0.0,
           py::arg("dTz") = 0.0)
      .def_readwrite("alpha", &ThermalLoad::alpha)
      .def_readwrite("hy", &ThermalLoad::hy)
      .def_readwrite("hz", &ThermalLoad::hz)
      .def_readwrite("dT", &ThermalLoad::dT)
      .def_readwrite("dTy", &ThermalLoad::dTy)
      .def_readwrite("dTz", &ThermalLoad::dTz);

  py::enum_<BeamTheory>(m, "BeamTheory")
      .value("EULER_BERNOULLI", BeamTheory::kEulerBernoulli)
      .value("TIMOSHENKO", BeamTheory::kTimoshenko);
  m.def("beam_local_stiffness", &beam_local_stiffness, py::arg("material"), py::arg("section"), py::arg("length"),
        py::arg("theory") = BeamTheory::kEulerBernoulli,
        "12x12 local stiffness of a beam (local dofs ux uy uz rx ry rz of node 1, then node 2).");
  m.def(
      "condense_releases",
      [](const Mat12& K, const BeamReleases& released) { return unwrap(condense_releases(K, released)); }, py::arg("K"),
      py::arg("released"),
      "Static condensation of the released local dofs (12 booleans). InputError when the element becomes free.");
  m.def("beam_transformation", &beam_transformation, py::arg("axes"), "T with u_local = T u_global (12x12).");
  m.def("joint_global_stiffness", &joint_global_stiffness, py::arg("frame"), py::arg("k"),
        py::arg("coupling") = Mat6(Mat6::Zero()),
        "12x12 [kc -kc; -kc kc] of a 6-dof joint spring k (N/m, N m/rad) in `frame`; inf components add nothing; "
        "`coupling`: the off-diagonal terms of a coupled spring in `frame` (6x6, zero diagonal).");
  m.def("joint_spring_block", &joint_spring_block, py::arg("frame"), py::arg("k"),
        py::arg("coupling") = Mat6(Mat6::Zero()), "The 6x6 kc block (global).");
}

}  // namespace kinestat::python
