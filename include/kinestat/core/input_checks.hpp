// The range every number read from a file or an option must lie in, checked after its conversion to
// SI (docs/reliability.md). The bounds lie far beyond any robot or frame, and close enough that the
// sums and products the methods form (a length to the fourth power, a stiffness times a length
// squared, the sum of many loads) stay finite and away from underflow: a value outside them is a typo
// or a unit mistake, never a model.
#pragma once

#include <cmath>
#include <string>

#include "kinestat/core/status.hpp"
#include "kinestat/core/types.hpp"

namespace kinestat {

enum class Quantity {
  kLength,                  // m: coordinates, dimensions, displacements
  kAngle,                   // rad
  kForce,                   // N
  kMoment,                  // N m
  kModulus,                 // Pa: E, G
  kArea,                    // m^2
  kInertia,                 // m^4: second moments, torsion constant
  kTranslationalStiffness,  // N/m
  kRotationalStiffness,     // N m/rad
  kCompliance,              // m/N, 1/N, rad/(N m): any compliance term
  kRatio,                   // dimensionless: coefficients, factors, Poisson's ratio
  kDensity,                 // kg/m^3
  kAcceleration,            // m/s^2: gravity
  kForcePerLength,          // N/m: distributed loads on beams
  kTemperature,             // K: temperature changes
  kThermalExpansion,        // 1/K
  kMass,                    // kg: nodal masses
  kMassInertia,             // kg m^2: nodal rotary inertias
};

struct QuantityRange {
  const char* name;     // "a length"
  const char* si_unit;  // "m"
  double max_abs;       // |value| <= max_abs (SI)
  double min_positive;  // a value that must be positive is >= min_positive (SI)
};
const QuantityRange& quantity_range(Quantity q);

enum class Sign { kAny, kPositive, kNonNegative };

// How a value was written: the unit the user wrote it in ("mm") and that unit in SI (1e-3).
struct UnitOfInput {
  double scale = 1.0;
  std::string name;  // empty: the SI unit of the quantity
};

// kInvalidInput "ITEM = VALUE UNIT is ..." when `value`, written in `unit` (SI by default), is not
// finite, lies outside the quantity's range once converted to SI (value * unit.scale), or has the wrong
// sign. The value and the bounds are printed in `unit`: what the user wrote.
Status check_quantity(double value, Quantity q, const std::string& item, const UnitOfInput& unit = {},
                      Sign sign = Sign::kAny);

// kInvalidInput "ITEM: ..." unless every component of the direction is finite and one is non-zero.
// Directions are normalized with Eigen's stableNormalized(): components near 1e300 do not overflow.
template <class V>
Status check_direction(const V& v, const std::string& item) {
  if (!v.allFinite() || v.cwiseAbs().maxCoeff() == 0.0)
    return Status::Invalid(item + ": the direction must be finite and non-zero, e.g. 0,0,1");
  return Status::Ok();
}

// "ITEM[i]" for a vector (one column), "ITEM[i, j]" for a matrix: the entry named by the checks below.
std::string entry_name(const std::string& item, long i, long j, bool vector);

// check_quantity on every entry of the vector or matrix `m`, in row order: the first bad one's status.
template <class M>
Status check_entries(const M& m, Quantity q, const std::string& item, Sign sign = Sign::kAny) {
  for (long i = 0; i < static_cast<long>(m.rows()); ++i)
    for (long j = 0; j < static_cast<long>(m.cols()); ++j)
      if (!check_quantity(m(i, j), q, item, {}, sign).ok())  // named only when it fails
        return check_quantity(m(i, j), q, entry_name(item, i, j, m.cols() == 1), {}, sign);
  return Status::Ok();
}

// kInvalidInput "ITEM[i, j] = VALUE is not a finite number; ..." for the first non-finite entry of a
// vector or matrix whose entries have no one unit or range (a matrix given to stiffness_indices).
template <class M>
Status check_finite(const M& m, const std::string& item) {
  for (long i = 0; i < static_cast<long>(m.rows()); ++i)
    for (long j = 0; j < static_cast<long>(m.cols()); ++j)
      if (!std::isfinite(m(i, j)))
        return Status::Invalid(entry_name(item, i, j, m.cols() == 1) + " = " + std::to_string(m(i, j)) +
                               " is not a finite number; give finite values");
  return Status::Ok();
}

// Size limits: every count that sets an allocation or a run time (mesh elements, grid points, chain
// coordinates) is estimated before anything is allocated. kInvalidInput "WHAT: about ESTIMATE UNITS,
// above the limit of LIMIT; ADVICE" when estimate > limit (ADVICE names the option that raises it).
Status check_size(double estimate, double limit, const std::string& what, const std::string& units,
                  const std::string& advice);

// "SOURCE: message" when the item's source ("file:line") is known, else the message.
std::string at_source(const std::string& source, const std::string& message);

}  // namespace kinestat
