// The forced response of a matrix system traced as the scenes trace it
// (response::solveForcedResponse on a response::ForcedResponseSetup, as
// drivers/src/ForcedResponseScene.cpp fills it from a scene), returned as arrays. The
// Python layer (python/cyclone/response.py) checks the options and names the argument;
// here they become the setup (TraceSetup.cpp). The trace runs without the GIL.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "Bindings.hpp"
#include "CurveArrays.hpp"
#include "TraceSetup.hpp"
#include "cyclone/response/ForcedResponse.hpp"

namespace py = pybind11;

namespace cyclone::python {

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
        response::ForcedResponseSetup setup = setupOf(system, options);
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
  using Engine = continuation::ContinuationOptions::Engine;
  m.attr("engine_names") = std::vector<std::string>{continuation::engineKey(Engine::PredictorCorrector),
                                                    continuation::engineKey(Engine::Loca)};
}

}  // namespace cyclone::python
