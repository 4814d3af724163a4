// Closed-form singular loci of the five-bar (five_bar.hpp) in the plane of P, for one working mode
// and assembly mode, as polylines for drawing over a workspace map, and the bounding box of the
// region they enclose.
//
// For a fixed working mode the reachable region of one assembly mode is bounded by
//  - the workspace boundary, the serial (type-1) singularity: leg i stretched or folded, A_iB_i and
//    B_iP aligned, i.e. |A_iP| = r1 + r2 or |A_iP| = |r1 - r2| (circles about A_i);
//  - the parallel (type-2) singularity, B1P and PB2 aligned: with P between B1 and B2, i.e.
//    |B1B2| = 2 r2 and P the midpoint of B1B2 (crossing it swaps the assembly mode); or with B1 = B2
//    at a point C where the proximal links' circles meet (r3 <= r1), P anywhere on the circle of
//    radius r2 about C (the paper's r1 = r3: C = O, theta1 = 0, theta2 = 180 deg).
#pragma once

#include <vector>

#include "kinestat/mechanisms/five_bar.hpp"
#include "kinestat/mechanisms/workspace_map.hpp"

namespace kinestat::mechanisms {

// Two curves, points (m) with z = 0, each sampled with `samples` points per turn of its parameter (an
// angle) and broken where it leaves the working/assembly mode:
//  [0] "workspace boundary": the parts of the circles |A_iP| = r1 + r2 and |A_iP| = |r1 - r2| where
//      the other leg reaches P and the posture of the working mode has the chosen assembly mode;
//  [1] "parallel singularity": the points P = (B1 + B2) / 2 with |B1B2| = 2 r2, and the points P at
//      distance r2 from C = B1 = B2, whose posture has the chosen working mode.
// Both empty for invalid parameters.
std::vector<MapCurve> five_bar_singular_loci(const FiveBarParams& p, WorkingMode mode, Assembly assembly,
                                             int samples = 4096);
// kInvalidInput unless 8 <= samples <= kMaxLociSamples: a million points per turn draw any map far
// below a pixel; more only cost time and memory (five_bar_singular_loci returns nothing for them
// without a word: callers check first).
inline constexpr int kMaxLociSamples = 1'000'000;
Status check_loci_samples(int samples);

// Bounding box (m) of the region of the working/assembly mode: that of its loci, which bound it.
// kInvalidInput when the mode reaches nothing.
struct Box2 {
  Vec2 min, max;
};
StatusOr<Box2> five_bar_workspace_box(const FiveBarParams& p, WorkingMode mode, Assembly assembly);

}  // namespace kinestat::mechanisms
