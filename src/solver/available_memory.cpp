#include "solver/available_memory.hpp"

#include <fstream>
#include <sstream>
#include <string>

namespace kinestat::solver {

double available_memory_bytes() {
  std::ifstream meminfo("/proc/meminfo");
  for (std::string line; std::getline(meminfo, line);) {
    if (line.rfind("MemAvailable:", 0) != 0) continue;
    std::istringstream fields(line.substr(13));
    double kilobytes = 0.0;
    return (fields >> kilobytes) ? kilobytes * 1024.0 : 0.0;
  }
  return 0.0;
}

}  // namespace kinestat::solver
