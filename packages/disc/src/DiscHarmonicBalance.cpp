#include "cyclone/disc/DiscHarmonicBalance.hpp"

#include "cyclone/disc/ShroudContactLaw.hpp"
#include "cyclone/disc/DiscForcedResponse.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <tuple>

#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/NumberText.hpp"
#include "cyclone/hbm/CondensedSystem.hpp"
#include "cyclone/response/ForcedResponseChecks.hpp"
#include "cyclone/hbm/FrictionContact.hpp"
#include "cyclone/hbm/ScalarElementAdapter.hpp"
#include "cyclone/hbm/UnilateralSpring.hpp"
#include "cyclone/hbm/HarmonicRefinement.hpp"
#include "cyclone/rom/HybridFrfModel.hpp"
#include "cyclone/mesh/Mesh.hpp"
#include "cyclone/rom/SectorReceptance.hpp"

namespace cyclone::disc {

using response::ForcedResponseSetup;

namespace {

Eigen::Vector3d vec(const mesh::Point& p) { return {p[0], p[1], p[2]}; }

int retainedIndex(const DiscReducedModels& models, mesh::Index node, const std::string& set) {
  const auto it = std::find(models.retainedNodes.begin(), models.retainedNodes.end(), node);
  if (it == models.retainedNodes.end())
    throw InputError("reduced_model/retained_node_sets", "does not retain node set '" + set +
                                                             "', which the forced response uses: add it");
  return int(it - models.retainedNodes.begin());
}

// Petrov's condensed unknowns (hbm/CondensedSystem.hpp): each contact's relative
// displacement and the excited and output DOFs instead of every retained DOF. The
// same solutions; half the unknowns of the default disc, an 8 times cheaper
// factorisation per Newton step. Where the coordinates are not independent (an
// output node on a contact face) the full system stays, and the log says so.
void condenseOntoContacts(ForcedResponseSetup& setup) {
  const auto& full = *setup.system;
  const int n = full.numDofs(), nc = full.numCoefficients();
  std::vector<int> kept;
  for (int dof = 0; dof < n; ++dof)
    if (full.excitation().segment(dof * nc, nc).squaredNorm() > 0 || full.staticLoad().segment(dof * nc, nc).squaredNorm() > 0)
      kept.push_back(dof);
  for (int dof : setup.outputDofs)
    if (std::find(kept.begin(), kept.end(), dof) == kept.end()) kept.push_back(dof);
  hbm::CondensedSystem condensed;
  try {
    condensed = hbm::condenseOntoElements(full, kept);
  } catch (const InputError& e) {
    log::info(std::string("forced response: the full retained DOFs are solved (") + e.what() + ")");
    return;
  }
  std::vector<std::string> names;
  for (int dof : condensed.keptDofs) names.push_back(setup.dofNames[std::size_t(dof)]);
  const char* axis[] = {"t1", "t2", "n"};
  for (std::size_t e = 0; e < full.elements().size(); ++e) {
    const int d = int(full.elements()[e].W.cols());
    for (int k = 0; k < d; ++k)
      names.push_back(setup.elementNames[e] + std::to_string(e) + "_" + axis[3 - d + k]);
  }
  for (int& dof : setup.outputDofs)
    dof = int(std::find(condensed.keptDofs.begin(), condensed.keptDofs.end(), dof) - condensed.keptDofs.begin());
  std::ostringstream msg;
  msg << "forced response: condensed onto the contacts' relative displacements and the excited and output DOFs, "
      << condensed.system->numDofs() << " coordinates for " << n << " retained DOFs";
  log::info(msg.str());
  setup.dofNames = std::move(names);
  setup.system = std::move(condensed.system);
}

}  // namespace

namespace {

// A contact frame the scene gives: unit vectors at right angles (InputError otherwise).
void checkContactFrame(const ShroudContactSpec& contact) {
  const Eigen::Vector3d &n = contact.normal, &t = contact.tangent;
  const double tol = 1e-6;
  if (std::abs(n.norm() - 1) > tol || std::abs(t.norm() - 1) > tol || std::abs(n.dot(t)) > tol) {
    std::ostringstream msg;
    msg << "contact frame not orthonormal: |normal| = " << n.norm() << ", |tangent| = " << t.norm()
        << ", normal . tangent = " << n.dot(t) << " (give unit vectors at right angles)";
    throw InputError("contact/normal, contact/tangent", msg.str());
  }
}

}  // namespace

Eigen::Matrix3d shroudContactFrame(const mesh::Mesh& mesh, const DiscReducedModels& models,
                                   const ShroudContactSpec& contact) {
  const auto& right = mesh.nodeSet(contact.rightSet);
  const Eigen::Vector3d a = models.sector.axis.direction.normalized(), p0 = models.sector.axis.point;
  Eigen::Vector3d n = contact.normal, t = contact.tangent;
  if (n.norm() == 0 && t.norm() == 0) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (auto i : right) c += vec(mesh.coords[i]);
    c /= double(right.size());
    Eigen::Vector3d r = (c - p0) - (c - p0).dot(a) * a;
    if (r.norm() == 0) throw InputError("contact", "the right contact face lies on the axis: give normal and tangent");
    r.normalize();
    n = a.cross(r);  // towards increasing angle: into the next sector
    t = r;
  } else {
    checkContactFrame(contact);
  }
  Eigen::Matrix3d E;
  E.col(0) = t, E.col(1) = n.cross(t), E.col(2) = n;
  return E;
}

mesh::NodePairing shroudContactPairs(const mesh::Mesh& mesh, int sectors, const mesh::RotationAxis& axis,
                                     const ShroudContactSpec& contact) {
  const auto& left = mesh.nodeSet(contact.leftSet);
  const auto& right = mesh.nodeSet(contact.rightSet);
  if (left.size() != right.size())
    throw InputError("contact", "node sets '" + contact.leftSet + "' (" + std::to_string(left.size()) +
                                    " nodes) and '" + contact.rightSet + "' (" + std::to_string(right.size()) +
                                    ") do not pair");
  double size = 0;
  const Eigen::Vector3d p0(axis.point[0], axis.point[1], axis.point[2]);
  for (const auto& c : mesh.coords) size = std::max(size, (vec(c) - p0).norm());
  try {
    return mesh::pairRotatedNodes(mesh, left, right, 2 * M_PI / sectors, axis, 1e-6 * size,
                                  "contact node sets '" + contact.leftSet + "' and '" + contact.rightSet +
                                      "' (each right node the image of a left node under the sector rotation)");
  } catch (const InputError& e) {
    throw InputError("contact", e.where() + ": " + e.problem());
  }
}

namespace {

// An engine order the sectors carry as a travelling wave: 1 <= EO < N.
void checkEngineOrder(int engineOrder, int N) {
  if (engineOrder < 1)
    throw InputError("disc_response/engine_order", "must be >= 1 (engine order " + std::to_string(engineOrder) +
                                                       " is no travelling excitation; 0 is a static load)");
  if (engineOrder > N)
    throw InputError("disc_response/engine_order",
                     std::to_string(engineOrder) + " on " + std::to_string(N) +
                         " sectors: the blades see it exactly as engine order " +
                         std::to_string(engineOrder % N) + " (EO mod N; the excitation exists only at the " +
                         "sectors, so higher orders fold back); give " + std::to_string(engineOrder % N));
  if (engineOrder == N)
    throw InputError("disc_response/engine_order", std::to_string(N) + " on " + std::to_string(N) +
                                                       " sectors folds to 0: every sector in phase (nodal diameter 0); "
                                                       "not a travelling wave, use the nodal-diameter-0 response");
}

// Which pairs carry a gap element instead of friction (checked), and that element.
std::shared_ptr<const hbm::NonlinearElement> gapElementFor(const ShroudGapSpec& gap, const ShroudContactSpec& contact,
                                                          std::size_t pairs, std::vector<bool>& isGap) {
  isGap.assign(pairs, false);
  if (gap.pairs.empty()) return nullptr;
  if (contact.patches > 0)
    throw InputError("gap/pairs", "names node pairs, which contact/patches groups: give one or the other");
  for (int i : gap.pairs) {
    if (i < 0 || i >= int(pairs))
      throw InputError("gap/pairs", "pair " + std::to_string(i) + " is not one of the " + std::to_string(pairs) +
                                        " contact pairs (0-based)");
    if (isGap[std::size_t(i)]) throw InputError("gap/pairs", "pair " + std::to_string(i) + " is listed twice");
    isGap[std::size_t(i)] = true;
  }
  if (!(std::isfinite(gap.kn) && gap.kn > 0))
    throw InputError("gap/kn", "must be a positive stiffness (N/mm), got " + std::to_string(gap.kn));
  if (!std::isfinite(gap.clearance)) throw InputError("gap/clearance", "must be finite");
  return std::make_shared<hbm::ScalarElementAdapter>(std::make_shared<hbm::UnilateralSpring>(gap.kn, gap.clearance));
}

// A shroud contact's 3D friction law (InputError naming `contact` for bad parameters).
std::shared_ptr<const hbm::NonlinearElement> frictionElement(double kn, double kt, double mu, double preload) {
  hbm::FrictionContactParameters p;
  p.tangentialDirections = 2, p.kn = kn, p.kt = kt, p.mu = mu;
  p.preload = preload;
  try {
    return std::make_shared<hbm::FrictionContact>(p);
  } catch (const InputError& e) {
    throw InputError("contact", e.what());
  }
}

// One element per pair, on w = E^T (Q^T u_next,left - u_right): friction (one element
// for all pairs where the law is per pair, each pair's own where it is per area), or a
// gap on the normal (the frame's last column) only.
void addContactElements(hbm::HarmonicBalanceSystem& hb, const mesh::Mesh& mesh, const DiscReducedModels& models,
                        const DiscResponseSpec& spec, const mesh::NodePairing& pairs,
                        const ShroudContactValues& values, ForcedResponseSetup& setup) {
  const auto &left = pairs.left, &right = pairs.right;
  const bool shared = spec.contact.law == ShroudContactSpec::Law::PerPair && spec.contact.patches == 0;
  const auto sharedElement = frictionElement(spec.contact.kn, spec.contact.kt, spec.contact.mu, spec.contact.preload);
  const Eigen::Matrix3d Q = models.sector.rotation();
  const Eigen::Matrix3d E = shroudContactFrame(mesh, models, spec.contact);
  std::vector<bool> isGap;
  const auto gapElement = gapElementFor(spec.gap, spec.contact, values.members.size(), isGap);
  const int n = hb.numDofs();
  // Models that retain the patches' mean motions (DiscModelSpec::retainedMeans): each
  // patch reads its two means, which must be this spec's patches (the same pairs, weights).
  const auto& means = models.retainedMeans;
  if (!means.empty()) {
    const auto expected = shroudPatchMeans(pairs, values, spec.contact);
    bool same = expected.size() == means.size();
    for (std::size_t m = 0; same && m < means.size(); ++m)
      same = expected[m].nodes == means[m].nodes && expected[m].weights == means[m].weights;
    if (!same)
      throw InputError("contact/patches", "the reduced models retain " + std::to_string(means.size()) +
                                              " means, not this contact's " + std::to_string(expected.size()) +
                                              " patch sides (build the models with this contact's patches)");
  }
  const int firstMean = int(models.retainedNodes.size());
  for (std::size_t c = 0; c < values.members.size(); ++c) {
    const int d = isGap[c] ? 1 : 3;
    const Eigen::MatrixXd Ei = E.rightCols(d);
    Eigen::MatrixXd W = Eigen::MatrixXd::Zero(n, d), Wnext = Eigen::MatrixXd::Zero(n, d);
    if (!means.empty()) {  // the patch's right mean and the next sector's left mean
      W.middleRows(3 * (firstMean + 2 * int(c)), 3) -= Ei;
      Wnext.middleRows(3 * (firstMean + 2 * int(c) + 1), 3) += Q.transpose() * Ei;
    }
    // The contact's motion: its pairs' relative motions weighted (one pair of weight 1
    // without patches); its force goes back to them by the same weights.
    for (std::size_t m = 0; means.empty() && m < values.members[c].size(); ++m) {
      const auto i = std::size_t(values.members[c][m]);
      const double w = values.memberWeights[c][m];
      const int r = retainedIndex(models, right[i], spec.contact.rightSet);
      const int l = retainedIndex(models, left[i], spec.contact.leftSet);
      W.middleRows(3 * r, 3) -= w * Ei;                    // - this sector's right node
      Wnext.middleRows(3 * l, 3) += w * Q.transpose() * Ei;  // + the next sector's left node, rotated into this frame
    }
    hb.addElement(isGap[c]  ? gapElement
                  : shared ? sharedElement
                           : frictionElement(values.kn[c], values.kt[c], spec.contact.mu, values.preload[c]),
                  W, Wnext);
    setup.elementNames.push_back(isGap[c] ? "gap" : "contact");
  }
}

// The excitation on harmonic 1 (cos), travelling with the engine order, and the output
// DOFs: each response node's excitation direction first, then its other two.
void addExcitationAndOutputs(hbm::HarmonicBalanceSystem& hb, const mesh::Mesh& mesh, const DiscReducedModels& models,
                             const DiscResponseSpec& spec, ForcedResponseSetup& setup) {
  // stableNormalized: [0, 0, 1e300] made a zero force (its squared norm overflowed), and
  // the run failed after the reduced models as "no resonance of the stuck system".
  const Eigen::Vector3d d = spec.excitation.direction.stableNormalized();
  if (!(spec.excitation.direction.stableNorm() > 0)) throw InputError("excitation/direction", "must not be zero");
  for (auto node : mesh.nodeSet(spec.excitation.nodeSet)) {
    const int i = retainedIndex(models, node, spec.excitation.nodeSet);
    for (int c = 0; c < 3; ++c)
      if (d(c) != 0) hb.addExcitation(3 * i + c, 1, spec.excitation.amplitude * d(c));
  }
  const int n = hb.numDofs();
  setup.dofNames.resize(n);
  const int nodes = int(models.retainedNodes.size());
  for (int i = 0; i < n / 3; ++i)
    for (int c = 0; c < 3; ++c) {
      std::string name = i < nodes ? "node" + std::to_string(mesh.nodeIds[models.retainedNodes[std::size_t(i)]])
                                   : models.retainedMeans.at(std::size_t(i - nodes)).name;
      std::replace(name.begin(), name.end(), ' ', '_');
      setup.dofNames[3 * i + c] = name + "_" + "xyz"[c];
    }
  for (const auto& set : spec.responseNodeSets)
    for (auto node : mesh.nodeSet(set)) {
      const int i = retainedIndex(models, node, set);
      // The output DOF: the direction of the excitation's largest component first.
      int c0 = 0;
      d.cwiseAbs().maxCoeff(&c0);
      setup.outputDofs.push_back(3 * i + c0);
      for (int c = 0; c < 3; ++c)
        if (c != c0) setup.outputDofs.push_back(3 * i + c);
    }
}

// A contact stiffer than any node of the sector can be, refused from the material and the
// mesh alone: kn = 1e30 N/mm^3 was refused only after the reduced models were built, by
// the bound on the sector's own stiffness at the pairs (kRigidContactRatio, which needs
// the models), and kt = 1e30 was traced to a curve without a peak, exit 0. Why E times
// the sector's size bounds that stiffness: the sector's compliance at a pair is at least
// 1 / lambda_max(K), and K's largest eigenvalue is at most its largest row sum, of order E
// times an element's size (which the sector's size, its bounding box's diagonal, exceeds).
// The margin of 1e3 over the bounds after the models covers the row sum's constant (the
// elements at a node, a poorly shaped one), so nothing refused here would have passed
// them; on the default disc (mesh size 12) a pair's kn is about 1e-3 of E times the size
// (the interface's 4e5 N/mm over 21 pairs against 1.16e5 x 133), and 207 times the
// sector's own stiffness at the pair.
void checkContactStiffnessScale(const mesh::Mesh& mesh, const ShroudContactValues& values,
                                const ShroudContactSpec& contact, double youngsModulus) {
  const double size = mesh::boundingDiagonal(mesh);
  if (!(youngsModulus > 0) || !(size > 0)) return;  // the material's and the mesh's own checks say why
  const char* unit = contact.law == ShroudContactSpec::Law::PerArea ? " N/mm^3" : " N/mm";
  for (const auto& [name, law, pairValues, ratio] :
       {std::tuple<const char*, double, const std::vector<double>*, double>{"kn", contact.kn, &values.kn,
                                                                            1e3 * kRigidContactRatio},
        {"kt", contact.kt, &values.kt, 1e3 * kRigidTangentialContactRatio}}) {
    const double stiffest = pairValues->empty() ? 0 : *std::max_element(pairValues->begin(), pairValues->end());
    if (stiffest > ratio * youngsModulus * size)
      throw InputError(std::string("contact/") + name,
                       numberText(law) + unit + " makes a contact of " + numberText(stiffest, 3) +
                           " N/mm, more than " + numberText(ratio) +
                           " times the material's E times the sector's size (" + numberText(youngsModulus, 4) +
                           " x " + numberText(size, 4) +
                           ", its bounding box's diagonal), which no node of the sector is as stiff as: "
                           "rigid in effect, it only makes the balance too stiff to solve (the default disc's "
                           "contacts are about 200 times the sector's own stiffness at their pairs)");
  }
}

}  // namespace

void checkDiscResponse(const mesh::Mesh& mesh, int sectors, const mesh::RotationAxis& axis,
                       const DiscResponseSpec& spec, double youngsModulus) {
  checkEngineOrder(spec.engineOrder, sectors);
  const hbm::HarmonicSet harmonics(spec.harmonics);
  const auto pairs = shroudContactPairs(mesh, sectors, axis, spec.contact);
  const auto values = shroudContactValues(mesh, pairs, spec.contact);
  frictionElement(spec.contact.kn, spec.contact.kt, spec.contact.mu, spec.contact.preload);
  for (std::size_t i = 0; i < values.kn.size(); ++i)
    frictionElement(values.kn[i], values.kt[i], spec.contact.mu, values.preload[i]);
  checkContactStiffnessScale(mesh, values, spec.contact, youngsModulus);
  std::vector<bool> isGap;
  gapElementFor(spec.gap, spec.contact, values.members.size(), isGap);
  if (!spec.gap.pairs.empty()) {
    // A clearance or interference beyond the small displacements the linear models hold:
    // -1e3 mm was taken, its pairs carrying 5.6e6 N against the face's 2e4 N preload, and
    // the headline said "converged" (issue 49's fourth probe).
    const double size = mesh::boundingDiagonal(mesh);
    if (std::abs(spec.gap.clearance) > 0.01 * size)
      throw InputError("gap/clearance", numberText(spec.gap.clearance) + " mm is more than 1 % of the sector's size (" +
                                            numberText(size, 4) + " mm, its bounding box's diagonal): beyond the small "
                                            "displacements the linear reduced models hold (a clearance or "
                                            "interference is a fraction of a millimetre)");
  }
  if (!(spec.excitation.direction.stableNorm() > 0)) throw InputError("excitation/direction", "must not be zero");
  if (!std::isfinite(spec.excitation.amplitude) || spec.excitation.amplitude == 0)
    throw InputError("excitation/amplitude", "must be finite and not zero (a force to respond to), got " +
                                                 numberText(spec.excitation.amplitude));
  // (the same bound the trace holds it to, response::checkExcitationSize, here before the
  // models: 1e300 was refused after them, as a response too small)
  if (!(std::abs(spec.excitation.amplitude) < response::kLargestTraceable))
    throw InputError("excitation/amplitude", numberText(spec.excitation.amplitude) + " N is beyond " +
                                                 numberText(response::kLargestTraceable) +
                                                 ": the trace's products of it overflow double precision");
  // And below the smallest response the trace can carry: a disc's compliance is far below
  // 1 mm/N, so such a force's response is smaller still (1e-200 was refused only after
  // the reduced models, issue 49's fourth probe).
  if (std::abs(spec.excitation.amplitude) < response::kSmallestTraceable)
    throw InputError("excitation/amplitude", numberText(spec.excitation.amplitude) + " N is below " +
                                                 numberText(response::kSmallestTraceable) +
                                                 ": its response is too small to trace in double precision (its "
                                                 "square underflows); the response is linear in a force that small: "
                                                 "scale it up");
  if (spec.contact.normal.norm() != 0 || spec.contact.tangent.norm() != 0) checkContactFrame(spec.contact);
  mesh.nodeSet(spec.excitation.nodeSet);
  for (const auto& set : spec.responseNodeSets) mesh.nodeSet(set);
}

double preloadOverExcitation(const mesh::Mesh& mesh, int sectors, const mesh::RotationAxis& axis,
                             const DiscResponseSpec& spec) {
  const auto values = shroudContactValues(mesh, shroudContactPairs(mesh, sectors, axis, spec.contact), spec.contact);
  const double force = std::abs(spec.excitation.amplitude) * double(mesh.nodeSet(spec.excitation.nodeSet).size());
  return force > 0 ? values.totalPreload / force : 0.0;
}

std::string preloadRoundoffText(double ratio, double tolerance) {
  const double roundoff = ratio * std::numeric_limits<double>::epsilon();
  if (!(roundoff > 0.1 * tolerance)) return "";
  return "the shroud contacts' preload is " + numberText(ratio, 3) +
         " times the excitation's force: its round-off in double precision is " + numberText(roundoff / tolerance, 3) +
         " times the continuation's tolerance (" + numberText(tolerance) +
         ", relative to the excitation), which Newton cannot meet; raise disc_response/excitation/amplitude (where "
         "the contacts stay stuck the response is linear in it), lower disc_response/contact/preload, or loosen "
         "disc_response/continuation/tolerance";
}

void checkRetainedNodeSets(const mesh::Mesh& mesh, const std::vector<std::string>& retainedNodeSets,
                           const DiscResponseSpec& spec, bool patchMeans) {
  if (retainedNodeSets.empty())
    throw InputError("reduced_model/retained_node_sets", "is empty: the reduced models need the node sets the "
                                                         "forced response uses (contact faces, excitation)");
  std::vector<mesh::Index> retained;
  for (const auto& name : retainedNodeSets)
    for (mesh::Index n : mesh.nodeSet(name)) retained.push_back(n);
  std::sort(retained.begin(), retained.end());
  std::vector<std::string> used{spec.excitation.nodeSet};
  if (!patchMeans) used.insert(used.end(), {spec.contact.leftSet, spec.contact.rightSet});
  used.insert(used.end(), spec.responseNodeSets.begin(), spec.responseNodeSets.end());
  for (const auto& set : used)
    for (mesh::Index n : mesh.nodeSet(set))
      if (!std::binary_search(retained.begin(), retained.end(), n))
        throw InputError("reduced_model/retained_node_sets", "does not retain node set '" + set +
                                                                 "', which the forced response uses: add it");
}

int discAutomaticSamples(const hbm::HarmonicSet& harmonics) {
  return std::max(hbm::FrictionContact::kRecommendedSamples, harmonics.nonsmoothSamples());
}

ForcedResponseSetup makeDiscForcedResponse(const mesh::Mesh& mesh, const DiscReducedModels& models,
                                           const DiscResponseSpec& spec, double referenceHz) {
  const int N = models.sectors;
  checkEngineOrder(spec.engineOrder, N);
  auto receptance = std::make_shared<rom::SectorReceptance>(N, models.models);
  const hbm::HarmonicSet harmonics(spec.harmonics);
  for (int k : nodalDiametersFor(N, spec.engineOrder, spec.harmonics)) receptance->model(k);  // all there?
  const auto pairs = shroudContactPairs(mesh, models.sectors, models.sector.axis, spec.contact);
  const auto values = shroudContactValues(mesh, pairs, spec.contact);
  const auto element = frictionElement(spec.contact.kn, spec.contact.kt, spec.contact.mu, spec.contact.preload);
  const int samples = spec.samples > 0 ? spec.samples : discAutomaticSamples(harmonics);
  ForcedResponseSetup setup;
  setup.system = std::make_unique<hbm::HarmonicBalanceSystem>(receptance, harmonics, samples);
  auto& hb = *setup.system;
  hbm::CyclicCoupling coupling;
  coupling.sectors = N, coupling.engineOrder = spec.engineOrder;
  hb.setCyclic(coupling);
  // Z = A^-1 per harmonic when every model has the full rank (hybrid, full FE): a
  // cheaper Newton step than the compliance statement a modal truncation needs.
  bool invertible = true;
  for (const auto& [k, m] : models.models) {
    const auto* h = dynamic_cast<const rom::HybridFrfModel*>(m.get());
    if (h && !h->hasStaticCorrection()) invertible = false;
  }
  hb.useDynamicStiffness(invertible);
  addContactElements(hb, mesh, models, spec, pairs, values, setup);
  addExcitationAndOutputs(hb, mesh, models, spec, setup);
  if (spec.condensed) condenseOntoContacts(setup);
  setup.parameter = ForcedResponseSetup::Parameter::Omega;
  setup.omegaUnit = 2 * M_PI * referenceHz;
  setup.unknownScale = 0;  // displacements of ~1e-3 mm: scaled to order one for the arclength
  setup.stability = ForcedResponseSetup::Stability::Auto;  // the scene's disc_response/stability
  setup.continuation = discContinuationOptions();
  setup.fallback = discContinuationOptions(continuation::ContinuationOptions::Engine::Loca);
  return setup;
}

continuation::ContinuationOptions discContinuationOptions(continuation::ContinuationOptions::Engine engine) {
  continuation::ContinuationOptions opt;
  opt.engine = engine;
  opt.maxSteps = 2000, opt.tolerance = 1e-8;
  if (engine == continuation::ContinuationOptions::Engine::PredictorCorrector) {
    // The smallest step passes the micro-folds of the sampled contact laws: a contact's
    // opening or slip instant crossing a time sample folds the path back by ~1e-7 of the
    // range (a gap clearance study, docs/decisions.md 2026-11-26); 1e-6 stopped there.
    opt.initialStep = 0.01, opt.maxStep = 0.2, opt.minStep = 1e-8;
    opt.turnAngle = 0.12;  // 0.25 turned the preload study's 1 N curve where Hill sees no fold (docs/decisions.md, D3)
  } else {
    opt.initialStep = 0.002, opt.maxStep = 0.02, opt.minStep = 1e-7;
    opt.arcLengthScaling = false;     // the unknowns are scaled to order one (unknownScale)
    opt.stopWhereItTurnsBack = true;  // never a false "range finished" after walking back from a kink
  }
  return opt;
}

ResonanceEstimate estimateResonance(ForcedResponseSetup& setup, const DiscReducedModels& models, int family) {
  auto& hb = *setup.system;
  ResonanceEstimate out;
  out.nodalDiameter = hb.nodalDiameter(1);
  const auto& hz = models.naturalHz.at(out.nodalDiameter);
  if (family < 1 || family > int(hz.size()))
    throw InputError("disc_response/family", "must lie in 1.." + std::to_string(hz.size()) +
                                                 " (the natural frequencies computed per nodal diameter)");
  out.freeHz = hz[family - 1];
  // The stuck system's peak: the response linearised at rest on a log scan from below
  // the family up to 8x its free frequency (stuck shroud contacts stiffen it a lot),
  // harmonic 1 alone (the linearised harmonics do not couple).
  // Linear at rest (contacts stuck and closed, gaps open or shut), so exact at any samples
  // from 3: 64 (the scene's 65536 made its 300 solves take 35 s).
  const auto first = hbm::withHarmonics(hb, hbm::HarmonicSet({1}), std::min(hb.aft().numSamples(), 64));
  const int dof = setup.outputDofs.front(), nc = first->numCoefficients();
  const int c = first->aft().harmonics().cosIndex(1);
  auto amplitude = [&](double f) {
    const Eigen::VectorXd X = first->linearizedSolution(2 * M_PI * f, setup.excitationScale);
    return std::hypot(X(dof * nc + c), X(dof * nc + c + 1));
  };
  const double lo = (family > 1 ? hz[family - 2] * 1.02 : 0.8 * out.freeHz), hi = 8.0 * out.freeHz;
  const int steps = 300;
  std::vector<double> f(steps + 1), amp(steps + 1);
  for (int i = 0; i <= steps; ++i) f[i] = lo * std::pow(hi / lo, double(i) / steps), amp[i] = amplitude(f[i]);
  // The first interior local maximum that stands out (a resonance, not a flat rise).
  int at = -1;
  for (int i = 1; i < steps; ++i)
    if (amp[i] > amp[i - 1] && amp[i] >= amp[i + 1] && amp[i] > 2 * std::min(amp[0], amp[steps])) {
      at = i;
      break;
    }
  if (at < 0 && hz.back() < hi)  // a model without the modes the stuck system resonates in
    throw InputError("reduced_model/modes", "no resonance of the stuck system between " + numberText(lo) + " and " +
                                                numberText(hi) + " Hz, and the reduced model of nodal diameter " +
                                                std::to_string(out.nodalDiameter) +
                                                " keeps natural frequencies only up to " + numberText(hz.back()) +
                                                " Hz: keep more modes");
  if (at < 0)
    throw InputError("disc_response", "no resonance of the stuck system between " + std::to_string(lo) + " and " +
                                          std::to_string(hi) + " Hz: give frequency_range_hz");
  out.stuckHz = f[at];
  // Golden-section polish on the bracketing scan interval.
  double a = f[at - 1], b = f[at + 1];
  const double g = 0.5 * (std::sqrt(5.0) - 1);
  for (int it = 0; it < 40; ++it) {
    const double x1 = b - g * (b - a), x2 = a + g * (b - a);
    if (amplitude(x1) > amplitude(x2)) b = x2;
    else a = x1;
  }
  out.stuckHz = 0.5 * (a + b);
  out.stuckAmplitude = amplitude(out.stuckHz);
  return out;
}

ResonanceEstimate estimateDiscResonance(const mesh::Mesh& mesh, const DiscReducedModels& models,
                                        const DiscResponseSpec& spec, int family) {
  auto first = spec;
  first.harmonics = {1};
  // Closed and stuck under any positive load: the same tangent at rest.
  if (!(first.contact.preload > 0)) first.contact.preload = 1.0;
  auto setup = makeDiscForcedResponse(mesh, models, first);
  return estimateResonance(setup, models, family);
}

}  // namespace cyclone::disc
