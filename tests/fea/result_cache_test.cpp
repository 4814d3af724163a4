#include <gtest/gtest.h>

#include <filesystem>

#include "kinestat/fea/result_cache.hpp"

namespace kinestat::fea {
namespace {

LinkStiffnessOptions some_options() {
  LinkStiffnessOptions o;
  o.clamp = Region::plane(Vec3::Zero(), Vec3::UnitX());
  o.reference = Region::plane(Vec3(0.2, 0, 0), Vec3::UnitX());
  return o;
}

TEST(ResultCache, RoundTripIsExact) {
  const std::string dir = (std::filesystem::temp_directory_path() / "kinestat_fea_cache_test").string();
  std::filesystem::remove_all(dir);
  Mat6 A = Mat6::Random();
  LinkStiffness r;
  set_compliance(r, A * A.transpose() + Mat6::Identity(), Vec3(0.2, 1e-3, -2e-3));
  const std::string key = link_stiffness_cache_key("mesh bytes", Material::from_E_nu("s", 210e9, 0.3), some_options());
  EXPECT_FALSE(load_cached_link_stiffness(dir, key).has_value());
  ASSERT_TRUE(store_cached_link_stiffness(dir, key, r).ok());
  auto back = load_cached_link_stiffness(dir, key);
  ASSERT_TRUE(back.has_value());
  EXPECT_EQ(back->cartesian.compliance, r.cartesian.compliance);  // %.17g round-trips doubles exactly
  EXPECT_EQ(back->cartesian.point, r.cartesian.point);
  EXPECT_LT((back->cartesian.stiffness * r.cartesian.compliance - Mat6::Identity()).norm(), 1e-10);
  std::filesystem::remove_all(dir);
}

TEST(ResultCache, KeyDependsOnWhatTheResultDependsOn) {
  const Material steel = Material::from_E_nu("s", 210e9, 0.3);
  const std::string base = link_stiffness_cache_key("mesh", steel, some_options());
  EXPECT_NE(base, link_stiffness_cache_key("mesh2", steel, some_options()));
  EXPECT_NE(base, link_stiffness_cache_key("mesh", Material::from_E_nu("s", 210e9, 0.29), some_options()));
  LinkStiffnessOptions o = some_options();
  o.reference.point.x() = 0.19;
  EXPECT_NE(base, link_stiffness_cache_key("mesh", steel, o));
  o = some_options();
  o.reference_model = ReferenceModel::kStiffBody;
  EXPECT_NE(base, link_stiffness_cache_key("mesh", steel, o));
  // Output-only options do not change the key.
  o = some_options();
  o.keep_fields = false;
  o.progress = [](const std::string&) {};
  EXPECT_EQ(base, link_stiffness_cache_key("mesh", steel, o));
  EXPECT_EQ(base.size(), 16u);
}

}  // namespace
}  // namespace kinestat::fea
