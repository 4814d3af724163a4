#include "io/map_png_layout.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace kinestat::io {

PlotWindow field_window(const PlotField2D& f) {
  return {f.x0 - 0.5 * f.dx, f.x0 + (f.nx - 0.5) * f.dx, f.y0 - 0.5 * f.dy, f.y0 + (f.ny - 0.5) * f.dy};
}

MapPngLayout map_png_layout(const std::vector<PlotField2D>& fields, const PlotOptions& options) {
  // Work in pixels with y down, convert to PLplot's normalized page coordinates at the end.
  const double W = options.width, H = options.height;
  MapPngLayout out;
  const double f = std::clamp(0.021 * std::min(W, H), 9.0, 48.0);
  out.char_px = f;
  const int n = static_cast<int>(fields.size());
  if (n == 0) return out;

  // Bands: title on top, colour bar and its labels on the right, legend at the bottom.
  // The title's lines are 1.25 f high, 1.6 line heights apart.
  const auto title_lines = options.title.empty() ? 0 : 1 + std::count(options.title.begin(), options.title.end(), '\n');
  const double top = f + 2.0 * f * static_cast<double>(title_lines);
  const double right = 11.0 * f;
  const double legend = options.curves.empty() ? 0.0 : 2.8 * f;
  // Inside a cell: y tick labels and axis label on the left, x ones below, the panel title above.
  const bool panel_titles = std::any_of(fields.begin(), fields.end(), [](const auto& p) { return !p.title.empty(); });
  const double m_left = 7.0 * f, m_right = 1.0 * f, m_bottom = 4.5 * f, m_top = panel_titles ? 2.2 * f : 1.0 * f;
  for (const PlotField2D& field : fields) out.windows.push_back(field_window(field));

  // Scale (pixels per plot unit) of the panels on a grid of `c` columns: the largest that fits every
  // panel in its cell. The sheet takes the number of columns with the largest scale.
  auto cell = [&](int c) { return std::array<double, 2>{(W - right) / c, (H - top - legend) / ((n + c - 1) / c)}; };
  auto scale = [&](int c) {
    const auto [cw, ch] = cell(c);
    const double aw = std::max(cw - m_left - m_right, 1.0), ah = std::max(ch - m_top - m_bottom, 1.0);
    double s = std::numeric_limits<double>::infinity();
    for (const PlotWindow& w : out.windows) s = std::min({s, aw / (w.x1 - w.x0), ah / (w.y1 - w.y0)});
    return s;
  };
  int cols = 1;
  for (int c = 2; c <= n; ++c)
    if (scale(c) > scale(cols)) cols = c;
  const double s = scale(cols);
  const auto [cell_w, cell_h] = cell(cols);
  const double avail_w = std::max(cell_w - m_left - m_right, 1.0), avail_h = std::max(cell_h - m_top - m_bottom, 1.0);

  double ux0 = W, ux1 = 0.0, uy0 = H, uy1 = 0.0;  // union of the panels, pixels
  for (int k = 0; k < n; ++k) {
    // Same scale on both axes and in every panel: a workspace is drawn undistorted.
    const PlotWindow& win = out.windows[k];
    const double bw = (win.x1 - win.x0) * s, bh = (win.y1 - win.y0) * s;
    const double cx = (k % cols) * cell_w + m_left + 0.5 * (avail_w - bw);
    const double cy = top + (k / cols) * cell_h + m_top + 0.5 * (avail_h - bh);
    out.panels.push_back({cx / W, (cx + bw) / W, 1.0 - (cy + bh) / H, 1.0 - cy / H});
    ux0 = std::min(ux0, cx), ux1 = std::max(ux1, cx + bw), uy0 = std::min(uy0, cy), uy1 = std::max(uy1, cy + bh);
  }
  const double bar_x = ux1 + 2.0 * f, bar_w = 1.6 * f;
  out.colorbar = {bar_x / W, (bar_x + bar_w) / W, 1.0 - uy1 / H, 1.0 - uy0 / H};
  const double legend_top = uy1 + m_bottom;
  out.legend = {ux0 / W, ux1 / W, 1.0 - (legend_top + legend) / H, 1.0 - legend_top / H};
  return out;
}

PixelPoint plot_to_pixel(const MapPngLayout& layout, int k, double x, double y, const PlotOptions& options) {
  const PageBox& b = layout.panels[k];
  const PlotWindow& w = layout.windows[k];
  const double u = b.x0 + (x - w.x0) / (w.x1 - w.x0) * (b.x1 - b.x0);
  const double v = b.y0 + (y - w.y0) / (w.y1 - w.y0) * (b.y1 - b.y0);
  return {u * options.width, (1.0 - v) * options.height};
}

}  // namespace kinestat::io
