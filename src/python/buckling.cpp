// kinestat.msa.buckling: the critical load factors of one load case and their mode shapes
// (msa/buckling.hpp, docs/stability-and-modes.md). Failures raise as msa.solve's do.
#include "kinestat/msa/buckling.hpp"
#include "python/bindings.hpp"

namespace kinestat::python {

void bind_msa_buckling(py::module_& m) {
  using namespace msa;
  py::class_<BucklingOptions>(m, "BucklingOptions")
      .def(py::init<>())
      .def_readwrite("solve", &BucklingOptions::solve, "SolveOptions of the linear solve that gives the axial forces")
      .def_readwrite("load_case", &BucklingOptions::load_case, "index of the load case (from 0)")
      .def_readwrite("count", &BucklingOptions::count, "how many of the smallest positive load factors")
      .def_readwrite("torsion_term", &BucklingOptions::torsion_term,
                     "the Wagner term N Ip / (A L) of the geometric stiffness (Ip: Section.Ip, or Iy + Iz)");

  py::class_<BucklingMode>(m, "BucklingMode", "One critical load factor and its mode shape.")
      .def_readonly("load_factor", &BucklingMode::load_factor,
                    "lambda (dimensionless): the loads times lambda are critical")
      .def_property_readonly(
          "shape", [](const BucklingMode& b) { return rows(b.shape); },
          "(nodes, 6): translations and rotations, global axes, the largest translation 1 (m)")
      .def_readonly("residual", &BucklingMode::residual, "||K phi + lambda K_G phi|| / ||K phi||");

  py::class_<BucklingResult>(m, "BucklingResult")
      .def_readonly("status", &BucklingResult::status)
      .def_readonly("linear", &BucklingResult::linear, "the linear Solution that gave the axial forces")
      .def_readonly("load_case", &BucklingResult::load_case)
      .def_readonly("load_case_name", &BucklingResult::load_case_name)
      .def_property_readonly(
          "axial_force", [](const BucklingResult& r) { return r.axial_force; },
          "per beam, N (tension positive): the mean of its end forces")
      .def_readonly("modes", &BucklingResult::modes, "BucklingMode list, ascending load factor")
      .def_readonly("num_free_dofs", &BucklingResult::num_free_dofs);

  m.def(
      "buckling",
      [](const Structure& s, const std::optional<BucklingOptions>& options) {
        const BucklingOptions o = options.value_or(BucklingOptions{});
        BucklingResult r = without_gil([&] { return msa::buckling(s, o); });
        if (!r.status.ok())
          raise_status(r.status,
                       r.status.code() == StatusCode::kSingular ? py::cast(r.linear.singularity) : py::none());
        return r;
      },
      py::arg("structure"), py::arg("options") = py::none(),
      "Linear buckling: the smallest positive critical load factors of one load case, K phi = -lambda K_G phi. "
      "Raises InputError (bad model, no compressed beam, end releases), SingularError (with .diagnosis) for a "
      "singular structure, NotConvergedError when the eigensolver fails. Releases the GIL.");
}

}  // namespace kinestat::python
