#pragma once
// A trace's settings as the Python layer gives them (python/cyclone/response.py checks
// them and names the argument) and the library's setup they make (TraceSetup.cpp): the
// forced response's trace and the peak following share them.
#include <optional>
#include <string>
#include <vector>

#include "cyclone/disc/DiscForcedResponse.hpp"
#include "cyclone/hbm/HarmonicBalanceSystem.hpp"
#include "cyclone/response/ForcedResponseSetup.hpp"

namespace cyclone::python {

struct TraceOptions {
  std::string parameter = "omega";  // omega | force_scale | damping_scale | <element name>/<its parameter>
  std::vector<std::string> elementNames;  // the system's elements', in order
  double start = 0, end = 1;
  double omega = 0;       // the fixed frequency of a force-scale curve
  double forceScale = 1;  // the excitation's scale of a frequency curve
  std::vector<int> outputDofs{0};
  std::string stability = "auto";  // auto | always | never
  int harmonicsCheckTo = 0;        // 0: H + 1; < 0: none
  std::string engine;              // "" (the predictor-corrector, LOCA where it stops short) | predictor_corrector | loca
  std::optional<double> tolerance, initialStep, minStep, maxStep, turnAngle;
  std::optional<int> maxPoints;
};

/// The setup a scene with these keys would give (ForcedResponseScene.cpp: readContinuation),
/// on a copy of `system`. InputError naming parameter or engine for a name not known.
response::ForcedResponseSetup setupOf(const hbm::HarmonicBalanceSystem& system, const TraceOptions& options);

/// A disc sweep's continuation as a scene's disc_response/continuation gives it
/// (DiscSweepReaders.cpp): an engine named is used alone (the disc's options for it), else
/// the predictor-corrector with LOCA retracing; the tolerance and steps on the first engine.
void applyDiscContinuation(const TraceOptions& options, disc::DiscSweepOptions& sweep);

}  // namespace cyclone::python
