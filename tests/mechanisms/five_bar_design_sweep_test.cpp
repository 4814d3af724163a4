// Five-bar design sweep: each design's counts equal those counted from a workspace map of that
// design computed separately (with the same sweep kernel, whose values posture_kernels_test.cpp checks
// against the reference kernels); the best design has the largest share; bad ranges are refused
// naming the range.
#include "kinestat/mechanisms/five_bar_design_sweep.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <string>

namespace kinestat::mechanisms {
namespace {

// 3 x 3 designs around the paper's (r1 = r2 = 0.1 m, r3 = 0.1 m), a region above the base.
FiveBarDesignSweepOptions small_sweep() {
  FiveBarDesignSweepOptions o;
  o.r1 = {0.07, 0.13};
  o.r2 = {0.08, 0.14};
  o.steps = 3;
  auto region = make_map_grid({MapRange{-0.1, 0.1}, MapRange{0.04, 0.2}, MapRange{}}, 0.01, 1'000'000);
  EXPECT_TRUE(region.ok());
  o.region = *region;
  o.min_stiffness = 3.0e4;  // N/m: between the weakest and the stiffest points of these designs
  return o;
}

TEST(FiveBarDesignSweep, CountsEqualThoseOfASeparateMapOfEachDesign) {
  const FiveBarDesignSweepOptions o = small_sweep();
  auto sweep = sweep_five_bar_designs(o);
  ASSERT_TRUE(sweep.ok()) << sweep.status().message();
  ASSERT_EQ(sweep->results.size(), 9u);
  EXPECT_EQ(sweep->designs.dimensions, (std::array<int, 3>{3, 3, 1}));

  MapOptions map_options;
  map_options.near_singular_threshold = o.near_singular_threshold;
  bool some_weak = false, some_stiff = false;
  for (std::size_t k = 0; k < sweep->results.size(); ++k) {
    const FiveBarDesignResult& r = sweep->results[k];
    // r1 fastest over the design grid.
    EXPECT_NEAR(r.r1, 0.07 + 0.03 * static_cast<double>(k % 3), 1e-15);
    EXPECT_NEAR(r.r2, 0.08 + 0.03 * static_cast<double>(k / 3), 1e-15);
    FiveBarKernelOptions design = o.base;
    design.params.r1 = r.r1;
    design.params.r2 = r.r2;
    auto map = compute_workspace_map(*make_five_bar_kernel(design), o.region, map_options);
    ASSERT_TRUE(map.ok());
    std::size_t reachable = 0, free = 0, stiff = 0;
    const std::vector<double>& kt = map->find(MapField::kTranslationalMin)->values;
    for (std::size_t i = 0; i < map->status.size(); ++i) {
      reachable += map->status[i] != PostureStatus::kUnreachable;
      const bool ok = map->status[i] == PostureStatus::kOk;
      free += ok;
      stiff += ok && kt[i] >= *o.min_stiffness;
      some_weak = some_weak || (ok && kt[i] < *o.min_stiffness);
      some_stiff = some_stiff || (ok && kt[i] >= *o.min_stiffness);
    }
    EXPECT_EQ(r.reachable, reachable) << "design " << k;
    EXPECT_EQ(r.singularity_free, free) << "design " << k;
    EXPECT_EQ(r.stiff, stiff) << "design " << k;
    EXPECT_NEAR(sweep->share(r.stiff), static_cast<double>(stiff) / static_cast<double>(o.region.num_points()), 1e-15);
  }
  // The threshold separates points, so the stiff share is a criterion of its own.
  EXPECT_TRUE(some_weak);
  EXPECT_TRUE(some_stiff);
}

TEST(FiveBarDesignSweep, BestDesignHasTheLargestShareThenTheStiffestWeakestPoint) {
  auto sweep = sweep_five_bar_designs(small_sweep());
  ASSERT_TRUE(sweep.ok()) << sweep.status().message();
  const FiveBarDesignResult& best = sweep->results[sweep->best];
  std::size_t smallest = best.stiff;
  for (std::size_t k = 0; k < sweep->results.size(); ++k) {
    const FiveBarDesignResult& r = sweep->results[k];
    smallest = std::min(smallest, r.stiff);
    EXPECT_LE(r.stiff, best.stiff) << "design " << k;
    if (r.stiff == best.stiff && k != sweep->best) {
      EXPECT_LE(r.k_t_min_worst, best.k_t_min_worst) << "design " << k;
    }
  }
  // The designs differ, so the choice means something.
  EXPECT_LT(smallest, best.stiff);
}

TEST(FiveBarDesignSweep, WeakestPointIsTheMinimumOverTheSingularityFreePoints) {
  FiveBarDesignSweepOptions o = small_sweep();
  o.r1 = {0.1, 0.1};
  o.r2 = {0.1, 0.1};
  auto sweep = sweep_five_bar_designs(o);
  ASSERT_TRUE(sweep.ok()) << sweep.status().message();
  ASSERT_EQ(sweep->results.size(), 1u);
  auto map = compute_workspace_map(*make_five_bar_kernel(o.base), o.region);
  ASSERT_TRUE(map.ok());
  double worst = std::numeric_limits<double>::infinity();
  const std::vector<double>& kt = map->find(MapField::kTranslationalMin)->values;
  for (std::size_t i = 0; i < kt.size(); ++i)
    if (map->status[i] == PostureStatus::kOk) worst = std::min(worst, kt[i]);
  // The weakest point lies by the near-singular band, where the sweep and reference kernels agree to
  // a few 1e-9 (not 1e-12).
  EXPECT_NEAR(sweep->results[0].k_t_min_worst, worst, 1e-7 * worst);
  // Ranking: more stiff points first; on equal counts the stiffer weakest point; none ranks last.
  FiveBarDesignResult a, b;
  a.stiff = b.stiff = 3;
  a.k_t_min_worst = 2.0;
  b.k_t_min_worst = 1.0;
  EXPECT_TRUE(better_design(a, b));
  EXPECT_FALSE(better_design(b, a));
  b.stiff = 4;
  EXPECT_TRUE(better_design(b, a));
  FiveBarDesignResult none;
  none.stiff = a.stiff;
  EXPECT_TRUE(better_design(a, none));
  EXPECT_FALSE(better_design(none, a));
}

TEST(FiveBarDesignSweep, WithoutThresholdTheShareIsTheSingularityFreeShare) {
  FiveBarDesignSweepOptions o = small_sweep();
  o.min_stiffness.reset();
  o.r1 = {0.1, 0.1};  // one value: one design along r1
  auto sweep = sweep_five_bar_designs(o);
  ASSERT_TRUE(sweep.ok()) << sweep.status().message();
  EXPECT_EQ(sweep->designs.dimensions, (std::array<int, 3>{1, 3, 1}));
  for (const FiveBarDesignResult& r : sweep->results) {
    EXPECT_EQ(r.stiff, r.singularity_free);
    EXPECT_LE(r.singularity_free, r.reachable);
  }
}

TEST(FiveBarDesignSweep, BadRangesAndStepsAreRefusedByName) {
  auto message = [](FiveBarDesignSweepOptions o) {
    auto s = sweep_five_bar_designs(o);
    EXPECT_FALSE(s.ok());
    EXPECT_EQ(s.status().code(), StatusCode::kInvalidInput);
    return s.status().message();
  };
  FiveBarDesignSweepOptions o = small_sweep();
  o.r1 = {0.0, 0.1};
  EXPECT_NE(message(o).find("r1 range"), std::string::npos);
  o = small_sweep();
  o.r2 = {0.2, 0.1};
  EXPECT_NE(message(o).find("the r2 range 0.2:0.1 m is reversed"), std::string::npos);
  o = small_sweep();
  o.steps = 1;
  EXPECT_NE(message(o).find("1 designs per length"), std::string::npos);
  o = small_sweep();
  o.min_stiffness = -1.0;
  EXPECT_NE(message(o).find("min_stiffness = -1 N/m must not be negative"), std::string::npos);
  o = small_sweep();
  o.threads = -5;
  EXPECT_NE(message(o).find("threads = -5"), std::string::npos);
  o = small_sweep();
  o.region = MapGrid{};  // never set: one point at the origin
  EXPECT_NE(message(o).find("region: 1 point(s), not a plane"), std::string::npos);
}

}  // namespace
}  // namespace kinestat::mechanisms
