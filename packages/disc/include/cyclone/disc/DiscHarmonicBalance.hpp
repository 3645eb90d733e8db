#pragma once
// The nonlinear half of the chain on a bladed disc: the harmonic balance system
// of one sector given by its reduced models (receptance form), with 3D friction
// contacts between each right-face shroud contact node and its partner on the
// neighbouring sector's left face (the engine-order cyclic constraint carries
// the neighbour), a force at a blade node travelling with engine order EO.
#include <string>
#include <utility>
#include <vector>

#include <Eigen/Dense>

#include "cyclone/disc/DiscReducedModels.hpp"
#include "cyclone/mesh/RotatedNodePairing.hpp"
#include "cyclone/response/ForcedResponseSetup.hpp"

namespace cyclone::disc {

/// The shroud contacts' friction law. The defaults are Scalvini 2021's (Table 8.4: kn = kt =
/// 1e4 N/mm per contact element of 2.4 mm^2, mu = 0.4) per unit area.
struct ShroudContactSpec {
  /// How kn, kt and preload are given. PerPair: each node pair's (N/mm, N), so the
  /// interface's total stiffness and load grow with the number of pairs a mesh has.
  /// PerArea: kn and kt per unit area of the interface (N/mm^3) and preload the
  /// interface's total normal load (N), spread over the pairs by each right-face node's
  /// tributary area (mesh::tributaryAreas, shroudContactValues): the same interface at any
  /// mesh, so the default; PerPair only where a caller names it.
  enum class Law { PerPair, PerArea };
  Law law = Law::PerArea;
  /// The faces' contact nodes, in any order: each right node is paired with the left
  /// node whose image under the sector rotation it is (shroudContactPairs).
  std::string leftSet = "shroud_contact_left", rightSet = "shroud_contact_right";
  double kn = 1e4 / 2.4, kt = 1e4 / 2.4, mu = 0.4;  ///< N/mm^3 (Law::PerArea), or N/mm per pair
  double preload = 0;  ///< N0: normal force at zero relative displacement per pair, or the interface's (N)
  /// 0: every node pair a contact. Else the face split into this many patches, each one
  /// contact on its pairs' mean motion (ShroudContactPatches.hpp): fewer contacts for
  /// the harmonic balance, the same interface (area, stiffness, load).
  int patches = 0;
  /// The contact frame, unit and orthogonal: the normal points from this sector into the
  /// next; zero vectors: the cyclic plane's normal at the right face and the radial direction.
  Eigen::Vector3d normal = Eigen::Vector3d::Zero(), tangent = Eigen::Vector3d::Zero();
};

/// Gap elements (Scalvini 2021, sec. 8.6) in place of friction contacts at some pairs: the
/// normal direction only, f = kn max(w_n - clearance, 0) with w_n the normal
/// approach; clearance > 0 is a gap that must close, < 0 an interference.
struct ShroudGapSpec {
  std::vector<int> pairs;  ///< contact pairs (0-based, in the contact node sets' order)
  double kn = 1e4;         ///< N/mm
  double clearance = 0;    ///< mm
};

struct DiscExcitationSpec {
  std::string nodeSet = "mid_blade";
  Eigen::Vector3d direction = Eigen::Vector3d::UnitZ();  ///< sector 0's frame; normalised
  double amplitude = 1.0;                                ///< per node (N)
};

struct DiscResponseSpec {
  int engineOrder = 0;
  std::vector<int> harmonics{0, 1, 2, 3};
  int samples = 0;  ///< 0: what the friction elements recommend, and at least HarmonicSet::nonsmoothSamples
  ShroudContactSpec contact;
  ShroudGapSpec gap;
  DiscExcitationSpec excitation;
  std::vector<std::string> responseNodeSets{"mid_blade"};
  /// Solve for the contacts' relative displacements and the excited and output DOFs
  /// (Petrov's condensed form, hbm/CondensedSystem.hpp) instead of every retained DOF:
  /// the same solutions, about half the unknowns. Off: the retained DOFs (the other
  /// nodes' motion in the solution; the condensed form's reference in the tests).
  bool condensed = true;
};

/// The contact pairs of the spec's node sets: each left node with the right node at its
/// image under the rotation by 2 pi / sectors about `axis` (to 1e-6 of the mesh's size),
/// any order in the sets; pairs in the left set's order (what the gap elements' and the
/// contact outputs' pair indices count). InputError naming `contact` where the sets do
/// not pair so (their sizes, the nodes without a partner).
mesh::NodePairing shroudContactPairs(const mesh::Mesh& mesh, int sectors, const mesh::RotationAxis& axis,
                                     const ShroudContactSpec& contact);

/// The contact frame [t1, t2, n] (columns) of the spec; InputError if the given one is not orthonormal.
Eigen::Matrix3d shroudContactFrame(const mesh::Mesh& mesh, const DiscReducedModels& models,
                                   const ShroudContactSpec& contact);

/// What makeDiscForcedResponse checks in the spec that needs no reduced model: the engine
/// order, the harmonics, the contact pairs and law (its values, the friction and gap
/// elements' parameters), the excitation's direction and amplitude, the node sets named;
/// and the contacts' kn and kt against the material's E times the sector's size (a
/// stiffness no node of the sector has, far above the bound kRigidContactRatio that
/// solveDiscForcedResponse holds them to once the models give the sector's own).
/// InputError naming the key; so a scene can refuse them before any FE work.
void checkDiscResponse(const mesh::Mesh& mesh, int sectors, const mesh::RotationAxis& axis,
                       const DiscResponseSpec& spec, double youngsModulus);

/// The shroud contacts' total preload over the excitation's total force (|amplitude| times
/// the excited nodes). The oscillating rows' residual is held to the continuation's
/// tolerance relative to the excitation, and the contact forces carry the preload's
/// round-off (double precision's 2.2e-16 of it) into those rows: far above
/// tolerance / 2.2e-16 no start converges (on the default disc, 2e4 N against 1e-3 N
/// traced, against 1e-4 N it did not).
double preloadOverExcitation(const mesh::Mesh& mesh, int sectors, const mesh::RotationAxis& axis,
                             const DiscResponseSpec& spec);

/// What that ratio means for a continuation tolerance, said with the keys to change
/// (empty where the preload's round-off is below a tenth of the tolerance).
std::string preloadRoundoffText(double preloadOverExcitation, double tolerance);

/// The node sets the forced response uses (contact faces, excitation, response sets) all
/// among the reduced models' retained node sets: InputError("reduced_model/retained_node_sets")
/// naming the set, before any model is built. With `patchMeans` the contact faces are not
/// asked for (the models retain the patches' mean motions instead).
void checkRetainedNodeSets(const mesh::Mesh& mesh, const std::vector<std::string>& retainedNodeSets,
                           const DiscResponseSpec& spec, bool patchMeans = false);

/// The system: receptance form over `models`, one friction3d element named "contact" per
/// pair (w = [t1, t2, n]^T (u_next - u), n > 0 pressing the faces together), or a
/// unilateral spring named "gap" on w_n for the pairs spec.gap names, the
/// excitation on harmonic 1, output DOFs the response nodes' x, y, z. Continuation in
/// omega by default, p = f / referenceHz.
/// The disc's automatic time samples per period (disc_response/samples left out): the
/// friction contacts' count (hbm::FrictionContact::kRecommendedSamples) or, for many
/// harmonics, harmonics.nonsmoothSamples() (16 to 32 per period of the highest).
int discAutomaticSamples(const hbm::HarmonicSet& harmonics);

response::ForcedResponseSetup makeDiscForcedResponse(const mesh::Mesh& mesh, const DiscReducedModels& models,
                                           const DiscResponseSpec& spec, double referenceHz = 1.0);

/// The continuation settings the FE disc's curves are traced with (library users get
/// the scenes' defaults): the predictor-corrector by default, its steps in its scaled
/// space (initial 0.01, max 0.2: measured on the default disc, 166 points for the whole
/// H = 1 curve against 288 with 0.05), Newton to 1e-8; for LOCA its tuned units
/// (initial 0.002, max 0.02, min 1e-7, its arclength rescaling off, a walk back stopped).
continuation::ContinuationOptions discContinuationOptions(
    continuation::ContinuationOptions::Engine engine = continuation::ContinuationOptions::Engine::PredictorCorrector);

/// Where the engine order's resonance lies (Hz): the first natural frequency of its nodal
/// diameter with the shroud free (`family` counted from 1) and the peak of the response
/// linearised at rest (contacts stuck, the shroud coupled), found on a fine scan.
struct ResonanceEstimate {
  int nodalDiameter = 0;
  double freeHz = 0, stuckHz = 0;
  double stuckAmplitude = 0;  ///< the output DOF's at stuckHz, the contacts stuck (mm)
};
ResonanceEstimate estimateResonance(response::ForcedResponseSetup& setup, const DiscReducedModels& models, int family = 1);
/// estimateResonance for the disc `spec` describes (harmonic 1 alone). Without a preload
/// the contacts linearised at rest carry nothing, so its stuck resonance would be the free
/// one: they are closed for it (any preload's linearisation at rest, the same tangent).
ResonanceEstimate estimateDiscResonance(const mesh::Mesh& mesh, const DiscReducedModels& models,
                                        const DiscResponseSpec& spec, int family = 1);

}  // namespace cyclone::disc
