// StatusOr hands out only a value it holds: reading the value of an error is a programming error that
// aborts with the status in the message (core/status.hpp), never a default-made value.
#include "kinestat/core/status.hpp"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

namespace kinestat {
namespace {

// Without a default constructor: a StatusOr must not need one to hold an error.
struct NoDefault {
  explicit NoDefault(int v) : v(v) {}
  int v;
};

TEST(StatusOr, HoldsAValueOrAnError) {
  const StatusOr<std::vector<double>> good(std::vector<double>{1.0, 2.0});
  ASSERT_TRUE(good.ok());
  EXPECT_EQ(good.value().size(), 2u);
  EXPECT_EQ((*good)[1], 2.0);
  EXPECT_EQ(good->front(), 1.0);

  const StatusOr<NoDefault> bad(Status::Invalid("'E' must be positive"));
  EXPECT_FALSE(bad.ok());
  EXPECT_EQ(bad.status().code(), StatusCode::kInvalidInput);

  StatusOr<std::unique_ptr<int>> moved(std::make_unique<int>(7));
  const std::unique_ptr<int> p = std::move(moved).value();
  EXPECT_EQ(*p, 7);
}

TEST(StatusOr, AnOkStatusWithoutAValueIsAnInternalError) {
  const StatusOr<int> r(Status::Ok());
  EXPECT_FALSE(r.ok());
  EXPECT_EQ(r.status().code(), StatusCode::kInternal);
}

TEST(StatusCodeName, NamesEveryCode) {
  EXPECT_STREQ(status_code_name(StatusCode::kOk), "kOk");
  EXPECT_STREQ(status_code_name(StatusCode::kInvalidInput), "kInvalidInput");
  EXPECT_STREQ(status_code_name(StatusCode::kSingular), "kSingular");
  EXPECT_STREQ(status_code_name(StatusCode::kNotConverged), "kNotConverged");
  EXPECT_STREQ(status_code_name(StatusCode::kInternal), "kInternal");
}

// The death tests fork; "threadsafe" re-runs the test binary in the child, safe with TBB's threads.
class StatusOrDeathTest : public ::testing::Test {
 protected:
  void SetUp() override { GTEST_FLAG_SET(death_test_style, "threadsafe"); }
};

TEST_F(StatusOrDeathTest, ReadingTheValueOfAnErrorAbortsNamingTheStatus) {
  const StatusOr<double> r(Status::Singular("node '5' translates along +y"));
  const char* expected = "value\\(\\) called on an error \\(kSingular: node '5' translates along \\+y\\)";
  EXPECT_DEATH({ [[maybe_unused]] const double v = r.value(); }, expected);
  EXPECT_DEATH({ [[maybe_unused]] const double v = *r; }, expected);
  StatusOr<std::string> s(Status::Invalid("bad"));
  EXPECT_DEATH({ [[maybe_unused]] const auto n = s->size(); }, "kInvalidInput: bad");
  EXPECT_DEATH({ [[maybe_unused]] const std::string v = std::move(s).value(); }, "kInvalidInput: bad");
}

}  // namespace
}  // namespace kinestat
