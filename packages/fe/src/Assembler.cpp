#include "cyclone/fe/Assembler.hpp"

#include <Tpetra_FECrsGraph.hpp>
#include <Tpetra_FECrsMatrix.hpp>
#include <Tpetra_FEMultiVector.hpp>
#include <Tpetra_Import.hpp>
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>
#include <Teuchos_CommHelpers.hpp>

#include <algorithm>
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
  std::vector<std::vector<GlobalIndex>> equations;  // per local element, -1 where constrained
};

namespace {

// Equations of an element's DOFs, node-major; -1 for constrained components.
std::vector<GlobalIndex> elementEquations(const DofMap& dofs, const mesh::Index* nodes, int n) {
  std::vector<GlobalIndex> eq(3 * n);
  for (int a = 0; a < n; ++a)
    for (int d = 0; d < 3; ++d) eq[3 * a + d] = dofs.equation(nodes[a], d);
  return eq;
}

std::string elementName(const mesh::Mesh& mesh, mesh::Index globalElement) {
  auto [b, e] = mesh.locateElement(globalElement);
  const auto& block = mesh.blocks[b];
  return "element " + std::to_string(block.elementIds.empty() ? e + 1 : block.elementIds[e]) + " (block '" +
         block.name + "')";
}

}  // namespace

Assembler::Assembler(const mesh::Mesh& mesh, const DofMap& dofs, linalg::CommPtr comm)
    : mesh_(mesh), dofs_(dofs), impl_(std::make_unique<Impl>()) {
  auto& I = *impl_;
  I.comm = comm;
  const GlobalIndex n = dofs.numFree();
  const int ranks = comm->getSize(), rank = comm->getRank();
  if (n == 0) throw InputError(mesh.source, "every degree of freedom is constrained: nothing to solve");

  // Contiguous ownership of equations.
  I.owned = Teuchos::rcp(new linalg::Map(n, 0, comm));
  const GlobalIndex first = I.owned->getMinGlobalIndex(), last = I.owned->getMaxGlobalIndex();
  auto ownedHere = [&](GlobalIndex g) { return g >= first && g <= last; };
  auto ownerOf = [&](GlobalIndex g) {  // same rule as Tpetra's uniform contiguous map
    const GlobalIndex base = n / ranks, extra = n % ranks;
    return g < extra * (base + 1) ? int(g / (base + 1)) : int(extra + (g - extra * (base + 1)) / base);
  };

  // Elements go to the rank owning their lowest free equation.
  std::set<GlobalIndex> shared;
  mesh::Index globalElement = 0;
  for (const auto& block : mesh.blocks) {
    const int nn = mesh::nodesPerElement(block.type);
    for (mesh::Index e = 0; e < block.numElements(); ++e, ++globalElement) {
      auto eq = elementEquations(dofs, block.element(e), nn);
      GlobalIndex lowest = -1;
      for (auto g : eq)
        if (g >= 0 && (lowest < 0 || g < lowest)) lowest = g;
      if (lowest < 0 || ownerOf(lowest) != rank) continue;
      for (auto g : eq)
        if (g >= 0 && !ownedHere(g)) shared.insert(g);
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
      if (r < 0) continue;
      auto& row = columns[I.ownedPlusShared->getLocalElement(r)];
      for (auto c : eq)
        if (c >= 0) row.push_back(c);
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

// Runs a kernel on every local element; a kernel's geometry error becomes an
// input error naming the element.
template <class Kernel>
void forEachElement(const Assembler& A, const std::vector<mesh::Index>& elements, Kernel&& kernel) {
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const auto e = elements[i];
    auto [b, local] = A.mesh().locateElement(e);
    try {
      kernel(i, A.mesh().blocks[b].type, A.elementCoords(e));
    } catch (const InvalidElementGeometry& err) {
      throw InputError(A.mesh().source, elementName(A.mesh(), e) + ": inverted or degenerate element (det J = " +
                                            std::to_string(err.detJ) + " at integration point " +
                                            std::to_string(err.point) + ")");
    }
  }
}

}  // namespace

static Teuchos::RCP<linalg::Matrix> assembleMatrix(
    const Assembler& A, const Assembler::Impl& I,
    const std::function<Eigen::MatrixXd(ElementType, const ElementCoords&)>& kernel) {
  auto matrix = Teuchos::rcp(new FEMatrix(I.graph));
  matrix->beginAssembly();
  std::vector<GlobalIndex> cols;
  std::vector<double> vals;
  forEachElement(A, I.elements, [&](std::size_t i, ElementType type, const ElementCoords& X) {
    const Eigen::MatrixXd Ke = kernel(type, X);
    const auto& eq = I.equations[i];
    for (std::size_t r = 0; r < eq.size(); ++r) {
      if (eq[r] < 0) continue;
      cols.clear();
      vals.clear();
      for (std::size_t c = 0; c < eq.size(); ++c)
        if (eq[c] >= 0) {
          cols.push_back(eq[c]);
          vals.push_back(Ke(r, c));
        }
      matrix->sumIntoGlobalValues(eq[r], Teuchos::ArrayView<const GlobalIndex>(cols),
                                  Teuchos::ArrayView<const double>(vals));
    }
  });
  matrix->endAssembly();
  return matrix;
}

static Teuchos::RCP<linalg::MultiVector> assembleVector(
    const Assembler& A, const Assembler::Impl& I,
    const std::function<Eigen::VectorXd(ElementType, const ElementCoords&)>& kernel) {
  auto vec = Teuchos::rcp(new FEVector(I.owned, I.importer, 1));
  vec->beginAssembly();
  forEachElement(A, I.elements, [&](std::size_t i, ElementType type, const ElementCoords& X) {
    const Eigen::VectorXd fe = kernel(type, X);
    const auto& eq = I.equations[i];
    for (std::size_t r = 0; r < eq.size(); ++r)
      if (eq[r] >= 0) vec->sumIntoGlobalValue(eq[r], 0, fe(r));
  });
  vec->endAssembly();
  // Hand out a plain owned MultiVector (an FEMultiVector cannot be copied or resized).
  auto out = Teuchos::rcp(new linalg::MultiVector(I.owned, 1));
  out->assign(*vec);
  return out;
}

Teuchos::RCP<linalg::Matrix> Assembler::stiffness(const IsotropicElastic& material) const {
  return assembleMatrix(*this, *impl_, [&](ElementType t, const ElementCoords& X) {
    return elementStiffness(t, X, material);
  });
}

Teuchos::RCP<linalg::Matrix> Assembler::mass(const IsotropicElastic& material) const {
  return assembleMatrix(*this, *impl_, [&](ElementType t, const ElementCoords& X) {
    return elementMass(t, X, material.rho);
  });
}

Teuchos::RCP<linalg::MultiVector> Assembler::centrifugalLoad(const IsotropicElastic& material, double omega,
                                                             const Axis& axis) const {
  return assembleVector(*this, *impl_, [&](ElementType t, const ElementCoords& X) {
    return elementCentrifugalLoad(t, X, material.rho, omega, axis);
  });
}

Teuchos::RCP<linalg::MultiVector> Assembler::bodyLoad(const Eigen::Vector3d& b) const {
  return assembleVector(*this, *impl_, [&](ElementType t, const ElementCoords& X) {
    return elementBodyLoad(t, X, b);
  });
}

Teuchos::RCP<linalg::MultiVector> Assembler::nodalLoad(const std::vector<mesh::Index>& nodes,
                                                       const Eigen::Vector3d& forcePerNode) const {
  auto out = Teuchos::rcp(new linalg::MultiVector(impl_->owned, 1));
  for (auto node : nodes)
    for (int d = 0; d < 3; ++d) {
      const GlobalIndex g = dofs_.equation(node, d);
      if (g >= 0 && impl_->owned->isNodeGlobalElement(g)) out->sumIntoGlobalValue(g, 0, forcePerNode[d]);
    }
  return out;
}

Teuchos::RCP<linalg::MultiVector> Assembler::rigidBodyModes() const {
  auto modes = Teuchos::rcp(new linalg::MultiVector(impl_->owned, 6));
  for (mesh::Index node = 0; node < mesh_.numNodes(); ++node) {
    const auto& x = mesh_.coords[node];
    // Columns: translations x, y, z; rotations about x, y, z (u = e_k cross x).
    const double values[6][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1},
                                 {0, -x[2], x[1]}, {x[2], 0, -x[0]}, {-x[1], x[0], 0}};
    for (int d = 0; d < 3; ++d) {
      const GlobalIndex g = dofs_.equation(node, d);
      if (g < 0 || !impl_->owned->isNodeGlobalElement(g)) continue;
      for (int k = 0; k < 6; ++k) modes->replaceGlobalValue(g, k, values[k][d]);
    }
  }
  return modes;
}

std::vector<std::array<double, 3>> Assembler::nodalField(const linalg::MultiVector& u, int column) const {
  // Every rank contributes its owned values; a sum over ranks replicates the field.
  const mesh::Index nn = mesh_.numNodes();
  std::vector<double> local(3 * nn, 0.0), global(3 * nn, 0.0);
  auto data = u.getData(column);
  for (mesh::Index node = 0; node < nn; ++node)
    for (int d = 0; d < 3; ++d) {
      const GlobalIndex g = dofs_.equation(node, d);
      if (g >= 0 && impl_->owned->isNodeGlobalElement(g)) local[3 * node + d] = data[impl_->owned->getLocalElement(g)];
    }
  Teuchos::reduceAll(*impl_->comm, Teuchos::REDUCE_SUM, int(3 * nn), local.data(), global.data());
  std::vector<std::array<double, 3>> field(nn);
  for (mesh::Index node = 0; node < nn; ++node) field[node] = {global[3 * node], global[3 * node + 1], global[3 * node + 2]};
  return field;
}

}  // namespace cyclone::fe
