// PNG maps: the file is a PNG of the stated size (IHDR chunk read by hand, pixels read back with
// VTK's PNG reader), and known features sit at the pixels computed from the layout: the blank (grey)
// half of a field, the ends of the colour scale, a vertical curve at a known x, a dashed curve at a
// known y, the frame of the plot area; a sheet shares one colour scale.
#include "kinestat/io/map_png.hpp"

#include <gtest/gtest.h>
#include <vtkImageData.h>
#include <vtkPNGReader.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <thread>
#include <vector>

#include "io/map_png_layout.hpp"
#include "kinestat/io/workspace_map_png.hpp"

namespace kinestat::io {
namespace {

namespace fs = std::filesystem;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
using Rgb = std::array<int, 3>;

// Width and height from the IHDR chunk, which the PNG format puts first after the 8-byte signature.
std::array<std::uint32_t, 2> png_size(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::array<unsigned char, 24> h{};
  in.read(reinterpret_cast<char*>(h.data()), h.size());
  const std::array<unsigned char, 8> signature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (!in || !std::equal(signature.begin(), signature.end(), h.begin()) || std::string(&h[12], &h[16]) != "IHDR")
    return {0, 0};
  auto be32 = [&](int i) {
    return (std::uint32_t{h[i]} << 24) | (std::uint32_t{h[i + 1]} << 16) | (std::uint32_t{h[i + 2]} << 8) | h[i + 3];
  };
  return {be32(16), be32(20)};
}

struct Image {
  int width = 0, height = 0, components = 0;
  vtkSmartPointer<vtkImageData> data;
  // Colour at (column, row from the top). VTK's reader puts row 0 at the bottom.
  Rgb at(int col, int row) const {
    auto* s = vtkUnsignedCharArray::SafeDownCast(data->GetPointData()->GetScalars());
    const vtkIdType id = col + static_cast<vtkIdType>(width) * (height - 1 - row);
    return {static_cast<int>(s->GetComponent(id, 0)), static_cast<int>(s->GetComponent(id, 1)),
            static_cast<int>(s->GetComponent(id, 2))};
  }
};

Image read_png(const std::string& path) {
  auto reader = vtkSmartPointer<vtkPNGReader>::New();
  Image im;
  if (!reader->CanReadFile(path.c_str())) return im;
  reader->SetFileName(path.c_str());
  reader->Update();
  im.data = reader->GetOutput();
  int dims[3];
  im.data->GetDimensions(dims);
  im.width = dims[0], im.height = dims[1];
  im.components = im.data->GetPointData()->GetScalars()->GetNumberOfComponents();
  return im;
}

bool near(const Rgb& a, const Rgb& b, int tol) {
  for (int c = 0; c < 3; ++c)
    if (std::abs(a[c] - b[c]) > tol) return false;
  return true;
}
bool dark(const Rgb& c) { return c[0] < 110 && c[1] < 110 && c[2] < 110; }
bool red(const Rgb& c) { return c[0] > 150 && c[1] < 90 && c[2] < 90; }

// Viridis by linear interpolation in its published table at 0, 0.1, ..., 1.
Rgb viridis(double t) {
  static const std::array<unsigned, 11> table = {0x440154, 0x482475, 0x414487, 0x355f8d, 0x2a788e, 0x21918c,
                                                 0x22a884, 0x44bf70, 0x7ad151, 0xbddf26, 0xfde725};
  const double s = std::clamp(t, 0.0, 1.0) * 10.0;
  const int i = std::min(static_cast<int>(s), 9);
  const double u = s - i;
  Rgb out{};
  for (int c = 0; c < 3; ++c) {
    const int shift = 16 - 8 * c;
    const double a = (table[i] >> shift) & 0xff, b = (table[i + 1] >> shift) & 0xff;
    out[c] = static_cast<int>(std::lround(a + u * (b - a)));
  }
  return out;
}

class MapPng : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ =
        ::testing::TempDir() + "kinestat_png_test_" + ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string dir_;
};

// 40 x 30 cells of 5 mm: x in [-100, 95], y in [0, 145]; no value for x < 0, value x on the right.
PlotField2D half_field() {
  PlotField2D f;
  f.nx = 40, f.ny = 30, f.x0 = -100.0, f.y0 = 0.0, f.dx = 5.0, f.dy = 5.0;
  for (int j = 0; j < f.ny; ++j)
    for (int i = 0; i < f.nx; ++i) {
      const double x = f.x0 + i * f.dx;
      f.values.push_back(x < 0.0 ? kNaN : x);
    }
  return f;
}

constexpr double kCurveX = 27.3, kCurveY = 100.0;

PlotOptions half_options() {
  PlotOptions o;
  o.title = "test map: value = x";
  o.colorbar_label = "x (mm)";
  o.width = 900, o.height = 700;
  o.curves.push_back({{{kCurveX, -20.0}, {kCurveX, 200.0}}, "vertical line", CurveStyle::kSolidBlack});
  o.curves.push_back({{{-120.0, kCurveY}, {120.0, kCurveY}}, "horizontal line", CurveStyle::kDashedRed});
  return o;
}

TEST_F(MapPng, SizeBlankHalfColourScaleCurvesAndFrameWhereComputed) {
  const PlotField2D f = half_field();
  const PlotOptions o = half_options();
  const std::string path = dir_ + "/half.png";
  const Status st = write_png_map(path, f, o);
  ASSERT_TRUE(st.ok()) << st.message();
  EXPECT_EQ(png_size(path), (std::array<std::uint32_t, 2>{900, 700}));
  const Image im = read_png(path);
  ASSERT_EQ(im.width, 900);
  ASSERT_EQ(im.height, 700);
  ASSERT_GE(im.components, 3);

  const MapPngLayout layout = map_png_layout({f}, o);
  auto pixel = [&](double x, double y) {
    const PixelPoint p = plot_to_pixel(layout, 0, x, y, o);
    return std::array<int, 2>{static_cast<int>(std::floor(p.col)), static_cast<int>(std::floor(p.row))};
  };
  auto colour = [&](double x, double y) {
    const auto p = pixel(x, y);
    return im.at(p[0], p[1]);
  };
  // Left half: no value, light grey; the cell centres of the right half carry the colour scale.
  for (double x : {-95.0, -50.0, -5.0})
    for (double y : {5.0, 70.0, 140.0}) EXPECT_TRUE(near(colour(x, y), {222, 222, 222}, 4)) << x << ", " << y;
  // (Sampled 1 mm off the cell centres, which are on the minor ticks of the frame.)
  const double vmax = 95.0;
  for (double x : {0.0, 15.0, 60.0, 95.0}) {
    const Rgb c = colour(x - 1.0, 41.0);
    EXPECT_TRUE(near(c, viridis(x / vmax), 8)) << "x = " << x << ": got " << c[0] << "," << c[1] << "," << c[2];
  }

  // The black vertical line at x = 27.3: dark within a pixel of the computed column, the field's
  // colour a few pixels beside it.
  for (double y : {20.0, 70.0, 130.0}) {
    const auto p = pixel(kCurveX, y);
    bool found = false;
    for (int dc = -1; dc <= 1; ++dc) found = found || dark(im.at(p[0] + dc, p[1]));
    EXPECT_TRUE(found) << "no dark pixel at column " << p[0] << ", row " << p[1];
    EXPECT_FALSE(dark(im.at(p[0] - 6, p[1])));
    EXPECT_FALSE(dark(im.at(p[0] + 6, p[1])));
  }
  // The red dashed line at y = 100: red on a good part of its row, nowhere two cells away.
  const auto a = pixel(5.0, kCurveY), b = pixel(90.0, kCurveY);
  int on_line = 0, off_line = 0;
  for (int col = a[0]; col <= b[0]; ++col) {
    bool r = false;
    for (int dr = -1; dr <= 1; ++dr) r = r || red(im.at(col, a[1] + dr));
    on_line += r;
    off_line += red(im.at(col, pixel(5.0, kCurveY + 10.0)[1]));
  }
  EXPECT_GT(on_line, (b[0] - a[0]) / 3) << "red pixels along y = 100";
  EXPECT_EQ(off_line, 0);

  // The frame of the plot area is drawn where the layout says (left and bottom edges).
  const PageBox& box = layout.panels[0];
  const int left = static_cast<int>(std::lround(box.x0 * o.width));
  const int bottom = static_cast<int>(std::lround((1.0 - box.y0) * o.height));
  const int mid_row = static_cast<int>((1.0 - 0.5 * (box.y0 + box.y1)) * o.height);
  const int mid_col = static_cast<int>(0.5 * (box.x0 + box.x1) * o.width);
  bool frame_left = false, frame_bottom = false;
  for (int d = -1; d <= 1; ++d) {
    frame_left = frame_left || dark(im.at(left + d, mid_row));
    frame_bottom = frame_bottom || dark(im.at(mid_col, bottom + d));
  }
  EXPECT_TRUE(frame_left);
  EXPECT_TRUE(frame_bottom);
}

TEST_F(MapPng, SheetSharesOneColourScale) {
  // Two constant panels, 1 and 3: on a common scale the first is its low end, the second its high end.
  PlotField2D low, high;
  for (PlotField2D* f : {&low, &high}) f->nx = 10, f->ny = 8, f->dx = 2.0, f->dy = 2.0;
  low.values.assign(80, 1.0), low.title = "z = 0 mm";
  high.values.assign(80, 3.0), high.title = "z = 10 mm";
  PlotOptions o;
  o.title = "sheet", o.colorbar_label = "value", o.width = 1000, o.height = 500;
  const std::string path = dir_ + "/sheet.png";
  const Status st = write_png_sheet(path, {low, high}, o);
  ASSERT_TRUE(st.ok()) << st.message();
  EXPECT_EQ(png_size(path), (std::array<std::uint32_t, 2>{1000, 500}));
  const Image im = read_png(path);
  const MapPngLayout layout = map_png_layout({low, high}, o);
  ASSERT_EQ(layout.panels.size(), 2u);
  for (int k = 0; k < 2; ++k) {
    const PixelPoint p = plot_to_pixel(layout, k, 9.0, 7.0, o);
    const Rgb c = im.at(static_cast<int>(p.col), static_cast<int>(p.row));
    EXPECT_TRUE(near(c, viridis(k == 0 ? 0.0 : 1.0), 8)) << "panel " << k << ": " << c[0] << "," << c[1] << "," << c[2];
  }
}

TEST_F(MapPng, ConcurrentWritersEachGetTheirPicture) {
  const PlotField2D f = half_field();
  const PlotOptions o = half_options();
  std::vector<std::thread> threads;
  std::vector<Status> status(3, Status::Ok());
  for (int t = 0; t < 3; ++t)
    threads.emplace_back([&, t] { status[t] = write_png_map(dir_ + "/t" + std::to_string(t) + ".png", f, o); });
  for (auto& th : threads) th.join();
  for (int t = 0; t < 3; ++t) {
    ASSERT_TRUE(status[t].ok()) << status[t].message();
    EXPECT_EQ(png_size(dir_ + "/t" + std::to_string(t) + ".png"), (std::array<std::uint32_t, 2>{900, 700}));
  }
}

TEST_F(MapPng, BadInputIsRefusedNamingThePath) {
  PlotField2D f = half_field();
  const PlotOptions o = half_options();
  const std::string path = dir_ + "/bad.png";

  PlotField2D short_values = f;
  short_values.values.pop_back();
  Status st = write_png_map(path, short_values, o);
  EXPECT_EQ(st.code(), StatusCode::kInvalidInput);
  EXPECT_NE(st.message().find(path), std::string::npos) << st.message();
  EXPECT_NE(st.message().find("1199 values for a 40 x 30 grid"), std::string::npos) << st.message();

  PlotField2D all_nan = f;
  all_nan.values.assign(all_nan.values.size(), kNaN);
  st = write_png_map(path, all_nan, o);
  EXPECT_NE(st.message().find("no value"), std::string::npos) << st.message();

  PlotOptions log = o;
  log.log_scale = true;
  st = write_png_map(path, f, log);  // the value 0 at x = 0
  EXPECT_NE(st.message().find("log colour scale needs positive values"), std::string::npos) << st.message();

  PlotOptions tiny = o;
  tiny.width = 20;
  st = write_png_map(path, f, tiny);
  EXPECT_NE(st.message().find("image size 20 x 700"), std::string::npos) << st.message();

  const std::string nowhere = dir_ + "/no/such/dir/map.png";
  st = write_png_map(nowhere, f, o);
  EXPECT_EQ(st.code(), StatusCode::kInvalidInput);
  EXPECT_NE(st.message().find(nowhere + ": cannot write"), std::string::npos) << st.message();
  EXPECT_FALSE(fs::exists(path));
}

TEST_F(MapPng, LogScaleColoursByDecade) {
  // Values 1, 10, 100 in three columns: on a log scale the middle one is the middle of the scale.
  PlotField2D f;
  f.nx = 3, f.ny = 2, f.dx = 10.0, f.dy = 10.0, f.values = {1.0, 10.0, 100.0, 1.0, 10.0, 100.0};
  PlotOptions o;
  o.log_scale = true, o.colorbar_label = "k (N/mm)";
  const std::string path = dir_ + "/log.png";
  const Status st = write_png_map(path, f, o);
  ASSERT_TRUE(st.ok()) << st.message();
  const Image im = read_png(path);
  const MapPngLayout layout = map_png_layout({f}, o);
  for (int i = 0; i < 3; ++i) {
    const PixelPoint p = plot_to_pixel(layout, 0, 10.0 * i, 5.0, o);
    const Rgb c = im.at(static_cast<int>(p.col), static_cast<int>(p.row));
    EXPECT_TRUE(near(c, viridis(0.5 * i), 8)) << "column " << i << ": " << c[0] << "," << c[1] << "," << c[2];
  }
}

TEST_F(MapPng, FixedColourRangeMapsAndClampsValues) {
  // 25 and 75 on a 0..100 scale: a quarter and three quarters; 150 beyond the end takes its colour.
  PlotField2D f;
  f.nx = 3, f.ny = 1, f.dx = 10.0, f.dy = 10.0, f.values = {25.0, 75.0, 150.0};
  PlotOptions o;
  o.colour_range = std::array<double, 2>{0.0, 100.0};
  const std::string path = dir_ + "/range.png";
  const Status st = write_png_map(path, f, o);
  ASSERT_TRUE(st.ok()) << st.message();
  const Image im = read_png(path);
  const MapPngLayout layout = map_png_layout({f}, o);
  for (int i = 0; i < 3; ++i) {
    const PixelPoint p = plot_to_pixel(layout, 0, 10.0 * i - 2.0, 2.0, o);
    const Rgb c = im.at(static_cast<int>(p.col), static_cast<int>(p.row));
    EXPECT_TRUE(near(c, viridis(std::min(f.values[i] / 100.0, 1.0)), 8))
        << "value " << f.values[i] << ": " << c[0] << "," << c[1] << "," << c[2];
  }
  o.colour_range = std::array<double, 2>{1.0, 1.0};
  EXPECT_NE(write_png_map(path, f, o).message().find("colour range [1, 1]"), std::string::npos);
}

}  // namespace
}  // namespace kinestat::io

namespace kinestat::io {
namespace {

// The title says which part of the grid a picture is (issue 21): the fixed coordinate of a plane of
// a box, and how many of a box's slices a sheet shows.
TEST(WorkspaceMapPngTitle, NamesTheSliceOrTheSlices) {
  mechanisms::WorkspaceMap map;
  map.description = "Orthoglide 3-PUU";
  map.grid.origin = Vec3(-0.1, -0.1, 0.02);
  map.grid.spacing = Vec3(0.005, 0.005, 0.005);
  map.grid.dimensions = {41, 41, 1};
  EXPECT_EQ(workspace_map_png_title(map, mechanisms::MapField::kTranslationalMin),
            "Orthoglide 3-PUU: k_t_min, slice z = 20 mm");
  map.grid.dimensions = {41, 1, 41};
  EXPECT_EQ(workspace_map_png_title(map, mechanisms::MapField::kTranslationalMin),
            "Orthoglide 3-PUU: k_t_min, slice y = -100 mm");
  map.grid.origin.z() = -0.1;
  map.grid.dimensions = {41, 41, 41};
  EXPECT_EQ(workspace_map_png_title(map, mechanisms::MapField::kConditionNumber),
            "Orthoglide 3-PUU: condition_number\n9 of the 41 slices z -100:100 mm");
}

}  // namespace
}  // namespace kinestat::io

namespace kinestat::io {
namespace {

// The contour of v = x at 4.5 is the line x = 4.5 across the defined cells only: a NaN column
// (a masked region) cuts it, and the mask's own edge draws nothing.
TEST(ContourLines, FollowTheLevelAndStopAtTheMask) {
  PlotField2D f;
  f.nx = 11, f.ny = 6, f.x0 = 0.0, f.y0 = 10.0, f.dx = 1.0, f.dy = 2.0;
  for (int j = 0; j < f.ny; ++j)
    for (int i = 0; i < f.nx; ++i) f.values.push_back(j == 3 ? std::nan("") : static_cast<double>(i));
  const auto lines = contour_lines(f, 4.5);
  double y_lo = 1e9, y_hi = -1e9;
  int breaks = 0;
  for (const auto& p : lines) {
    if (std::isnan(p[0])) {
      ++breaks;
      continue;
    }
    EXPECT_NEAR(p[0], 4.5, 1e-12);  // linear data: the interpolation is exact
    y_lo = std::min(y_lo, p[1]), y_hi = std::max(y_hi, p[1]);
    EXPECT_FALSE(p[1] > 14.0 && p[1] < 18.0) << p[1];  // row j = 3 (y = 16) masks the cells y 14..18
  }
  EXPECT_EQ(breaks, 1);  // two pieces: y 10..14 and 18..20
  EXPECT_DOUBLE_EQ(y_lo, 10.0);
  EXPECT_DOUBLE_EQ(y_hi, 20.0);
  // Every value above the level: no contour at all; every value NaN: none either.
  EXPECT_TRUE(contour_lines(f, 50.0).empty());
  PlotField2D blank = f;
  blank.values.assign(blank.values.size(), std::nan(""));
  EXPECT_TRUE(contour_lines(blank, 4.5).empty());
}

}  // namespace
}  // namespace kinestat::io
