#pragma once
/// \file
/// The two sides of an ALE sliding node (paper 000 §5, eqs. (39)–(40); docs/rancf.md "Sliding
/// node and length control"). The element left of the sliding node holds the node block
/// [r⁽¹⁾, r_x⁽¹⁾], the element right of it [r⁽²⁾, r_x⁽²⁾] (2·Dim entries each, Dim = 2 or 3);
///   Φ = [r⁽¹⁾ − r⁽²⁾; C^s],
///   continuous slopes:    C^s = r_x⁽¹⁾ − r_x⁽²⁾                         (Dim equations),
///   discontinuous slopes: C^s = (|r_x⁽¹⁾|² − |r_x⁽²⁾|²)/2                (1 equation).
/// 000 eq. (40) writes the second as |r_x⁽¹⁾| − |r_x⁽²⁾| = 0; squared and halved it has the same
/// solutions for non-zero slopes and is smooth where a slope vanishes. The node is then a hinge
/// whose two sides stretch alike: the cable may kink at the mass. Φ's first rows and the first
/// condition are linear; the second has B = [0, r_x⁽¹⁾ᵀ, 0, −r_x⁽²⁾ᵀ], the multiplier tangent
/// λ diag(0, I, 0, −I) and Φ̈ = B v̇ + |ṙ_x⁽¹⁾|² − |ṙ_x⁽²⁾|².

#include <spar/joints/constraint.hpp>

#include <Eigen/Core>

#include <vector>

namespace spar::joints {

enum class SlopeCondition { continuous, discontinuous };

class SlidingNodeSlopes final : public Constraint {
 public:
  /// Throws spar::Error unless `left` and `right` are distinct vector blocks of 2·dimension
  /// entries in q, dimension 2 or 3.
  SlidingNodeSlopes(int left, int right, int dimension, SlopeCondition condition, const core::Configuration& q);

  int equation_count() const override;
  const std::vector<int>& blocks() const override { return blocks_; }
  SlopeCondition condition() const { return condition_; }

 private:
  void compute_value(const core::Configuration& q, double t, Eigen::Ref<Eigen::VectorXd> phi) const override;
  void compute_jacobian(const core::Configuration& q, double t, Eigen::Ref<Eigen::MatrixXd> B) const override;
  void compute_multiplier_tangent(const core::Configuration& q, double t,
                                  const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                  Eigen::Ref<Eigen::MatrixXd> K) const override;
  void compute_acceleration_terms(const core::Configuration& q, const Eigen::VectorXd& velocity, double t,
                                  Eigen::Ref<Eigen::VectorXd> c) const override;

  std::vector<int> blocks_;
  int dimension_;
  SlopeCondition condition_;
};

}  // namespace spar::joints
