#include "kinestat/fea/link_stiffness.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <span>
#include <sstream>

#include <sys/resource.h>

#include <fmt/format.h>
#include <tbb/parallel_for.h>

#include "fea/elasticity_assembly.hpp"
#include "kinestat/core/frame.hpp"
#include "kinestat/core/input_checks.hpp"
#include "kinestat/fea/tet_element.hpp"
#include "kinestat/solver/generalized_eigen.hpp"
#include "kinestat/solver/linear_solver_factory.hpp"
#include "kinestat/solver/parallel.hpp"

namespace kinestat::fea {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The peak resident set of this process (getrusage reports it in KiB on Linux).
double peak_memory_bytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return 1024.0 * static_cast<double>(usage.ru_maxrss);
}

// The rigid-body modes of the reduced dofs about `point` (num_dofs x 6, columns ux uy uz rx ry rz):
// a free node moves by u + theta x (x - point), the reference node's six dofs are (u, theta) itself.
// Multigrid backends take them as the near-null space of the unclamped link.
MatX rigid_body_modes(const TetMesh& mesh, const DofMap& map, const Vec3& point) {
  MatX modes = MatX::Zero(map.num_dofs, 6);
  for (int n = 0; n < mesh.num_nodes(); ++n) {
    const DofMap::Terms& t = map.terms[3 * n];
    if (t.count == 1 && (map.reference_dof < 0 || t.index[0] < map.reference_dof))
      modes.middleRows<3>(t.index[0]) = rigid_transfer(mesh.nodes[n] - point).topRows<3>();
  }
  if (map.reference_dof >= 0) modes.middleRows<6>(map.reference_dof).setIdentity();
  return modes;
}

Vec6 symmetric_eigenvalues(const Mat6& A) {
  return Eigen::SelfAdjointEigenSolver<Mat6>(0.5 * (A + A.transpose()), Eigen::EigenvaluesOnly).eigenvalues();
}

// Von Mises stress at each element's centroid for the displacement field u.
std::vector<double> centroid_von_mises(const TetMesh& mesh, const std::vector<Mat6>& D,
                                       const std::vector<int>& material, const std::vector<Vec3>& u) {
  std::vector<double> vm(mesh.num_elements());
  const int npe = mesh.nodes_per_element;
  tbb::parallel_for(0, mesh.num_elements(), [&](int e) {
    std::array<Vec3, 10> x;
    VecX ue(3 * npe);
    const int* v = mesh.element(e);
    for (int a = 0; a < npe; ++a) {
      x[a] = mesh.nodes[v[a]];
      ue.segment<3>(3 * a) = u[v[a]];
    }
    double det = 0.0;
    const MatX B = tet_strain_matrix(x.data(), npe, Vec3::Constant(0.25), &det);
    vm[e] = von_mises(D[material.empty() ? 0 : material[e]] * (B * ue));
  });
  return vm;
}

// Mean length of the elements' corner edges (m): the mesh size the user chose, as meshed.
double mean_edge_length(const TetMesh& mesh) {
  double sum = 0.0;
  for (int e = 0; e < mesh.num_elements(); ++e) {
    const int* v = mesh.element(e);
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b) sum += (mesh.nodes[v[a]] - mesh.nodes[v[b]]).norm();
  }
  return mesh.num_elements() > 0 ? sum / (6.0 * mesh.num_elements()) : 0.0;
}

// A factorization refused for memory, with what fits: the factor's memory grows as dofs^1.43
// (nnz(L) of the bench bars, benchmarks/README.md) and the dofs as h^-3, so the memory as h^-4.3;
// the size that fits keeps a 20 % margin.
Status memory_refusal(const TetMesh& mesh, int dofs, const solver::FactorizationReport& f) {
  const double ratio = f.factor_bytes / f.memory_available_bytes;
  const double h = mean_edge_length(mesh), coarser = std::pow(1.2 * ratio, 1.0 / 4.3);
  return check_size(
      f.factor_bytes * 1e-9, f.memory_available_bytes * 1e-9,
      fmt::format("link stiffness: {} dofs, memory for the Cholesky factor", dofs), "GB (the memory available)",
      fmt::format("a mesh about {:.2g} times coarser would fit (mean edge now {:.3g} mm: --size {:.3g} mm, ~{:.2g} "
                  "dofs), or use the iterative or distributed backend (--solver petsc, docs/fea.md \"Large meshes\")",
                  coarser, h * 1e3, h * coarser * 1e3, dofs / std::pow(coarser, 3.0)));
}

// The modes' checks, before any work: a count in range, a density (a massless link has no
// frequencies), and a backend whose solves the eigensolver can iterate on (a direct one).
Status check_modes_request(const Material& material, const LinkStiffnessOptions& options) {
  if (options.modes == 0) return Status::Ok();
  if (options.modes < 0 || options.modes > kMaxLinkModes)
    return Status::Invalid(
        fmt::format("link modes: {} modes asked for; give a count from 1 to {}", options.modes, kMaxLinkModes));
  if (!(material.density > 0.0) || !std::isfinite(material.density))
    return Status::Invalid(
        fmt::format("link modes: material '{}' has no density (density = {:g} kg/m^3), so the link "
                    "has no mass and no natural frequencies; give the material a density in kg/m^3",
                    material.id, material.density));
  if (!solver::solves_generalized_eigenproblems(options.solver.backend))
    return Status::Invalid(
        fmt::format("link modes: natural frequencies need a direct solver (cholmod, or petsc-mumps on any number "
                    "of MPI ranks): the eigensolver's Krylov iteration assumes exact solves with K, and {} solves "
                    "only to its CG tolerance",
                    solver::backend_name(options.solver.backend)));
  return Status::Ok();
}

// The modes of the clamped link: M q = mu K q for the largest mu = 1/omega^2 (solver/generalized_eigen.hpp)
// with `factor` prepared with K; M and K are lower triangles on the dof map `map`, on `ranks` > 1
// (the distributed assembly) this rank's summands, as `factor` was given K. `F` maps the reference
// point's wrench to the dofs (its transpose gives the reference motion of a stiff body).
Status solve_link_modes(const TetMesh& mesh, const DofMap& map, const solver::SparseMatrix& K,
                        const solver::SparseMatrix& M, const solver::LinearSolver& factor, int ranks, const MatX& F,
                        bool stiff_body, const Vec3& reference_point, int count, bool keep_shapes,
                        std::vector<LinkMode>* modes) {
  auto eig = solver::largest_generalized_eigenpairs(M, K, factor, count);
  if (!eig.ok()) return Status(eig.status().code(), "link modes: " + eig.status().message());
  const auto& [mu, Q] = *eig;
  const MatX R = rigid_body_modes(mesh, map, reference_point).leftCols<3>();  // unit translations x, y, z
  // The products with K and M, whose summands' products add up over the ranks to the whole ones.
  MatX MR = M.selfadjointView<Eigen::Lower>() * R;
  MatX KQ = K.selfadjointView<Eigen::Lower>() * Q, MQ = M.selfadjointView<Eigen::Lower>() * Q;
  if (ranks > 1)
    for (MatX* product : {&MR, &KQ, &MQ})
      if (Status s = solver::sum_over_ranks(std::span(product->data(), product->size())); !s.ok()) return s;
  for (int k = 0; k < mu.size(); ++k) {
    if (!(mu(k) > 1e-12 * mu(0))) continue;  // a massless motion: no frequency
    LinkMode m;
    m.omega = 1.0 / std::sqrt(mu(k));
    m.frequency = m.omega / (2.0 * std::numbers::pi);
    const double scale = 1.0 / std::sqrt(Q.col(k).dot(MQ.col(k)));  // mass-normalized
    VecX q = scale * Q.col(k);
    const VecX Kq = scale * KQ.col(k), Mq = scale * MQ.col(k);
    m.residual = (Kq - m.omega * m.omega * Mq).norm() / Kq.norm();
    if (!(m.residual <= kLinkModeResidualLimit))
      return Status::NotConverged(
          fmt::format("link modes: mode {} ({:.6g} Hz) has the residual ||K q - omega^2 M q|| / "
                      "||K q|| = {:.2e}, above {:g}; the eigensolver did not converge on this "
                      "mesh: ask for fewer modes or remesh",
                      k + 1, m.frequency, m.residual, kLinkModeResidualLimit));
    std::vector<Vec3> u = expand(map, q);
    // The sign is arbitrary: the largest node displacement component is made positive.
    double largest = 0.0;
    for (const Vec3& v : u)
      for (int d = 0; d < 3; ++d)
        if (std::abs(v(d)) > std::abs(largest)) largest = v(d);
    const double sign = largest < 0.0 ? -1.0 : 1.0;
    q *= sign;
    m.reference_motion = stiff_body ? Vec6(F.transpose() * q) : Vec6(q.segment<6>(map.reference_dof));
    m.participation = MR.transpose() * q;
    m.effective_mass = m.participation.cwiseAbs2();
    if (keep_shapes) {
      for (Vec3& v : u) v *= sign;
      m.shape = std::move(u);
    }
    modes->push_back(std::move(m));
  }
  std::sort(modes->begin(), modes->end(), [](const LinkMode& a, const LinkMode& b) { return a.omega < b.omega; });
  if (modes->empty()) return Status::Invalid("link modes: no mode with mass was found; check the material's density");
  return Status::Ok();
}

// A node of a part of the mesh (elements connected through shared nodes) that holds no clamped
// node, or -1 when every part is clamped: two separate solids in one file, say.
int unclamped_part_node(const TetMesh& mesh, const std::vector<int>& clamped) {
  std::vector<int> parent(static_cast<std::size_t>(mesh.num_nodes()));
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&parent](int n) {
    while (parent[n] != n) n = parent[n] = parent[parent[n]];
    return n;
  };
  for (int e = 0; e < mesh.num_elements(); ++e)
    for (int k = 1; k < mesh.nodes_per_element; ++k) parent[root(mesh.element(e)[k])] = root(mesh.element(e)[0]);
  std::vector<char> held(parent.size(), 0);
  for (int n : clamped) held[root(n)] = 1;
  for (int e = 0; e < mesh.num_elements(); ++e)
    if (!held[root(mesh.element(e)[0])]) return mesh.element(e)[0];
  return -1;
}

}  // namespace

const char* reference_model_name(ReferenceModel m) {
  return m == ReferenceModel::kRigidCoupling ? "rigid coupling (exact multipoint constraint)"
                                             : "pseudo-rigid stiff body";
}

double scaled_symmetry_error(const Mat6& A) {
  const Vec6 s = A.diagonal().cwiseAbs().cwiseSqrt().cwiseInverse();
  const Mat6 B = s.asDiagonal() * A * s.asDiagonal();
  return (B - B.transpose()).norm() / B.norm();
}

void set_compliance(LinkStiffness& r, const Mat6& compliance, const Vec3& point) {
  r.compliance_symmetry_error = scaled_symmetry_error(compliance);
  r.stiffness_symmetry_error = scaled_symmetry_error(compliance.inverse());
  r.compliance_eigenvalues = symmetric_eigenvalues(compliance);
  r.cartesian = cartesian_from_compliance(compliance, point, kLinkFrame);
}

StatusOr<LinkStiffness> link_stiffness(const TetMesh& mesh, const Material& material,
                                       const LinkStiffnessOptions& options) {
  if (Status s = validate(mesh); !s.ok()) return s;
  if (!(material.E > 0.0) || !(material.nu() > -1.0 && material.nu() < 0.5))
    return Status::Invalid(fmt::format("material '{}': E = {:g} Pa, nu = {:g}; need E > 0 and -1 < nu < 0.5",
                                       material.id, material.E, material.nu()));
  if (Status s = check_modes_request(material, options); !s.ok()) return s;
  auto progress = [&](const std::string& stage) {
    if (options.progress) options.progress(stage);
  };
  if (Status s = solver::check_backend_built(options.solver.backend); !s.ok()) return s;
  const auto t0 = std::chrono::steady_clock::now();
  LinkStiffness r;
  r.reference_model = options.reference_model;
  r.num_nodes = mesh.num_nodes();
  r.num_elements = mesh.num_elements();
  r.nodes_per_element = mesh.nodes_per_element;

  const std::vector<int> clamped = select_nodes(mesh, options.clamp);
  if (clamped.empty())
    return Status::Invalid("link stiffness: the clamp region (" + options.clamp.describe() +
                           ") contains no mesh node; give a region on the link's origin face");

  std::vector<Mat6> D = {elasticity_matrix(material)};
  std::vector<int> element_material;
  std::vector<int> reference_nodes;
  const bool stiff_body = options.reference_model == ReferenceModel::kStiffBody;
  if (stiff_body) {
    if (!(options.stiff_body_ratio > 1.0 && options.stiff_body_ratio <= kMaxStiffBodyRatio))  // inf is no ratio
      return Status::Invalid(fmt::format("link stiffness: stiff-body ratio {:g} must exceed 1 and be at most {:g}",
                                         options.stiff_body_ratio, kMaxStiffBodyRatio));
    Material body = Material::from_E_nu("pseudo-rigid body", options.stiff_body_ratio * material.E, material.nu());
    D.push_back(elasticity_matrix(body));
    element_material.assign(mesh.num_elements(), 0);
    const double tol = region_tolerance(mesh, options.reference);
    std::vector<char> in_body(mesh.num_nodes(), 0);
    for (int e = 0; e < mesh.num_elements(); ++e) {
      const int* v = mesh.element(e);
      if (std::all_of(v, v + 4, [&](int n) { return options.reference.contains(mesh.nodes[n], tol); })) {
        element_material[e] = 1;
        ++r.num_stiff_elements;
        for (int a = 0; a < mesh.nodes_per_element; ++a) in_body[v[a]] = 1;
      }
    }
    for (int n = 0; n < mesh.num_nodes(); ++n)
      if (in_body[n]) reference_nodes.push_back(n);
    if (reference_nodes.empty())
      return Status::Invalid("link stiffness: no element lies entirely in the reference region (" +
                             options.reference.describe() +
                             "), so there is no pseudo-rigid body; give a box "
                             "around the reference body");
  } else {
    reference_nodes = select_nodes(mesh, options.reference);
    if (reference_nodes.empty())
      return Status::Invalid("link stiffness: the reference region (" + options.reference.describe() +
                             ") contains no mesh node; give a region on the link's reference end");
  }
  std::vector<int> overlap;
  std::set_intersection(clamped.begin(), clamped.end(), reference_nodes.begin(), reference_nodes.end(),
                        std::back_inserter(overlap));
  if (!overlap.empty())
    return Status::Invalid(fmt::format(
        "link stiffness: {} nodes are both clamped and on the reference (first at "
        "({:g}, {:g}, {:g}) m); the clamp and reference regions must not touch",
        overlap.size(), mesh.nodes[overlap[0]].x(), mesh.nodes[overlap[0]].y(), mesh.nodes[overlap[0]].z()));
  // Said before the factorization, which would only find a free motion and blame the clamp.
  if (const int n = unclamped_part_node(mesh, clamped); n >= 0)
    return Status::Singular(fmt::format(
        "link stiffness: the mesh is in separate parts and the one through ({:g}, {:g}, {:g}) m holds no clamped "
        "node: it moves freely; mesh the link as one connected solid, or clamp every part",
        mesh.nodes[n].x(), mesh.nodes[n].y(), mesh.nodes[n].z()));
  r.num_clamped_nodes = static_cast<int>(clamped.size());
  r.num_reference_nodes = static_cast<int>(reference_nodes.size());
  Vec3 reference_point;
  if (options.reference_point) {
    reference_point = *options.reference_point;
  } else {
    // The centre of the nodes' bounding box, not their average: it does not depend on how the
    // mesher spread nodes over the face (the centre of a face, a bore's axis).
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
    for (int n : reference_nodes) {
      lo = lo.cwiseMin(mesh.nodes[n]);
      hi = hi.cwiseMax(mesh.nodes[n]);
    }
    reference_point = 0.5 * (lo + hi);
  }

  const DofMap map = make_dof_map(mesh, clamped, stiff_body ? std::vector<int>{} : reference_nodes, reference_point);
  r.num_dofs = map.num_dofs;
  solver::LinearSolverOptions solver_options = options.solver;
  if (!solver_options.progress) solver_options.progress = options.progress;
  // The multigrid backend's near-null space: the link's rigid-body motions (made only if it asks).
  solver_options.near_null_space = [&] { return rigid_body_modes(mesh, map, reference_point); };
  auto linear_solver = solver::make_linear_solver(solver_options);
  // A distributed backend (PETSc on several MPI ranks): each rank assembles one slab of the link (an
  // equal range of the elements ordered along its longest axis), its summand of K, and the backend
  // adds the summands in its distributed matrix (entries of rows another rank owns are sent to it),
  // so no rank holds all of K. Equal ranges balance the work exactly. Giving each element to the rank
  // owning its lowest row would send fewer entries but, for 10-node elements on two ranks, give rank
  // 0 all of them: an element's lowest row is a vertex's, and the vertices, numbered before the
  // mid-edge nodes (to_quadratic), are far fewer than half.
  const int ranks = linear_solver->summing_ranks(), rank = ranks > 1 ? solver::process_group().rank : 0;
  for (int q = 0; q < ranks; ++q) {
    const auto [first, last] = element_range(mesh.num_elements(), q, ranks);
    r.elements_per_rank.push_back(last - first);
  }
  progress(ranks == 1 ? fmt::format("assembling {} elements", mesh.num_elements())
                      : fmt::format("assembling {} of the {} elements on MPI rank {} of {}", r.elements_per_rank[rank],
                                    mesh.num_elements(), rank, ranks));
  std::vector<int> slab;
  if (ranks > 1) {
    const std::vector<int> order = elements_along_longest_axis(mesh);
    const auto [first, last] = element_range(mesh.num_elements(), rank, ranks);
    slab.assign(order.begin() + first, order.begin() + last);
  }
  solver::SparseMatrix K;
  // A bad element stops the rank that assembles it: every rank stops with it, none waits in Factorize.
  if (Status s = solver::agree_on_status(assemble_stiffness(mesh, D, element_material, map, &K, slab)); !s.ok())
    return s;
  solver::SparseMatrix M;
  if (options.modes > 0) {
    // The same density in the stiff body: it is the link's own material in the reference region.
    // Distributed: this rank's slab, as K (the eigensolver adds the summands as the backend did K's).
    if (Status s = solver::agree_on_status(
            assemble_mass(mesh, {material.density, material.density}, element_material, map, &M, slab));
        !s.ok())
      return s;
    for (int e = 0; e < mesh.num_elements(); ++e) r.mass += material.density * element_volume(mesh, e);
  }
  r.assembly_seconds = seconds_since(t0);

  // Right-hand sides: unit wrenches on the reference node, or spread over the stiff body.
  MatX F = MatX::Zero(map.num_dofs, 6);
  if (stiff_body) {
    Mat6 AtA = Mat6::Zero();
    for (int n : reference_nodes) {
      const Eigen::Matrix<double, 3, 6> A = rigid_transfer(mesh.nodes[n] - reference_point).topRows<3>();
      AtA += A.transpose() * A;
    }
    const Mat6 AtA_inv = AtA.inverse();
    for (int n : reference_nodes) {
      const Eigen::Matrix<double, 3, 6> A = rigid_transfer(mesh.nodes[n] - reference_point).topRows<3>();
      F.middleRows<3>(map.terms[3 * n].index[0]) = A * AtA_inv;  // body nodes are free: one term each
    }
  } else {
    F.middleRows<6>(map.reference_dof).setIdentity();
  }

  progress(fmt::format("analysing {} dofs ({} matrix entries{})", map.num_dofs, K.nonZeros(),
                       ranks == 1 ? "" : " on this rank"));
  r.backend = linear_solver->backend_description();
  if (Status s = linear_solver->FactorizeSum(std::span(&K, 1), &r.factorization); !s.ok()) {
    if (r.factorization.refused_for_memory()) return memory_refusal(mesh, map.num_dofs, r.factorization);
    if (s.code() == StatusCode::kSingular)
      return Status::Singular("link stiffness: the clamped link still has a free motion (" + s.message() +
                              "); the clamp region must hold at least three non-collinear nodes");
    return s;
  }
  // The backend holds its own copy (CHOLMOD's factor, PETSc's rows); the modes multiply by K.
  if (options.modes == 0) solver::SparseMatrix().swap(K);
  progress("solving the six unit load cases");
  const auto t1 = std::chrono::steady_clock::now();
  MatX X;
  if (Status s = linear_solver->Solve(F, &X, &r.solve); !s.ok()) return s;
  set_compliance(r, stiff_body ? Mat6(F.transpose() * X) : Mat6(X.middleRows<6>(map.reference_dof)), reference_point);
  if (options.keep_fields) {
    for (int k = 0; k < 6; ++k) {
      r.displacement[k] = expand(map, X.col(k));
      r.von_mises[k] = centroid_von_mises(mesh, D, element_material, r.displacement[k]);
    }
  }
  r.solve_seconds = seconds_since(t1);
  if (options.modes > 0) {
    progress(fmt::format("the {} lowest natural frequencies (Krylov eigensolver on the factor of K)", options.modes));
    const auto t2 = std::chrono::steady_clock::now();
    if (Status s = solve_link_modes(mesh, map, K, M, *linear_solver, ranks, F, stiff_body, reference_point,
                                    options.modes, options.keep_fields, &r.modes);
        !s.ok())
      return s;
    r.modes_seconds = seconds_since(t2);
  }
  r.peak_memory_bytes = peak_memory_bytes();
  return r;
}

std::string link_stiffness_report(const LinkStiffness& r) {
  std::ostringstream os;
  os << fmt::format("Link stiffness by FEA ({}-node tetrahedra), reference body: {}\n", r.nodes_per_element,
                    reference_model_name(r.reference_model));
  os << fmt::format("  mesh: {} nodes, {} elements; {} clamped nodes, {} reference nodes", r.num_nodes, r.num_elements,
                    r.num_clamped_nodes, r.num_reference_nodes);
  if (r.reference_model == ReferenceModel::kStiffBody)
    os << fmt::format(", {} stiff-body elements", r.num_stiff_elements);
  os << "\n";
  if (!r.backend.empty()) {  // empty for a result read back from the cache
    const solver::FactorizationReport& f = r.factorization;
    os << fmt::format("  solver: {} dofs, {}, ordering {}, nnz(L) = {}\n", r.num_dofs, r.backend, f.ordering,
                      f.nnz_factor);
    if (r.elements_per_rank.size() > 1) {
      os << "  distributed assembly: elements per MPI rank";
      for (int count : r.elements_per_rank) os << fmt::format(" {}", count);
      os << fmt::format(" (rank 0: {:.1f} %)\n", 100.0 * r.elements_per_rank[0] / std::max(1, r.num_elements));
    }
    os << fmt::format(
        "  time: assembly {:.3f} s, analysis {:.3f} s, factorization {:.3f} s ({:.3g} Gflop), "
        "six solves {:.3f} s; peak memory {:.0f} MB\n",
        r.assembly_seconds, f.analyze_seconds, f.factor_seconds, f.flops * 1e-9, r.solve_seconds,
        r.peak_memory_bytes / 1e6);
    if (r.solve.relative_tolerance > 0.0) {
      os << fmt::format("  iterations (Fx Fy Fz Mx My Mz, relative tolerance {:g}):", r.solve.relative_tolerance);
      for (int it : r.solve.iterations) os << fmt::format(" {}", it);
      os << "\n  relative residuals ||b - K x|| / ||b||:";
      for (double res : r.solve.relative_residual) os << fmt::format(" {:.2e}", res);
      os << "\n";
      if (std::any_of(r.solve.relative_residual.begin(), r.solve.relative_residual.end(),
                      [&](double res) { return res > r.solve.relative_tolerance; }))
        os << "  (above the tolerance: round-off bounds the true residual there; restarting CG from its last iterate "
              "stopped halving it)\n";
    }
  }
  os << cartesian_stiffness_report(r.cartesian, "  6x6 of the reference");
  os << fmt::format("  symmetry error (diagonally scaled, Frobenius): compliance {:.2e}, stiffness {:.2e}\n",
                    r.compliance_symmetry_error, r.stiffness_symmetry_error);
  os << "  eigenvalues of C (SI, mixed units):";
  for (int i = 0; i < 6; ++i) os << fmt::format(" {:.5e}", r.compliance_eigenvalues(i));
  os << "\n";
  os << link_modes_report(r);
  return os.str();
}

std::string link_modes_report(const LinkStiffness& r) {
  if (r.modes.empty()) return "";
  std::ostringstream os;
  os << fmt::format("  natural frequencies (clamped link, reference body massless; link mass {:.6g} kg{}):\n", r.mass,
                    r.modes_seconds > 0.0 ? fmt::format(", eigensolver {:.3f} s", r.modes_seconds) : "");
  os << fmt::format("  {:>4} {:>14} {:>26} {:>12}\n", "mode", "frequency (Hz)", "effective mass x, y, z (%)",
                    "residual");
  for (size_t k = 0; k < r.modes.size(); ++k) {
    const LinkMode& m = r.modes[k];
    const Vec3 pct = 100.0 * m.effective_mass / r.mass;
    os << fmt::format("  {:>4} {:>14.6g} {:>8.2f} {:>8.2f} {:>8.2f} {:>12.2e}\n", k + 1, m.frequency, pct(0), pct(1),
                      pct(2), m.residual);
  }
  return os.str();
}

}  // namespace kinestat::fea
