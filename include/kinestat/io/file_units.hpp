// The units a file is written in, and their factors to SI: shared by the YAML structure reader
// (`units:`) and the Frame3DD reader (`--units FORCE-LENGTH`, a .3dd file states none).
#pragma once

#include <optional>
#include <string>

#include "kinestat/core/input_checks.hpp"
#include "kinestat/core/status.hpp"

namespace kinestat::io {

// Scale factors from a file's units to SI: `units: SI` (m, N, Pa), `units: mm-N-s` (mm, N, MPa) or,
// in structure files, any length and force unit `units: {length: in, force: kip}` (time in s, so
// mass in force s^2/length).
struct FileUnits {
  double length = 1.0;  // file length unit in m
  double force = 1.0;   // file force unit in N
  std::string length_name = "m", force_name = "N";
  // The file's unit of `q` (its SI factor and name, e.g. 1e6 and "MPa"); angles: the SI rad.
  UnitOfInput of(Quantity q) const;
};

// A length or force unit by name: m, mm, cm, in, ft; N, kN, lbf, kip. nullopt when unknown.
std::optional<double> length_unit(const std::string& name);
std::optional<double> force_unit(const std::string& name);

// "FORCE-LENGTH" (kip-in, N-mm, kN-m, ...), the value of an option named `option` ("--units"):
// kInvalidInput naming the option, the unknown part and the names there are.
StatusOr<FileUnits> units_from_name(const std::string& force_length, const std::string& option);

}  // namespace kinestat::io
