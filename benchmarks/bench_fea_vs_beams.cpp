// Lumped (beam) models of a link against its FEA 6x6 stiffness (Pashkevich, Klimchik, Chablat,
// Wenger 2009, section 4.3: one beam is said to approximate the Orthoglide links to ~50 %, four
// beams to ~30 %). For each link of meshes/ (foot and parallelogram bar, with the plain bar and
// tube as controls where beam theory is known to hold) the program prints, before the timings:
//   - the FEA stiffness (rigid reference coupling) on two meshes, and their largest diagonal change;
//   - the relative difference (K_beam - K_FEA) / K_FEA of the six diagonal terms and of the main
//     couplings (|K_ij| / sqrt(K_ii K_jj) > 0.2 in the FEA) for a one-beam and a four-beam chain;
//   - the relative difference of the sorted eigenvalues of K (SI units, so they mix N/m and
//     N m/rad: compare them link against link, not across dof types).
// The beam chains are vjm::serial_link_spring chains of Timoshenko cantilevers; their sections are
// read from the link dimensions in docs/fea.md (table "Geometry"), chosen as documented next to
// each link below. Steel (E = 210 GPa, nu = 0.3) throughout: the ratios barely depend on it.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <Eigen/Eigenvalues>
#include <fmt/format.h>

#include "elements/section.hpp"
#include "fea/link_stiffness.hpp"
#include "fea/region.hpp"
#include "fea/surface_mesher.hpp"
#include "vjm/link_spring.hpp"

namespace {

using namespace kinestat;

const Material kSteel = Material::from_E_nu("steel", 210e9, 0.3);
constexpr const char* kDofNames[6] = {"ux", "uy", "uz", "rx", "ry", "rz"};

// A straight beam segment from `from` to `to` (m, link frame, in the link's x-z plane): local x along
// the segment, local y = the link's y, so a rectangle's b is its extent along the link's y.
struct Segment {
  Vec3 from, to;
  Section section;
};

// The spring of the reference point relative to the clamp, link axes, about the reference point:
// a serial chain (rigid offsets where the segments do not meet, e.g. inside a rigidly coupled region).
StatusOr<Mat6> beam_link_spring(const std::vector<Segment>& segments, const Vec3& reference_point) {
  vjm::Chain chain("beam model");
  Vec3 at = segments.front().from;
  for (const Segment& s : segments) {
    if ((s.from - at).norm() > 0) chain.add_translation(s.from - at, "rigid offset");
    const Vec3 x = (s.to - s.from).normalized();
    vjm::Transform axes = vjm::Transform::Identity();
    axes.linear() << x, Vec3::UnitY(), x.cross(Vec3::UnitY());
    chain.add_transform(axes, "beam axes");
    const double length = (s.to - s.from).norm();
    chain.add_translation(length * Vec3::UnitX(), "beam");
    chain.add_spring(vjm::cantilever_spring(kSteel, s.section, length, BeamTheory::kTimoshenko), "beam");
    chain.add_transform(axes.inverse(), "link axes");
    at = s.to;
  }
  if ((reference_point - at).norm() > 0) chain.add_translation(reference_point - at, "rigid offset");
  return vjm::serial_link_spring(chain);
}

struct LinkCase {
  std::string file;                   // in meshes/
  fea::Region clamp, reference;
  Vec3 reference_point;               // m
  double coarse_size, fine_size;      // m
  std::vector<Segment> one_beam, four_beams;
  std::string sections;               // how the sections were chosen
};

Vec3 mm(double x, double y, double z) { return 1e-3 * Vec3(x, y, z); }

// Controls: a prismatic link along x, clamped at x = 0, reference face at x = length (m); one beam
// is the exact lumped model and four equal beams are the same model.
LinkCase prismatic_case(std::string file, double length, const Section& s, double coarse, double fine,
                        std::string sections) {
  const Vec3 end = length * Vec3::UnitX();
  LinkCase c{std::move(file), fea::Region::plane(Vec3::Zero(), Vec3::UnitX()), fea::Region::plane(end, Vec3::UnitX()),
             end, coarse, fine, {{Vec3::Zero(), end, s}}, {}, std::move(sections)};
  for (int i = 0; i < 4; ++i) c.four_beams.push_back({end * i / 4.0, end * (i + 1) / 4.0, s});
  return c;
}

std::vector<LinkCase> link_cases() {
  std::vector<LinkCase> cases;
  cases.push_back(prismatic_case("bar.off", 0.2, rectangle_section(0.020, 0.030), 6e-3, 4e-3,
                                 "20 x 30 mm rectangle, 1 x 200 or 4 x 50 mm"));
  cases.push_back(prismatic_case("tube.off", 0.3, tube_section(0.040, 0.004), 7.5e-3, 5e-3,
                                 "tube D40 x 4 mm, 1 x 300 or 4 x 75 mm"));
  {  // Foot: clamped face x = 0 (centre z = 7.5 mm), reference = the bore (x 102.5, z 30 mm).
     // One beam: the straight line between them with the base's 50 x 15 mm section. Four beams
     // along the centre line of the material: the base in two halves (50 x 15 mm), the step along
     // x to below the bore (50 wide, the step's full 45 mm height), then up to the bore (50 mm
     // along y, 35 mm along x: the step's width).
    const Section base = rectangle_section(0.050, 0.015);
    cases.push_back(LinkCase{"foot.off", fea::Region::plane(Vec3::Zero(), Vec3::UnitX()),
                             fea::Region::box(mm(94, -25, 21), mm(111, 25, 39)), mm(102.5, 0, 30), 5e-3, 3.5e-3,
                             {{mm(0, 0, 7.5), mm(102.5, 0, 30), base}},
                             {{mm(0, 0, 7.5), mm(42.5, 0, 7.5), base},
                              {mm(42.5, 0, 7.5), mm(85, 0, 7.5), base},
                              {mm(85, 0, 7.5), mm(102.5, 0, 7.5), rectangle_section(0.050, 0.045)},
                              {mm(102.5, 0, 7.5), mm(102.5, 0, 30), rectangle_section(0.050, 0.035)}},
                             "1: base 50x15 mm on the straight line; 4: base 2x(50x15), step 50x45, riser 50x35"});
  }
  {  // Parallelogram bar: bores 310.6 mm apart, both coupled through 13 mm boxes (rigid to 6.5 mm
     // from each bore axis). One beam: the 20 x 10 mm bar from bore axis to bore axis. Four beams:
     // rigid to 6.5 mm, boss to 15 mm (the bar's 20 mm width, the boss's 16 mm height), the bar in
     // two halves, boss, rigid.
    const double L = 310.6;
    const Section bar = rectangle_section(0.020, 0.010), boss = rectangle_section(0.020, 0.016);
    cases.push_back(LinkCase{"parallelogram_bar.off", fea::Region::box(mm(-6.5, -6.5, -8), mm(6.5, 6.5, 8)),
                             fea::Region::box(mm(L - 6.5, -6.5, -8), mm(L + 6.5, 6.5, 8)), mm(L, 0, 0), 4e-3, 3e-3,
                             {{Vec3::Zero(), mm(L, 0, 0), bar}},
                             {{mm(6.5, 0, 0), mm(15, 0, 0), boss},
                              {mm(15, 0, 0), mm(L / 2, 0, 0), bar},
                              {mm(L / 2, 0, 0), mm(L - 15, 0, 0), bar},
                              {mm(L - 15, 0, 0), mm(L - 6.5, 0, 0), boss}},
                             "1: bar 20x10 mm axis to axis; 4: boss 20x16 (6.5-15 mm), bar 2x(20x10), boss"});
  }
  return cases;
}

StatusOr<fea::LinkStiffness> fea_link(const LinkCase& c, double size) {
  fea::MeshingOptions mo;
  mo.size = size;
  StatusOr<fea::TetMesh> mesh = fea::mesh_surface_file(std::string(KINESTAT_SOURCE_DIR) + "/meshes/" + c.file, mo);
  if (!mesh.ok()) return Status::Invalid(fmt::format("meshing at size {} mm: {}", size * 1e3, mesh.status().message()));
  fea::LinkStiffnessOptions o;
  o.clamp = c.clamp;
  o.reference = c.reference;
  o.reference_point = c.reference_point;
  o.keep_fields = false;
  StatusOr<fea::LinkStiffness> r = fea::link_stiffness(*mesh, kSteel, o);
  if (!r.ok()) return Status::Invalid(fmt::format("FEA at size {} mm: {}", size * 1e3, r.status().message()));
  return r;
}

Vec6 eigenvalues(const Mat6& K) { return Eigen::SelfAdjointEigenSolver<Mat6>(0.5 * (K + K.transpose())).eigenvalues(); }

std::string percent(double beam, double reference) { return fmt::format("{:+7.1f}%", 100.0 * (beam / reference - 1.0)); }

// Prints the comparison of one link; returns false when a model failed.
bool compare_link(const LinkCase& c) {
  StatusOr<fea::LinkStiffness> coarse = fea_link(c, c.coarse_size), fine = fea_link(c, c.fine_size);
  StatusOr<Mat6> one = beam_link_spring(c.one_beam, c.reference_point);
  StatusOr<Mat6> four = beam_link_spring(c.four_beams, c.reference_point);
  for (const Status& s : {coarse.status(), fine.status(), one.status(), four.status()})
    if (!s.ok()) {
      std::printf("%s: %s\n", c.file.c_str(), s.message().c_str());
      return false;
    }
  const Mat6& K = fine->stiffness;
  double mesh_change = 0.0;
  for (int i = 0; i < 6; ++i) mesh_change = std::max(mesh_change, std::abs(coarse->stiffness(i, i) / K(i, i) - 1.0));
  std::printf("\n== %s  (FEA: quadratic tets, size %.1f mm, %d dofs; largest diagonal change from size %.1f mm "
              "(%d dofs): %.1f %%)\n   beam sections: %s\n",
              c.file.c_str(), c.fine_size * 1e3, fine->num_dofs, c.coarse_size * 1e3, coarse->num_dofs,
              100.0 * mesh_change, c.sections.c_str());
  std::printf("   %-8s %14s %10s %10s\n", "entry", "K_FEA [SI]", "1 beam", "4 beams");
  for (int i = 0; i < 6; ++i)
    std::printf("   %-8s %14.4e %10s %10s\n", fmt::format("{}-{}", kDofNames[i], kDofNames[i]).c_str(), K(i, i),
                percent((*one)(i, i), K(i, i)).c_str(), percent((*four)(i, i), K(i, i)).c_str());
  for (int i = 0; i < 6; ++i)
    for (int j = i + 1; j < 6; ++j)
      if (std::abs(K(i, j)) > 0.2 * std::sqrt(K(i, i) * K(j, j)))
        std::printf("   %-8s %14.4e %10s %10s\n", fmt::format("{}-{}", kDofNames[i], kDofNames[j]).c_str(), K(i, j),
                    percent((*one)(i, j), K(i, j)).c_str(), percent((*four)(i, j), K(i, j)).c_str());
  const Vec6 e = eigenvalues(K), e1 = eigenvalues(*one), e4 = eigenvalues(*four);
  for (int i = 0; i < 6; ++i)
    std::printf("   %-8s %14.4e %10s %10s\n", fmt::format("eig {}", i + 1).c_str(), e(i), percent(e1(i), e(i)).c_str(),
                percent(e4(i), e(i)).c_str());
  return true;
}

// Cost of the lumped model, for comparison with the FEA run (bench_fea).
void BM_FourBeamLinkSpring(benchmark::State& state) {
  const LinkCase c = link_cases()[3];
  for (auto _ : state) benchmark::DoNotOptimize(beam_link_spring(c.four_beams, c.reference_point));
}
BENCHMARK(BM_FourBeamLinkSpring)->Unit(benchmark::kMicrosecond);

// Meshing + FEA of the parallelogram bar at the comparison's fine size.
void BM_FeaLinkStiffness(benchmark::State& state) {
  const LinkCase c = link_cases()[3];
  int dofs = 0;
  for (auto _ : state) {
    StatusOr<fea::LinkStiffness> r = fea_link(c, c.fine_size);
    if (!r.ok()) state.SkipWithError(r.status().message().c_str());
    else dofs = r->num_dofs;
  }
  state.counters["dofs"] = dofs;
}
BENCHMARK(BM_FeaLinkStiffness)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

int main(int argc, char** argv) {
  std::printf("Link 6x6 stiffness: beam chains against FEA (rigid reference coupling), steel; "
              "(K_beam / K_FEA - 1) per entry, K in N/m, N/rad, N m/rad\n");
  bool ok = true;
  for (const LinkCase& c : link_cases()) ok &= compare_link(c);
  std::printf("\n");
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return ok ? 0 : 1;
}
