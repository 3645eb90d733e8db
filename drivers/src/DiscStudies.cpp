// disc_response/studies: the scene's lists of values onto disc::studyDisc (a frequency
// curve per value), each curve's files as it comes and the study's plot and table
// (post::StudyCurvesFiles); a value that reproduces the reference scene copies disc_frc's.
#include <filesystem>

#include <Teuchos_Comm.hpp>

#include "DiscStages.hpp"
#include "cyclone/core/AtomicFile.hpp"
#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/disc/DiscParameterStudy.hpp"
#include "cyclone/post/StudyCurvesFiles.hpp"
#include "cyclone/scenes/SceneSection.hpp"

namespace cyclone::scenes {

// A study value that reproduces the reference scene: disc_frc's files under the study's name.
void copyReferenceCurve(const std::string& outDir, const std::string& tag, const std::string& what,
                        linalg::CommPtr comm, SceneSummary& summary) {
  if (comm->getRank() == 0)
    for (const std::string ext : {".csv", ".h5", ".svg"}) {
      if (!std::filesystem::exists(outDir + "/disc_frc" + ext)) continue;
      AtomicFile copy(outDir + "/" + tag + ext);
      std::filesystem::copy_file(outDir + "/disc_frc" + ext, copy.tempPath(),
                                 std::filesystem::copy_options::overwrite_existing);
      copy.commit();
    }
  for (const std::string ext : {".h5", ".csv", ".svg"}) summary.written.push_back(outDir + "/" + tag + ext);
  const std::string line = tag + ": " + what + " is the reference scene: disc_frc's curve, not traced again";
  summary.computed.push_back(line);
  log::info(line);
}

namespace {

// One parameter study of disc_response/studies: a curve per value (each written as it
// comes, a reference value's files copied from disc_frc's), study_<name>.svg with every
// curve and study_<name>.csv with their peaks. Returns the curves traced; each curve's
// top (with a peak) in `peaks`.
int studyStage(SceneSection& studies, const char* name, const mesh::Mesh& mesh, const DiscReducedModels& models,
               const DiscPlan& plan, const disc::DiscForcedResponse& solved, const disc::DiscSweepOptions& sweep,
               const std::string& outDir, linalg::CommPtr comm, SceneSummary& summary,
               std::vector<continuation::KnownPeak>& peaks) {
  const auto values = studies.getDoubleList(name, {});
  if (values.empty()) throw InputError(studies.where(name), "needs a list of values");
  const auto& setup = solved.setup;
  post::StudyCurvesFiles files(name, std::string("Study: ") + name + " (engine order " +
                                         std::to_string(plan.spec.engineOrder) + ")",
                               "max |x(t)| of " + setup.dofNames[setup.outputDofs.front()]);
  const auto writeCurve = [&](const disc::DiscStudyCurve& c, const ForcedResponseSetup& traced) {
    const std::string tag = "study_" + std::string(name) + "_" + std::to_string(files.curves());
    if (c.isReference) copyReferenceCurve(outDir, tag, files.label(c.value), comm, summary);
    else writeDiscCurve(solved, traced, c.curve, tag, c.warnings, outDir, comm, summary);
    const auto& r = c.curve;
    if (r.peak > 0) peaks.push_back({c.value, {r.branch.points[r.peakIndex].x, r.peakOmega, r.peak, 0}});
    files.add(c.value, r, c.seconds);
  };
  studies.underKey(name, [&] {
    disc::studyDisc(mesh, models, plan.spec, solved, *disc::discStudyParameterFromName(name), values, sweep,
                    writeCurve);
  });
  const std::string base = outDir + "/study_" + name;
  if (comm->getRank() == 0) files.write(base + ".svg", base + ".csv");
  summary.written.push_back(base + ".svg");
  summary.written.push_back(base + ".csv");
  return files.curves();
}

}  // namespace

ValueStudies valueStudiesStage(SceneSection studies, const mesh::Mesh& mesh, const DiscReducedModels& models,
                               const DiscPlan& plan, const disc::DiscForcedResponse& solved,
                               const disc::DiscSweepOptions& sweep, const std::string& outDir, linalg::CommPtr comm,
                               SceneSummary& summary) {
  ValueStudies done;
  for (const char* name : kStudyNames)
    if (studies.has(name)) {
      std::vector<continuation::KnownPeak> peaks;
      done.curves += studyStage(studies, name, mesh, models, plan, solved, sweep, outDir, comm, summary, peaks);
      if (!peaks.empty()) done.tops[name] = peaks;
    }
  return done;
}

}  // namespace cyclone::scenes
