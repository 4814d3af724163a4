// PNG maps drawn by PLplot's cairo driver ("pngcairo"). PLplot keeps its state in globals (the
// current stream, the abort handler): every picture is drawn under one mutex, in a stream of its
// own that plend1 frees.
#include "kinestat/io/map_png.hpp"

#include <plplot.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <mutex>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <vtkCellType.h>
#include <vtkContourFilter.h>
#include <vtkDoubleArray.h>
#include <vtkIdList.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStripper.h>
#include <vtkUnstructuredGrid.h>

#include "io/map_png_layout.hpp"
#include "kinestat/core/atomic_file.hpp"

namespace kinestat::io {
namespace {

// Colour map 0 (lines, text, fills), by index.
enum Colour : PLINT { kBackground = 0, kBlack, kRed, kMagenta, kNoValue, kColourCount };
constexpr std::array<PLINT, kColourCount> kRed8 = {255, 0, 220, 255, 222};
constexpr std::array<PLINT, kColourCount> kGreen8 = {255, 0, 20, 0, 222};
constexpr std::array<PLINT, kColourCount> kBlue8 = {255, 0, 20, 255, 222};

// Colour map 1: viridis (perceptually uniform, readable in grey and by colour-blind readers), its
// eleven tabulated colours at 0, 0.1, ..., 1.
constexpr int kViridisPoints = 11;
constexpr std::array<unsigned, kViridisPoints> kViridis = {0x440154, 0x482475, 0x414487, 0x355f8d, 0x2a788e, 0x21918c,
                                                           0x22a884, 0x44bf70, 0x7ad151, 0xbddf26, 0xfde725};

struct CurvePen {
  PLINT colour, line_style;  // line_style: PLplot's predefined patterns (pllsty): 1 solid, 2 short dashes, 3 long
};
CurvePen curve_pen(CurveStyle style) {
  switch (style) {
    case CurveStyle::kDashedRed:
      return {kRed, 3};
    case CurveStyle::kShortDashedMagenta:
      return {kMagenta, 2};
    case CurveStyle::kSolidBlack:
      break;
  }
  return {kBlack, 1};
}

std::mutex& plplot_mutex() {
  static std::mutex m;
  return m;
}

// PLplot reports recoverable errors through the abort handler (global, set under the mutex).
std::string* g_plplot_errors = nullptr;
void record_plplot_error(const char* message) {
  if (g_plplot_errors == nullptr) return;
  if (!g_plplot_errors->empty()) *g_plplot_errors += "; ";
  *g_plplot_errors += message;
}

// PLplot reads '#' as the start of an escape sequence.
std::string escape_text(const std::string& s) {
  std::string out;
  for (char c : s) {
    out += c;
    if (c == '#') out += '#';
  }
  return out;
}

Status check_input(const std::string& path, const std::vector<PlotField2D>& fields, const PlotOptions& o) {
  constexpr int kMaxPixels = 8192;  // per side: the cairo surface is 4 bytes per pixel
  if (o.width < 200 || o.height < 150 || o.width > kMaxPixels || o.height > kMaxPixels)
    return Status::Invalid(
        fmt::format("{}: image size {} x {} pixels: width must lie in [200, {}], height in "
                    "[150, {}]",
                    path, o.width, o.height, kMaxPixels, kMaxPixels));
  if (fields.empty()) return Status::Invalid(path + ": no field to draw");
  constexpr long long kMaxCells = 1LL << 26;
  bool any_value = false;
  for (std::size_t k = 0; k < fields.size(); ++k) {
    const PlotField2D& f = fields[k];
    const std::string which = fields.size() > 1 ? fmt::format(" (panel {})", k + 1) : std::string();
    if (f.nx < 1 || f.ny < 1 || static_cast<long long>(f.nx) * f.ny > kMaxCells)
      return Status::Invalid(
          fmt::format("{}{}: grid {} x {}: needs 1 to {} cells", path, which, f.nx, f.ny, kMaxCells));
    if (f.values.size() != static_cast<std::size_t>(f.nx) * static_cast<std::size_t>(f.ny))
      return Status::Invalid(
          fmt::format("{}{}: {} values for a {} x {} grid", path, which, f.values.size(), f.nx, f.ny));
    if (!(std::isfinite(f.x0) && std::isfinite(f.y0) && std::isfinite(f.dx) && std::isfinite(f.dy) && f.dx > 0.0 &&
          f.dy > 0.0))
      return Status::Invalid(
          fmt::format("{}{}: grid origin ({}, {}) and spacing ({}, {}) must be finite, spacing "
                      "positive",
                      path, which, f.x0, f.y0, f.dx, f.dy));
    for (std::size_t i = 0; i < f.values.size(); ++i) {
      const double v = f.values[i];
      if (std::isnan(v)) continue;
      if (!std::isfinite(v) || (o.log_scale && v <= 0.0))
        return Status::Invalid(
            fmt::format("{}{}: value {} at ({}, {}){}", path, which, v, f.x0 + f.dx * static_cast<double>(i % f.nx),
                        f.y0 + f.dy * static_cast<double>(i / f.nx),
                        std::isinf(v) ? ": an infinite value (a rigid direction) has no colour; draw another field"
                        : o.log_scale ? ": a log colour scale needs positive values (NaN: no value)"
                                      : ": must be finite (NaN: no value)"));
      any_value = true;
    }
  }
  if (!any_value) return Status::Invalid(path + ": the field has no value to draw (all NaN)");
  if (o.colour_range) {
    const auto [lo, hi] = *o.colour_range;
    if (!(std::isfinite(lo) && std::isfinite(hi) && lo < hi && (!o.log_scale || lo > 0.0)))
      return Status::Invalid(fmt::format("{}: colour range [{}, {}] must be finite and increasing{}", path, lo, hi,
                                         o.log_scale ? ", positive on a log scale" : ""));
  }
  for (const PlotCurve& c : o.curves)
    for (const auto& p : c.points)
      if (std::isinf(p[0]) || std::isinf(p[1]))
        return Status::Invalid(fmt::format("{}: curve '{}' has an infinite point (NaN breaks a line)", path, c.label));
  return Status::Ok();
}

// The colour scale: the range of the finite values of all fields (log10 of them on a log scale),
// widened when the field is constant so that the colour bar has an extent.
std::array<double, 2> colour_range(const std::vector<PlotField2D>& fields, const PlotOptions& o) {
  const bool log_scale = o.log_scale;
  if (o.colour_range) {
    const auto [lo, hi] = *o.colour_range;
    return log_scale ? std::array<double, 2>{std::log10(lo), std::log10(hi)} : *o.colour_range;
  }
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const PlotField2D& f : fields)
    for (double v : f.values)
      if (!std::isnan(v)) {
        const double c = log_scale ? std::log10(v) : v;
        lo = std::min(lo, c), hi = std::max(hi, c);
      }
  if (hi - lo <= 1e-12 * std::max(std::abs(lo), std::abs(hi))) {
    const double pad = lo == 0.0 ? 1.0 : 0.5 * std::abs(lo);
    lo -= pad, hi += pad;
  }
  return {lo, hi};
}

// Index space (i, j) of plimagefr's corners to plot units.
void cell_corner_transform(PLFLT i, PLFLT j, PLFLT* x, PLFLT* y, PLPointer data) {
  const auto* c = static_cast<const PlotWindow*>(data);
  *x = c->x0 + i * c->x1;
  *y = c->y0 + j * c->y1;
}

void draw_field(const PlotField2D& f, const PlotWindow& w, bool log_scale, const std::array<double, 2>& range) {
  // No value: the light grey of the whole panel shows through (plimagefr skips data outside
  // [zmin, zmax], and -inf is outside).
  plcol0(kNoValue);
  const std::array<PLFLT, 4> xs = {w.x0, w.x1, w.x1, w.x0}, ys = {w.y0, w.y0, w.y1, w.y1};
  plfill(4, xs.data(), ys.data());
  // plimagefr takes data[ix][iy]: transpose the x-fastest values.
  std::vector<PLFLT> data(f.values.size());
  std::vector<const PLFLT*> columns(f.nx);
  for (int i = 0; i < f.nx; ++i) {
    columns[i] = data.data() + static_cast<std::size_t>(i) * f.ny;
    for (int j = 0; j < f.ny; ++j) {
      const double v = f.values[i + static_cast<std::size_t>(f.nx) * j];
      data[static_cast<std::size_t>(i) * f.ny + j] =
          std::isnan(v) ? -std::numeric_limits<double>::infinity() : (log_scale ? std::log10(v) : v);
    }
  }
  // Cell corners through a transform of our own: without one, PLplot 5.15 spreads the cells over
  // (xmax - xmin) / (nx - 1), not / nx.
  PlotWindow cell_corners = w;  // x0, y0: corner of cell (0, 0); x1, y1: the cell size
  cell_corners.x1 = f.dx, cell_corners.y1 = f.dy;
  constexpr double kAll = std::numeric_limits<double>::max();  // every finite value is drawn, clamped to the range
  plimagefr(columns.data(), f.nx, f.ny, w.x0, w.x1, w.y0, w.y1, -kAll, kAll, range[0], range[1], cell_corner_transform,
            &cell_corners);
}

// A tick spacing of 1, 2 or 5 times a power of ten that leaves `label_px` pixels per label along
// `length_px` pixels of an axis spanning `range` plot units (PLplot's own choice ignores the room).
double tick_step(double range, double length_px, double label_px) {
  const double max_ticks = std::max(2.0, std::floor(length_px / label_px));
  const double raw = range / max_ticks;
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0})
    if (m * decade >= raw) return m * decade;
  return 10.0 * decade;
}

void draw_curves(const std::vector<PlotCurve>& curves, double line_width) {
  for (const PlotCurve& c : curves) {
    const CurvePen s = curve_pen(c.style);
    plcol0(s.colour);
    pllsty(s.line_style);
    plwidth(line_width);
    // A NaN point ends one polyline and starts the next.
    std::vector<PLFLT> xs, ys;
    auto flush = [&] {
      if (xs.size() >= 2) plline(static_cast<PLINT>(xs.size()), xs.data(), ys.data());
      xs.clear(), ys.clear();
    };
    for (const auto& p : c.points) {
      if (std::isnan(p[0]) || std::isnan(p[1])) {
        flush();
        continue;
      }
      xs.push_back(p[0]), ys.push_back(p[1]);
    }
    flush();
  }
  pllsty(1);
  plwidth(1.0);
}

void draw_colorbar(const PageBox& box, const std::string& label, bool log_scale, const std::array<double, 2>& range) {
  plvpor(box.x0, box.x1, box.y0, box.y1);
  plwind(0.0, 1.0, 0.0, 1.0);
  constexpr int kSteps = 256;
  std::vector<PLFLT> values(kSteps);
  for (int i = 0; i < kSteps; ++i) values[i] = range[0] + (range[1] - range[0]) * i / (kSteps - 1);
  const PLFLT* value_rows[] = {values.data()};
  const PLINT n_values[] = {kSteps};
  const std::string text = escape_text(label);
  const char* labels[] = {text.c_str()};
  const PLINT label_opts[] = {PL_COLORBAR_LABEL_RIGHT};
  // 'l': labels 10^n on a log scale; 'm': numbers on the right; 'v': written horizontally.
  const char* axis_opts[] = {log_scale ? "bcvtml" : "bcvtm"};
  const PLFLT ticks[] = {0.0};
  const PLINT sub_ticks[] = {0};
  PLFLT width = 0.0, height = 0.0;
  plcolorbar(&width, &height, PL_COLORBAR_IMAGE, PL_POSITION_LEFT | PL_POSITION_INSIDE | PL_POSITION_VIEWPORT, 0.0, 0.0,
             1.0, 1.0, kBackground, kBlack, 1, 0.0, 0.0, kBlack, 1.0, label.empty() ? 0 : 1, label_opts, labels, 1,
             axis_opts, ticks, sub_ticks, n_values, value_rows);
}

void draw_legend(const PageBox& box, const std::vector<PlotCurve>& curves, double line_width) {
  plvpor(box.x0, box.x1, box.y0, box.y1);
  plwind(0.0, 1.0, 0.0, 1.0);
  const auto n = static_cast<PLINT>(curves.size());
  std::vector<std::string> texts;
  std::vector<const char*> text_ptrs;
  std::vector<PLINT> opts(n, PL_LEGEND_LINE), text_colours(n, kBlack), line_colours, line_styles;
  std::vector<PLFLT> line_widths(n, line_width);
  for (const PlotCurve& c : curves) texts.push_back(escape_text(c.label));
  for (const std::string& t : texts) text_ptrs.push_back(t.c_str());
  for (const PlotCurve& c : curves) {
    line_colours.push_back(curve_pen(c.style).colour);
    line_styles.push_back(curve_pen(c.style).line_style);
  }
  PLFLT width = 0.0, height = 0.0;
  pllegend(&width, &height, PL_LEGEND_BACKGROUND | PL_LEGEND_BOUNDING_BOX,
           PL_POSITION_TOP | PL_POSITION_INSIDE | PL_POSITION_VIEWPORT, 0.0, 0.0, 0.07, kBackground, kBlack, 1, 1, n, n,
           opts.data(), 1.0, 1.0, 2.0, 0.0, text_colours.data(), text_ptrs.data(), nullptr, nullptr, nullptr, nullptr,
           line_colours.data(), line_styles.data(), line_widths.data(), nullptr, nullptr, nullptr, nullptr);
}

// Draws the whole picture into the current (initialized) stream.
void draw(const std::vector<PlotField2D>& fields, const PlotOptions& o, const MapPngLayout& layout) {
  // Text height: PLplot's default is in mm; scale it to the layout's pixel height.
  PLFLT def_mm = 0.0, height_mm = 0.0, page_x0 = 0.0, page_x1 = 0.0, page_y0 = 0.0, page_y1 = 0.0;
  plgchr(&def_mm, &height_mm);
  plgspa(&page_x0, &page_x1, &page_y0, &page_y1);
  const double px_per_mm = o.width / (page_x1 - page_x0);
  const double text_scale = layout.char_px / (height_mm * px_per_mm);
  plschr(0.0, text_scale);
  const double line_width = std::max(1.0, layout.char_px / 7.0);
  const std::array<double, 2> range = colour_range(fields, o);

  for (std::size_t k = 0; k < fields.size(); ++k) {
    const PageBox& b = layout.panels[k];
    const PlotWindow& w = layout.windows[k];
    plvpor(b.x0, b.x1, b.y0, b.y1);
    plwind(w.x0, w.x1, w.y0, w.y1);
    draw_field(fields[k], w, o.log_scale, range);
    draw_curves(o.curves, line_width);
    draw_curves(fields[k].curves, line_width);
    plcol0(kBlack);
    // Room per tick label: about five characters across, two lines up.
    plbox("bcnst", tick_step(w.x1 - w.x0, (b.x1 - b.x0) * o.width, 5.0 * layout.char_px), 0, "bcnstv",
          tick_step(w.y1 - w.y0, (b.y1 - b.y0) * o.height, 2.5 * layout.char_px), 0);
    plmtex("b", 3.0, 0.5, 0.5, escape_text(o.x_label).c_str());
    plmtex("l", 5.0, 0.5, 0.5, escape_text(o.y_label).c_str());
    if (!fields[k].title.empty()) plmtex("t", 0.8, 0.5, 0.5, escape_text(fields[k].title).c_str());
  }
  draw_colorbar(layout.colorbar, o.colorbar_label, o.log_scale, range);
  if (!o.curves.empty()) draw_legend(layout.legend, o.curves, line_width);
  if (!o.title.empty()) {
    // One plmtex per line, in a font shrunk until the longest line fits the page width (estimated:
    // a character of the sans-serif font is at most ~0.72 of its height wide).
    std::vector<std::string> lines;
    std::size_t longest = 0;
    for (std::size_t begin = 0, end = 0; end != std::string::npos; begin = end + 1) {
      end = o.title.find('\n', begin);
      const std::string line = o.title.substr(begin, end == std::string::npos ? end : end - begin);
      longest = std::max<std::size_t>(longest, std::count_if(line.begin(), line.end(), [](char c) {
                                        return (static_cast<unsigned char>(c) & 0xc0) != 0x80;  // UTF-8 starts
                                      }));
      lines.push_back(escape_text(line));
    }
    plvpor(0.0, 1.0, 0.0, 1.0);
    plcol0(kBlack);
    double scale = 1.25 * text_scale;
    const double width_px = 0.72 * 1.25 * layout.char_px * static_cast<double>(longest);
    if (const double room = 0.96 * o.width; width_px > room) scale *= room / width_px;
    plschr(0.0, scale);
    // plmtex's displacement is in character heights of the current font; the lines keep the
    // layout's spacing (1.6 line heights of 1.25 f).
    const double spacing = 1.6 * 1.25 * text_scale / scale;
    for (std::size_t i = 0; i < lines.size(); ++i)
      plmtex("t", -spacing * (static_cast<double>(i) + 1.0), 0.5, 0.5, lines[i].c_str());
  }
}

// PLplot closes the file itself (plend1), so a failed last write is not reported: a complete PNG
// ends with its IEND chunk, which a truncated one lacks.
bool ends_like_a_png(const std::string& file) {
  static constexpr unsigned char kEnd[12] = {0, 0, 0, 0, 'I', 'E', 'N', 'D', 0xae, 0x42, 0x60, 0x82};
  std::ifstream in(file, std::ios::binary | std::ios::ate);
  if (!in || in.tellg() < static_cast<std::streamoff>(sizeof kEnd)) return false;
  in.seekg(-static_cast<std::streamoff>(sizeof kEnd), std::ios::end);
  unsigned char end[sizeof kEnd] = {};
  in.read(reinterpret_cast<char*>(end), sizeof end);
  return in && std::equal(std::begin(kEnd), std::end(kEnd), end);
}

// Draws into `file_name` (the temporary file of `path`, which the messages name).
Status render_png(const std::string& file_name, const std::string& path, const std::vector<PlotField2D>& fields,
                  const PlotOptions& o, const MapPngLayout& layout) {
  std::lock_guard<std::mutex> lock(plplot_mutex());
  // Opened here so that a path that cannot be written is an error, not PLplot's exit().
  std::FILE* file = std::fopen(file_name.c_str(), "wb");
  if (file == nullptr) return Status::Invalid(fmt::format("{}: cannot write: {}", path, std::strerror(errno)));
  std::string errors;
  g_plplot_errors = &errors;
  plsabort(record_plplot_error);
  PLINT previous = 0, stream = -1;
  plgstrm(&previous);
  plmkstrm(&stream);
  if (stream < 0) {
    std::fclose(file);
    g_plplot_errors = nullptr;
    return Status::Invalid(path + ": PLplot has no free stream");
  }
  plsdev("pngcairo");
  plsfile(file);  // plend1 closes it
  plspage(0.0, 0.0, o.width, o.height, 0, 0);
  plscmap0(kRed8.data(), kGreen8.data(), kBlue8.data(), kColourCount);
  std::array<PLFLT, kViridisPoints> at{}, r{}, g{}, b{};
  for (int i = 0; i < kViridisPoints; ++i) {
    at[i] = i / static_cast<double>(kViridisPoints - 1);
    r[i] = ((kViridis[i] >> 16) & 0xff) / 255.0, g[i] = ((kViridis[i] >> 8) & 0xff) / 255.0;
    b[i] = (kViridis[i] & 0xff) / 255.0;
  }
  plscmap1n(256);
  plscmap1l(1, kViridisPoints, at.data(), r.data(), g.data(), b.data(), nullptr);
  plinit();
  pladv(0);
  draw(fields, o, layout);
  plend1();
  plsstrm(previous);
  plsabort(nullptr);
  g_plplot_errors = nullptr;
  if (!errors.empty()) return Status::Invalid(fmt::format("{}: PLplot could not draw the map: {}", path, errors));
  if (!ends_like_a_png(file_name))
    return Status::Invalid(fmt::format("{}: the PNG was not written completely; check that the folder has room", path));
  return Status::Ok();
}

Status write_png(const std::string& path, const std::vector<PlotField2D>& fields, const PlotOptions& o) {
  if (Status st = check_input(path, fields, o); !st.ok()) return st;
  const MapPngLayout layout = map_png_layout(fields, o);
  for (const PageBox& b : layout.panels)
    if ((b.x1 - b.x0) * o.width < 20.0 || (b.y1 - b.y0) * o.height < 20.0)
      return Status::Invalid(fmt::format("{}: an image of {} x {} pixels is too small for {} panel(s)", path, o.width,
                                         o.height, fields.size()));

  return write_file_atomically(path,
                               [&](const std::string& temp) { return render_png(temp, path, fields, o, layout); });
}

}  // namespace

Status write_png_map(const std::string& path, const PlotField2D& field, const PlotOptions& options) {
  return write_png(path, {field}, options);
}

Status write_png_sheet(const std::string& path, const std::vector<PlotField2D>& fields, const PlotOptions& options) {
  return write_png(path, fields, options);
}

// VTK's contour filter does the contouring on the cells without a NaN corner; vtkStripper joins
// its segments into lines.
std::vector<std::array<double, 2>> contour_lines(const PlotField2D& p, double level) {
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto scalars = vtkSmartPointer<vtkDoubleArray>::New();
  for (int j = 0; j < p.ny; ++j)
    for (int i = 0; i < p.nx; ++i) {
      points->InsertNextPoint(p.x0 + i * p.dx, p.y0 + j * p.dy, 0.0);
      const double v = p.values[i + static_cast<std::size_t>(p.nx) * j];
      scalars->InsertNextValue(std::isnan(v) ? 0.0 : v);  // only read by cells without NaN corners
    }
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(points);
  grid->GetPointData()->SetScalars(scalars);
  for (int j = 0; j + 1 < p.ny; ++j)
    for (int i = 0; i + 1 < p.nx; ++i) {
      const vtkIdType ids[4] = {i + p.nx * j, i + 1 + p.nx * j, i + 1 + p.nx * (j + 1), i + p.nx * (j + 1)};
      if (std::none_of(ids, ids + 4, [&p](vtkIdType id) { return std::isnan(p.values[static_cast<std::size_t>(id)]); }))
        grid->InsertNextCell(VTK_QUAD, 4, ids);
    }
  std::vector<std::array<double, 2>> lines;
  if (grid->GetNumberOfCells() == 0) return lines;
  vtkNew<vtkContourFilter> contour;
  contour->SetInputData(grid);
  contour->SetValue(0, level);
  vtkNew<vtkStripper> stripper;
  stripper->SetInputConnection(contour->GetOutputPort());
  stripper->Update();
  vtkPolyData* out = stripper->GetOutput();
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c) {
    out->GetCellPoints(c, ids);
    if (!lines.empty())
      lines.push_back({std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN()});
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k) {
      const double* x = out->GetPoint(ids->GetId(k));
      lines.push_back({x[0], x[1]});
    }
  }
  return lines;
}

}  // namespace kinestat::io
