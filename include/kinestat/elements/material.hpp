// Linear elastic isotropic material. Units: Pa (N/m^2) in SI; density kg/m^3.
#pragma once

#include <string>

namespace kinestat {

struct Material {
  std::string id;
  double E = 0.0;        // Young's modulus
  double G = 0.0;        // shear modulus
  double density = 0.0;  // mass per volume, for self-weight (0: weightless)
  double nu() const { return E / (2.0 * G) - 1.0; }
  static Material from_E_nu(std::string id, double E, double nu) { return {std::move(id), E, E / (2.0 * (1.0 + nu))}; }
};

}  // namespace kinestat
