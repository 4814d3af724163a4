// Units of measurement as constants: each is the SI value of one unit, so a value written in the unit
// times the constant is SI (`25.0 * kMm` is 0.025 m) and an SI value divided by it is in the unit
// (`length / kMm` is millimetres, `angle / kDeg` is degrees). kinestat computes in SI (m, N, rad, Pa,
// kg, s); these are for the edges: options, files, reports and plots. Use these rather than a
// constant of your own.
#pragma once

#include <numbers>

namespace kinestat::units {

// Lengths (m). The inch and the foot are exact by definition (1959).
inline constexpr double kMm = 1e-3;      // millimetre
inline constexpr double kCm = 1e-2;      // centimetre
inline constexpr double kInch = 0.0254;  // inch
inline constexpr double kFoot = 0.3048;  // foot

// Angles (rad).
inline constexpr double kDeg = std::numbers::pi / 180.0;  // degree

// Forces (N). 1 lbf = 0.45359237 kg x 9.80665 m/s^2 exactly; 1 kip = 1000 lbf.
inline constexpr double kKN = 1e3;               // kilonewton
inline constexpr double kLbf = 4.4482216152605;  // pound-force
inline constexpr double kKip = 4448.2216152605;  // kip

// Stresses and moduli (Pa).
inline constexpr double kMPa = 1e6;  // megapascal (N/mm^2)

// Moments (N m).
inline constexpr double kNMm = 1e-3;  // newton millimetre

}  // namespace kinestat::units
