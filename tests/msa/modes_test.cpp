// Modal analysis (msa/modes.hpp): the cantilever and the simply supported beam against the
// Euler-Bernoulli closed forms as the beam is divided, lumped against consistent masses, the
// cantilever's effective mass, and the refusals.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "beam_line.hpp"
#include "kinestat/elements/section.hpp"
#include "kinestat/msa/modes.hpp"

namespace kinestat::msa {
namespace {

constexpr double kPi = std::numbers::pi;
// Cantilever: the first root of cos(bL) cosh(bL) = -1 (Blevins, Formulas for Natural Frequency and
// Mode Shape, table 8-1).
constexpr double kCantileverBetaL = 1.8751040687119611;

// A beam along x from node 0 to node n (L = 2 m, 20 x 30 mm steel: Iz < Iy, so the first mode bends
// in the x-y plane). cantilever: node 0 clamped; otherwise pinned at both ends (twist held at 0).
Structure beam(bool cantilever, int n, const Material& mat = kSteel) {
  Structure s = straight(2.0, n, rectangle_section(0.02, 0.03), BeamTheory::kEulerBernoulli, mat);
  if (cantilever) {
    s.add_support({0, kAllDofs, Mat3::Identity()});
  } else {
    s.add_support({0, {true, true, true, true, false, false}, Mat3::Identity()});
    s.add_support({n, {false, true, true, false, false, false}, Mat3::Identity()});
  }
  return s;
}

// omega_1 = (beta L)^2 sqrt(E Iz / (rho A L^4)).
double closed_form_omega(bool cantilever) {
  const Section sec = rectangle_section(0.02, 0.03);
  const double bl = cantilever ? kCantileverBetaL : kPi, L = 2.0;
  return bl * bl * std::sqrt(kSteel.E * sec.Iz / (kSteel.density * sec.A * L * L * L * L));
}

ModalResult run(const Structure& s, bool lumped, bool rotary_inertia, int count = 3) {
  ModalOptions opt;
  opt.count = count;
  opt.lumped = lumped;
  opt.rotary_inertia = rotary_inertia;
  ModalResult r = modal_analysis(s, opt);
  EXPECT_TRUE(r.status.ok()) << r.status.message();
  return r;
}

// Consistent masses without rotary inertia (the Euler-Bernoulli beam of the closed forms): an upper
// bound converging as h^4 in omega^2. Measured relative errors of omega_1:
//   cantilever          n = 4: 3.27e-05  8: 2.08e-06  16: 1.31e-07  (ratios 15.7, 15.9)
//   simply supported    n = 4: 2.60e-04  8: 1.64e-05  16: 1.03e-06  (ratios 15.9, 15.9)
// Asserted: positive, each halving dividing it by 12..20, n = 16 within twice its measured error.
TEST(Modes, ConsistentMassConvergesToEulerBernoulli) {
  for (bool cantilever : {true, false}) {
    const double exact = closed_form_omega(cantilever);
    const double err16 = cantilever ? 1.31e-7 : 1.03e-6;
    double previous = 0.0;
    for (int n : {4, 8, 16}) {
      const ModalResult r = run(beam(cantilever, n), false, false);
      ASSERT_FALSE(r.modes.empty());
      EXPECT_LT(r.modes[0].residual, 1e-8);
      const double err = (r.modes[0].omega - exact) / exact;
      std::printf("%s n = %d: omega_1 relative error %.2e (f_1 = %.6f Hz)\n",
                  cantilever ? "cantilever" : "simply supported", n, err, r.modes[0].frequency);
      EXPECT_GT(err, 0.0) << n;
      if (previous > 0.0) {
        EXPECT_GT(previous / err, 12.0) << n;
        EXPECT_LT(previous / err, 20.0) << n;
      }
      if (n == 16) {
        EXPECT_LT(err, 2.0 * err16);
      }
      previous = err;
    }
  }
}

// Lumped masses (no rotational mass in bending) converge from below, as h^2. Measured:
//   cantilever n = 4: -2.79e-02  8: -7.12e-03  16: -1.79e-03  (ratios 3.92, 3.98)
// Asserted: negative, ratios 3.5..4.5, n = 16 within twice its measured error.
// A simply supported beam made by end releases (beam_line.hpp, pinned_by_releases): the released
// beams' mass is condensed with their released dofs' static shapes (condense_with_releases), the
// simply supported beam's masses restricted to those shapes, so omega_1 is an upper bound above
// the pinned-support beam's, converging to pi^2 sqrt(E Iz / (rho A L^4)). Measured relative errors:
// n = 4: 2.904e-4 (pinned supports 2.597e-4), 8: 1.669e-5 (1.644e-5), 16: 1.033e-6 (1.031e-6). Asserted: positive, at
// least the pinned beam's, each halving dividing it by 12..20, and n = 16 within twice its measured error.
TEST(Modes, SimplySupportedByEndReleasesConvergesToEulerBernoulli) {
  const double exact = closed_form_omega(false);
  double previous = 0.0;
  for (int n : {4, 8, 16}) {
    const ModalResult r = run(pinned_by_releases(2.0, n, rectangle_section(0.02, 0.03)), false, false, 1);
    const ModalResult p = run(beam(false, n), false, false, 1);
    ASSERT_FALSE(r.modes.empty() || p.modes.empty());
    const double err = r.modes[0].omega / exact - 1.0, pinned = p.modes[0].omega / exact - 1.0;
    std::printf("simply supported by releases n = %d: omega_1 relative error %.3e (pinned supports %.3e)\n", n, err,
                pinned);
    EXPECT_GT(err, 0.0) << "n = " << n;
    EXPECT_GE(err, pinned - 1e-12) << "n = " << n;
    if (previous > 0.0) {
      EXPECT_GT(previous / err, 12.0) << "n = " << n;
      EXPECT_LT(previous / err, 20.0) << "n = " << n;
    }
    if (n == 16) {
      EXPECT_LT(err, 2.0 * 1.033e-6);
    }
    previous = err;
  }
}

TEST(Modes, LumpedMassConvergesFromBelow) {
  const double exact = closed_form_omega(true);
  double previous = 0.0;
  for (int n : {4, 8, 16}) {
    const ModalResult r = run(beam(true, n), true, false);
    ASSERT_FALSE(r.modes.empty());
    const double err = (r.modes[0].omega - exact) / exact;
    std::printf("lumped cantilever n = %d: omega_1 relative error %.2e\n", n, err);
    EXPECT_LT(err, 0.0) << n;
    if (previous < 0.0) {
      EXPECT_GT(previous / err, 3.5) << n;
      EXPECT_LT(previous / err, 4.5) << n;
    }
    if (n == 16) {
      EXPECT_GT(err, 2.0 * -1.79e-3);
    }
    previous = err;
  }
}

TEST(Modes, ShapesAreMassNormalizedAndEffectiveMassesAddUp) {
  const Structure s = beam(true, 16);
  const int nfree = 16 * 6;
  const ModalResult r = run(s, false, true, nfree - 1);
  ASSERT_EQ(static_cast<int>(r.modes.size()), nfree - 1);
  // Total mass rho A L = 7850 * 6e-4 * 2 = 9.42 kg along each axis.
  EXPECT_NEAR(r.total_mass(0), 9.42, 1e-12 * 9.42);
  EXPECT_NEAR(r.total_mass(1), 9.42, 1e-12 * 9.42);
  // The cantilever's first bending mode carries 61.3 % of the mass (Chopra, Dynamics of Structures,
  // the distributed-mass cantilever: 0.613). Measured here 0.61305 (16 beams): asserted 0.613 +- 0.001.
  const double first_y = r.modes[0].effective_mass(1) / r.total_mass(1);
  std::printf("first mode: effective mass fraction along y %.5f\n", first_y);
  EXPECT_NEAR(first_y, 0.613, 0.001);
  // Over all modes the effective masses add up to the mass that moves (the free dofs' share: the
  // clamped node keeps half an element's consistent share), i.e. r' M_r r of the free dofs.
  Vec3 sum = Vec3::Zero();
  for (const auto& m : r.modes) sum += m.effective_mass;
  EXPECT_LT(sum(1), r.total_mass(1));
  EXPECT_GT(sum(1), 0.9 * r.total_mass(1));
  // Rotary inertia lowers the frequency a little (a Rayleigh beam): (r/L)^2 = Iz / (A L^2) = 8.3e-6.
  const double without = run(s, false, false, 1).modes[0].omega;
  EXPECT_LT(r.modes[0].omega, without);
  EXPECT_GT(r.modes[0].omega, without * (1 - 1e-4));
}

TEST(Modes, NoDensityIsRefused) {
  const Material weightless{"air_steel", 2.1e11, 0.81e11, 0.0};
  const ModalResult r = modal_analysis(beam(true, 4, weightless));
  EXPECT_EQ(r.status.code(), StatusCode::kInvalidInput);
  EXPECT_NE(r.status.message().find("material 'air_steel' has no density"), std::string::npos) << r.status.message();
}

// The pinned column of `beam(false, 8)` scaled: every length by `length` (so omega by 1 / length,
// exactly, for a geometrically similar Euler-Bernoulli structure with rotary inertia), its material
// `mat`.
Structure scaled_column(double length, const Material& mat) {
  const int n = 8;
  Structure s =
      straight(2.0 * length, n, rectangle_section(0.02 * length, 0.03 * length), BeamTheory::kEulerBernoulli, mat);
  s.add_support({0, {true, true, true, true, false, false}, Mat3::Identity()});
  s.add_support({n, {false, true, true, false, false, false}, Mat3::Identity()});
  return s;
}

// A 20 um column (1/omega^2 ~ 2e-14 s^2) and one of density 1e-6 kg/m^3 (~1e-14 s^2) give the
// 2 m steel column's frequencies times 1e5 and sqrt(7850 / 1e-6). Before, Spectra's absolute tests
// (a vector below 2.2e-16 taken for 0, Ritz values below 3.7e-11 converged to an absolute tolerance)
// stopped it at residuals of 0.26 to 0.92: f_2 of the small column 0.6 % high, f_1 of the light one
// 2.9 %, with exit 0. The eigensolver now works on the pencil equilibrated by K's diagonal
// (solver/generalized_eigen.cpp). Measured: the ratios equal to 4e-14, residuals 4e-13; asserted: the
// ratios within 1e-9 (round-off of a residual of 1e-13 is far below), residuals below 1e-8, and the
// first frequency against the closed form within twice the 8-beam error (1.64e-5, measured here without
// rotary inertia).
TEST(Modes, TinyAndLightColumnsKeepTheirScaledFrequencies) {
  ModalOptions opt;
  opt.count = 4;
  const ModalResult reference = modal_analysis(scaled_column(1.0, kSteel), opt);
  ASSERT_TRUE(reference.status.ok()) << reference.status.message();
  const Material light{"light_steel", kSteel.E, kSteel.G, 1e-6};
  const struct {
    const char* name;
    double length;
    const Material& mat;
    double omega_ratio;
  } cases[] = {{"20 um column", 1e-5, kSteel, 1e5}, {"density 1e-6", 1.0, light, std::sqrt(7850.0 / 1e-6)}};
  for (const auto& c : cases) {
    const ModalResult r = modal_analysis(scaled_column(c.length, c.mat), opt);
    ASSERT_TRUE(r.status.ok()) << c.name << ": " << r.status.message();
    ASSERT_EQ(r.modes.size(), reference.modes.size()) << c.name;
    for (std::size_t k = 0; k < r.modes.size(); ++k) {
      const double ratio = r.modes[k].omega / reference.modes[k].omega / c.omega_ratio;
      std::printf("%s: mode %zu omega ratio / expected - 1 = %.1e, residual %.1e\n", c.name, k + 1, ratio - 1.0,
                  r.modes[k].residual);
      EXPECT_NEAR(ratio, 1.0, 1e-9) << c.name << " mode " << k + 1;
      EXPECT_LT(r.modes[k].residual, 1e-8) << c.name << " mode " << k + 1;
    }
    ModalOptions euler = opt;
    euler.rotary_inertia = false;
    const ModalResult e = modal_analysis(scaled_column(c.length, c.mat), euler);
    ASSERT_TRUE(e.status.ok()) << e.status.message();
    const double exact = closed_form_omega(false) * c.omega_ratio;
    const double err = e.modes[0].omega / exact - 1.0;
    EXPECT_GT(err, 0.0) << c.name;
    EXPECT_LT(err, 2.0 * 1.64e-5) << c.name;
  }
}

// A mode whose residual is above ModalOptions::max_residual is refused, not printed: here a limit
// below the converged column's 1e-13 stands for an eigensolver that did not converge.
TEST(Modes, AModeAboveTheResidualLimitIsRefused) {
  ModalOptions opt;
  opt.count = 2;
  opt.max_residual = 1e-16;
  const ModalResult r = modal_analysis(scaled_column(1.0, kSteel), opt);
  EXPECT_EQ(r.status.code(), StatusCode::kNotConverged);
  EXPECT_NE(r.status.message().find("has the residual ||K q - omega^2 M q|| / ||K q|| = "), std::string::npos)
      << r.status.message();
  EXPECT_NE(r.status.message().find("above 1e-16"), std::string::npos) << r.status.message();
  EXPECT_TRUE(r.modes.empty());
}

// A zero nodal mass lets a model without density past the check above, and a density of 1e-300
// kg/m^3 is a mass in name only: both are refused before the eigensolver, on the dense path (2 beams,
// 12 free dofs) and on the Lanczos path (8 beams, 48), whose tridiagonal solver failed on them before
// ("TridiagEigen: eigen decomposition failed", exit 1). M_ii / K_ii of a beam of 1e-300 kg/m^3 is
// about 1e-312 s^2, below the limit of 1e-60.
TEST(Modes, MasslessOrNegligibleMassIsRefusedOnBothPaths) {
  const Material weightless{"air_steel", 2.1e11, 0.81e11, 0.0}, feather{"feather_steel", 2.1e11, 0.81e11, 1e-300};
  for (int n : {2, 8}) {
    Structure s = beam(true, n, weightless);
    s.add_mass({n / 2, 0.0, Vec3::Zero()});
    ModalResult r = modal_analysis(s);
    EXPECT_EQ(r.status.code(), StatusCode::kInvalidInput) << n;
    EXPECT_NE(r.status.message().find("no free dof has mass"), std::string::npos) << r.status.message();
    EXPECT_TRUE(r.modes.empty());
    r = modal_analysis(beam(true, n, feather));
    EXPECT_EQ(r.status.code(), StatusCode::kInvalidInput) << n;
    EXPECT_NE(r.status.message().find("the mass is negligible against the stiffness"), std::string::npos)
        << r.status.message();
    EXPECT_NE(r.status.message().find("check the materials' densities and the nodal masses"), std::string::npos);
    EXPECT_TRUE(r.modes.empty());
  }
}

}  // namespace
}  // namespace kinestat::msa

namespace kinestat::msa {
namespace {

// A massless cantilever (no density) with a tip mass m and tip rotary inertia Ixx: the bending
// modes are sqrt(k / m) with the exact tip stiffness k = 3 E I / L^3 (one cubic beam is exact for a
// tip load, and no other dof has mass), the torsion mode sqrt(G J / (L Ixx)): to round-off.
TEST(Modes, TipMassOnMasslessCantilever) {
  const Material massless{"steel", 2.1e11, 0.81e11, 0.0};
  const Section sec = rectangle_section(0.02, 0.03);
  const double L = 1.5, m = 20.0, Ixx = 0.05;
  for (int n : {1, 3}) {
    Structure s = straight(L, n, sec, BeamTheory::kEulerBernoulli, massless);
    s.add_support({0, kAllDofs, Mat3::Identity()});
    s.add_mass({n, m, Vec3(Ixx, 0, 0)});
    const ModalResult r = run(s, false, true, 3);
    ASSERT_EQ(r.modes.size(), 3u) << n;  // y and z bending, torsion; the axial mode is far above
    const double wy = std::sqrt(3 * kSteel.E * sec.Iz / (m * L * L * L));
    const double wz = std::sqrt(3 * kSteel.E * sec.Iy / (m * L * L * L));
    const double wt = std::sqrt(kSteel.G * sec.J / (L * Ixx));
    std::vector<double> expected{wy, wz, wt};
    std::sort(expected.begin(), expected.end());
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(r.modes[k].omega, expected[k], 1e-10 * expected[k]) << n << " " << k;
    EXPECT_NEAR(r.total_mass(1), m, 1e-12 * m);
    // The y-bending mode carries the whole tip mass along y.
    for (const auto& mode : r.modes) {
      if (std::abs(mode.omega - wy) < 1e-6 * wy) {
        EXPECT_NEAR(mode.effective_mass(1), m, 1e-9 * m);
      }
    }
  }
}

}  // namespace
}  // namespace kinestat::msa

namespace kinestat::msa {
namespace {

// The simply supported beam of `beam(false, n)` with an axial force P (N, tension positive) at its
// free-sliding end, as the load case "axial", prestressing the modes.
Structure axially_loaded(int n, double P) {
  Structure s = beam(false, n);
  LoadCase lc{.name = "axial"};
  lc.loads.push_back({n, Vec6::Unit(0) * P});
  s.add_load_case(lc);
  return s;
}

ModalResult prestressed(const Structure& s, bool second_order = false) {
  ModalOptions opt;
  opt.count = 1;
  opt.rotary_inertia = false;  // the Euler-Bernoulli beam of the closed form
  opt.prestress = ModalPrestress{0, second_order, {}};
  return modal_analysis(s, opt);
}

// A simply supported Euler-Bernoulli beam under an axial force P vibrates in the sine mode of the
// unloaded beam, with omega_1^2 = omega_0^2 (1 + P / P_cr), P_cr = pi^2 E Iz / L^2 (tension
// raises, compression lowers it; Timoshenko & Young, Vibration Problems in Engineering, 5.12).
// Cubic beams with the consistent K_G are a Rayleigh-Ritz discretisation of that problem, so omega_1
// is an upper bound converging as h^4 in omega^2. Measured relative errors of omega_1:
//   P = +0.5 P_cr  n = 4: 1.74e-04  8: 1.10e-05  16: 6.88e-07  (ratios 15.8, 16.0)
//   P = -0.5 P_cr  n = 4: 5.16e-04  8: 3.28e-05  16: 2.06e-06  (ratios 15.7, 15.9)
// Asserted: positive, each halving dividing it by 12..20, n = 16 within twice its measured error, and
// the prestress moving omega_1 the way the formula says (tension above, compression below the
// unstressed beam's). The axial force is statically determinate here, so the second-order
// prestress equals the linear one (to round-off: 1e-12).
TEST(Modes, PrestressedSimplySupportedBeamFollowsTheAxialForceFormula) {
  const Section sec = rectangle_section(0.02, 0.03);
  const double L = 2.0, pcr = kPi * kPi * kSteel.E * sec.Iz / (L * L);
  const double omega0 = closed_form_omega(false);
  for (double ratio : {0.5, -0.5}) {
    const double exact = omega0 * std::sqrt(1.0 + ratio);
    const double err16 = ratio > 0 ? 6.88e-7 : 2.06e-6;
    double previous = 0.0;
    for (int n : {4, 8, 16}) {
      const Structure s = axially_loaded(n, ratio * pcr);
      const ModalResult r = prestressed(s);
      ASSERT_TRUE(r.status.ok()) << r.status.message();
      ASSERT_TRUE(r.prestress.has_value());
      EXPECT_EQ(r.prestress->load_case_name, "axial");
      EXPECT_FALSE(r.prestress->second_order);
      ASSERT_EQ(r.prestress->axial_force.size(), static_cast<std::size_t>(n));
      EXPECT_NEAR(r.prestress->axial_force[0], ratio * pcr, 1e-9 * pcr);
      ASSERT_FALSE(r.modes.empty());
      EXPECT_LT(r.modes[0].residual, 1e-8);
      const double err = (r.modes[0].omega - exact) / exact;
      std::printf("simply supported, P = %+.1f P_cr, n = %d: omega_1 relative error %.2e\n", ratio, n, err);
      EXPECT_GT(err, 0.0) << n;
      if (previous > 0.0) {
        EXPECT_GT(previous / err, 12.0) << n;
        EXPECT_LT(previous / err, 20.0) << n;
      }
      if (n == 16) {
        EXPECT_LT(err, 2.0 * err16);
        const ModalResult unstressed = run(s, false, false, 1);
        if (ratio > 0) {
          EXPECT_GT(r.modes[0].omega, 1.2 * unstressed.modes[0].omega);
        } else {
          EXPECT_LT(r.modes[0].omega, 0.75 * unstressed.modes[0].omega);
        }
        const ModalResult second = prestressed(s, true);
        ASSERT_TRUE(second.status.ok()) << second.status.message();
        EXPECT_TRUE(second.prestress->second_order);
        EXPECT_NEAR(second.modes[0].omega, r.modes[0].omega, 1e-12 * r.modes[0].omega);
      }
      previous = err;
    }
  }
}

// Compression past P_cr: K + K_G is not positive definite, so there is no frequency: refused with
// the case and the reason (and by the second-order solve, which cannot reach equilibrium there).
// A case index out of range is refused too.
TEST(Modes, PrestressPastTheCriticalLoadIsRefused) {
  const Section sec = rectangle_section(0.02, 0.03);
  const double pcr = kPi * kPi * kSteel.E * sec.Iz / 4.0;
  const Structure s = axially_loaded(8, -1.2 * pcr);
  ModalResult r = prestressed(s);
  EXPECT_EQ(r.status.code(), StatusCode::kInvalidInput);
  EXPECT_NE(r.status.message().find("prestress of load case 'axial': its loads are at or past the critical "
                                    "(buckling) load"),
            std::string::npos)
      << r.status.message();
  r = prestressed(s, true);
  EXPECT_EQ(r.status.code(), StatusCode::kNotConverged);
  EXPECT_NE(r.status.message().find("prestress: "), std::string::npos) << r.status.message();
  EXPECT_NE(r.status.message().find("load case 'axial': the loads reach or exceed the critical (buckling) load"),
            std::string::npos)
      << r.status.message();
  ModalOptions opt;
  opt.prestress = ModalPrestress{1, false, {}};
  r = modal_analysis(s, opt);
  EXPECT_EQ(r.status.code(), StatusCode::kInvalidInput);
  EXPECT_NE(r.status.message().find("load case index 1 out of range"), std::string::npos) << r.status.message();
}

}  // namespace
}  // namespace kinestat::msa
