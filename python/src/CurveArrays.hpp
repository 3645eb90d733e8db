#pragma once
// A traced curve as arrays for Python (CurveArrays.cpp): the matrix system's curves and
// the disc's alike.
#include <pybind11/pybind11.h>

#include <vector>

#include "cyclone/hbm/HarmonicBalanceSystem.hpp"
#include "cyclone/response/ForcedResponse.hpp"

namespace cyclone::python {

/// Per point the parameter, frequency, coefficients (points x unknowns), amplitude per
/// DOF and harmonic, the output DOFs' max |x(t)|, stability, flags and segment; the end,
/// its reason, the peak and the checks' lines. `system` is the one the curve was traced on.
pybind11::dict curveArrays(const hbm::HarmonicBalanceSystem& system, const std::vector<int>& outputDofs,
                           const response::ForcedResponseResult& result);

}  // namespace cyclone::python
