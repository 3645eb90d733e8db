#pragma once
// The FE half of the chain on a bladed disc: from the mesh of one sector to one
// reduced model per nodal diameter at the retained DOFs (shroud contact nodes
// and the excitation/response nodes), on the prestressed tangent at one speed,
// cantilever configuration (only the disc faces cyclic; the shroud faces free
// for the contact elements). Models are written to HDF5 under a name holding
// the content hash of everything they depend on, and reused when it matches.
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "cyclone/cyclic/CyclicSector.hpp"
#include "cyclone/cyclic/Prestress.hpp"
#include "cyclone/fe/LinearAlgebra.hpp"
#include "cyclone/fe/Material.hpp"
#include "cyclone/rom/ComplianceModel.hpp"
#include "cyclone/rom/RetainedDofs.hpp"

namespace cyclone::disc {

/// The reduced model per nodal diameter: Petrov's hybrid FRF model (modes plus the exact
/// static correction), plain modal truncation, Guyan, Craig-Bampton, or the full FE
/// compliance itself (the reference: a complex solve per frequency).
enum class ReducedModelKind { Hybrid, Truncation, Guyan, CraigBampton, FullFe };
/// hybrid, truncation, guyan, craig_bampton, full_fe: the scene's and the files' names.
std::string reducedModelKindName(ReducedModelKind kind);
/// The kind of a name (InputError naming `key` for another).
ReducedModelKind reducedModelKindFromName(const std::string& name, const std::string& key);

struct DiscModelSpec {
  fe::IsotropicElastic material;
  std::vector<std::string> fixedNodeSets{"bore"};
  int sectors = 0;
  mesh::RotationAxis axis;
  std::vector<std::string> leftSets{"disc_left"}, rightSets{"disc_right"};  ///< cantilever: disc faces only
  std::vector<std::string> retainedNodeSets{"shroud_contact_left", "shroud_contact_right", "mid_blade"};
  /// Retained after the sets' nodes: weighted means of nodes (the contact patches' mean
  /// motions, shroudPatchMeans, in place of the contact sets' nodes).
  std::vector<rom::RetainedMean> retainedMeans;
  double rpm = 0;
  cyclic::PrestressKind prestress = cyclic::PrestressKind::Nonlinear;
  ReducedModelKind kind = ReducedModelKind::Hybrid;
  int modes = 20;                       ///< natural frequencies per nodal diameter (a pair counts once)
  double omega0 = 0;                    ///< expansion frequency of the hybrid model's static compliance (rad/s)
  double lossFactor = 0.006;            ///< structural damping (1 + i eta) K; 2 x the modal damping ratio at resonance
  int checkNodalDiameter = -1;          ///< compare this diameter's model with the full FE model (-1: none)
  int checkFrequencies = 12;            ///< how many frequencies the check spans (first to fifth family)
};

/// The most frequencies the check of a reduced model spans (log-spaced from half the first
/// natural frequency to the fifth's: 200 are steps of about 1.5 %); each one is a complex
/// factorization of the nodal diameter's full FE system.
constexpr int kMaxCheckFrequencies = 200;

/// DiscModelSpec::checkFrequencies against 0..kMaxCheckFrequencies: InputError naming
/// "check_frequencies" (100000 ran the check for hours, issue 49's sixth probe).
void checkModelCheckFrequencies(int frequencies);

/// The centrifugal prestress the spec's models are built on (k = 0 transform of `sector`);
/// none when spec.prestress is None or the speed is 0.
std::optional<cyclic::PrestressState> discPrestress(const mesh::Mesh& mesh, const cyclic::CyclicSector& sector,
                                                   const DiscModelSpec& spec, linalg::CommPtr comm);

/// The reduced model against the full FE compliance at one nodal diameter.
struct ReducedModelCheck {
  int nodalDiameter = -1;
  std::vector<double> hz, reduced, full;  ///< |A| at the first retained DOF of the excitation direction...
  /// ||A_reduced - A_full||_F / ||A_full||_F per frequency, estimated by 8 random probe
  /// columns R: ||(A_reduced - A_full) R||_F / ||A_full R||_F
  std::vector<double> error;
  double seconds = 0;                     ///< the full solves
  /// Read back with a reused model: the check was made when the model was built, at
  /// `checkedAt` (the check file's time, UTC), not in this run.
  bool reused = false;
  std::string checkedAt;
  /// Asked for but not made: its full FE solves did not fit in memory (the reason; the
  /// model is used unchecked, hz empty).
  std::string notMade;
  double maxError() const;
};

/// freq_hz,reduced_abs,full_abs,relative_error (written atomically). With `digest` (the
/// reduced-model cache's .check.csv) a last line "# content_digest,<hex>" of the lines
/// above it, which a reused model's check must match.
void writeReducedModelCheckCsv(const std::string& path, const ReducedModelCheck& check, bool digest = false);

struct DiscReducedModels {
  int sectors = 0;
  double rpm = 0;  ///< the speed the models were built at (their prestress)
  cyclic::CyclicSector sector;
  std::vector<mesh::Index> retainedNodes;  ///< retained DOF 3 i + d is direction d of node retainedNodes[i]
  /// then DOF 3 (retainedNodes.size() + m) + d is direction d of mean m
  std::vector<rom::RetainedMean> retainedMeans;
  std::map<int, std::shared_ptr<const rom::ComplianceModel>> models;  ///< by nodal diameter
  std::map<int, std::vector<double>> naturalHz;  ///< by nodal diameter: the distinct natural frequencies (cantilever)
  std::map<int, std::string> files;              ///< by nodal diameter: the HDF5 file (none for full_fe)
  int reused = 0, built = 0;
  double seconds = 0;
  ReducedModelCheck check;  ///< empty unless spec.checkNodalDiameter was built now or its check was cached
};

/// The nodal diameters harmonics `harmonics` of engine order `engineOrder` live on (h EO mod N folded to 0..N/2).
std::vector<int> nodalDiametersFor(int sectors, int engineOrder, const std::vector<int>& harmonics);
/// The nodal diameters a curve of `harmonics` needs with its harmonics check, which adds
/// the harmonics above the highest up to `harmonicsCheckTo` (at least one: highest + 1).
std::vector<int> nodalDiametersForCheckedCurve(int sectors, int engineOrder, const std::vector<int>& harmonics,
                                               int harmonicsCheckTo);

/// The file the model of nodal diameter `nodalDiameter` is cached in under cacheDirectory
/// (its name carries the digest of the model's inputs).
std::string reducedModelCachePath(const mesh::Mesh& mesh, const DiscModelSpec& spec, int nodalDiameter,
                                  const std::string& cacheDirectory);

/// InputError naming reduced_model/cache where the cache cannot be used as it is: the
/// directory's name taken by a file, or a model's file name by a directory (found only
/// when its model was written, after the models were built). Before any work.
void checkReducedModelCache(const mesh::Mesh& mesh, const DiscModelSpec& spec, const std::vector<int>& nodalDiameters,
                            const std::string& cacheDirectory);

/// Builds (or reads from `cacheDirectory` when its inputs match) the models of the
/// nodal diameters asked for. An empty cacheDirectory writes and reuses nothing.
DiscReducedModels buildDiscReducedModels(const mesh::Mesh& mesh, const DiscModelSpec& spec,
                                         const std::vector<int>& nodalDiameters, const std::string& cacheDirectory,
                                         linalg::CommPtr comm);

}  // namespace cyclone::disc
