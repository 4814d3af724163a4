// Design sweep of any robot (robot_model.hpp): for every design of a grid of named parameters, the
// workspace map (workspace_map.hpp, make_robot_kernel) of one fixed region, reduced to its stiff and
// reachable measures; the best design is the one with the largest stiff measure. The models are
// built by a caller's factory (the CLI re-reads the robot file with the parameters replaced,
// io::read_robot_model), so this layer knows nothing of files. Under MPI (solver::start_parallel
// called, more than one rank) the designs are split round-robin across the ranks and the results
// gathered on rank 0 (docs/maps.md, "Design sweep of a robot file").
#pragma once

#include <cstddef>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "kinestat/core/status.hpp"
#include "kinestat/mechanisms/robot_kernel.hpp"
#include "kinestat/mechanisms/robot_model.hpp"
#include "kinestat/mechanisms/workspace_map.hpp"

namespace kinestat::mechanisms {

// One swept parameter: its name and range in the units its model description uses (a robot file's
// units: mm for lengths of an mm-N-s file). lo == hi: that one value.
struct DesignParameter {
  std::string name;
  double lo = 0.0, hi = 0.0;
};

// The model of one design: the parameters' names and values in the order of
// RobotDesignSweepOptions::parameters. A failure (a drawing that does not close, a singular home
// posture) marks that design failed and the sweep goes on.
using RobotDesignFactory = std::function<StatusOr<RobotModel>(const std::vector<std::pair<std::string, double>>&)>;

// Designs x region points above this are refused before anything runs, with the estimated time:
// 1.5e7 postures take about 8 minutes on two cores (the five-bar's limit is as long).
inline constexpr double kDefaultMaxRobotDesignPostures = 1.5e7;
// The generic robot kernel's rate per thread used for that estimate and for a robot file's map
// (kinestat map), rounded down from the Delta's sweep over its `workspace:` box at 25 mm (`kinestat
// design models/robots/delta.yaml --param arm=250:350 --param forearm=700:900 --steps 3 --step 25
// --min-stiffness 2 --threads 1`, 2026-11-29, the other core busy): 1.8e4 postures/s, 1.0e4 under
// `--wrench 0,0,-50,0,0,0` (the unreachable points, walked to from home until the walk fails, cost
// the most).
inline constexpr double kRobotKernelPosturesPerSecond = 1.5e4;
inline constexpr double kRobotKernelLoadedPosturesPerSecond = 8e3;

struct RobotDesignSweepOptions {
  std::vector<DesignParameter> parameters;  // 1 or more, names distinct
  int steps = 3;                            // designs per swept parameter, 2 to 1000
  MapGrid region;                           // the postures of every design (make_map_grid), m
  // Everything of the kernel but the model: the task values of the coordinates not mapped (an
  // orientation; empty: each design's home), the map axes, a load. The model is the factory's.
  RobotKernelOptions kernel;
  double near_singular_threshold = MapOptions{}.near_singular_threshold;
  double min_stiffness = 0.0;  // N/m, on k_t_min: the stiff measure counts points at or above it
  int threads = 0;             // 0: all cores
  double max_postures = kDefaultMaxRobotDesignPostures;  // designs x region points; refused above
  // Split the designs across the MPI ranks when solver::start_parallel has been called (off: every
  // rank computes every design).
  bool distribute = true;
  // progress(done, total) in postures of this rank's designs, from one thread at a time.
  std::function<void(std::size_t done, std::size_t total)> progress;
};

// One design: its parameter values, whether its model and map were built, and its measures.
struct RobotDesignResult {
  std::vector<double> values;      // per parameter, in its units
  Status status;                   // Ok, or why the design has no map (the factory's or the map's message)
  double reachable_measure = 0.0;  // m^2 or m^3 (WorkspaceMap::reachable_measure)
  double stiff_measure = 0.0;      // m^2 or m^3: points with k_t_min >= min_stiffness (WorkspaceMap::stiff_measure)
  std::size_t reachable_points = 0, stiff_points = 0;
  // The smallest k_t_min over the points with values (N/m); NaN without any.
  double k_t_min_worst = std::numeric_limits<double>::quiet_NaN();
};

struct RobotDesignSweep {
  std::vector<DesignParameter> parameters;
  std::vector<int> dimensions;  // designs per parameter (1 for a single value)
  MapGrid region;
  std::string description;  // the first built design's kernel
  double near_singular_threshold = 0.0;
  double min_stiffness = 0.0;  // N/m
  // In design grid order, the first parameter fastest. Under MPI complete on rank 0 only.
  std::vector<RobotDesignResult> results;
  std::size_t best = 0;  // the largest stiff measure of the built designs; of equal ones the first
  int ranks = 1;         // MPI ranks the designs were split across
  bool complete = true;  // false on MPI ranks other than 0 (their results hold their designs only)
  // The design measures' unit: m^3 for a box, m^2 for a plane.
  bool volume() const { return region.num_varying_axes() == 3; }
};

// Design values of a parameter: lo, lo + (hi - lo)/(steps - 1), ..., hi (lo alone when lo == hi).
std::vector<double> design_values(const DesignParameter& p, int steps);

// kInvalidInput naming the parameter, the steps or the region when they are not usable, the cost
// (designs x points, with the time) above max_postures; the first design's failure when every
// design fails. Collective under MPI (every rank calls it with the same options).
StatusOr<RobotDesignSweep> robot_design_sweep(const RobotDesignFactory& factory,
                                              const RobotDesignSweepOptions& options);

}  // namespace kinestat::mechanisms
