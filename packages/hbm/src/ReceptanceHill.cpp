// Hill's method on a receptance model. A perturbation e^{lambda t} p(t) is
// expanded on exponentials e^{i k w t}, k = +-h for every harmonic h of the set
// (block (h, +) and (h, -); one block for h = 0), so that each block is a
// plain frequency s = lambda + i k w of one phase's linear model:
//   dX_b = R_b G_b + U_b q_b,   (l + c s + s^2) q_b = V_b^T G_b,   G = -J dX,
// J the harmonic balance Jacobian of the element forces in this basis, R_b, U_b,
// V_b the modal realization of the block's phase (its conjugate for k < 0: the
// system is real). Eliminating dX = (I + R J)^{-1} U q leaves the quadratic
// eigenproblem in the modal coordinates
//   [lambda^2 + lambda (c + 2 i k w) + (l + i c k w - (k w)^2) + V^T J (I + R J)^{-1} U] q = 0,
// whose matrix at lambda = 0 is singular exactly when the harmonic balance
// Jacobian is (the determinant lemma): folds are where the curve turns.
//
// Which eigenvalues are the Floquet exponents: those in the strip
// |Im lambda| <= w / 2. Near lambda = 0 Hill's linearisation holds and a fold
// (a real exponent through 0) is exact (the determinant lemma); period
// doubling sits on the strip's edge. Far out it does not hold for a hysteretic
// element (friction): the harmonic balance Jacobian is the element's response
// to periodic perturbations, not to e^{lambda t} p(t) far off the harmonics. A
// cyclic test (test_receptance_form) has eigenvalues with Re > 0 at |Im| near
// 2.4 w, steady in H, on a solution to which a time integration of the
// perturbed full ring returns, and the default disc's friction-damped curve
// has them at |Im| of 2 to 7 w. The matrix form's pick (the 2 n of smallest
// |Im|) leans on every block holding the same system; in a cyclic system
// harmonic h lives on nodal diameter h EO, an exponent has no shifted copies
// there, and that pick would take such far eigenvalues. A strip with no
// eigenvalue in it (the linear stuck disc far below its resonance) leaves no
// exponent that could grow: stable.
#include "ReceptanceHill.hpp"

#include "EigenvaluesNearZero.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/Sparse>
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <map>
#include <vector>
#include <string>

#include "cyclone/core/Error.hpp"

#include <Teuchos_LAPACK.hpp>

// LAPACK's complex eigenvalue driver (the reference LAPACK interface; OpenBLAS provides it).
extern "C" void zgeev_(const char* jobvl, const char* jobvr, const int* n, std::complex<double>* a, const int* lda,
                       std::complex<double>* w, std::complex<double>* vl, const int* ldvl, std::complex<double>* vr,
                       const int* ldvr, std::complex<double>* work, const int* lwork, double* rwork, int* info);

extern "C" void zgetrf_(const int* m, const int* n, std::complex<double>* a, const int* lda, int* ipiv, int* info);
extern "C" void zgetrs_(const char* trans, const int* n, const int* nrhs, const std::complex<double>* a, const int* lda,
                        const int* ipiv, std::complex<double>* b, const int* ldb, int* info);

namespace cyclone::hbm {

namespace {
using cd = std::complex<double>;

struct Block {
  int h = 0, sign = 1;      // exponent k = sign h
  int first = 0, size = 0;  // its modal coordinates
};

// The exponent blocks of the harmonic set (h = 0 once, then +h and -h) and, per DOF,
// the map y = t x from real coefficients to exponent-block values, x = ti y.
std::vector<Block> exponentBlocks(const HarmonicSet& H, Eigen::MatrixXcd& t, Eigen::MatrixXcd& ti) {
  const int nc = H.numCoefficients();
  std::vector<Block> blocks;
  t = Eigen::MatrixXcd::Zero(nc, nc), ti = Eigen::MatrixXcd::Zero(nc, nc);
  for (int h : H.harmonics()) {
    const int b = int(blocks.size());
    if (h == 0) {
      blocks.push_back({0, 1});
      t(b, H.cosIndex(0)) = 1, ti(H.cosIndex(0), b) = 1;
      continue;
    }
    blocks.push_back({h, 1});
    blocks.push_back({h, -1});
    const int c = H.cosIndex(h), s = H.sinIndex(h);
    // c cos + s sin = (c - i s)/2 e^{i h w t} + (c + i s)/2 e^{-i h w t}.
    t(b, c) = 0.5, t(b, s) = cd(0, -0.5), t(b + 1, c) = 0.5, t(b + 1, s) = cd(0, 0.5);
    ti(c, b) = 1, ti(c, b + 1) = 1, ti(s, b) = cd(0, 1), ti(s, b + 1) = cd(0, -1);
  }
  return blocks;
}

// The element Jacobian, sparse (an element couples only its own DOFs).
Eigen::SparseMatrix<double> elementJacobian(const HarmonicBalanceSystem& sys, const Eigen::VectorXd& X, double omega) {
  const int m = sys.numUnknowns();
  Eigen::VectorXd F;
  Eigen::MatrixXd Jr;
  sys.nonlinearForces(X, omega, F, &Jr);
  std::vector<Eigen::Triplet<double>> entries;
  for (int r = 0; r < m; ++r)
    for (int c = 0; c < m; ++c)
      if (Jr(r, c) != 0) entries.emplace_back(r, c, Jr(r, c));
  Eigen::SparseMatrix<double> J(m, m);
  J.setFromTriplets(entries.begin(), entries.end());
  return J;
}

// The realization of every block (conjugated for k < 0: the system is real); sets the
// blocks' modal coordinates and returns their count.
int blockRealizations(const HarmonicBalanceSystem& sys, std::vector<Block>& blocks, std::vector<ModalRealization>& real) {
  const int n = sys.numDofs();
  const ReceptanceModel& model = *sys.receptance();
  std::map<long, ModalRealization> byPhase;
  int mt = 0;
  real.assign(blocks.size(), {});
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const long p = sys.phaseIndex(blocks[b].h);
    auto it = byPhase.find(p);
    if (it == byPhase.end()) {
      auto r = model.modalRealization(p);
      if (!r)
        throw InputError("stability", "the reduced model of nodal diameter " + std::to_string(sys.nodalDiameter(blocks[b].h)) +
                                          " has no modal form (Hill's method needs one)");
      if (r->R.rows() != n || r->U.rows() != n || r->V.rows() != n || r->U.cols() != r->numModes() ||
          r->V.cols() != r->numModes() || (r->viscous.size() != 0 && r->viscous.size() != r->numModes()))
        throw Error("modal realization of phase " + std::to_string(p) + " has inconsistent sizes");
      it = byPhase.emplace(p, std::move(*r)).first;
    }
    real[b] = it->second;
    if (blocks[b].sign < 0) {
      real[b].R = real[b].R.conjugate();
      real[b].U = real[b].U.conjugate();
      real[b].V = real[b].V.conjugate();
    }
    blocks[b].first = mt, blocks[b].size = real[b].numModes();
    mt += blocks[b].size;
  }
  if (mt == 0) throw InputError("stability", "the reduced model has no modes: no Floquet exponents");
  return mt;
}

// The modal parts in time scaled by w (lambda = w mu, l -> l / w^2, c -> c / w): the
// stacked U and V (block b's rows at b n), the constant parts R per block, and the
// quadratic's coefficients per modal coordinate, d0 = l + i c k - k^2 and d1 = c + 2 i k.
struct ModalTerms {
  Eigen::MatrixXcd U, V;
  std::vector<Eigen::MatrixXcd> R;
  Eigen::VectorXcd d0, d1;
};
ModalTerms modalTerms(const std::vector<Block>& blocks, const std::vector<ModalRealization>& real, int n, int mt,
                      double omega) {
  const int nb = int(blocks.size());
  ModalTerms out{Eigen::MatrixXcd::Zero(nb * n, mt), Eigen::MatrixXcd::Zero(nb * n, mt), std::vector<Eigen::MatrixXcd>(nb),
                 Eigen::VectorXcd(mt), Eigen::VectorXcd(mt)};
  for (int b = 0; b < nb; ++b) {
    const auto& r = real[b];
    const auto& blk = blocks[b];
    const double eta = r.lossFactor;
    const cd rfac = blk.h == 0 ? cd(1) : 1.0 / cd(1, blk.sign * eta);
    out.R[b] = rfac * r.R;
    out.U.block(b * n, blk.first, n, blk.size) = r.U;
    out.V.block(b * n, blk.first, n, blk.size) = r.V;
    const double k = blk.sign * blk.h;  // in units of w
    for (int j = 0; j < blk.size; ++j) {
      const double l = r.eigenvalues(j) / (omega * omega);
      double c = r.viscous.size() ? r.viscous(j) / omega : 0.0;
      c += blk.h > 0 ? eta * l / blk.h : eta * std::sqrt(std::max(l, 0.0));
      out.d0(blk.first + j) = cd(l - k * k, c * k);
      out.d1(blk.first + j) = cd(c, 2 * k);
    }
  }
  return out;
}

// V^T J_exp (I + R_exp J_exp)^{-1} U in scaled time. With T the per-DOF map y = t x to
// the exponent basis, R_exp = T R T^-1 is real (the blocks +h and -h are conjugate),
// and the product equals (V^T T) J (I + R J)^{-1} (T^{-1} U): U and V enter in the
// real coefficients (Ui = T^-1 U, Vi = T^T V), and the one large LU is real.
Eigen::MatrixXcd elementTerm(const ModalTerms& mt, const std::vector<Block>& blocks, const Eigen::SparseMatrix<double>& J,
                             const Eigen::MatrixXcd& t, const Eigen::MatrixXcd& ti, int n, double omega) {
  const int nb = int(mt.R.size()), nc = nb, m = n * nc, cols = int(mt.U.cols());
  // Rreal's block (a, c) is Re(ti diag(R_b(a, c)) t), summed over the few nonzeros of
  // ti's column b and t's row b (a harmonic's cos and sin), not by dense products.
  struct Entry {
    int index;
    cd value;
  };
  std::vector<std::vector<Entry>> tiColumn(nb), tRow(nb);
  for (int b = 0; b < nb; ++b)
    for (int i = 0; i < nc; ++i) {
      if (ti(i, b) != cd(0)) tiColumn[b].push_back({i, ti(i, b)});
      if (t(b, i) != cd(0)) tRow[b].push_back({i, t(b, i)});
    }
  Eigen::MatrixXd Rreal = Eigen::MatrixXd::Zero(m, m);  // interleaved like X: DOF a, slot i at a nc + i
  for (int c = 0; c < n; ++c)
    for (int a = 0; a < n; ++a)
      for (int b = 0; b < nb; ++b) {
        const cd d = mt.R[b](a, c);
        for (const Entry& left : tiColumn[b])
          for (const Entry& right : tRow[b]) Rreal(a * nc + left.index, c * nc + right.index) += (left.value * d * right.value).real();
      }
  Eigen::MatrixXd IRJ = Rreal * J;
  IRJ.diagonal().array() += 1.0;
  // LAPACK's LU and one solve for the real and imaginary parts of every column at once
  // (dgetrs: BLAS 3), not Eigen's PartialPivLU and its solve: at H = 6 on the default
  // disc (m = 1716, 260 modal coordinates) Eigen's two were a third of Hill's time.
  const Teuchos::LAPACK<int, double> lapack;
  std::vector<int> pivots(static_cast<std::size_t>(std::max(m, 1)));
  int info = 0;
  lapack.GETRF(m, m, IRJ.data(), std::max(m, 1), pivots.data(), &info);
  if (info != 0) throw Error("Hill's method: I + R J is singular (dgetrf info " + std::to_string(info) + ")");
  Eigen::MatrixXcd Ui(m, cols), Vi(m, cols), rows(nb, cols);
  for (int a = 0; a < n; ++a) {
    for (int b = 0; b < nb; ++b) rows.row(b) = mt.U.row(b * n + a);
    Ui.middleRows(a * nc, nc) = ti * rows;
    for (int b = 0; b < nb; ++b) rows.row(b) = mt.V.row(b * n + a);
    Vi.middleRows(a * nc, nc) = t.transpose() * rows;
  }
  // The blocks -h are the conjugates of the blocks +h (the system is real): their columns
  // of Ui, and so of (I + R J)^{-1} Ui, are the conjugates of the +h ones, and only the
  // +h and h = 0 columns ("kept") are solved for and multiplied.
  std::vector<int> kept, partner(static_cast<std::size_t>(cols), -1);  // partner: -h column -> its +h column
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    if (blocks[b].sign > 0)
      for (int j = 0; j < blocks[b].size; ++j) kept.push_back(blocks[b].first + j);
    else
      for (std::size_t q = 0; q < blocks.size(); ++q)
        if (blocks[q].h == blocks[b].h && blocks[q].sign > 0)
          for (int j = 0; j < blocks[b].size; ++j) partner[std::size_t(blocks[b].first + j)] = blocks[q].first + j;
  }
  const int nk = int(kept.size());
  Eigen::MatrixXd parts(m, 2 * nk);  // [Re Ui, Im Ui] of the kept columns, overwritten by (I + R J)^{-1} of them
  for (int k = 0; k < nk; ++k) parts.col(k) = Ui.col(kept[k]).real(), parts.col(nk + k) = Ui.col(kept[k]).imag();
  lapack.GETRS('N', m, 2 * nk, IRJ.data(), std::max(m, 1), pivots.data(), parts.data(), std::max(m, 1), &info);
  if (info != 0) throw Error("Hill's method: dgetrs info " + std::to_string(info));
  Eigen::MatrixXcd JS(m, nk);  // J (I + R J)^{-1} Ui, kept columns
  JS.real() = J * parts.leftCols(nk);
  JS.imag() = J * parts.rightCols(nk);
  // Vi is nonzero only in the slots (cos, sin) of a column's own harmonic: E's rows of a
  // block are its slots' rows of Vi against those of J S (2 n rows, not m). In scaled
  // time J is divided by w^2, like l.
  Eigen::MatrixXcd Ekept(cols, nk);
  std::vector<int> zeroRows;
  Eigen::MatrixXcd zeroPart;  // rows h = 0, columns the kept ones' conjugates (the -h columns)
  for (int b = 0; b < nb; ++b) {
    const Block& blk = blocks[std::size_t(b)];
    const int ns = int(tRow[std::size_t(b)].size());
    Eigen::MatrixXcd Vb(n * ns, blk.size), JSb(n * ns, nk);
    for (int a = 0; a < n; ++a)
      for (int si = 0; si < ns; ++si) {
        const int row = a * nc + tRow[std::size_t(b)][std::size_t(si)].index;
        Vb.row(a * ns + si) = Vi.row(row).segment(blk.first, blk.size);
        JSb.row(a * ns + si) = JS.row(row);
      }
    Ekept.middleRows(blk.first, blk.size) = Vb.transpose() * JSb / (omega * omega);
    if (blk.h == 0) {
      for (int j = 0; j < blk.size; ++j) zeroRows.push_back(blk.first + j);
      zeroPart = Vb.transpose() * JSb.conjugate() / (omega * omega);
    }
  }
  Eigen::MatrixXcd E(cols, cols);
  for (int k = 0; k < nk; ++k) E.col(kept[k]) = Ekept.col(k);
  // A -h column: E(r, c-) = conj(conj(Vi_r)^T J S_c+), and conj(Vi_r) is the column of
  // r's partner where r is in a +-h block; rows of the h = 0 block directly.
  std::vector<int> keptIndex(static_cast<std::size_t>(cols), -1), rowPartner(static_cast<std::size_t>(cols), -1);
  for (int k = 0; k < nk; ++k) keptIndex[std::size_t(kept[k])] = k;
  for (int c = 0; c < cols; ++c)
    if (partner[std::size_t(c)] >= 0) rowPartner[std::size_t(c)] = partner[std::size_t(c)], rowPartner[std::size_t(partner[std::size_t(c)])] = c;
  for (int c = 0; c < cols; ++c) {
    const int from = partner[std::size_t(c)];
    if (from < 0) continue;
    const int k = keptIndex[std::size_t(from)];
    for (int r = 0; r < cols; ++r)
      if (rowPartner[std::size_t(r)] >= 0) E(r, c) = std::conj(Ekept(rowPartner[std::size_t(r)], k));
    for (std::size_t i = 0; i < zeroRows.size(); ++i) E(zeroRows[i], c) = zeroPart(Eigen::Index(i), k);
  }
  return E;
}

// The eigenvalues of a dense complex matrix by LAPACK's zgeev (no vectors): 4-5 times
// Eigen's ComplexEigenSolver at the sizes Hill's method meets (120 at H = 1 on the
// default disc), where the eigen-solution was most of a stability computation.
Eigen::VectorXcd eigenvaluesOf(Eigen::MatrixXcd A) {
  const int n = int(A.rows()), ld = std::max(n, 1), one = 1;
  Eigen::VectorXcd w(n);
  cd vl[1], vr[1], query;
  int info = 0, lwork = -1;
  std::vector<double> rwork(static_cast<std::size_t>(2 * ld));
  zgeev_("N", "N", &n, A.data(), &ld, w.data(), vl, &one, vr, &one, &query, &lwork, rwork.data(), &info);
  lwork = std::max(int(query.real()), 2 * ld);
  std::vector<cd> work(static_cast<std::size_t>(lwork));
  zgeev_("N", "N", &n, A.data(), &ld, w.data(), vl, &one, vr, &one, work.data(), &lwork, rwork.data(), &info);
  if (info != 0) throw Error("Hill's method: the eigen-solution did not converge (zgeev info " + std::to_string(info) + ")");
  return w;
}

// The Floquet exponents among Hill's eigenvalues mu (times w): those in the strip
// |Im| <= w / 2, by decreasing real part.
FloquetExponents pickExponents(Eigen::VectorXcd all, double omega, double covered) {
  FloquetExponents out;
  out.all = std::move(all);
  out.covered = covered;
  std::vector<cd> kept;
  for (int e = 0; e < out.all.size(); ++e)
    if (std::abs(out.all(e).imag()) <= 0.5 * omega * (1 + 1e-9)) kept.push_back(out.all(e));
  std::sort(kept.begin(), kept.end(), [](const cd& a, const cd& b) { return a.real() > b.real(); });
  out.exponents = Eigen::Map<Eigen::VectorXcd>(kept.data(), Eigen::Index(kept.size()));
  out.maxRealPart = kept.empty() ? -std::numeric_limits<double>::infinity() : kept.front().real();
  out.stable = out.maxRealPart < 1e-8 * std::max(1.0, omega);
  return out;
}

// The quadratic eigenproblem [mu^2 + mu diag(d1) + D0] q = 0 linearised, A = [0 I; -D0
// -diag(d1)], every eigenvalue.
FloquetExponents allExponents(const Eigen::MatrixXcd& D0, const Eigen::VectorXcd& d1, double omega) {
  const int mt = int(D0.rows());
  Eigen::MatrixXcd A = Eigen::MatrixXcd::Zero(2 * mt, 2 * mt);
  A.block(0, mt, mt, mt).setIdentity();
  A.block(mt, 0, mt, mt) = -D0;
  A.block(mt, mt, mt, mt).diagonal() = -d1;
  return pickExponents(eigenvaluesOf(A) * omega, omega, std::numeric_limits<double>::infinity());
}

// Only the eigenvalues of A nearest zero, by ARPACK on A^{-1}: [a; b] -> [-D0^{-1} (b +
// d1 a); a], one LU of D0 (the harmonic balance Jacobian's condensed form at mu = 0,
// singular only exactly at a fold, where the whole problem is solved instead). Their
// count is doubled until the farthest reaches coverage (scaled time: w = 1).
FloquetExponents nearestExponents(const Eigen::MatrixXcd& D0, const Eigen::VectorXcd& d1, double omega,
                                  double coverage, int firstCount) {
  const int mt = int(D0.rows()), n = 2 * mt, ld = std::max(mt, 1), one = 1;
  if (n < 4) return allExponents(D0, d1, omega);  // ARPACK wants at least one eigenvalue and two more
  Eigen::MatrixXcd lu = D0;
  std::vector<int> pivots(static_cast<std::size_t>(ld));
  int info = 0;
  zgetrf_(&mt, &mt, lu.data(), &ld, pivots.data(), &info);
  if (info != 0) return allExponents(D0, d1, omega);
  Eigen::VectorXcd rhs(mt);
  const InverseAction inverse = [&](const cd* x, cd* y) {
    for (int i = 0; i < mt; ++i) rhs(i) = -(x[mt + i] + d1(i) * x[i]);
    int solveInfo = 0;
    zgetrs_("N", &mt, &one, lu.data(), &ld, pivots.data(), rhs.data(), &ld, &solveInfo);
    for (int i = 0; i < mt; ++i) y[i] = rhs(i), y[mt + i] = x[i];
  };
  for (int count = std::min(n - 2, firstCount);; count = std::min(n - 2, 2 * count)) {
    const EigenvaluesNearZero near = eigenvaluesNearZero(n, count, inverse);
    const double reached = near.values.size() ? std::abs(near.values(near.values.size() - 1)) : 0.0;
    if (near.converged && reached >= coverage) return pickExponents(near.values * omega, omega, reached * omega);
    if (count == n - 2) break;
  }
  return allExponents(D0, d1, omega);  // ARPACK did not get there: the whole problem
}

}  // namespace

int receptanceModalCoordinates(const HarmonicBalanceSystem& sys) {
  int coordinates = 0;
  for (int h : sys.aft().harmonics().harmonics()) {
    const auto r = sys.receptance()->modalRealization(sys.phaseIndex(h));
    if (!r) return 0;
    coordinates += (h == 0 ? 1 : 2) * r->numModes();
  }
  return coordinates;
}

FloquetExponents receptanceHillStability(const HarmonicBalanceSystem& sys, const Eigen::VectorXd& X, double omega,
                                         const HillOptions& options) {
  if (!(omega > 0)) throw InputError("stability", "Hill's method needs a frequency > 0");
  Eigen::MatrixXcd t, ti;
  std::vector<Block> blocks = exponentBlocks(sys.aft().harmonics(), t, ti);
  const Eigen::SparseMatrix<double> J = elementJacobian(sys, X, omega);
  std::vector<ModalRealization> real;
  const int mt = blockRealizations(sys, blocks, real);
  const ModalTerms terms = modalTerms(blocks, real, sys.numDofs(), mt, omega);
  Eigen::MatrixXcd D0 = elementTerm(terms, blocks, J, t, ti, sys.numDofs(), omega);
  D0.diagonal() += terms.d0;
  if (2 * mt <= options.denseUpTo) return allExponents(D0, terms.d1, omega);
  // Asked for first: about the strip's count (two per harmonic block on the default disc).
  return nearestExponents(D0, terms.d1, omega, options.coverage, 2 * int(blocks.size()) + 4);
}

}  // namespace cyclone::hbm
