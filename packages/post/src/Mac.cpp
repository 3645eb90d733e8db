#include "cyclone/post/Mac.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "cyclone/core/AtomicFile.hpp"
#include "cyclone/core/Error.hpp"

namespace cyclone::post {

Eigen::MatrixXd macMatrix(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B) {
  if (A.rows() != B.rows()) throw Error("MAC: mode shapes of different lengths");
  const Eigen::MatrixXd AB = A.transpose() * B;
  const Eigen::VectorXd aa = A.colwise().squaredNorm(), bb = B.colwise().squaredNorm();
  Eigen::MatrixXd mac(A.cols(), B.cols());
  for (Eigen::Index i = 0; i < A.cols(); ++i)
    for (Eigen::Index j = 0; j < B.cols(); ++j) mac(i, j) = AB(i, j) * AB(i, j) / (aa(i) * bb(j));
  return mac;
}

double subspaceMac(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B) {
  if (A.rows() != B.rows()) throw Error("MAC: mode shapes of different lengths");
  const Eigen::MatrixXd QA = Eigen::HouseholderQR<Eigen::MatrixXd>(A).householderQ() *
                             Eigen::MatrixXd::Identity(A.rows(), A.cols());
  const Eigen::MatrixXd QB = Eigen::HouseholderQR<Eigen::MatrixXd>(B).householderQ() *
                             Eigen::MatrixXd::Identity(B.rows(), B.cols());
  return (QA.transpose() * QB).squaredNorm() / double(std::max(A.cols(), B.cols()));
}

void writeMacCsv(const std::string& path, const Eigen::MatrixXd& mac) {
  AtomicFile file(path);
  {
    std::ofstream out(file.tempPath());
    out << "mode";
    for (Eigen::Index j = 0; j < mac.cols(); ++j) out << "," << j + 1;
    out << "\n";
    out.precision(6);
    for (Eigen::Index i = 0; i < mac.rows(); ++i) {
      out << i + 1;
      for (Eigen::Index j = 0; j < mac.cols(); ++j) out << "," << mac(i, j);
      out << "\n";
    }
    file.check(out);
  }
  file.commit();
}

void writeMacSvg(const std::string& path, const Eigen::MatrixXd& mac, const std::string& title) {
  const double cell = std::max(8.0, std::min(40.0, 600.0 / std::max<Eigen::Index>(1, std::max(mac.rows(), mac.cols()))));
  const double left = 50, top = 50;
  std::ostringstream o;
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << left + cell * mac.cols() + 20 << "\" height=\""
    << top + cell * mac.rows() + 20 << "\" font-family=\"sans-serif\" font-size=\"11\">\n"
    << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<text x=\"" << left << "\" y=\"20\" font-size=\"14\">"
    << title << "</text>\n";
  for (Eigen::Index i = 0; i < mac.rows(); ++i)
    for (Eigen::Index j = 0; j < mac.cols(); ++j) {
      const int shade = int(std::round(255 * (1 - std::clamp(mac(i, j), 0.0, 1.0))));
      o << "<rect x=\"" << left + j * cell << "\" y=\"" << top + i * cell << "\" width=\"" << cell << "\" height=\""
        << cell << "\" fill=\"rgb(" << shade << "," << shade << ",255)\" stroke=\"#ccc\"/>\n";
    }
  o << "</svg>\n";
  AtomicFile file(path);
  {
    std::ofstream out(file.tempPath());
    out << o.str();
    file.check(out);
  }
  file.commit();
}

}  // namespace cyclone::post
