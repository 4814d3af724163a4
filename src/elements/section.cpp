#include "kinestat/elements/section.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace kinestat {

using std::numbers::pi;

Section circle_section(double d) {
  Section s;
  s.A = pi * d * d / 4.0;
  s.Iy = s.Iz = pi * std::pow(d, 4) / 64.0;
  s.J = 2.0 * s.Iy;
  s.Asy = s.Asz = 0.9 * s.A;
  return s;
}

Section tube_section(double D, double t) {
  const double d = D - 2.0 * t;
  Section s;
  s.A = pi * (D * D - d * d) / 4.0;
  s.Iy = s.Iz = pi * (std::pow(D, 4) - std::pow(d, 4)) / 64.0;
  s.J = 2.0 * s.Iy;
  s.Asy = s.Asz = 0.5 * s.A;
  return s;
}

Section scaled_section(const Section& s, double factor) {
  const double f2 = factor * factor, f4 = f2 * f2;
  Section out = s;
  out.A *= f2;
  out.Asy *= f2;
  out.Asz *= f2;
  out.Iy *= f4;
  out.Iz *= f4;
  out.J *= f4;
  out.Ip *= f4;
  return out;
}

double polar_moment(const Section& s) { return s.Ip > 0.0 ? s.Ip : s.Iy + s.Iz; }

double rectangle_torsion_constant(double b, double h) {
  const double a = std::max(b, h), c = std::min(b, h);  // long side a, short side c
  // J = a c^3 / 3 * (1 - 192/pi^5 * c/a * sum_{n odd} tanh(n pi a / 2c) / n^5)
  double sum = 0.0;
  for (int n = 1; n < 60; n += 2) sum += std::tanh(n * pi * a / (2.0 * c)) / std::pow(n, 5);
  return a * c * c * c / 3.0 * (1.0 - 192.0 / std::pow(pi, 5) * (c / a) * sum);
}

Section rectangle_section(double b, double h) {
  Section s;
  s.A = b * h;
  s.Iy = b * h * h * h / 12.0;
  s.Iz = h * b * b * b / 12.0;
  s.J = rectangle_torsion_constant(b, h);
  s.Asy = s.Asz = 5.0 / 6.0 * s.A;
  return s;
}

Section hollow_rectangle_section(double b, double h, double t) {
  const double bi = b - 2.0 * t, hi = h - 2.0 * t;
  Section s;
  s.A = b * h - bi * hi;
  s.Iy = (b * h * h * h - bi * hi * hi * hi) / 12.0;
  s.Iz = (h * b * b * b - hi * bi * bi * bi) / 12.0;
  // Bredt: J = 4 Am^2 t / perimeter of the wall's mid-line.
  const double bm = b - t, hm = h - t;
  s.J = 4.0 * (bm * hm) * (bm * hm) * t / (2.0 * (bm + hm));
  s.Asy = 2.0 * t * b;  // walls parallel to local y carry shear along y
  s.Asz = 2.0 * t * h;
  return s;
}

}  // namespace kinestat
