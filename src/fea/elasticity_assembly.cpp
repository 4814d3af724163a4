#include "fea/elasticity_assembly.hpp"

#include <algorithm>
#include <atomic>
#include <limits>
#include <numeric>
#include <type_traits>

#include <fmt/format.h>
#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>

#include "kinestat/core/frame.hpp"
#include "kinestat/fea/tet_element.hpp"

namespace kinestat::fea {

DofMap make_dof_map(const TetMesh& mesh, const std::vector<int>& clamped, const std::vector<int>& coupled,
                    const Vec3& reference_point) {
  enum : char { kFree, kClamped, kCoupled };
  std::vector<char> kind(mesh.num_nodes(), kFree);
  for (int n : clamped) kind[n] = kClamped;
  for (int n : coupled) kind[n] = kCoupled;
  DofMap map;
  map.terms.resize(3 * static_cast<size_t>(mesh.num_nodes()));
  for (int n = 0; n < mesh.num_nodes(); ++n)
    if (kind[n] == kFree)
      for (int d = 0; d < 3; ++d) map.terms[3 * n + d] = {1, {map.num_dofs++, 0, 0}, {1.0, 0.0, 0.0}};
  if (coupled.empty()) return map;
  map.reference_dof = map.num_dofs;
  map.num_dofs += 6;
  for (int n : coupled) {
    // u_node = u_ref + theta x r = [I, -[r]x] (u_ref, theta)
    const Mat3 minus_skew = -skew(mesh.nodes[n] - reference_point);
    for (int d = 0; d < 3; ++d) {
      DofMap::Terms& t = map.terms[3 * n + d];
      t.index[t.count] = map.reference_dof + d;
      t.coef[t.count++] = 1.0;
      for (int r = 0; r < 3; ++r)
        if (minus_skew(d, r) != 0.0) {
          t.index[t.count] = map.reference_dof + 3 + r;
          t.coef[t.count++] = minus_skew(d, r);
        }
    }
  }
  return map;
}

DofMap free_dof_map(const TetMesh& mesh) { return make_dof_map(mesh, {}, {}, Vec3::Zero()); }

std::vector<Vec3> expand(const DofMap& map, const Eigen::Ref<const VecX>& reduced) {
  std::vector<Vec3> u(map.terms.size() / 3, Vec3::Zero());
  for (size_t i = 0; i < map.terms.size(); ++i) {
    const DofMap::Terms& t = map.terms[i];
    for (int k = 0; k < t.count; ++k) u[i / 3](i % 3) += t.coef[k] * reduced(t.index[k]);
  }
  return u;
}

std::vector<int> elements_along_longest_axis(const TetMesh& mesh) {
  Vec3 lo, hi;
  bounding_box(mesh, lo, hi);
  int axis = 0;
  (hi - lo).maxCoeff(&axis);
  std::vector<double> centre(mesh.num_elements());
  for (int e = 0; e < mesh.num_elements(); ++e) {
    const int* v = mesh.element(e);
    centre[e] = mesh.nodes[v[0]](axis) + mesh.nodes[v[1]](axis) + mesh.nodes[v[2]](axis) + mesh.nodes[v[3]](axis);
  }
  std::vector<int> order(mesh.num_elements());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return centre[a] < centre[b]; });
  return order;
}

std::pair<int, int> element_range(int num_elements, int rank, int ranks) {
  auto first = [&](int r) { return static_cast<int>(static_cast<long>(num_elements) * r / ranks); };
  return {first(rank), first(rank + 1)};
}

namespace {

// The reduced dofs in blocks, in dof order: a free node's three (3b, 3b+1, 3b+2: make_dof_map numbers
// them so) and, last, the reference node's six. A mesh node belongs to its own block (free), to the
// reference block (rigidly coupled: its dofs are combinations of the six) or to none (clamped).
struct Blocks {
  int num_free = 0;                // blocks 0 .. num_free-1: free nodes
  int reference = -1;              // block index of the reference node (num_free), -1 if none
  std::vector<int> of_node;        // block of each mesh node, -1 if clamped
  std::vector<int> node_of_free;   // mesh node of each free block
  std::vector<int> coupled_nodes;  // mesh nodes of the reference block

  int count() const { return num_free + (reference >= 0 ? 1 : 0); }
  int size(int b) const { return b == reference ? 6 : 3; }
  int first_dof(int b, int reference_dof) const { return b == reference ? reference_dof : 3 * b; }
  // The compressed column (a, d), the d-th dof of block a, holds rows (a, d..size(a)-1), then every
  // dof of the later blocks of a's list (BlockPattern); this is where the k-th block of the list
  // starts in column (a, 0). Only the reference block has 6 dofs, and it is the last block: it
  // precedes no other.
  int list_offset(int a, int k) const { return k == 0 ? 0 : size(a) + 3 * (k - 1); }
};

Blocks make_blocks(const TetMesh& mesh, const DofMap& map) {
  Blocks b;
  b.num_free = map.reference_dof >= 0 ? map.reference_dof / 3 : map.num_dofs / 3;
  if (map.reference_dof >= 0) b.reference = b.num_free;
  b.of_node.assign(mesh.num_nodes(), -1);
  b.node_of_free.assign(b.num_free, -1);
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    const DofMap::Terms& t = map.terms[3 * n];
    if (t.count == 0) continue;
    if (t.count == 1 && (map.reference_dof < 0 || t.index[0] < map.reference_dof)) {
      b.of_node[n] = t.index[0] / 3;
      b.node_of_free[t.index[0] / 3] = n;
    } else {
      b.of_node[n] = b.reference;
      b.coupled_nodes.push_back(n);
    }
  }
  return b;
}

// The elements to assemble: a list of indices, or all of them (empty list).
struct ElementSet {
  std::span<const int> list;
  int num_elements = 0;
  int size() const { return list.empty() ? num_elements : static_cast<int>(list.size()); }
  int operator[](int k) const { return list.empty() ? k : list[k]; }
};

// The elements of `set` around each node (compressed rows).
struct NodeElements {
  std::vector<long> start;
  std::vector<int> element;
};

NodeElements node_elements(const TetMesh& mesh, const ElementSet& set) {
  NodeElements ne;
  const int npe = mesh.nodes_per_element;
  ne.start.assign(mesh.num_nodes() + 1, 0);
  for (int k = 0; k < set.size(); ++k)
    for (int a = 0; a < npe; ++a) ++ne.start[mesh.element(set[k])[a] + 1];
  for (int n = 0; n < mesh.num_nodes(); ++n) ne.start[n + 1] += ne.start[n];
  ne.element.resize(ne.start.back());
  std::vector<long> next(ne.start.begin(), ne.start.end() - 1);
  for (int k = 0; k < set.size(); ++k)
    for (int a = 0; a < npe; ++a) ne.element[next[mesh.element(set[k])[a]]++] = set[k];
  return ne;
}

// The lower triangle's sparsity by blocks: for each block a, the blocks c >= a that share an
// element with it, ascending (a itself first).
struct BlockPattern {
  std::vector<long> start;
  std::vector<int> block;
  // Index of block c in a's list (binary search; the lists hold a few dozen blocks).
  int find(int a, int c) const {
    const int* first = block.data() + start[a];
    const int* last = block.data() + start[a + 1];
    return static_cast<int>(std::lower_bound(first, last, c) - first);
  }
};

BlockPattern block_pattern(const TetMesh& mesh, const Blocks& blocks, const ElementSet& set) {
  const NodeElements ne = node_elements(mesh, set);
  const int npe = mesh.nodes_per_element, nb = blocks.count();
  // Two passes (count, then fill) over the same neighbour sets: no per-block vectors at 1M blocks.
  auto neighbours = [&](int a, std::vector<int>& out) {
    out.clear();
    auto add_node = [&](int n) {
      for (long k = ne.start[n]; k < ne.start[n + 1]; ++k) {
        const int* v = mesh.element(ne.element[k]);
        for (int i = 0; i < npe; ++i)
          if (const int c = blocks.of_node[v[i]]; c >= a) out.push_back(c);
      }
    };
    if (a == blocks.reference)
      for (int n : blocks.coupled_nodes) add_node(n);
    else
      add_node(blocks.node_of_free[a]);
    if (out.empty()) out.push_back(a);  // a node in none of the elements: its diagonal block only
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
  };
  BlockPattern p;
  p.start.assign(nb + 1, 0);
  tbb::enumerable_thread_specific<std::vector<int>> scratch;
  tbb::parallel_for(0, nb, [&](int a) {
    neighbours(a, scratch.local());
    p.start[a + 1] = static_cast<long>(scratch.local().size());
  });
  for (int a = 0; a < nb; ++a) p.start[a + 1] += p.start[a];
  p.block.resize(p.start[nb]);
  tbb::parallel_for(0, nb, [&](int a) {
    neighbours(a, scratch.local());
    std::copy(scratch.local().begin(), scratch.local().end(), p.block.begin() + p.start[a]);
  });
  return p;
}

// Adds every element's T_e^T K_e T_e into the compressed columns laid out by `pattern` (lower
// triangle only: all the Cholesky reads). Entries shared with elements on other threads: atomic
// adds (rarely contended). K_e is the stiffness or the mass: `element_matrix(e, x, &Ke)` computes it
// (false: a non-positive Jacobian).
struct ElementScatter {
  const TetMesh& mesh;
  const DofMap& map;
  const Blocks& blocks;
  const BlockPattern& pattern;
  const int* outer;
  double* values;

  template <int N, class ElementMatrix>
  void add_elements(const ElementSet& set, std::atomic<int>& bad_element, const ElementMatrix& element_matrix) const {
    const int ref_dof = map.reference_dof;
    tbb::parallel_for(tbb::blocked_range<int>(0, set.size(), 256), [&](const tbb::blocked_range<int>& range) {
      std::array<Vec3, N> x;
      std::array<int, N> node_block;
      std::array<std::array<int, N>, N> k_of{};  // k_of[p][q]: place of node q's block in node p's block's list
      TetMatrix<N> Ke;
      for (int k = range.begin(); k != range.end(); ++k) {
        const int e = set[k];
        const int* v = mesh.element(e);
        for (int a = 0; a < N; ++a) x[a] = mesh.nodes[v[a]], node_block[a] = blocks.of_node[v[a]];
        if (!element_matrix(e, x.data(), &Ke)) {
          bad_element = e;
          continue;
        }
        for (int p = 0; p < N; ++p)
          for (int q = 0; q < N; ++q)
            if (node_block[p] >= 0 && node_block[q] >= node_block[p])
              k_of[p][q] = pattern.find(node_block[p], node_block[q]);
        for (int i = 0; i < 3 * N; ++i) {
          const DofMap::Terms& ti = map.terms[3 * v[i / 3] + i % 3];
          for (int j = 0; j < 3 * N; ++j) {
            const DofMap::Terms& tj = map.terms[3 * v[j / 3] + j % 3];
            for (int a = 0; a < ti.count; ++a)
              for (int b = 0; b < tj.count; ++b) {
                const int row = ti.index[a], col = tj.index[b];
                if (row < col) continue;
                // Column in node j/3's block, row in node i/3's: the same block or a later one.
                const int cb = node_block[j / 3], rb = node_block[i / 3];
                const long pos = outer[col] + blocks.list_offset(cb, k_of[j / 3][i / 3]) +
                                 (row - blocks.first_dof(rb, ref_dof)) - (col - blocks.first_dof(cb, ref_dof));
                std::atomic_ref<double>(values[pos])
                    .fetch_add(ti.coef[a] * tj.coef[b] * Ke(i, j), std::memory_order_relaxed);
              }
          }
        }
      }
    });
  }
};

// The reduced matrix sum_e T_e^T K_e T_e (lower triangle, compressed columns) of the element matrices
// `element_matrix` computes: the stiffness and the mass share this and so their pattern.
template <class ElementMatrix>
Status assemble_elements(const TetMesh& mesh, const DofMap& map, solver::SparseMatrix* matrix,
                         std::span<const int> elements, const ElementMatrix& element_matrix) {
  const ElementSet set{elements, mesh.num_elements()};
  // Straight into compressed columns: the pattern first (from the blocks' adjacency), then every
  // element adds its entries in place. Triplets would hold ~465 entries of 16 bytes per Tet10
  // element and a sorted copy (5 GB and more at 3M dofs, and the fresh memory's page faults at any
  // size: benchmarks/README.md, "Factorization rate"); the matrix itself holds 12 bytes per entry.
  const Blocks blocks = make_blocks(mesh, map);
  const BlockPattern pattern = block_pattern(mesh, blocks, set);
  const int n = map.num_dofs, nb = blocks.count();
  const int ref_dof = map.reference_dof;

  solver::SparseMatrix& K = *matrix;
  K.resize(n, n);
  int* outer = K.outerIndexPtr();
  outer[0] = 0;
  for (int a = 0; a < nb; ++a) {
    const int k_end = static_cast<int>(pattern.start[a + 1] - pattern.start[a]);
    const int column_length = blocks.list_offset(a, k_end - 1) + blocks.size(pattern.block[pattern.start[a + 1] - 1]);
    const int first = blocks.first_dof(a, ref_dof);
    for (int d = 0; d < blocks.size(a); ++d) {
      const long next = static_cast<long>(outer[first + d]) + column_length - d;
      if (next > std::numeric_limits<int>::max())
        return Status::Invalid(
            fmt::format("stiffness assembly: more than {} matrix entries (32-bit indices); "
                        "use a coarser mesh",
                        std::numeric_limits<int>::max()));
      outer[first + d + 1] = static_cast<int>(next);
    }
  }
  K.resizeNonZeros(outer[n]);
  // Indices and zeros written in parallel: the first touch of these pages is spread over the cores.
  tbb::parallel_for(0, nb, [&](int a) {
    const int first = blocks.first_dof(a, ref_dof);
    for (int d = 0; d < blocks.size(a); ++d) {
      int* rows = K.innerIndexPtr() + outer[first + d];
      std::fill(K.valuePtr() + outer[first + d], K.valuePtr() + outer[first + d + 1], 0.0);
      for (int r = first + d; r < first + blocks.size(a); ++r) *rows++ = r;
      for (long k = pattern.start[a] + 1; k < pattern.start[a + 1]; ++k) {
        const int c = pattern.block[k], c_first = blocks.first_dof(c, ref_dof);
        for (int r = 0; r < blocks.size(c); ++r) *rows++ = c_first + r;
      }
    }
  });

  std::atomic<int> bad_element{-1};
  const ElementScatter scatter{mesh, map, blocks, pattern, K.outerIndexPtr(), K.valuePtr()};
  if (mesh.quadratic())
    scatter.add_elements<10>(set, bad_element, element_matrix);
  else
    scatter.add_elements<4>(set, bad_element, element_matrix);
  if (bad_element >= 0)
    return Status::Invalid(
        fmt::format("tetrahedral mesh: element {} has a non-positive Jacobian (inverted or "
                    "degenerate); remesh the link",
                    bad_element.load()));
  return Status::Ok();
}

// The number of nodes of the element matrix type TetMatrix<N>.
template <class Matrix>
constexpr int nodes_of = std::remove_pointer_t<Matrix>::RowsAtCompileTime / 3;

}  // namespace

Status assemble_stiffness(const TetMesh& mesh, const std::vector<Mat6>& D, const std::vector<int>& material,
                          const DofMap& map, solver::SparseMatrix* stiffness, std::span<const int> elements) {
  return assemble_elements(mesh, map, stiffness, elements, [&](int e, const Vec3* x, auto* Ke) {
    return tet_stiffness<nodes_of<decltype(Ke)>>(x, D[material.empty() ? 0 : material[e]], Ke);
  });
}

Status assemble_mass(const TetMesh& mesh, const std::vector<double>& density, const std::vector<int>& material,
                     const DofMap& map, solver::SparseMatrix* mass, std::span<const int> elements) {
  return assemble_elements(mesh, map, mass, elements, [&](int e, const Vec3* x, auto* Me) {
    return tet_mass<nodes_of<decltype(Me)>>(x, density[material.empty() ? 0 : material[e]], Me);
  });
}

}  // namespace kinestat::fea
