// A followed peak's points as arrays (PeakArrays.hpp).
#include "PeakArrays.hpp"

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <vector>

namespace py = pybind11;

namespace cyclone::python {

py::dict followedPeakArrays(const continuation::FollowedPeakCurve& curve) {
  const auto& points = curve.points;
  std::vector<double> parameter, frequency, measure;
  std::vector<bool> jump;
  Eigen::MatrixXd X(Eigen::Index(points.size()), points.empty() ? 0 : points.front().x.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& p = points[i];
    parameter.push_back(p.parameter), frequency.push_back(p.frequency), measure.push_back(p.measure);
    jump.push_back(p.jump);
    X.row(Eigen::Index(i)) = p.x.transpose();
  }
  py::dict d;
  d["parameter"] = py::array(py::cast(parameter));
  d["omega"] = py::array(py::cast(frequency));
  d["peak"] = py::array(py::cast(measure));
  d["jump"] = py::array(py::cast(jump));
  d["x"] = X;
  d["optimum"] = curve.optimum;
  d["optimum_located"] = curve.optimumLocated;
  d["complete"] = curve.complete;
  d["end"] = continuation::peakFollowingEndName(curve.end);
  d["branch_end"] = continuation::branchEndName(curve.branchEnd);
  d["stop_reason"] = curve.stopReason;
  d["sweeps"] = curve.sweeps, d["searches"] = curve.searches, d["solves"] = curve.solves;
  d["seconds"] = curve.seconds;
  return d;
}

}  // namespace cyclone::python
