// Structure::validate() for models built in code as well as read from files: every value in its
// physical range (so no sum of loads overflows), one value per prescribed dof, and messages that
// start with the item's source when it has one.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "kinestat/msa/static_analysis.hpp"
#include "kinestat/msa/structure.hpp"

namespace kinestat::msa {
namespace {

void expect_contains(const std::string& message, const std::string& part) {
  EXPECT_NE(message.find(part), std::string::npos) << "expected \"" << part << "\" in: " << message;
}

// A 1 m steel cantilever along x, fixed at node 0.
Structure cantilever() {
  Structure s;
  s.add_node("A", Vec3::Zero());
  s.add_node("B", Vec3(1, 0, 0), "frame.yaml:3");
  const int m = s.add_material(Material::from_E_nu("steel", 210e9, 0.3));
  const int c = s.add_section(circle_section(0.02));
  Beam b;
  b.id = "b";
  b.node1 = 0;
  b.node2 = 1;
  b.material = m;
  b.section = c;
  s.add_beam(b);
  s.add_support({0, kAllDofs, Mat3::Identity(), "frame.yaml:9"});
  return s;
}

TEST(StructureValidation, LoadsWhoseSumWouldOverflowAreRefused) {
  Structure s = cantilever();
  // Two loads of 1e308 N on B sum to inf: each is already beyond the range of a force.
  s.add_load_case({"push",
                   {{1, (Vec6() << 1e308, 0, 0, 0, 0, 0).finished(), "frame.yaml:12"},
                    {1, (Vec6() << 1e308, 0, 0, 0, 0, 0).finished(), "frame.yaml:13"}},
                   {},
                   "frame.yaml:10"});
  const Status st = s.validate();
  ASSERT_EQ(st.code(), StatusCode::kInvalidInput);
  EXPECT_EQ(
      st.message().rfind("frame.yaml:12: load case 'push': the load on node 'B', force = 1e+308 N is too large", 0), 0u)
      << st.message();
  // A solve never sees it: the status says why.
  EXPECT_EQ(solve(s).status.code(), StatusCode::kInvalidInput);
}

TEST(StructureValidation, NonFiniteAndOutOfRangeValuesNameTheirItem) {
  Structure s = cantilever();
  Structure far = s;
  far.add_node("C", Vec3(1e300, 0, 0), "frame.yaml:5");
  expect_contains(far.validate().message(), "frame.yaml:5: node 'C': coordinate x = 1e+300 m is too large");
  Structure stiff = s;
  stiff.add_node("B2", Vec3(1, 0, 0));
  Joint j;
  j.id = "j";
  j.node1 = 1;
  j.node2 = 2;
  j.stiffness << kRigid, 1, 1, 1, 1, std::nan("");
  j.source = "frame.yaml:7";
  stiff.add_joint(j);
  expect_contains(stiff.validate().message(), "frame.yaml:7: joint 'j': stiffness rz");
  expect_contains(stiff.validate().message(), "is not a finite number");
}

TEST(StructureValidation, CoupledJointChecked) {
  // A coupled joint's terms: symmetric, off the diagonal, away from rigid components, and a spring
  // (positive semidefinite with the diagonal), each refused by FILE:LINE and the joint.
  const auto refusal = [](const Vec6& k, const Mat6& coupling) {
    Structure s = cantilever();
    const int b = s.add_node("B2", Vec3(1, 0, 0));
    s.add_joint({"j", 1, b, Mat3::Identity(), k, coupling, "frame.yaml:7"});
    return s.validate().message();
  };
  const Vec6 k = Vec6::Constant(10.0);
  Mat6 c = Mat6::Zero();
  c(0, 1) = c(1, 0) = 4.0;
  EXPECT_EQ(refusal(k, c), "");  // [[10, 4], [4, 10]]: a spring
  Mat6 asymmetric = c;
  asymmetric(1, 0) = 3.0;
  expect_contains(refusal(k, asymmetric), "frame.yaml:7: joint 'j': its stiffness with its coupling is not symmetric");
  Mat6 gives_back = c;
  gives_back(0, 1) = gives_back(1, 0) = 11.0;  // eigenvalue 10 - 11 < 0
  expect_contains(refusal(k, gives_back),
                  "frame.yaml:7: joint 'j': its stiffness with its coupling is not positive "
                  "semidefinite");
  Mat6 on_diagonal = c;
  on_diagonal(2, 2) = 1.0;
  expect_contains(refusal(k, on_diagonal), "the diagonal of its coupling must be zero");
  Vec6 rigid = k;
  rigid(0) = kRigid;
  expect_contains(refusal(rigid, c), "frame.yaml:7: joint 'j': its rigid component ux is coupled to others");
}

TEST(StructureValidation, OneValuePerPrescribedDof) {
  Structure s = cantilever();
  s.add_load_case({"settle", {}, {{0, 2, 1e-3, "frame.yaml:11"}, {0, 2, 2e-3, "frame.yaml:12"}}, "frame.yaml:10"});
  const Status st = s.validate();
  ASSERT_EQ(st.code(), StatusCode::kInvalidInput);
  expect_contains(st.message(), "frame.yaml:12: load case 'settle': the uz of node 'A' is prescribed twice");
}

}  // namespace
}  // namespace kinestat::msa
