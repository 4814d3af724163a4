// Design sweep of the five-bar (five_bar.hpp): a workspace map (workspace_map.hpp) of one fixed
// region of the plane for every design (r1, r2) of a grid, reduced per design to the share of the
// region it serves. The maps "feed the optimum design of the robot" (Goncalves et al., paper 001,
// section 3): here the criterion is the usable, stiff share of a task region.
#pragma once

#include <array>
#include <cstddef>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "kinestat/core/status.hpp"
#include "kinestat/mechanisms/five_bar_kernel.hpp"
#include "kinestat/mechanisms/workspace_map.hpp"

namespace kinestat::mechanisms {

// Designs x region points above this are refused before anything runs, with the estimated time:
// 2e8 postures take about 7 minutes on two cores (benchmarks/README.md, "Design sweep").
inline constexpr double kDefaultMaxDesignPostures = 2e8;

struct FiveBarDesignSweepOptions {
  // Everything but r1 and r2 (r3, links, joints), the working and assembly mode, the method.
  FiveBarKernelOptions base;
  MapRange r1, r2;  // m, positive; lo == hi: that one value
  int steps = 10;   // designs per swept length (a range of one value has one design)
  MapGrid region;   // the postures of every design (make_map_grid), the plane of P
  double near_singular_threshold = MapOptions{}.near_singular_threshold;
  std::optional<double> min_stiffness;              // N/m, on k_t_min (the weakest direction, workspace_map.hpp)
  int threads = 0;                                  // 0: all cores
  double max_postures = kDefaultMaxDesignPostures;  // designs x region points; refused above
  // The kernel of one design; empty: make_five_bar_kernel (the sweep kernel).
  std::function<std::unique_ptr<PostureKernel>(const FiveBarKernelOptions&)> make_kernel;
  // progress(done, total) in postures over the whole sweep, from one thread at a time.
  std::function<void(std::size_t done, std::size_t total)> progress;
};

// One design's region points, nested: reachable (not kUnreachable) >= singularity-free (kOk: values,
// singularity measure >= the threshold) >= stiff (singularity-free with k_t_min >= min_stiffness;
// equal to singularity-free without a threshold).
struct FiveBarDesignResult {
  double r1 = 0.0, r2 = 0.0;  // m
  std::size_t reachable = 0, singularity_free = 0, stiff = 0;
  // The smallest k_t_min over the singularity-free points (N/m): the design's weakest point in the
  // region, which breaks ties of the share. NaN without singularity-free points.
  double k_t_min_worst = std::numeric_limits<double>::quiet_NaN();
};

// The order of the choice: the larger stiff count, then the larger k_t_min_worst (none ranks below
// any value). A strict weak order, for sorting.
bool better_design(const FiveBarDesignResult& a, const FiveBarDesignResult& b);

// The three counts as shares of the region, by the names files give them.
struct DesignShareInfo {
  const char* name;
  std::size_t FiveBarDesignResult::*count;
  const char* meaning;
};
inline constexpr std::array<DesignShareInfo, 3> kDesignShares = {{
    {"reachable_share", &FiveBarDesignResult::reachable, "share of the region the design reaches in its mode"},
    {"singularity_free_share", &FiveBarDesignResult::singularity_free,
     "share of the region reached with stiffness values and singularity measure >= the near-singular threshold"},
    {"share", &FiveBarDesignResult::stiff,
     "share of the region reached singularity-free with k_t_min >= min_stiffness (the design criterion)"},
}};

struct FiveBarDesignSweep {
  MapGrid designs;  // x: r1, y: r2 (m), one z; design i + nx j
  MapGrid region;
  std::string description;  // the first design's kernel: method, working and assembly mode
  double near_singular_threshold = 0.0;
  std::optional<double> min_stiffness;       // N/m
  std::vector<FiveBarDesignResult> results;  // in design grid order (r1 fastest)
  // The best design by better_design; of equal ones the first in grid order.
  std::size_t best = 0;
  // Shares of the region's points, in [0, 1].
  double share(std::size_t count) const {
    return static_cast<double>(count) / static_cast<double>(region.num_points());
  }
};

// kInvalidInput naming the range ("r1", "r2"), the step count or the region when they are not usable.
StatusOr<FiveBarDesignSweep> sweep_five_bar_designs(const FiveBarDesignSweepOptions& options);

}  // namespace kinestat::mechanisms
