#include "cyclone/fe/Assembler.hpp"

#include <Tpetra_FECrsGraph.hpp>
#include <Tpetra_FECrsMatrix.hpp>
#include <Tpetra_FEMultiVector.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
#include <array>
#include <functional>
#include <set>

#include "cyclone/core/Error.hpp"

namespace cyclone::fe {

using linalg::GlobalIndex;
using FEGraph = Tpetra::FECrsGraph<>;
using FEMatrix = Tpetra::FECrsMatrix<>;
using FEVector = Tpetra::FEMultiVector<>;

struct Assembler::Impl {
  linalg::CommPtr comm;
  Teuchos::RCP<const linalg::Map> owned, ownedPlusShared;
  Teuchos::RCP<const Tpetra::Import<>> importer;
  Teuchos::RCP<const FEGraph> graph;
  std::vector<mesh::Index> elements;               // assembled on this rank
  std::vector<std::vector<GlobalIndex>> equations;  // per local element: its unknowns, sorted
};

namespace {

// The unknowns an element's DOFs depend on, over all copies, sorted and unique.
std::vector<GlobalIndex> elementEquations(const DofTransform& T, const mesh::Index* nodes, int n) {
  std::vector<GlobalIndex> eq;
  for (int c = 0; c < T.copies(); ++c)
    for (int a = 0; a < n; ++a)
      for (int d = 0; d < 3; ++d)
        for (const auto& t : T.terms(nodes[a], d, c)) eq.push_back(t.equation);
  std::sort(eq.begin(), eq.end());
  eq.erase(std::unique(eq.begin(), eq.end()), eq.end());
  return eq;
}

// An element's unknowns over both copies of a transform: at most two per DOF. Element
// arrays of that size keep their storage inside (no allocation per element).
constexpr int kMaxElementUnknowns = 2 * kMaxElementDofs;
using ElementTransform =
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, kMaxElementDofs, kMaxElementUnknowns>;
using ReducedMatrix =
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, kMaxElementUnknowns, kMaxElementUnknowns>;
using ReducedVector = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, kMaxElementUnknowns, 1>;

// T_c restricted to one element: rows = element DOFs (node-major), columns = its unknowns.
ElementTransform elementTransform(const DofTransform& T, const mesh::Index* nodes, int n, int copy,
                                  const std::vector<GlobalIndex>& eq) {
  ElementTransform Te = ElementTransform::Zero(3 * n, Eigen::Index(eq.size()));
  for (int a = 0; a < n; ++a)
    for (int d = 0; d < 3; ++d)
      for (const auto& t : T.terms(nodes[a], d, copy)) {
        const auto col = std::lower_bound(eq.begin(), eq.end(), t.equation) - eq.begin();
        Te(3 * a + d, col) += t.coefficient;
      }
  return Te;
}

// The same as a scatter when every element DOF has at most one term: position
// among the element's unknowns (-1: fixed) and coefficient; `simple` false otherwise.
struct ElementScatter {
  std::array<int, kMaxElementDofs> position;
  std::array<double, kMaxElementDofs> coefficient;
  bool simple = true;
};
ElementScatter elementScatter(const DofTransform& T, const mesh::Index* nodes, int n, int copy,
                              const std::vector<GlobalIndex>& eq) {
  ElementScatter s;
  s.position.fill(-1);
  s.coefficient.fill(0.0);
  for (int a = 0; a < n && s.simple; ++a)
    for (int d = 0; d < 3; ++d) {
      const auto terms = T.terms(nodes[a], d, copy);
      if (terms.empty()) continue;
      if (terms.last - terms.first > 1) {
        s.simple = false;
        break;
      }
      s.position[3 * a + d] = int(std::lower_bound(eq.begin(), eq.end(), terms.first->equation) - eq.begin());
      s.coefficient[3 * a + d] = terms.first->coefficient;
    }
  return s;
}

}  // namespace

Assembler::Assembler(const mesh::Mesh& mesh, const DofMap& dofs, linalg::CommPtr comm)
    : Assembler(mesh, dofs.transform(), std::move(comm)) {}

Assembler::Assembler(const mesh::Mesh& mesh, DofTransform transform, linalg::CommPtr comm)
    : mesh_(mesh), transform_(std::move(transform)), impl_(std::make_unique<Impl>()) {
  auto& I = *impl_;
  I.comm = comm;
  const GlobalIndex n = transform_.numEquations();
  const int ranks = comm->getSize(), rank = comm->getRank();
  if (n == 0) throw InputError(mesh.source, "every degree of freedom is constrained: nothing to solve");
  if (transform_.numNodes() != mesh.numNodes())
    throw Error("Assembler: the DOF transform is for " + std::to_string(transform_.numNodes()) +
                " nodes, the mesh has " + std::to_string(mesh.numNodes()));

  // Contiguous ownership of equations.
  I.owned = Teuchos::rcp(new linalg::Map(n, 0, comm));
  const GlobalIndex first = I.owned->getMinGlobalIndex(), last = I.owned->getMaxGlobalIndex();
  auto ownedHere = [&](GlobalIndex g) { return g >= first && g <= last; };
  auto ownerOf = [&](GlobalIndex g) {  // same rule as Tpetra's uniform contiguous map
    const GlobalIndex base = n / ranks, extra = n % ranks;
    return g < extra * (base + 1) ? int(g / (base + 1)) : int(extra + (g - extra * (base + 1)) / base);
  };

  // Elements go to the rank owning their lowest unknown.
  std::set<GlobalIndex> shared;
  mesh::Index globalElement = 0;
  for (const auto& block : mesh.blocks) {
    const int nn = mesh::nodesPerElement(block.type);
    for (mesh::Index e = 0; e < block.numElements(); ++e, ++globalElement) {
      auto eq = elementEquations(transform_, block.element(e), nn);
      if (eq.empty() || ownerOf(eq.front()) != rank) continue;
      for (auto g : eq)
        if (!ownedHere(g)) shared.insert(g);
      I.elements.push_back(globalElement);
      I.equations.push_back(std::move(eq));
    }
  }

  // Owned rows first, then the shared ones (FECrsGraph's requirement).
  std::vector<GlobalIndex> overlap;
  overlap.reserve((last - first + 1) + shared.size());
  for (GlobalIndex g = first; g <= last; ++g) overlap.push_back(g);
  overlap.insert(overlap.end(), shared.begin(), shared.end());
  const auto invalid = Teuchos::OrdinalTraits<Tpetra::global_size_t>::invalid();
  I.ownedPlusShared = Teuchos::rcp(new linalg::Map(invalid, overlap.data(), overlap.size(), 0, comm));
  I.importer = Teuchos::rcp(new Tpetra::Import<>(I.owned, I.ownedPlusShared));

  // Exact row lengths from the element adjacency, so memory is not sized by the worst row.
  const std::size_t nLocal = overlap.size();
  std::vector<std::vector<GlobalIndex>> columns(nLocal);
  for (const auto& eq : I.equations)
    for (auto r : eq) {
      auto& row = columns[I.ownedPlusShared->getLocalElement(r)];
      row.insert(row.end(), eq.begin(), eq.end());
    }
  Kokkos::DualView<std::size_t*, FEGraph::device_type> counts("row counts", nLocal);
  for (std::size_t r = 0; r < nLocal; ++r) {
    auto& row = columns[r];
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    counts.h_view(r) = row.size();
  }
  counts.modify_host();
  counts.sync_device();
  Kokkos::DualView<const std::size_t*, FEGraph::device_type> constCounts = counts;
  auto graph = Teuchos::rcp(new FEGraph(I.owned, I.ownedPlusShared, constCounts, I.importer));
  graph->beginAssembly();
  for (std::size_t r = 0; r < nLocal; ++r)
    if (!columns[r].empty())
      graph->insertGlobalIndices(I.ownedPlusShared->getGlobalElement(r),
                                 Teuchos::ArrayView<const GlobalIndex>(columns[r]));
  graph->endAssembly();
  I.graph = graph;
}

Assembler::~Assembler() = default;

linalg::CommPtr Assembler::comm() const { return impl_->comm; }
Teuchos::RCP<const linalg::Map> Assembler::map() const { return impl_->owned; }
const std::vector<mesh::Index>& Assembler::localElements() const { return impl_->elements; }

ElementCoords Assembler::elementCoords(mesh::Index globalElement) const {
  auto [b, e] = mesh_.locateElement(globalElement);
  const auto& block = mesh_.blocks[b];
  const int nn = mesh::nodesPerElement(block.type);
  const mesh::Index* nodes = block.element(e);
  ElementCoords X(nn, 3);
  for (int a = 0; a < nn; ++a)
    for (int d = 0; d < 3; ++d) X(a, d) = mesh_.coords[nodes[a]][d];
  return X;
}

namespace {

// Runs a kernel on every local element with its element transforms; a kernel's
// geometry error becomes an input error naming the element.
template <class Kernel>
void forEachElement(const Assembler& A, const Assembler::Impl& I, Kernel&& kernel) {
  const auto& T = A.transform();
  for (std::size_t i = 0; i < I.elements.size(); ++i) {
    const auto e = I.elements[i];
    auto [b, local] = A.mesh().locateElement(e);
    const auto& block = A.mesh().blocks[b];
    const int nn = mesh::nodesPerElement(block.type);
    try {
      kernel(
          i, block.type, A.elementCoords(e),
          [&](int copy) { return elementTransform(T, block.element(local), nn, copy, I.equations[i]); },
          [&](int copy) { return elementScatter(T, block.element(local), nn, copy, I.equations[i]); });
    } catch (const InvalidElementGeometry& err) {
      throw InputError(A.mesh().source, A.mesh().elementName(e) + ": inverted or degenerate element (det J = " +
                                            std::to_string(err.detJ) + " at integration point " +
                                            std::to_string(err.point) + ")");
    }
  }
}

Teuchos::RCP<linalg::Matrix> assembleMatrix(const Assembler& A, const Assembler::Impl& I,
                                            const Assembler::ElementMatrixKernel& kernel) {
  auto matrix = Teuchos::rcp(new FEMatrix(I.graph));
  matrix->beginAssembly();
  std::vector<double> row;
  forEachElement(A, I, [&](std::size_t i, ElementType type, const ElementCoords& X, auto&& transformOf,
                           auto&& scatterOf) {
    const ElementMatrix Ke = kernel(I.elements[i], type, X);
    const auto& eq = I.equations[i];
    if (eq.size() > std::size_t(kMaxElementUnknowns)) throw Error("Assembler: an element with more than 120 unknowns");
    ReducedMatrix Kr = ReducedMatrix::Zero(Eigen::Index(eq.size()), Eigen::Index(eq.size()));
    for (int c = 0; c < A.transform().copies(); ++c) {
      // Most elements have at most one term per DOF (no right-face node): scatter.
      const auto& [pos, coef, simple] = scatterOf(c);
      if (simple) {
        for (int r = 0; r < Ke.rows(); ++r) {
          if (pos[r] < 0) continue;
          for (int q = 0; q < Ke.cols(); ++q)
            if (pos[q] >= 0) Kr(pos[r], pos[q]) += coef[r] * coef[q] * Ke(r, q);
        }
      } else {
        const ElementTransform Te = transformOf(c);
        Kr.noalias() += Te.transpose() * Ke * Te;
      }
    }
    row.resize(eq.size());
    for (std::size_t r = 0; r < eq.size(); ++r) {
      for (std::size_t c = 0; c < eq.size(); ++c) row[c] = Kr(r, c);
      matrix->sumIntoGlobalValues(eq[r], Teuchos::ArrayView<const GlobalIndex>(eq),
                                  Teuchos::ArrayView<const double>(row));
    }
  });
  matrix->endAssembly();
  return matrix;
}

Teuchos::RCP<linalg::MultiVector> assembleVectorImpl(const Assembler& A, const Assembler::Impl& I,
                                                     const Assembler::ElementVectorKernel& kernel) {
  auto vec = Teuchos::rcp(new FEVector(I.owned, I.importer, 1));
  vec->beginAssembly();
  forEachElement(A, I, [&](std::size_t i, ElementType type, const ElementCoords& X, auto&& transformOf, auto&&) {
    const ReducedVector fr = transformOf(0).transpose() * kernel(I.elements[i], type, X);  // loads act on copy 0
    const auto& eq = I.equations[i];
    for (std::size_t r = 0; r < eq.size(); ++r) vec->sumIntoGlobalValue(eq[r], 0, fr(r));
  });
  vec->endAssembly();
  // Hand out a plain owned MultiVector (an FEMultiVector cannot be copied or resized).
  auto out = Teuchos::rcp(new linalg::MultiVector(I.owned, 1));
  out->assign(*vec);
  return out;
}

}  // namespace

Teuchos::RCP<linalg::Matrix> Assembler::assemble(const ElementMatrixKernel& kernel) const {
  return assembleMatrix(*this, *impl_, kernel);
}

Teuchos::RCP<linalg::Matrix> Assembler::stiffness(const IsotropicElastic& material) const {
  return assemble([&](mesh::Index, ElementType t, const ElementCoords& X) { return elementStiffness(t, X, material); });
}

Teuchos::RCP<linalg::Matrix> Assembler::mass(const IsotropicElastic& material) const {
  return assemble([&](mesh::Index, ElementType t, const ElementCoords& X) {
    return elementMass(t, X, material.rho, material.massQuadrature);
  });
}

Teuchos::RCP<linalg::MultiVector> Assembler::assembleVector(const ElementVectorKernel& kernel) const {
  return assembleVectorImpl(*this, *impl_, kernel);
}

Teuchos::RCP<linalg::MultiVector> Assembler::centrifugalLoad(const IsotropicElastic& material, double omega,
                                                             const RotationAxis& axis) const {
  return assembleVector([&](mesh::Index, ElementType t, const ElementCoords& X) {
    return elementCentrifugalLoad(t, X, material.rho, omega, axis, material.massQuadrature);
  });
}

Teuchos::RCP<linalg::MultiVector> Assembler::bodyLoad(const Eigen::Vector3d& b) const {
  return assembleVector([&](mesh::Index, ElementType t, const ElementCoords& X) { return elementBodyLoad(t, X, b); });
}

Teuchos::RCP<linalg::MultiVector> Assembler::nodalLoad(const std::vector<mesh::Index>& nodes,
                                                       const Eigen::Vector3d& forcePerNode) const {
  // Every rank adds the terms it owns; T^T f for copy 0.
  auto out = Teuchos::rcp(new linalg::MultiVector(impl_->owned, 1));
  for (auto node : nodes)
    for (int d = 0; d < 3; ++d)
      for (const auto& t : transform_.terms(node, d, 0))
        if (impl_->owned->isNodeGlobalElement(t.equation))
          out->sumIntoGlobalValue(t.equation, 0, t.coefficient * forcePerNode[d]);
  return out;
}

Teuchos::RCP<linalg::MultiVector> Assembler::rigidBodyModes() const {
  // Each unknown takes the rigid motion's value at its master DOF (exact for plain
  // constraints; for cyclic transforms a near null space good enough for MueLu).
  // Six columns per copy: the rigid motions of the real part, then of the imaginary part.
  auto modes = Teuchos::rcp(new linalg::MultiVector(impl_->owned, 6 * transform_.copies()));
  const auto& master = transform_.masterDof();
  const auto& copyOf = transform_.masterCopy();
  for (std::size_t i = 0; i < impl_->owned->getNodeNumElements(); ++i) {
    const GlobalIndex g = impl_->owned->getGlobalElement(i);
    if (master[g] < 0) continue;
    const auto node = master[g] / 3;
    const int d = int(master[g] % 3);
    const auto& x = mesh_.coords[node];
    // Columns: translations x, y, z; rotations about x, y, z (u = e_k cross x).
    const double values[6][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1},
                                 {0, -x[2], x[1]}, {x[2], 0, -x[0]}, {-x[1], x[0], 0}};
    for (int k = 0; k < 6; ++k) modes->replaceLocalValue(i, 6 * copyOf[g] + k, values[k][d]);
  }
  return modes;
}

std::vector<std::array<double, 3>> Assembler::nodalField(const linalg::MultiVector& u, int column, int copy) const {
  // Replicate the unknowns on every rank, then expand through the transform.
  const GlobalIndex n = transform_.numEquations();
  std::vector<double> local(n, 0.0), global(n, 0.0);
  auto data = u.getData(column);
  for (std::size_t i = 0; i < impl_->owned->getNodeNumElements(); ++i) local[impl_->owned->getGlobalElement(i)] = data[i];
  Teuchos::reduceAll(*impl_->comm, Teuchos::REDUCE_SUM, int(n), local.data(), global.data());
  return transform_.nodalField(global.data(), copy);
}

}  // namespace cyclone::fe
