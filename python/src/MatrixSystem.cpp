// A harmonic balance system of matrices M, C, K and nonlinear elements
// (hbm::HarmonicBalanceSystem), built by python/cyclone/system.py from its arguments, and
// its residual and Jacobian for a user who drives a solver of their own (tmdsimpy's
// hbm_res). Arrays arrive checked (shapes, finite entries) by the Python layer, which
// names the argument; what the library refuses it names as well (InputError).
#include <pybind11/eigen.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <memory>
#include <string>
#include <utility>

#include "Bindings.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/hbm/HarmonicBalanceSystem.hpp"
#include "cyclone/hbm/ModalDamping.hpp"
#include "cyclone/hbm/PeakMagnitude.hpp"

namespace py = pybind11;

namespace cyclone::python {

namespace {

using hbm::HarmonicBalanceSystem;

void requireUnknowns(const HarmonicBalanceSystem& system, const Eigen::VectorXd& x, const char* name) {
  if (x.size() != system.numUnknowns())
    throw InputError(name, "has " + std::to_string(x.size()) + " entries; the system has " +
                               std::to_string(system.numUnknowns()) + " unknowns (" +
                               std::to_string(system.numDofs()) + " DOFs x " +
                               std::to_string(system.numCoefficients()) + " coefficients)");
}

// R(x; omega) and dR/dx, computed without the GIL (an element's AFT over many samples).
py::tuple residual(const HarmonicBalanceSystem& system, const Eigen::VectorXd& x, double omega, double forceScale,
                   bool withJacobian) {
  requireUnknowns(system, x, "x");
  Eigen::VectorXd R;
  Eigen::MatrixXd J;
  {
    py::gil_scoped_release release;
    system.residual(x, omega, R, withJacobian ? &J : nullptr, forceScale);
  }
  if (!withJacobian) return py::make_tuple(R, py::none());
  return py::make_tuple(R, J);
}

}  // namespace

void bindMatrixSystem(py::module_& m) {
  py::class_<HarmonicBalanceSystem, std::shared_ptr<HarmonicBalanceSystem>>(
      m, "MatrixSystem", "M x'' + C x' + K x + nonlinear forces = excitation, by harmonic balance")
      .def(py::init([](Eigen::MatrixXd M, Eigen::MatrixXd C, Eigen::MatrixXd K, std::vector<int> harmonics,
                       int samples) {
             return std::make_shared<HarmonicBalanceSystem>(std::move(M), std::move(C), std::move(K),
                                                            hbm::HarmonicSet(std::move(harmonics)), samples);
           }),
           py::arg("M"), py::arg("C"), py::arg("K"), py::arg("harmonics"), py::arg("samples"))
      .def(
          "set_cyclic",
          [](HarmonicBalanceSystem& s, int sectors, int engineOrder, Eigen::MatrixXd Mnext, Eigen::MatrixXd Cnext,
             Eigen::MatrixXd Knext) {
            s.setCyclic(hbm::CyclicCoupling{sectors, engineOrder, std::move(Mnext), std::move(Cnext), std::move(Knext)});
          },
          py::arg("sectors"), py::arg("engine_order"), py::arg("M_next"), py::arg("C_next"), py::arg("K_next"))
      .def(
          "add_element",
          [](HarmonicBalanceSystem& s, std::shared_ptr<hbm::NonlinearElement> law, Eigen::MatrixXd W,
             Eigen::MatrixXd Wnext) { s.addElement(std::move(law), std::move(W), std::move(Wnext)); },
          py::arg("law"), py::arg("W"), py::arg("W_next"))
      .def("add_excitation", &HarmonicBalanceSystem::addExcitation, py::arg("dof"), py::arg("harmonic"),
           py::arg("cos"), py::arg("sin"))
      .def("add_static_load", &HarmonicBalanceSystem::addStaticLoad, py::arg("dof"), py::arg("value"))
      .def("residual", &residual, py::arg("x"), py::arg("omega"), py::arg("force_scale"), py::arg("jacobian"))
      .def(
          "linearized_solution",
          [](const HarmonicBalanceSystem& s, double omega, double forceScale) {
            py::gil_scoped_release release;
            return s.linearizedSolution(omega, forceScale);
          },
          py::arg("omega"), py::arg("force_scale"))
      .def(
          "max_abs",
          [](const HarmonicBalanceSystem& s, const Eigen::VectorXd& x, int dof) {
            requireUnknowns(s, x, "x");
            if (dof < 0 || dof >= s.numDofs()) throw InputError("dof", std::to_string(dof) + " is out of range");
            const int nc = s.numCoefficients();
            return hbm::peakMagnitude(s.aft().harmonics(), Eigen::VectorXd(x.segment(dof * nc, nc)));
          },
          py::arg("x"), py::arg("dof"))
      .def("nodal_diameter", &HarmonicBalanceSystem::nodalDiameter, py::arg("harmonic"))
      .def_property_readonly("num_dofs", &HarmonicBalanceSystem::numDofs)
      .def_property_readonly("num_coefficients", &HarmonicBalanceSystem::numCoefficients)
      .def_property_readonly("num_unknowns", &HarmonicBalanceSystem::numUnknowns)
      .def_property_readonly("harmonics", [](const HarmonicBalanceSystem& s) { return s.aft().harmonics().harmonics(); })
      .def_property_readonly("samples", [](const HarmonicBalanceSystem& s) { return s.aft().numSamples(); });
  m.def("modal_damping", &hbm::modalDamping, py::arg("M"), py::arg("K"), py::arg("ratio"));
  m.def(
      "nonsmooth_samples", [](std::vector<int> harmonics) { return hbm::HarmonicSet(std::move(harmonics)).nonsmoothSamples(); },
      py::arg("harmonics"), "samples for friction and gaps that grow with the harmonics (HarmonicSet::nonsmoothSamples)");
}

}  // namespace cyclone::python
