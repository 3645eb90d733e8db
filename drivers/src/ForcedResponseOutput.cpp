#include "SceneStages.hpp"

#include <Teuchos_Comm.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/NumberText.hpp"
#include "cyclone/post/ForcedResponseFiles.hpp"
#include "cyclone/response/StiffContacts.hpp"

namespace cyclone::scenes {

namespace {

// The summary's line for a curve: points, stability, time, how the trace ended, flags.
std::string curveLine(const std::string& name, const response::ForcedResponseResult& result) {
  std::ostringstream line;
  line << name << ": " << result.branch.points.size() << " points (";
  if (result.stabilityComputed) {
    line << result.unstablePoints() << " unstable by Hill's method";
    if (result.stabilityRechecked)
      line << ", " << result.undeterminedPoints() << " undetermined (verdict changes with 2x samples)";
  } else {
    // Why, where the library said (stabilityNote starts "stability not computed: ...").
    line << (result.stabilityNote.rfind("stability not computed", 0) == 0 ? result.stabilityNote
                                                                           : std::string("stability not computed"));
  }
  line << ") in " << result.seconds << " s, " << result.branch.stopReason;
  for (const auto& [kind, count] : result.flagCounts()) line << "; " << count << " " << kind;
  return line.str();
}

// Why a curve may have found no start, said before the engines' long account of it: a
// friction contact far stiffer than the system along its coordinate (kt = 1e12 against
// tmdsimpy's 2-DOF system's 12 failed with a 3000-character "no start" that named no
// key). Above 1e4 times, as the disc's contacts are named.
std::string stiffContactsText(const response::ForcedResponseSetup& setup) {
  std::ostringstream text;
  for (const auto& s : response::stiffContacts(setup, 1e4)) {
    const auto i = std::size_t(s.element);
    text << "; nonlinear_elements/" << (i < setup.elementNames.size() ? setup.elementNames[i] : std::to_string(i))
         << "/" << s.parameter << " ("
         << numberText(s.stiffness) << ") is " << numberText(s.ratio(), 3)
         << " times the system's stiffness along the contact's "
         << (s.parameter == "kn" ? "normal" : "tangential") << " coordinate (" << numberText(s.systemStiffness, 4)
         << "): rigid in effect, "
         << (s.parameter == "kt" ? "the contact sticks and slips within a sliver of a period, which the samples "
                                   "cannot place: lower it"
                                 : "it only makes the balance stiff: lower it");
  }
  // A cubic spring stiffer at the linear response than the system by far (k3 = 1e300):
  // its response lies at a scale the start, made on the linear response, does not reach.
  const double omega = setup.parameter == response::ForcedResponseSetup::Parameter::Omega
                           ? setup.continuation.from * setup.omegaUnit
                           : setup.omega;
  for (const auto& s : response::stiffCubicSprings(setup, omega, 1e6)) {
    const auto i = std::size_t(s.element);
    text << "; nonlinear_elements/" << (i < setup.elementNames.size() ? setup.elementNames[i] : std::to_string(i))
         << "/k3 (" << numberText(s.value) << ") is a stiffness 3 k3 x^2 of " << numberText(s.stiffness, 3)
         << " at the linear response's amplitude along its direction (" << numberText(s.amplitude, 4) << "), "
         << numberText(s.ratio(), 3) << " times the system's there (" << numberText(s.systemStiffness, 4)
         << "): the response lies at a scale the start does not reach; check k3's value and units";
  }
  return text.str();
}

}  // namespace

void writeForcedResponse(const response::ForcedResponseSetup& setup, const response::ForcedResponseResult& result,
                         const std::string& outDir, const std::string& name, linalg::CommPtr comm,
                         SceneSummary& summary) {
  const std::string harmonicsCsv = outDir + "/" + name + "_harmonics.csv";
  if (comm->getRank() == 0) {
    post::writeForcedResponseFiles(setup, result, outDir, name);
    if (!result.harmonicsCheck.levels.empty()) post::writeHarmonicsLevelsCsv(result.harmonicsCheck, harmonicsCsv);
  }
  for (const char* ext : {".h5", ".csv", ".svg"}) summary.written.push_back(outDir + "/" + name + ext);
  if (!result.harmonicsCheck.levels.empty()) summary.written.push_back(harmonicsCsv);
  if (!result.branch.finished && !result.branch.points.empty()) {
    // A curve that stops short of its range is the scene's answer missing in part: said
    // as a warning with how much of the range it covers (a force scale over 1e-3..1e6
    // gave 2 points, its checks "by 0", exit 0 without one: issue 49's fourth probe).
    double lo = HUGE_VAL, hi = -HUGE_VAL;
    for (const auto& p : result.branch.points) lo = std::min(lo, p.parameter), hi = std::max(hi, p.parameter);
    std::ostringstream msg;
    msg << name << ": the curve is incomplete: " << result.branch.points.size() << " points over " << lo << ".." << hi
        << " of the range " << setup.continuation.from << ".." << setup.continuation.to
        << " (in the continuation's parameter); its checks and peak cover only those";
    log::warn(msg.str());
    summary.computed.push_back("warning: " + msg.str());
  }
  summary.computed.push_back(curveLine(name, result));
  if (const auto flags = result.flagCounts(); flags.count("turn")) {
    std::ostringstream msg;
    msg << name << ": the path turns at " << flags.at("turn") << " point(s) where Hill's method finds the same "
        << "stability on both sides: no fold; the continuation jumped or stalled there, and what follows may be "
           "another branch";
    log::warn(msg.str());
    summary.computed.push_back("warning: " + msg.str());
  }
  if (!result.samplesCheck.text.empty()) summary.computed.push_back(result.samplesCheck.text);
  if (!result.harmonicsCheck.text.empty()) summary.computed.push_back(result.harmonicsCheck.text);
  for (const auto& other : result.otherPeakChecks)
    summary.computed.push_back("another peak of the curve, " + other.text);
  if (!result.harmonicsTarget.text.empty()) summary.computed.push_back(result.harmonicsTarget.text);
}

response::ForcedResponseResult traceAndWriteForcedResponse(response::ForcedResponseSetup& setup,
                                                           const std::string& outDir, const std::string& name,
                                                           linalg::CommPtr comm, SceneSummary& summary) {
  auto result = response::solveForcedResponse(setup);
  if (result.branch.points.empty())
    throw SolverError(name + ": no point of the curve was computed, so nothing was written" +
                      stiffContactsText(setup) + ": " + result.branch.stopReason);
  writeForcedResponse(setup, result, outDir, name, comm, summary);
  return result;
}

void forcedResponseStage(SceneSection& scene, const std::string& outDir,
                         const std::shared_ptr<continuation::TraceCheckpoints>& checkpoints, linalg::CommPtr comm,
                         SceneSummary& summary) {
  auto setup = readForcedResponseSetup(scene);
  setup.continuation.checkpoints = checkpoints;
  if (setup.fallback) setup.fallback->checkpoints = checkpoints;
  for (const auto& note : setup.notes) {
    log::info(note);
    summary.computed.push_back(note);
  }
  traceAndWriteForcedResponse(setup, outDir, "frc", comm, summary);
}

}  // namespace cyclone::scenes
