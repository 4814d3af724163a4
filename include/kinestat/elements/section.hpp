// Cross-section properties of a prismatic beam, in the beam's local axes (x along the beam).
// Units: m^2 for areas, m^4 for second moments and the torsion constant.
#pragma once

#include <string>

namespace kinestat {

struct Section {
  std::string id;
  double A = 0.0;    // area
  double Iy = 0.0;   // second moment about local y (bending in the local x-z plane)
  double Iz = 0.0;   // second moment about local z (bending in the local x-y plane)
  double J = 0.0;    // Saint-Venant torsion constant
  double Asy = 0.0;  // shear area along local y (Timoshenko); 0 = no shear deformation
  double Asz = 0.0;  // shear area along local z
  // Polar second moment of the twist: the rotary inertia rho Ip L of the beam mass and the Wagner
  // term N Ip/(A L) of the geometric stiffness. 0 (the default): Iy + Iz, the centroidal polar moment
  // (physical for any section). The Frame3DD reader sets J, which is what Frame3DD's element takes there.
  double Ip = 0.0;
};

// The polar second moment of the twist: Section::Ip, or Iy + Iz when it is 0.
double polar_moment(const Section& s);

// Standard shapes. Shear areas use the usual shear coefficients: 9/10 for a solid circle,
// 1/2 for a thin tube, 5/6 for a rectangle, the webs for a hollow rectangle.
Section circle_section(double diameter);
Section tube_section(double outer_diameter, double wall);
// Rectangle of width b (along local y) and height h (along local z). J from the exact
// Saint-Venant series (Timoshenko & Goodier), not the thin-strip approximation.
Section rectangle_section(double b, double h);
// Hollow rectangle, outer b x h, wall t (constant). J from Bredt's thin-wall formula.
Section hollow_rectangle_section(double b, double h, double t);

// The section with every dimension multiplied by `factor` (> 0): areas times factor^2, second
// moments and J times factor^4 (a tube D x t becomes the tube factor D x factor t).
Section scaled_section(const Section& s, double factor);

// Saint-Venant torsion constant of a solid b x h rectangle.
double rectangle_torsion_constant(double b, double h);

}  // namespace kinestat
