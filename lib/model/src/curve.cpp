#include <spar/core/curve.hpp>

#include <spar/error.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace spar::core {

namespace {

void require_second_order(const CurvePoint& p, const char* where) {
  if (p.order < max_curve_derivative)
    throw Error("the curve point has derivatives up to order " + std::to_string(p.order) + ", this needs x_zeta_zeta",
                where, "evaluate the point with Curve::point(q, zeta, 2)");
}

/// P_i: a frame's position, or three coordinates of a vector block.
Eigen::Vector3d coefficient_vector(const Configuration& q, const CurveCoefficient& c) {
  return q.is_frame(c.block) ? q.position[c.block] : Eigen::Vector3d(q.vector(c.block).segment<3>(c.coordinate));
}

}  // namespace

CurvePoint Curve::point(const Configuration& q, double zeta, int order) const {
  constexpr const char* where = "core::Curve::point";
  if (!std::isfinite(zeta))
    throw Error("zeta = " + std::to_string(zeta) + " is not finite", where, "give a finite curve parameter");
  if (order < 0 || order > max_curve_derivative)
    throw Error("derivative order " + std::to_string(order), where,
                "ask for 0 … " + std::to_string(max_curve_derivative));
  return compute_point(q, zeta, order);
}

void Curve::add_jacobian(const Configuration& q, const CurvePoint& p, const Eigen::Matrix3d& weight,
                         Eigen::Ref<Eigen::MatrixXd> B, int first_row, int first_column) const {
  compute_jacobian(q, p, weight, B, first_row, first_column);
}

void Curve::add_multiplier_tangent(const Configuration& q, const CurvePoint& p, const Eigen::Vector3d& f,
                                   Eigen::Ref<Eigen::MatrixXd> K, int zeta_index, int first_column) const {
  require_second_order(p, "core::Curve::add_multiplier_tangent");
  // ∂(x_ζ·f)/∂ζ (003 eq. 52, ∂²x_B/∂ζ²·λ).
  K(zeta_index, zeta_index) += p.x[2].dot(f);
  compute_multiplier_tangent(q, p, f, K, zeta_index, first_column);
}

void Curve::add_acceleration_terms(const Configuration& q, const CurvePoint& p, const Eigen::VectorXd& velocity,
                                   double zeta_rate, Eigen::Vector3d& terms) const {
  require_second_order(p, "core::Curve::add_acceleration_terms");
  terms += p.x[2] * zeta_rate * zeta_rate;
  compute_acceleration_terms(q, p, velocity, zeta_rate, terms);
}

// x^(k) = Σ_i w_i^(k) P_i; beyond an end ζ_e, w_i = w_i(ζ_e) + w_i,ζ(ζ_e)(ζ − ζ_e) and the
// second derivatives vanish (eq. J29).
CurvePoint LinearCurve::compute_point(const Configuration& q, double zeta, int order) const {
  const double end = zeta <= 0.0 ? 0.0 : (zeta >= length() ? length() : zeta);
  CurvePoint p;
  compute_basis(end, std::max(order, 1), p);
  p.zeta = zeta;
  p.order = order;
  if (zeta != end) {
    p.shape.row(0) += (zeta - end) * p.shape.row(1);
    p.shape.bottomRows(iga::max_derivative_order - 1).setZero();
  }
  for (int k = 0; k <= order; ++k) {
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    for (int i = 0; i < p.coefficient_count; ++i) x += p.shape(k, i) * coefficient_vector(q, p.coefficients[i]);
    p.x[k] = x;
  }
  return p;
}

void LinearCurve::compute_jacobian(const Configuration& /*q*/, const CurvePoint& p, const Eigen::Matrix3d& weight,
                                   Eigen::Ref<Eigen::MatrixXd> B, int first_row, int first_column) const {
  for (int i = 0; i < p.coefficient_count; ++i)
    B.block<3, 3>(first_row, first_column + p.coefficients[i].column) += weight * p.shape(0, i);
}

void LinearCurve::compute_multiplier_tangent(const Configuration& /*q*/, const CurvePoint& p, const Eigen::Vector3d& f,
                                             Eigen::Ref<Eigen::MatrixXd> K, int zeta_index, int first_column) const {
  // (∂x/∂P_i)ᵀ f = w_i f and x_ζ·f = Σ w_i,ζ P_i·f: their cross derivatives w_i,ζ f (003 eq. 52).
  for (int i = 0; i < p.coefficient_count; ++i) {
    const int column = first_column + p.coefficients[i].column;
    K.block<1, 3>(zeta_index, column) += p.shape(1, i) * f.transpose();
    K.block<3, 1>(column, zeta_index) += p.shape(1, i) * f;
  }
}

void LinearCurve::compute_acceleration_terms(const Configuration& q, const CurvePoint& p,
                                             const Eigen::VectorXd& velocity, double zeta_rate,
                                             Eigen::Vector3d& terms) const {
  // ẍ = Σ w_i P̈_i + x_ζ ζ̈ + 2ζ̇ Σ w_i,ζ Ṗ_i + x_ζζ ζ̇².
  for (int i = 0; i < p.coefficient_count; ++i) {
    const CurveCoefficient& c = p.coefficients[i];
    terms += 2 * zeta_rate * p.shape(1, i) * velocity.segment<3>(q.blocks[c.block].offset + c.coordinate);
  }
}

}  // namespace spar::core
