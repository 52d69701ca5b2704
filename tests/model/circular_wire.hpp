#pragma once
// A bead on a rigid circular wire, written outside the library against the public Constraint
// interface only (issue 10): a joint that owns a coordinate of its own. The bead's position x is
// a 3-vector block; its place on the wire is the arc length s, a 1-vector block of the model that
// carries no mass. With θ = s/R measured from the lowest point, in the vertical x–z plane through
// the centre c0,
//     c(s) = c0 + R (sin θ, 0, −cos θ),  c′ = (cos θ, 0, sin θ),  c″ = (−sin θ, 0, cos θ)/R,
//     Φ = x − c(s)                           (3 equations, blocks {bead, s}),
//     B = [I₃  −c′],  ∂(Bᵀλ)/∂(x, s) = 0 except the (s, s) entry −c″ · λ,
//     Φ̈ = ẍ − c′ s̈ − c″ ṡ²,  so the acceleration terms are −c″ ṡ².
#include <spar/core/configuration.hpp>
#include <spar/error.hpp>
#include <spar/joints/constraint.hpp>

#include <Eigen/Core>

#include <cmath>
#include <vector>

namespace spar::test {

struct CircularWireParameters {
  int bead = 0;        ///< 3-vector block: the bead's position, m
  int arc_length = 1;  ///< 1-vector block: s, m
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double radius = 1.0;  ///< R, m
};

class CircularWire final : public joints::Constraint {
public:
  explicit CircularWire(const CircularWireParameters& p)
      : blocks_{p.bead, p.arc_length}, centre_(p.centre), radius_(p.radius) {
    if (!(p.radius > 0.0)) throw Error("non-positive radius", "test::CircularWire", "give R > 0");
  }

  int equation_count() const override { return 3; }
  const std::vector<int>& blocks() const override { return blocks_; }

  /// c(s), c′(s), c″(s).
  Eigen::Vector3d point(double s) const {
    const double theta = s / radius_;
    return centre_ + radius_ * Eigen::Vector3d(std::sin(theta), 0, -std::cos(theta));
  }
  Eigen::Vector3d tangent(double s) const {
    const double theta = s / radius_;
    return {std::cos(theta), 0, std::sin(theta)};
  }
  Eigen::Vector3d curvature(double s) const {
    const double theta = s / radius_;
    return Eigen::Vector3d(-std::sin(theta), 0, std::cos(theta)) / radius_;
  }

private:
  void compute_value(const core::Configuration& q, double, Eigen::Ref<Eigen::VectorXd> phi) const override {
    phi = q.vector(blocks_[0]) - point(arc(q));
  }
  void compute_jacobian(const core::Configuration& q, double, Eigen::Ref<Eigen::MatrixXd> B) const override {
    B.leftCols<3>().setIdentity();
    B.col(3) = -tangent(arc(q));
  }
  void compute_multiplier_tangent(const core::Configuration& q, double,
                                  const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                  Eigen::Ref<Eigen::MatrixXd> K) const override {
    K(3, 3) = -curvature(arc(q)).dot(lambda);
  }
  void compute_acceleration_terms(const core::Configuration& q, const Eigen::VectorXd& velocity, double,
                                  Eigen::Ref<Eigen::VectorXd> c) const override {
    const double s_dot = velocity(q.blocks[blocks_[1]].offset);
    c = -curvature(arc(q)) * s_dot * s_dot;
  }

  double arc(const core::Configuration& q) const { return q.vector(blocks_[1])(0); }

  std::vector<int> blocks_;
  Eigen::Vector3d centre_;
  double radius_;
};

}  // namespace spar::test
