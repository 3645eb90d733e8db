// The nonlinear elements' laws as opaque objects the Python element classes make
// (python/cyclone/elements.py holds their parameters and where they act). Each law checks
// its own parameters and names the one out of range (InputError).
#include <pybind11/pybind11.h>

#include <memory>

#include "Bindings.hpp"
#include "cyclone/hbm/CubicSpring.hpp"
#include "cyclone/hbm/FrictionContact.hpp"
#include "cyclone/hbm/JenkinsElement.hpp"
#include "cyclone/hbm/NonlinearElement.hpp"
#include "cyclone/hbm/QuadraticDamper.hpp"
#include "cyclone/hbm/ScalarElementAdapter.hpp"
#include "cyclone/hbm/UnilateralSpring.hpp"

namespace py = pybind11;

namespace cyclone::python {

namespace {

using Element = std::shared_ptr<hbm::NonlinearElement>;

// A one-coordinate law as the harmonic balance system takes every element.
Element scalar(std::shared_ptr<const hbm::ScalarElement> law) {
  return std::make_shared<hbm::ScalarElementAdapter>(std::move(law));
}

}  // namespace

void bindElements(py::module_& m) {
  py::class_<hbm::NonlinearElement, Element>(m, "ElementLaw", "A nonlinear element's law (cyclone.elements makes them)")
      .def_property_readonly("dimension", &hbm::NonlinearElement::dimension,
                             "coordinates the element acts on (columns of W)")
      .def_property_readonly("recommended_samples", &hbm::NonlinearElement::recommendedSamples,
                             "time samples per period its law needs at least (0: no need)")
      .def_property_readonly("uses_velocity", &hbm::NonlinearElement::usesVelocity,
                             "its force depends on the velocity (so on the frequency at given coefficients)");
  m.def("cubic_spring", [](double k3) { return scalar(std::make_shared<hbm::CubicSpring>(k3)); }, py::arg("k3"));
  m.def(
      "unilateral_spring",
      [](double k, double gap) { return scalar(std::make_shared<hbm::UnilateralSpring>(k, gap)); }, py::arg("k"),
      py::arg("gap"));
  m.def("quadratic_damper", [](double c2) { return scalar(std::make_shared<hbm::QuadraticDamper>(c2)); },
        py::arg("c2"));
  m.def(
      "jenkins", [](double kt, double slipForce) { return scalar(std::make_shared<hbm::JenkinsElement>(kt, slipForce)); },
      py::arg("kt"), py::arg("slip_force"));
  m.def(
      "friction_contact",
      [](int tangentialDirections, double kt, double kn, double mu, double preload) -> Element {
        hbm::FrictionContactParameters p;
        p.tangentialDirections = tangentialDirections;
        p.kt = kt, p.kn = kn, p.mu = mu, p.preload = preload;
        return std::make_shared<hbm::FrictionContact>(p);
      },
      py::arg("tangential_directions"), py::arg("kt"), py::arg("kn"), py::arg("mu"), py::arg("preload"));
}

}  // namespace cyclone::python
