// Workspace stiffness maps: a posture kernel (posture_kernel.hpp) evaluated at every point of a
// regular grid, turned into scalar fields per point (SI), a status per point and a summary. Fields,
// formulas, units and statuses: docs/maps.md.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "kinestat/core/status.hpp"
#include "kinestat/core/types.hpp"
#include "kinestat/mechanisms/posture_kernel.hpp"

namespace kinestat::mechanisms {

// A regular grid, x fastest: point i + nx (j + ny k) is origin + (i dx, j dy, k dz). An axis with
// one point is a slice (a 2D map of a 3D robot, or the five-bar's plane z = 0).
struct MapGrid {
  Vec3 origin = Vec3::Zero();              // m (rad on an angular axis)
  Vec3 spacing = Vec3::Ones();             // m (rad), positive
  std::array<int, 3> dimensions{1, 1, 1};  // points per axis
  // What the axes are: lengths (m) by default; a robot's orientation map has angles (rad) named
  // rx, ry, rz. Writers label and scale each axis by axis_unit / axis_display (below).
  std::array<bool, 3> angular{false, false, false};
  std::array<const char*, 3> names{"x", "y", "z"};
  std::size_t num_points() const;
  int num_varying_axes() const;  // axes with more than one point: 2 (a plane) or 3 (a box)
  Vec3 point(std::size_t index) const;
  // The grid index of the k-th point of the serpentine path through the grid: x rows alternately
  // forward and backward, the rows of a z layer alternately up and down, so that consecutive points
  // are grid neighbours (compute_workspace_map's order, for the loaded kernels' warm starts).
  std::size_t path_index(std::size_t k) const;
  // Area (2D, m^2) or volume (3D, m^3) one point stands for: the product of the varying axes' spacings.
  double cell_measure() const;
};

// An axis's SI unit ("m" or "rad") and the unit it is shown in with its factor from SI ("mm", 1e3;
// "deg", 180/pi); the unit of cell_measure() ("m^2", "m rad", "rad^2", ...) and its display form.
const char* axis_unit(const MapGrid& g, int axis);
struct UnitDisplay {
  std::string unit;
  double scale = 1.0;  // displayed = SI value * scale
};
UnitDisplay axis_display(const MapGrid& g, int axis);
std::string measure_unit(const MapGrid& g);
UnitDisplay measure_display(const MapGrid& g);

// A closed range of one coordinate (m); lo == hi: that single value.
struct MapRange {
  double lo = 0.0, hi = 0.0;
};

// Points per axis of the grid lo, lo + step, ... (the last point within step * 1e-9 of hi), as a
// double so that a huge request is estimated before anything is allocated.
double map_axis_points(const MapRange& r, double step);

// The grid of `ranges` (x, y, z) at `step` (m), after checking that the ranges are finite and
// ordered, the step positive and finite, at least two ranges span more than one point, and the
// grid has at most `max_points` points. kInvalidInput names the axis ("the x range") or the limit.
StatusOr<MapGrid> make_map_grid(const std::array<MapRange, 3>& ranges, double step, std::size_t max_points);

// The fields of a map point, from the 6x6 tool-point stiffness K and compliance C = K^-1 (blocks
// _tt translational, _rr rotational). Units SI; the indices of the whole 6x6 mix units (Goncalves
// et al. 2010 section 3 computes them all the same). The directional stiffnesses are those a force
// (a moment) at the tool point meets, with the tool free to rotate (translate): the eigenvalues of
// C_tt^-1 = K_tt - K_tr K_rr^-1 K_rt (and of C_rr^-1), not of the block K_tt, which is the
// stiffness with the rotation blocked and overestimates (docs/maps.md). Symmetric parts throughout.
enum class MapField : int {
  kTranslationalMin,       // smallest eigenvalue of C_tt^-1: stiffness in the weakest direction (N/m)
  kTranslationalMax,       // largest eigenvalue of C_tt^-1 (N/m; +inf along a rigid direction)
  kRotationalMin,          // smallest eigenvalue of C_rr^-1 (N m/rad)
  kRotationalMax,          // largest eigenvalue of C_rr^-1 (N m/rad; +inf along a rigid direction)
  kTrace,                  // tr K, eq. (8)
  kNorm1,                  // max column sum of |k_ij|, eq. (9)
  kNorm2,                  // spectral norm, eq. (10)
  kNormFrobenius,          // eq. (11)
  kNormInf,                // max row sum of |k_ij| (the paper's Chebyshev norm)
  kConditionNumber,        // max|eig| / min|eig| of K, eq. (13)
  kLog10Det,               // log10 det K, eq. (7) (det K in SI spans decades: 1e13 to 1e28 in the examples)
  kDeflectionTranslation,  // |C w| translational part under the load w (m)
  kDeflectionRotation,     // |C w| rotational part (rad)
  kSingularityMeasure,     // the kernel's distance to a singularity (1), 0 at a singularity
  kNewtonIterations,       // loaded mode: the equilibrium's Newton steps (PostureResult::newton_iterations)
};
inline constexpr int kNumMapFields = 15;

struct MapFieldInfo {
  const char* name;         // "k_t_min": JSON key, VTI array name (with the unit), --field value
  const char* unit;         // SI: "N/m", "N m/rad", "m", "rad", "1", "SI (mixed)"
  const char* description;  // one line
};
const MapFieldInfo& field_info(MapField f);
std::optional<MapField> field_from_name(const std::string& name);
// Every field's name, comma-separated, for messages that list the choices.
std::string field_names();
// Every field of a point with values (has_values(status)), indexed by MapField; the deflection is
// r.deflection (zero without a load).
std::array<double, kNumMapFields> point_fields(const PostureResult& r);

struct FieldSummary {
  std::size_t count = 0;  // points with a value
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  double min = kNaN, max = kNaN, mean = kNaN;
  Vec3 argmin = Vec3::Constant(kNaN);  // where the minimum sits (m); the first such point in grid order
};

struct MapOptions {
  // A point with values whose singularity measure is below this is kNearSingular. 0.01: for the
  // paper's five-bar (links 0.1 m) a band about 1 mm wide along its loci, up to 1 cm along the
  // B1 = B2 circle of working modes +- and -+ (docs/maps.md).
  double near_singular_threshold = 0.01;
  // Stiff region: points with values and k_t_min >= min_stiffness (N/m).
  std::optional<double> min_stiffness;
  // The kernel carries a load: the deflection fields are part of the map.
  bool with_deflection = false;
  // The kernel iterates (loaded mode): the newton_iterations field is part of the map, set at every
  // reachable point (also singular and failed ones) so that slow regions show.
  bool with_iterations = false;
  std::size_t max_points = 2'000'000;
  int threads = 0;  // 0: all cores
  // progress(done, total) from one thread at a time (evaluate_postures).
  std::function<void(std::size_t done, std::size_t total)> progress;
};

// kInvalidInput naming the field: near_singular_threshold in [0, 1], min_stiffness finite and >= 0,
// max_points >= 1, threads >= 0. compute_workspace_map checks it first.
Status validate(const MapOptions& options);

struct FieldValues {
  MapField field;
  std::vector<double> values;  // per grid point; NaN where the point has no value
  FieldSummary summary;
};

// A curve drawn over a map (a singular locus, the workspace boundary) in the map's coordinates (m),
// as polylines.
struct MapCurve {
  std::string label;  // "workspace boundary", "parallel singularity"
  std::vector<std::vector<Vec3>> lines;
};

struct WorkspaceMap {
  MapGrid grid;
  std::string description;  // the kernel's (robot, mode, method)
  double near_singular_threshold = 0.0;
  std::optional<double> min_stiffness;  // N/m
  std::vector<PostureStatus> status;    // per grid point
  std::vector<FieldValues> fields;      // every MapField, the deflections only with a load
  std::array<std::size_t, kNumPostureStatuses> status_counts{};
  double reachable_measure = 0.0;  // m^2 or m^3: points not kUnreachable, times cell_measure()
  double stiff_measure = 0.0;      // points with k_t_min >= min_stiffness, times cell_measure(); 0 without
  std::vector<MapCurve> curves;    // set by the caller (e.g. five_bar_singular_loci); written to JSON and PNG
  const FieldValues* find(MapField f) const;  // nullptr when the map does not have it
};

// Evaluates `kernel` at every grid point (in chunks, on options.threads threads, along a serpentine
// path: PointOrder::kPath) and fills the fields and summary. Unreachable points have no value in any
// field (NaN); singular and failed points keep only the singularity measure and the iterations. kInvalidInput when the
// grid is empty or above options.max_points.
StatusOr<WorkspaceMap> compute_workspace_map(const PostureKernel& kernel, const MapGrid& grid,
                                             const MapOptions& options = {});

}  // namespace kinestat::mechanisms
