#include "kinestat/core/input_checks.hpp"

#include <cmath>

#include <fmt/format.h>

namespace kinestat {

const QuantityRange& quantity_range(Quantity q) {
  // max_abs: about 1e6 m for lengths and the powers of it that sections use; 1e12 N for forces.
  // min_positive: about 1e-9 m (a nanometre) and its powers.
  static const QuantityRange kRanges[] = {
      {"a length", "m", 1e6, 1e-9},
      {"an angle", "rad", 1e3, 0.0},
      {"a force", "N", 1e12, 0.0},
      {"a moment", "N m", 1e18, 0.0},
      {"a modulus", "Pa", 1e15, 1.0},
      {"an area", "m^2", 1e12, 1e-18},
      {"a second moment of area", "m^4", 1e24, 1e-36},
      {"a translational stiffness", "N/m", 1e24, 1e-12},
      {"a rotational stiffness", "N m/rad", 1e30, 1e-12},
      {"a compliance", "SI units", 1e12, 1e-40},
      {"a ratio", "", 1e12, 1e-12},
      // Osmium is 2.3e4 kg/m^3; a density of 1e6 is a unit mistake (t/mm^3 written in an SI file).
      {"a density", "kg/m^3", 1e6, 1e-6},
      {"an acceleration", "m/s^2", 1e6, 0.0},
      {"a force per length", "N/m", 1e12, 0.0},
      {"a temperature change", "K", 1e4, 0.0},
      {"a thermal expansion coefficient", "1/K", 1.0, 1e-12},
      {"a mass", "kg", 1e12, 0.0},
      {"a rotary inertia", "kg m^2", 1e24, 0.0},
  };
  return kRanges[static_cast<int>(q)];
}

Status check_quantity(double value, Quantity q, const std::string& item, const UnitOfInput& unit, Sign sign) {
  const QuantityRange& r = quantity_range(q);
  const double scale = unit.scale > 0.0 ? unit.scale : 1.0;
  const std::string u = unit.name.empty() ? r.si_unit : unit.name;
  const std::string space_unit = u.empty() ? "" : " " + u;
  const std::string shown = fmt::format("{:g}{}", value, space_unit);
  // Compared in the written unit: value * scale may overflow where the bound does not.
  const double max_abs = r.max_abs / scale, min_positive = r.min_positive / scale;
  if (!std::isfinite(value))
    return Status::Invalid(fmt::format("{} = {} is not a finite number; give a finite value", item, shown));
  if (std::abs(value) > max_abs)
    return Status::Invalid(fmt::format("{} = {} is too large for {} (|value| <= {:g}{}); check the value and its unit",
                                       item, shown, r.name, max_abs, space_unit));
  if (sign == Sign::kPositive && !(value > 0.0))
    return Status::Invalid(fmt::format("{} = {} must be positive", item, shown));
  if (sign == Sign::kNonNegative && value < 0.0)
    return Status::Invalid(fmt::format("{} = {} must not be negative", item, shown));
  if (sign == Sign::kPositive && value < min_positive)
    return Status::Invalid(fmt::format("{} = {} is too small for {} (at least {:g}{}); check the value and its unit",
                                       item, shown, r.name, min_positive, space_unit));
  return Status::Ok();
}

Status check_size(double estimate, double limit, const std::string& what, const std::string& units,
                  const std::string& advice) {
  if (estimate <= limit) return Status::Ok();  // NaN estimates are refused too
  return Status::Invalid(
      fmt::format("{}: about {:.3g} {}, above the limit of {:.3g}; {}", what, estimate, units, limit, advice));
}

std::string entry_name(const std::string& item, long i, long j, bool vector) {
  return vector ? fmt::format("{}[{}]", item, i) : fmt::format("{}[{}, {}]", item, i, j);
}

std::string at_source(const std::string& source, const std::string& message) {
  return source.empty() ? message : source + ": " + message;
}

}  // namespace kinestat
