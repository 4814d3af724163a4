#include "cli/grid_options.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <ostream>

#include <fmt/format.h>

#include "kinestat/core/input_checks.hpp"
#include "kinestat/core/threads.hpp"
#include "kinestat/core/units.hpp"

namespace kinestat::cli {

using mechanisms::MapRange;

namespace {
using units::kDeg;
using units::kMm;
using units::kNMm;

// The components of a vector option, each with its quantity and the unit it is written in.
struct Component {
  Quantity quantity;
  UnitOfInput unit;
};

template <int N>
StatusOr<Eigen::Matrix<double, N, 1>> vector_option(const std::vector<double>& v, const char* option, const char* form,
                                                    const std::array<Component, N>& parts) {
  if (static_cast<int>(v.size()) != N) return Status::Invalid(fmt::format("{} takes {} numbers: {}", option, N, form));
  Eigen::Matrix<double, N, 1> si;
  for (int i = 0; i < N; ++i) {
    const Component& c = parts[static_cast<std::size_t>(i)];
    if (Status st = check_quantity(v[i], c.quantity, fmt::format("{} component {}", option, i + 1), c.unit); !st.ok())
      return st;
    si(i) = v[i] * c.unit.scale;
  }
  return si;
}

const Component kN{Quantity::kForce, {1.0, "N"}}, kNmm{Quantity::kMoment, {kNMm, "N mm"}},
    kMillimetre{Quantity::kLength, {kMm, "mm"}}, kDegree{Quantity::kAngle, {kDeg, "deg"}};
}  // namespace

StatusOr<Vec6> parse_wrench_option(const std::vector<double>& v, const char* option) {
  return vector_option<6>(v, option, "Fx,Fy,Fz (N), Mx,My,Mz (N mm)", {kN, kN, kN, kNmm, kNmm, kNmm});
}

StatusOr<Vec6> parse_displacement_option(const std::vector<double>& v, const char* option) {
  return vector_option<6>(v, option, "dx,dy,dz (mm), rx,ry,rz (deg)",
                          {kMillimetre, kMillimetre, kMillimetre, kDegree, kDegree, kDegree});
}

StatusOr<Vec3> parse_point_option(const std::vector<double>& v, const char* option) {
  return vector_option<3>(v, option, "x,y,z (mm)", {kMillimetre, kMillimetre, kMillimetre});
}

Status parse_load_options(const std::vector<double>& load, const std::vector<double>& wrench,
                          std::optional<Vec6>& displacement, std::optional<Vec6>& wrench_si) {
  if (!load.empty()) {
    auto d = parse_displacement_option(load, "--load");
    if (!d.ok()) return d.status();
    displacement = *d;
  } else if (!wrench.empty()) {
    auto w = parse_wrench_option(wrench, "--wrench");
    if (!w.ok()) return w.status();
    wrench_si = *w;
  }
  return Status::Ok();
}

std::string task_text(const mechanisms::RobotDescription& d) {
  std::string out;
  for (mechanisms::TaskCoordinate c : d.task) out += fmt::format("{}{}", out.empty() ? "" : ", ", to_string(c));
  return "[" + out + "]";
}

Status set_robot_task_values(const mechanisms::RobotDescription& d, const std::vector<double>& values, int first,
                             const char* option, VecX& task) {
  if (values.empty()) return Status::Ok();
  const bool angles = first == 3;
  const Component& part = angles ? kDegree : kMillimetre;
  auto si = vector_option<3>(values, option, angles ? "rx,ry,rz (deg)" : "x,y,z (mm)", {part, part, part});
  if (!si.ok()) return si.status();
  std::array<bool, 3> commanded{};
  for (std::size_t t = 0; t < d.task.size(); ++t) {
    const int c = static_cast<int>(d.task[t]) - first;
    if (c < 0 || c > 2) continue;
    task(static_cast<int>(t)) = (*si)(c);
    commanded[static_cast<std::size_t>(c)] = true;
  }
  if (std::none_of(commanded.begin(), commanded.end(), [](bool b) { return b; }))
    return Status::Invalid(fmt::format("{}: {} commands no {} (its task is {})", option, d.name,
                                       angles ? "orientation" : "position", task_text(d)));
  // A value for a coordinate the robot does not command would be dropped: its legs decide it.
  for (int c = 0; c < 3; ++c)
    if (!commanded[static_cast<std::size_t>(c)] && values[static_cast<std::size_t>(c)] != 0.0)
      return Status::Invalid(fmt::format("{}: {} does not command {} (its task is {}): its legs set it; give 0 there",
                                         option, d.name, to_string(static_cast<mechanisms::TaskCoordinate>(first + c)),
                                         task_text(d)));
  return Status::Ok();
}

Status check_threads_option(int threads) {
  if (threads < 0) return Status::Invalid("--threads must be 0 (all cores) or a positive count");
  if (threads > available_cpus())
    return Status::Invalid(
        fmt::format("--threads {}: this process may run {} at once; give at most {} (0: all of them)", threads,
                    available_cpus(), available_cpus()));
  return Status::Ok();
}

StatusOr<std::array<int, 3>> robot_grid_axes(const mechanisms::RobotDescription& d,
                                             const std::array<mechanisms::MapRange, 3>& ranges, bool angular,
                                             const std::string& range_option) {
  std::array<int, 3> axes{-1, -1, -1};
  for (std::size_t t = 0; t < d.task.size(); ++t) {
    const int c = static_cast<int>(d.task[t]) - (angular ? 3 : 0);
    if (c >= 0 && c < 3) axes[c] = static_cast<int>(t);
  }
  for (int i = 0; i < 3; ++i)
    if (axes[i] < 0 && ranges[i].lo != ranges[i].hi)
      return Status::Invalid(fmt::format("{} commands no {}{} (its task is {}): give a single value for it in {}",
                                         d.name, angular ? "r" : "", "xyz"[i], task_text(d), range_option));
  return axes;
}

std::optional<double> parse_number(const std::string& s) {
  double v = 0.0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v)) return std::nullopt;
  return v;
}

StatusOr<MapRange> parse_range_mm(const std::string& text, const std::string& what) {
  const std::size_t colon = text.find(':', 1);  // not the sign of a leading negative bound
  const auto lo = parse_number(text.substr(0, colon));
  const auto hi = colon == std::string::npos ? lo : parse_number(text.substr(colon + 1));
  if (!lo || !hi)
    return Status::Invalid(fmt::format("{} '{}' is not a range in mm; write lo:hi or a single value", what, text));
  if (*lo > *hi) return Status::Invalid(fmt::format("{} {} is reversed; write the smaller bound first", what, text));
  return MapRange{*lo * kMm, *hi * kMm};
}

StatusOr<std::vector<MapRange>> parse_ranges_mm(const std::vector<std::string>& parts, std::size_t count,
                                                const char* option, const char* form) {
  if (parts.size() != count)
    return Status::Invalid(fmt::format("{} takes {} ranges, {} (mm); got {}", option, count, form, parts.size()));
  std::vector<MapRange> ranges;
  for (std::size_t a = 0; a < count; ++a) {
    auto r = parse_range_mm(parts[a], fmt::format("{}: the {} range", option, "xyz"[a]));
    if (!r.ok()) return r.status();
    ranges.push_back(*r);
  }
  return ranges;
}

Status parse_five_bar_modes(const std::string& mode, const std::string& assembly, const std::string& method,
                            mechanisms::FiveBarKernelOptions& o) {
  using namespace mechanisms;
  const auto m = working_mode_from_name(mode);
  if (!m)
    return Status::Invalid(fmt::format("--mode '{}' is not a working mode; use ++, +-, -+ or -- (as --mode=--)", mode));
  o.mode = *m;
  const auto a = assembly_from_name(assembly);
  if (!a) return Status::Invalid(fmt::format("--assembly '{}' must be up or down", assembly));
  o.assembly = *a;
  if (method != "msa" && method != "vjm")
    return Status::Invalid(fmt::format("--method '{}' must be msa or vjm", method));
  o.method = method == "msa" ? StiffnessMethod::kMsa : StiffnessMethod::kVjm;
  return Status::Ok();
}

void Progress::operator()(std::size_t done, std::size_t total) {
  const double t = std::chrono::duration<double>(Clock::now() - start_).count();
  if (t < 1.0 || (done < total && t - last_ < 0.5) || (shown_ && done == last_done_)) return;
  last_ = t;
  last_done_ = done;
  shown_ = true;
  err_ << fmt::format("\r{}: {:3.0f}% ({} of {} {}, {:.3g} {}/s)", label_, 100.0 * done / total, done, total, unit_,
                      done / t, unit_)
       << std::flush;
}

Progress::~Progress() {
  if (shown_) err_ << "\n";
}

}  // namespace kinestat::cli
