// Belos' block GMRES on Eigen vectors: Belos::MultiVec and Belos::Operator implemented
// over Eigen storage (a multivector is a set of columns of a shared matrix, so Belos'
// views are column index lists into it), the solver manager's templates instantiated
// only here.
#include "cyclone/continuation/KrylovSolve.hpp"

#include <BelosBlockGmresSolMgr.hpp>
#include <BelosLinearProblem.hpp>
#include <BelosMultiVec.hpp>
#include <BelosOperator.hpp>
#include <Teuchos_ParameterList.hpp>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "cyclone/core/Error.hpp"

namespace cyclone::continuation {

namespace {

// Belos fills a column its orthogonalisation found dependent with random entries: one
// engine per solve, seeded at its start (a solve is the same run after run, and a second
// fill is not the first one again).
thread_local std::mt19937 randomFill;
// MvTimesMatAddMv's work, shared by every view (Belos makes fresh views at every
// iteration): grown, never shrunk.
thread_local std::vector<double> productWork;

class EigenMultiVec final : public Belos::MultiVec<double> {
public:
  EigenMultiVec(Eigen::Index rows, int columns)
      : data_(std::make_shared<Eigen::MatrixXd>(Eigen::MatrixXd::Zero(rows, columns))), cols_(std::size_t(columns)) {
    for (int j = 0; j < columns; ++j) cols_[std::size_t(j)] = j;
  }
  EigenMultiVec(std::shared_ptr<Eigen::MatrixXd> data, std::vector<int> cols) : data_(std::move(data)), cols_(std::move(cols)) {}

  auto col(int j) { return data_->col(cols_[std::size_t(j)]); }
  auto col(int j) const { return std::as_const(*data_).col(cols_[std::size_t(j)]); }
  Eigen::Index rows() const { return data_->rows(); }

  Belos::MultiVec<double>* Clone(const int numvecs) const override { return new EigenMultiVec(rows(), numvecs); }
  Belos::MultiVec<double>* CloneCopy() const override {
    auto* c = new EigenMultiVec(rows(), GetNumberVecs());
    for (int j = 0; j < GetNumberVecs(); ++j) c->col(j) = col(j);
    return c;
  }
  Belos::MultiVec<double>* CloneCopy(const std::vector<int>& index) const override {
    auto* c = new EigenMultiVec(rows(), int(index.size()));
    for (std::size_t j = 0; j < index.size(); ++j) c->col(int(j)) = col(index[j]);
    return c;
  }
  Belos::MultiVec<double>* CloneViewNonConst(const std::vector<int>& index) override { return view(index); }
  const Belos::MultiVec<double>* CloneView(const std::vector<int>& index) const override { return view(index); }
  ptrdiff_t GetGlobalLength() const override { return ptrdiff_t(rows()); }
  int GetNumberVecs() const override { return int(cols_.size()); }

  // this = beta this + alpha A B (A may share storage with this: the product goes
  // through a temporary).
  void MvTimesMatAddMv(const double alpha, const Belos::MultiVec<double>& A,
                       const Teuchos::SerialDenseMatrix<int, double>& B, const double beta) override {
    const auto& a = cast(A);
    const int k = a.GetNumberVecs(), m = GetNumberVecs();
    if (productWork.size() < std::size_t(rows() * m)) productWork.resize(std::size_t(rows() * m));
    Eigen::Map<Eigen::MatrixXd> product_(productWork.data(), rows(), m);
    product_.setZero();
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < k; ++i)
        if (B(i, j) != 0) product_.col(j) += B(i, j) * a.col(i);
    for (int j = 0; j < m; ++j) {
      if (beta == 0) col(j) = alpha * product_.col(j);
      else col(j) = beta * col(j) + alpha * product_.col(j);
    }
  }
  void MvAddMv(const double alpha, const Belos::MultiVec<double>& A, const double beta,
               const Belos::MultiVec<double>& B) override {
    const auto &a = cast(A), &b = cast(B);
    for (int j = 0; j < GetNumberVecs(); ++j) col(j) = alpha * a.col(j) + beta * b.col(j);
  }
  void MvScale(const double alpha) override {
    for (int j = 0; j < GetNumberVecs(); ++j) col(j) *= alpha;
  }
  void MvScale(const std::vector<double>& alpha) override {
    for (int j = 0; j < GetNumberVecs(); ++j) col(j) *= alpha[std::size_t(j)];
  }
  void MvTransMv(const double alpha, const Belos::MultiVec<double>& A,
                 Teuchos::SerialDenseMatrix<int, double>& B) const override {
    const auto& a = cast(A);
    for (int j = 0; j < GetNumberVecs(); ++j)
      for (int i = 0; i < a.GetNumberVecs(); ++i) B(i, j) = alpha * a.col(i).dot(col(j));
  }
  void MvDot(const Belos::MultiVec<double>& A, std::vector<double>& b) const override {
    const auto& a = cast(A);
    b.resize(std::size_t(GetNumberVecs()));
    for (int j = 0; j < GetNumberVecs(); ++j) b[std::size_t(j)] = col(j).dot(a.col(j));
  }
  void MvNorm(std::vector<double>& norms, Belos::NormType type = Belos::TwoNorm) const override {
    norms.resize(std::size_t(GetNumberVecs()));
    for (int j = 0; j < GetNumberVecs(); ++j)
      norms[std::size_t(j)] = type == Belos::OneNorm ? col(j).lpNorm<1>()
                              : type == Belos::InfNorm ? col(j).lpNorm<Eigen::Infinity>()
                                                       : col(j).norm();
  }
  void SetBlock(const Belos::MultiVec<double>& A, const std::vector<int>& index) override {
    const auto& a = cast(A);
    for (std::size_t j = 0; j < index.size(); ++j) col(index[j]) = a.col(int(j));
  }
  void MvRandom() override {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int j = 0; j < GetNumberVecs(); ++j)
      for (Eigen::Index i = 0; i < rows(); ++i) col(j)(i) = u(randomFill);
  }
  void MvInit(const double alpha) override {
    for (int j = 0; j < GetNumberVecs(); ++j) col(j).setConstant(alpha);
  }
  void MvPrint(std::ostream& os) const override {
    for (int j = 0; j < GetNumberVecs(); ++j) os << col(j).transpose() << "\n";
  }

private:
  static const EigenMultiVec& cast(const Belos::MultiVec<double>& A) { return dynamic_cast<const EigenMultiVec&>(A); }
  EigenMultiVec* view(const std::vector<int>& index) const {
    std::vector<int> cols(index.size());
    for (std::size_t j = 0; j < index.size(); ++j) cols[j] = cols_[std::size_t(index[j])];
    return new EigenMultiVec(data_, std::move(cols));
  }
  std::shared_ptr<Eigen::MatrixXd> data_;
  std::vector<int> cols_;
};

class FunctionOperator final : public Belos::Operator<double> {
public:
  explicit FunctionOperator(const VectorFunction& f) : f_(f) {}
  void Apply(const Belos::MultiVec<double>& x, Belos::MultiVec<double>& y, Belos::ETrans trans) const override {
    if (trans != Belos::NOTRANS) throw Error("GMRES: a transposed product was asked for");
    const auto& X = dynamic_cast<const EigenMultiVec&>(x);
    auto& Y = dynamic_cast<EigenMultiVec&>(y);
    for (int j = 0; j < X.GetNumberVecs(); ++j) {
      in_ = X.col(j);
      f_(in_, out_);
      Y.col(j) = out_;
    }
  }

private:
  const VectorFunction& f_;
  mutable Eigen::VectorXd in_, out_;
};

}  // namespace

KrylovResult solveKrylov(const VectorFunction& apply, const VectorFunction& precondition, const Eigen::VectorXd& b,
                         Eigen::VectorXd& x, const KrylovOptions& options) {
  using MV = Belos::MultiVec<double>;
  using OP = Belos::Operator<double>;
  KrylovResult result;
  const Eigen::Index n = b.size();
  x = Eigen::VectorXd::Zero(n);
  const double bNorm = b.norm();
  if (bNorm == 0) {
    result.converged = true;
    return result;
  }
  if (!b.allFinite()) {
    x.setConstant(std::numeric_limits<double>::quiet_NaN());
    return result;
  }
  randomFill.seed(12345);
  auto B = Teuchos::rcp(new EigenMultiVec(n, 1));
  B->col(0) = b;
  auto X = Teuchos::rcp(new EigenMultiVec(n, 1));
  auto A = Teuchos::rcp(new FunctionOperator(apply));
  auto M = Teuchos::rcp(new FunctionOperator(precondition));
  auto problem = Teuchos::rcp(new Belos::LinearProblem<double, MV, OP>(A, X, B));
  problem->setRightPrec(M);
  problem->setProblem();
  auto params = Teuchos::rcp(new Teuchos::ParameterList);
  params->set("Convergence Tolerance", options.tolerance);
  params->set("Maximum Iterations", options.maxIterations);
  params->set("Num Blocks", options.restart);
  params->set("Maximum Restarts", std::max(1, options.maxIterations / std::max(1, options.restart)));
  params->set("Block Size", 1);
  // Flexible GMRES keeps the preconditioned vectors: the solution is then exactly their
  // combination, so a preconditioner that is linear only to its rounding (single-precision
  // factors: hbm::JacobianBlocks) still reaches a double-precision residual.
  params->set("Flexible Gmres", true);
  params->set("Orthogonalization", std::string("ICGS"));
  params->set("Verbosity", int(Belos::Errors));
  Belos::BlockGmresSolMgr<double, MV, OP> solver(problem, params);
  Belos::ReturnType outcome = Belos::Unconverged;
  try {
    outcome = solver.solve();
  } catch (const std::exception&) {
    outcome = Belos::Unconverged;
  }
  result.iterations = solver.getNumIters();
  x = X->col(0);
  // The true residual (Belos' test is on its implicit one).
  Eigen::VectorXd Ax;
  apply(x, Ax);
  result.relativeResidual = (b - Ax).norm() / bNorm;
  result.converged = outcome == Belos::Converged && x.allFinite() && result.relativeResidual <= 10 * options.tolerance;
  return result;
}

BorderedKrylovSolve::BorderedKrylovSolve(std::shared_ptr<const JacobianOperator> J, Eigen::VectorXd b, Eigen::VectorXd c,
                                         double d, KrylovOptions options)
    : J_(std::move(J)), b_(std::move(b)), c_(std::move(c)), d_(d), options_(options) {
  J_->precondition(b_, Pb_);
  schur_ = d_ - c_.dot(Pb_);
  // A Schur complement that cancels to rounding (P is single precision) would make the
  // border's part of the preconditioner huge: left out there (preconditionBordered).
  if (std::abs(schur_) <= 1e-8 * (std::abs(d_) + c_.norm() * Pb_.norm())) schur_ = 0;
}

void BorderedKrylovSolve::applyBordered(const Eigen::VectorXd& v, Eigen::VectorXd& y) const {
  const Eigen::Index n = b_.size();
  head_ = v.head(n);
  J_->apply(head_, out_);
  y.resize(n + 1);
  y.head(n) = out_ + v(n) * b_;
  y(n) = c_.dot(head_) + d_ * v(n);
}

// [P, b; c^T, d]^-1 [r; s]: y = (s - c^T P^-1 r) / (d - c^T P^-1 b), x = P^-1 r - y P^-1 b.
// A Schur complement of zero (P's border singular) leaves the border out: x = P^-1 r.
void BorderedKrylovSolve::preconditionBordered(const Eigen::VectorXd& r, Eigen::VectorXd& z) const {
  const Eigen::Index n = b_.size();
  head_ = r.head(n);
  J_->precondition(head_, out_);
  z.resize(n + 1);
  const double y = schur_ != 0 ? (r(n) - c_.dot(out_)) / schur_ : 0.0;
  z.head(n) = out_ - y * Pb_;
  z(n) = y;
}

Eigen::VectorXd BorderedKrylovSolve::solve(const Eigen::VectorXd& rhs, double tolerance) const {
  if (!J_) throw Error("BorderedKrylovSolve: no operator");
  const VectorFunction apply = [this](const Eigen::VectorXd& v, Eigen::VectorXd& y) { applyBordered(v, y); };
  const VectorFunction precondition = [this](const Eigen::VectorXd& r, Eigen::VectorXd& z) { preconditionBordered(r, z); };
  Eigen::VectorXd x;
  KrylovOptions options = options_;
  if (tolerance > 0) options.tolerance = tolerance;
  const KrylovResult r = solveKrylov(apply, precondition, rhs, x, options);
  iterations_ += r.iterations;
  if (!r.converged) {
    ++failures_;
    x.setConstant(std::numeric_limits<double>::quiet_NaN());
  }
  return x;
}

}  // namespace cyclone::continuation
