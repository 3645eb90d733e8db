#pragma once
// A^T B of two multivectors as a small dense matrix on every rank (private header).
#include <Tpetra_Map.hpp>
#include <Tpetra_MultiVector.hpp>

#include <Eigen/Dense>

#include "cyclone/fe/LinearAlgebra.hpp"

namespace cyclone::rom {

inline Eigen::MatrixXd transposeProduct(const linalg::MultiVector& A, const linalg::MultiVector& B) {
  const auto local = Teuchos::rcp(
      new linalg::Map(Tpetra::global_size_t(A.getNumVectors()), 0, A.getMap()->getComm(), Tpetra::LocallyReplicated));
  linalg::MultiVector C(local, B.getNumVectors());
  C.multiply(Teuchos::TRANS, Teuchos::NO_TRANS, 1.0, A, B, 0.0);
  Eigen::MatrixXd out(Eigen::Index(A.getNumVectors()), Eigen::Index(B.getNumVectors()));
  for (std::size_t j = 0; j < B.getNumVectors(); ++j) {
    const auto c = C.getData(j);
    for (std::size_t i = 0; i < A.getNumVectors(); ++i) out(Eigen::Index(i), Eigen::Index(j)) = c[i];
  }
  return out;
}

}  // namespace cyclone::rom
