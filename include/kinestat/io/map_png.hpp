// PNG pictures of maps (workspace stiffness maps, design maps) that a person reads without
// ParaView: a colour map of a scalar field on a regular grid with axes, units, a colour bar, curves
// drawn over it (workspace boundary, singular loci) and a title. Drawn by a plotting library.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "kinestat/core/status.hpp"

namespace kinestat::io {

// A scalar field on a regular 2D grid, x fastest: values[i + nx * j] at (x0 + i dx, y0 + j dy),
// in plot units (those the axis labels state). NaN where there is no value (drawn blank).
// How a curve is drawn; no colour is one of viridis's.
enum class CurveStyle { kSolidBlack, kDashedRed, kShortDashedMagenta };

// A polyline in plot units drawn over the field; a NaN point breaks the line.
struct PlotCurve {
  std::vector<std::array<double, 2>> points;
  std::string label;  // legend entry ("workspace boundary", "parallel singularity")
  CurveStyle style = CurveStyle::kSolidBlack;
};

struct PlotField2D {
  int nx = 0, ny = 0;
  double x0 = 0.0, y0 = 0.0, dx = 1.0, dy = 1.0;
  std::vector<double> values;
  std::string title;              // of this panel (a slice "z = 10 mm" on a sheet); may be empty
  std::vector<PlotCurve> curves;  // drawn on this panel only (a contour of this slice); no legend
};

struct PlotOptions {
  std::string title;  // robot and mode, e.g. "five-bar ++ up: min translational stiffness"; '\n' breaks lines
  std::string x_label = "x (mm)";
  std::string y_label = "y (mm)";
  std::string colorbar_label;      // quantity and unit, e.g. "k_t,min (N/mm)"
  int width = 1000, height = 800;  // pixels of the whole image
  bool log_scale = false;          // colour scale in log10 (positive fields)
  // Fixed ends of the colour scale (plot units; values beyond take the end colours); default: the
  // range of the values.
  std::optional<std::array<double, 2>> colour_range;
  std::vector<PlotCurve> curves;
};

// The `level` contour of a field as polylines in plot units (NaN-separated), over the cells whose
// four corners have values only: the edge of a masked (NaN) region is no contour.
std::vector<std::array<double, 2>> contour_lines(const PlotField2D& field, double level);

// One map in one PNG. kInvalidInput (naming the path) when it cannot be written or the field is
// empty/inconsistent.
Status write_png_map(const std::string& path, const PlotField2D& field, const PlotOptions& options);

// Several panels (the slices of a 3D map) on one sheet with one common colour scale; each panel's
// title from PlotField2D::title, curves drawn on every panel.
Status write_png_sheet(const std::string& path, const std::vector<PlotField2D>& fields, const PlotOptions& options);

}  // namespace kinestat::io
