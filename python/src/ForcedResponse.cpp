// The forced response of a matrix system traced as the scenes trace it
// (response::solveForcedResponse on a response::ForcedResponseSetup, as
// drivers/src/ForcedResponseScene.cpp fills it from a scene), returned as arrays. The
// Python layer (python/cyclone/response.py) checks the options and names the argument;
// here they become the setup. The trace runs without the GIL.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <vector>

#include "Bindings.hpp"
#include "CurveArrays.hpp"
#include "Names.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/hbm/HarmonicRefinement.hpp"
#include "cyclone/response/ForcedResponse.hpp"

namespace py = pybind11;

namespace cyclone::python {

namespace {

using response::ForcedResponseSetup;

struct TraceOptions {
  std::string parameter = "omega";  // omega | force_scale | damping_scale | <element name>/<its parameter>
  std::vector<std::string> elementNames;  // the system's elements', in order
  double start = 0, end = 1;
  double omega = 0;       // the fixed frequency of a force-scale curve
  double forceScale = 1;  // the excitation's scale of a frequency curve
  std::vector<int> outputDofs{0};
  std::string stability = "auto";  // auto | always | never
  int harmonicsCheckTo = 0;        // 0: H + 1; < 0: none
  std::string engine;              // "" (the predictor-corrector, LOCA where it stops short) | predictor_corrector | loca
  std::optional<double> tolerance, initialStep, minStep, maxStep, turnAngle;
  std::optional<int> maxPoints;
};

// The setup a scene with these keys would give (ForcedResponseScene.cpp: readContinuation).
ForcedResponseSetup setupOf(const hbm::HarmonicBalanceSystem& system, const TraceOptions& o) {
  ForcedResponseSetup setup;
  setup.system = hbm::withHarmonics(system, system.aft().harmonics(), system.aft().numSamples());
  setup.elementNames = o.elementNames;
  if (o.parameter != "omega") setup.omega = o.omega;
  if (o.parameter == "omega") {
    setup.parameter = ForcedResponseSetup::Parameter::Omega;
  } else if (o.parameter == "force_scale") {
    setup.parameter = ForcedResponseSetup::Parameter::ForceScale;
  } else if (o.parameter == "damping_scale") {
    setup.parameter = ForcedResponseSetup::Parameter::DampingScale;
  } else if (const auto slash = o.parameter.find('/'); slash != std::string::npos) {
    try {  // every element of that name, the law's parameter checked at the range's start
      response::selectElementParameter(setup, o.parameter.substr(0, slash), o.parameter.substr(slash + 1), o.start);
    } catch (const InputError& e) {
      throw InputError("parameter", e.problem());
    }
  } else {
    throw InputError("parameter", "'" + o.parameter + "': must be omega, force_scale, damping_scale or "
                                  "<element name>/<parameter> (e.g. contact/preload)");
  }
  setup.excitationScale = o.forceScale;
  auto& opt = setup.continuation;
  if (o.engine.empty()) {
    setup.fallback = continuation::locaOptions();
  } else if (o.engine == "loca") {
    opt = continuation::locaOptions();
  } else if (o.engine != "predictor_corrector") {
    throw InputError("engine", "'" + o.engine + "': must be predictor_corrector or loca");
  }
  opt.from = o.start, opt.to = o.end;
  opt.tolerance = o.tolerance.value_or(opt.tolerance);
  opt.initialStep = o.initialStep.value_or(opt.initialStep);
  opt.minStep = o.minStep.value_or(opt.minStep);
  opt.maxStep = o.maxStep.value_or(opt.maxStep);
  opt.maxSteps = o.maxPoints.value_or(opt.maxSteps);
  opt.turnAngle = o.turnAngle.value_or(opt.turnAngle);
  setup.outputDofs = o.outputDofs;
  for (int d = 0; d < system.numDofs(); ++d) setup.dofNames.push_back("dof" + std::to_string(d));
  setup.stability = stabilityFromName(o.stability);
  setup.harmonicsCheckTo = o.harmonicsCheckTo;
  return setup;
}

}  // namespace

void bindForcedResponse(py::module_& m) {
  py::class_<TraceOptions>(m, "TraceOptions", "The trace's settings (cyclone.response fills them)")
      .def(py::init<>())
      .def_readwrite("parameter", &TraceOptions::parameter)
      .def_readwrite("element_names", &TraceOptions::elementNames)
      .def_readwrite("start", &TraceOptions::start)
      .def_readwrite("end", &TraceOptions::end)
      .def_readwrite("omega", &TraceOptions::omega)
      .def_readwrite("force_scale", &TraceOptions::forceScale)
      .def_readwrite("output_dofs", &TraceOptions::outputDofs)
      .def_readwrite("stability", &TraceOptions::stability)
      .def_readwrite("harmonics_check_to", &TraceOptions::harmonicsCheckTo)
      .def_readwrite("engine", &TraceOptions::engine)
      .def_readwrite("tolerance", &TraceOptions::tolerance)
      .def_readwrite("initial_step", &TraceOptions::initialStep)
      .def_readwrite("min_step", &TraceOptions::minStep)
      .def_readwrite("max_step", &TraceOptions::maxStep)
      .def_readwrite("turn_angle", &TraceOptions::turnAngle)
      .def_readwrite("max_points", &TraceOptions::maxPoints);
  m.def(
      "forced_response",
      [](const hbm::HarmonicBalanceSystem& system, const TraceOptions& options) {
        ForcedResponseSetup setup = setupOf(system, options);
        response::ForcedResponseResult result;
        {
          py::gil_scoped_release release;
          result = response::solveForcedResponse(setup);
        }
        return curveArrays(*setup.system, setup.outputDofs, result);
      },
      py::arg("system"), py::arg("options"));
  std::vector<std::string> ends;
  using continuation::BranchEnd;
  for (BranchEnd e : {BranchEnd::Running, BranchEnd::RangeEnd, BranchEnd::MetFromTheEnd, BranchEnd::SinglePoint,
                      BranchEnd::ReturnedToStart, BranchEnd::Wall, BranchEnd::PointBudget, BranchEnd::NoStart,
                      BranchEnd::StartFailed, BranchEnd::EngineStopped})
    ends.push_back(continuation::branchEndName(e));
  m.attr("branch_end_names") = ends;
}

}  // namespace cyclone::python
