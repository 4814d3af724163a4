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

// What a .3dd file asks of the analysis beyond the structure itself.
struct Frame3ddAnalysis {
  // The geometric stiffness flag is 1: Frame3DD's second-order analysis, which `kinestat solve`
  // honours with msa::solve_second_order (docs/structure-format.md, "Frame3DD files").
  bool geometric_stiffness = false;
  std::string geometric_stiffness_source;  // "FILE:LINE" of the flag

  // The modal data that ends the file (Frame3DD's dynamic modes), for `kinestat modes`. The extra
  // node masses and inertias are in the Structure (its nodal masses), and so are the extra element
  // masses, as Frame3DD treats them: half on each end node's translations.
  int modes = 0;              // the number of desired dynamic modes (0: no modal data)
  std::string modes_source;   // "FILE:LINE" of the count
  bool lumped = false;        // the lumped mass flag is 1 (0: consistent masses)
  std::string lumped_source;  // "FILE:LINE" of the flag
  // Read and checked, not used by kinestat's eigensolver (docs/stability-and-modes.md): Frame3DD's
  // method (1 subspace Jacobi, 2 Stodola), its convergence tolerance, its shift (1/s^2, for
  // unrestrained structures), and its matrix condensation method (0 none, 1 static, 2 Guyan,
  // 3 dynamic; the condensation data after it is not read).
  int method = 1;
  double tolerance = 0.0;
  double shift = 0.0;
  int condensation = 0;
};

// Parses and validates a .3dd file whose numbers are in `units` (force and length; time in s, so
// densities in force s^2/length^4 and gravity in length/s^2; angles in degrees; temperatures and
// the expansion coefficient in the file's own degrees). Any problem, or anything kinestat cannot
// solve as written (node radii), gives kInvalidInput "FILE:LINE: ITEM: what is
// wrong; what to do". `notes` (when given) receives "FILE:LINE: ..." remarks on what was read but is
// used by no kinestat analysis (Frame3DD's matrix condensation); `analysis` (when given) what the
// file asks of the analysis (the geometric stiffness flag, the modal data).
// True for a Frame3DD input file by its extension, .3dd in any case (the commands' choice of reader).
bool is_frame3dd_file(const std::string& path);

StatusOr<msa::Structure> read_frame3dd(const std::string& path, const FileUnits& units,
                                       std::vector<std::string>* notes = nullptr, Frame3ddAnalysis* analysis = nullptr);

// The same from text in memory; `display_name` stands for the file name in messages.
StatusOr<msa::Structure> read_frame3dd_string(const std::string& text, const std::string& display_name,
                                              const FileUnits& units, std::vector<std::string>* notes = nullptr,
                                              Frame3ddAnalysis* analysis = nullptr);

}  // namespace kinestat::io
