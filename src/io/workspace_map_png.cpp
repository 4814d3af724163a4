#include "kinestat/io/workspace_map_png.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <fmt/format.h>

#include "kinestat/core/units.hpp"
#include "kinestat/io/map_png.hpp"

namespace kinestat::io {
namespace {

using namespace mechanisms;

using units::kDeg;
using units::kMm;
using units::kNMm;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();  // breaks a plotted line

// "x -100:100 mm", "x = 0 mm" or "rx -10:10 deg" for axis i of a grid.
std::string axis_text(const MapGrid& g, int i) {
  const UnitDisplay u = axis_display(g, i);
  const double lo = g.origin(i) * u.scale, hi = (g.origin(i) + (g.dimensions[i] - 1) * g.spacing(i)) * u.scale;
  return lo == hi ? fmt::format("{} = {:g} {}", g.names[i], lo, u.unit)
                  : fmt::format("{} {:g}:{:g} {}", g.names[i], lo, hi, u.unit);
}

// The picture's plane: axes a (across) and b (up), the slicing axis c, and the slices drawn (at
// most nine panels, spread over the grid's slices).
struct PngPlanes {
  int a = 0, b = 1, c = 2;
  std::vector<int> slices;
};

PngPlanes png_planes(const MapGrid& g) {
  PngPlanes p;
  if (g.num_varying_axes() == 2) {
    if (g.dimensions[0] == 1)
      p.a = 1, p.b = 2, p.c = 0;
    else if (g.dimensions[1] == 1)
      p.a = 0, p.b = 2, p.c = 1;
  }
  const int nc = g.dimensions[p.c];
  constexpr int kMaxPanels = 9;
  for (int k = 0; k < std::min(nc, kMaxPanels); ++k)
    p.slices.push_back(nc <= kMaxPanels ? k : static_cast<int>(std::lround(k * (nc - 1.0) / (kMaxPanels - 1))));
  return p;
}

}  // namespace

std::string workspace_map_png_title(const WorkspaceMap& map, MapField field) {
  const MapGrid& g = map.grid;
  const PngPlanes p = png_planes(g);
  std::string title = fmt::format("{}: {}", map.description, field_info(field).name);
  // Which part of the grid the picture is: the fixed coordinate of a slice, the slices of a sheet.
  const int nc = g.dimensions[p.c];
  if (nc == 1 && g.num_varying_axes() == 2) title += fmt::format(", slice {}", axis_text(g, p.c));
  if (nc > 1) title += fmt::format("\n{} of the {} slices {}", p.slices.size(), nc, axis_text(g, p.c));
  return title;
}

MapFieldDisplay map_field_display(MapField f) {
  switch (f) {
    case MapField::kTranslationalMin:
    case MapField::kTranslationalMax:
      return {"N/mm", kMm};
    case MapField::kRotationalMin:
    case MapField::kRotationalMax:
      return {"N mm/deg", kDeg / kNMm};
    case MapField::kDeflectionTranslation:
      return {"mm", 1.0 / kMm};
    case MapField::kDeflectionRotation:
      return {"deg", 1.0 / kDeg};
    default:
      return {field_info(f).unit, 1.0};
  }
}

Status write_workspace_map_png(const std::string& path, const WorkspaceMap& map, MapField field) {
  const FieldValues* found = map.find(field);
  if (found == nullptr)
    return Status::Invalid(
        fmt::format("{}: the map has no field {} (the deflections need a load, the iterations the "
                    "loaded mode)",
                    path, field_info(field).name));
  const MapGrid& g = map.grid;
  const PngPlanes planes = png_planes(g);
  const int a = planes.a, b = planes.b, c = planes.c;
  const MapFieldDisplay d = map_field_display(field);
  const std::vector<double>& values = found->values;
  const std::vector<int>& slices = planes.slices;
  const int nc = g.dimensions[c];
  const std::size_t stride[3] = {1, static_cast<std::size_t>(g.dimensions[0]),
                                 static_cast<std::size_t>(g.dimensions[0]) * g.dimensions[1]};
  const UnitDisplay ua = axis_display(g, a), ub = axis_display(g, b), uc = axis_display(g, c);
  // Slice k of a field's values, in plot units.
  const auto slice = [&](const std::vector<double>& field_values, double scale, int k) {
    PlotField2D p;
    p.nx = g.dimensions[a];
    p.ny = g.dimensions[b];
    p.x0 = g.origin(a) * ua.scale;
    p.y0 = g.origin(b) * ub.scale;
    p.dx = g.spacing(a) * ua.scale;
    p.dy = g.spacing(b) * ub.scale;
    p.values.resize(static_cast<std::size_t>(p.nx) * p.ny);
    for (int j = 0; j < p.ny; ++j)
      for (int i = 0; i < p.nx; ++i)
        p.values[i + static_cast<std::size_t>(p.nx) * j] =
            field_values[i * stride[a] + j * stride[b] + k * stride[c]] * scale;
    return p;
  };
  // The border of the region stiffer than --min-stiffness: the k_t_min = K contour, whatever field
  // is drawn (one legend entry; the lines differ per slice).
  const FieldValues* kt = map.find(MapField::kTranslationalMin);
  const bool contour = map.min_stiffness.has_value() && kt != nullptr;
  std::vector<PlotField2D> panels;
  for (int k : slices) {
    PlotField2D p = slice(values, d.scale, k);
    if (nc > 1) p.title = fmt::format("{} = {:g} {}", g.names[c], (g.origin(c) + k * g.spacing(c)) * uc.scale, uc.unit);
    if (contour)
      p.curves.push_back({contour_lines(slice(kt->values, 1.0, k), *map.min_stiffness), "", CurveStyle::kDashedRed});
    panels.push_back(std::move(p));
  }
  PlotOptions o;
  const char* name = field_info(field).name;
  o.title = workspace_map_png_title(map, field);
  o.x_label = fmt::format("{} ({})", g.names[a], ua.unit);
  o.y_label = fmt::format("{} ({})", g.names[b], ub.unit);
  o.colorbar_label = fmt::format("{} ({})", name, d.unit);
  o.log_scale = field == MapField::kConditionNumber;
  for (std::size_t i = 0; i < map.curves.size(); ++i) {
    PlotCurve curve;
    curve.label = map.curves[i].label;
    constexpr CurveStyle kCycle[] = {CurveStyle::kSolidBlack, CurveStyle::kDashedRed, CurveStyle::kShortDashedMagenta};
    curve.style = kCycle[i % 3];
    for (const std::vector<Vec3>& line : map.curves[i].lines) {
      if (!curve.points.empty()) curve.points.push_back({kNaN, kNaN});
      for (const Vec3& q : line) curve.points.push_back({q(a) * ua.scale, q(b) * ub.scale});
    }
    o.curves.push_back(std::move(curve));
  }
  if (contour)  // the legend's entry; the lines are the panels'
    o.curves.push_back(
        {{}, fmt::format("k_t_min = {:g} N/mm (--min-stiffness)", *map.min_stiffness * kMm), CurveStyle::kDashedRed});
  if (panels.size() == 1) return write_png_map(path, panels.front(), o);
  return write_png_sheet(path, panels, o);
}

std::string design_sweep_criteria(const FiveBarDesignSweep& s) {
  return fmt::format("singularity measure >= {:g}{}", s.near_singular_threshold,
                     s.min_stiffness ? fmt::format(", k_t_min >= {:g} N/mm", *s.min_stiffness * kMm) : std::string());
}

Status write_design_sweep_png(const std::string& path, const FiveBarDesignSweep& s) {
  if (s.results.empty() || s.best >= s.results.size())
    return Status::Invalid(fmt::format("{}: the design sweep has no designs to draw", path));
  const MapGrid& g = s.designs;
  PlotField2D f;
  f.nx = g.dimensions[0], f.ny = g.dimensions[1];
  f.x0 = g.origin.x() / kMm, f.y0 = g.origin.y() / kMm;
  f.dx = g.spacing.x() / kMm, f.dy = g.spacing.y() / kMm;
  for (const auto& r : s.results) f.values.push_back(100.0 * s.share(r.stiff));
  PlotOptions o;
  o.title = fmt::format("{} design sweep: share of {}, {}\nreached with {}", s.description, axis_text(s.region, 0),
                        axis_text(s.region, 1), design_sweep_criteria(s));
  o.x_label = "r1 (mm)";
  o.y_label = "r2 (mm)";
  o.colorbar_label = "share of the region (%)";
  o.colour_range = {0.0, 100.0};  // shares of different runs compare
  const auto& b = s.results[s.best];
  const double x = b.r1 / kMm, y = b.r2 / kMm;
  o.curves.push_back(
      {{{x - 0.4 * f.dx, y}, {x + 0.4 * f.dx, y}, {kNaN, kNaN}, {x, y - 0.4 * f.dy}, {x, y + 0.4 * f.dy}},
       fmt::format("best design: r1 = {:.4g} mm, r2 = {:.4g} mm ({:.1f}% of the region)", x, y,
                   100.0 * s.share(b.stiff)),
       CurveStyle::kSolidBlack});
  return write_png_map(path, f, o);
}

}  // namespace kinestat::io
