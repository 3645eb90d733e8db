#include "cyclone/continuation/PeakFollowing.hpp"

#include "GoldenSection.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"

namespace cyclone::continuation {

const char* peakFollowingEndName(PeakFollowingEnd end) {
  switch (end) {
    case PeakFollowingEnd::Running: return "running";
    case PeakFollowingEnd::RangeEnd: return "range_end";
    case PeakFollowingEnd::NoPeakAtStart: return "no_peak_at_start";
    case PeakFollowingEnd::PeakVanished: return "peak_vanished";
    case PeakFollowingEnd::ValueNotReached: return "value_not_reached";
    case PeakFollowingEnd::ContinuationStopped: return "continuation_stopped";
  }
  return "unknown";
}

namespace {

// The frequency response at parameter p (the problem's frequency as the
// continuation parameter).
ContinuationProblem atParameter(const PeakTrackingProblem& P, double p) {
  ContinuationProblem f;
  f.size = P.size;
  f.residual = [P, p](const Eigen::VectorXd& x, double w, Eigen::VectorXd& R) { P.residual(x, w, p, R); };
  f.jacobian = [P, p](const Eigen::VectorXd& x, double w, Eigen::MatrixXd& J) { P.jacobian(x, w, p, J); };
  f.measure = P.measure;
  f.scaleGroups = P.scaleGroups;
  return f;
}

class Follower {
 public:
  Follower(const PeakTrackingProblem& P, const PeakFollowingOptions& o, FollowedPeakCurve& out)
      : P_(P), o_(o), out_(out) {}

  // The largest local maximum of the band's sweep at p (none: false).
  bool largestInBand(double p, FollowedPeak& peak) {
    ++out_.sweeps;
    ContinuationOptions s = o_.sweep;
    s.from = o_.bandFrom, s.to = o_.bandTo;
    const auto f = atParameter(P_, p);
    const auto branch = traceBranch(f, Eigen::VectorXd::Zero(P_.size), s);
    const auto peaks = prominentPeaks(branch, P_.measure, 0.0);  // every local maximum, largest first
    if (peaks.empty()) return false;
    peak = {p, peaks.front().frequency, peaks.front().measure, peaks.front().x, false};
    // The sweep's points are the path's; its maximum is located on it (the
    // measure was the problem's), and the search narrows it to the search's
    // tolerance.
    return searchFrom(p, peak.x, peak.frequency, peak);
  }

  // The local maximum near (x, w) at p.
  bool searchFrom(double p, const Eigen::VectorXd& x, double w, FollowedPeak& peak) {
    ++out_.searches;
    PeakSearchOptions s = o_.search;
    const auto r = findLocalPeak(atParameter(P_, p), x, w, P_.measure, s);
    out_.solves += r.solves;
    if (!r.found) return false;
    peak = {p, r.parameter, r.value, r.x, false};
    return true;
  }

  void run(const Eigen::VectorXd& x0, double w0);

  // The known peaks at p (options.knownPeaks) searched from; where one is larger than
  // `peak` by more than the search's tolerance, it replaces it, marked as a jump.
  void takeKnownPeaks(double p, FollowedPeak& peak) {
    for (const auto& known : o_.knownPeaks) {
      if (std::abs(known.parameter - p) > 1e-12 * std::max(std::abs(p), 1e-300)) continue;
      FollowedPeak other;
      if (!searchFrom(p, known.peak.x, known.peak.frequency, other)) continue;
      if (other.measure <= peak.measure * (1 + 1e-6)) continue;
      std::ostringstream msg;
      msg << "peak following: at p = " << p << " a known peak at frequency " << other.frequency << " (" << other.measure
          << ") is above the followed one at " << peak.frequency << " (" << peak.measure << "); followed from it";
      log::info(msg.str());
      other.jump = true;
      peak = std::move(other);
    }
  }

 private:
  void locateOptimum();

  const PeakTrackingProblem& P_;
  const PeakFollowingOptions& o_;
  FollowedPeakCurve& out_;
};

void Follower::run(const Eigen::VectorXd& x0, double w0) {
  FollowedPeak first;
  const double p0 = o_.parameters.front();
  const bool started = x0.size() > 0 ? searchFrom(p0, x0, w0, first) : largestInBand(p0, first);
  if (!started) {
    out_.end = PeakFollowingEnd::NoPeakAtStart;
    out_.stopReason = "no peak at the start of the range (p = " + std::to_string(p0) + ")";
    return;
  }
  out_.points.push_back(first);
  for (std::size_t i = 1; i < o_.parameters.size(); ++i) {
    const double p = o_.parameters[i];
    const auto& a = out_.points.back();
    // The secant predictor from the last two peaks (in the parameter's
    // spacing).
    Eigen::VectorXd x = a.x;
    double w = a.frequency;
    if (out_.points.size() >= 2 && !a.jump) {
      const auto& b = out_.points[out_.points.size() - 2];
      const double s = (p - a.parameter) / (a.parameter - b.parameter);
      x += s * (a.x - b.x), w += s * (a.frequency - b.frequency);
    }
    FollowedPeak next;
    if (!searchFrom(p, x, w, next) && !searchFrom(p, a.x, a.frequency, next)) {
      // The followed maximum vanished: the band's largest, marked.
      if (!largestInBand(p, next)) {
        out_.end = PeakFollowingEnd::PeakVanished;
        out_.stopReason = "the followed peak vanished at p = " + std::to_string(p) + " and the band's sweep found none";
        return;
      }
      next.jump = true;
      std::ostringstream msg;
      msg << "peak following: the peak at frequency " << a.frequency << " (the problem's unit) vanished between p = "
          << a.parameter << " and " << p << "; the band's largest is at " << next.frequency;
      log::info(msg.str());
    }
    takeKnownPeaks(p, next);
    out_.points.push_back(std::move(next));
  }
  out_.complete = true;
  out_.end = PeakFollowingEnd::RangeEnd;
  out_.stopReason = "end of the parameter range reached";
  if (o_.locateOptimum) locateOptimum();
}

// Golden section on the peak's measure in p between the grid neighbours of the
// smallest peak (each trial a peak search from the nearer neighbour), when both
// neighbours exist and neither side is a jump.
void Follower::locateOptimum() {
  auto& pts = out_.points;
  std::size_t k = 0;
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (pts[i].measure < pts[k].measure) k = i;
  out_.optimum = int(k);
  if (k == 0 || k + 1 >= pts.size() || pts[k].jump || pts[k + 1].jump) return;
  // Each trial from the nearest of the three grid points around the smallest.
  auto peakAt = [&](double p, const FollowedPeak&, const FollowedPeak&) {
    std::size_t near = k - 1;
    for (std::size_t j : {k, k + 1})
      if (std::abs(p - pts[j].parameter) < std::abs(p - pts[near].parameter)) near = j;
    FollowedPeak peak;
    return searchFrom(p, pts[near].x, pts[near].frequency, peak) ? std::optional<FollowedPeak>(std::move(peak))
                                                                 : std::nullopt;
  };
  const double tolerance = 1e-6 * std::abs(o_.parameters.back() - o_.parameters.front());
  auto located = detail::goldenSection(
      pts[k - 1], pts[k], pts[k + 1], tolerance, [](const FollowedPeak& p) { return p.parameter; }, peakAt,
      [](const FollowedPeak& a, const FollowedPeak& b) { return a.measure < b.measure; });
  if (!located) return;
  FollowedPeak best = std::move(*located);
  const auto at = pts.begin() + long(best.parameter < pts[k].parameter ? k : k + 1);
  const std::size_t index = std::size_t(at - pts.begin());
  if (best.measure < pts[k].measure) {
    pts.insert(at, std::move(best));
    out_.optimum = int(index);
    out_.optimumLocated = true;
  }
}

}  // namespace

std::vector<double> logarithmicValues(double from, double to, int n) {
  if (n < 2 || !(from > 0 && to > 0) || from == to)
    throw InputError("peak following", "logarithmic values need n >= 2 and two different positive ends");
  std::vector<double> v;
  for (int i = 0; i < n; ++i) v.push_back(i + 1 == n ? to : from * std::pow(to / from, double(i) / (n - 1)));
  return v;
}

FollowedPeakCurve followPeak(const PeakTrackingProblem& problem, const Eigen::VectorXd& x0, double w0,
                             const PeakFollowingOptions& o) {
  const auto& v = o.parameters;
  if (v.size() < 2) throw InputError("peak following", "needs at least 2 parameter values");
  for (std::size_t i = 1; i < v.size(); ++i)
    if (!((v[i] - v[i - 1]) * (v[1] - v[0]) > 0))
      throw InputError("peak following", "the parameter values must be strictly monotone");
  if (x0.size() == 0 && !(o.bandTo > o.bandFrom && o.bandFrom > 0))
    throw InputError("peak following", "a start by sweep needs a frequency band 0 < from < to");
  if (!problem.measure) throw InputError("peak following", "the problem needs its response measure");
  Timer timer;
  FollowedPeakCurve out;
  Follower(problem, o, out).run(x0, w0);
  out.seconds = timer.seconds();
  return out;
}

std::vector<PeakStart> prominentPeaks(const Branch& curve, const std::function<double(const Eigen::VectorXd&)>& measure,
                                      double prominence) {
  const auto& pts = curve.points;
  std::vector<double> m;
  for (const auto& p : pts) m.push_back(measure(p.x));
  std::vector<std::size_t> bounds{0};
  for (std::size_t s : curve.segmentStarts)
    if (s > bounds.back() && s < pts.size()) bounds.push_back(s);
  bounds.push_back(pts.size());
  std::vector<PeakStart> out;
  for (std::size_t b = 0; b + 1 < bounds.size(); ++b) {
    const std::size_t begin = bounds[b], end = bounds[b + 1];
    for (std::size_t i = begin + 1; i + 1 < end; ++i) {
      // Interior points only: at a sweep's end the response may rise beyond it.
      if (m[i] < m[i - 1] || m[i] < m[i + 1]) continue;
      // The lowest point on each side before the path rises above m[i] (or ends).
      double lowLeft = m[i], lowRight = m[i];
      for (std::size_t j = i; j-- > begin && m[j] <= m[i];) lowLeft = std::min(lowLeft, m[j]);
      for (std::size_t j = i + 1; j < end && m[j] <= m[i]; ++j) lowRight = std::min(lowRight, m[j]);
      if (m[i] - std::max(lowLeft, lowRight) < prominence * m[i]) continue;
      out.push_back({pts[i].x, pts[i].parameter, m[i], i});
    }
  }
  std::sort(out.begin(), out.end(), [](const PeakStart& a, const PeakStart& b) { return a.measure > b.measure; });
  return out;
}

FollowedPeakCurve followPeaks(const PeakTrackingProblem& problem, const std::vector<PeakStart>& starts,
                              const PeakFollowingOptions& o) {
  if (starts.empty()) throw InputError("peak following", "needs at least one peak to start from");
  if (starts.size() == 1) return followPeak(problem, starts.front().x, starts.front().frequency, o);
  Timer timer;
  PeakFollowingOptions each = o;
  each.locateOptimum = false;  // the values must line up across the followed peaks
  std::vector<FollowedPeakCurve> curves;
  FollowedPeakCurve out;
  for (const auto& s : starts) {
    curves.push_back(followPeak(problem, s.x, s.frequency, each));
    const auto& c = curves.back();
    out.sweeps += c.sweeps, out.searches += c.searches, out.solves += c.solves;
  }
  int previous = -1;
  for (std::size_t i = 0; i < o.parameters.size(); ++i) {
    int best = -1;
    for (std::size_t k = 0; k < curves.size(); ++k)
      if (i < curves[k].points.size() &&
          (best < 0 || curves[k].points[i].measure > curves[std::size_t(best)].points[i].measure))
        best = int(k);
    if (best < 0) {
      out.end = PeakFollowingEnd::ValueNotReached;
      out.stopReason = "no followed peak reached p = " + std::to_string(o.parameters[i]);
      break;
    }
    FollowedPeak point = curves[std::size_t(best)].points[i];
    if (previous >= 0 && best != previous) point.jump = true;  // another peak overtook
    previous = best;
    out.points.push_back(std::move(point));
  }
  out.complete = out.points.size() == o.parameters.size();
  if (out.complete) out.end = PeakFollowingEnd::RangeEnd, out.stopReason = "end of the parameter range reached";
  for (std::size_t i = 0; i < out.points.size(); ++i)
    if (out.optimum < 0 || out.points[i].measure < out.points[std::size_t(out.optimum)].measure) out.optimum = int(i);
  out.seconds = timer.seconds();
  return out;
}

int FollowedPeakCurve::jumps() const {
  int count = 0;
  for (const auto& p : points) count += p.jump;
  return count;
}

std::size_t FollowedPeakCurve::largestPeak() const {
  std::size_t top = 0;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (points[i].measure > points[top].measure) top = i;
  return top;
}

}  // namespace cyclone::continuation
