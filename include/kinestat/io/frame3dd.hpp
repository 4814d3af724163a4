// Reading Frame3DD's text input format (.3dd, as in Frame3DD's examples/exA.3dd: density per
// element, gravity per load case, shear and geometric flags, plot settings) into an msa::Structure.
// A .3dd file states no units: the caller gives them (kinestat solve --units kip-in); the Structure
// is SI. What is read and what is refused: docs/structure-format.md, "Frame3DD files".
#pragma once

#include <string>
#include <vector>

#include "kinestat/core/status.hpp"
#include "kinestat/io/file_units.hpp"
#include "kinestat/msa/structure.hpp"

namespace kinestat::io {

// Parses and validates a .3dd file whose numbers are in `units` (force and length; time in s, so
// densities in force s^2/length^4 and gravity in length/s^2; angles in degrees; temperatures and
// the expansion coefficient in the file's own degrees). Any problem, or anything kinestat cannot
// solve as written (geometric stiffness, node radii), gives kInvalidInput "FILE:LINE: ITEM: what is
// wrong; what to do". `notes` (when given) receives "FILE:LINE: ..." remarks on what was read but is
// not used by a static solve (dynamic modes).
StatusOr<msa::Structure> read_frame3dd(const std::string& path, const FileUnits& units,
                                       std::vector<std::string>* notes = nullptr);

// The same from text in memory; `display_name` stands for the file name in messages.
StatusOr<msa::Structure> read_frame3dd_string(const std::string& text, const std::string& display_name,
                                              const FileUnits& units, std::vector<std::string>* notes = nullptr);

}  // namespace kinestat::io
