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

// kInvalidInput naming the bad value: the model (validate_stiffness_model), a wrench and a
// displacement given together (the loaded mode takes one), their components (finite, in range,
// core/input_checks). The kernels below take any options; callers check first.
Status validate(const OrthoglideKernelOptions& options);

// Singularity measure: sigma_min / sigma_max of the inverse Jacobian (eq. 5 of the design paper;
// velocity_transmission in orthoglide_kinematics.hpp), 0 at a serial or parallel singularity.
// Points outside the working-mode inverse kinematics are kUnreachable; a point where the stiffness
// is not defined is kSingular; a loaded equilibrium that does not exist is kFailed.

// The sweep kernel, the same model as the reference below with no heap allocation per posture.
//  Unloaded: the chains of orthoglide_chains written out with fixed-size matrices (the springs'
//    compliances computed once, the parallelogram's spring from its two bars per posture), each
//    chain's stiffness by eq. (10) with the wrenches its passive joints transmit in closed form,
//    their sum. Singular when a pivot ratio of the Cholesky factorization of the length-scaled sum
//    is below 1e-10 (vjm's rank tolerance).
//  Loaded: the same chains, factor by factor, in fixed-capacity storage; each chain's equilibrium
//    (eq. 11) by Newton-Raphson from the unloaded state, the loaded stiffness (eq. 21), and under a
//    wrench the platform's Newton iteration of vjm::platform_equilibrium_under_wrench; the tests
//    of vjm (1e-12 residuals, 1e-10 rank tolerance). Where the reference's iterations stall (next to
//    the flat singularity) this one may converge (see the tests). evaluate_next() (a sweep's next
//    grid point) starts from the previous posture's equilibrium, falling back to the start from
//    rest where that does not converge or fails the branch test (docs/maps.md, "Speed"); the answer
//    equals evaluate()'s to ~1e-11. PostureResult::newton_iterations counts the chain steps.
std::unique_ptr<PostureKernel> make_orthoglide_kernel(const OrthoglideKernelOptions& options);

// Today's single-posture path: orthoglide_chains + vjm platform stiffness. The reference of tests.
std::unique_ptr<PostureKernel> make_reference_orthoglide_kernel(const OrthoglideKernelOptions& options);

}  // namespace kinestat::mechanisms
