// Natural frequencies and mode shapes of an msa::Structure: K phi = omega^2 M phi on the reduced
// dofs u = C q of the static solve (supports and rigid ties), M assembled from the beams' density
// (elements/beam_element.hpp: consistent or lumped) and the structure's nodal masses and rotary
// inertias. Documented in docs/stability-and-modes.md.
#pragma once

#include <vector>

#include "kinestat/core/status.hpp"
#include "kinestat/msa/static_analysis.hpp"
#include "kinestat/msa/structure.hpp"

namespace kinestat::msa {

struct ModalOptions {
  SolveOptions solve;         // of the factorization of K (and its singularity diagnosis)
  int count = 6;              // how many of the lowest frequencies
  bool lumped = false;        // lumped instead of consistent beam masses
  bool rotary_inertia = true; // the cross-sections' rotary inertia in the consistent mass
};

struct VibrationMode {
  double omega = 0.0;         // rad/s
  double frequency = 0.0;     // Hz, omega / (2 pi)
  std::vector<Vec6> shape;    // per node, global; mass-normalized: phi' M phi = 1 (m/sqrt(kg), rad/sqrt(kg))
  Vec3 participation = Vec3::Zero();    // Gamma_d = phi' M r_d, r_d: unit translation along global d (sqrt(kg))
  Vec3 effective_mass = Vec3::Zero();   // Gamma_d^2 (kg)
  double residual = 0.0;      // ||K q - omega^2 M q|| / ||K q|| on the reduced dofs
};

struct ModalResult {
  // kInvalidInput (bad model, a beam without density in a structure without nodal masses, a beam with
  // end releases), kSingular (K
  // singular: see `linear.singularity`), kNotConverged (the eigensolver), kInternal.
  Status status;
  Solution linear;            // the static solve (its checks and diagnosis; load cases if any)
  int num_free_dofs = 0;
  Vec3 total_mass = Vec3::Zero();  // r_d' M r_d over every node (supported ones included), kg
  std::vector<VibrationMode> modes;  // ascending frequency
};

ModalResult modal_analysis(const Structure& s, const ModalOptions& options = {});

}  // namespace kinestat::msa
