#include "kinestat/core/cartesian_stiffness.hpp"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>

#include "kinestat/core/frame.hpp"

namespace kinestat {
namespace {

// A 6x6 matrix under a title line "  TITLE [UNITS]", one labelled row per dof.
std::string matrix_lines(const Mat6& M, const std::string& title, const char* units) {
  static const char* names[6] = {"ux", "uy", "uz", "rx", "ry", "rz"};
  std::string out = fmt::format("  {} [{}]\n          ", title, units);
  for (const char* n : names) out += fmt::format("{:>12}", n);
  out += "\n";
  for (int i = 0; i < 6; ++i) {
    out += fmt::format("    {:>4}  ", names[i]);
    for (int j = 0; j < 6; ++j) out += fmt::format("{:>12.4e}", M(i, j));
    out += "\n";
  }
  return out;
}

}  // namespace

CartesianStiffness cartesian_from_compliance(const Mat6& compliance, const Vec3& point, std::string frame) {
  CartesianStiffness c;
  c.point = point;
  c.frame = std::move(frame);
  c.compliance = 0.5 * (compliance + compliance.transpose());  // exact up to round-off
  c.compliance_defined = true;
  const Eigen::SelfAdjointEigenSolver<Mat6> eig(c.compliance);
  const double cmax = eig.eigenvalues().cwiseAbs().maxCoeff();
  for (int i = 0; i < 6; ++i)
    if (!(eig.eigenvalues()(i) > 1e-13 * cmax)) c.rigid_directions.push_back(eig.eigenvectors().col(i).normalized());
  if (!(cmax > 0)) {
    c.note = "the point is fully supported: its stiffness is infinite";
  } else if (!c.rigid_directions.empty()) {
    c.note =
        "the compliance is singular (a supported or rigidly tied dof at this point): the stiffness is "
        "infinite in some direction; see the compliance";
  } else {
    c.stiffness = eig.eigenvectors() * eig.eigenvalues().cwiseInverse().asDiagonal() * eig.eigenvectors().transpose();
    c.stiffness_defined = true;
    c.indices = stiffness_indices(c.stiffness);
  }
  return c;
}

std::string describe_twist(const Vec6& t) {
  const Vec3 v = t.head<3>(), r = t.tail<3>();
  const double scale = t.norm();
  if (r.norm() <= 1e-9 * scale) return "translation along " + direction_words(v);
  if (v.norm() <= 1e-9 * scale) return "rotation about " + direction_words(r) + " through the point";
  return fmt::format("screw motion: rotation about {} with point translation {:.3g} m/rad along {}", direction_words(r),
                     v.norm() / r.norm(), direction_words(v));
}

std::string cartesian_stiffness_report(const CartesianStiffness& c, const std::string& title) {
  std::string out = fmt::format("{}: point ({:.6g}, {:.6g}, {:.6g}) m, {}; dofs ux uy uz rx ry rz\n", title,
                                c.point.x(), c.point.y(), c.point.z(), c.frame);
  if (c.stiffness_defined || !c.stiffness.isZero(0.0))  // MSA leaves an undefined stiffness zero
    out += matrix_lines(c.stiffness, c.stiffness_defined ? "stiffness K" : "stiffness K, finite part",
                        CartesianStiffness::kStiffnessUnits);
  if (c.compliance_defined)
    out += matrix_lines(c.compliance, "compliance C = K^-1", CartesianStiffness::kComplianceUnits);
  if (c.indices) {
    out += "  indices of K:\n" + indices_report(*c.indices);
    out += "  eigenvalues of K (SI, mixed units):";
    for (int i = 0; i < c.indices->eigenvalues.size(); ++i) out += fmt::format(" {:.4e}", c.indices->eigenvalues(i));
    out += "\n";
  }
  for (const Vec6& d : c.free_directions) out += "  LOST (free, zero stiffness): " + describe_twist(d) + "\n";
  for (const Vec6& d : c.rigid_directions) out += "  LOST (rigid, infinite stiffness): " + describe_twist(d) + "\n";
  if (!c.note.empty()) out += "  " + c.note + "\n";
  if (!c.status.ok()) out += "  STATUS: " + c.status.message() + "\n";
  return out;
}

}  // namespace kinestat
