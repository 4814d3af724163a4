// fea::compute_link_stiffness, the one path from a surface file to a link's 6x6: the same numbers
// as meshing and solving by hand, the cache on the second call, fields (and the mesh) on request,
// and errors that name the file.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <filesystem>
#include <functional>
#include <utility>
#include <vector>

#include "cache_entry_edit.hpp"
#include "kinestat/fea/link_stiffness_request.hpp"
#include "kinestat/fea/result_cache.hpp"

namespace kinestat::fea {
namespace {

const std::string kBar = std::string(KINESTAT_SOURCE_DIR) + "/meshes/bar.off";  // x 0-200, y +-10, z +-15 mm

LinkStiffnessRequest bar_request(const std::string& cache_dir) {
  LinkStiffnessRequest r;
  r.mesh_file = kBar;
  r.mesh_size = 0.02;  // coarse: a second
  r.options.clamp = Region::plane(Vec3::Zero(), Vec3::UnitX());
  r.options.reference = Region::plane(Vec3(0.2, 0, 0), Vec3::UnitX());
  r.cache_dir = cache_dir;
  return r;
}

TEST(LinkStiffnessRequest, EqualsMeshingAndSolvingByHandThenComesFromTheCache) {
  const std::string cache = (std::filesystem::path(::testing::TempDir()) / "kinestat_request_cache").string();
  std::filesystem::remove_all(cache);
  const LinkStiffnessRequest request = bar_request(cache);
  StatusOr<LinkStiffnessRun> first = compute_link_stiffness(request);
  ASSERT_TRUE(first.ok()) << first.status().message();
  EXPECT_FALSE(first->from_cache);
  EXPECT_FALSE(first->mesh.has_value());  // no fields asked for: the mesh is not kept
  EXPECT_TRUE(std::filesystem::exists(first->cache_file)) << first->cache_file;
  EXPECT_EQ(first->surface.triangles, 12);  // a box
  EXPECT_NE(first->report.find("[N/m"), std::string::npos);

  // The same steps written out: mesh the file, solve.
  MeshingOptions meshing;
  meshing.size = 0.02;
  StatusOr<TetMesh> mesh = mesh_surface_file(kBar, meshing);
  ASSERT_TRUE(mesh.ok());
  StatusOr<LinkStiffness> by_hand = link_stiffness(*mesh, request.material, request.options);
  ASSERT_TRUE(by_hand.ok());
  EXPECT_EQ(first->result.num_dofs, by_hand->num_dofs);
  // Same mesh (fixed seed) and system; the parallel assembly and BLAS sum in varying order, so the
  // two solves agree to round-off amplified by the conditioning (measured 3e-12 relative).
  EXPECT_LT((first->result.cartesian.compliance - by_hand->cartesian.compliance).norm(),
            1e-9 * by_hand->cartesian.compliance.norm());

  StatusOr<LinkStiffnessRun> second = compute_link_stiffness(request);
  ASSERT_TRUE(second.ok());
  EXPECT_TRUE(second->from_cache);
  EXPECT_EQ(second->result.cartesian.compliance, first->result.cartesian.compliance);  // %.17g round trip
  EXPECT_NE(second->report.find("from cache"), std::string::npos);

  // Fields need the solve (and keep the mesh for VTK), even with a cache entry.
  LinkStiffnessRequest with_fields = request;
  with_fields.options.keep_fields = true;
  StatusOr<LinkStiffnessRun> third = compute_link_stiffness(with_fields);
  ASSERT_TRUE(third.ok());
  EXPECT_FALSE(third->from_cache);
  ASSERT_TRUE(third->mesh.has_value());
  EXPECT_EQ(third->result.displacement[0].size(), static_cast<size_t>(third->mesh->num_nodes()));
  std::filesystem::remove_all(cache);
}

// A damaged entry is never served: the run recomputes, says why in its warnings, and replaces the
// entry with a good one (served by the next run).
TEST(LinkStiffnessRequest, DamagedCacheEntryIsRecomputedWithAWarning) {
  const std::string cache = (std::filesystem::path(::testing::TempDir()) / "kinestat_request_damaged").string();
  std::filesystem::remove_all(cache);
  const LinkStiffnessRequest request = bar_request(cache);
  StatusOr<LinkStiffnessRun> first = compute_link_stiffness(request);
  ASSERT_TRUE(first.ok()) << first.status().message();
  EXPECT_TRUE(first->warnings.empty());
  const std::string entry = first->cache_file;
  const Mat6 good = first->result.cartesian.compliance;
  const std::vector<std::pair<std::string, std::function<void()>>> damages = {
      {"checksum",
       [&] {
         std::filesystem::resize_file(entry, std::filesystem::file_size(entry) - 10);  // cut 10 bytes short
       }},
      {"not symmetric", [&] { testing::set_entry_compliance_term(entry, 2, 4, 2.0 * good(2, 4)); }},  // checksum right
      {"not a regular file",
       [&] {
         std::filesystem::remove(entry);
         ASSERT_EQ(::mkfifo(entry.c_str(), 0600), 0);
       }},
  };
  for (const auto& [reason, damage] : damages) {
    damage();
    StatusOr<LinkStiffnessRun> again = compute_link_stiffness(request);
    ASSERT_TRUE(again.ok()) << again.status().message();
    EXPECT_FALSE(again->from_cache) << reason;
    ASSERT_EQ(again->warnings.size(), 1u) << reason;
    EXPECT_NE(again->warnings[0].find(entry), std::string::npos) << again->warnings[0];
    EXPECT_NE(again->warnings[0].find(reason == "checksum" ? "cut short" : reason), std::string::npos)
        << again->warnings[0];
    EXPECT_LT((again->result.cartesian.compliance - good).norm(), 1e-9 * good.norm()) << reason;
    StatusOr<LinkStiffnessRun> served = compute_link_stiffness(request);  // the entry was rewritten
    ASSERT_TRUE(served.ok());
    EXPECT_TRUE(served->from_cache) << reason;
    EXPECT_TRUE(served->warnings.empty()) << reason;
  }
  std::filesystem::remove_all(cache);
}

TEST(LinkStiffnessRequest, ErrorsNameTheFile) {
  LinkStiffnessRequest request = bar_request("");
  request.options.clamp = Region::plane(Vec3(-0.05, 0, 0), Vec3::UnitX());  // off the part: no node
  StatusOr<LinkStiffnessRun> run = compute_link_stiffness(request);
  ASSERT_FALSE(run.ok());
  EXPECT_EQ(run.status().code(), StatusCode::kInvalidInput);
  EXPECT_EQ(run.status().message().rfind(kBar + ": ", 0), 0u) << run.status().message();
  EXPECT_NE(run.status().message().find("clamp region"), std::string::npos);

  request = bar_request("");
  request.mesh_file = "/nonexistent/link.off";
  run = compute_link_stiffness(request);
  EXPECT_EQ(run.status().code(), StatusCode::kInvalidInput);
  EXPECT_NE(run.status().message().find("/nonexistent/link.off"), std::string::npos);
}

}  // namespace
}  // namespace kinestat::fea
