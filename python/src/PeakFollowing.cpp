// The resonance peak of a matrix system followed over a parameter (the force scale, the
// damping's scale or an element's parameter) by a peak search per value
// (continuation::followPeak on response::peakFollowingProblem), as disc::followDiscPeak
// follows the disc's: the first value's peak is the largest of a sweep of the band, each
// next one is searched from the one before (a secant predictor), and where the followed
// peak vanishes the band's largest is taken, marked as a jump. The search's steps,
// window and tolerance are the disc's, relative to the band's middle frequency. Without
// the GIL.
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <vector>

#include "Bindings.hpp"
#include "PeakArrays.hpp"
#include "TraceSetup.hpp"
#include "cyclone/continuation/PeakFollowing.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/response/ForcedResponseSetup.hpp"

namespace py = pybind11;

namespace cyclone::python {

namespace {

py::dict followPeak(const hbm::HarmonicBalanceSystem& system, const TraceOptions& options,
                    const std::vector<double>& values, double bandFrom, double bandTo, bool locateOptimum) {
  if (!(bandFrom > 0 && bandTo > bandFrom)) throw InputError("band", "must be (from, to) with 0 < from < to (rad/s)");
  response::ForcedResponseSetup setup = setupOf(system, options);
  const auto problem = response::peakFollowingProblem(setup);
  continuation::PeakFollowingOptions o;
  o.parameters = values;
  const double w0 = std::sqrt(bandFrom * bandTo);
  o.search.step = 5e-4 * w0, o.search.maxStep = 5e-3 * w0, o.search.window = 0.15 * w0;
  o.search.parameterTolerance = 1e-7 * w0, o.search.tolerance = setup.continuation.tolerance;
  o.bandFrom = bandFrom, o.bandTo = bandTo;
  o.sweep = setup.continuation;
  o.locateOptimum = locateOptimum;
  continuation::FollowedPeakCurve curve;
  {
    py::gil_scoped_release release;
    curve = continuation::followPeak(problem, Eigen::VectorXd(), w0, o);
  }
  return followedPeakArrays(curve);
}

}  // namespace

void bindPeakFollowing(py::module_& m) {
  m.def("follow_peak", &followPeak, py::arg("system"), py::arg("options"), py::arg("values"), py::arg("band_from"),
        py::arg("band_to"), py::arg("locate_optimum"));
  std::vector<std::string> ends;
  using continuation::PeakFollowingEnd;
  for (PeakFollowingEnd e : {PeakFollowingEnd::Running, PeakFollowingEnd::RangeEnd, PeakFollowingEnd::NoPeakAtStart,
                             PeakFollowingEnd::PeakVanished, PeakFollowingEnd::ValueNotReached,
                             PeakFollowingEnd::ContinuationStopped})
    ends.push_back(continuation::peakFollowingEndName(e));
  m.attr("peak_following_end_names") = ends;
}

}  // namespace cyclone::python
