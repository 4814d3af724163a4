// The four bundled link meshes feed a VJM model file through `fea:` springs (issue 4: "the four
// link meshes produce 6x6 matrices that a VJM model consumes from a file"). For each: the model's
// one-spring chain at the reference point has exactly the FEA's 6x6 (read back from the result
// cache the resolution wrote: the spring enters unchanged in the documented frame), symmetric and
// positive definite, with a physical check where a closed form bounds it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <numbers>

#include "kinestat/fea/result_cache.hpp"
#include "kinestat/io/vjm_yaml.hpp"
#include "kinestat/vjm/stiffness.hpp"

namespace kinestat::io {
namespace {

namespace fs = std::filesystem;

struct LinkCase {
  const char* mesh;
  const char* regions;  // clamp, reference, reference_point (mm), as in docs/fea.md
  Vec3 reference_point_mm;
  double size_mm;
  double axial_lo, axial_hi;  // bounds of K_xx (N/m) from bar models; 0 = none
};

TEST(VjmFeaLinks, EveryBundledMeshFeedsAModelFile) {
  const double E = 210e9;
  const double tube_area = std::numbers::pi / 4 * (0.04 * 0.04 - 0.032 * 0.032);
  const LinkCase cases[] = {
      {"bar.off",
       "clamp: x=0, reference: x=200, reference_point: [200, 0, 0]",
       {200, 0, 0},
       8,
       0.98 * E * 0.02 * 0.03 / 0.2,
       1.03 * E * 0.02 * 0.03 / 0.2},
      // 48 facets per circle: the polygon's area is 0.3 % below the circle's.
      {"tube.off",
       "clamp: x=0, reference: x=300, reference_point: [300, 0, 0]",
       {300, 0, 0},
       8,
       0.98 * E * tube_area / 0.3,
       1.03 * E * tube_area / 0.3},
      {"foot.off",
       "clamp: x=0, reference: 'box:94,-25,21,111,25,39', reference_point: [102.5, 0, 30]",
       {102.5, 0, 30},
       7,
       0,
       0},
      // Axial: between the 20 x 10 mm bar over L - 13 mm (softest) and over L - 30 mm (stiffest).
      {"parallelogram_bar.off",
       "clamp: 'box:-6.5,-6.5,-8,6.5,6.5,8', reference: 'box:304.1,-6.5,-8,317.1,6.5,8', "
       "reference_point: [310.6, 0, 0]",
       {310.6, 0, 0},
       5,
       E * 0.02 * 0.01 / (0.3106 - 0.013),
       E * 0.02 * 0.01 / (0.3106 - 0.030)},
  };
  for (const LinkCase& c : cases) {
    SCOPED_TRACE(c.mesh);
    const fs::path dir = fs::path(::testing::TempDir()) / (std::string("vjm_fea_links_") + c.mesh);
    fs::remove_all(dir);
    fs::create_directories(dir);
    fs::copy_file(fs::path(KINESTAT_SOURCE_DIR) / "meshes" / c.mesh, dir / c.mesh);
    std::ofstream(dir / "model.yaml") << "units: mm-N-s\nchains:\n  - name: link\n    elements:\n"
                                      << "      - {translate: [" << c.reference_point_mm.x() << ", "
                                      << c.reference_point_mm.y() << ", " << c.reference_point_mm.z() << "]}\n"
                                      << "      - {spring: {fea: {mesh: " << c.mesh << ", material: steel, "
                                      << c.regions << ", size: " << c.size_mm << ", cache: cache}}}\n";
    auto model = read_vjm_model_yaml((dir / "model.yaml").string());
    ASSERT_TRUE(model.ok()) << model.status().message();
    const Status resolved = resolve_fea_springs(*model);
    ASSERT_TRUE(resolved.ok()) << resolved.message();
    auto chains = vjm_model_chains(*model, std::nullopt);
    ASSERT_TRUE(chains.ok()) << chains.status().message();
    auto K = vjm::platform_unloaded_stiffness(*chains);
    ASSERT_TRUE(K.ok()) << K.status().message();

    // The FEA result the resolution stored: the chain's stiffness is that 6x6 (symmetric).
    ASSERT_EQ(std::distance(fs::directory_iterator(dir / "cache"), fs::directory_iterator{}), 1);
    const fs::path cached = fs::directory_iterator(dir / "cache")->path();
    auto found = fea::load_cached_link_stiffness((dir / "cache").string(), cached.stem().string());
    ASSERT_TRUE(found.ok() && found->result.has_value());
    const auto& fea = found->result;
    const Mat6& expected = fea->cartesian.stiffness;
    EXPECT_LT((K->stiffness - expected).norm(), 1e-9 * expected.norm());
    EXPECT_LT((K->stiffness - K->stiffness.transpose()).norm(), 1e-12 * K->stiffness.norm());
    EXPECT_GT(Eigen::SelfAdjointEigenSolver<Mat6>(K->stiffness).eigenvalues().minCoeff(), 0.0);
    if (c.axial_hi > 0) {
      EXPECT_GT(K->stiffness(0, 0), c.axial_lo);
      EXPECT_LT(K->stiffness(0, 0), c.axial_hi);
    }
  }
}

}  // namespace
}  // namespace kinestat::io
