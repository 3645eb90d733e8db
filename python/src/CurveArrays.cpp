// A traced curve (response::ForcedResponseResult) as the dict of numpy arrays and values
// python/cyclone/response.py's ForcedResponse is made from: a matrix system's curve and a
// disc's alike.
#include "CurveArrays.hpp"

#include <pybind11/eigen.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <complex>
#include <limits>

#include "cyclone/hbm/PeakMagnitude.hpp"

namespace py = pybind11;

namespace cyclone::python {

namespace {

// Per point: the coefficients (points x unknowns), each DOF's mean and harmonic
// amplitudes, and the output DOFs' max |x(t)|.
py::dict pointArrays(const hbm::HarmonicBalanceSystem& system, const std::vector<int>& outputDofs,
                     const response::ForcedResponseResult& r) {
  const auto& points = r.branch.points;
  const auto& H = system.aft().harmonics();
  const int P = int(points.size()), n = system.numDofs(), nc = system.numCoefficients(), nh = H.size();
  Eigen::MatrixXd X(P, system.numUnknowns());
  py::array_t<double> amplitude({P, n, nh}), maxAbs({P, int(outputDofs.size())});
  py::array_t<std::complex<double>> exponent(P);
  auto a = amplitude.mutable_unchecked<3>();
  auto m = maxAbs.mutable_unchecked<2>();
  auto e = exponent.mutable_unchecked<1>();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int i = 0; i < P; ++i) {
    const Eigen::VectorXd& x = points[std::size_t(i)].x;
    X.row(i) = x.transpose();
    for (int d = 0; d < n; ++d)
      for (int j = 0; j < nh; ++j) {
        const int h = H.harmonics()[std::size_t(j)];
        a(i, d, j) = h == 0 ? std::abs(x(d * nc + H.cosIndex(0))) : system.amplitude(x, d, h);
      }
    for (std::size_t k = 0; k < outputDofs.size(); ++k) {
      const int d = outputDofs[k];
      m(i, k) = hbm::peakMagnitude(H, Eigen::VectorXd(x.segment(d * nc, nc)));
    }
    const auto& lead = r.leadingExponent[std::size_t(i)];
    e(i) = lead ? *lead : std::complex<double>(nan, nan);
  }
  py::dict d;
  d["x"] = X;
  d["amplitude"] = amplitude;
  d["max_abs"] = maxAbs;
  d["leading_exponent"] = exponent;
  return d;
}

}  // namespace

py::dict curveArrays(const hbm::HarmonicBalanceSystem& system, const std::vector<int>& outputDofs,
                     const response::ForcedResponseResult& r) {
  py::dict d = pointArrays(system, outputDofs, r);
  std::vector<double> parameter;
  for (const auto& pt : r.branch.points) parameter.push_back(pt.parameter);
  d["parameter"] = py::array(py::cast(parameter));
  d["omega"] = py::array(py::cast(r.omega));
  d["stable"] = py::array(py::cast(r.stable));
  d["flags"] = r.flags;
  d["segment"] = py::array(py::cast(r.segment));
  d["end"] = continuation::branchEndName(r.branch.end);
  d["stop_reason"] = r.branch.stopReason;
  const auto& retraces = r.branch.retraces;
  d["retraces"] = py::dict(py::arg("engine") = continuation::engineKey(retraces.engine),
                           py::arg("other_engine_tried") = retraces.otherEngineTried,
                           py::arg("samples_factor") = retraces.samplesFactor,
                           py::arg("samples_factors_tried") = py::cast(retraces.samplesFactorsTried));
  d["finished"] = r.branch.finished;
  d["start_method"] = r.startMethod;
  d["stability_computed"] = r.stabilityComputed;
  d["stability_note"] = r.stabilityNote;
  d["peak_index"] = r.peakIndex;
  d["peak"] = r.peak;
  d["peak_parameter"] = r.peakParameter;
  d["peak_omega"] = r.peakOmega;
  d["samples_check"] = r.samplesCheck.text;
  d["harmonics_check"] = r.harmonicsCheck.text;
  const auto& c = r.harmonicsCheck.converged;
  d["harmonics_check_peak"] = c.found ? py::dict(py::arg("max_harmonic") = c.maxHarmonic, py::arg("value") = c.value,
                                                 py::arg("hz") = c.hz, py::arg("change") = c.change)
                                      : py::dict();
  d["seconds"] = r.seconds;
  return d;
}

}  // namespace cyclone::python
