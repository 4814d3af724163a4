#include "msa/dof_map.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <map>

#include <Eigen/QR>

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

// The loops' ties: each tied component's constraint e_i^T R^T (u_s - A u_m) = 0 over the tree's
// unknowns q (rows G), length-scaled (rotations times the structure's size) so that one threshold
// ranks them; the independent rows (a column-pivoted QR of G^T) solved for as many unknowns (the
// pivots of a column-pivoted QR of those rows), q_p = -F q_rest, so that u = C T q_rest.
void eliminate_loops(const Structure& s, const std::vector<int>& loop_ties, const std::vector<NodeRows>& rows,
                     DofMap& map) {
  const int n = static_cast<int>(map.C.cols());
  const double L = s.length_scale();
  auto dense = [&](int node) {
    MatX D = MatX::Zero(6, n);
    for (int row = 0; row < 6; ++row)
      for (const auto& [col, v] : rows[node][row]) D(row, col) += v;
    return D;
  };
  std::vector<DofMap::LoopRow> all;
  std::vector<VecX> g;
  for (int t : loop_ties) {
    const auto& tie = map.ties[t];
    const MatX D = rotation6(tie.frame).transpose() * (dense(tie.slave) - tie_transfer(s, tie) * dense(tie.master));
    for (int i = 0; i < 6; ++i)
      if (tie.mask[i]) {
        all.push_back({t, i});
        g.push_back(D.row(i).transpose());
      }
  }
  VecX column_scale(n);
  for (int j = 0; j < n; ++j) column_scale(j) = map.reduced[j].component >= 3 ? 1.0 / L : 1.0;
  MatX G(static_cast<int>(all.size()), n), scaled(static_cast<int>(all.size()), n);
  for (std::size_t k = 0; k < all.size(); ++k) {
    G.row(static_cast<int>(k)) = g[k].transpose();
    scaled.row(static_cast<int>(k)) = (all[k].component >= 3 ? L : 1.0) * g[k].cwiseProduct(column_scale).transpose();
  }
  Eigen::ColPivHouseholderQR<MatX> by_rows;
  by_rows.setThreshold(1e-10).compute(scaled.transpose());
  const int r = static_cast<int>(by_rows.rank());
  if (r == 0) return;  // every loop constraint holds already (redundant ties)
  std::vector<int> independent(r);
  for (int k = 0; k < r; ++k) independent[k] = by_rows.colsPermutation().indices()(k);
  std::sort(independent.begin(), independent.end());
  MatX Gs(r, n);
  for (int k = 0; k < r; ++k) Gs.row(k) = scaled.row(independent[k]);
  Eigen::ColPivHouseholderQR<MatX> by_columns;
  by_columns.setThreshold(1e-10).compute(Gs);
  std::vector<bool> pivot(n, false);
  std::vector<int> pivots(r), rest;
  for (int k = 0; k < r; ++k) pivot[pivots[k] = by_columns.colsPermutation().indices()(k)] = true;
  for (int j = 0; j < n; ++j)
    if (!pivot[j]) rest.push_back(j);
  MatX Gp(r, r), Gr(r, static_cast<int>(rest.size()));
  for (int k = 0; k < r; ++k) Gp.col(k) = Gs.col(pivots[k]);
  for (std::size_t k = 0; k < rest.size(); ++k) Gr.col(static_cast<int>(k)) = Gs.col(rest[k]);
  const MatX F = Gp.partialPivLu().solve(Gr);  // scaled: q~_p = -F q~_rest, q = q~ .* column_scale
  // u = C q with q_rest the new unknowns: C T, T's pivot rows -F (unscaled), its other rows the identity.
  std::vector<int> new_index(n, -1), pivot_row(n, -1);
  for (std::size_t k = 0; k < rest.size(); ++k) new_index[rest[k]] = static_cast<int>(k);
  for (int k = 0; k < r; ++k) pivot_row[pivots[k]] = k;
  std::vector<Eigen::Triplet<double>> trip;
  for (int col = 0; col < n; ++col)
    for (solver::SparseMatrix::InnerIterator it(map.C, col); it; ++it) {
      if (new_index[col] >= 0) {
        trip.emplace_back(static_cast<int>(it.row()), new_index[col], it.value());
        continue;
      }
      const int k = pivot_row[col];
      for (std::size_t j = 0; j < rest.size(); ++j)
        if (F(k, static_cast<int>(j)) != 0.0)
          trip.emplace_back(static_cast<int>(it.row()), static_cast<int>(j),
                            -it.value() * column_scale(col) * F(k, static_cast<int>(j)) / column_scale(rest[j]));
    }
  map.tree_C = map.C;
  map.C = solver::SparseMatrix(map.C.rows(), static_cast<int>(rest.size()));
  map.C.setFromTriplets(trip.begin(), trip.end());
  std::vector<ReducedDof> reduced;
  for (int j : rest) reduced.push_back(map.reduced[j]);
  map.reduced = std::move(reduced);
  map.loop_G.resize(r, n);
  for (int k = 0; k < r; ++k) {
    map.loop_rows.push_back(all[independent[k]]);
    map.loop_G.row(k) = G.row(independent[k]);
  }
}

}  // namespace

Mat6 tie_transfer(const Structure& s, const DofMap::Tie& tie) {
  return rigid_transfer(s.nodes()[tie.slave].position - s.nodes()[tie.master].position);
}

Mat6 tied_transfer(const Structure& s, const DofMap::Tie& tie) {
  const Mat6 R = rotation6(tie.frame);
  return R * mask_projector(tie.mask, true) * R.transpose() * tie_transfer(s, tie);
}

std::vector<int> tied_nodes_by_depth(const DofMap& map) {
  std::vector<std::pair<int, int>> order;  // (depth, node)
  for (int n = 0; n < static_cast<int>(map.slave_of_tie.size()); ++n) {
    int depth = 0;
    for (int m = n; map.slave_of_tie[m] >= 0; m = map.ties[map.slave_of_tie[m]].master) ++depth;
    if (depth > 0) order.emplace_back(depth, n);
  }
  std::sort(order.begin(), order.end());
  std::vector<int> nodes;
  for (const auto& [depth, n] : order) nodes.push_back(n);
  return nodes;
}

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
  // A tie whose slave is tied already, or whose master hangs from its slave through the masters'
  // ties, closes a loop of ties: a constraint on the tree's unknowns (below).
  std::vector<int> loop_ties;
  for (size_t t = 0; t < map.ties.size(); ++t) {
    const auto& tie = map.ties[t];
    bool loop = map.slave_of_tie[tie.slave] >= 0;
    for (int m = tie.master; !loop && m >= 0; m = map.slave_of_tie[m] >= 0 ? map.ties[map.slave_of_tie[m]].master : -1)
      loop = m == tie.slave;
    if (loop)
      loop_ties.push_back(static_cast<int>(t));
    else
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
      const Mat6 M = tied_transfer(s, tie);
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
  if (!loop_ties.empty()) eliminate_loops(s, loop_ties, rows, map);
  return map;
}

VecX remove_loop_forces(const Structure& s, const DofMap& map, const VecX& residual, VecX& forces) {
  forces = VecX::Zero(static_cast<int>(map.loop_rows.size()));
  if (map.loop_rows.empty()) return residual;
  // tree_C^T r = loop_G^T forces: the loops' forces are what the tree's unknowns do not balance.
  const VecX b = map.tree_C.transpose() * residual;
  forces = MatX(map.loop_G.transpose()).colPivHouseholderQr().solve(b);
  VecX out = residual;
  for (std::size_t k = 0; k < map.loop_rows.size(); ++k) {
    const auto& tie = map.ties[map.loop_rows[k].tie];
    const Vec6 on_slave = rotation6(tie.frame).col(map.loop_rows[k].component) * forces(static_cast<int>(k));
    out.segment<6>(6 * tie.slave) -= on_slave;
    out.segment<6>(6 * tie.master) += tie_transfer(s, tie).transpose() * on_slave;
  }
  return out;
}

VecX prescribed_displacements(const Structure& s, const DofMap& map, const LoadCase& lc) {
  VecX u0 = VecX::Zero(s.num_dofs());
  if (lc.prescribed.empty()) return u0;
  for (const auto& p : lc.prescribed) {
    Mat3 f = Mat3::Identity();
    for (const auto& sup : s.supports())
      if (sup.node == p.node) f = sup.frame;
    u0.segment<6>(6 * p.node) += rotation6(f).col(p.dof) * p.value;
  }
  for (int n : tied_nodes_by_depth(map)) {  // down the trees of ties
    const auto& tie = map.ties[map.slave_of_tie[n]];
    u0.segment<6>(6 * n) += tied_transfer(s, tie) * u0.segment<6>(6 * tie.master);
  }
  if (map.loop_rows.empty()) return u0;
  VecX c(static_cast<int>(map.loop_rows.size()));
  for (std::size_t k = 0; k < map.loop_rows.size(); ++k) {
    const auto& tie = map.ties[map.loop_rows[k].tie];
    const Vec6 gap = u0.segment<6>(6 * tie.slave) - tie_transfer(s, tie) * u0.segment<6>(6 * tie.master);
    c(static_cast<int>(k)) = rotation6(tie.frame).col(map.loop_rows[k].component).dot(gap);
  }
  const VecX dq = map.loop_G.colPivHouseholderQr().solve(-c);
  return u0 + map.tree_C * dq;
}

VecX nodal_loads(const Structure& s, const LoadCase& lc) {
  VecX f = VecX::Zero(s.num_dofs());
  for (const auto& l : lc.loads) f.segment<6>(6 * l.node) += l.wrench;
  return f;
}

}  // namespace kinestat::msa
