#include "msa/dof_map.hpp"

#include <cmath>
#include <functional>
#include <map>

#include <fmt/format.h>

#include "kinestat/core/frame.hpp"
#include "kinestat/core/input_checks.hpp"

namespace kinestat::msa {
namespace {

using SparseRow = std::map<int, double>;    // column -> coefficient
using NodeRows = std::array<SparseRow, 6>;  // the 6 rows of C for one node

Mat6 mask_projector(const DofMask& mask, bool value) {
  Mat6 P = Mat6::Zero();
  for (int i = 0; i < 6; ++i)
    if (mask[i] == value) P(i, i) = 1.0;
  return P;
}

}  // namespace

StatusOr<DofMap> build_dof_map(const Structure& s) {
  const int nn = static_cast<int>(s.nodes().size());
  DofMap map;
  map.supported_node.assign(nn, false);
  map.slave_of_tie.assign(nn, -1);

  // Support frame and fixed mask per node (several supports of one node must share the frame).
  std::vector<Mat3> frame(nn, Mat3::Identity());
  std::vector<DofMask> fixed(nn, DofMask{});
  for (const auto& sup : s.supports()) {
    if (map.supported_node[sup.node] && (frame[sup.node] - sup.frame).norm() > 1e-12)
      return Status::Invalid(at_source(sup.source, fmt::format("node '{}' has two supports in different frames; merge "
                                                               "them into one",
                                                               s.nodes()[sup.node].id)));
    map.supported_node[sup.node] = true;
    frame[sup.node] = sup.frame;
    for (int i = 0; i < 6; ++i) fixed[sup.node][i] = fixed[sup.node][i] || sup.fixed[i];
  }

  // A node that no beam, joint or rigid link reaches is held by nothing in the dofs its supports leave
  // free (with no element at all, CHOLMOD would only say "analysis failed"): name it.
  std::vector<bool> connected(nn, false);
  for (const auto& b : s.beams()) connected[b.node1] = connected[b.node2] = true;
  for (const auto& j : s.joints()) connected[j.node1] = connected[j.node2] = true;
  for (const auto& r : s.rigid_links()) connected[r.master] = connected[r.slave] = true;
  for (int n = 0; n < nn; ++n) {
    if (connected[n]) continue;
    std::string free;
    for (int i = 0; i < 6; ++i)
      if (!fixed[n][i]) free += fmt::format("{}{}", free.empty() ? "" : " ", dof_name(i));
    if (!free.empty())
      return Status::Invalid(at_source(s.nodes()[n].source,
                                       fmt::format("node '{}' is connected to no beam, joint or rigid link, so nothing "
                                                   "holds its dofs {}: connect it to the structure, fix all its dofs "
                                                   "or remove it",
                                                   s.nodes()[n].id, free)));
  }

  // Ties: rigid links, and the rigid components of joints (slave = the unsupported node).
  for (const auto& r : s.rigid_links()) map.ties.push_back({r.master, r.slave, r.mask, r.frame, -1, r.source});
  for (size_t j = 0; j < s.joints().size(); ++j) {
    const Joint& jt = s.joints()[j];
    DofMask mask{};
    bool any = false;
    for (int i = 0; i < 6; ++i) any |= (mask[i] = std::isinf(jt.stiffness(i)));
    if (!any) continue;
    int master = jt.node1, slave = jt.node2;
    if (map.supported_node[slave]) std::swap(master, slave);
    if (map.supported_node[slave])
      return Status::Invalid(at_source(jt.source, fmt::format("joint '{}' has rigid components between two supported "
                                                              "nodes; remove one of the supports or make the joint "
                                                              "elastic",
                                                              jt.id)));
    map.ties.push_back({master, slave, mask, jt.frame, static_cast<int>(j), jt.source});
  }
  for (size_t t = 0; t < map.ties.size(); ++t) {
    const auto& tie = map.ties[t];
    if (map.slave_of_tie[tie.slave] >= 0)
      return Status::Invalid(at_source(tie.source, fmt::format("node '{}' is tied rigidly to two nodes (rigid links "
                                                               "or rigid joint components); tie it to one and "
                                                               "connect the others to it",
                                                               s.nodes()[tie.slave].id)));
    map.slave_of_tie[tie.slave] = static_cast<int>(t);
  }

  // Independent unknowns: the free components of every node, in the node's support or tie frame.
  std::vector<std::array<int, 6>> own(nn);
  for (int n = 0; n < nn; ++n) {
    const int t = map.slave_of_tie[n];
    const Mat3 f = t >= 0 ? map.ties[t].frame : frame[n];
    for (int i = 0; i < 6; ++i) {
      const bool tied = t >= 0 && map.ties[t].mask[i];
      own[n][i] = -1;
      if (!tied && !fixed[n][i]) {
        own[n][i] = static_cast<int>(map.reduced.size());
        map.reduced.push_back({n, i, f});
      }
    }
  }

  // Rows of C per node, masters before slaves (chains of ties are resolved recursively).
  std::vector<NodeRows> rows(nn);
  std::vector<int> state(nn, 0);  // 0 = todo, 1 = in progress, 2 = done
  std::function<Status(int)> resolve = [&](int n) -> Status {
    if (state[n] == 2) return Status::Ok();
    if (state[n] == 1)
      return Status::Invalid(at_source(map.ties[map.slave_of_tie[n]].source,
                                       fmt::format("rigid links / rigid joints form a closed loop through node '{}'; a "
                                                   "loop of rigid ties is over-constrained, release one of them",
                                                   s.nodes()[n].id)));
    state[n] = 1;
    const int t = map.slave_of_tie[n];
    const Mat6 R = rotation6(t >= 0 ? map.ties[t].frame : frame[n]);
    NodeRows r;
    for (int i = 0; i < 6; ++i)
      if (own[n][i] >= 0)
        for (int row = 0; row < 6; ++row)
          if (R(row, i) != 0.0) r[row][own[n][i]] += R(row, i);
    if (t >= 0) {
      const auto& tie = map.ties[t];
      if (Status st = resolve(tie.master); !st.ok()) return st;
      // u_s = R P_tied R^T A u_m + (own free components), A: rigid transfer from master to slave.
      const Mat6 M = R * mask_projector(tie.mask, true) * R.transpose() *
                     rigid_transfer(s.nodes()[n].position - s.nodes()[tie.master].position);
      for (int row = 0; row < 6; ++row)
        for (int k = 0; k < 6; ++k)
          if (M(row, k) != 0.0)
            for (const auto& [col, v] : rows[tie.master][k]) r[row][col] += M(row, k) * v;
    }
    rows[n] = std::move(r);
    state[n] = 2;
    return Status::Ok();
  };
  std::vector<Eigen::Triplet<double>> trip;
  for (int n = 0; n < nn; ++n) {
    if (Status st = resolve(n); !st.ok()) return st;
    for (int row = 0; row < 6; ++row)
      for (const auto& [col, v] : rows[n][row])
        if (v != 0.0) trip.emplace_back(6 * n + row, col, v);
  }
  map.C.resize(6 * nn, static_cast<int>(map.reduced.size()));
  map.C.setFromTriplets(trip.begin(), trip.end());
  return map;
}

VecX prescribed_displacements(const Structure& s, const LoadCase& lc) {
  VecX u0 = VecX::Zero(s.num_dofs());
  for (const auto& p : lc.prescribed) {
    Mat3 f = Mat3::Identity();
    for (const auto& sup : s.supports())
      if (sup.node == p.node) f = sup.frame;
    u0.segment<6>(6 * p.node) += rotation6(f).col(p.dof) * p.value;
  }
  return u0;
}

VecX nodal_loads(const Structure& s, const LoadCase& lc) {
  VecX f = VecX::Zero(s.num_dofs());
  for (const auto& l : lc.loads) f.segment<6>(6 * l.node) += l.wrench;
  return f;
}

}  // namespace kinestat::msa
