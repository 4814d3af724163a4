// Options shared by several commands (map, design fivebar, vjm): ranges in mm, loads in the command
// line's units, the five-bar's modes, and the progress line on stderr.
#pragma once

#include <array>
#include <chrono>
#include <cstddef>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

#include "kinestat/core/status.hpp"
#include "kinestat/mechanisms/five_bar_kernel.hpp"
#include "kinestat/mechanisms/robot_model.hpp"
#include "kinestat/mechanisms/workspace_map.hpp"

namespace kinestat::cli {

// A finite number filling the whole string.
std::optional<double> parse_number(const std::string& s);

// "lo:hi" or a single value, in mm, to m. Messages start with `what` ("--r1", "--region: the x range").
StatusOr<mechanisms::MapRange> parse_range_mm(const std::string& text, const std::string& what);

// `count` ranges for the axes x, y, z of `option`, given in the form `form` ("x0:x1,y0:y1").
StatusOr<std::vector<mechanisms::MapRange>> parse_ranges_mm(const std::vector<std::string>& parts, std::size_t count,
                                                            const char* option, const char* form);

// Six numbers of a load option, each checked finite and in its physical range (core/input_checks)
// in the unit written, then converted to SI. A wrench: Fx,Fy,Fz (N), Mx,My,Mz (N mm) -> N, N m.
// A displacement: dx,dy,dz (mm), rx,ry,rz (deg) -> m, rad. A point: x,y,z (mm) -> m.
StatusOr<Vec6> parse_wrench_option(const std::vector<double>& v, const char* option);
StatusOr<Vec6> parse_displacement_option(const std::vector<double>& v, const char* option);
StatusOr<Vec3> parse_point_option(const std::vector<double>& v, const char* option);

// The loaded mode of map and design: --load (a prescribed displacement) into `displacement`, else
// --wrench into `wrench`; neither set when both are empty.
Status parse_load_options(const std::vector<double>& load, const std::vector<double>& wrench,
                          std::optional<Vec6>& displacement, std::optional<Vec6>& wrench_si);

// A robot's task coordinates for messages: "[z, rx, ry]".
std::string task_text(const mechanisms::RobotDescription& d);

// Three values of `option` into a robot's task vector: with `first` 0 its x, y, z (mm), with 3 its
// rx, ry, rz (deg). Nothing to do for no values; kInvalidInput naming the option when there are not
// three, one is not finite or out of range, the task commands none of them, or one it does not
// command is not 0.
Status set_robot_task_values(const mechanisms::RobotDescription& d, const std::vector<double>& values, int first,
                             const char* option, VecX& task);

// --threads: 0 (all cores) up to the cores this process may use (more would only be ignored by the
// scheduler, with a warning); kInvalidInput naming the option otherwise.
Status check_threads_option(int threads);

// Which task coordinate each grid axis sets, x, y, z (or rx, ry, rz when `angular`): its index in the
// task, -1 for an axis the task lacks, whose range must then be one value (kInvalidInput naming the
// axis and `range_option` otherwise).
StatusOr<std::array<int, 3>> robot_grid_axes(const mechanisms::RobotDescription& d,
                                             const std::array<mechanisms::MapRange, 3>& ranges, bool angular,
                                             const std::string& range_option);

// --mode ++|+-|-+|--, --assembly up|down, --method msa|vjm into `o`.
Status parse_five_bar_modes(const std::string& mode, const std::string& assembly, const std::string& method,
                            mechanisms::FiveBarKernelOptions& o);

// Percentage and rate on stderr ("\r" updated), once the run has taken a second: shorter runs stay
// silent. The line ends when the object goes.
class Progress {
 public:
  Progress(std::ostream& err, std::string label, std::string unit)
      : err_(err), label_(std::move(label)), unit_(std::move(unit)) {}
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;
  void operator()(std::size_t done, std::size_t total);
  ~Progress();

 private:
  using Clock = std::chrono::steady_clock;
  std::ostream& err_;
  std::string label_, unit_;
  Clock::time_point start_ = Clock::now();
  double last_ = 0.0;
  std::size_t last_done_ = 0;  // evaluate_postures may report the end twice
  bool shown_ = false;
};

}  // namespace kinestat::cli
