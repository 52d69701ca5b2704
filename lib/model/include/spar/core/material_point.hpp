#pragma once
/// \file
/// A material point of the model that a joint can hold (docs/joints.md §2.6): a point of a body
/// whose position is a function of some blocks — an ANCF node's r or a point r = S(ξ, y, z) e
/// inside an ANCF element (001 eq. 5), a point fixed in a frame. Any element family offers its
/// own; the point joint grips this interface and names no element kind.
///
/// Derivatives are in the blocks' local increments Δ (core/configuration.hpp). With f a fixed
/// inertial vector a point gives a joint:
///   p(q),   W ∂p/∂Δ,   ∂((∂p/∂Δ)ᵀ f)/∂Δ,   p̈ − (∂p/∂Δ) v̇ (the part not proportional to v̇).

#include <spar/core/configuration.hpp>

#include <Eigen/Core>

#include <memory>
#include <string_view>
#include <vector>

namespace spar::core {

class MaterialPoint {
public:
  virtual ~MaterialPoint() = default;
  /// A copy (a joint keeps its own).
  virtual std::unique_ptr<MaterialPoint> clone() const = 0;

  /// The model blocks p depends on, in the order of its Jacobian's column groups.
  virtual const std::vector<int>& blocks() const = 0;
  /// Throws spar::Error naming `where` unless q holds blocks() as the point expects them (kind and
  /// size).
  virtual void check(const Configuration& q, std::string_view where) const = 0;

  /// p(q).
  virtual Eigen::Vector3d position(const Configuration& q) const = 0;
  /// Adds W ∂p/∂Δ to the rows first_row … first_row + 2 of B; block k of blocks() has its first
  /// column at columns[k].
  virtual void add_jacobian(const Configuration& q, const Eigen::Matrix3d& weight, Eigen::Ref<Eigen::MatrixXd> B,
                            int first_row, const std::vector<int>& columns) const = 0;
  /// Adds ∂((∂p/∂Δ)ᵀ f)/∂Δ for a fixed inertial f, columns (and rows) as in add_jacobian.
  virtual void add_multiplier_tangent(const Configuration& q, const Eigen::Vector3d& f,
                                      Eigen::Ref<Eigen::MatrixXd> K, const std::vector<int>& columns) const = 0;
  /// The part of p̈ not proportional to the accelerations; `velocity` is the model's global one.
  virtual Eigen::Vector3d acceleration_terms(const Configuration& q, const Eigen::VectorXd& velocity) const = 0;
};

}  // namespace spar::core
