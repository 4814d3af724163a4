#include "msa/singularity_diagnosis.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "kinestat/core/frame.hpp"
#include "kinestat/solver/null_space.hpp"

namespace kinestat::msa {
namespace {

std::string weak_dof_words(const Structure& s, const ReducedDof& rd) {
  const bool global = rd.frame.isApprox(Mat3::Identity());
  return fmt::format("node '{}' {}{}", s.nodes()[rd.node].id, dof_name(rd.component), global ? "" : " (local frame)");
}

// Node ids as "{'a', 'b', 'c'}", the first 12 of them.
std::string node_set_words(const Structure& s, const std::vector<int>& nodes) {
  std::string out;
  for (size_t i = 0; i < nodes.size() && i < 12; ++i)
    out += fmt::format("{}'{}'", i ? ", " : "", s.nodes()[nodes[i]].id);
  if (nodes.size() > 12) out += fmt::format(", ... ({} nodes)", nodes.size());
  return "{" + out + "}";
}

int find_root(std::vector<int>& parent, int n) {
  while (parent[n] != n) n = parent[n] = parent[parent[n]];
  return n;
}

// A part cut loose: nodes that beams, joints with some stiffness and rigid links join to one another
// but to no support; it moves as a rigid body whatever its elements are.
struct LoosePart {
  std::vector<int> nodes;
  Vec3 centroid = Vec3::Zero();
};

std::vector<LoosePart> loose_parts(const Structure& s) {
  const int nn = static_cast<int>(s.nodes().size());
  std::vector<int> parent(nn);
  for (int n = 0; n < nn; ++n) parent[n] = n;
  auto join = [&](int a, int b) { parent[find_root(parent, a)] = find_root(parent, b); };
  for (const Beam& b : s.beams()) join(b.node1, b.node2);
  for (const Joint& j : s.joints())
    if (j.stiffness.cwiseAbs().maxCoeff() > 0) join(j.node1, j.node2);
  for (const RigidLink& r : s.rigid_links())
    if (std::find(r.mask.begin(), r.mask.end(), true) != r.mask.end()) join(r.master, r.slave);
  std::vector<bool> held(nn, false);
  for (const Support& sup : s.supports())
    if (std::find(sup.fixed.begin(), sup.fixed.end(), true) != sup.fixed.end())
      held[find_root(parent, sup.node)] = true;
  std::vector<int> part_of_root(nn, -1);
  std::vector<LoosePart> parts;
  for (int n = 0; n < nn; ++n) {
    const int r = find_root(parent, n);
    if (held[r]) continue;
    if (part_of_root[r] < 0) {
      part_of_root[r] = static_cast<int>(parts.size());
      parts.emplace_back();
    }
    parts[part_of_root[r]].nodes.push_back(n);
  }
  for (LoosePart& p : parts) {
    for (int n : p.nodes) p.centroid += s.nodes()[n].position;
    p.centroid /= static_cast<double>(p.nodes.size());
  }
  return parts;
}

// The reduced coordinates q (u = C q) of a nodal motion `u` (6N, global axes), read off each reduced
// dof in its frame. Exact for rigid-body motions of loose parts: their ties are rigid too.
VecX reduced_coordinates(const DofMap& map, const VecX& u) {
  VecX q(map.num_free());
  for (int j = 0; j < map.num_free(); ++j) {
    const ReducedDof& rd = map.reduced[j];
    const Vec3 part = u.segment<3>(6 * rd.node + (rd.component < 3 ? 0 : 3));
    q(j) = (rd.frame.transpose() * part)(rd.component % 3);
  }
  return q;
}

const char* const kAxisWords[3] = {"+x", "+y", "+z"};

}  // namespace

std::string describe_node_motion(const Vec6& m, double L) {
  const Vec3 t = m.head<3>(), r = m.tail<3>();
  const double scale = std::max(t.norm(), r.norm() * L);
  std::string out;
  if (t.norm() > 0.05 * scale) out += fmt::format("translates along {} ({:.3g})", direction_words(t), t.norm());
  if (r.norm() * L > 0.05 * scale) {
    if (!out.empty()) out += " and ";
    out += fmt::format("rotates about {} ({:.3g} rad{})", direction_words(r), r.norm(),
                       t.norm() > 0 || L != 1.0 ? "/m" : "");
  }
  return out;
}

SingularityDiagnosis diagnose_singularity(const Structure& s, const DofMap& map, const solver::SparseMatrix& Kr,
                                          const solver::FactorizationReport& report, double tolerance,
                                          const solver::LinearSolverOptions& options) {
  SingularityDiagnosis d;
  d.singular = true;
  std::vector<int> cols = report.weak_columns;
  if (report.failed_column >= 0) cols.push_back(report.failed_column);
  for (int c : cols) d.weak_dofs.push_back({map.reduced[c].node, map.reduced[c].component});

  const double L = s.length_scale();
  const int nn = static_cast<int>(s.nodes().size());
  std::string text =
      "The structure is singular: some motion is resisted by no element (a mechanism, a released "
      "chain, a missing support, or a singular posture).\n";
  if (!cols.empty()) {
    text += "  Elimination found no stiffness at: ";
    for (size_t i = 0; i < cols.size(); ++i) text += (i ? ", " : "") + weak_dof_words(s, map.reduced[cols[i]]);
    text += "\n";
  }

  // Loose parts first, in the canonical basis: translations along x, y, z and rotations about x, y,
  // z through the part's centroid (global axes), each with its own stiffness ratio as a check.
  const std::vector<LoosePart> loose = loose_parts(s);
  const VecX D = solver::stiffness_scaling(Kr);
  const bool no_support = !loose.empty() && static_cast<int>(loose.front().nodes.size()) == nn;
  MatX rigid_modes(Kr.rows(), 6 * static_cast<Eigen::Index>(loose.size()));
  for (size_t p = 0; p < loose.size(); ++p) {
    const LoosePart& part = loose[p];
    const bool one = no_support || part.nodes.size() == 1;
    const std::string who =
        no_support ? "the whole model" : fmt::format("node{} {}", one ? "" : "s", node_set_words(s, part.nodes));
    const char* verb_s = one ? "s" : "";
    if (no_support)
      text += "  The model has no supports: it moves as a rigid body (3 translations, 3 rotations).\n";
    else
      text += fmt::format(
          "  N{} {} not connected to any support: {} as a rigid body (3 translations, 3 "
          "rotations).\n",
          who.substr(1), one ? "is" : "are", one ? "it moves" : "they move");
    for (int k = 0; k < 6; ++k) {
      FreeMotion fm;
      fm.node_motion.assign(nn, Vec6::Zero());
      VecX u = VecX::Zero(s.num_dofs());
      const Vec3 axis = Vec3::Unit(k % 3);
      for (int n : part.nodes) {
        Vec6 m = Vec6::Zero();
        if (k < 3)
          m.head<3>() = axis;
        else
          m << axis.cross(s.nodes()[n].position - part.centroid), axis;
        fm.node_motion[n] = m;
        u.segment<6>(6 * n) = m;
      }
      const VecX q = reduced_coordinates(map, u);
      rigid_modes.col(6 * static_cast<Eigen::Index>(p) + k) = q;
      fm.rayleigh_ratio = q.dot(Kr * q) / q.dot(D.asDiagonal() * q);
      const int number = static_cast<int>(d.modes.size()) + 1;
      if (k < 3)
        fm.description = fmt::format("free motion {} (rigid body, stiffness ratio {:.1e}): {} translate{} along {}",
                                     number, fm.rayleigh_ratio, who, verb_s, kAxisWords[k]);
      else
        fm.description = fmt::format(
            "free motion {} (rigid body, stiffness ratio {:.1e}): {} rotate{} about {} through ({:.6g}, {:.6g}, "
            "{:.6g}) "
            "m, the centroid",
            number, fm.rayleigh_ratio, who, verb_s, kAxisWords[k - 3], part.centroid.x(), part.centroid.y(),
            part.centroid.z());
      text += "  " + fm.description + "\n";
      d.modes.push_back(std::move(fm));
    }
  }

  const int block = std::min<int>(Kr.rows(), static_cast<int>(cols.size()) + 6 + static_cast<int>(rigid_modes.cols()));
  // Modes count as free up to the pivot tolerance; at least the lowest one is always described.
  auto ns = solver::near_null_space(Kr, block, tolerance, options);
  if (!ns.ok()) {
    d.message = text + "  (the free motions could not be computed: " + ns.status().message() + ")";
    return d;
  }
  if (rigid_modes.cols() > 0) {
    // The other free motions: the near-null space without the loose parts' rigid-body motions
    // (D-orthogonal complement, then Rayleigh-Ritz again); only those below the tolerance.
    const VecX Ds = D.cwiseSqrt();
    const MatX Q = Eigen::HouseholderQR<MatX>(Ds.asDiagonal() * rigid_modes).householderQ() *
                   MatX::Identity(Kr.rows(), rigid_modes.cols());
    MatX V = Ds.asDiagonal() * ns->modes;
    V -= Q * (Q.transpose() * V);
    Eigen::JacobiSVD<MatX> svd(V, Eigen::ComputeThinU);
    int keep = 0;
    while (keep < svd.singularValues().size() && svd.singularValues()(keep) > 0.5) ++keep;
    const MatX Z = Ds.cwiseInverse().asDiagonal() * svd.matrixU().leftCols(keep);
    ns->modes.resize(Kr.rows(), 0);
    ns->ratios.resize(0);
    if (keep > 0) {
      const MatX H = Z.transpose() * (Kr * Z);
      Eigen::SelfAdjointEigenSolver<MatX> eig(0.5 * (H + H.transpose()));  // Z is D-orthonormal
      int below = 0;
      while (below < keep && eig.eigenvalues()(below) < tolerance) ++below;
      ns->modes = Z * eig.eigenvectors().leftCols(below);
      ns->ratios = eig.eigenvalues().head(below).cwiseMax(0.0);
    }
  }
  for (int k = 0; k < ns->modes.cols(); ++k) {
    const VecX u = map.C * ns->modes.col(k);
    FreeMotion fm;
    fm.rayleigh_ratio = ns->ratios(k);
    fm.node_motion.resize(nn);
    // Scale so that the largest nodal translation is 1 (rotations then read in rad per m of that
    // translation), or the largest rotation when nothing translates; the sign makes the largest
    // component positive, so the printed mode is reproducible.
    double tmax = 0.0, rmax = 0.0;
    int imax = 0;
    for (int i = 0; i < u.size(); ++i) {
      const bool translation = (i % 6) < 3;
      if (translation && std::abs(u(i)) > tmax) tmax = std::abs(u(i)), imax = i;
      if (!translation) rmax = std::max(rmax, std::abs(u(i)));
    }
    if (tmax <= 1e-9 * rmax * L)
      for (int i = 0; i < u.size(); ++i)
        if (std::abs(u(i)) >= rmax) imax = i;
    const double scale = (u(imax) < 0 ? -1.0 : 1.0) / std::abs(u(imax));
    for (int n = 0; n < nn; ++n) fm.node_motion[n] = scale * u.segment<6>(6 * n);
    std::vector<int> order(nn);
    for (int n = 0; n < nn; ++n) order[n] = n;
    const bool rotation_only = tmax <= 1e-9 * rmax * L;
    auto size = [&](int n) {
      const Vec6& m = fm.node_motion[n];
      return rotation_only ? m.tail<3>().norm() : std::max(m.head<3>().norm(), m.tail<3>().norm() * L);
    };
    std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return size(a) > size(b); });
    fm.description = fmt::format("free motion {} (stiffness ratio {:.1e}; largest {} scaled to 1):", d.modes.size() + 1,
                                 fm.rayleigh_ratio, rotation_only ? "rotation" : "translation");
    int listed = 0;
    for (int n : order) {
      if (size(n) < 0.05 || listed == 8) break;
      fm.description += fmt::format("\n    node '{}' {}", s.nodes()[n].id,
                                    describe_node_motion(fm.node_motion[n], rotation_only ? 1.0 : L));
      ++listed;
    }
    const int moving =
        static_cast<int>(std::count_if(order.begin(), order.end(), [&](int n) { return size(n) >= 0.05; }));
    if (moving > listed) fm.description += fmt::format("\n    ... and {} more nodes", moving - listed);
    text += "  " + fm.description + "\n";
    d.modes.push_back(std::move(fm));
  }
  text +=
      "  Fix: add the missing support or stiffness, or move away from the singular posture "
      "(--regularize gives a marked, regularized answer).";
  d.message = text;
  return d;
}

}  // namespace kinestat::msa
