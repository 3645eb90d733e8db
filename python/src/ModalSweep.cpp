// The cyclic modes of a sector over speeds (cyclic::solveModalSweep), as a modal scene
// runs them (drivers/src/ModalStage.cpp: the paired faces, the prestress per speed, the
// modes per nodal diameter): the frequencies per speed and nodal diameter, on request
// the mode shapes, and over two or more speeds the Campbell diagram's branches (each
// nodal diameter's families tracked by MAC) and their engine-order resonances, as the
// scene's campbell.csv and resonances.csv (post::trackFamilies, post::findResonances).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <complex>

#include <map>
#include <string>
#include <vector>

#include "Bindings.hpp"
#include "Names.hpp"
#include "ProgramEnvironment.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/cyclic/CyclicSector.hpp"
#include "cyclone/cyclic/ModalSweep.hpp"
#include "cyclone/post/CampbellDiagram.hpp"
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
  bool shapes = false;  // the mode shapes as arrays (modes x nodes x 3, complex) as well
  std::vector<int> engineOrders;  // the resonances' (empty: 1..N, as the scenes' diagrams)
};

// One nodal diameter's shapes: modes x nodes x 3, the real part copy a's, the imaginary
// part copy b's (zero for a diameter with one copy).
py::array_t<std::complex<double>> shapesOf(const cyclic::ModeShapes& shapes) {
  const auto modes = py::ssize_t(shapes.size()), nodes = py::ssize_t(shapes.numNodes());
  py::array_t<std::complex<double>> out({modes, nodes, py::ssize_t(3)});
  auto a = out.mutable_unchecked<3>();
  for (py::ssize_t m = 0; m < modes; ++m) {
    const auto shape = shapes[std::size_t(m)];
    for (py::ssize_t n = 0; n < nodes; ++n)
      for (int c = 0; c < 3; ++c) a(m, n, c) = {shape.real[std::size_t(n)][c], shape.imag[std::size_t(n)][c]};
  }
  return out;
}

// The Campbell diagram's branches and the engine orders' crossings with them, as arrays.
py::tuple campbellOf(const std::vector<post::Branch>& tracked, const std::vector<post::Resonance>& crossings) {
  py::list branches, resonances;
  for (const auto& b : tracked)
    branches.append(py::dict(py::arg("nd") = b.nd, py::arg("family") = b.family, py::arg("rpm") = py::array(py::cast(b.rpm)),
                             py::arg("hz") = py::array(py::cast(b.freqHz)), py::arg("worst_mac") = b.worstMac));
  for (const auto& r : crossings)
    resonances.append(py::dict(py::arg("eo") = r.engineOrder, py::arg("nd") = r.nd, py::arg("family") = r.family,
                               py::arg("rpm") = r.rpm, py::arg("hz") = r.freqHz));
  return py::make_tuple(branches, resonances);
}

// Per speed {rpm, {nodal diameter: frequencies in Hz, ascending, each member of a pair}}
// (and {nodal diameter: shapes} when asked), the Campbell branches and resonances, and the
// seconds the library's calls took.
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
  std::vector<post::Branch> tracked;
  std::vector<post::Resonance> crossings;
  // The calls as C++ makes them, the Campbell tracking with them as the modal scene's: what
  // the Python layer adds is the rest.
  Timer library;
  {
    py::gil_scoped_release release;
    const auto sector = cyclic::makeCyclicSector(mesh, s.sectors, axis, s.leftSets, s.rightSets);
    speeds = cyclic::solveModalSweep(mesh, sector, sweep, comm);
    if (speeds.size() > 1) {  // a Campbell diagram needs a range of speeds
      std::vector<int> orders = s.engineOrders;
      if (orders.empty())
        for (int eo = 1; eo <= s.sectors; ++eo) orders.push_back(eo);
      tracked = post::trackFamilies(speeds);
      crossings = post::findResonances(tracked, s.sectors, orders);
    }
  }
  const double librarySeconds = library.seconds();
  py::list out;
  for (const auto& speed : speeds) {
    std::map<int, std::vector<double>> byDiameter;
    py::dict shapes;
    for (const auto& k : speed.nodalDiameters) {
      byDiameter[k.nodalDiameter] = k.frequenciesHz;
      if (s.shapes) shapes[py::int_(k.nodalDiameter)] = shapesOf(k.shapes);
    }
    out.append(py::make_tuple(speed.rpm, byDiameter, shapes));
  }
  return py::make_tuple(out, campbellOf(tracked, crossings), librarySeconds);
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
      .def_readwrite("threads", &SweepSpec::threads)
      .def_readwrite("shapes", &SweepSpec::shapes)
      .def_readwrite("engine_orders", &SweepSpec::engineOrders);
  m.def("modal_sweep", &modalSweep, py::arg("mesh"), py::arg("spec"));
}

}  // namespace cyclone::python
