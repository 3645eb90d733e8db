// Benchmark (a program, not a test; issue 21): the default disc's friction-damped peak
// over the shroud preload by one LOCA continuation of the peak (disc::followDiscPeak,
// Method::Continuation), against the equivalent sweep of frequency curves at the same
// resolution (one curve per continued point over 2 % about its peak, the study's way of
// reading a peak off a curve). The sweep is timed on every k-th point and scaled to all
// of them (printed as an estimate with the measured share); each measured curve's peak is
// compared with the continued one.
//   build/regression/disc_peak_benchmark [from N (50)] [to N (5000)] [H (1)] [mesh size (12)]
//                                        [k: every k-th point traced (4)] [cache dir]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/disc/DiscForcedResponse.hpp"
#include "cyclone/disc/DiscPeakFollowing.hpp"
#include "cyclone/fe/Environment.hpp"
#include "cyclone/mesh/ShroudedSectorGenerator.hpp"
#include "DemoDisc.hpp"

using namespace cyclone;

int main(int argc, char** argv) {
  Environment env(argc, argv);
  const double from = argc > 1 ? std::atof(argv[1]) : 50.0, to = argc > 2 ? std::atof(argv[2]) : 5000.0;
  const int H = argc > 3 ? std::atoi(argv[3]) : 1;
  const double meshSize = argc > 4 ? std::atof(argv[4]) : 12.0;
  const int every = argc > 5 ? std::max(1, std::atoi(argv[5])) : 4;
  const std::string cache = argc > 6 ? argv[6] : "disc_peak_benchmark_models";
  if (!(from > 0 && to > from && from <= 500 && to >= 500)) {
    std::fprintf(stderr, "needs 0 < from <= 500 <= to (the reference preload is 500 N)\n");
    return 2;
  }
  mesh::ShroudedSectorParameters p;
  p.meshSize = meshSize;
  const auto mesh = mesh::generateShroudedSector(p);
  const disc::DiscModelSpec models = demo_disc::demoDiscModels(p);
  const disc::DiscResponseSpec spec = demo_disc::demoDiscResponse(H);
  const auto reduced =
      disc::buildDiscReducedModels(mesh, models, disc::nodalDiametersFor(p.sectors, 3, spec.harmonics), cache, env.comm());
  disc::DiscSweepOptions sweep;
  sweep.stability = response::ForcedResponseSetup::Stability::Never;
  sweep.harmonicsCheckTo = -1;
  Timer timer;
  const auto ref = disc::solveDiscForcedResponse(mesh, reduced, spec, sweep);
  std::printf("reference curve at 500 N (H = %d, mesh size %g): %zu points, peak %.6f mm at %.4f Hz, %.1f s\n", H,
              meshSize, ref.curve.branch.points.size(), ref.curve.peak, ref.curve.peakOmega / (2 * M_PI),
              timer.seconds());

  disc::DiscPeakFollowingSpec f;
  f.parameter = disc::DiscStudyParameter::Preload;
  f.from = from, f.to = to;
  f.method = disc::DiscPeakFollowingSpec::Method::Continuation;
  timer.restart();
  const auto continued = disc::followDiscPeak(mesh, reduced, spec, ref.setup, ref.curve, ref.fromHz, ref.toHz, f);
  const double continuedSeconds = timer.seconds();
  const auto& cc = continued.curve;
  std::printf("continued %g..%g N: %zu points, %s, %.1f s (%d LOCA steps, %d Newton solves)\n", from, to,
              cc.points.size(), cc.complete ? "whole" : ("stopped: " + cc.stopReason).c_str(), continuedSeconds,
              cc.searches, cc.solves);
  if (cc.optimum >= 0) {
    const auto& o = cc.points[std::size_t(cc.optimum)];
    std::printf("  smallest peak %.6f mm at %.2f N (%.3f Hz)%s\n", o.measure, o.parameter, o.frequency / (2 * M_PI),
                cc.optimumLocated ? ", located" : "");
  }

  double sweepSeconds = 0, worst = 0;
  int traced = 0;
  for (std::size_t i = 0; i < cc.points.size(); i += std::size_t(every)) {
    const auto& a = cc.points[i];
    timer.restart();
    const auto curve = demo_disc::curveAboutPeak(mesh, reduced, spec, a.parameter, a.frequency, sweep);
    const double s = timer.seconds();
    sweepSeconds += s, ++traced;
    const double d = a.measure / curve.curve.peak - 1;
    worst = std::max(worst, std::abs(d));
    std::printf("  %9.2f N: continued %.6f mm at %.4f Hz; curve %zu points%s in %.1f s, peak %.6f mm at %.4f Hz "
                "(%+.1e)\n",
                a.parameter, a.measure, a.frequency / (2 * M_PI), curve.curve.branch.points.size(),
                curve.curve.branch.finished ? "" : " (unfinished)", s, curve.curve.peak,
                curve.curve.peakOmega / (2 * M_PI), d);
  }
  std::printf("sweep of frequency curves at the continuation's %zu preloads: %d traced in %.1f s, all %zu estimated "
              "%.0f s (x %.1f the continuation); largest peak difference %.1e\n",
              cc.points.size(), traced, sweepSeconds, cc.points.size(),
              sweepSeconds * double(cc.points.size()) / std::max(traced, 1),
              sweepSeconds * double(cc.points.size()) / std::max(traced, 1) / continuedSeconds, worst);
  return 0;
}
