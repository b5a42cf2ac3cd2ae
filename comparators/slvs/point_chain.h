// The comparison set of the constraint solvers: chains of points, each a set length from the
// next, the first on the plane z = 0, the last dragged to a target. Every parameter is a point
// coordinate in both solvers, so "the change" means the same thing to both.
#pragma once

#include <cstdint>
#include <vector>

#include <Eigen/Core>

namespace collido::slvs_comparison {

struct PointChain {
  std::vector<Eigen::Vector3d> start;  ///< the points before the drag; the constraints hold here
  std::vector<double> lengths;         ///< lengths[i]: from point i to point i + 1
  Eigen::Vector3d target;              ///< where the last point is dragged to
};

/// `points` points (3 · points parameters) with unit links turned at random, the last one
/// dragged by `drag` in a random direction.
PointChain makePointChain(int points, double drag, std::uint64_t seed);

/// How far a solution is from meeting the chain's constraints (the largest residual).
double constraintError(const PointChain& chain, const std::vector<Eigen::Vector3d>& solution);

/// √Σ|p_i − start_i|²: the change the least-change solution minimises.
double change(const PointChain& chain, const std::vector<Eigen::Vector3d>& solution);

/// How far `solution` is from the first-order condition of the least change: the change must be
/// a combination of the constraint gradients (Δ = Jᵀλ). Returns |Δ − Jᵀλ| / |Δ| for the best λ.
double stationarityError(const PointChain& chain, const std::vector<Eigen::Vector3d>& solution);

}  // namespace collido::slvs_comparison
