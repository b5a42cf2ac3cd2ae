#include "point_chain.h"

#include <algorithm>
#include <cmath>
#include <random>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

namespace collido::slvs_comparison {

PointChain makePointChain(int points, double drag, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::normal_distribution<double> normal;
  const auto direction = [&] {
    Eigen::Vector3d d(normal(random), normal(random), normal(random));
    return Eigen::Vector3d(d.normalized());
  };
  PointChain chain;
  chain.start.push_back(Eigen::Vector3d::Zero());
  for (int i = 1; i < points; ++i) {
    // Mostly along +x, so the chain is stretched out and far from folding onto itself.
    const Eigen::Vector3d step = (Eigen::Vector3d::UnitX() + 0.6 * direction()).normalized();
    chain.start.push_back(chain.start.back() + step);
    chain.lengths.push_back(1.0);
  }
  chain.target = chain.start.back() + drag * direction();
  return chain;
}

double constraintError(const PointChain& chain, const std::vector<Eigen::Vector3d>& p) {
  double worst = std::abs(p.front().z());
  for (std::size_t i = 0; i + 1 < p.size(); ++i)
    worst = std::max(worst, std::abs((p[i + 1] - p[i]).norm() - chain.lengths[i]));
  return std::max(worst, (p.back() - chain.target).cwiseAbs().maxCoeff());
}

double change(const PointChain& chain, const std::vector<Eigen::Vector3d>& p) {
  double sum = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i)
    sum += (p[i] - chain.start[i]).squaredNorm();
  return std::sqrt(sum);
}

double stationarityError(const PointChain& chain, const std::vector<Eigen::Vector3d>& p) {
  const int n = static_cast<int>(p.size());
  std::vector<Eigen::Triplet<double>> triplets;
  int row = 0;
  triplets.emplace_back(row++, 2, 1.0);  // the first point's z
  for (int i = 0; i + 1 < n; ++i, ++row) {
    const Eigen::Vector3d u = (p[i + 1] - p[i]).normalized();
    for (int k = 0; k < 3; ++k) {
      triplets.emplace_back(row, 3 * (i + 1) + k, u[k]);
      triplets.emplace_back(row, 3 * i + k, -u[k]);
    }
  }
  for (int k = 0; k < 3; ++k)
    triplets.emplace_back(row++, 3 * (n - 1) + k, 1.0);
  Eigen::SparseMatrix<double> jacobian(row, 3 * n);
  jacobian.setFromTriplets(triplets.begin(), triplets.end());
  Eigen::VectorXd delta(3 * n);
  for (int i = 0; i < n; ++i)
    delta.segment<3>(3 * i) = p[i] - chain.start[i];
  const Eigen::SparseMatrix<double> normal = jacobian * jacobian.transpose();
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> factor(normal);
  const Eigen::VectorXd lambda = factor.solve(jacobian * delta);
  return (delta - jacobian.transpose() * lambda).norm() / delta.norm();
}

}  // namespace collido::slvs_comparison
