#pragma once
// A traced curve as arrays for Python (CurveArrays.cpp), and the trace's settings by the
// names the Python layer gives them (ForcedResponse.cpp): shared by the matrix system's
// curves and the disc's.
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "cyclone/hbm/HarmonicBalanceSystem.hpp"
#include "cyclone/response/ForcedResponse.hpp"

namespace cyclone::python {

/// Per point the parameter, frequency, coefficients (points x unknowns), amplitude per
/// DOF and harmonic, the output DOFs' max |x(t)|, stability, flags and segment; the end,
/// its reason, the peak and the checks' lines. `system` is the one the curve was traced on.
pybind11::dict curveArrays(const hbm::HarmonicBalanceSystem& system, const std::vector<int>& outputDofs,
                           const response::ForcedResponseResult& result);

/// "auto", "always", "never" (InputError naming stability otherwise).
response::ForcedResponseSetup::Stability stabilityFromName(const std::string& name);

}  // namespace cyclone::python
