// Mesh-convergence study of the link stiffness: the 6x6 compliance on three or more meshes of
// decreasing size h, and a Richardson estimate of the limit of each diagonal entry.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "kinestat/core/status.hpp"
#include "kinestat/fea/link_stiffness.hpp"
#include "kinestat/fea/tet_mesh.hpp"

namespace kinestat::fea {

// f(h) = f0 + c h^p fitted through the last three (h, f) pairs (h decreasing, any ratios).
struct RichardsonEstimate {
  double order = 0.0;         // observed order of convergence p
  double extrapolated = 0.0;  // f0
  double finest_error = 0.0;  // (f(h_finest) - f0) / f0: the estimated relative error of the finest mesh
};

// kNotConverged when the last two differences change sign or vanish (not in the asymptotic
// range, or already converged to round-off); kInvalidInput for fewer than 3 points or h not
// strictly decreasing.
StatusOr<RichardsonEstimate> richardson_estimate(const std::vector<double>& h, const std::vector<double>& f);

struct ConvergenceStudy {
  std::vector<double> sizes;  // m, as requested
  std::vector<int> num_dofs;
  std::vector<Mat6> compliance;                        // per size, SI units (see LinkStiffness)
  std::vector<StatusOr<RichardsonEstimate>> diagonal;  // per dof ux..rz of the compliance
};

// Runs link_stiffness on make_mesh(h) for each h of `sizes` (>= 3, decreasing).
StatusOr<ConvergenceStudy> mesh_convergence_study(const std::function<StatusOr<TetMesh>(double h)>& make_mesh,
                                                  const std::vector<double>& sizes, const Material& material,
                                                  const LinkStiffnessOptions& options);

// Table of the study: one row per mesh, then the extrapolated values, orders and error estimates.
std::string convergence_report(const ConvergenceStudy& study);

}  // namespace kinestat::fea
