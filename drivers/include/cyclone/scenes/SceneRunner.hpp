#pragma once
// Runs a scene: reads it strictly, computes only what its analysis needs,
// writes the products into the output directory and returns a summary.
#include <optional>
#include <string>
#include <vector>

#include "cyclone/fe/LinearAlgebra.hpp"

namespace cyclone::scenes {

struct SceneOverrides {
  std::optional<std::string> outputDirectory;
  std::optional<double> meshSize;  ///< built-in sector only
  /// Continue a killed run into the same directory from its saved traces
  /// (<output>/checkpoints, docs/scenes.md); otherwise a run starts without them.
  bool resume = false;
  double checkpointSeconds = 5;  ///< of work between two saves of an unfinished curve
};

/// One stage of a run: how long it took and what its error estimate says.
struct StageRecord {
  std::string stage;
  double seconds = 0;
  std::string errorEstimate;
};

struct SceneSummary {
  std::vector<std::string> computed;  ///< one line per result, for the final summary
  std::vector<std::string> written;   ///< files produced
  std::vector<StageRecord> stages;    ///< for the report's table of error against run time
  /// The peak studies' parameters whose peak was continued by LOCA (the others: a peak
  /// search per value), for the report's words.
  std::vector<std::string> continuedPeakStudies;
};

/// `source` names the scene in messages (a file name or "embedded demo scene").
SceneSummary runSceneText(const std::string& yaml, const std::string& source, const SceneOverrides& overrides,
                          linalg::CommPtr comm);
SceneSummary runSceneFile(const std::string& path, const SceneOverrides& overrides, linalg::CommPtr comm);
/// The embedded default scene (drivers/scenes/demo.yaml).
const char* demoScene();

}  // namespace cyclone::scenes
