// The whole sector's vibration at the disc's friction-damped peak and its fatigue margin,
// as a disc scene's disc_response/peak_stress (drivers/src/DiscPeakStress.cpp): the
// reference curve's peak point (the harmonics check's highest level found, else the
// traced point nearest the peak; or the curve at a chosen frequency), a full FE solve per
// harmonic under the loads the harmonic balance solution puts on the retained DOFs
// (disc::solveDiscPeakVibration), and per node the stress cycle's measures and the
// Goodman-Haigh safety factor. Per node in the mesh's order (disc_peak_stress.csv lists
// them worst first). Without the GIL.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "Bindings.hpp"
#include "DiscReference.hpp"
#include "ProgramEnvironment.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/disc/DiscPeakVibration.hpp"
#include "cyclone/fatigue/GoodmanHaigh.hpp"

namespace py = pybind11;

namespace cyclone::python {

namespace {

// Ti-6Al-4V's data sheet values (MPa: the library's mm-N-s-t) or the strengths given,
// checked as a scene's material/fatigue.
fatigue::FatigueMaterial materialOf(const py::dict& f) {
  fatigue::FatigueMaterial m;
  const std::string data = f.contains("data") ? f["data"].cast<std::string>() : "";
  if (!data.empty()) {
    if (data != "Ti-6Al-4V") throw InputError("fatigue", "'" + data + "' is not known (Ti-6Al-4V is; or give the strengths)");
    m = fatigue::ti6al4vAnnealed(1.0);
  } else {
    m.name = f.contains("name") ? f["name"].cast<std::string>() : "material";
    m.source = "given from Python";
  }
  auto number = [&f](const char* key, double& value) {
    if (f.contains(key)) value = f[key].cast<double>();
  };
  number("ultimate_strength", m.ultimateStrength);
  number("endurance_limit", m.enduranceLimit);
  number("yield_strength", m.yieldStrength);
  number("design_cycles", m.designCycles);
  m.validate("fatigue");
  return m;
}

py::dict peakStress(DiscReference& ref, const disc::DiscModelSpec& modelSpec, const py::object& fatigueData, double atHz) {
  std::optional<fatigue::FatigueMaterial> material;
  if (!fatigueData.is_none()) material = materialOf(fatigueData.cast<py::dict>());
  auto comm = environmentComm();
  disc::DiscPeakVibration peak;
  std::string what, caveat;
  double hz = 0;
  {
    py::gil_scoped_release release;
    auto& setup = ref.solved.setup;
    const disc::PeakPoint point = atHz > 0 ? disc::referencePointAt(setup, ref.solved.curve, atHz)
                                           : disc::referencePeakPoint(setup, ref.solved.curve);
    peak = disc::solveDiscPeakVibration(*ref.mesh, *ref.models, modelSpec, point, setup.excitationScale,
                                        material ? &*material : nullptr, comm);
    what = point.what, caveat = point.caveat, hz = point.omega / (2 * M_PI);
  }
  py::dict d;
  d["what"] = what, d["caveat"] = caveat, d["hz"] = hz;
  d["model_error"] = peak.modelError;
  d["harmonics"] = peak.vibration.harmonics;
  d["nodal_diameters"] = peak.vibration.nodalDiameters;
  d["node_ids"] = py::array(py::cast(std::vector<long long>(ref.mesh->nodeIds.begin(), ref.mesh->nodeIds.end())));
  Eigen::MatrixXd coordinates(ref.mesh->numNodes(), 3);
  for (Eigen::Index i = 0; i < coordinates.rows(); ++i)
    for (int c = 0; c < 3; ++c) coordinates(i, c) = ref.mesh->coords[std::size_t(i)][c];
  d["coordinates"] = coordinates;
  if (!peak.fatigue) return d;
  const auto& map = *peak.fatigue;
  const std::size_t n = map.cycle.size();
  Eigen::VectorXd mean(n), alternating(n), principal(n), largest(n);
  for (std::size_t i = 0; i < n; ++i) {
    const auto& c = map.cycle[i];
    mean(Eigen::Index(i)) = c.meanVonMises, alternating(Eigen::Index(i)) = c.alternatingVonMises;
    principal(Eigen::Index(i)) = c.alternatingPrincipal, largest(Eigen::Index(i)) = c.maxVonMises;
  }
  d["mean_von_mises"] = mean;
  d["alternating_von_mises"] = alternating;
  d["alternating_principal"] = principal;
  d["max_von_mises"] = largest;
  d["safety_factor"] = py::array(py::cast(map.safetyFactor));
  d["critical"] = map.critical;
  const auto& m = *material;
  d["material"] = py::dict(py::arg("name") = m.name, py::arg("ultimate_strength") = m.ultimateStrength,
                           py::arg("endurance_limit") = m.enduranceLimit, py::arg("yield_strength") = m.yieldStrength,
                           py::arg("design_cycles") = m.designCycles, py::arg("source") = m.source);
  return d;
}

}  // namespace

void bindDiscPeakStress(py::module_& m) {
  m.def("disc_peak_stress", &peakStress, py::arg("reference"), py::arg("model_spec"), py::arg("fatigue"),
        py::arg("at_hz"));
}

}  // namespace cyclone::python
