#include "kinestat/mechanisms/workspace_map.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "kinestat/core/input_checks.hpp"
#include "kinestat/core/threads.hpp"
#include "kinestat/core/units.hpp"

namespace kinestat::mechanisms {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Indexed by MapField.
constexpr std::array<MapFieldInfo, kNumMapFields> kFields = {{
    {"k_t_min", "N/m", "stiffness against a force in the weakest direction: smallest eigenvalue of C_tt^-1"},
    {"k_t_max", "N/m", "stiffness against a force in the stiffest direction: largest eigenvalue of C_tt^-1"},
    {"k_r_min", "N m/rad", "stiffness against a moment about the weakest axis: smallest eigenvalue of C_rr^-1"},
    {"k_r_max", "N m/rad", "stiffness against a moment about the stiffest axis: largest eigenvalue of C_rr^-1"},
    {"trace", "SI (mixed)", "trace of the 6x6 K (Goncalves et al. 2010 eq. 8)"},
    {"norm_1", "SI (mixed)", "1-norm of K: max column sum of |k_ij| (eq. 9)"},
    {"norm_2", "SI (mixed)", "2-norm of K: largest |eigenvalue| (eq. 10)"},
    {"norm_frobenius", "SI (mixed)", "Frobenius norm of K (eq. 11)"},
    {"norm_inf", "SI (mixed)", "infinity-norm of K: max row sum of |k_ij|, the paper's Chebyshev norm"},
    {"condition_number", "1 (of mixed units)", "condition number of K: max|eig| / min|eig| (eq. 13)"},
    {"log10_det", "log10 of SI (mixed)", "log10 of det K (eq. 7)"},
    {"deflection_t", "m", "tool-point translation under the load: |(C w)_xyz|"},
    {"deflection_r", "rad", "tool-point rotation under the load: |(C w)_rx,ry,rz|"},
    {"singularity_measure", "1", "distance to a singularity in [0, 1], 0 at a singularity (the kernel's measure)"},
    {"newton_iterations", "1", "Newton steps of the loaded equilibrium, every chain's summed (failed points too)"},
}};

void summarize(FieldValues& f, const MapGrid& grid) {
  FieldSummary& s = f.summary;
  double sum = 0.0;
  for (std::size_t i = 0; i < f.values.size(); ++i) {
    const double v = f.values[i];
    if (std::isnan(v)) continue;
    if (s.count == 0 || v < s.min) {
      s.min = v;
      s.argmin = grid.point(i);
    }
    if (s.count == 0 || v > s.max) s.max = v;
    sum += v;
    ++s.count;
  }
  if (s.count > 0) s.mean = sum / static_cast<double>(s.count);
}

}  // namespace

std::size_t MapGrid::num_points() const {
  return static_cast<std::size_t>(dimensions[0]) * static_cast<std::size_t>(dimensions[1]) *
         static_cast<std::size_t>(dimensions[2]);
}

int MapGrid::num_varying_axes() const {
  return static_cast<int>(std::count_if(dimensions.begin(), dimensions.end(), [](int n) { return n > 1; }));
}

Vec3 MapGrid::point(std::size_t index) const {
  const std::size_t nx = dimensions[0], ny = dimensions[1];
  const Vec3 ijk(static_cast<double>(index % nx), static_cast<double>((index / nx) % ny),
                 static_cast<double>(index / (nx * ny)));
  return origin + spacing.cwiseProduct(ijk);
}

std::size_t MapGrid::path_index(std::size_t k) const {
  const std::size_t nx = dimensions[0], ny = dimensions[1];
  const std::size_t row = k / nx, z = row / ny;  // row: the path's row count, over the layers
  std::size_t x = k % nx, y = row % ny;
  if (row % 2 == 1) x = nx - 1 - x;
  if (z % 2 == 1) y = ny - 1 - y;
  return x + nx * (y + ny * z);
}

const char* axis_unit(const MapGrid& g, int axis) { return g.angular[axis] ? "rad" : "m"; }

UnitDisplay axis_display(const MapGrid& g, int axis) {
  return g.angular[axis] ? UnitDisplay{"deg", 1.0 / units::kDeg} : UnitDisplay{"mm", 1.0 / units::kMm};
}

namespace {
// "m^2 rad" from the varying axes' units.
std::string product_unit(const MapGrid& g, const char* length, const char* angle) {
  int lengths = 0, angles = 0;
  for (int a = 0; a < 3; ++a)
    if (g.dimensions[a] > 1) ++(g.angular[a] ? angles : lengths);
  auto power = [](const char* u, int n) {
    return n == 0 ? std::string() : n == 1 ? std::string(u) : fmt::format("{}^{}", u, n);
  };
  const std::string l = power(length, lengths), r = power(angle, angles);
  return l.empty() ? r : r.empty() ? l : l + " " + r;
}
}  // namespace

std::string measure_unit(const MapGrid& g) { return product_unit(g, "m", "rad"); }

UnitDisplay measure_display(const MapGrid& g) {
  double scale = 1.0;
  for (int a = 0; a < 3; ++a)
    if (g.dimensions[a] > 1) scale *= axis_display(g, a).scale;
  return {product_unit(g, "mm", "deg"), scale};
}

double MapGrid::cell_measure() const {
  double m = 1.0;
  for (int a = 0; a < 3; ++a)
    if (dimensions[a] > 1) m *= spacing(a);
  return m;
}

double map_axis_points(const MapRange& r, double step) {
  if (!(step > 0.0) || !std::isfinite(step) || !(r.lo <= r.hi)) return 0.0;
  return std::floor((r.hi - r.lo) / step + 1e-9) + 1.0;
}

StatusOr<MapGrid> make_map_grid(const std::array<MapRange, 3>& ranges, double step, std::size_t max_points) {
  if (!(step > 0.0) || !std::isfinite(step))
    return Status::Invalid(fmt::format("grid step {:g} m: it must be positive and finite", step));
  static constexpr const char* kAxis[3] = {"x", "y", "z"};
  double count = 1.0;
  MapGrid grid;
  for (int a = 0; a < 3; ++a) {
    const MapRange& r = ranges[a];
    if (!std::isfinite(r.lo) || !std::isfinite(r.hi))
      return Status::Invalid(fmt::format("the {} range has a non-finite bound", kAxis[a]));
    if (r.lo > r.hi)
      return Status::Invalid(
          fmt::format("the {} range {:g}:{:g} m is reversed; write the smaller bound first", kAxis[a], r.lo, r.hi));
    const double n = map_axis_points(r, step);
    count *= n;
    grid.origin(a) = r.lo;
    grid.spacing(a) = step;
    grid.dimensions[a] = static_cast<int>(std::min(n, 2e9));
  }
  if (grid.num_varying_axes() < 2)
    return Status::Invalid(
        fmt::format("a map needs two ranges longer than the step {:g} m (a plane or a box); "
                    "got {} x {} x {} points",
                    step, grid.dimensions[0], grid.dimensions[1], grid.dimensions[2]));
  if (count > static_cast<double>(max_points))
    return Status::Invalid(fmt::format("the grid has {:.3g} points, more than the limit of {}", count, max_points));
  return grid;
}

const MapFieldInfo& field_info(MapField f) { return kFields[static_cast<int>(f)]; }

std::optional<MapField> field_from_name(const std::string& name) {
  for (int i = 0; i < kNumMapFields; ++i)
    if (name == kFields[i].name) return static_cast<MapField>(i);
  return std::nullopt;
}

std::string field_names() {
  std::string names;
  for (int i = 0; i < kNumMapFields; ++i) names += fmt::format("{}{}", i ? ", " : "", kFields[i].name);
  return names;
}

std::array<double, kNumMapFields> point_fields(const PostureResult& r) {
  // Stiffness under a pure force (moment): the inverse of the compliance block, i.e. the Schur
  // complement K_tt - K_tr K_rr^-1 K_rt; judged by its symmetric part like every index here.
  // A block with a rigid direction (compliance zero along it: docs/robots.md, "Stiffness") has no
  // inverse; its stiffnesses are then the inverses of its compliances, +inf along the rigid one.
  const auto block_eigenvalues = [](const Mat3& compliance_block) -> Vec3 {
    const Mat3 k = compliance_block.inverse();
    if (k.allFinite())
      return Eigen::SelfAdjointEigenSolver<Mat3>(0.5 * (k + k.transpose()), Eigen::EigenvaluesOnly).eigenvalues();
    const Vec3 mu = Eigen::SelfAdjointEigenSolver<Mat3>(0.5 * (compliance_block + compliance_block.transpose()),
                                                        Eigen::EigenvaluesOnly)
                        .eigenvalues();
    const auto stiffness = [](double m) { return m > 0.0 ? 1.0 / m : std::numeric_limits<double>::infinity(); };
    return {stiffness(mu(2)), stiffness(mu(1)), stiffness(mu(0))};
  };
  const Vec3 t = block_eigenvalues(r.compliance.topLeftCorner<3, 3>());
  const Vec3 rot = block_eigenvalues(r.compliance.bottomRightCorner<3, 3>());
  const CartesianIndices& ix = r.indices;
  return {t(0),
          t(2),
          rot(0),
          rot(2),
          ix.trace,
          ix.norm_1,
          ix.norm_2,
          ix.norm_frobenius,
          ix.norm_inf,
          ix.condition_number,
          ix.log10_abs_det,
          r.deflection.head<3>().norm(),
          r.deflection.tail<3>().norm(),
          r.singularity_measure,
          static_cast<double>(r.newton_iterations)};
}

const FieldValues* WorkspaceMap::find(MapField f) const {
  for (const FieldValues& v : fields)
    if (v.field == f) return &v;
  return nullptr;
}

Status validate(const MapOptions& o) {
  if (!(o.near_singular_threshold >= 0.0 && o.near_singular_threshold <= 1.0))
    return Status::Invalid(
        fmt::format("near_singular_threshold = {:g}: the threshold on the singularity measure lies "
                    "in [0, 1] (default 0.01)",
                    o.near_singular_threshold));
  if (o.min_stiffness)
    if (Status s = check_quantity(*o.min_stiffness, Quantity::kTranslationalStiffness, "min_stiffness", {},
                                  Sign::kNonNegative);
        !s.ok())
      return s;
  if (o.max_points < 1) return Status::Invalid("max_points = 0: give the largest grid to allow (default 2000000)");
  if (o.threads < 0 || o.threads > available_cpus())
    return Status::Invalid(fmt::format("threads = {}: give 0 (all cores) or a count up to the {} this process may use",
                                       o.threads, available_cpus()));
  return Status::Ok();
}

StatusOr<WorkspaceMap> compute_workspace_map(const PostureKernel& kernel, const MapGrid& grid,
                                             const MapOptions& options) {
  if (Status s = validate(options); !s.ok()) return s;
  const std::size_t n = grid.num_points();
  if (n == 0) return Status::Invalid("the map grid has no points");
  if (n > options.max_points)
    return Status::Invalid(fmt::format("the grid has {} points, more than the limit of {}", n, options.max_points));

  WorkspaceMap map;
  map.grid = grid;
  map.description = kernel.description();
  map.near_singular_threshold = options.near_singular_threshold;
  map.min_stiffness = options.min_stiffness;
  map.status.assign(n, PostureStatus::kUnreachable);
  static_assert(static_cast<int>(MapField::kSingularityMeasure) == kNumMapFields - 2 &&
                static_cast<int>(MapField::kNewtonIterations) == kNumMapFields - 1);
  for (int i = 0; i < kNumMapFields; ++i) {
    const auto f = static_cast<MapField>(i);
    const bool deflection = f == MapField::kDeflectionTranslation || f == MapField::kDeflectionRotation;
    if (deflection && !options.with_deflection) continue;
    if (f == MapField::kNewtonIterations && !options.with_iterations) continue;
    map.fields.push_back({f, std::vector<double>(n, kNaN), {}});
  }
  // Both set at every reachable point, with values or not.
  FieldValues* const measure = &map.fields[map.fields.size() - (options.with_iterations ? 2 : 1)];
  FieldValues* const iterations = options.with_iterations ? &map.fields.back() : nullptr;

  // Each result is digested into the fields on the thread that computed it (in parallel, no buffer of
  // results); chunks bound the memory of the points (32 B each) whatever the grid size. The points are
  // visited along the serpentine path, so that a loaded kernel starts each posture from its
  // neighbour's equilibrium (evaluate_postures, PointOrder::kPath; kChunk is a multiple of kPathChunk,
  // so the path's chunks do not depend on it).
  constexpr std::size_t kChunk = std::size_t{1} << 20;
  static_assert(kChunk % kPathChunk == 0);
  std::vector<Vec3> points;
  std::vector<std::size_t> index;
  for (std::size_t begin = 0; begin < n; begin += kChunk) {
    const std::size_t end = std::min(n, begin + kChunk);
    points.resize(end - begin);
    index.resize(end - begin);
    for (std::size_t k = begin; k < end; ++k) {
      index[k - begin] = grid.path_index(k);
      points[k - begin] = grid.point(index[k - begin]);
    }
    std::function<void(std::size_t, std::size_t)> progress;
    if (options.progress) progress = [&, begin](std::size_t done, std::size_t) { options.progress(begin + done, n); };
    const auto visit = [&](std::size_t k, const PostureResult& r) {
      if (r.status == PostureStatus::kUnreachable) return;
      const std::size_t i = index[k];
      if (FieldValues* it = iterations) it->values[i] = r.newton_iterations;
      PostureStatus s = static_cast<PostureStatus>(r.status);
      if (s == PostureStatus::kOk && !(r.singularity_measure >= options.near_singular_threshold))
        s = PostureStatus::kNearSingular;
      map.status[i] = s;
      if (has_values(s)) {
        const std::array<double, kNumMapFields> v = point_fields(r);
        for (FieldValues& f : map.fields) f.values[i] = v[static_cast<int>(f.field)];
      } else {
        measure->values[i] = r.singularity_measure;
      }
    };
    evaluate_postures(kernel, points, visit, options.threads, progress, PointOrder::kPath);
  }

  for (PostureStatus s : map.status) ++map.status_counts[static_cast<int>(s)];
  for (FieldValues& f : map.fields) summarize(f, grid);
  const std::size_t reachable = n - map.status_counts[static_cast<int>(PostureStatus::kUnreachable)];
  map.reachable_measure = static_cast<double>(reachable) * grid.cell_measure();
  if (options.min_stiffness) {
    const std::vector<double>& kt = map.find(MapField::kTranslationalMin)->values;
    const auto stiff = std::count_if(kt.begin(), kt.end(), [&](double k) { return k >= *options.min_stiffness; });
    map.stiff_measure = static_cast<double>(stiff) * grid.cell_measure();
  }
  return map;
}

}  // namespace kinestat::mechanisms
