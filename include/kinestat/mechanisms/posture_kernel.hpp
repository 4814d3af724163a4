// Posture kernels: the stiffness of a mechanism's tool point at many postures (workspace maps,
// design sweeps). Everything that does not change between postures (element pattern, dof map,
// factorization workspace, buffers) is built once when the kernel is made; evaluate() costs the
// inverse kinematics, the assembly of the changed values, one small factorization and the solves
// for the 6x6, and the indices of the 6x6. A kernel is not thread-safe: clone() one per thread.
//
// Points are in the mechanism's kinematics frame, SI (m). The five-bar is planar: z is ignored.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "kinestat/core/cartesian_stiffness.hpp"
#include "kinestat/core/stiffness_indices.hpp"
#include "kinestat/core/types.hpp"

namespace kinestat::mechanisms {

// The one status of a posture, for kernels, maps and design sweeps.
enum class PostureStatus : std::uint8_t {
  kOk = 0,           // stiffness, compliance and indices computed
  kUnreachable = 1,  // outside the workspace of the chosen working/assembly mode: no values
  kSingular = 2,     // reachable, but the stiffness is not defined there (a free motion): no values
  kFailed = 3,       // reachable, no answer (e.g. no loaded equilibrium: the load buckles the robot)
  // Set by maps only (a kernel returns kOk there): values, and a singularity measure below
  // MapOptions::near_singular_threshold.
  kNearSingular = 4,
};
inline constexpr int kNumPostureStatuses = 5;
const char* to_string(PostureStatus s);  // "ok", "unreachable", "singular", "failed", "near-singular"
inline bool has_values(PostureStatus s) { return s == PostureStatus::kOk || s == PostureStatus::kNearSingular; }

// How a kernel computes the stiffness (the five-bar's and the robot files' kernels offer both).
enum class StiffnessMethod { kMsa, kVjm };
const char* to_string(StiffnessMethod m);  // "MSA", "VJM"

// The tool point's stiffness and compliance (global axes, SI: CartesianMatrices, the fixed-size part
// of CartesianStiffness: a sweep keeps one per point), set when kOk, and what a posture adds.
struct PostureResult : CartesianMatrices {
  PostureStatus status = PostureStatus::kUnreachable;
  CartesianIndices indices;  // of `stiffness` when kOk (fixed size: no eigenvectors)
  // Distance to a singularity, dimensionless in [0, 1], 0 at a singularity; each kernel documents
  // its measure (the five-bar: the smaller of its parallel and serial measures). Set whenever the
  // point is reachable, also when singular.
  double singularity_measure = 0.0;
  Vec6 deflection = Vec6::Zero();  // tool-point displacement under the kernel's load (m, rad); 0 without
  // Loaded mode: the Newton steps its equilibrium took (every chain's, summed, a discarded warm
  // start's included), also when it failed; 0 for a kernel without an iteration or an unreachable point.
  int newton_iterations = 0;
};

// Sets the stiffness K, its compliance C and K's indices (the status is the caller's).
void set_stiffness(PostureResult& r, const Mat6& K, const Mat6& C);

class PostureKernel {
 public:
  virtual ~PostureKernel() = default;
  // The posture reached at `point` (m) and its stiffness.
  virtual PostureResult evaluate(const Vec3& point) = 0;
  // The same posture, for a sweep whose previous point, the last one this kernel evaluated, is a grid
  // neighbour of `point`: a kernel that iterates (loaded mode) may start from that point's solution,
  // and gives evaluate(point)'s answer to its convergence tolerance. Others: evaluate(point).
  virtual PostureResult evaluate_next(const Vec3& point) { return evaluate(point); }
  // An independent copy for another thread (shares only immutable model data).
  virtual std::unique_ptr<PostureKernel> clone() const = 0;
  // "five-bar ++ up (MSA)", "Orthoglide 3-PUU (VJM, loaded)", ...: for titles and reports.
  virtual std::string description() const = 0;
};

// How evaluate_postures may visit the points: kIndependent, each by evaluate(); kPath, the caller
// promises that consecutive points are grid neighbours (a serpentine path, workspace_map.cpp), and
// each chunk of kPathChunk consecutive points is evaluated in order on one clone, its first point by
// evaluate() and the others by evaluate_next(). The chunks are fixed, so the results do not depend
// on the threads, bit for bit, either way.
enum class PointOrder : std::uint8_t { kIndependent, kPath };
inline constexpr std::size_t kPathChunk = 256;

// Evaluates `kernel` at every point, on `threads` threads (0: all cores; TBB), one clone of the
// kernel per thread; results[i] belongs to points[i]. `progress(done, total)` (may be empty) is
// called from one thread at a time, about every 0.1 s, and once at the end.
void evaluate_postures(const PostureKernel& kernel, const std::vector<Vec3>& points,
                       std::vector<PostureResult>& results, int threads = 0,
                       const std::function<void(std::size_t done, std::size_t total)>& progress = {},
                       PointOrder order = PointOrder::kIndependent);

// The same, each result handed to visit(i, result) (i: its point's index) on the thread that computed
// it, as soon as it is computed, and not kept: concurrent calls have distinct i. A map digests its
// results there, in parallel, and needs no buffer of them.
void evaluate_postures(const PostureKernel& kernel, const std::vector<Vec3>& points,
                       const std::function<void(std::size_t i, const PostureResult& result)>& visit, int threads,
                       const std::function<void(std::size_t done, std::size_t total)>& progress, PointOrder order);

}  // namespace kinestat::mechanisms
