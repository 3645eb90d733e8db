// One linear static solve of a mesh, as a static scene (drivers/src/StaticStage.cpp:
// analysis::solveStatic): fixed node sets and the centrifugal load of a speed, the
// displacement and von Mises stress per node. Without the GIL.
#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <string>
#include <vector>

#include "Bindings.hpp"
#include "ProgramEnvironment.hpp"
#include "cyclone/analysis/StaticAnalysis.hpp"

namespace py = pybind11;

namespace cyclone::python {

namespace {

py::dict staticSolve(const mesh::Mesh& mesh, const py::tuple& material, const std::vector<std::string>& fixedNodeSets,
                     double speedRpm) {
  analysis::StaticProblem problem;  // the z axis through the origin, the built-in sector's
  problem.material.name = material[0].cast<std::string>(), problem.material.E = material[1].cast<double>();
  problem.material.nu = material[2].cast<double>(), problem.material.rho = material[3].cast<double>();
  problem.material.validate("material");
  problem.fixedNodeSets = fixedNodeSets;
  problem.speedRpm = speedRpm;
  auto comm = environmentComm();
  analysis::StaticResult r;
  {
    py::gil_scoped_release release;
    r = analysis::solveStatic(mesh, problem, comm);
  }
  Eigen::MatrixXd u(mesh.numNodes(), 3);
  for (Eigen::Index i = 0; i < u.rows(); ++i)
    for (int c = 0; c < 3; ++c) u(i, c) = r.displacement[std::size_t(i)][std::size_t(c)];
  py::dict d;
  d["displacement"] = u;
  d["von_mises"] = py::array(py::cast(r.stress.nodalVonMises));
  d["equations"] = r.equations;
  d["max_displacement"] = r.maxDisplacement;
  d["max_displacement_node"] = r.maxDisplacementNode;
  d["max_von_mises"] = r.maxVonMises;
  d["relative_residual"] = r.solve.relativeResidual;
  return d;
}

}  // namespace

void bindStaticSolve(py::module_& m) {
  m.def("static_solve", &staticSolve, py::arg("mesh"), py::arg("material"), py::arg("fixed_node_sets"),
        py::arg("speed_rpm"));
}

}  // namespace cyclone::python
