// cyclone._core: the compiled half of the Python package `cyclone`, not meant for direct
// use (python/cyclone/__init__.py is the API).
#include "Bindings.hpp"

PYBIND11_MODULE(_core, m) {
  m.doc() = "Cyclone's compiled core; use the package cyclone, not this module";
  cyclone::python::bindErrors(m);
  cyclone::python::bindLogToPython(m);
  cyclone::python::bindElements(m);
  cyclone::python::bindMatrixSystem(m);
  cyclone::python::bindForcedResponse(m);
  cyclone::python::bindPeakFollowing(m);
  cyclone::python::bindEnvironment(m);
  cyclone::python::bindModalSweep(m);
  cyclone::python::bindDisc(m);
  cyclone::python::bindDiscPeakFollowing(m);
  cyclone::python::bindDiscPeakStress(m);
  cyclone::python::bindDiscStudies(m);
  cyclone::python::bindStaticSolve(m);
}
