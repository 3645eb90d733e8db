#include "cyclone/rom/BoundaryReduction.hpp"

#include <Teuchos_CommHelpers.hpp>
#include <Tpetra_CrsMatrix.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>
#include <TpetraExt_MatrixMatrix.hpp>

#include <array>
#include <sstream>

#include "cyclone/core/Error.hpp"
#include "cyclone/core/Log.hpp"
#include "cyclone/core/Timer.hpp"
#include "cyclone/cyclic/CyclicModalAnalysis.hpp"
#include "cyclone/rom/NodalDiameterModel.hpp"
#include "cyclone/solvers/DirectSolver.hpp"
#include "cyclone/solvers/ModalSolver.hpp"
#include "TransposeProduct.hpp"

namespace cyclone::rom {
namespace {

using linalg::GlobalIndex;

// The unknowns split into the retained DOFs (boundary, in retained order) and the
// rest (interior, renumbered 0.. in the same order: the interior map keeps each
// row on the rank that owns it in the full map). A node retained in a local frame
// has its 3 unknowns rotated into that frame first (rotation below): then unknown
// j of the node is the displacement along frame vector j, and the directions not
// retained are interior, so Guyan and Craig-Bampton condense them correctly.
struct Partition {
  std::vector<GlobalIndex> boundary;  // unknown of retained DOF r
  std::vector<GlobalIndex> interior;  // full unknown -> interior unknown, -1 on the boundary
  std::vector<int> boundaryOf;        // full unknown -> retained DOF, -1 in the interior
  Teuchos::RCP<const linalg::Map> interiorMap;
  std::vector<long long> localInterior;  // owned full row -> owned interior row, -1 on the boundary
  // The rotated nodes' unknowns: per node and copy, the unknowns of x, y, z and the frame.
  std::vector<std::pair<std::array<GlobalIndex, 3>, Eigen::Matrix3d>> rotations;
};

std::string dofName(const mesh::Mesh& mesh, mesh::Index node, int d, int c) {
  std::ostringstream s;
  s << "node " << mesh.nodeIds.at(std::size_t(node)) << " direction " << "xyz"[d] << " copy " << c;
  return s.str();
}

Partition partition(const NodalDiameterModel& model, const linalg::Map& fullMap) {
  const auto& T = model.operators().assembler->transform();
  const auto& mesh = model.operators().assembler->mesh();
  const auto& retained = model.retainedDofs();
  // A boundary coordinate is one unknown; a mean of several nodes is none.
  if (!retained.means.empty())
    throw InputError("retained", "a Guyan or Craig-Bampton boundary keeps nodes' DOFs; the mean '" +
                                     retained.means.front().name +
                                     "' of several nodes is not one (a hybrid or truncation model retains means)");
  Partition p;
  const auto n = std::size_t(T.numEquations());
  p.boundaryOf.assign(n, -1);
  // The unknown of (node, global direction d, copy c). A boundary coordinate must be an
  // unknown itself: a fixed DOF has none, a right-face or axis node is a combination
  // (its partner unknowns are interior). A rotated node needs all 3 (the frame mixes them).
  const auto unknown = [&](mesh::Index node, int d, int c) {
    const auto terms = T.terms(node, d, c);
    const auto count = terms.end() - terms.begin();
    if (count == 0)
      throw InputError("retained", dofName(mesh, node, d, c) +
                                       " is fixed: a Guyan or Craig-Bampton boundary DOF (or a DOF of a node "
                                       "retained in a local frame) must be free");
    if (count > 1 || terms.begin()->coefficient != 1.0)
      throw InputError("retained", dofName(mesh, node, d, c) +
                                       " is a combination of unknowns (a cyclic right-face or axis node): "
                                       "retain nodes off the paired side faces and the axis");
    return GlobalIndex(terms.begin()->equation);
  };
  for (int c = 0; c < model.copies(); ++c) {
    for (std::size_t i = 0; i < retained.nodes.size(); ++i)
      if (retained.rotated[i]) {
        std::array<GlobalIndex, 3> eqs{};
        for (int d = 0; d < 3; ++d) eqs[std::size_t(d)] = unknown(retained.nodes[i], d, c);
        p.rotations.emplace_back(eqs, retained.frames[i]);
      }
    for (const auto& [i, j] : retained.dofs) {
      const mesh::Index node = retained.nodes[std::size_t(i)];
      // After the rotation the node's unknown of direction j is its coordinate along frame vector j.
      const GlobalIndex eq = unknown(node, j, c);
      if (p.boundaryOf[std::size_t(eq)] >= 0)
        throw InputError("retained", dofName(mesh, node, j, c) + " repeats another retained DOF");
      p.boundaryOf[std::size_t(eq)] = int(p.boundary.size());
      p.boundary.push_back(eq);
    }
  }
  p.interior.assign(n, -1);
  GlobalIndex next = 0;
  for (std::size_t eq = 0; eq < n; ++eq)
    if (p.boundaryOf[eq] < 0) p.interior[eq] = next++;
  std::vector<GlobalIndex> owned;
  for (std::size_t r = 0; r < fullMap.getNodeNumElements(); ++r) {
    const GlobalIndex g = p.interior[std::size_t(fullMap.getGlobalElement(r))];
    if (g >= 0) owned.push_back(g);
  }
  using GO = GlobalIndex;
  p.interiorMap = Teuchos::rcp(new linalg::Map(Tpetra::global_size_t(next), Teuchos::ArrayView<const GO>(owned), 0,
                                               fullMap.getComm()));
  for (std::size_t r = 0; r < fullMap.getNodeNumElements(); ++r) {
    const GlobalIndex g = p.interior[std::size_t(fullMap.getGlobalElement(r))];
    p.localInterior.push_back(g >= 0 ? (long long)(p.interiorMap->getLocalElement(g)) : -1);
  }
  return p;
}

// A_ii: the interior rows and columns of A, on the interior map.
Teuchos::RCP<linalg::Matrix> interiorBlock(const linalg::Matrix& A, const Partition& p) {
  const auto rowMap = A.getRowMap();
  const auto colMap = A.getColMap();
  linalg::Matrix::local_inds_host_view_type cols;
  linalg::Matrix::values_host_view_type vals;
  // Tpetra 13.2 allocates rows up front: count each interior row's entries first.
  std::vector<std::size_t> counts(p.interiorMap->getNodeNumElements(), 0);
  for (std::size_t r = 0; r < A.getNodeNumRows(); ++r) {
    const GlobalIndex row = p.interior[std::size_t(rowMap->getGlobalElement(r))];
    if (row < 0) continue;
    A.getLocalRowView(r, cols, vals);
    auto& count = counts[std::size_t(p.interiorMap->getLocalElement(row))];
    for (std::size_t k = 0; k < cols.extent(0); ++k) count += p.interior[std::size_t(colMap->getGlobalElement(cols(k)))] >= 0;
  }
  auto out = Teuchos::rcp(new linalg::Matrix(p.interiorMap, Teuchos::ArrayView<const std::size_t>(counts)));
  std::vector<GlobalIndex> ic;
  std::vector<double> iv;
  for (std::size_t r = 0; r < A.getNodeNumRows(); ++r) {
    const GlobalIndex row = p.interior[std::size_t(rowMap->getGlobalElement(r))];
    if (row < 0) continue;
    A.getLocalRowView(r, cols, vals);
    ic.clear();
    iv.clear();
    for (std::size_t k = 0; k < cols.extent(0); ++k) {
      const GlobalIndex col = p.interior[std::size_t(colMap->getGlobalElement(cols(k)))];
      if (col >= 0) {
        ic.push_back(col);
        iv.push_back(vals(k));
      }
    }
    out->insertGlobalValues(row, Teuchos::ArrayView<const GlobalIndex>(ic), Teuchos::ArrayView<const double>(iv));
  }
  out->fillComplete(p.interiorMap, p.interiorMap);
  return out;
}

// -K_ib: the boundary columns of the interior rows, one column per retained DOF.
linalg::MultiVector interiorCouplingRhs(const linalg::Matrix& K, const Partition& p) {
  linalg::MultiVector out(p.interiorMap, p.boundary.size());
  const auto rowMap = K.getRowMap();
  const auto colMap = K.getColMap();
  linalg::Matrix::local_inds_host_view_type cols;
  linalg::Matrix::values_host_view_type vals;
  for (std::size_t r = 0; r < K.getNodeNumRows(); ++r) {
    const GlobalIndex row = p.interior[std::size_t(rowMap->getGlobalElement(r))];
    if (row < 0) continue;
    K.getLocalRowView(r, cols, vals);
    for (std::size_t k = 0; k < cols.extent(0); ++k) {
      const int b = p.boundaryOf[std::size_t(colMap->getGlobalElement(cols(k)))];
      if (b >= 0) out.sumIntoGlobalValue(row, std::size_t(b), -vals(k));
    }
  }
  return out;
}

// Full-space vectors from interior ones (boundary rows = `boundaryRows`, a retained
// x columns matrix; for constraint modes the identity, for fixed-interface modes 0).
linalg::MultiVector embed(const linalg::MultiVector& interior, const Eigen::MatrixXd& boundaryRows,
                          const Teuchos::RCP<const linalg::Map>& fullMap, const Partition& p) {
  const std::size_t nv = interior.getNumVectors();
  linalg::MultiVector out(fullMap, nv);
  for (std::size_t j = 0; j < nv; ++j) {
    const auto src = interior.getData(j);
    auto dst = out.getDataNonConst(j);
    for (std::size_t r = 0; r < fullMap->getNodeNumElements(); ++r) {
      if (const long long i = p.localInterior[r]; i >= 0)
        dst[r] = src[i];
      else
        dst[r] = boundaryRows(p.boundaryOf[std::size_t(fullMap->getGlobalElement(r))], Eigen::Index(j));
    }
  }
  return out;
}

// The boundary rows of X (retained x columns, on every rank): K_g = (K Psi)_b, since
// K Psi vanishes on the interior; cheaper than Psi^T K Psi by a factor n / nb.
Eigen::MatrixXd boundaryRows(const linalg::MultiVector& X, const Partition& p) {
  const auto& map = *X.getMap();
  Eigen::MatrixXd local = Eigen::MatrixXd::Zero(Eigen::Index(p.boundary.size()), Eigen::Index(X.getNumVectors()));
  for (std::size_t j = 0; j < X.getNumVectors(); ++j) {
    const auto x = X.getData(j);
    for (std::size_t b = 0; b < p.boundary.size(); ++b)
      if (map.isNodeGlobalElement(p.boundary[b]))
        local(Eigen::Index(b), Eigen::Index(j)) = x[map.getLocalElement(p.boundary[b])];
  }
  Eigen::MatrixXd out(local.rows(), local.cols());
  Teuchos::reduceAll(*map.getComm(), Teuchos::REDUCE_SUM, int(local.size()), local.data(), out.data());
  return out;
}

Eigen::MatrixXd symmetricPart(const Eigen::MatrixXd& A) { return 0.5 * (A + A.transpose()); }

// R = the identity except, for each rotated node, u_d = sum_j frame(j, d) q_j on its
// unknowns (frame rows are the unit vectors): new unknown j is q_j. Orthogonal.
Teuchos::RCP<linalg::Matrix> rotation(const Partition& p, const Teuchos::RCP<const linalg::Map>& map) {
  std::vector<const std::pair<std::array<GlobalIndex, 3>, Eigen::Matrix3d>*> rotatedRow(
      map->getGlobalNumElements(), nullptr);
  std::vector<int> directionOf(map->getGlobalNumElements(), -1);
  for (const auto& r : p.rotations)
    for (int d = 0; d < 3; ++d) rotatedRow[std::size_t(r.first[std::size_t(d)])] = &r, directionOf[std::size_t(r.first[std::size_t(d)])] = d;
  auto R = Teuchos::rcp(new linalg::Matrix(map, 3));
  for (std::size_t r = 0; r < map->getNodeNumElements(); ++r) {
    const GlobalIndex row = map->getGlobalElement(r);
    if (const auto* rot = rotatedRow[std::size_t(row)]) {
      const int d = directionOf[std::size_t(row)];
      const std::array<double, 3> v{rot->second(0, d), rot->second(1, d), rot->second(2, d)};
      R->insertGlobalValues(row, Teuchos::ArrayView<const GlobalIndex>(rot->first.data(), 3),
                            Teuchos::ArrayView<const double>(v.data(), 3));
    } else {
      const double one = 1.0;
      R->insertGlobalValues(row, Teuchos::ArrayView<const GlobalIndex>(&row, 1), Teuchos::ArrayView<const double>(&one, 1));
    }
  }
  R->fillComplete(map, map);
  return R;
}

// R^T A R (sparse; only the rotated nodes' rows and columns change).
Teuchos::RCP<linalg::Matrix> rotated(const linalg::Matrix& A, const linalg::Matrix& R) {
  auto RtA = Teuchos::rcp(new linalg::Matrix(R.getDomainMap(), 0));
  Tpetra::MatrixMatrix::Multiply(R, true, A, false, *RtA);
  auto out = Teuchos::rcp(new linalg::Matrix(R.getDomainMap(), 0));
  Tpetra::MatrixMatrix::Multiply(*RtA, false, R, false, *out);
  return out;
}

}  // namespace

BoundaryReduction reduceOntoRetainedDofs(const NodalDiameterModel& model, int fixedInterfaceModes) {
  if (fixedInterfaceModes < 0) throw InputError("fixed_interface_modes", "must be >= 0");
  const auto& op = model.operators();
  const auto fullMap = op.K->getRowMap();
  Timer timer;
  const Partition p = partition(model, *fullMap);
  // Nodes in local frames: K and M in the rotated unknowns (otherwise the model's own).
  Teuchos::RCP<const linalg::Matrix> K = op.K, M = op.M;
  if (!p.rotations.empty()) {
    const auto R = rotation(p, fullMap);
    K = rotated(*op.K, *R);
    M = rotated(*op.M, *R);
  }
  const auto interiorEquations = (long long)(p.interiorMap->getGlobalNumElements());
  if (fixedInterfaceModes * model.copies() >= interiorEquations)
    throw InputError("fixed_interface_modes", std::to_string(fixedInterfaceModes) + " asked for, the interior has " +
                                                  std::to_string(interiorEquations) + " unknowns");
  const auto Kii = interiorBlock(*K, p);
  std::unique_ptr<solvers::DirectSolver> solver;
  try {
    solver = std::make_unique<solvers::DirectSolver>(*Kii);
  } catch (const SolverError& e) {
    throw InputError("retained", std::string("K_ii (the sector with the retained DOFs held) does not factor: the "
                                             "retained DOFs do not hold it. ") + e.what());
  }
  const double factorSeconds = timer.seconds();
  const auto nb = Eigen::Index(p.boundary.size());
  linalg::MultiVector psiInterior(p.interiorMap, std::size_t(nb));
  solver->solve(interiorCouplingRhs(*K, p), psiInterior);
  const double solveSeconds = timer.seconds() - factorSeconds;
  const auto Psi = embed(psiInterior, Eigen::MatrixXd::Identity(nb, nb), fullMap, p);
  linalg::MultiVector KPsi(fullMap, std::size_t(nb)), MPsi(fullMap, std::size_t(nb));
  K->apply(Psi, KPsi);
  M->apply(Psi, MPsi);

  BoundaryReduction out;
  out.copies = model.copies();
  out.interiorEquations = interiorEquations;
  out.stiffness = symmetricPart(boundaryRows(KPsi, p));
  out.mass = symmetricPart(transposeProduct(Psi, MPsi));
  out.staticSeconds = timer.seconds();

  timer.restart();
  out.massCoupling.resize(nb, 0);
  if (fixedInterfaceModes > 0) {
    solvers::ModalOptions opt;
    opt.numModes = fixedInterfaceModes * model.copies();
    opt.blockSize = std::max(4, 2 * model.copies());  // as for the sector's own modes: pairs together
    const auto Mii = interiorBlock(*M, p);
    const auto modes = solvers::solveModes(*Kii, *Mii, opt);
    out.interfaceEigenvalues = modes.eigenvalues;
    const auto Phi = embed(*modes.modes, Eigen::MatrixXd::Zero(nb, Eigen::Index(modes.modes->getNumVectors())),
                           fullMap, p);
    out.massCoupling = transposeProduct(MPsi, Phi);
  }
  out.modesSeconds = timer.seconds();
  std::ostringstream msg;
  msg << "boundary reduction k = " << model.nodalDiameter() << ": " << nb << " boundary DOFs, " << interiorEquations
      << " interior unknowns; constraint modes " << out.staticSeconds << " s (K_ii and its factorization "
      << factorSeconds << " s, solves " << solveSeconds << " s, K_g and M_g " << out.staticSeconds - factorSeconds - solveSeconds
      << " s), " << out.numInterfaceModes()
      << " fixed-interface modes " << out.modesSeconds << " s";
  log::info(msg.str());
  return out;
}

}  // namespace cyclone::rom
