#include <gtest/gtest.h>

#include <sys/stat.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <thread>
#include <vector>

#include "cache_entry_edit.hpp"
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
  StatusOr<CachedLinkStiffness> absent = load_cached_link_stiffness(dir, key);
  ASSERT_TRUE(absent.ok());
  EXPECT_FALSE(absent->result.has_value());
  EXPECT_EQ(absent->rejected, "");  // absent is not damaged: no warning
  ASSERT_TRUE(store_cached_link_stiffness(dir, key, r).ok());
  StatusOr<CachedLinkStiffness> found = load_cached_link_stiffness(dir, key);
  ASSERT_TRUE(found.ok() && found->result.has_value()) << (found.ok() ? found->rejected : "");
  EXPECT_EQ(found->rejected, "");
  const auto& back = found->result;
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
  EXPECT_EQ(base.size(), 32u);
  EXPECT_TRUE(is_link_stiffness_cache_key(base));
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_file(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

// A valid result, always the same: symmetric positive definite compliance.
LinkStiffness valid_result() {
  LinkStiffness r;
  set_compliance(r, 1e-6 * (2.0 * Mat6::Identity() + 0.1 * Mat6::Ones()), Vec3(0.2, 0, 0));
  return r;
}

// One way of damaging the entry `key` in `dir` (stored valid first), and a word the reason must hold.
struct Damage {
  const char* name;
  std::function<void(const std::string& dir, const std::string& key)> apply;
  const char* reason;
};

std::vector<Damage> damages() {
  const auto path = [](const std::string& dir, const std::string& key) { return link_stiffness_cache_path(dir, key); };
  return {
      {"cut 10 bytes short",
       [=](const std::string& d, const std::string& k) {
         std::filesystem::resize_file(path(d, k), std::filesystem::file_size(path(d, k)) - 10);
       },
       "cut short"},
      {"one digit flipped",
       [=](const std::string& d, const std::string& k) {
         std::string text = read_file(path(d, k));
         const std::size_t e = text.find("e-", text.find("\nkey "));  // a compliance exponent
         ASSERT_NE(e, std::string::npos);
         text[e + 3] = text[e + 3] == '9' ? '8' : static_cast<char>(text[e + 3] + 1);
         write_file(path(d, k), text);
       },
       "checksum"},
      {"asymmetric, correct checksum",
       [=](const std::string& d, const std::string& k) {
         const LinkStiffness r = valid_result();
         testing::set_entry_compliance_term(path(d, k), 0, 1, 1.5 * r.cartesian.compliance(0, 1));
       },
       "not symmetric"},
      {"all zero, correct checksum",
       [=](const std::string& d, const std::string& k) {
         LinkStiffness r = valid_result();
         set_compliance(r, Mat6::Zero(), r.cartesian.point);
         ASSERT_TRUE(store_cached_link_stiffness(d, k, r).ok());
       },
       "not positive definite"},
      {"indefinite, correct checksum",
       [=](const std::string& d, const std::string& k) {
         LinkStiffness r = valid_result();
         Mat6 C = Mat6::Identity();
         C(0, 1) = C(1, 0) = 2.0;  // eigenvalues -1 and 3
         set_compliance(r, C, r.cartesian.point);
         ASSERT_TRUE(store_cached_link_stiffness(d, k, r).ok());
       },
       "not positive definite"},
      {"not finite, correct checksum",
       [=](const std::string& d, const std::string& k) {
         LinkStiffness r = valid_result();
         Mat6 C = r.cartesian.compliance;
         C(2, 2) = std::numeric_limits<double>::quiet_NaN();
         set_compliance(r, C, r.cartesian.point);
         ASSERT_TRUE(store_cached_link_stiffness(d, k, r).ok());
       },
       "not finite"},
      {"stored under another key",
       [=](const std::string& d, const std::string& k) {
         const std::string other(32, 'a');
         ASSERT_TRUE(store_cached_link_stiffness(d, other, valid_result()).ok());
         std::filesystem::rename(path(d, other), path(d, k));
       },
       "another key"},
      {"a FIFO",
       [=](const std::string& d, const std::string& k) {
         std::filesystem::remove(path(d, k));
         ASSERT_EQ(::mkfifo(path(d, k).c_str(), 0600), 0);
       },
       "not a regular file"},
      {"a folder",
       [=](const std::string& d, const std::string& k) {
         std::filesystem::remove(path(d, k));
         std::filesystem::create_directory(path(d, k));
       },
       "not a regular file"},
      {"not an entry", [=](const std::string& d, const std::string& k) { write_file(path(d, k), "hello\n"); },
       "not a cache entry"},
  };
}

// Every kind of damage is rejected with its reason (the entry's path first), and never returned.
TEST(ResultCache, DamagedEntriesAreRejectedWithTheReason) {
  const std::string dir = (std::filesystem::temp_directory_path() / "kinestat_fea_cache_damage").string();
  const std::string key = link_stiffness_cache_key("mesh", Material::from_E_nu("s", 210e9, 0.3), some_options());
  for (const Damage& damage : damages()) {
    std::filesystem::remove_all(dir);
    ASSERT_TRUE(store_cached_link_stiffness(dir, key, valid_result()).ok());
    damage.apply(dir, key);
    const auto start = std::chrono::steady_clock::now();
    StatusOr<CachedLinkStiffness> found = load_cached_link_stiffness(dir, key);
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5)) << damage.name;  // no FIFO hang
    ASSERT_TRUE(found.ok()) << damage.name;
    EXPECT_FALSE(found->result.has_value()) << damage.name;
    EXPECT_EQ(found->rejected.rfind(link_stiffness_cache_path(dir, key) + ": cache entry ignored", 0), 0u)
        << damage.name << ": " << found->rejected;
    EXPECT_NE(found->rejected.find(damage.reason), std::string::npos) << damage.name << ": " << found->rejected;
  }
  // A damaged entry is replaced by the next store.
  std::filesystem::remove_all(dir);
  ASSERT_TRUE(store_cached_link_stiffness(dir, key, valid_result()).ok());
  damages()[1].apply(dir, key);
  ASSERT_TRUE(store_cached_link_stiffness(dir, key, valid_result()).ok());
  EXPECT_TRUE(load_cached_link_stiffness(dir, key)->result.has_value());
  std::filesystem::remove_all(dir);
}

// Keys name a file in the cache folder and nothing else: anything but 32 hex digits is refused.
TEST(ResultCache, KeysCannotLeaveTheCacheFolder) {
  const std::filesystem::path root = std::filesystem::temp_directory_path() / "kinestat_fea_cache_keys";
  std::filesystem::remove_all(root);
  const std::string dir = (root / "a" / "b" / "cache").string();
  const std::vector<std::string> keys = {"../../escaped",
                                         "..",
                                         "a/b",
                                         "/tmp/x",
                                         "",
                                         std::string(31, 'a') + "/",
                                         std::string(32, 'A'),
                                         std::string(33, 'a'),
                                         std::string(16, '0')};
  for (const std::string& key : keys) {
    StatusOr<CachedLinkStiffness> load = load_cached_link_stiffness(dir, key);
    EXPECT_EQ(load.status().code(), StatusCode::kInvalidInput) << key;
    const Status store = store_cached_link_stiffness(dir, key, valid_result());
    EXPECT_EQ(store.code(), StatusCode::kInvalidInput) << key;
    EXPECT_NE(store.message().find("hex digits"), std::string::npos) << store.message();
  }
  EXPECT_FALSE(std::filesystem::exists(root / "a" / "escaped.txt"));
  EXPECT_FALSE(std::filesystem::exists(root / "a" / "b" / "cache")) << "nothing created for a refused key";
  std::filesystem::remove_all(root);
}

// Stores go through a temporary file renamed over the entry: none is left behind, and the file
// holds the key and the checksum line.
TEST(ResultCache, StoreLeavesOnlyTheEntry) {
  const std::string dir = (std::filesystem::temp_directory_path() / "kinestat_fea_cache_store").string();
  std::filesystem::remove_all(dir);
  const std::string key = link_stiffness_cache_key("m", Material::from_E_nu("s", 210e9, 0.3), some_options());
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(store_cached_link_stiffness(dir, key, valid_result()).ok());
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    ++files;
    EXPECT_EQ(entry.path().string(), link_stiffness_cache_path(dir, key));
  }
  EXPECT_EQ(files, 1);
  const std::string text = read_file(link_stiffness_cache_path(dir, key));
  EXPECT_NE(text.find("\nkey " + key + "\n"), std::string::npos);
  EXPECT_NE(text.find("\nsha256 "), std::string::npos);
  std::filesystem::remove_all(dir);
}

// Writers storing one entry while readers read it (as MPI ranks or parallel runs sharing a cache
// do): every read finds a whole entry, never a half-written one.
TEST(ResultCache, ConcurrentWritersNeverExposeHalfAnEntry) {
  const std::string dir = (std::filesystem::temp_directory_path() / "kinestat_fea_cache_concurrent").string();
  std::filesystem::remove_all(dir);
  const std::string key = link_stiffness_cache_key("c", Material::from_E_nu("s", 210e9, 0.3), some_options());
  ASSERT_TRUE(store_cached_link_stiffness(dir, key, valid_result()).ok());
  std::atomic<int> rejected{0}, served{0}, failed_stores{0};
  std::atomic<bool> done{false};
  std::vector<std::thread> threads;
  for (int w = 0; w < 3; ++w)
    threads.emplace_back([&] {
      for (int i = 0; i < 200; ++i)
        if (!store_cached_link_stiffness(dir, key, valid_result()).ok()) ++failed_stores;
    });
  for (int r = 0; r < 2; ++r)
    threads.emplace_back([&] {
      while (!done) {
        StatusOr<CachedLinkStiffness> found = load_cached_link_stiffness(dir, key);
        if (!found.ok() || !found->result)
          ++rejected;
        else
          ++served;
      }
    });
  for (int w = 0; w < 3; ++w) threads[w].join();
  done = true;
  for (std::size_t t = 3; t < threads.size(); ++t) threads[t].join();
  EXPECT_EQ(failed_stores, 0);
  EXPECT_EQ(rejected, 0);
  EXPECT_GT(served, 0);
  int files = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++files;
  EXPECT_EQ(files, 1);  // no temporary file left
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace kinestat::fea
