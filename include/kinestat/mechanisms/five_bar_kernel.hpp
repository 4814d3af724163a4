// Posture kernels of the five-bar (posture_kernel.hpp): the 6x6 stiffness at the platform point P
// over the plane, for one working mode and one assembly mode.
#pragma once

#include <memory>

#include "kinestat/mechanisms/five_bar.hpp"
#include "kinestat/mechanisms/posture_kernel.hpp"

namespace kinestat::mechanisms {

struct FiveBarKernelOptions {
  FiveBarParams params;
  WorkingMode mode;                   // the inverse kinematics' root per leg (five_bar.hpp)
  Assembly assembly = Assembly::kUp;  // points whose posture has the other assembly mode are unreachable
  StiffnessMethod method = StiffnessMethod::kMsa;
  Vec6 load = Vec6::Zero();  // wrench at P (N, N m) for PostureResult::deflection = C load
};

// kInvalidInput naming the bad value: the parameters (validate(FiveBarParams)) and the load's
// components (finite, in the range of a force and a moment, core/input_checks). The kernels below
// take any options (a bad one gives unreachable or failed points); callers check first.
Status validate(const FiveBarKernelOptions& options);

// Singularity measure: min(parallel_measure, serial_measure) of five_bar_jacobians (five_bar.hpp).
// A point whose stiffness is not defined (a free motion) is kSingular.

// The sweep kernel: the same model as the reference below, built once (element pattern, unknowns,
// spring compliances), then per posture the inverse kinematics and fixed-size dense algebra, with
// no heap allocation.
//  kMsa: the structure of make_five_bar_structure splits exactly into an in-plane and an
//    out-of-plane system of 18 unknowns each, written in the joints' deformations and three nodes
//    (an exact change of variables that keeps the 2e11 N/m joint springs off the link terms: the
//    nodal form loses ~7 digits to them, see five_bar_kernel.cpp). One Cholesky factorization of
//    each, with node "5"'s dofs last, gives the 6x6 stiffness at P as L_55 L_55^T (the static
//    condensation) and the compliance as its inverse.
//    Singular (kSingular) when a factorization fails or the condensed stiffness S at P, scaled by
//    the diagonal D of the nodal matrix there, has an eigenvalue below 2e-13. This stands for the
//    reference's test (the softest mode of the whole structure, by inverse iteration, with
//    u'Ku / u'Du < 1e-13): near the parallel singularity P's two coincident nodes move together and
//    the reference's u'Du counts both, so its ratio is half the condensed one. The two tests agree
//    except in a thin band where both ratios are near their thresholds; near the singularity the
//    reference's test holds up to ~2e-3 (the sine of the angle between the distal links).
//  kVjm: each leg's spring compliance moved to P (eq. 9), the leg's stiffness by eq. (10) with the
//    wrenches its passive joints transmit, their sum; singular when a pivot ratio of the Cholesky
//    factorization of the length-scaled sum is below 1e-10 (vjm's rank tolerance).
// A model the reference rejects (non-positive lengths: every point kUnreachable; link or joint
// properties its validation refuses: kFailed) is refused the same way.
std::unique_ptr<PostureKernel> make_five_bar_kernel(const FiveBarKernelOptions& options);

// Today's single-posture path, posture by posture: make_five_bar_structure + msa::cartesian_stiffness
// (kMsa), or five_bar_vjm_chains + vjm::platform_unloaded_stiffness (kVjm). The reference of tests.
std::unique_ptr<PostureKernel> make_reference_five_bar_kernel(const FiveBarKernelOptions& options);

}  // namespace kinestat::mechanisms
