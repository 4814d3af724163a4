// kinestat.msa.modal_analysis: natural frequencies, mass-normalized mode shapes and participation
// (msa/modes.hpp, docs/stability-and-modes.md). Failures raise as msa.solve's do.
#include "kinestat/msa/modes.hpp"
#include "python/bindings.hpp"

namespace kinestat::python {

void bind_msa_modes(py::module_& m) {
  using namespace msa;
  py::class_<ModalOptions>(m, "ModalOptions")
      .def(py::init<>())
      .def_readwrite("solve", &ModalOptions::solve, "SolveOptions of the factorization of K")
      .def_readwrite("count", &ModalOptions::count, "how many of the lowest frequencies")
      .def_readwrite("lumped", &ModalOptions::lumped, "lumped instead of consistent beam masses")
      .def_readwrite("rotary_inertia", &ModalOptions::rotary_inertia,
                     "the cross-sections' rotary inertia in the consistent mass");

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
      .def_readonly("modes", &ModalResult::modes, "VibrationMode list, ascending frequency");

  m.def(
      "modal_analysis",
      [](const Structure& s, const std::optional<ModalOptions>& options) {
        const ModalOptions o = options.value_or(ModalOptions{});
        ModalResult r = without_gil([&] { return msa::modal_analysis(s, o); });
        if (!r.status.ok())
          raise_status(r.status, r.status.code() == StatusCode::kSingular ? py::cast(r.linear.singularity)
                                                                            : py::none());
        return r;
      },
      py::arg("structure"), py::arg("options") = py::none(),
      "The lowest natural frequencies, K phi = omega^2 M phi, with beam masses from the densities and the nodal "
      "masses. Raises InputError (bad model, a missing density, end releases), SingularError (with .diagnosis), "
      "NotConvergedError. Releases the GIL.");
}

}  // namespace kinestat::python
