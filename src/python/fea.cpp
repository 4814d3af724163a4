// kinestat.fea: tetrahedral meshes of links, their FEA link stiffness (6x6 and report), the input
// parsers shared with the CLI and model files, and the on-disk result cache (fea/*.hpp).
#include "kinestat/core/input_checks.hpp"
#include "kinestat/fea/link_stiffness.hpp"
#include "kinestat/fea/link_stiffness_inputs.hpp"
#include "kinestat/fea/link_stiffness_request.hpp"
#include "kinestat/fea/mesh_convergence.hpp"
#include "kinestat/fea/region.hpp"
#include "kinestat/fea/result_cache.hpp"
#include "kinestat/fea/surface_mesher.hpp"
#include "kinestat/fea/tet_element.hpp"
#include "kinestat/fea/tet_mesh.hpp"
#include "python/bindings.hpp"

namespace kinestat::python {

namespace {

using namespace fea;

// A RuntimeWarning (Python's warnings filters decide whether it shows or raises).
void warn_user(const std::string& message) {
  if (PyErr_WarnEx(PyExc_RuntimeWarning, message.c_str(), 1) != 0) throw py::error_already_set();
}

py::array_t<int> connectivity_array(const TetMesh& mesh) {
  py::array_t<int> a({static_cast<py::ssize_t>(mesh.num_elements()), static_cast<py::ssize_t>(mesh.nodes_per_element)});
  std::copy(mesh.connectivity.begin(), mesh.connectivity.begin() + a.size(), a.mutable_data());
  return a;
}

void set_connectivity(TetMesh& mesh, const py::array_t<int, py::array::c_style | py::array::forcecast>& a) {
  if (a.ndim() != 2 || (a.shape(1) != 4 && a.shape(1) != 10))
    raise_status(Status::Invalid("TetMesh.connectivity: an (elements, 4) or (elements, 10) array of node indices"));
  mesh.nodes_per_element = static_cast<int>(a.shape(1));
  mesh.connectivity.assign(a.data(), a.data() + a.size());
}

void bind_mesh(py::module_& m) {
  py::class_<TetMesh>(m, "TetMesh",
                      "Tetrahedral mesh of a link (m, link frame): nodes (n, 3), connectivity (elements, 4 or 10) "
                      "in VTK order. Assigning the arrays copies them.")
      .def(py::init<>())
      .def_property(
          "nodes", [](const TetMesh& t) { return rows(t.nodes); },
          [](TetMesh& t, const RowsRef<3>& a) { t.nodes = from_rows<3>(a); })
      .def_property("connectivity", &connectivity_array, &set_connectivity)
      .def_readonly("nodes_per_element", &TetMesh::nodes_per_element)
      .def_property_readonly("num_nodes", &TetMesh::num_nodes)
      .def_property_readonly("num_elements", &TetMesh::num_elements)
      .def_property_readonly("quadratic", &TetMesh::quadratic);
  m.def(
      "make_box_mesh",
      [](const Vec3& lo, const Vec3& hi, int nx, int ny, int nz, double max_elements) {
        check(check_box_mesh(lo, hi, nx, ny, nz, max_elements));
        return make_box_mesh(lo, hi, nx, ny, nz);
      },
      py::arg("lo"), py::arg("hi"), py::arg("nx"), py::arg("ny"), py::arg("nz"),
      py::arg("max_elements") = kDefaultMaxElements,
      "Structured 4-node mesh of the box [lo, hi] (m), six tetrahedra per cell. InputError for lo >= hi, fewer than "
      "one cell along an axis, or more than max_elements tetrahedra.");
  m.def("to_quadratic", &to_quadratic, py::arg("linear"), "4-node -> 10-node elements.");
  m.def(
      "validate", [](const TetMesh& t) { check(validate(t)); }, py::arg("mesh"),
      "Raises InputError naming the first bad element.");
  m.def(
      "element_volume",
      [](const TetMesh& t, int e) {
        check(validate(t));
        check_index(e, t.num_elements(), "element_volume: element");
        return element_volume(t, e);
      },
      py::arg("mesh"), py::arg("element"), "Signed volume (m^3).");
  m.def(
      "bounding_box",
      [](const TetMesh& t) {
        Vec3 lo, hi;
        bounding_box(t, lo, hi);
        return std::make_pair(lo, hi);
      },
      py::arg("mesh"), "(lo, hi) corners (m).");
  m.def("content_hash", &content_hash, py::arg("mesh"));

  py::class_<MeshingOptions>(m, "MeshingOptions", "CGAL Mesh_3 criteria; lengths in m after unit_scale.")
      .def(py::init<>())
      .def_readwrite("unit_scale", &MeshingOptions::unit_scale, "file length unit in m (1e-3: mm)")
      .def_readwrite("size", &MeshingOptions::size, "tetrahedron size bound (m)")
      .def_readwrite("facet_distance", &MeshingOptions::facet_distance)
      .def_readwrite("facet_angle", &MeshingOptions::facet_angle)
      .def_readwrite("cell_radius_edge_ratio", &MeshingOptions::cell_radius_edge_ratio)
      .def_readwrite("feature_angle", &MeshingOptions::feature_angle)
      .def_readwrite("optimize", &MeshingOptions::optimize)
      .def_readwrite("quadratic", &MeshingOptions::quadratic, "10-node tetrahedra (default)")
      .def_readwrite("random_seed", &MeshingOptions::random_seed);
  py::class_<SurfaceInfo>(m, "SurfaceInfo")
      .def_readonly("triangles", &SurfaceInfo::triangles)
      .def_readonly("lo", &SurfaceInfo::lo, "bounding box, file units")
      .def_readonly("hi", &SurfaceInfo::hi);
  m.def(
      "check_surface_file", [](const std::string& path) { return unwrap(check_surface_file(path)); }, py::arg("path"),
      "Reads and checks a closed surface (STL, OFF, OBJ, PLY); InputError names the file and the problem.");
  m.def(
      "mesh_surface_file",
      [](const std::string& path, const MeshingOptions& o) {
        return unwrap(without_gil([&] { return mesh_surface_file(path, o); }));
      },
      py::arg("path"), py::arg("options") = MeshingOptions{}, "Checks and meshes a surface file. Releases the GIL.");

  py::enum_<Region::Kind>(m, "RegionKind").value("PLANE", Region::Kind::kPlane).value("BOX", Region::Kind::kBox);
  py::class_<Region>(m, "Region", "A plane or a box of the link frame (m) selecting boundary nodes.")
      .def(py::init<>())
      .def_static("plane", &Region::plane, py::arg("point"), py::arg("normal"), py::arg("tolerance") = 0.0)
      .def_static("box", &Region::box, py::arg("lo"), py::arg("hi"), py::arg("tolerance") = 0.0)
      .def_readwrite("kind", &Region::kind)
      .def_readwrite("point", &Region::point)
      .def_readwrite("normal", &Region::normal)
      .def_readwrite("lo", &Region::lo)
      .def_readwrite("hi", &Region::hi)
      .def_readwrite("tolerance", &Region::tolerance)
      .def("contains", &Region::contains, py::arg("x"), py::arg("tol"))
      .def("describe", &Region::describe)
      .def("__repr__", &Region::describe);
  m.def("select_nodes", &select_nodes, py::arg("mesh"), py::arg("region"));
  m.def("region_tolerance", &region_tolerance, py::arg("mesh"), py::arg("region"));

  m.def("elasticity_matrix", &elasticity_matrix, py::arg("material"), "6x6 isotropic D (Pa), Voigt order.");
  m.def(
      "tet_stiffness",
      [](const RowsRef<3>& x, const Mat6& D) {
        const auto nodes = from_rows<3>(x);
        if (nodes.size() != 4 && nodes.size() != 10) raise_status(Status::Invalid("tet_stiffness: 4 or 10 nodes"));
        MatX K = tet_stiffness(nodes.data(), static_cast<int>(nodes.size()), D);
        // The library's answer for a Jacobian that is not positive somewhere (tet_element.hpp).
        if (K.size() == 0)
          raise_status(Status::Invalid(
              "x: the tetrahedron's Jacobian is not positive (its points are coplanar, not finite, or in the wrong "
              "order); give a tetrahedron of positive volume with its nodes in VTK order"));
        return K;
      },
      py::arg("x"), py::arg("D"),
      "Element stiffness (3n x 3n) of a 4- or 10-node tetrahedron, x (n, 3) in m. InputError for a degenerate or "
      "inverted element.");
  m.def(
      "tet_mass",
      [](const RowsRef<3>& x, double density) {
        const auto nodes = from_rows<3>(x);
        if (nodes.size() != 4 && nodes.size() != 10) raise_status(Status::Invalid("tet_mass: 4 or 10 nodes"));
        MatX M = tet_mass(nodes.data(), static_cast<int>(nodes.size()), density);
        if (M.size() == 0)
          raise_status(Status::Invalid(
              "x: the tetrahedron's Jacobian is not positive (its points are coplanar, not finite, or in the wrong "
              "order); give a tetrahedron of positive volume with its nodes in VTK order"));
        return M;
      },
      py::arg("x"), py::arg("density"),
      "Consistent element mass (3n x 3n, kg) of a 4- or 10-node tetrahedron, x (n, 3) in m, density in kg/m^3. "
      "InputError for a degenerate or inverted element.");
  m.def("von_mises", &von_mises, py::arg("stress"), "Von Mises stress of a Voigt stress vector (Pa).");
}

void bind_link_stiffness(py::module_& m) {
  py::enum_<ReferenceModel>(m, "ReferenceModel")
      .value("RIGID_COUPLING", ReferenceModel::kRigidCoupling)
      .value("STIFF_BODY", ReferenceModel::kStiffBody);
  py::class_<LinkStiffnessOptions>(m, "LinkStiffnessOptions")
      .def(py::init<>())
      .def_readwrite("clamp", &LinkStiffnessOptions::clamp, "Region fixed in ux, uy, uz")
      .def_readwrite("reference", &LinkStiffnessOptions::reference, "Region of the reference end")
      .def_readwrite("reference_model", &LinkStiffnessOptions::reference_model)
      .def_readwrite("stiff_body_ratio", &LinkStiffnessOptions::stiff_body_ratio)
      .def_readwrite("reference_point", &LinkStiffnessOptions::reference_point, "m; None: the reference nodes' centre")
      .def_readwrite("keep_fields", &LinkStiffnessOptions::keep_fields, "keep displacement and von Mises fields")
      .def_readwrite("solver", &LinkStiffnessOptions::solver)
      .def_readwrite("modes", &LinkStiffnessOptions::modes,
                     "how many of the lowest natural frequencies (count, 0: none, at most 100; needs the material's "
                     "density and the cholmod backend)")
      .def_readwrite("progress", &LinkStiffnessOptions::progress, "callable(stage: str) before each stage, or None");
  py::class_<LinkMode>(m, "LinkMode", "A natural mode of the clamped link, mass-normalized (q' M q = 1).")
      .def_readonly("omega", &LinkMode::omega, "rad/s")
      .def_readonly("frequency", &LinkMode::frequency, "Hz")
      .def_readonly("reference_motion", &LinkMode::reference_motion,
                    "(u, theta) of the reference point, m/sqrt(kg) and rad/sqrt(kg)")
      .def_readonly("participation", &LinkMode::participation, "q' M r_d along x, y, z (sqrt(kg))")
      .def_readonly("effective_mass", &LinkMode::effective_mass, "participation squared (kg)")
      .def_readonly("residual", &LinkMode::residual, "||K q - omega^2 M q|| / ||K q||")
      .def_property_readonly(
          "shape", [](const LinkMode& mode) { return rows(mode.shape); },
          "(nodes, 3) node displacements, m/sqrt(kg); empty without keep_fields");
  py::class_<LinkStiffness>(m, "LinkStiffness",
                            "6x6 link stiffness from FEA (rows ux uy uz rx ry rz, link frame, SI units) and its "
                            "report; per unit load case (Fx Fy Fz Mx My Mz) the fields when kept.")
      .def(py::init<>(), "An empty result, for set_compliance (e.g. a measured compliance).")
      .def_readonly("cartesian", &LinkStiffness::cartesian, "the 6x6 (CartesianStiffness) at the reference point")
      .def_property_readonly(
          "reference_point", [](const LinkStiffness& r) { return r.cartesian.point; }, "m")
      .def_property_readonly(
          "compliance", [](const LinkStiffness& r) { return r.cartesian.compliance; },
          "m/N, m/(N m) | rad/N, rad/(N m)")
      .def_property_readonly(
          "stiffness", [](const LinkStiffness& r) { return r.cartesian.stiffness; }, "N/m, N/rad | N m/m, N m/rad")
      .def_readonly("compliance_symmetry_error", &LinkStiffness::compliance_symmetry_error)
      .def_readonly("stiffness_symmetry_error", &LinkStiffness::stiffness_symmetry_error)
      .def_readonly("compliance_eigenvalues", &LinkStiffness::compliance_eigenvalues)
      .def_readonly("num_nodes", &LinkStiffness::num_nodes)
      .def_readonly("num_elements", &LinkStiffness::num_elements)
      .def_readonly("nodes_per_element", &LinkStiffness::nodes_per_element)
      .def_readonly("num_dofs", &LinkStiffness::num_dofs)
      .def_readonly("num_clamped_nodes", &LinkStiffness::num_clamped_nodes)
      .def_readonly("num_reference_nodes", &LinkStiffness::num_reference_nodes)
      .def_readonly("num_stiff_elements", &LinkStiffness::num_stiff_elements)
      .def_readonly("reference_model", &LinkStiffness::reference_model)
      .def_readonly("factorization", &LinkStiffness::factorization)
      .def_readonly("backend", &LinkStiffness::backend)
      .def_readonly("assembly_seconds", &LinkStiffness::assembly_seconds)
      .def_readonly("solve_seconds", &LinkStiffness::solve_seconds)
      .def_property_readonly(
          "displacement",
          [](const LinkStiffness& r) {
            py::list l;
            for (const auto& d : r.displacement) l.append(rows(d));
            return l;
          },
          "six (nodes, 3) arrays, m per unit load; empty without keep_fields")
      .def_readonly("von_mises", &LinkStiffness::von_mises, "six lists of element stresses (Pa per unit load)")
      .def_readonly("mass", &LinkStiffness::mass, "kg, density times the mesh volume (with modes)")
      .def_readonly("modes", &LinkStiffness::modes, "LinkMode list, ascending frequency (options.modes)")
      .def_readonly("modes_seconds", &LinkStiffness::modes_seconds, "mass assembly and eigensolver, s");
  m.def(
      "link_stiffness",
      [](const TetMesh& mesh, const Material& material, const LinkStiffnessOptions& o) {
        return unwrap(without_gil([&] { return link_stiffness(mesh, material, o); }));
      },
      py::arg("mesh"), py::arg("material"), py::arg("options"), "FEA 6x6 link stiffness. Releases the GIL.");
  m.def("link_stiffness_report", &link_stiffness_report, py::arg("result"));
  m.def(
      "set_compliance",
      [](LinkStiffness& r, const Mat6& compliance, const Vec3& point) {
        check(check_entries(compliance, Quantity::kCompliance, "compliance"));
        check(check_entries(point, Quantity::kLength, "point"));
        set_compliance(r, compliance, point);
      },
      py::arg("result"), py::arg("compliance"), py::arg("point"),
      "Sets the compliance (SI) at `point` (m) and what derives from it. InputError for a value not finite or "
      "out of range.");
  m.def("reference_model_name", &reference_model_name, py::arg("model"));
  m.def("scaled_symmetry_error", &scaled_symmetry_error, py::arg("A"));

  // The text inputs of the CLI and of `fea:` springs in model files.
  m.def(
      "parse_numbers",
      [](const std::string& t, size_t n, const std::string& what) { return unwrap(parse_numbers(t, n, what)); },
      py::arg("text"), py::arg("count"), py::arg("what"));
  m.def(
      "parse_region",
      [](const std::string& t, double scale, const std::string& what) { return unwrap(parse_region(t, scale, what)); },
      py::arg("text"), py::arg("scale"), py::arg("what"),
      "'x=V', 'plane:PX,PY,PZ,NX,NY,NZ' or 'box:X0,Y0,Z0,X1,Y1,Z1' in file units, times `scale` to m.");
  m.def(
      "parse_material", [](const std::string& t, const std::string& what) { return unwrap(parse_material(t, what)); },
      py::arg("text"), py::arg("what"), "'steel', 'aluminium' or 'E=PA,nu=V'.");
  m.def("default_mesh_size", &default_mesh_size, py::arg("surface"), py::arg("unit_scale"),
        "1/20 of the surface's largest extent (m).");
  m.def(
      "surface_mesh_identity",
      [](const std::string& path, const MeshingOptions& o) { return unwrap(surface_mesh_identity(path, o)); },
      py::arg("path"), py::arg("meshing"));

  // The result cache.
  m.def("link_stiffness_cache_key", &link_stiffness_cache_key, py::arg("mesh_identity"), py::arg("material"),
        py::arg("options"));
  m.def(
      "is_link_stiffness_cache_key", [](const std::string& k) { return is_link_stiffness_cache_key(k); },
      py::arg("key"), "Whether `key` has the form of link_stiffness_cache_key's keys (32 hex digits).");
  m.def(
      "load_cached_link_stiffness",
      [](const std::string& dir, const std::string& key) -> std::optional<LinkStiffness> {
        CachedLinkStiffness found = unwrap(load_cached_link_stiffness(dir, key));
        if (!found.rejected.empty()) warn_user(found.rejected);
        return found.result;
      },
      py::arg("dir"), py::arg("key"),
      "The cached result (compliance and derived values), or None when absent or rejected: a damaged entry "
      "(checksum, key, a compliance not finite, symmetric and positive definite, not a regular file) gives None "
      "and a RuntimeWarning saying why. InputError for a key not of the cache's form.");
  m.def(
      "store_cached_link_stiffness",
      [](const std::string& dir, const std::string& key, const LinkStiffness& r) {
        check(store_cached_link_stiffness(dir, key, r));
      },
      py::arg("dir"), py::arg("key"), py::arg("result"));

  py::class_<RichardsonEstimate>(m, "RichardsonEstimate")
      .def_readonly("order", &RichardsonEstimate::order)
      .def_readonly("extrapolated", &RichardsonEstimate::extrapolated)
      .def_readonly("finest_error", &RichardsonEstimate::finest_error);
  m.def(
      "richardson_estimate",
      [](const std::vector<double>& h, const std::vector<double>& f) { return unwrap(richardson_estimate(h, f)); },
      py::arg("h"), py::arg("f"), "f(h) = f0 + c h^p through the last three points.");
}

// The one path from a surface file to the 6x6 (what `kinestat link-stiffness` and the `fea:` springs
// of model files run), and its mesh convergence study.
void bind_request(py::module_& m) {
  py::class_<LinkStiffnessRequest>(m, "LinkStiffnessRequest",
                                   "A link's surface file and what to compute from it (compute_link_stiffness).")
      .def(py::init<>())
      .def_readwrite("mesh_file", &LinkStiffnessRequest::mesh_file, "closed surface: STL, OFF, OBJ or PLY")
      .def_readwrite("unit_scale", &LinkStiffnessRequest::unit_scale, "the file's length unit in m (1e-3: mm)")
      .def_readwrite("mesh_size", &LinkStiffnessRequest::mesh_size,
                     "tetrahedron size (m); 0: 1/20 of the largest extent")
      .def_readwrite("quadratic", &LinkStiffnessRequest::quadratic, "10-node tetrahedra (default)")
      .def_readwrite("material", &LinkStiffnessRequest::material)
      .def_readwrite("options", &LinkStiffnessRequest::options, "LinkStiffnessOptions: regions (m), model, fields")
      .def_readwrite("cache_dir", &LinkStiffnessRequest::cache_dir, "result cache folder; '': no cache");
  py::class_<LinkStiffnessRun>(m, "LinkStiffnessRun", "What compute_link_stiffness did and found.")
      .def_readonly("result", &LinkStiffnessRun::result, "LinkStiffness: the 6x6 at the reference point, link axes")
      .def_readonly("mesh", &LinkStiffnessRun::mesh, "the TetMesh solved when the fields were kept, else None")
      .def_readonly("surface", &LinkStiffnessRun::surface)
      .def_readonly("mesh_size", &LinkStiffnessRun::mesh_size, "m, as used")
      .def_readonly("from_cache", &LinkStiffnessRun::from_cache)
      .def_readonly("cache_file", &LinkStiffnessRun::cache_file)
      .def_readonly("report", &LinkStiffnessRun::report, "what was done and the result, as the CLI prints it")
      .def_readonly("warnings", &LinkStiffnessRun::warnings,
                    "what the user should hear: a cache entry rejected and recomputed, and why");
  m.def(
      "compute_link_stiffness",
      [](const LinkStiffnessRequest& r) {
        LinkStiffnessRun run = unwrap(without_gil([&] { return compute_link_stiffness(r); }));
        for (const std::string& w : run.warnings) warn_user(w);
        return run;
      },
      py::arg("request"),
      "Checks the surface, then reads the result from the cache or meshes, solves and stores it. InputError naming "
      "the file. Releases the GIL.");
  py::class_<ConvergenceStudy>(m, "ConvergenceStudy", "The link solved on meshes of decreasing size.")
      .def_readonly("sizes", &ConvergenceStudy::sizes, "m")
      .def_readonly("num_dofs", &ConvergenceStudy::num_dofs)
      .def_readonly("compliance", &ConvergenceStudy::compliance, "6x6 per size (SI)")
      .def_property_readonly(
          "diagonal",
          [](const ConvergenceStudy& s) {
            py::list l;
            for (const auto& d : s.diagonal) l.append(d.ok() ? py::cast(*d) : py::none());
            return l;
          },
          "per dof ux..rz: the RichardsonEstimate of the compliance's diagonal term, None where it has none");
  m.def(
      "link_stiffness_convergence",
      [](const LinkStiffnessRequest& r, const std::vector<double>& sizes) {
        return unwrap(without_gil([&] { return link_stiffness_convergence(r, sizes); }));
      },
      py::arg("request"), py::arg("sizes"),
      "The request on meshes of `sizes` (m, >= 3, decreasing). Releases the GIL.");
  m.def("convergence_report", &convergence_report, py::arg("study"));
}

}  // namespace

void bind_fea(py::module_& m) {
  bind_mesh(m);
  bind_link_stiffness(m);
  bind_request(m);
}

}  // namespace kinestat::python
