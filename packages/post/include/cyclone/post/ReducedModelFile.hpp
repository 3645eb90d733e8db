#pragma once
// The HDF5 form of a reduced model of one harmonic index (hybrid FRF or modal
// truncation), so a forced-response run can reuse it without the FE model.
// Schema (docs/reduced_models.md):
//   /eigenvalues         [m]        omega_j^2, (rad/s)^2, ascending (pairs listed twice)
//   /shapes              [r x m]    mass-normalised modes at the retained DOFs
//   /static_compliance   [r x r]    G^T (K - sigma M)^-1 G (hybrid models only)
//   /retained_nodes      [r]        node id of each retained DOF (0-based, the mesh's order)
//   /retained_directions [r]        0, 1, 2: x, y, z
//   /retained_copies     [r]        real-form copy (0: real part, 1: imaginary part)
//   attributes on /: format_version (1), harmonic, sectors, copies, static_correction (0/1),
//                    loss_factor, omega0, shift, rpm
#include <string>
#include <vector>

#include "cyclone/rom/HybridFrfModel.hpp"

namespace cyclone::post {

struct ReducedModelRecord {
  int harmonic = 0;     ///< nodal diameter k
  int sectors = 0;      ///< N of the disc
  double rpm = 0;       ///< speed of the prestress the model was built at
  std::vector<int> retainedNodes, retainedDirections, retainedCopies;  ///< one entry per retained DOF
  rom::RetainedModes modes;
  bool staticCorrection = false;
  rom::StaticCompliance staticCompliance;  ///< used when staticCorrection
  double lossFactor = 0;

  /// The model this record describes.
  rom::HybridFrfModel model() const;
};

/// From a model and where it came from (InputError if the DOF labels do not match its size).
ReducedModelRecord makeReducedModelRecord(const rom::HybridFrfModel& model, int harmonic, int sectors, double rpm,
                                          std::vector<int> nodes, std::vector<int> directions,
                                          std::vector<int> copies);

/// Written under a temporary name and renamed when complete; read back bit-identical.
void writeReducedModelHdf5(const std::string& path, const ReducedModelRecord& record);
/// InputError naming the file if it is not such a file or is inconsistent.
ReducedModelRecord readReducedModelHdf5(const std::string& path);

}  // namespace cyclone::post
