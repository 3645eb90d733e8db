#include "cyclone/hbm/JacobianBlocks.hpp"

#include <cmath>

#include "cyclone/core/Error.hpp"
#include "cyclone/hbm/HarmonicBalanceSystem.hpp"

namespace cyclone::hbm {

namespace {

// The coefficient slots of harmonic index i: {cos} for the mean, {cos, sin} otherwise.
std::vector<int> slotsOf(const HarmonicSet& H, std::size_t i) {
  const int h = H.harmonics()[i];
  if (h == 0) return {H.cosIndex(0)};
  return {H.cosIndex(h), H.sinIndex(h)};
}

}  // namespace

namespace {

// A harmonic's (cos, sin) block [[re, im], [-im, re]] per DOF pair is the complex A =
// re + i im acting on c - i s: held so it is half the memory a GMRES product streams
// through (the linear part of the matrix and dynamic-stiffness forms always is).
bool complexStructured(const Eigen::MatrixXd& P, Eigen::MatrixXcd& A) {
  const Eigen::Index n = P.rows() / 2;
  A.resize(n, n);
  const double tolerance = 1e-13 * P.cwiseAbs().maxCoeff();
  for (Eigen::Index b = 0; b < n; ++b)
    for (Eigen::Index a = 0; a < n; ++a) {
      const double re = P(2 * a, 2 * b), im = P(2 * a, 2 * b + 1);
      if (std::abs(P(2 * a + 1, 2 * b + 1) - re) > tolerance || std::abs(P(2 * a + 1, 2 * b) + im) > tolerance) {
        A.resize(0, 0);
        return false;
      }
      A(a, b) = {re, im};
    }
  return true;
}

}  // namespace

JacobianBlocks::JacobianBlocks(const HarmonicBalanceSystem& system, double omega, std::vector<ElementBlock> elements)
    : system_(system), omega_(omega), elements_(std::move(elements)) {
  const auto& H = system_.aft().harmonics();
  woodbury_ = system_.modalStiffnessBlocks(omega_);
  for (std::size_t i = 0; i < H.harmonics().size(); ++i) {
    slots_.push_back(slotsOf(H, i));
    if (woodbury_ && woodbury_->covers(i)) {
      linear_.emplace_back(), linearComplex_.emplace_back();
      continue;
    }
    Eigen::MatrixXd block = system_.linearHarmonicBlock(omega_, i);
    Eigen::MatrixXcd complexBlock;
    if (slots_.back().size() == 2 && complexStructured(block, complexBlock)) block.resize(0, 0);
    linear_.push_back(std::move(block));
    linearComplex_.push_back(std::move(complexBlock));
  }
  sparseElements_.resize(elements_.size());
  for (std::size_t e = 0; e < elements_.size(); ++e) {
    const Eigen::MatrixXd& J = elements_[e].jacobian;
    if (elements_[e].linearization) continue;
    const Eigen::Index nonzeros = (J.array() != 0).count();
    if (nonzeros * 4 < J.size()) sparseElements_[e] = J.sparseView(0.0, 0.0);
  }
}

int JacobianBlocks::size() const { return system_.numUnknowns(); }

int JacobianBlocks::sparseElements() const {
  int count = 0;
  for (const auto& e : sparseElements_) count += e.size() != 0;
  return count;
}

void JacobianBlocks::scaleRows(Eigen::VectorXd s) {
  if (s.size() != size()) throw Error("JacobianBlocks: a row scale of the wrong size");
  rowScale_ = std::move(s);
  blockLu_.clear();  // blended rows' shifts are factored in over the row scale
}

void JacobianBlocks::blendRows(const std::vector<int>& rows, double scale, double shift) {
  for (int i : rows)
    if (i < 0 || i >= size()) throw Error("JacobianBlocks: a blended row out of range");
  blendedRows_ = rows, blendScale_ = scale, blendShift_ = shift;
  blockLu_.clear();
}

// J v = Z v + sum_e B_e Jf_e A_e v, A_e v the element's coordinates' coefficients
// (Xm W + S Xm W_next on the nc x n matrix of the DOFs' coefficients) and B_e its
// forces carried back (F W^T + S^T F W_next^T), as HarmonicBalanceSystem's residual.
void JacobianBlocks::apply(const Eigen::VectorXd& v, Eigen::VectorXd& y) const {
  const int n = system_.numDofs(), nc = system_.numCoefficients();
  y.resize(v.size());
  if (woodbury_) {  // the covered harmonics together, X = c - i s as columns
    woodburyIn_.setZero(n, Eigen::Index(slots_.size()));
    woodburyOut_.resize(n, Eigen::Index(slots_.size()));
    for (std::size_t i = 0; i < slots_.size(); ++i) {
      if (!woodbury_->covers(i)) continue;
      const std::vector<int>& slots = slots_[i];
      for (int a = 0; a < n; ++a) woodburyIn_(a, Eigen::Index(i)) = {v(a * nc + slots[0]), -v(a * nc + slots[1])};
    }
    woodbury_->apply(woodburyIn_, woodburyOut_);
    for (std::size_t i = 0; i < slots_.size(); ++i) {
      if (!woodbury_->covers(i)) continue;
      const std::vector<int>& slots = slots_[i];
      for (int a = 0; a < n; ++a)
        y(a * nc + slots[0]) = woodburyOut_(a, Eigen::Index(i)).real(), y(a * nc + slots[1]) = -woodburyOut_(a, Eigen::Index(i)).imag();
    }
  }
  for (std::size_t i = 0; i < slots_.size(); ++i) {
    if (woodbury_ && woodbury_->covers(i)) continue;
    if (linearComplex_[i].size() != 0) {  // X = c - i s, Y = A X: y_c = Re Y, y_s = -Im Y
      const std::vector<int>& slots = slots_[i];
      complexIn_.resize(n);
      for (int a = 0; a < n; ++a) complexIn_(a) = {v(a * nc + slots[0]), -v(a * nc + slots[1])};
      complexOut_.noalias() = linearComplex_[i] * complexIn_;
      for (int a = 0; a < n; ++a) y(a * nc + slots[0]) = complexOut_(a).real(), y(a * nc + slots[1]) = -complexOut_(a).imag();
      continue;
    }
    const int w = width(i);
    gather(i, v, gathered_[w]);
    solved_[w].noalias() = linear_[i] * gathered_[w];
    scatter(i, solved_[w], y);
  }
  const Eigen::Map<const Eigen::MatrixXd> Vm(v.data(), nc, n);
  Eigen::Map<Eigen::MatrixXd> Ym(y.data(), nc, n);
  const Eigen::MatrixXd& S = system_.nextSectorMap();
  const auto& connections = system_.elements();
  Eigen::MatrixXd &w = w_, &wNext = wNext_, &f = f_;
  for (std::size_t ei = 0; ei < elements_.size(); ++ei) {
    const ElementBlock& e = elements_[ei];
    const auto& c = connections[e.element];
    const int d = c.element->dimension();
    const bool across = c.Wnext.size() != 0;
    w.setZero(nc, d);
    if (across) wNext.setZero(nc, d);
    for (int b : e.support) {
      for (int k = 0; k < d; ++k) {
        if (c.W(b, k) != 0) w.col(k) += c.W(b, k) * Vm.col(b);
        if (across && c.Wnext(b, k) != 0) wNext.col(k) += c.Wnext(b, k) * Vm.col(b);
      }
    }
    if (across) w.noalias() += S * wNext;
    f.resize(nc, d);
    if (e.linearization)
      e.linearization->apply(w, f);
    else if (sparseElements_[ei].size() != 0)
      Eigen::Map<Eigen::VectorXd>(f.data(), nc * d).noalias() =
          sparseElements_[ei] * Eigen::Map<const Eigen::VectorXd>(w.data(), nc * d);
    else
      Eigen::Map<Eigen::VectorXd>(f.data(), nc * d).noalias() =
          e.jacobian * Eigen::Map<const Eigen::VectorXd>(w.data(), nc * d);
    if (across) wNext.noalias() = S.transpose() * f;
    for (int a : e.support)
      for (int k = 0; k < d; ++k) {
        if (c.W(a, k) != 0) Ym.col(a) += c.W(a, k) * f.col(k);
        if (across && c.Wnext(a, k) != 0) Ym.col(a) += c.Wnext(a, k) * wNext.col(k);
      }
  }
  if (rowScale_.size() != 0) y.array() *= rowScale_.array();
  for (int i : blendedRows_) y(i) = blendScale_ * y(i) + blendShift_ * v(i);
}

// Harmonic index i's block: the linear part's plus, per element, E^T Jf_hh E with
// E (d m x |support| m) the map of the support DOFs' harmonic-h coefficients to the
// element's (block (k, b) = W(b, k) I + W_next(b, k) S_h), its transpose carrying the
// forces back (S_h^T for W_next).
Eigen::MatrixXd JacobianBlocks::harmonicBlock(std::size_t i) const {
  const std::vector<int>& slots = slots_[i];
  const int m = int(slots.size()), nc = system_.numCoefficients();
  // A harmonic the products apply in Woodbury's parts: its block as the system forms it
  // (its residual at this frequency has formed them already).
  const bool covered = woodbury_ && woodbury_->covers(i);
  Eigen::MatrixXd P = covered ? system_.linearHarmonicBlock(omega_, i) : linear_[i];
  if (!covered && linearComplex_[i].size() != 0) {
    const Eigen::MatrixXcd& A = linearComplex_[i];
    P.resize(2 * A.rows(), 2 * A.cols());
    for (Eigen::Index b = 0; b < A.cols(); ++b)
      for (Eigen::Index a = 0; a < A.rows(); ++a) {
        const double re = A(a, b).real(), im = A(a, b).imag();
        P(2 * a, 2 * b) = re, P(2 * a, 2 * b + 1) = im, P(2 * a + 1, 2 * b) = -im, P(2 * a + 1, 2 * b + 1) = re;
      }
  }
  const Eigen::MatrixXd& Sfull = system_.nextSectorMap();
  Eigen::MatrixXd S(m, m);
  for (int r = 0; r < m; ++r)
    for (int q = 0; q < m; ++q) S(r, q) = Sfull(slots[r], slots[q]);
  const auto& connections = system_.elements();
  for (const ElementBlock& e : elements_) {
    const auto& c = connections[e.element];
    const int d = c.element->dimension();
    const bool across = c.Wnext.size() != 0;
    const int ns = int(e.support.size());
    Eigen::MatrixXd Jhh(d * m, d * m), E = Eigen::MatrixXd::Zero(d * m, ns * m);
    if (e.linearization)
      Jhh = e.linearization->harmonicBlock(slots);
    else
      for (int k = 0; k < d; ++k)
        for (int l = 0; l < d; ++l)
          for (int r = 0; r < m; ++r)
            for (int q = 0; q < m; ++q) Jhh(k * m + r, l * m + q) = e.jacobian(k * nc + slots[r], l * nc + slots[q]);
    for (int bi = 0; bi < ns; ++bi) {
      const int b = e.support[bi];
      for (int k = 0; k < d; ++k) {
        auto block = E.block(k * m, bi * m, m, m);
        if (c.W(b, k) != 0) block.diagonal().array() += c.W(b, k);
        if (across && c.Wnext(b, k) != 0) block += c.Wnext(b, k) * S;
      }
    }
    // The forces' map back: W(a, k) I + W_next(a, k) S^T, i.e. E^T.
    const Eigen::MatrixXd local = E.transpose() * Jhh * E;
    for (int ai = 0; ai < ns; ++ai)
      for (int bi = 0; bi < ns; ++bi)
        P.block(e.support[ai] * m, e.support[bi] * m, m, m) += local.block(ai * m, bi * m, m, m);
  }
  return P;
}

// The blocks are factored without the row scale (precondition divides it out first); a
// blended row i of diag(s) J, b s_i J_i + shift e_i, is s_i (b J_i + shift / s_i e_i) there.
void JacobianBlocks::factorPreconditioner() {
  const int nc = system_.numCoefficients();
  std::vector<std::vector<int>> blended(slots_.size());  // per harmonic index: local rows
  if (!blendedRows_.empty()) {
    for (std::size_t i = 0; i < slots_.size(); ++i)
      for (int g : blendedRows_) {
        const int a = g / nc, slot = g % nc;
        for (std::size_t j = 0; j < slots_[i].size(); ++j)
          if (slots_[i][j] == slot) blended[i].push_back(a * int(slots_[i].size()) + int(j));
      }
  }
  blockLu_.clear();
  blockLu_.reserve(slots_.size());
  for (std::size_t i = 0; i < slots_.size(); ++i) {
    Eigen::MatrixXd P = harmonicBlock(i);
    for (int local : blended[i]) {
      const int m = int(slots_[i].size());
      const int g = (local / m) * nc + slots_[i][std::size_t(local % m)];
      const double s = rowScale_.size() != 0 ? rowScale_(g) : 1.0;
      P.row(local) *= blendScale_;
      P(local, local) += blendShift_ / s;
    }
    blockLu_.emplace_back(P.cast<float>());
  }
}

// The rows' scale s makes the matrix diag(s) J, so its block diagonal's inverse takes
// r / s first.
void JacobianBlocks::precondition(const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
  if (blockLu_.empty()) throw Error("JacobianBlocks: precondition() before factorPreconditioner()");
  z.resize(r.size());
  if (rowScale_.size() != 0) {
    unscaled_ = r.cwiseQuotient(rowScale_);
    for (std::size_t i = 0; i < slots_.size(); ++i) {
      gather(i, unscaled_, gathered_[width(i)]);
      solveBlock(i);
      scatter(i, solved_[width(i)], z);
    }
    return;
  }
  for (std::size_t i = 0; i < slots_.size(); ++i) {
    gather(i, r, gathered_[width(i)]);
    solveBlock(i);
    scatter(i, solved_[width(i)], z);
  }
}

// solved_ = P_i^-1 gathered_ (of the block's width) by the single-precision factors: a
// preconditioner needs no more digits (GMRES measures its residual on the true
// operator), and the factors are half the memory each product streams through.
void JacobianBlocks::solveBlock(std::size_t i) const {
  const int w = width(i);
  gatheredSingle_[w] = gathered_[w].cast<float>();
  solvedSingle_[w] = blockLu_[i].solve(gatheredSingle_[w]);
  solved_[w] = solvedSingle_[w].cast<double>();
}

// Harmonic index i's coefficients of every DOF (local index a m + j), and back.
void JacobianBlocks::gather(std::size_t i, const Eigen::VectorXd& v, Eigen::VectorXd& local) const {
  const int n = system_.numDofs(), nc = system_.numCoefficients();
  const std::vector<int>& slots = slots_[i];
  const int m = int(slots.size());
  local.resize(n * m);
  for (int a = 0; a < n; ++a)
    for (int j = 0; j < m; ++j) local(a * m + j) = v(a * nc + slots[j]);
}

void JacobianBlocks::scatter(std::size_t i, const Eigen::VectorXd& local, Eigen::VectorXd& v) const {
  const int n = system_.numDofs(), nc = system_.numCoefficients();
  const std::vector<int>& slots = slots_[i];
  const int m = int(slots.size());
  for (int a = 0; a < n; ++a)
    for (int j = 0; j < m; ++j) v(a * nc + slots[j]) = local(a * m + j);
}

Eigen::MatrixXd JacobianBlocks::dense() const {
  const int N = size();
  Eigen::MatrixXd J(N, N);
  Eigen::VectorXd e = Eigen::VectorXd::Zero(N), y;
  for (int j = 0; j < N; ++j) {
    e(j) = 1;
    apply(e, y);
    J.col(j) = y;
    e(j) = 0;
  }
  return J;
}

}  // namespace cyclone::hbm
