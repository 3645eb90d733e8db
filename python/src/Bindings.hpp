#pragma once
// The parts of the compiled module cyclone._core, one file each; Module.cpp calls them in
// order. The public API is the pure-Python package over them (python/cyclone/).
#include <pybind11/pybind11.h>

namespace cyclone::python {

/// InputError and SolverError raised as cyclone.InputError (a ValueError carrying the key)
/// and cyclone.SolverError (a RuntimeError).
void bindErrors(pybind11::module_& m);
/// The library's progress lines to Python's logging (logger "cyclone").
void bindLogToPython(pybind11::module_& m);
/// The nonlinear elements' laws (cubic spring, gap, quadratic damper, Jenkins, friction contact).
void bindElements(pybind11::module_& m);
/// A harmonic balance system of matrices and elements, and its residual and Jacobian.
void bindMatrixSystem(pybind11::module_& m);
/// The forced response traced over the frequency or the force scale, as arrays.
void bindForcedResponse(pybind11::module_& m);
/// A matrix system's resonance peak followed over a parameter, as arrays.
void bindPeakFollowing(pybind11::module_& m);
/// MPI and Kokkos ended at the interpreter's exit (ProgramEnvironment.hpp starts them).
void bindEnvironment(pybind11::module_& m);
/// The cyclic modes of a sector over speeds (Campbell data).
void bindModalSweep(pybind11::module_& m);
/// The bladed disc's chain: the sector's mesh, reduced models, friction forced response.
void bindDisc(pybind11::module_& m);
/// The disc's peak followed over a parameter from a response's curve.
void bindDiscPeakFollowing(pybind11::module_& m);
/// The sector's stresses and fatigue margin at the disc's peak.
void bindDiscPeakStress(pybind11::module_& m);
/// The disc's value-list studies: a frequency curve per value of a parameter.
void bindDiscStudies(pybind11::module_& m);
/// One linear static solve of a mesh under its centrifugal load.
void bindStaticSolve(pybind11::module_& m);

}  // namespace cyclone::python
