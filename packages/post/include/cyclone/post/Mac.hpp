#pragma once
// Modal assurance criterion between mode sets (columns are shapes).
#include <Eigen/Dense>
#include <string>

namespace cyclone::post {

/// MAC(i, j) = (a_i . b_j)^2 / ((a_i . a_i)(b_j . b_j)). Auto-MAC: macMatrix(A, A).
Eigen::MatrixXd macMatrix(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B);

/// MAC of two groups of modes as subspaces (e.g. the two members of a double
/// mode, which any rotation within the pair leaves valid): the mean squared
/// cosine of their principal angles, ||Q_A^T Q_B||_F^2 / max(dim A, dim B);
/// 1 when both span the same space, 0 when orthogonal.
double subspaceMac(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B);

/// CSV with a header row of column indices; atomic.
void writeMacCsv(const std::string& path, const Eigen::MatrixXd& mac);
/// Heat map (white 0 to dark blue 1) as SVG; atomic.
void writeMacSvg(const std::string& path, const Eigen::MatrixXd& mac, const std::string& title);

}  // namespace cyclone::post
