// The disc's resonance peak followed over a contact or excitation parameter, as a disc
// scene's disc_response/peak_studies (drivers/src/DiscPeakStudies.cpp:
// disc::followDiscPeak from the reference curve's prominent peaks, over the band the
// reference curve swept), from the curve a Python disc response keeps (DiscReference.hpp).
// Over the speed the reduced models are built again at each value, as the scene's: the
// followed harmonics' nodal diameters, the same spec and cache. Without the GIL.
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "Bindings.hpp"
#include "DiscReference.hpp"
#include "PeakArrays.hpp"
#include "ProgramEnvironment.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/disc/DiscPeakFollowing.hpp"

namespace py = pybind11;

namespace cyclone::python {

namespace {

struct FollowSpec {
  std::string parameter = "preload";  // preload | mu | contact_stiffness | force | loss_factor | clearance | speed
  double from = 0, to = 0;
  int values = 24;
  std::string method = "peak_search";  // peak_search | continuation
  double phaseStep = 0.1;
  int optimumRaises = 2;
};

disc::DiscPeakFollowingSpec followingOf(const FollowSpec& s) {
  disc::DiscPeakFollowingSpec f;
  const auto parameter = disc::discStudyParameterFromName(s.parameter);
  if (!parameter)
    throw InputError("parameter", "'" + s.parameter + "': must be preload, mu, contact_stiffness, force, loss_factor, "
                                  "clearance or speed");
  if (s.method != "peak_search" && s.method != "continuation")
    throw InputError("method", "'" + s.method + "': must be peak_search (a peak search per value) or continuation "
                               "(one LOCA continuation of the peak)");
  f.parameter = *parameter;
  f.from = s.from, f.to = s.to, f.values = s.values;
  f.method = s.method == "continuation" ? disc::DiscPeakFollowingSpec::Method::Continuation
                                        : disc::DiscPeakFollowingSpec::Method::PeakSearch;
  f.phaseStep = s.phaseStep, f.optimumRaises = s.optimumRaises;
  return f;
}

py::dict followDiscPeak(const DiscReference& ref, const FollowSpec& spec, const disc::DiscModelSpec& modelSpec,
                        const std::string& cacheDirectory) {
  auto following = followingOf(spec);
  auto comm = environmentComm();
  following.modelsAtSpeed = [&ref, modelSpec, cacheDirectory, comm](double rpm) {
    auto ms = modelSpec;
    ms.rpm = rpm;
    ms.checkNodalDiameter = -1;
    const auto nds = disc::nodalDiametersFor(ms.sectors, ref.spec.engineOrder, ref.spec.harmonics);
    return disc::buildDiscReducedModels(*ref.mesh, ms, nds, cacheDirectory, comm);
  };
  disc::DiscPeakFollowing f;
  {
    py::gil_scoped_release release;
    f = disc::followDiscPeak(*ref.mesh, *ref.models, ref.spec, ref.solved.setup, ref.solved.curve, ref.solved.fromHz,
                             ref.solved.toHz, following);
  }
  py::dict d = followedPeakArrays(f.curve);
  d["grid"] = py::array(py::cast(f.grid));
  d["reference_value"] = f.referenceValue;
  d["starting_peaks"] = f.startingPeaks;
  d["warnings"] = f.warnings;
  d["by_force"] = f.byForce;
  d["continued"] = f.continued;
  d["force_beyond"] = py::array(py::cast(f.forceBeyond));
  py::list levels;
  for (const auto& level : f.optimumCheck.levels)
    levels.append(py::dict(py::arg("max_harmonic") = level.maxHarmonic, py::arg("found") = level.peak.found,
                           py::arg("value") = level.peak.value, py::arg("hz") = level.peak.parameter));
  d["optimum_check"] = levels;
  d["optimum_check_change"] = f.optimumCheck.change;
  d["num_dofs"] = f.setup.system->numDofs();
  d["num_coefficients"] = f.setup.system->numCoefficients();
  return d;
}

}  // namespace

void bindDiscPeakFollowing(py::module_& m) {
  py::class_<FollowSpec>(m, "DiscFollowSpec")
      .def(py::init<>())
      .def_readwrite("parameter", &FollowSpec::parameter)
      .def_readwrite("start", &FollowSpec::from)
      .def_readwrite("end", &FollowSpec::to)
      .def_readwrite("values", &FollowSpec::values)
      .def_readwrite("method", &FollowSpec::method)
      .def_readwrite("phase_step", &FollowSpec::phaseStep)
      .def_readwrite("optimum_raises", &FollowSpec::optimumRaises);
  m.def("disc_follow_peak", &followDiscPeak, py::arg("reference"), py::arg("spec"), py::arg("model_spec"),
        py::arg("cache_directory"));
}

}  // namespace cyclone::python
