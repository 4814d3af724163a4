#include "kinestat/mechanisms/robot_design_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <set>

#include <fmt/format.h>

#include "kinestat/core/input_checks.hpp"
#include "kinestat/core/threads.hpp"
#include "kinestat/solver/parallel.hpp"

namespace kinestat::mechanisms {
namespace {

constexpr int kMaxSteps = 1000;
// Numbers per design gathered from the ranks: status code, reachable and stiff measures and
// points, k_t_min_worst.
constexpr std::size_t kPacked = 6;

Status check_parameters(const std::vector<DesignParameter>& ps) {
  if (ps.empty()) return Status::Invalid("design sweep: no parameter to sweep; name at least one");
  std::set<std::string> seen;
  for (const DesignParameter& p : ps) {
    if (p.name.empty()) return Status::Invalid("design sweep: a parameter without a name");
    if (!seen.insert(p.name).second)
      return Status::Invalid(fmt::format("design sweep: parameter '{}' is swept twice; name it once", p.name));
    if (!(std::isfinite(p.lo) && std::isfinite(p.hi)))
      return Status::Invalid(
          fmt::format("design sweep: parameter '{}': the range {:g}:{:g} is not finite", p.name, p.lo, p.hi));
    if (p.lo > p.hi)
      return Status::Invalid(
          fmt::format("design sweep: parameter '{}': the range {:g}:{:g} is reversed; write the "
                      "smaller bound first",
                      p.name, p.lo, p.hi));
  }
  return Status::Ok();
}

std::string duration_text(double seconds) {
  if (seconds >= 3600.0) return fmt::format("{:.2g} h", seconds / 3600.0);
  if (seconds >= 60.0) return fmt::format("{:.2g} min", seconds / 60.0);
  return fmt::format("{:.2g} s", seconds);
}

// One design's map reduced to its measures.
RobotDesignResult measure(const WorkspaceMap& map, double min_stiffness) {
  RobotDesignResult r;
  r.reachable_measure = map.reachable_measure;
  r.stiff_measure = map.stiff_measure;
  r.reachable_points = map.status.size() - map.status_counts[static_cast<int>(PostureStatus::kUnreachable)];
  const std::vector<double>& kt = map.find(MapField::kTranslationalMin)->values;
  bool any = false;
  for (std::size_t i = 0; i < kt.size(); ++i) {
    if (!has_values(map.status[i]) || std::isnan(kt[i])) continue;
    r.k_t_min_worst = any ? std::min(r.k_t_min_worst, kt[i]) : kt[i];
    any = true;
    if (kt[i] >= min_stiffness) ++r.stiff_points;
  }
  return r;
}

}  // namespace

std::vector<double> design_values(const DesignParameter& p, int steps) {
  if (!(p.hi > p.lo)) return {p.lo};
  std::vector<double> v;
  for (int i = 0; i < steps; ++i) v.push_back(i == steps - 1 ? p.hi : p.lo + (p.hi - p.lo) * i / (steps - 1));
  return v;
}

StatusOr<RobotDesignSweep> robot_design_sweep(const RobotDesignFactory& factory, const RobotDesignSweepOptions& o) {
  if (!factory) return Status::Invalid("design sweep: no model factory");
  if (Status s = check_parameters(o.parameters); !s.ok()) return s;
  const bool varies =
      std::any_of(o.parameters.begin(), o.parameters.end(), [](const DesignParameter& p) { return p.hi > p.lo; });
  if (varies && (o.steps < 2 || o.steps > kMaxSteps))
    return Status::Invalid(
        fmt::format("{} designs per parameter: a range needs 2 to {} (a single value needs none)", o.steps, kMaxSteps));
  const std::size_t n_region = o.region.num_points();
  if (o.region.num_varying_axes() < 2)
    return Status::Invalid(
        fmt::format("region: {} point(s), neither a plane nor a box; make it with make_map_grid "
                    "over ranges of which at least two span more than one point",
                    n_region));
  MapOptions map_options;
  map_options.near_singular_threshold = o.near_singular_threshold;
  map_options.min_stiffness = o.min_stiffness;
  map_options.threads = o.threads;
  map_options.max_points = n_region;
  const bool loaded = o.kernel.wrench || o.kernel.displacement;
  map_options.with_deflection = loaded;
  map_options.with_iterations = loaded;
  if (Status s = validate(map_options); !s.ok()) return s;

  RobotDesignSweep out;
  out.parameters = o.parameters;
  out.region = o.region;
  out.near_singular_threshold = o.near_singular_threshold;
  out.min_stiffness = o.min_stiffness;
  std::vector<std::vector<double>> axis_values;
  double designs = 1.0;
  for (const DesignParameter& p : o.parameters) {
    axis_values.push_back(design_values(p, o.steps));
    out.dimensions.push_back(static_cast<int>(axis_values.back().size()));
    designs *= static_cast<double>(axis_values.back().size());
  }
  const solver::ProcessGroup group =
      o.distribute && solver::parallel_running() ? solver::process_group() : solver::ProcessGroup{};
  out.ranks = group.size;
  // Counted before anything runs: a sweep of hours is a choice to make, not a typo to start.
  const double postures = designs * static_cast<double>(n_region);
  const int threads = o.threads > 0 ? o.threads : available_cpus();
  const double rate =
      (loaded ? kRobotKernelLoadedPosturesPerSecond : kRobotKernelPosturesPerSecond) * threads * group.size;
  if (Status s = check_size(postures, o.max_postures, fmt::format("{:g} designs x {} region points", designs, n_region),
                            "postures",
                            fmt::format("that is about {} on {} thread{}{}; sweep fewer designs (steps) or a coarser "
                                        "region, or raise the limit (--max-postures, max_postures)",
                                        duration_text(postures / rate), threads, threads > 1 ? "s" : "",
                                        group.size > 1 ? fmt::format(" x {} MPI ranks", group.size) : ""));
      !s.ok())
    return s;

  const std::size_t n_designs = static_cast<std::size_t>(designs);
  out.results.resize(n_designs);
  for (std::size_t k = 0; k < n_designs; ++k) {
    std::size_t rest = k;
    for (std::size_t p = 0; p < axis_values.size(); ++p) {
      out.results[k].values.push_back(axis_values[p][rest % axis_values[p].size()]);
      rest /= axis_values[p].size();
    }
  }
  std::vector<std::size_t> mine;
  for (std::size_t k = static_cast<std::size_t>(group.rank); k < n_designs; k += static_cast<std::size_t>(group.size))
    mine.push_back(k);
  const std::size_t total = mine.size() * n_region;
  std::vector<std::string> descriptions(n_designs);
  for (std::size_t m = 0; m < mine.size(); ++m) {
    const std::size_t k = mine[m];
    RobotDesignResult& r = out.results[k];
    std::vector<std::pair<std::string, double>> named;
    for (std::size_t p = 0; p < o.parameters.size(); ++p) named.emplace_back(o.parameters[p].name, r.values[p]);
    StatusOr<RobotModel> model = factory(named);
    if (!model.ok()) {
      r.status = model.status();
      continue;
    }
    RobotKernelOptions kernel_options = o.kernel;
    kernel_options.model = std::make_shared<const RobotModel>(std::move(*model));
    if (Status s = validate(kernel_options); !s.ok()) {
      r.status = s;
      continue;
    }
    const std::unique_ptr<PostureKernel> kernel = make_robot_kernel(kernel_options);
    descriptions[k] = kernel->description();
    if (o.progress)
      map_options.progress = [&, m](std::size_t done, std::size_t) { o.progress(m * n_region + done, total); };
    StatusOr<WorkspaceMap> map = compute_workspace_map(*kernel, o.region, map_options);
    if (!map.ok()) {
      r.status = map.status();
      continue;
    }
    std::vector<double> values = std::move(r.values);
    r = measure(*map, o.min_stiffness);
    r.values = std::move(values);
  }

  if (group.size > 1) {
    // This rank's designs, packed; rank 0 receives every rank's in rank order and unpacks them.
    std::vector<double> numbers;
    std::vector<char> text;
    for (std::size_t k : mine) {
      const RobotDesignResult& r = out.results[k];
      numbers.insert(numbers.end(),
                     {static_cast<double>(r.status.code()), r.reachable_measure, r.stiff_measure,
                      static_cast<double>(r.reachable_points), static_cast<double>(r.stiff_points), r.k_t_min_worst});
      for (const std::string* s : {&r.status.message(), static_cast<const std::string*>(&descriptions[k])}) {
        text.insert(text.end(), s->begin(), s->end());
        text.push_back('\0');
      }
    }
    Status gathered = solver::gather_to_root(numbers);
    if (gathered.ok()) gathered = solver::gather_to_root(text);
    if (Status s = solver::agree_on_status(gathered); !s.ok()) return s;
    if (group.rank == 0) {
      std::size_t at = 0, chars = 0;
      const auto next_text = [&]() {
        const auto end = std::find(text.begin() + static_cast<std::ptrdiff_t>(chars), text.end(), '\0');
        std::string s(text.begin() + static_cast<std::ptrdiff_t>(chars), end);
        chars = static_cast<std::size_t>(end - text.begin()) + 1;
        return s;
      };
      for (int rank = 0; rank < group.size; ++rank)
        for (std::size_t k = static_cast<std::size_t>(rank); k < n_designs; k += static_cast<std::size_t>(group.size)) {
          if (at + kPacked > numbers.size()) return Status::Internal("design sweep: MPI ranks sent too few results");
          RobotDesignResult& r = out.results[k];
          const std::string message = next_text();
          r.status = Status(static_cast<StatusCode>(static_cast<int>(numbers[at])), message);
          r.reachable_measure = numbers[at + 1];
          r.stiff_measure = numbers[at + 2];
          r.reachable_points = static_cast<std::size_t>(numbers[at + 3]);
          r.stiff_points = static_cast<std::size_t>(numbers[at + 4]);
          r.k_t_min_worst = numbers[at + 5];
          descriptions[k] = next_text();
          at += kPacked;
        }
    } else {
      out.complete = false;
    }
  }

  // The best of the built designs: the most stiff points (the same cell for every design: the
  // largest stiff measure), of equal ones the first. Every design failed: the first one's reason.
  Status all_failed = Status::Ok();
  if (out.complete) {
    std::optional<std::size_t> best;
    for (std::size_t k = 0; k < n_designs; ++k) {
      const RobotDesignResult& r = out.results[k];
      if (!r.status.ok()) continue;
      if (out.description.empty()) out.description = descriptions[k];
      if (!best || r.stiff_points > out.results[*best].stiff_points) best = k;
    }
    if (best) {
      out.best = *best;
    } else {
      const RobotDesignResult& r = out.results.front();
      std::string values;
      for (std::size_t p = 0; p < o.parameters.size(); ++p)
        values += fmt::format("{}{} = {:g}", p ? ", " : "", o.parameters[p].name, r.values[p]);
      all_failed =
          Status(r.status.code(), fmt::format("every design failed; the first ({}): {}", values, r.status.message()));
    }
  }
  // Rank 0 alone knows: every rank returns its verdict.
  if (group.size > 1) {
    if (Status s = solver::agree_on_status(all_failed); !s.ok()) return s;
  } else if (!all_failed.ok()) {
    return all_failed;
  }
  return out;
}

}  // namespace kinestat::mechanisms
