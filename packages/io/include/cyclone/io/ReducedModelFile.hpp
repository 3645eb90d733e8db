#pragma once
// The HDF5 form of a reduced model of one nodal diameter (hybrid FRF, modal
// truncation, Guyan or Craig-Bampton), so a forced-response run can reuse it
// without the FE model. Schema (docs/reduced_models.md):
//   hybrid, truncation:
//     /eigenvalues         [m]        omega_j^2, (rad/s)^2, ascending (pairs listed twice)
//     /shapes              [r x m]    mass-normalised modes at the retained DOFs
//     /static_compliance   [r x r]    G^T (K - sigma M)^-1 G (hybrid models only)
//     /load_modal_forces   [m x p]    optional, the excitation part: phi_j^T f for p load patterns
//     /load_static_response [r x p]   with it (hybrid): G^T (K - sigma M)^-1 f
//   guyan, craig_bampton:
//     /boundary_stiffness  [r x r]    K_g
//     /boundary_mass       [r x r]    M_g
//     /interface_eigenvalues [m]      lambda_j of the fixed-interface modes kept (Craig-Bampton only)
//     /mass_coupling       [r x m]    M_bm = Psi^T M Phi (Craig-Bampton only)
//     /full_model_eigenvalues [n]     the full model's omega_j^2 computed beside it (optional)
//   every kind:
//     /retained_nodes      [r]        node id of each retained DOF (0-based, the mesh's order)
//     /retained_directions [r]        0, 1, 2: x, y, z (of the node's frame when it has one)
//     /retained_copies     [r]        real-form copy (0: real part, 1: imaginary part)
//     /retained_axes       [r x 3]    optional: each DOF's unit vector (a local frame's); absent: x, y, z
//   attributes on /: format_version (2; 1: no kind, hybrid or truncation), kind (string),
//                    harmonic, sectors, copies, static_correction (0/1), loss_factor, omega0, shift, rpm,
//                    input_digest (string, optional: the digest of the inputs the model was built
//                    from, e.g. the disc chain's cache key),
//                    content_digest (string, written last: contentDigest of what the file holds;
//                    files written before it have none)
#include <memory>
#include <string>
#include <vector>

#include "cyclone/rom/BoundaryReduction.hpp"
#include "cyclone/rom/HybridFrfModel.hpp"

namespace cyclone::rom {
class GuyanModel;
class CraigBamptonModel;
}  // namespace cyclone::rom

namespace cyclone::io {

struct ReducedModelRecord {
  std::string kind = "hybrid";  ///< hybrid | truncation | guyan | craig_bampton
  int nodalDiameter = 0;        ///< k
  int sectors = 0;              ///< N of the disc
  double rpm = 0;               ///< speed of the prestress the model was built at
  std::vector<int> retainedNodes, retainedDirections, retainedCopies;  ///< one entry per retained DOF
  Eigen::MatrixXd retainedAxes;  ///< optional (r x 3): unit vector of each DOF in a local frame; empty: x, y, z
  double lossFactor = 0;
  // hybrid and truncation
  rom::RetainedModes modes;
  bool staticCorrection = false;
  rom::StaticCompliance staticCompliance;  ///< used when staticCorrection
  // guyan and craig_bampton: K_g, M_g (and the interface modes kept, M_bm); copies
  rom::BoundaryReduction reduction;
  std::vector<double> fullModelEigenvalues;  ///< optional: the full model's omega_j^2 (e.g. for a resonance estimate)
  /// Optional: the digest of the inputs the model was built from (the disc chain's cache
  /// key: mesh, material, speed, kind, retained DOFs), so that a valid model of other
  /// inputs filed under this one's name is told apart from it. Empty: none given.
  std::string inputDigest;
  /// Read back: the file carried a content digest and it matched what was read (false: a
  /// file written without one).
  bool contentVerified = false;

  /// The model this record describes, whatever its kind.
  std::shared_ptr<const rom::ComplianceModel> model() const;
  /// The hybrid or truncation model (InputError for another kind).
  rom::HybridFrfModel hybridModel() const;
};

/// From a model and where it came from (InputError if the DOF labels do not match its size).
ReducedModelRecord makeReducedModelRecord(const rom::HybridFrfModel& model, int nodalDiameter, int sectors, double rpm,
                                          std::vector<int> nodes, std::vector<int> directions,
                                          std::vector<int> copies);
ReducedModelRecord makeReducedModelRecord(const rom::GuyanModel& model, int nodalDiameter, int sectors, double rpm,
                                          std::vector<int> nodes, std::vector<int> directions,
                                          std::vector<int> copies);
ReducedModelRecord makeReducedModelRecord(const rom::CraigBamptonModel& model, int nodalDiameter, int sectors, double rpm,
                                          std::vector<int> nodes, std::vector<int> directions,
                                          std::vector<int> copies);

/// A digest of everything the record holds that a file stores (its values, bit for bit,
/// and its labels): a changed value, label or size changes it.
std::string contentDigest(const ReducedModelRecord& record);

/// Written under a temporary name and renamed when complete; read back bit-identical.
void writeReducedModelHdf5(const std::string& path, const ReducedModelRecord& record);
/// InputError naming the file if it is not such a file or is inconsistent, or if its
/// content does not match the digest written with it (a damaged or edited file).
ReducedModelRecord readReducedModelHdf5(const std::string& path);

}  // namespace cyclone::io
