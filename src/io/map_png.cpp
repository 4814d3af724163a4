// Placeholder until the plotting backend lands (PLplot/gnuplot): refuses with a clear message.
#include "kinestat/io/map_png.hpp"

namespace kinestat::io {

Status write_png_map(const std::string& path, const PlotField2D&, const PlotOptions&) {
  return Status::Invalid(path + ": PNG output is not available in this build");
}

Status write_png_sheet(const std::string& path, const std::vector<PlotField2D>&, const PlotOptions&) {
  return Status::Invalid(path + ": PNG output is not available in this build");
}

}  // namespace kinestat::io
