// kinestat.io: structure, VJM model and identification-target files; MSA results as JSON (a Python
// dict) and VTK; link and workspace VTK files; PNG maps (io/*.hpp). Writes the files the CLI writes.
#include <nlohmann/json.hpp>

#include "kinestat/io/fea_vtk.hpp"
#include "kinestat/io/five_bar_design_output.hpp"
#include "kinestat/io/identification_yaml.hpp"
#include "kinestat/io/link_stiffness_json.hpp"
#include "kinestat/io/map_json.hpp"
#include "kinestat/io/map_png.hpp"
#include "kinestat/io/map_vti.hpp"
#include "kinestat/io/results_json.hpp"
#include "kinestat/io/structure_yaml.hpp"
#include "kinestat/io/vjm_yaml.hpp"
#include "kinestat/io/vtk_output.hpp"
#include "kinestat/io/workspace_map_png.hpp"
#include "kinestat/io/workspace_vtk.hpp"
#include "python/bindings.hpp"

namespace kinestat::python {

namespace {

py::object to_python(const nlohmann::json& j) { return py::module_::import("json").attr("loads")(j.dump()); }

nlohmann::json from_python(const py::object& o) {
  const std::string text =
      py::module_::import("json").attr("dumps")(o, py::arg("allow_nan") = false).cast<std::string>();
  return nlohmann::json::parse(text);
}

// A function that writes files and lists them: returns the list.
template <class F>
std::vector<std::string> written_by(F&& write) {
  std::vector<std::string> written;
  check(without_gil([&] { return write(&written); }));
  return written;
}

void bind_files(py::module_& m) {
  m.def(
      "read_structure_yaml", [](const std::string& path) { return unwrap(io::read_structure_yaml(path)); },
      py::arg("path"),
      "Parses and validates a structure file (docs/structure-format.md; SI or mm-N-s, the Structure is SI). "
      "InputError 'FILE:LINE: ITEM: what is wrong; what to do', as the CLI prints.");
  m.def(
      "read_structure_yaml_string",
      [](const std::string& text, const std::string& name) {
        return unwrap(io::read_structure_yaml_string(text, name));
      },
      py::arg("text"), py::arg("display_name") = "<string>", "The same from text; display_name stands for the file.");

  py::class_<io::VjmModel>(m, "VjmModel",
                           "A VJM model file: an Orthoglide (design inputs, chains at any point) or explicit chains.")
      .def_readonly("title", &io::VjmModel::title)
      .def_readonly("orthoglide", &io::VjmModel::orthoglide, "mechanisms.OrthoglideStiffnessModel or None")
      .def_readonly("architecture", &io::VjmModel::architecture)
      .def_readonly("chains", &io::VjmModel::chains);
  m.def(
      "read_vjm_model_yaml",
      [](const std::string& path) { return unwrap(without_gil([&] { return io::read_vjm_model_yaml(path); })); },
      py::arg("path"), "Parses a VJM model file (docs/vjm.md); fea: springs are meshed and solved, or cached.");
  m.def(
      "read_vjm_model_yaml_string",
      [](const std::string& text, const std::string& name) {
        return unwrap(without_gil([&] { return io::read_vjm_model_yaml_string(text, name); }));
      },
      py::arg("text"), py::arg("display_name") = "<string>");
  m.def(
      "vjm_model_chains",
      [](const io::VjmModel& model, const std::optional<Vec3>& point) {
        return unwrap(io::vjm_model_chains(model, point));
      },
      py::arg("model"), py::arg("point") = py::none(),
      "The chains at the tool point (m; Orthoglide models only; None: Q0 or the file's posture).");

  py::class_<io::IdentificationTargets>(m, "IdentificationTargets")
      .def_readonly("inputs", &io::IdentificationTargets::inputs)
      .def_readonly("targets", &io::IdentificationTargets::targets, "SI");
  m.def(
      "read_identification_targets_yaml",
      [](const std::string& path) { return unwrap(io::read_identification_targets_yaml(path)); }, py::arg("path"));
  m.def("input_key", &io::input_key, py::arg("input"));
}

void bind_results(py::module_& m) {
  m.attr("RESULTS_SCHEMA_VERSION") = io::kResultsSchemaVersion;
  m.def(
      "solution_to_json",
      [](const msa::Structure& s, const msa::Solution& sol) { return to_python(unwrap(io::solution_to_json(s, sol))); },
      py::arg("structure"), py::arg("solution"),
      "The JSON results document (docs/results-json.md) as a dict; non-finite numbers are null and listed under "
      "'non_finite_values'.");
  m.def(
      "stiffness_indices_to_json",
      [](const StiffnessIndices& ix) {
        nlohmann::json j = io::stiffness_indices_to_json(ix);
        io::encode_non_finite(j);
        return to_python(j);
      },
      py::arg("indices"));
  m.def(
      "write_json",
      [](const std::string& path, const py::object& j, int indent) {
        check(io::write_json(path, from_python(j), indent));
      },
      py::arg("path"), py::arg("document"), py::arg("indent") = 2,
      "Writes a JSON document (a dict) as the CLI does: indented, or compact with indent=-1 (maps).");
  m.def(
      "write_vtk",
      [](const msa::Structure& s, const msa::Solution& sol, const std::string& dir, const std::string& basename) {
        return written_by([&](std::vector<std::string>* w) { return io::write_vtk(s, sol, dir, basename, w); });
      },
      py::arg("structure"), py::arg("solution"), py::arg("dir"), py::arg("basename"),
      "ParaView files DIR/BASENAME_caseN.vtu and DIR/BASENAME.pvd (free motions for a singular structure). "
      "Returns the paths written.");
  m.def(
      "link_load_case_name",
      [](int k) {
        check_index(k, 6, "link_load_case_name: k");
        return io::link_load_case_name(k);
      },
      py::arg("k"), "'Fx', 'Fy', 'Fz', 'Mx', 'My', 'Mz' for k = 0..5.");
  m.def(
      "write_link_vtu",
      [](const std::string& path, const fea::TetMesh& mesh, const fea::LinkStiffness& r, int k) {
        check(io::write_link_vtu(path, mesh, r, k));
      },
      py::arg("path"), py::arg("mesh"), py::arg("result"), py::arg("k"));
  m.def(
      "write_link_vtu_files",
      [](const std::string& dir, const std::string& prefix, const fea::TetMesh& mesh, const fea::LinkStiffness& r) {
        return written_by(
            [&](std::vector<std::string>* w) { return io::write_link_vtu_files(dir, prefix, mesh, r, w); });
      },
      py::arg("dir"), py::arg("prefix"), py::arg("mesh"), py::arg("result"),
      "The six deformed-link files DIR/PREFIX_Fx.vtu ... (needs keep_fields). Returns the paths written.");
  m.def(
      "write_link_mode_vtu_files",
      [](const std::string& dir, const std::string& prefix, const fea::TetMesh& mesh, const fea::LinkStiffness& r) {
        return written_by(
            [&](std::vector<std::string>* w) { return io::write_link_mode_vtu_files(dir, prefix, mesh, r, w); });
      },
      py::arg("dir"), py::arg("prefix"), py::arg("mesh"), py::arg("result"),
      "One file per mode DIR/PREFIX_modes_modeK.vtu (point vector mode_shape, m/sqrt(kg)) and DIR/PREFIX_modes.pvd "
      "(needs modes and keep_fields). Returns the paths written.");
  m.def(
      "write_orthoglide_workspace_vtk",
      [](const mechanisms::OrthoglideDesign& d, int n, const std::string& dir) {
        return written_by(
            [&](std::vector<std::string>* w) { return io::write_orthoglide_workspace_vtk(d, n, dir, w); });
      },
      py::arg("design"), py::arg("n"), py::arg("dir"), "Joint workspace and cube of a design as .vtu files.");
}

void bind_png(py::module_& m) {
  py::class_<io::PlotField2D>(m, "PlotField2D", "A scalar field on a regular grid, in plot units; NaN = blank.")
      .def(
          py::init([](const Eigen::Ref<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>& v,
                      double x0, double y0, double dx, double dy, std::string title) {
            io::PlotField2D f{
                static_cast<int>(v.cols()), static_cast<int>(v.rows()), x0, y0, dx, dy, {}, std::move(title), {}};
            f.values.assign(v.data(), v.data() + v.size());
            return f;
          }),
          py::arg("values"), py::arg("x0") = 0.0, py::arg("y0") = 0.0, py::arg("dx") = 1.0, py::arg("dy") = 1.0,
          py::arg("title") = "", "values: (ny, nx) array, values[j, i] at (x0 + i dx, y0 + j dy).")
      .def_readonly("nx", &io::PlotField2D::nx)
      .def_readonly("ny", &io::PlotField2D::ny)
      .def_readwrite("title", &io::PlotField2D::title);
  py::enum_<io::CurveStyle>(m, "CurveStyle", "How a PlotCurve is drawn (no colour is one of viridis's)")
      .value("SOLID_BLACK", io::CurveStyle::kSolidBlack)
      .value("DASHED_RED", io::CurveStyle::kDashedRed)
      .value("SHORT_DASHED_MAGENTA", io::CurveStyle::kShortDashedMagenta);
  py::class_<io::PlotCurve>(m, "PlotCurve")
      .def(py::init([](const RowsRef<2>& points, std::string label, io::CurveStyle style) {
             io::PlotCurve c{{}, std::move(label), style};
             for (Eigen::Index i = 0; i < points.rows(); ++i) c.points.push_back({points(i, 0), points(i, 1)});
             return c;
           }),
           py::arg("points"), py::arg("label") = "", py::arg("style") = io::CurveStyle::kSolidBlack)
      .def_readonly("label", &io::PlotCurve::label)
      .def_readonly("style", &io::PlotCurve::style);
  py::class_<io::PlotOptions>(m, "PlotOptions")
      .def(py::init<>())
      .def_readwrite("title", &io::PlotOptions::title)
      .def_readwrite("x_label", &io::PlotOptions::x_label)
      .def_readwrite("y_label", &io::PlotOptions::y_label)
      .def_readwrite("colorbar_label", &io::PlotOptions::colorbar_label)
      .def_readwrite("width", &io::PlotOptions::width)
      .def_readwrite("height", &io::PlotOptions::height)
      .def_readwrite("log_scale", &io::PlotOptions::log_scale)
      .def_readwrite("curves", &io::PlotOptions::curves, py::return_value_policy::copy);
  m.def(
      "write_png_map",
      [](const std::string& path, const io::PlotField2D& f, const io::PlotOptions& o) {
        check(io::write_png_map(path, f, o));
      },
      py::arg("path"), py::arg("field"), py::arg("options"));
  m.def(
      "write_png_sheet",
      [](const std::string& path, const std::vector<io::PlotField2D>& f, const io::PlotOptions& o) {
        check(io::write_png_sheet(path, f, o));
      },
      py::arg("path"), py::arg("fields"), py::arg("options"));
}

// The files of `kinestat map` and `kinestat design fivebar`.
void bind_map_files(py::module_& m) {
  m.def(
      "workspace_map_to_json",
      [](const mechanisms::WorkspaceMap& map) { return to_python(io::workspace_map_to_json(map)); }, py::arg("map"),
      "The map as the JSON document of `kinestat map --json` (schema kinestat-workspace-map, docs/maps.md), a dict: "
      "flat arrays x fastest, None where a point has no value.");
  m.def(
      "write_map_vti",
      [](const std::string& path, const mechanisms::WorkspaceMap& map, bool hide_masked_points) {
        check(without_gil([&] { return io::write_map_vti(path, map, io::MapVtiOptions{hide_masked_points}); }));
      },
      py::arg("path"), py::arg("map"), py::arg("hide_masked_points") = true,
      "VTK ImageData for ParaView, as `kinestat map --vti`: one array per field 'NAME (UNIT)', NaN where no value, "
      "'status'; points without values hidden (vtkGhostType) unless hide_masked_points is False.");
  m.def(
      "write_workspace_map_png",
      [](const std::string& path, const mechanisms::WorkspaceMap& map, const MapFieldArg& field) {
        const mechanisms::MapField f = map_field(field);
        check(without_gil([&] { return io::write_workspace_map_png(path, map, f); }));
      },
      py::arg("path"), py::arg("map"), py::arg("field") = std::string("k_t_min"),
      "The PNG of `kinestat map --png --field FIELD`: axes in mm, values in display units (map_field_display), "
      "the map's curves over it; a box gives a sheet of z slices.");
  m.def(
      "map_field_display",
      [](const MapFieldArg& field) {
        const io::MapFieldDisplay d = io::map_field_display(map_field(field));
        return py::make_tuple(d.unit, d.scale);
      },
      py::arg("field"), "(unit, scale): the field as the CLI shows it is its SI value times scale, in unit.");
  m.def(
      "design_sweep_to_json",
      [](const mechanisms::FiveBarDesignSweep& s) { return to_python(io::design_sweep_to_json(s)); }, py::arg("sweep"),
      "The sweep as the JSON document of `kinestat design fivebar --json` (without its timing), a dict.");
  m.def(
      "write_design_sweep_vti",
      [](const std::string& path, const mechanisms::FiveBarDesignSweep& s) {
        check(io::write_design_sweep_vti(path, s));
      },
      py::arg("path"), py::arg("sweep"), "The design grid (x = r1, y = r2, m) with the shares, for ParaView.");
  m.def(
      "write_design_sweep_png",
      [](const std::string& path, const mechanisms::FiveBarDesignSweep& s) {
        check(without_gil([&] { return io::write_design_sweep_png(path, s); }));
      },
      py::arg("path"), py::arg("sweep"), "The PNG of `kinestat design fivebar --png`: the share (%) over r1, r2 (mm).");
  m.def(
      "link_stiffness_to_json",
      [](const std::string& mesh_file, double mesh_size, const fea::LinkStiffness& r, bool from_cache) {
        return to_python(io::link_stiffness_to_json(mesh_file, mesh_size, r, from_cache));
      },
      py::arg("mesh_file"), py::arg("mesh_size"), py::arg("result"), py::arg("from_cache") = false,
      "The JSON document of `kinestat link-stiffness --json` (mesh_size in m), a dict.");
}

}  // namespace

void bind_io(py::module_& m) {
  bind_files(m);
  bind_results(m);
  bind_png(m);
  bind_map_files(m);
}

}  // namespace kinestat::python
