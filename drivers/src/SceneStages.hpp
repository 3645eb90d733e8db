#pragma once
// What the scene runner's stages share (private to the scenes library).
#include <string>

#include "cyclone/continuation/ArclengthContinuation.hpp"
#include "cyclone/fe/LinearAlgebra.hpp"
#include "cyclone/fe/Material.hpp"
#include "cyclone/scenes/ForcedResponseScene.hpp"
#include "cyclone/scenes/SceneRunner.hpp"

namespace cyclone::mesh {
class Mesh;
}

namespace cyclone::scenes {

class SceneSection;

/// The most time samples per period a scene may ask for: every residual's cost grows in
/// proportion (a friction contact's march too), and 2e6 ran for minutes without a point
/// (issue 20). The largest shipped need is 4096 (the samples check of 2048).
constexpr int kMaxSamples = 1 << 16;

/// The peak of a frequency curve at the highest harmonic count the harmonics check
/// reached, with the change from the level below: the run's headline.
struct HarmonicsConvergedPeak {
  bool found = false;
  int maxHarmonic = 0;
  double value = 0, hz = 0;
  int belowHarmonic = -1;  ///< the level compared with (-1: none found)
  double change = -1;      ///< |peak / peak below - 1| (-1: not known)
  int notFoundHarmonic = -1;  ///< the next level, tried and its peak not found (-1: none)
};

struct ForcedResponseResult {
  continuation::Branch branch;
  double peak = 0;           ///< largest max |x(t)| of the first output DOF
  double peakParameter = 0;  ///< the continuation parameter there
  double peakOmega = 0;      ///< the frequency there (rad/s)
  double seconds = 0;
  std::string startMethod, samplesCheck, harmonicsCheck;
  HarmonicsConvergedPeak harmonicsPeak;  ///< filled by the harmonics check of a frequency curve
};

/// Finds the first point, traces the curve and writes <name>.csv, <name>.svg and
/// <name>.h5 (rank 0), with stability (matrix systems), bifurcation flags and the
/// sample-count check; lines for the summary.
ForcedResponseResult traceAndWriteForcedResponse(ForcedResponseSetup& setup, const std::string& outDir,
                                                 const std::string& name, linalg::CommPtr comm, SceneSummary& summary);

fe::IsotropicElastic readMaterial(SceneSection section);

/// `harmonics_check_to` of a forced-response section: the highest harmonic the
/// harmonics check of a frequency curve raises H to (0 when absent: H + 1); given,
/// it must exceed the curve's H.
int readHarmonicsCheckTo(SceneSection& section, int maxHarmonic);

/// report.md in the output directory: the run's summary, its figures (the SVGs the
/// stages wrote), the studies' tables and the stages' error against run time.
void writeRunReport(const std::string& outDir, const std::string& source, const SceneSummary& summary);

/// The disc chain's stages: reduced models per nodal diameter (cached), then the
/// forced response with friction at the shroud and its parameter studies.
void discStages(SceneSection& scene, const mesh::Mesh& mesh, int builtInSectors, bool forcedResponse,
                const std::string& outDir, linalg::CommPtr comm, SceneSummary& summary);

}  // namespace cyclone::scenes
