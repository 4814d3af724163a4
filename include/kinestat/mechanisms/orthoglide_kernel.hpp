// Posture kernels of the Orthoglide (posture_kernel.hpp): the VJM 6x6 stiffness at the tool point
// over its Cartesian workspace, unloaded or in loaded mode.
#pragma once

#include <memory>
#include <optional>

#include "kinestat/mechanisms/orthoglide_stiffness.hpp"
#include "kinestat/mechanisms/posture_kernel.hpp"

namespace kinestat::mechanisms {

struct OrthoglideKernelOptions {
  OrthoglideStiffnessModel model;
  OrthoglideArchitecture architecture = OrthoglideArchitecture::kPUU;
  // Loaded mode (at most one): the platform under an external wrench at the tool point (N, N m),
  // or displaced by a prescribed tool displacement (m, rad), as `kinestat vjm --wrench/--load`.
  // PostureResult::deflection is the equilibrium displacement. Neither: unloaded, deflection 0.
  std::optional<Vec6> wrench;
  std::optional<Vec6> displacement;
};

// Singularity measure: sigma_min / sigma_max of the inverse Jacobian (eq. 5 of the design paper;
// velocity_transmission in orthoglide_kinematics.hpp), 0 at a serial or parallel singularity.
// Points outside the working-mode inverse kinematics are kUnreachable; a point where the stiffness
// is not defined is kSingular; a loaded equilibrium that does not exist is kFailed.

// The sweep kernel: the chains of orthoglide_chains written out with fixed-size matrices (the
// springs' compliances computed once, the parallelogram's spring from its two bars per posture),
// each chain's stiffness by eq. (10), their sum; no heap allocation. Singular when a pivot ratio of
// the Cholesky factorization of the length-scaled sum is below 1e-10 (vjm's rank tolerance).
std::unique_ptr<PostureKernel> make_orthoglide_kernel(const OrthoglideKernelOptions& options);

// Today's single-posture path: orthoglide_chains + vjm platform stiffness. The reference of tests.
std::unique_ptr<PostureKernel> make_reference_orthoglide_kernel(const OrthoglideKernelOptions& options);

}  // namespace kinestat::mechanisms
