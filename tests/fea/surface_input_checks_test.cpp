// Surface files that would crash, exhaust memory or hang the mesher are refused before CGAL reads them
// or before Mesh_3 starts (docs/reliability.md); the option parsers refuse what is not a finite value
// in range and every unknown item.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "kinestat/fea/link_stiffness_inputs.hpp"
#include "kinestat/fea/surface_mesher.hpp"

namespace kinestat::fea {
namespace {

const std::string kMeshes = std::string(KINESTAT_SOURCE_DIR) + "/meshes/";

void expect_contains(const std::string& message, const std::string& part) {
  EXPECT_NE(message.find(part), std::string::npos) << "expected \"" << part << "\" in: " << message;
}

std::string write_file(const std::string& name, const std::string& bytes) {
  const auto path = std::filesystem::temp_directory_path() / ("kinestat_checks_" + name);
  std::ofstream(path, std::ios::binary) << bytes;
  return path.string();
}

// The surface of an axis-aligned box [0, a] x [0, b] x [0, c] as OFF text.
std::string box_off(double a, double b, double c) {
  std::string s = "OFF\n8 12 0\n";
  for (int i = 0; i < 8; ++i) s += fmt::format("{} {} {}\n", i & 4 ? a : 0.0, i & 2 ? b : 0.0, i & 1 ? c : 0.0);
  for (const char* f :
       {"0 1 3", "0 3 2", "4 6 7", "4 7 5", "0 4 5", "0 5 1", "2 3 7", "2 7 6", "0 2 6", "0 6 4", "1 5 7", "1 7 3"})
    s += std::string("3 ") + f + "\n";
  return s;
}

void expect_refused(const std::string& name, const std::string& bytes, const std::string& part) {
  const std::string path = write_file(name, bytes);
  const auto r = check_surface_file(path);
  ASSERT_FALSE(r.ok()) << name;
  EXPECT_EQ(r.status().code(), StatusCode::kInvalidInput);
  EXPECT_EQ(r.status().message().rfind(path + ": ", 0), 0u) << r.status().message();
  expect_contains(r.status().message(), part);
}

TEST(SurfaceInputChecks, CountsTheFileCannotHoldAreRefusedBeforeReading) {
  expect_refused("huge_header.off", "OFF\n8 1000000000 0\n0 0 0\n", "announces 8 vertices and 1000000000 faces");
  expect_refused("huge_ply.ply", "ply\nformat ascii 1.0\nelement vertex 1000000000000\nproperty float x\nend_header\n",
                 "announces 1000000000000 'vertex' elements");
  std::string stl(84 + 50, '\0');
  stl[80] = '\x00', stl[81] = '\x28', stl[82] = '\x6b', stl[83] = '\xee';  // 4e9 triangles, little endian
  expect_refused("huge.stl", stl, "announces 4000000000 triangles");
}

TEST(SurfaceInputChecks, FaceRecordsThatWouldAllocateOrConvertOutOfRangeAreRefused) {
  const std::string tet = "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
  expect_refused("negative_size.off", tet + "-1 0 1 2\n", "face 0: '-1 0 1 2' does not list");
  expect_refused("huge_size.off", tet + "1e18 0 1 2\n", "does not list as many vertex indices");
  expect_refused("bad_index.off", tet + "3 0 1 9\n", "vertex index 9 is not one of the 4 vertices");
  expect_refused("colour.off", "COFF\n4 1 0\n0 0 0 1e10 0 0\n", "only plain ASCII OFF is read");
  expect_refused("int_list.ply",
                 "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                 "element face 1\nproperty list int int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n"
                 "1000000000 0 1 2\n",
                 "list's length is of type 'int'");
  // Found by fuzz_surface_mesh: CGAL's PLY reader attached the property to an element that did not exist.
  expect_refused("property_first.ply", "ply\nformat ascii 1.0\nproperty float x\nelement vertex 1\nend_header\n0\n",
                 "a PLY property is declared before any element");
  // Found by fuzz_surface_mesh: CGAL read the count's leading digits and allocated 1.6 GB for a 48-byte file.
  expect_refused("count_with_letters.ply", "ply\nformat ascii 1.0\nelement vertex 90000001eader\n",
                 "the PLY element 'vertex' has the count '90000001eader'");
  // Found by fuzz_surface_mesh: CGAL dereferenced a coordinate of another type than float or double as a float.
  expect_refused("int_coordinate.ply",
                 "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty uchar y\nproperty float z\n"
                 "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
                 "the PLY vertex property 'y' is of type 'uchar'");
  expect_refused("out_of_range.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 99\n", "cannot read a triangle surface");
}

TEST(SurfaceInputChecks, GeometryThatWouldOverflowOrHangTheMesherIsRefused) {
  expect_refused("huge.off", box_off(1e300, 1e300, 1e300), "is not finite or beyond 1e+09");
  // A closed needle 1e-9 thick: Mesh_3 ran for minutes protecting its edges.
  expect_refused("needle.off", box_off(100, 1e-9, 1e-9), "a needle or a sheet");
  // A box pressed flat (its top on its bottom, two sheets of faces) and a triangle whose corners lie on
  // one line (a bar's edge split at its middle, the bottom closed by a triangle through that point)
  // are self-intersections to CGAL: each is named as what it is. A file with no face says so.
  std::ifstream bar(kMeshes + "bar.off");
  std::string flat((std::istreambuf_iterator<char>(bar)), std::istreambuf_iterator<char>());
  for (const std::string z : {" -15\n", " 15\n"})
    for (std::size_t at = flat.find(z); at != std::string::npos; at = flat.find(z)) flat.replace(at, z.size(), " 0\n");
  expect_refused("flat.off", flat, "a needle or a sheet");
  expect_refused("no_face.off", "OFF\n0 0 0\n", "the file has no face");
  expect_refused("collinear.off",
                 "OFF\n9 14 0\n0 -10 -15\n0 10 -15\n0 10 15\n0 -10 15\n200 -10 -15\n200 10 -15\n200 10 15\n"
                 "200 -10 15\n100 -10 -15\n3 4 8 1\n3 8 0 1\n3 5 1 2\n3 6 2 3\n3 7 3 0\n3 0 3 2\n3 7 4 5\n"
                 "3 1 5 4\n3 2 6 5\n3 3 7 6\n3 0 4 7\n3 2 1 0\n3 5 6 7\n3 0 8 4\n",
                 "has no area (they lie on one line)");
  EXPECT_TRUE(check_surface_file(write_file("box.off", box_off(100, 10, 10))).ok());
}

TEST(SurfaceInputChecks, ElementCountIsEstimatedAndLimitedBeforeMeshing) {
  // The bundled bar, 200 x 20 x 30 mm: V = 120 000 mm^3, A = 21 200 mm^2 (meshes/make_meshes.cpp).
  const auto info = check_surface_file(kMeshes + "bar.off");
  ASSERT_TRUE(info.ok()) << info.status().message();
  EXPECT_NEAR(info->volume, 120000.0, 1e-6);
  EXPECT_NEAR(info->area, 21200.0, 1e-6);
  // 4 V / h^3 + 1.3 A / h^2 at h = 5 mm (under 2 V / A = 11.3 mm): 3840 + 1102.4.
  EXPECT_NEAR(estimate_tetrahedra(*info, 1e-3, 5e-3), 4942.4, 1e-6);
  // Mesh_3 makes 4765 tetrahedra there (docs/reliability.md): the estimate is within 4 %.
  MeshingOptions o;
  o.quadratic = false;
  o.size = 5e-3;
  const auto mesh = mesh_surface_file(kMeshes + "bar.off", o);
  ASSERT_TRUE(mesh.ok()) << mesh.status().message();
  const double ratio = estimate_tetrahedra(*info, 1e-3, 5e-3) / mesh->num_elements();
  EXPECT_GT(ratio, 0.8);
  EXPECT_LT(ratio, 2.0);

  // 0.3 mm asks for about 1.8e7 tetrahedra: refused at once, naming the estimate and the option.
  o.size = 0.3e-3;
  const auto refused = mesh_surface_file(kMeshes + "bar.off", o);
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.status().code(), StatusCode::kInvalidInput);
  expect_contains(refused.status().message(), "meshing with size 0.0003 m: about 1.81e+07 tetrahedra");
  expect_contains(refused.status().message(), "above the limit of 3e+05");
  expect_contains(refused.status().message(), "--max-elements");
}

TEST(OptionParsers, NumbersMustBeFiniteAndComplete) {
  expect_contains(parse_numbers("1,nan,3", 3, "--reference-point").status().message(), "'nan' is not a finite number");
  expect_contains(parse_numbers("1,1e400,3", 3, "--reference-point").status().message(), "'1e400' is not");
  expect_contains(parse_numbers("1,2,3,", 3, "--reference-point").status().message(), "expected 3");
  ASSERT_TRUE(parse_numbers("1,2,3", 3, "p").ok());
  expect_contains(parse_point("0,1e300,0", 1e-3, "--reference-point").status().message(),
                  "--reference-point = 1e+300 mm is too large for a length");
  const auto p = parse_point("1,2,3", 1e-3, "p");
  ASSERT_TRUE(p.ok());
  EXPECT_NEAR((*p - Vec3(1e-3, 2e-3, 3e-3)).norm(), 0.0, 1e-18);
}

TEST(OptionParsers, RegionsAreRangedAndNormalized) {
  expect_contains(parse_region("x=1e300", 1e-3, "--clamp").status().message(),
                  "--clamp = 1e+300 mm is too large for a length");
  const auto plane = parse_region("plane:0,0,0,1e300,1e300,0", 1e-3, "--clamp");
  ASSERT_TRUE(plane.ok()) << plane.status().message();
  EXPECT_NEAR((plane->normal - Vec3(1, 1, 0) / std::sqrt(2.0)).norm(), 0.0, 1e-15);  // not nan
  expect_contains(parse_region("plane:0,0,0,0,0,0", 1e-3, "--clamp").status().message(), "non-zero");
}

TEST(OptionParsers, MaterialRefusesUnknownItemsAndOutOfRangeValues) {
  expect_contains(parse_material("E=2.1e11,nu=0.3,G=8e10", "--material").status().message(), "unknown item 'G=8e10'");
  // rho (kg/m^3) is an item since the link modes need a density.
  EXPECT_DOUBLE_EQ(parse_material("E=2.1e11,nu=0.3,rho=7800", "--material")->density, 7800.0);
  expect_contains(parse_material("E=2.1e11,nu=0.3,rho=0", "--material").status().message(), "rho");
  expect_contains(parse_material("E=2.1e11,E=1e11,nu=0.3", "--material").status().message(), "'E' is given twice");
  expect_contains(parse_material("E=1e300,nu=0.3", "--material").status().message(), "too large for a modulus");
  expect_contains(parse_material("E=2.1e11,nu=0.5", "--material").status().message(), "nu = 0.5 is not in");
  const auto m = parse_material("nu=0.25,E=1e9", "--material");
  ASSERT_TRUE(m.ok()) << m.status().message();
  EXPECT_DOUBLE_EQ(m->E, 1e9);
  EXPECT_DOUBLE_EQ(m->G, 1e9 / 2.5);
}

}  // namespace
}  // namespace kinestat::fea
