// mechanisms::robot_design_sweep with models read from models/robots/delta.yaml (the factory the CLI
// uses): the factory gets the parameters by name in the grid's order (first fastest); equal stiff
// volumes go to the first design; a failing design is kept with its reason; every design failing,
// a sweep above max_postures and unusable parameters are refused with the reason.
#include "kinestat/mechanisms/robot_design_sweep.hpp"

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "kinestat/io/robot_yaml.hpp"

namespace kinestat::mechanisms {
namespace {

const std::string kDelta = std::string(KINESTAT_SOURCE_DIR) + "/models/robots/delta.yaml";

using Named = std::vector<std::pair<std::string, double>>;

RobotDesignSweepOptions small_sweep() {
  RobotDesignSweepOptions o;
  o.parameters = {{"arm", 250, 350}, {"forearm", 700, 900}};
  o.steps = 2;
  // A small box about the axis that every design reaches whole: all designs tie.
  o.region = *make_map_grid({MapRange{-0.05, 0.05}, MapRange{-0.05, 0.05}, MapRange{-0.75, -0.65}}, 0.05, 1000);
  o.min_stiffness = 0.0;
  o.threads = 1;
  return o;
}

TEST(RobotDesignSweep, FactoryGetsTheGridInOrderAndTiesGoToTheFirst) {
  std::vector<Named> calls;
  const RobotDesignFactory factory = [&calls](const Named& values) {
    calls.push_back(values);
    return io::read_robot_model(kDelta, values);
  };
  auto s = robot_design_sweep(factory, small_sweep());
  ASSERT_TRUE(s.ok()) << s.status().message();
  ASSERT_EQ(calls.size(), 4u);
  EXPECT_EQ(calls[1], (Named{{"arm", 350}, {"forearm", 700}}));  // the first parameter fastest
  EXPECT_EQ(calls[2], (Named{{"arm", 250}, {"forearm", 900}}));
  EXPECT_EQ(s->dimensions, (std::vector<int>{2, 2}));
  EXPECT_TRUE(s->volume());
  for (const RobotDesignResult& r : s->results) {
    ASSERT_TRUE(r.status.ok()) << r.status.message();
    EXPECT_EQ(r.reachable_points, s->region.num_points());
    EXPECT_EQ(r.stiff_points, r.reachable_points);
  }
  EXPECT_EQ(s->best, 0u);  // four equal stiff volumes: the first
  EXPECT_EQ(s->ranks, 1);
  EXPECT_NE(s->description.find("Delta"), std::string::npos) << s->description;
}

TEST(RobotDesignSweep, FailedDesignsAreKeptAndAllFailingIsAnError) {
  int calls = 0;
  const RobotDesignFactory some_fail = [&calls](const Named& values) -> StatusOr<RobotModel> {
    if (calls++ % 2 == 0) return Status::Invalid("planted failure");
    return io::read_robot_model(kDelta, values);
  };
  auto s = robot_design_sweep(some_fail, small_sweep());
  ASSERT_TRUE(s.ok()) << s.status().message();
  EXPECT_EQ(s->results[0].status.message(), "planted failure");
  EXPECT_TRUE(s->results[1].status.ok());
  EXPECT_EQ(s->best, 1u);  // the first built design

  const RobotDesignFactory all_fail = [](const Named&) -> StatusOr<RobotModel> {
    return Status::Invalid("planted failure");
  };
  auto none = robot_design_sweep(all_fail, small_sweep());
  ASSERT_FALSE(none.ok());
  EXPECT_NE(none.status().message().find("every design failed; the first (arm = 250, forearm = 700): planted failure"),
            std::string::npos)
      << none.status().message();
}

TEST(RobotDesignSweep, UnusableOptionsAreRefusedBeforeAnyDesign) {
  int calls = 0;
  const RobotDesignFactory factory = [&calls](const Named& values) {
    ++calls;
    return io::read_robot_model(kDelta, values);
  };
  const std::vector<std::pair<RobotDesignSweepOptions, std::string>> cases = [] {
    std::vector<std::pair<RobotDesignSweepOptions, std::string>> c;
    RobotDesignSweepOptions o = small_sweep();
    o.parameters.clear();
    c.emplace_back(o, "no parameter to sweep");
    o = small_sweep();
    o.parameters.push_back({"arm", 1, 2});
    c.emplace_back(o, "'arm' is swept twice");
    o = small_sweep();
    o.parameters[1] = {"forearm", 900, 700};
    c.emplace_back(o, "is reversed");
    o = small_sweep();
    o.steps = 1;
    c.emplace_back(o, "1 designs per parameter");
    o = small_sweep();
    o.max_postures = 10;
    c.emplace_back(o, "4 designs x 27 region points: about 108 postures, above the limit of 10");
    o = small_sweep();
    o.region = MapGrid{};
    c.emplace_back(o, "neither a plane nor a box");
    return c;
  }();
  for (const auto& [options, expected] : cases) {
    auto s = robot_design_sweep(factory, options);
    ASSERT_FALSE(s.ok()) << expected;
    EXPECT_NE(s.status().message().find(expected), std::string::npos) << s.status().message();
  }
  EXPECT_EQ(calls, 0);
}

}  // namespace
}  // namespace kinestat::mechanisms
