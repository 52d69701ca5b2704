#pragma once
/// \file
/// A material point linear in the coordinates of vector blocks, p(q) = Σ_k C_k q_k (C_k: 3 × the
/// block's size): an ANCF node's r, a point S(ξ, y, z) e inside an ANCF element (001 eq. 5), a
/// cable point S(u) e. Its Jacobian is constant (W C_k), its multiplier tangent and acceleration
/// terms are zero.

#include <spar/core/material_point.hpp>

#include <Eigen/Core>

#include <vector>

namespace spar::core {

class LinearPoint final : public MaterialPoint {
public:
  /// p = Σ_k maps[k] q_{blocks[k]}. Throws spar::Error for no block, a different number of maps
  /// than blocks, a negative block or a map that has not three rows.
  LinearPoint(std::vector<int> blocks, std::vector<Eigen::MatrixXd> maps);

  std::unique_ptr<MaterialPoint> clone() const override { return std::make_unique<LinearPoint>(*this); }
  const std::vector<int>& blocks() const override { return blocks_; }
  const std::vector<Eigen::MatrixXd>& maps() const { return maps_; }
  /// Every block a vector block of the size of its map's columns.
  void check(const Configuration& q, std::string_view where) const override;

  Eigen::Vector3d position(const Configuration& q) const override;
  /// W C_k at each block's columns.
  void add_jacobian(const Configuration& q, const Eigen::Matrix3d& weight, Eigen::Ref<Eigen::MatrixXd> B,
                    int first_row, const std::vector<int>& columns) const override;
  /// Zero: ∂p/∂Δ does not depend on q.
  void add_multiplier_tangent(const Configuration& q, const Eigen::Vector3d& f, Eigen::Ref<Eigen::MatrixXd> K,
                              const std::vector<int>& columns) const override;
  /// Zero: p̈ = Σ_k C_k q̈_k.
  Eigen::Vector3d acceleration_terms(const Configuration& q, const Eigen::VectorXd& velocity) const override;

private:
  std::vector<int> blocks_;
  std::vector<Eigen::MatrixXd> maps_;
};

}  // namespace spar::core
