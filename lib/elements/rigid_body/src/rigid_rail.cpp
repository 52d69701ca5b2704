#include <spar/elements/rigid_body/rigid_rail.hpp>

#include <spar/elements/rigid_body/rigid_body.hpp>
#include <spar/error.hpp>
#include <spar/lie/hat.hpp>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <string>

namespace spar::core {

RigidRail::RigidRail(const Model& model, int frame, iga::NurbsCurve<3> curve)
    : frame_(frame), curve_(std::move(curve)) {
  model.check_frame(frame, "core::RigidRail");
  const iga::KnotVector& U = curve_.knots();
  length_ = curve_.arc_length(U.first(), U.last());
  if (!(length_ > 0.0) || !std::isfinite(length_))
    throw Error("the rail's length is " + std::to_string(length_), "core::RigidRail",
                "give a curve of positive length");
  parameter_per_zeta_ = (U.last() - U.first()) / length_;
}

// d^k c/dζ^k = c^k d^k c/du^k (eq. J23); beyond an end ζ_e, c(ζ_e) + c_ζ(ζ_e)(ζ − ζ_e) (eq. J29).
std::array<Eigen::Vector3d, max_curve_derivative + 1> RigidRail::body_point(double zeta, int order) const {
  const iga::KnotVector& U = curve_.knots();
  const double end = zeta <= 0.0 ? 0.0 : (zeta >= length_ ? length_ : zeta);
  const double u = std::clamp(U.first() + parameter_per_zeta_ * end, U.first(), U.last());
  const auto derivatives = curve_.derivatives(u, std::max(order, 1));
  std::array<Eigen::Vector3d, max_curve_derivative + 1> c{};
  double scale = 1.0;
  for (int k = 0; k <= std::max(order, 1); ++k) {
    c[k] = scale * derivatives.col(k);
    scale *= parameter_per_zeta_;
  }
  if (zeta != end) {
    c[0] += (zeta - end) * c[1];
    c[2].setZero();
  }
  return c;
}

CurvePoint RigidRail::compute_point(const Configuration& q, double zeta, int order) const {
  const std::array<Eigen::Vector3d, max_curve_derivative + 1> c = body_point(zeta, order);
  const Eigen::Matrix3d& R = q.rotation[frame_];
  CurvePoint p;
  p.zeta = zeta;
  p.block_count = 1;
  p.order = order;
  p.x[0] = q.position[frame_] + R * c[0];
  for (int k = 1; k <= order; ++k) p.x[k] = R * c[k];
  return p;
}

void RigidRail::compute_jacobian(const Configuration& q, const CurvePoint& p, const Eigen::Matrix3d& weight,
                                 Eigen::Ref<Eigen::MatrixXd> B, int first_row, int first_column) const {
  // ∂x/∂Δ = [I, −R c̃] (eq. J2).
  const Eigen::Vector3d c = body_point(p.zeta, 0)[0];
  B.block<3, 3>(first_row, first_column) += weight;
  B.block<3, 3>(first_row, first_column + 3) -= weight * q.rotation[frame_] * lie::hat(c);
}

void RigidRail::compute_multiplier_tangent(const Configuration& q, const CurvePoint& p, const Eigen::Vector3d& f,
                                           Eigen::Ref<Eigen::MatrixXd> K, int zeta_index, int first_column) const {
  const std::array<Eigen::Vector3d, max_curve_derivative + 1> c = body_point(p.zeta, 1);
  const Eigen::Vector3d w = q.rotation[frame_].transpose() * f;
  const int rotation = first_column + 3;
  // x_ζ·f = c_ζ·Rᵀf, whose rotation derivative is c_ζᵀ (Rᵀf)~ = (c_ζ × Rᵀf)ᵀ; the rotation rows of
  // (∂x/∂Δ)ᵀf are c̃ Rᵀf (eq. J3), with ζ-derivative c_ζ × Rᵀf and rotation derivative c̃ (Rᵀf)~.
  const Eigen::Vector3d cross = c[1].cross(w);
  K.block<1, 3>(zeta_index, rotation) += cross.transpose();
  K.block<3, 1>(rotation, zeta_index) += cross;
  K.block<3, 3>(rotation, rotation) += lie::hat(c[0]) * lie::hat(w);
}

void RigidRail::compute_acceleration_terms(const Configuration& q, const CurvePoint& p,
                                           const Eigen::VectorXd& velocity, double zeta_rate,
                                           Eigen::Vector3d& terms) const {
  const std::array<Eigen::Vector3d, max_curve_derivative + 1> c = body_point(p.zeta, 1);
  const Eigen::Vector3d omega = velocity.segment<3>(q.blocks[frame_].offset + 3);
  // d/dt (R c(ζ)) = R (Ω × c + c_ζ ζ̇); its second derivative less R c_ζ ζ̈, −R c̃ Ω̇ and R c_ζζ ζ̇².
  terms += q.rotation[frame_] * (2 * zeta_rate * omega.cross(c[1]) + omega.cross(omega.cross(c[0])));
}

std::shared_ptr<const Curve> rigid_body_rail(const Model& model, int body, const iga::NurbsCurve<3>& curve) {
  return std::make_shared<RigidRail>(model, rigid_body(model, body).node, curve);
}

}  // namespace spar::core
