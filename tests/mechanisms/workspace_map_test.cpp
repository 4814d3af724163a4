// Workspace maps: the grid, the fields against single-posture solves (msa::solve, the VJM), the
// five-bar's mirror symmetry, its singular loci against the closed-form conditions, and the
// Orthoglide in loaded mode against per-point loaded solves.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>

#include "kinestat/core/stiffness_indices.hpp"
#include "kinestat/mechanisms/five_bar_kernel.hpp"
#include "kinestat/mechanisms/five_bar_loci.hpp"
#include "kinestat/mechanisms/five_bar_vjm.hpp"
#include "kinestat/mechanisms/orthoglide_kernel.hpp"
#include "kinestat/mechanisms/orthoglide_kinematics.hpp"
#include "kinestat/mechanisms/workspace_map.hpp"
#include "kinestat/msa/static_analysis.hpp"
#include "kinestat/vjm/stiffness.hpp"

namespace kinestat::mechanisms {
namespace {

// The map fields of a 6x6 stiffness computed without the map code: the general indices of
// core/stiffness_indices.hpp, and the directional stiffnesses as the Schur complements of K (the
// map inverts the compliance blocks instead).
std::array<double, kNumMapFields> expected_fields(const Mat6& K, const Vec6& deflection, double measure) {
  const StiffnessIndices ix = stiffness_indices(MatX(K));
  const auto schur_eigenvalues = [](const Mat3& a, const Mat3& b, const Mat3& c, const Mat3& d) -> Vec3 {
    const Mat3 s = a - b * d.inverse() * c;
    return Eigen::SelfAdjointEigenSolver<Mat3>(0.5 * (s + s.transpose())).eigenvalues();
  };
  const Mat3 Ktt = K.topLeftCorner<3, 3>(), Ktr = K.topRightCorner<3, 3>(), Krt = K.bottomLeftCorner<3, 3>(),
             Krr = K.bottomRightCorner<3, 3>();
  const Vec3 t = schur_eigenvalues(Ktt, Ktr, Krt, Krr);
  const Vec3 r = schur_eigenvalues(Krr, Krt, Ktr, Ktt);
  return {t(0),
          t(2),
          r(0),
          r(2),
          ix.trace,
          ix.norm_1,
          ix.norm_2,
          ix.norm_frobenius,
          ix.norm_inf,
          ix.condition_number,
          ix.log10_abs_det,
          deflection.head<3>().norm(),
          deflection.tail<3>().norm(),
          measure};
}

void expect_point_fields(const WorkspaceMap& map, std::size_t i, const std::array<double, kNumMapFields>& want,
                         double rel) {
  for (const FieldValues& f : map.fields) {
    const double w = want[static_cast<int>(f.field)];
    EXPECT_NEAR(f.values[i], w, rel * std::abs(w)) << field_info(f.field).name << " at point " << i;
  }
}

void expect_no_values(const WorkspaceMap& map, std::size_t i, bool keeps_measure) {
  for (const FieldValues& f : map.fields) {
    if (keeps_measure && f.field == MapField::kSingularityMeasure) {
      EXPECT_TRUE(std::isfinite(f.values[i])) << i;
    } else {
      EXPECT_TRUE(std::isnan(f.values[i])) << field_info(f.field).name << " at point " << i;
    }
  }
}

MapGrid plane_grid(double x0, double x1, double y0, double y1, double step) {
  auto g = make_map_grid({MapRange{x0, x1}, MapRange{y0, y1}, MapRange{}}, step, 1'000'000);
  EXPECT_TRUE(g.ok()) << g.status().message();
  return *g;
}

TEST(MapGrid, PointsSpacingSlicesAndRefusals) {
  auto g = make_map_grid({MapRange{-0.1, 0.1}, MapRange{0.0, 0.05}, MapRange{0.02, 0.02}}, 0.025, 1000);
  ASSERT_TRUE(g.ok()) << g.status().message();
  EXPECT_EQ(g->dimensions, (std::array<int, 3>{9, 3, 1}));
  EXPECT_EQ(g->num_points(), 27u);
  EXPECT_EQ(g->num_varying_axes(), 2);
  EXPECT_NEAR(g->cell_measure(), 0.025 * 0.025, 1e-18);
  const Vec3 last = g->point(26);
  EXPECT_NEAR(last.x(), 0.1, 1e-15);
  EXPECT_NEAR(last.y(), 0.05, 1e-15);
  EXPECT_EQ(last.z(), 0.02);
  EXPECT_EQ(g->point(9 + 4), Vec3(-0.1 + 4 * 0.025, 0.025, 0.02));
  // A range that is not a multiple of the step stops at the last point inside it.
  EXPECT_EQ(map_axis_points(MapRange{0.0, 0.06}, 0.025), 3.0);

  EXPECT_FALSE(make_map_grid({MapRange{0.1, -0.1}, MapRange{0, 1}, MapRange{}}, 0.1, 1000).ok());
  EXPECT_FALSE(make_map_grid({MapRange{0, 1}, MapRange{0, 1}, MapRange{}}, 0.0, 1000).ok());
  EXPECT_FALSE(make_map_grid({MapRange{0, 1}, MapRange{}, MapRange{}}, 0.1, 1000).ok());  // a line, not a map
  auto big = make_map_grid({MapRange{0, 1}, MapRange{0, 1}, MapRange{0, 1}}, 1e-4, 1'000'000);
  ASSERT_FALSE(big.ok());
  EXPECT_NE(big.status().message().find("1e+12 points"), std::string::npos) << big.status().message();
}

// The fields of every reachable point equal those of one msa::solve of the posture (the `kinestat
// fivebar` path), and the deflection under the load equals the solve's compliance times the load.
TEST(FiveBarMap, EqualsSingleMsaSolvesAndMarksUnreachablePoints) {
  FiveBarKernelOptions o;
  o.mode = {1, -1};
  o.load << 3.0, -2.0, 1.0, 0.05, -0.02, 0.1;
  MapOptions mo;
  mo.with_deflection = true;
  mo.min_stiffness = 8e3;
  const MapGrid grid = plane_grid(-0.2, 0.2, -0.1, 0.2, 0.02);
  auto map = compute_workspace_map(*make_reference_five_bar_kernel(o), grid, mo);
  ASSERT_TRUE(map.ok()) << map.status().message();
  std::size_t ok = 0, unreachable = 0, stiff = 0;
  for (std::size_t i = 0; i < grid.num_points(); ++i) {
    const Vec3 x = grid.point(i);
    auto q = inverse_kinematics(o.params, Vec2(x.x(), x.y()), o.mode);
    if (!q.ok() || q->assembly != o.assembly) {
      EXPECT_EQ(map->status[i], PostureStatus::kUnreachable) << i;
      expect_no_values(*map, i, false);
      ++unreachable;
      continue;
    }
    const msa::Solution sol = msa::solve(make_five_bar_structure(o.params, *q));
    if (!sol.status.ok() || !sol.cartesian || !sol.cartesian->stiffness_defined) {
      EXPECT_EQ(map->status[i], PostureStatus::kSingular) << i;
      expect_no_values(*map, i, true);
      continue;
    }
    const FiveBarJacobians jac = five_bar_jacobians(*q);
    const double measure = std::min(jac.parallel_measure, jac.serial_measure);
    EXPECT_EQ(map->status[i], measure < mo.near_singular_threshold ? PostureStatus::kNearSingular : PostureStatus::kOk);
    const auto want = expected_fields(sol.cartesian->stiffness, sol.cartesian->compliance * o.load, measure);
    expect_point_fields(*map, i, want, 1e-9);
    ++ok;
    if (want[0] >= *mo.min_stiffness) ++stiff;
  }
  EXPECT_GT(ok, 20u);
  EXPECT_GT(unreachable, 20u);
  EXPECT_EQ(map->status_counts[1], unreachable);
  EXPECT_NEAR(map->reachable_measure, (grid.num_points() - unreachable) * 0.02 * 0.02, 1e-12);
  EXPECT_GT(stiff, 0u);
  EXPECT_LT(stiff, ok);
  EXPECT_NEAR(map->stiff_measure, stiff * 0.02 * 0.02, 1e-12);

  // The summary's minimum is a value of the field, found where it is.
  const FieldValues* kt = map->find(MapField::kTranslationalMin);
  ASSERT_NE(kt, nullptr);
  const auto at = std::min_element(kt->values.begin(), kt->values.end(),
                                   [](double a, double b) { return std::isnan(b) || (!std::isnan(a) && a < b); });
  EXPECT_EQ(kt->summary.min, *at);
  EXPECT_EQ(kt->summary.argmin, grid.point(at - kt->values.begin()));
}

TEST(FiveBarMap, VjmMethodEqualsTheVjmOfEachPosture) {
  FiveBarKernelOptions o;
  o.method = StiffnessMethod::kVjm;
  const MapGrid grid = plane_grid(-0.1, 0.1, 0.05, 0.2, 0.05);
  auto map = compute_workspace_map(*make_reference_five_bar_kernel(o), grid);
  ASSERT_TRUE(map.ok());
  EXPECT_EQ(map->find(MapField::kDeflectionTranslation), nullptr);  // no load, no deflection fields
  int compared = 0;
  for (std::size_t i = 0; i < grid.num_points(); ++i) {
    if (!has_values(map->status[i])) continue;
    const Vec3 x = grid.point(i);
    auto q = inverse_kinematics(o.params, Vec2(x.x(), x.y()), o.mode);
    ASSERT_TRUE(q.ok());
    auto K = vjm::platform_unloaded_stiffness(five_bar_vjm_chains(o.params, *q));
    ASSERT_TRUE(K.ok() && K->compliance_defined);
    const FiveBarJacobians jac = five_bar_jacobians(*q);
    expect_point_fields(
        *map, i, expected_fields(K->stiffness, Vec6::Zero(), std::min(jac.parallel_measure, jac.serial_measure)), 1e-9);
    ++compared;
  }
  EXPECT_GT(compared, 5);
}

// x -> -x swaps the legs and turns a clockwise bend into a counter-clockwise one: working mode
// (s1, s2) becomes (-s2, -s1), the assembly mode stays, and a force (Fx, Fy) becomes (-Fx, Fy). What
// a force at P meets is then mirrored: k_t_min, k_t_max, the deflection under the force, the
// singularity measure, the status. (The 6x6 at the report node is not: that node is P on link PB2,
// whose mirror is P on B1P, so the rotation about z, and with it the indices of the whole 6x6 and the
// rotational fields, belong to another link. And the translations of P on B1P and on PB2 differ by
// the compliance of the joint spring at P, 1/k_j: a relative change of up to k_t_max / k_j in the
// stiffnesses and the deflection, twice that between the two maps, the tolerance besides round-off.)
TEST(FiveBarMap, MirrorSymmetricWithTheMirroredWorkingMode) {
  FiveBarKernelOptions o;
  o.mode = {1, 1};
  o.load << 2.0, 1.0, 0.0, 0.0, 0.0, 0.0;
  FiveBarKernelOptions mirrored = o;
  mirrored.mode = {-1, -1};
  mirrored.load(0) = -o.load(0);
  MapOptions mo;
  mo.with_deflection = true;
  const MapGrid grid = plane_grid(-0.19, 0.19, -0.19, 0.19, 0.02);  // x = 0 would sit on B1 = B2
  auto a = compute_workspace_map(*make_five_bar_kernel(o), grid, mo);
  auto b = compute_workspace_map(*make_five_bar_kernel(mirrored), grid, mo);
  ASSERT_TRUE(a.ok() && b.ok());
  const int nx = grid.dimensions[0], ny = grid.dimensions[1];
  int with_values = 0;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const std::size_t p = i + nx * j, m = (nx - 1 - i) + nx * j;
      ASSERT_EQ(a->status[p], b->status[m]) << "point (" << i << ", " << j << ")";
      if (!has_values(a->status[p])) continue;
      ++with_values;
      const double rel = 1e-9 + 2 * a->find(MapField::kTranslationalMax)->values[p] / o.params.joint_stiffness(0);
      for (const MapField f : {MapField::kTranslationalMin, MapField::kTranslationalMax,
                               MapField::kDeflectionTranslation, MapField::kSingularityMeasure}) {
        const double va = a->find(f)->values[p], vb = b->find(f)->values[m];
        EXPECT_NEAR(va, vb, rel * std::abs(va)) << field_info(f).name << " at (" << i << ", " << j << ")";
      }
    }
  EXPECT_GT(with_values, 50);
  // The mode is not its own mirror: without the mirror the two maps differ.
  EXPECT_NE(a->status, b->status);
}

double distance_to_segment(const Vec2& p, const Vec2& a, const Vec2& b) {
  const Vec2 d = b - a;
  const double t = d.squaredNorm() > 0 ? std::clamp((p - a).dot(d) / d.squaredNorm(), 0.0, 1.0) : 0.0;
  return (p - (a + t * d)).norm();
}

double distance_to_curves(const std::vector<MapCurve>& curves, const Vec2& p) {
  double best = std::numeric_limits<double>::infinity();
  for (const MapCurve& c : curves)
    for (const auto& line : c.lines)
      for (std::size_t k = 0; k + 1 < line.size(); ++k)
        best = std::min(best, distance_to_segment(p, line[k].head<2>(), line[k + 1].head<2>()));
  return best;
}

// Every locus point meets its closed-form condition, checked through the inverse kinematics (an
// independent route from the loci's own construction).
TEST(FiveBarLoci, PointsMeetTheClosedFormConditions) {
  const FiveBarParams p;
  for (const WorkingMode mode : {WorkingMode{1, 1}, WorkingMode{1, -1}})
    for (const Assembly assembly : {Assembly::kUp, Assembly::kDown}) {
      const std::vector<MapCurve> loci = five_bar_singular_loci(p, mode, assembly, 512);
      ASSERT_EQ(loci.size(), 2u);
      ASSERT_FALSE(loci[0].lines.empty());
      for (const auto& line : loci[0].lines)
        for (const Vec3& P : line) {
          const double d1 = (P.head<2>() - Vec2(-p.r3, 0)).norm(), d2 = (P.head<2>() - Vec2(p.r3, 0)).norm();
          EXPECT_NEAR(std::min(std::abs(d1 - p.r1 - p.r2), std::abs(d2 - p.r1 - p.r2)), 0.0, 1e-12);
          auto q = inverse_kinematics(p, P.head<2>(), mode);
          ASSERT_TRUE(q.ok());
          EXPECT_EQ(q->assembly, assembly);
          EXPECT_LT(five_bar_jacobians(*q).serial_measure, 1e-5);
        }
      int midpoints = 0, coincident = 0;
      for (const auto& line : loci[1].lines)
        for (const Vec3& P : line) {
          auto q = inverse_kinematics(p, P.head<2>(), mode);
          if (!q.ok()) {  // P on a base joint with r1 = r2: theta_i undetermined, a point of the B1 = B2 circle
            EXPECT_NEAR(std::min((P.head<2>() - Vec2(-p.r3, 0)).norm(), (P.head<2>() - Vec2(p.r3, 0)).norm()), 0.0,
                        1e-12);
            continue;
          }
          const double b = (q->B1 - q->B2).norm();
          EXPECT_TRUE(std::abs(b - 2 * p.r2) < 1e-9 || b < 1e-9) << "|B1B2| = " << b;
          (b < 1e-9 ? coincident : midpoints)++;
          EXPECT_LT(five_bar_jacobians(*q).parallel_measure, 1e-6);
        }
      EXPECT_GT(midpoints, 0);
      // Only the modes with one leg bent each way reach the circle about B1 = B2 = O (five_bar_loci.hpp).
      if (mode.sign1 != mode.sign2) {
        EXPECT_GT(coincident, 0);
      }
    }
}

// The map's singular and near-singular points lie within a grid step of the loci, and the loci
// bound the reachable region: wherever a reachable point neighbours an unreachable one, a locus
// passes within a step of one of them. Mode +- holds the B1 = B2 circle, along which the stiffness fades slowly
// (the distal links part slowly as P leaves it): its near-singular band is ~1 cm wide, against ~1 mm
// along the other loci (docs/maps.md), hence the coarser grid.
TEST(FiveBarLoci, AgreeWithTheMapToTheGridStep) {
  struct Case {
    WorkingMode mode;
    double step;
  };
  for (const Case c : {Case{{1, 1}, 0.005}, Case{{1, -1}, 0.01}})
    for (const Assembly assembly : {Assembly::kUp, Assembly::kDown}) {
      SCOPED_TRACE(to_string(c.mode) + " " + to_string(assembly));
      FiveBarKernelOptions o;
      o.mode = c.mode;
      o.assembly = assembly;
      auto box = five_bar_workspace_box(o.params, o.mode, o.assembly);
      ASSERT_TRUE(box.ok());
      const double step = c.step;
      const MapGrid grid =
          plane_grid(box->min.x() - step, box->max.x() + step, box->min.y() - step, box->max.y() + step, step);
      auto map = compute_workspace_map(*make_five_bar_kernel(o), grid);
      ASSERT_TRUE(map.ok());
      const std::vector<MapCurve> loci = five_bar_singular_loci(o.params, o.mode, o.assembly);
      const int nx = grid.dimensions[0];
      int flagged = 0, boundary_pairs = 0;
      for (std::size_t i = 0; i < grid.num_points(); ++i) {
        const Vec2 x = grid.point(i).head<2>();
        const PostureStatus s = map->status[i];
        if (s == PostureStatus::kNearSingular || s == PostureStatus::kSingular) {
          ++flagged;
          EXPECT_LE(distance_to_curves(loci, x), step) << "flagged point (" << x.x() << ", " << x.y() << ")";
        }
        // Right and upper neighbours.
        for (const std::size_t k : {i + 1, i + nx}) {
          if (k >= grid.num_points() || (k == i + 1 && (i + 1) % nx == 0)) continue;
          if ((s == PostureStatus::kUnreachable) == (map->status[k] == PostureStatus::kUnreachable)) continue;
          ++boundary_pairs;
          const double d = std::min(distance_to_curves(loci, x), distance_to_curves(loci, grid.point(k).head<2>()));
          EXPECT_LE(d, step) << "boundary at (" << x.x() << ", " << x.y() << ")";
        }
      }
      EXPECT_GT(flagged, 0);
      EXPECT_GT(boundary_pairs, 40);
      // The first grid row lies a step below the box: all unreachable.
      const auto& st = map->status;
      EXPECT_EQ(std::count(st.begin(), st.begin() + nx, PostureStatus::kUnreachable), nx);
    }
}

// Loaded mode: every point equals its own loaded equilibrium and loaded stiffness (eq. 11-21), and
// the deflection is the equilibrium's displacement.
TEST(OrthoglideMap, LoadedModeEqualsPerPointLoadedSolves) {
  OrthoglideKernelOptions o;
  o.wrench = (Vec6() << 100.0, -50.0, 150.0, 0.5, 0.0, -0.5).finished();
  MapOptions mo;
  mo.with_deflection = true;
  auto grid = make_map_grid({MapRange{-0.06, 0.06}, MapRange{-0.06, 0.06}, MapRange{0.0, 0.06}}, 0.06, 100);
  ASSERT_TRUE(grid.ok());
  ASSERT_EQ(grid->num_varying_axes(), 3);
  auto map = compute_workspace_map(*make_orthoglide_kernel(o), *grid, mo);
  ASSERT_TRUE(map.ok());
  int compared = 0;
  for (std::size_t i = 0; i < grid->num_points(); ++i) {
    const Vec3 x = grid->point(i);
    auto chains = orthoglide_chains(o.model, o.architecture, x);
    ASSERT_TRUE(chains.ok());
    auto vt = velocity_transmission_at(OrthoglideGeometry{o.model.link_length}, x);
    ASSERT_TRUE(vt.ok());
    auto state = vjm::platform_equilibrium_under_wrench(*chains, *o.wrench);
    if (!state.ok()) {  // no equilibrium: failed, with the singularity measure only
      EXPECT_EQ(map->status[i], PostureStatus::kFailed) << x.transpose();
      expect_no_values(*map, i, true);
      continue;
    }
    auto K = vjm::platform_loaded_stiffness(*chains, *state);
    ASSERT_TRUE(K.ok() && K->compliance_defined);
    ASSERT_TRUE(has_values(map->status[i])) << i;
    expect_point_fields(*map, i, expected_fields(K->stiffness, state->displacement, vt->mu_min / vt->mu_max), 1e-9);
    ++compared;
  }
  EXPECT_EQ(compared, 18);
  EXPECT_NEAR(map->reachable_measure, 18 * 0.06 * 0.06 * 0.06, 1e-15);
}

}  // namespace
}  // namespace kinestat::mechanisms

namespace kinestat::mechanisms {
namespace {

// A rigid direction (compliance zero along it, docs/robots.md "Stiffness"): the stiffness under a
// pure force is the inverse of the block's compliances, +inf along the rigid one, not NaN from the
// inverse of a singular block.
TEST(PointFields, RigidDirectionIsInfinitelyStiff) {
  PostureResult r;
  r.status = PostureStatus::kOk;
  r.compliance = (Vec6() << 2e-8, 5e-8, 0.0, 1e-6, 4e-6, 0.0).finished().asDiagonal();
  r.stiffness = Mat6::Zero();
  const auto f = point_fields(r);
  const auto at = [&f](MapField m) { return f[static_cast<std::size_t>(m)]; };
  EXPECT_DOUBLE_EQ(at(MapField::kTranslationalMin), 1.0 / 5e-8);
  EXPECT_EQ(at(MapField::kTranslationalMax), std::numeric_limits<double>::infinity());
  EXPECT_DOUBLE_EQ(at(MapField::kRotationalMin), 1.0 / 4e-6);
  EXPECT_EQ(at(MapField::kRotationalMax), std::numeric_limits<double>::infinity());
}

}  // namespace
}  // namespace kinestat::mechanisms
