// Posture kernels of the five-bar (posture_kernel.hpp): the 6x6 stiffness at the platform point P
// over the plane, for one working mode and one assembly mode.
#pragma once

#include <memory>

#include "kinestat/mechanisms/five_bar.hpp"
#include "kinestat/mechanisms/posture_kernel.hpp"

namespace kinestat::mechanisms {

enum class StiffnessMethod { kMsa, kVjm };
const char* to_string(StiffnessMethod m);  // "MSA", "VJM"

struct FiveBarKernelOptions {
  FiveBarParams params;
  WorkingMode mode;                  // the inverse kinematics' root per leg (five_bar.hpp)
  Assembly assembly = Assembly::kUp; // points whose posture has the other assembly mode are unreachable
  StiffnessMethod method = StiffnessMethod::kMsa;
  Vec6 load = Vec6::Zero();          // wrench at P (N, N m) for PostureResult::deflection = C load
};

// Singularity measure: min(parallel_measure, serial_measure) of five_bar_jacobians (five_bar.hpp).
// A point whose stiffness is not defined (a free motion) is kSingular.

// Today's single-posture path, posture by posture: make_five_bar_structure + msa::cartesian_stiffness
// (kMsa), or five_bar_vjm_chains + vjm::platform_unloaded_stiffness (kVjm). The reference of tests.
std::unique_ptr<PostureKernel> make_reference_five_bar_kernel(const FiveBarKernelOptions& options);

}  // namespace kinestat::mechanisms
