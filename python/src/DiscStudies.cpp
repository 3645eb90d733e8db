// The disc's value-list studies, as a disc scene's disc_response/studies
// (drivers/src/DiscStages.cpp): one frequency curve per value of a contact, excitation
// or model parameter over the reference curve's band, traced with the reference's sweep
// options without the harmonics check (disc::studyDisc), from the curve a Python disc
// response keeps (DiscReference.hpp). Every value is checked before any work, as the
// scene's reader checks them. Without the GIL but while a curve's arrays are made.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <string>
#include <vector>

#include "Bindings.hpp"
#include "CurveArrays.hpp"
#include "DiscReference.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/disc/DiscParameterStudy.hpp"

namespace py = pybind11;

namespace cyclone::python {

namespace {

// The highest harmonic a harmonics study may ask for, as a scene's (DiscStages.cpp): the
// curve's, or the harmonics check's when given.
int highestHarmonic(const DiscReference& ref) {
  const int curve = *std::max_element(ref.spec.harmonics.begin(), ref.spec.harmonics.end());
  return std::max(curve, ref.sweep.harmonicsCheckTo);
}

// Per value: the value, whether it is the reference's, the curve's arrays with the
// harmonics and output DOFs of the system it was traced on, its warnings and seconds.
py::list studyCurves(const DiscReference& ref, const std::string& name, const std::vector<double>& values,
                     const disc::DiscModelSpec& modelSpec) {
  const auto parameter = disc::discStudyParameterFromName(name);
  if (!parameter || *parameter == disc::DiscStudyParameter::Speed)
    throw InputError("parameter", "'" + name + "': must be preload, mu, contact_stiffness, force, clearance, "
                                  "harmonics, loss_factor or modes (the speed is followed: follow_peak)");
  py::list curves;
  const auto visit = [&curves](const disc::DiscStudyCurve& c, const response::ForcedResponseSetup& setup) {
    py::gil_scoped_acquire acquire;
    py::dict d;
    d["value"] = c.value;
    d["is_reference"] = c.isReference;
    d["curve"] = curveArrays(*setup.system, setup.outputDofs, c.curve);
    d["harmonics"] = setup.system->aft().harmonics().harmonics();
    d["num_dofs"] = setup.system->numDofs();
    d["output_dofs"] = setup.outputDofs;
    d["warnings"] = c.warnings;
    d["seconds"] = c.seconds;
    curves.append(d);
  };
  try {
    disc::checkDiscStudyValues(*ref.mesh, modelSpec.sectors, modelSpec.axis, ref.spec, *parameter, values,
                               modelSpec.modes, highestHarmonic(ref), modelSpec.material.E);
    py::gil_scoped_release release;
    disc::studyDisc(*ref.mesh, *ref.models, ref.spec, ref.solved, *parameter, values, ref.sweep, visit);
  } catch (const InputError& e) {
    // The library names the scene's key (disc_response/studies/<name>); here the argument.
    throw InputError("values", e.problem());
  }
  return curves;
}

}  // namespace

void bindDiscStudies(py::module_& m) {
  m.def("disc_study", &studyCurves, py::arg("reference"), py::arg("parameter"), py::arg("values"),
        py::arg("model_spec"));
}

}  // namespace cyclone::python
