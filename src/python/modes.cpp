// kinestat.msa.modal_analysis: natural frequencies, mass-normalized mode shapes and participation
// (msa/modes.hpp, docs/stability-and-modes.md). Failures raise as msa.solve's do.
#include "kinestat/msa/modes.hpp"
#include "python/bindings.hpp"

namespace kinestat::python {

void bind_msa_modes(py::module_& m) {
  using namespace msa;
  py::class_<ModalPrestress>(m, "ModalPrestress",
                             "K_G of one load case's axial forces added to K: the frequencies of the prestressed "
                             "structure (tension raises them, compression lowers them).")
      .def(py::init([](int load_case, bool second_order) {
             return ModalPrestress{load_case, second_order, {}};
           }),
           py::arg("load_case") = 0, py::arg("second_order") = false)
      .def_readwrite("load_case", &ModalPrestress::load_case, "index into Structure.load_cases")
      .def_readwrite("second_order", &ModalPrestress::second_order,
                     "axial forces of solve_second_order (Frame3DD's geometric stiffness flag) instead of solve")
      .def_readwrite("second_order_options", &ModalPrestress::second_order_options,
                     "SecondOrderOptions: tolerance, max_iterations, torsion_term (the Wagner term, either solve)");

  py::class_<ModalPrestressReport>(m, "ModalPrestressReport", "What prestressed the structure.")
      .def_readonly("load_case", &ModalPrestressReport::load_case)
      .def_readonly("load_case_name", &ModalPrestressReport::load_case_name)
      .def_readonly("second_order", &ModalPrestressReport::second_order)
      .def_readonly("axial_force", &ModalPrestressReport::axial_force, "per beam, N (tension positive): the N of K_G");

  py::class_<ModalOptions>(m, "ModalOptions")
      .def(py::init<>())
      .def_readwrite("solve", &ModalOptions::solve, "SolveOptions of the factorization of K")
      .def_readwrite("count", &ModalOptions::count, "how many of the lowest frequencies")
      .def_readwrite("lumped", &ModalOptions::lumped, "lumped instead of consistent beam masses")
      .def_readwrite("rotary_inertia", &ModalOptions::rotary_inertia,
                     "the cross-sections' rotary inertia in the consistent mass")
      .def_readwrite("prestress", &ModalOptions::prestress,
                     "ModalPrestress or None (the unstressed structure); assign a whole ModalPrestress");

  py::class_<VibrationMode>(m, "VibrationMode", "One natural frequency and its mode shape.")
      .def_readonly("omega", &VibrationMode::omega, "rad/s")
      .def_readonly("frequency", &VibrationMode::frequency, "Hz")
      .def_property_readonly(
          "shape", [](const VibrationMode& v) { return rows(v.shape); },
          "(nodes, 6), global axes, mass-normalized (phi' M phi = 1): m/sqrt(kg), rad/sqrt(kg)")
      .def_readonly("participation", &VibrationMode::participation,
                    "Gamma_d = phi' M r_d along global x, y, z (sqrt(kg))")
      .def_readonly("effective_mass", &VibrationMode::effective_mass, "Gamma_d^2 (kg)")
      .def_readonly("residual", &VibrationMode::residual, "||K q - omega^2 M q|| / ||K q||");

  py::class_<ModalResult>(m, "ModalResult")
      .def_readonly("status", &ModalResult::status)
      .def_readonly("linear", &ModalResult::linear, "the static Solution (its checks and diagnosis)")
      .def_readonly("num_free_dofs", &ModalResult::num_free_dofs)
      .def_readonly("total_mass", &ModalResult::total_mass, "r_d' M r_d over every node, x y z (kg)")
      .def_readonly("modes", &ModalResult::modes, "VibrationMode list, ascending frequency")
      .def_readonly("prestress", &ModalResult::prestress, "ModalPrestressReport, or None without a prestress");

  m.def(
      "modal_analysis",
      [](const Structure& s, const std::optional<ModalOptions>& options) {
        const ModalOptions o = options.value_or(ModalOptions{});
        ModalResult r = without_gil([&] { return msa::modal_analysis(s, o); });
        if (!r.status.ok())
          raise_status(r.status,
                       r.status.code() == StatusCode::kSingular ? py::cast(r.linear.singularity) : py::none());
        return r;
      },
      py::arg("structure"), py::arg("options") = py::none(),
      "The lowest natural frequencies, K phi = omega^2 M phi, with beam masses from the densities and the nodal "
      "masses; with options.prestress, (K + K_G) phi = omega^2 M phi. Raises InputError (bad model, a missing "
      "density, end releases, a prestress at or past its case's critical load), SingularError (with .diagnosis), "
      "NotConvergedError (also a second-order prestress whose solve fails). Releases the GIL.");
}

}  // namespace kinestat::python
