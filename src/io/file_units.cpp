#include "kinestat/io/file_units.hpp"

#include <fmt/format.h>

#include <utility>

#include "kinestat/core/units.hpp"

namespace kinestat::io {

UnitOfInput FileUnits::of(Quantity q) const {
  if (length == 1.0 && force == 1.0) return {};  // SI: the quantity's own unit
  const double area = length * length;
  const std::string& L = length_name;
  const std::string& F = force_name;
  const bool n_mm = L == "mm" && F == "N";  // mm-N-s keeps its customary names (MPa, t)
  switch (q) {
    case Quantity::kLength:
      return {length, L};
    case Quantity::kForce:
      return {force, F};
    case Quantity::kMoment:
      return {force * length, F + " " + L};
    case Quantity::kModulus:
      return {force / area, n_mm ? "MPa" : F + "/" + L + "^2"};
    case Quantity::kArea:
      return {area, L + "^2"};
    case Quantity::kInertia:
      return {area * area, L + "^4"};
    case Quantity::kTranslationalStiffness:
      return {force / length, F + "/" + L};
    case Quantity::kRotationalStiffness:
      return {force * length, F + " " + L + "/rad"};
    // Mass is force / acceleration: N s^2/mm = 1000 kg = 1 t, so a density is in t/mm^3.
    case Quantity::kDensity:
      return {force / (area * area), n_mm ? "t/mm^3" : F + " s^2/" + L + "^4"};
    case Quantity::kAcceleration:
      return {length, L + "/s^2"};
    case Quantity::kForcePerLength:
      return {force / length, F + "/" + L};
    case Quantity::kMass:
      return {force / length, n_mm ? "t" : F + " s^2/" + L};
    case Quantity::kMassInertia:
      return {force * length, n_mm ? "t mm^2" : F + " s^2 " + L};
    default:
      return {};
  }
}

std::optional<double> length_unit(const std::string& name) {
  static const std::pair<const char*, double> kUnits[] = {
      {"m", 1.0}, {"mm", units::kMm}, {"cm", units::kCm}, {"in", units::kInch}, {"ft", units::kFoot}};
  for (const auto& [n, v] : kUnits)
    if (name == n) return v;
  return std::nullopt;
}

std::optional<double> force_unit(const std::string& name) {
  static const std::pair<const char*, double> kUnits[] = {
      {"N", 1.0}, {"kN", units::kKN}, {"lbf", units::kLbf}, {"kip", units::kKip}};
  for (const auto& [n, v] : kUnits)
    if (name == n) return v;
  return std::nullopt;
}

StatusOr<FileUnits> units_from_name(const std::string& force_length, const std::string& option) {
  const std::size_t dash = force_length.find('-');
  const std::string f = force_length.substr(0, dash);
  const std::string l = dash == std::string::npos ? "" : force_length.substr(dash + 1);
  const std::optional<double> fs = force_unit(f), ls = length_unit(l);
  if (dash == std::string::npos || !fs || !ls)
    return Status::Invalid(fmt::format(
        "{} {}: expected FORCE-LENGTH with a force unit N, kN, lbf or kip and a length unit m, mm, cm, in or ft, "
        "e.g. kip-in or N-mm",
        option, force_length));
  return FileUnits{*ls, *fs, l, f};
}

}  // namespace kinestat::io
