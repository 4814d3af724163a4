#include "kinestat/core/types.hpp"

namespace kinestat {

const char* dof_name(int dof) {
  static constexpr const char* kNames[kDofsPerNode] = {"ux", "uy", "uz", "rx", "ry", "rz"};
  return (dof >= 0 && dof < kDofsPerNode) ? kNames[dof] : "?";
}

}  // namespace kinestat
