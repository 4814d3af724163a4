// Where write_png_map/write_png_sheet put things on the page: computed from the field extents and
// the image size alone, before PLplot draws, so that tests can map plot units to pixels.
#pragma once

#include <vector>

#include "kinestat/io/map_png.hpp"

namespace kinestat::io {

// A rectangle in normalized page coordinates (0..1, y up), as PLplot's plvpor takes it.
struct PageBox {
  double x0 = 0.0, x1 = 0.0, y0 = 0.0, y1 = 0.0;
};

// A rectangle in plot units (the data window of a panel).
struct PlotWindow {
  double x0 = 0.0, x1 = 0.0, y0 = 0.0, y1 = 0.0;
};

struct MapPngLayout {
  double char_px = 0.0;             // height of the text in pixels
  std::vector<PageBox> panels;      // plot area (inside the frame) of each field
  std::vector<PlotWindow> windows;  // plot units at the edges of each panel: the extent of the cells
  PageBox colorbar;                 // the colour bar, beside the panels
  PageBox legend;                   // band under the panels for the curves' legend (zero height: none)
};

// The window of a field: cell i spans x0 + (i -+ 1/2) dx, so the grid points are cell centres.
PlotWindow field_window(const PlotField2D& field);

// Panels on the grid of columns that draws them largest, all at one scale, the same on both axes
// (plot units are lengths on both axes), each centred in its cell; one colour bar on the right; the
// legend at the bottom.
MapPngLayout map_png_layout(const std::vector<PlotField2D>& fields, const PlotOptions& options);

// Pixel (column, row from the top) of the point (x, y) in plot units on panel `k`; the centre of
// pixel (c, r) is at (c + 0.5, r + 0.5).
struct PixelPoint {
  double col = 0.0, row = 0.0;
};
PixelPoint plot_to_pixel(const MapPngLayout& layout, int k, double x, double y, const PlotOptions& options);

}  // namespace kinestat::io
