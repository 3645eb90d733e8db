#pragma once
// A peak followed over a parameter (continuation::FollowedPeakCurve) as the dict of numpy
// arrays python/cyclone/peaks.py's FollowedPeaks is made from: a matrix system's and the
// disc's alike.
#include <pybind11/pybind11.h>

#include "cyclone/continuation/PeakFollowing.hpp"

namespace cyclone::python {

/// Per peak the parameter, frequency (rad/s), measure (max |x(t)| of the first output DOF),
/// jump and coefficients; the optimum, the typed end and its sentence, the work done.
pybind11::dict followedPeakArrays(const continuation::FollowedPeakCurve& curve);

}  // namespace cyclone::python
