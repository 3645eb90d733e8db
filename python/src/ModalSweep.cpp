// The cyclic modes of a sector over speeds (cyclic::solveModalSweep), as a modal scene
// runs them (drivers/src/ModalStage.cpp: the paired faces, the prestress per speed, the
// modes per nodal diameter): the frequencies per speed and nodal diameter, a Campbell
// diagram's data. The shapes stay in the library (their files are the scenes').
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <map>
#include <string>
#include <vector>

#include "Bindings.hpp"
#include "Names.hpp"
#include "ProgramEnvironment.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/cyclic/CyclicSector.hpp"
#include "cyclone/cyclic/ModalSweep.hpp"
#include "cyclone/solvers/ModalSolver.hpp"

namespace py = pybind11;

namespace cyclone::python {

namespace {

struct SweepSpec {
  int sectors = 0;
  std::vector<std::string> leftSets, rightSets, fixedNodeSets;
  std::string material = "titanium";
  double E = 1.16e5, nu = 0.34, rho = 4.507e-9;
  std::vector<double> speedsRpm{0.0};
  std::vector<int> nodalDiameters;  // empty: all
  int modesPerNodalDiameter = 6;
  std::string prestress = "linear";
  int threads = 0;  // 0: the cores this process may use, as the scenes
};

// Per speed {rpm, {nodal diameter: frequencies in Hz, ascending, each member of a pair}},
// and the seconds the library's calls took.
py::tuple modalSweep(const mesh::Mesh& mesh, const SweepSpec& s) {
  const mesh::RotationAxis axis;  // z through the origin, as the scenes' default
  cyclic::ModalSweepProblem sweep;
  auto& problem = sweep.modes;
  problem.material.name = s.material, problem.material.E = s.E, problem.material.nu = s.nu;
  problem.material.rho = s.rho;
  problem.material.validate("material");
  problem.fixedNodeSets = s.fixedNodeSets;
  problem.nodalDiameters = s.nodalDiameters;
  problem.modesPerNodalDiameter = s.modesPerNodalDiameter;
  problem.shift = solvers::ModalOptions::automaticShift();
  problem.threads = s.threads;
  sweep.speedsRpm = s.speedsRpm;
  sweep.prestress = prestressFromName(s.prestress);
  sweep.axis = axis;
  auto comm = environmentComm();
  std::vector<cyclic::SpeedModes> speeds;
  Timer library;  // the calls as C++ makes them: what the Python layer adds is the rest
  {
    py::gil_scoped_release release;
    const auto sector = cyclic::makeCyclicSector(mesh, s.sectors, axis, s.leftSets, s.rightSets);
    speeds = cyclic::solveModalSweep(mesh, sector, sweep, comm);
  }
  const double librarySeconds = library.seconds();
  py::list out;
  for (const auto& speed : speeds) {
    std::map<int, std::vector<double>> byDiameter;
    for (const auto& k : speed.nodalDiameters) byDiameter[k.nodalDiameter] = k.frequenciesHz;
    out.append(py::make_tuple(speed.rpm, byDiameter));
  }
  return py::make_tuple(out, librarySeconds);
}

}  // namespace

void bindModalSweep(py::module_& m) {
  py::class_<SweepSpec>(m, "ModalSweepSpec")
      .def(py::init<>())
      .def_readwrite("sectors", &SweepSpec::sectors)
      .def_readwrite("left_sets", &SweepSpec::leftSets)
      .def_readwrite("right_sets", &SweepSpec::rightSets)
      .def_readwrite("fixed_node_sets", &SweepSpec::fixedNodeSets)
      .def_readwrite("material", &SweepSpec::material)
      .def_readwrite("E", &SweepSpec::E)
      .def_readwrite("nu", &SweepSpec::nu)
      .def_readwrite("rho", &SweepSpec::rho)
      .def_readwrite("speeds_rpm", &SweepSpec::speedsRpm)
      .def_readwrite("nodal_diameters", &SweepSpec::nodalDiameters)
      .def_readwrite("modes_per_nd", &SweepSpec::modesPerNodalDiameter)
      .def_readwrite("prestress", &SweepSpec::prestress)
      .def_readwrite("threads", &SweepSpec::threads);
  m.def("modal_sweep", &modalSweep, py::arg("mesh"), py::arg("spec"));
}

}  // namespace cyclone::python
