// kinestat.mechanisms, maps: the workspace stiffness map (mechanisms/workspace_map.hpp) and the
// five-bar design sweep (mechanisms/five_bar_design_sweep.hpp), their grids, fields and statuses as
// NumPy arrays of shape (nz, ny, nx) (the map) and (ny, nx) = (r2 steps, r1 steps) (the designs).
// In its own file beside mechanisms.cpp, which holds the single-posture models.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "kinestat/core/input_checks.hpp"
#include "kinestat/mechanisms/five_bar_design_sweep.hpp"
#include "kinestat/mechanisms/five_bar_loci.hpp"
#include "kinestat/mechanisms/workspace_map.hpp"
#include "python/bindings.hpp"

namespace kinestat::python {

namespace {

using namespace mechanisms;

// The grid's points as the shape NumPy indexes them: [k, j, i] is point i + nx (j + ny k).
std::vector<py::ssize_t> grid_shape(const MapGrid& g) { return {g.dimensions[2], g.dimensions[1], g.dimensions[0]}; }

template <class T, class V>
py::array_t<T> grid_array(const MapGrid& g, const std::vector<V>& values) {
  py::array_t<T> a(grid_shape(g));
  T* out = a.mutable_data();
  for (size_t i = 0; i < values.size(); ++i) out[i] = static_cast<T>(values[i]);
  return a;
}

// The design results' values over the (r1, r2) grid: (ny, nx) = (r2 steps, r1 steps).
template <class F>
py::array_t<double> design_array(const FiveBarDesignSweep& s, F&& value) {
  py::array_t<double> a(
      {static_cast<py::ssize_t>(s.designs.dimensions[1]), static_cast<py::ssize_t>(s.designs.dimensions[0])});
  double* out = a.mutable_data();
  for (size_t i = 0; i < s.results.size(); ++i) out[i] = value(s.results[i]);
  return a;
}

const FieldValues& map_field_values(const WorkspaceMap& m, MapField f) {
  const FieldValues* v = m.find(f);
  if (v == nullptr)
    raise_status(
        Status::Invalid(fmt::format("field {}: this map has none (the deflections need a load)", field_info(f).name)));
  return *v;
}

// Checked here because C++ trusts a MapGrid: a negative or huge dimension would allocate wildly.
MapGrid make_grid(const Vec3& origin, const Vec3& spacing, const std::array<int, 3>& dimensions) {
  double points = 1.0;
  for (int a = 0; a < 3; ++a) {
    const std::string axis = fmt::format("MapGrid: the {} axis's ", "xyz"[a]);
    if (dimensions[a] < 1)
      raise_status(
          Status::Invalid(fmt::format("{}dimension {}: every axis has at least one point", axis, dimensions[a])));
    check(check_quantity(spacing(a), Quantity::kLength, axis + "spacing", {}, Sign::kPositive));
    check(check_quantity(origin(a), Quantity::kLength, axis + "origin"));
    points *= dimensions[a];
  }
  check(check_size(points, static_cast<double>(MapOptions{}.max_points), "MapGrid", "points",
                   "use fewer points per axis"));
  return MapGrid{origin, spacing, dimensions};
}

void bind_grid(py::module_& m) {
  py::class_<MapRange>(m, "MapRange",
                       "A closed range lo..hi of one coordinate (m); lo == hi: that single value. A "
                       "(lo, hi) tuple or a number converts to it.")
      .def(py::init([](double lo, std::optional<double> hi) {
             return MapRange{lo, hi.value_or(lo)};
           }),
           py::arg("lo"), py::arg("hi") = py::none())
      .def(py::init([](const std::pair<double, double>& t) {
             return MapRange{t.first, t.second};
           }),
           py::arg("range"))
      .def_readwrite("lo", &MapRange::lo)
      .def_readwrite("hi", &MapRange::hi)
      .def("__repr__", [](const MapRange& r) { return fmt::format("MapRange({:g}, {:g})", r.lo, r.hi); });
  py::implicitly_convertible<py::tuple, MapRange>();
  py::implicitly_convertible<py::float_, MapRange>();
  py::implicitly_convertible<py::int_, MapRange>();

  py::class_<MapGrid>(m, "MapGrid",
                      "A regular grid, x fastest: point i + nx (j + ny k) is origin + (i dx, j dy, k dz) (m). Arrays "
                      "over it have shape (nz, ny, nx): [k, j, i].")
      .def(py::init(&make_grid), py::arg("origin"), py::arg("spacing"), py::arg("dimensions"))
      .def_readonly("origin", &MapGrid::origin, "m")
      .def_readonly("spacing", &MapGrid::spacing, "m")
      .def_readonly("dimensions", &MapGrid::dimensions, "[nx, ny, nz]")
      .def_property_readonly(
          "shape", [](const MapGrid& g) { return py::tuple(py::cast(grid_shape(g))); },
          "(nz, ny, nx): the shape of the arrays over the grid")
      .def_property_readonly(
          "axes",
          [](const MapGrid& g) {
            py::list l;
            for (int a = 0; a < 3; ++a) {
              Eigen::VectorXd v(g.dimensions[a]);
              for (int i = 0; i < g.dimensions[a]; ++i) v(i) = g.origin(a) + i * g.spacing(a);
              l.append(py::cast(v));
            }
            return py::tuple(l);
          },
          "(x, y, z): the coordinates (m) along each axis, for plotting")
      .def("num_points", &MapGrid::num_points)
      .def("num_varying_axes", &MapGrid::num_varying_axes)
      .def("cell_measure", &MapGrid::cell_measure, "m^2 (a plane) or m^3 (a box) per point")
      .def(
          "point",
          [](const MapGrid& g, long i) {
            check_index(i, static_cast<long>(g.num_points()), "MapGrid.point: index");
            return g.point(static_cast<size_t>(i));
          },
          py::arg("index"), "The point (m) of flat index i + nx (j + ny k).");
  m.def("map_axis_points", &map_axis_points, py::arg("range"), py::arg("step"),
        "Points along one axis of make_map_grid's grid (a float, to estimate before allocating).");
  m.def(
      "make_map_grid",
      [](const std::array<MapRange, 3>& ranges, double step, std::size_t max_points) {
        return unwrap(make_map_grid(ranges, step, max_points));
      },
      py::arg("ranges"), py::arg("step"), py::arg("max_points") = MapOptions{}.max_points,
      "The grid of ranges [x, y, z] (each (lo, hi) or one value, m) at `step` (m): lo, lo + step, ... InputError "
      "when a range is reversed or not finite, fewer than two ranges span the step, or the grid exceeds max_points.");
}

void bind_map(py::module_& m) {
  py::enum_<MapField>(m, "MapField",
                      "A map field; its name (field_info(f).name, e.g. 'k_t_min') is accepted wherever "
                      "a MapField is (docs/maps.md lists formulas and units).")
      .value("TRANSLATIONAL_MIN", MapField::kTranslationalMin)
      .value("TRANSLATIONAL_MAX", MapField::kTranslationalMax)
      .value("ROTATIONAL_MIN", MapField::kRotationalMin)
      .value("ROTATIONAL_MAX", MapField::kRotationalMax)
      .value("TRACE", MapField::kTrace)
      .value("NORM1", MapField::kNorm1)
      .value("NORM2", MapField::kNorm2)
      .value("NORM_FROBENIUS", MapField::kNormFrobenius)
      .value("NORM_INF", MapField::kNormInf)
      .value("CONDITION_NUMBER", MapField::kConditionNumber)
      .value("LOG10_DET", MapField::kLog10Det)
      .value("DEFLECTION_TRANSLATION", MapField::kDeflectionTranslation)
      .value("DEFLECTION_ROTATION", MapField::kDeflectionRotation)
      .value("SINGULARITY_MEASURE", MapField::kSingularityMeasure)
      .value("NEWTON_ITERATIONS", MapField::kNewtonIterations);
  py::class_<MapFieldInfo>(m, "MapFieldInfo")
      .def_readonly("name", &MapFieldInfo::name)
      .def_readonly("unit", &MapFieldInfo::unit, "SI")
      .def_readonly("description", &MapFieldInfo::description);
  m.def(
      "field_info", [](const MapFieldArg& f) { return field_info(map_field(f)); }, py::arg("field"),
      py::return_value_policy::reference);
  m.def("field_from_name", &field_from_name, py::arg("name"), "The MapField named 'k_t_min', ..., or None.");

  py::class_<FieldSummary>(m, "FieldSummary", "Over the points with a value: count, min, max, mean, argmin (m).")
      .def_readonly("count", &FieldSummary::count)
      .def_readonly("min", &FieldSummary::min)
      .def_readonly("max", &FieldSummary::max)
      .def_readonly("mean", &FieldSummary::mean)
      .def_readonly("argmin", &FieldSummary::argmin, "where the minimum is (m), the first in grid order");
  py::class_<MapOptions>(m, "MapOptions")
      .def(py::init<>())
      .def_readwrite("near_singular_threshold", &MapOptions::near_singular_threshold,
                     "points with values and singularity measure below this are NEAR_SINGULAR")
      .def_readwrite("min_stiffness", &MapOptions::min_stiffness, "N/m on k_t_min for stiff_measure, or None")
      .def_readwrite("with_deflection", &MapOptions::with_deflection, "the kernel carries a load: deflection fields")
      .def_readwrite("with_iterations", &MapOptions::with_iterations,
                     "the kernel iterates (loaded mode): the newton_iterations field")
      .def_readwrite("max_points", &MapOptions::max_points)
      .def_readwrite("threads", &MapOptions::threads, "0: all cores");
  py::class_<MapCurve>(m, "MapCurve", "Polylines (each an (n, 3) array, m) drawn over a map, e.g. a singular locus.")
      .def(py::init([](std::string label, const std::vector<RowsRef<3>>& lines) {
             MapCurve c{std::move(label), {}};
             for (const auto& l : lines) c.lines.push_back(from_rows<3>(l));
             return c;
           }),
           py::arg("label"), py::arg("lines"))
      .def_readonly("label", &MapCurve::label)
      .def_property_readonly("lines", [](const MapCurve& c) {
        py::list l;
        for (const auto& line : c.lines) l.append(rows(line));
        return l;
      });

  py::class_<WorkspaceMap>(m, "WorkspaceMap",
                           "A workspace stiffness map. Arrays have the grid's shape (nz, ny, nx), [k, j, i] at "
                           "origin + (i dx, j dy, k dz): a plane keeps its axis of one point (field(f)[0] for z = "
                           "const). Fields are NaN where a point has no value (unreachable; singular and failed "
                           "points keep only the singularity measure); status says why.")
      .def_readonly("grid", &WorkspaceMap::grid)
      .def_readonly("description", &WorkspaceMap::description, "the kernel's: robot, mode, method")
      .def_readonly("near_singular_threshold", &WorkspaceMap::near_singular_threshold)
      .def_readonly("min_stiffness", &WorkspaceMap::min_stiffness, "N/m or None")
      .def_readonly("reachable_measure", &WorkspaceMap::reachable_measure, "m^2 (a plane) or m^3 (a box)")
      .def_readonly("stiff_measure", &WorkspaceMap::stiff_measure, "m^2 or m^3 with k_t_min >= min_stiffness")
      .def_property_readonly("shape", [](const WorkspaceMap& w) { return py::tuple(py::cast(grid_shape(w.grid))); })
      .def_property_readonly(
          "status", [](const WorkspaceMap& w) { return grid_array<std::uint8_t>(w.grid, w.status); },
          "(nz, ny, nx) uint8, PostureStatus values")
      .def_property_readonly(
          "mask",
          [](const WorkspaceMap& w) {
            std::vector<bool> none;
            for (PostureStatus s : w.status) none.push_back(!has_values(s));
            return grid_array<bool>(w.grid, none);
          },
          "(nz, ny, nx) bool, True where the point has no stiffness values (for numpy.ma)")
      .def(
          "field",
          [](const WorkspaceMap& w, const MapFieldArg& f) {
            return grid_array<double>(w.grid, map_field_values(w, map_field(f)).values);
          },
          py::arg("field"), "(nz, ny, nx) float64 in SI units (field_info(f).unit), NaN where no value.")
      .def(
          "summary",
          [](const WorkspaceMap& w, const MapFieldArg& f) { return map_field_values(w, map_field(f)).summary; },
          py::arg("field"))
      .def_property_readonly(
          "field_names",
          [](const WorkspaceMap& w) {
            std::vector<std::string> names;
            for (const FieldValues& f : w.fields) names.emplace_back(field_info(f.field).name);
            return names;
          },
          "the fields this map has")
      .def_property_readonly(
          "status_counts",
          [](const WorkspaceMap& w) {
            py::dict d;
            for (int s = 0; s < kNumPostureStatuses; ++s)
              d[to_string(static_cast<PostureStatus>(s))] = w.status_counts[s];
            return d;
          },
          "{'ok': n, 'unreachable': n, ...}")
      .def_readwrite("curves", &WorkspaceMap::curves, "curves drawn over the map in its JSON and PNG (MapCurve list)");
  m.def(
      "compute_workspace_map",
      [](const PostureKernel& kernel, const MapGrid& grid, MapOptions options) {
        if (is_python_kernel(kernel)) options.threads = 1;  // it takes the GIL for every point
        return unwrap(without_gil([&] { return compute_workspace_map(kernel, grid, options); }));
      },
      py::arg("kernel"), py::arg("grid"), py::arg("options") = MapOptions{},
      "The kernel at every grid point (on options.threads threads, a Python kernel on one; the GIL released) and "
      "the fields, statuses and summary. InputError when the grid is empty or above options.max_points.");

  m.def(
      "five_bar_singular_loci",
      [](const FiveBarParams& p, WorkingMode mode, Assembly a, int samples) {
        check(validate(p));
        check(check_loci_samples(samples));
        return without_gil([&] { return five_bar_singular_loci(p, mode, a, samples); });
      },
      py::arg("params"), py::arg("mode"), py::arg("assembly"), py::arg("samples") = 4096,
      "[workspace boundary, parallel singularity] of a working and assembly mode as MapCurves (m, z = 0), as "
      "`kinestat map fivebar` draws them. InputError for bad parameters or samples outside 8..1e6.");
  m.def(
      "five_bar_workspace_box",
      [](const FiveBarParams& p, WorkingMode mode, Assembly a) {
        const Box2 b = unwrap(five_bar_workspace_box(p, mode, a));
        return py::make_tuple(b.min, b.max);
      },
      py::arg("params"), py::arg("mode"), py::arg("assembly"),
      "(min, max) corners (m) of the region of the working/assembly mode. InputError when it reaches nothing.");
}

void bind_design_sweep(py::module_& m) {
  py::class_<FiveBarDesignSweepOptions>(m, "FiveBarDesignSweepOptions",
                                        "A sweep of the five-bar's link lengths r1 x r2 over a fixed region of P.")
      .def(py::init<>())
      .def_readwrite("base", &FiveBarDesignSweepOptions::base, "FiveBarKernelOptions: all but r1, r2")
      .def_readwrite("r1", &FiveBarDesignSweepOptions::r1, "MapRange (m)")
      .def_readwrite("r2", &FiveBarDesignSweepOptions::r2, "MapRange (m)")
      .def_readwrite("steps", &FiveBarDesignSweepOptions::steps, "designs per swept length")
      .def_readwrite("region", &FiveBarDesignSweepOptions::region, "MapGrid of P (make_map_grid, z = 0)")
      .def_readwrite("near_singular_threshold", &FiveBarDesignSweepOptions::near_singular_threshold)
      .def_readwrite("min_stiffness", &FiveBarDesignSweepOptions::min_stiffness, "N/m on k_t_min, or None")
      .def_readwrite("threads", &FiveBarDesignSweepOptions::threads, "0: all cores");
  py::class_<FiveBarDesignResult>(m, "FiveBarDesignResult",
                                  "One design's region points: reachable >= singularity_free >= stiff.")
      .def_readonly("r1", &FiveBarDesignResult::r1, "m")
      .def_readonly("r2", &FiveBarDesignResult::r2, "m")
      .def_readonly("reachable", &FiveBarDesignResult::reachable)
      .def_readonly("singularity_free", &FiveBarDesignResult::singularity_free)
      .def_readonly("stiff", &FiveBarDesignResult::stiff)
      .def_readonly("k_t_min_worst", &FiveBarDesignResult::k_t_min_worst, "N/m, NaN: no singularity-free point");
  m.def("better_design", &better_design, py::arg("a"), py::arg("b"));
  auto shares = [](std::size_t FiveBarDesignResult::*count) {
    return [count](const FiveBarDesignSweep& s) {
      return design_array(s, [&](const FiveBarDesignResult& r) { return s.share(r.*count); });
    };
  };
  py::class_<FiveBarDesignSweep>(m, "FiveBarDesignSweep",
                                 "Every design's shares of the region. Arrays have shape (ny, nx) = (r2 steps, r1 "
                                 "steps): [j, i] is design i + nx j.")
      .def_readonly("designs", &FiveBarDesignSweep::designs, "MapGrid: x = r1, y = r2 (m)")
      .def_readonly("region", &FiveBarDesignSweep::region)
      .def_readonly("description", &FiveBarDesignSweep::description)
      .def_readonly("near_singular_threshold", &FiveBarDesignSweep::near_singular_threshold)
      .def_readonly("min_stiffness", &FiveBarDesignSweep::min_stiffness, "N/m or None")
      .def_readonly("results", &FiveBarDesignSweep::results, "FiveBarDesignResult per design, r1 fastest")
      .def_readonly("best", &FiveBarDesignSweep::best, "index of the best design (better_design)")
      .def_property_readonly("best_design", [](const FiveBarDesignSweep& s) { return s.results.at(s.best); })
      .def_property_readonly(
          "r1",
          [](const FiveBarDesignSweep& s) {
            return design_array(s, [](const FiveBarDesignResult& r) { return r.r1; });
          },
          "(ny, nx) m")
      .def_property_readonly(
          "r2",
          [](const FiveBarDesignSweep& s) {
            return design_array(s, [](const FiveBarDesignResult& r) { return r.r2; });
          },
          "(ny, nx) m")
      .def_property_readonly("reachable_share", shares(&FiveBarDesignResult::reachable), "(ny, nx) in [0, 1]")
      .def_property_readonly("singularity_free_share", shares(&FiveBarDesignResult::singularity_free), "(ny, nx)")
      .def_property_readonly("share", shares(&FiveBarDesignResult::stiff), "(ny, nx): the design criterion")
      .def_property_readonly(
          "k_t_min_worst",
          [](const FiveBarDesignSweep& s) {
            return design_array(s, [](const FiveBarDesignResult& r) { return r.k_t_min_worst; });
          },
          "(ny, nx) N/m, NaN where no point is singularity-free");
  m.def(
      "sweep_five_bar_designs",
      [](const FiveBarDesignSweepOptions& o) {
        check(check_size(static_cast<double>(o.region.num_points()), static_cast<double>(MapOptions{}.max_points),
                         "the region", "points", "use a larger step"));
        return unwrap(without_gil([&] { return sweep_five_bar_designs(o); }));
      },
      py::arg("options"),
      "A workspace map of the region for every design (the GIL released), reduced to its shares; the best design "
      "is the one `kinestat design fivebar` picks. InputError naming a bad range, step count or region.");
}

}  // namespace

MapField map_field(const MapFieldArg& f) {
  if (const auto* field = std::get_if<MapField>(&f)) return *field;
  const std::string& name = std::get<std::string>(f);
  if (const auto field = field_from_name(name)) return *field;
  raise_status(Status::Invalid(fmt::format("field '{}' is not a map field; use one of {}", name, field_names())));
}

void bind_workspace_maps(py::module_& m) {
  bind_grid(m);
  bind_map(m);
  bind_design_sweep(m);
}

}  // namespace kinestat::python
