#pragma once
/// \file
/// A rail: a fixed curve c in a rigid body's frame, offered as a core::Curve for a sliding joint
/// (docs/joints.md §2.7). x(ζ) = x_b + R c(ζ) with c any NURBS curve in body coordinates
/// (relative to the body's node, its centre of mass), e.g. an exact circle (iga::circular_arc).
/// As for a beam's centerline, ζ is the curve parameter u rescaled to metres,
/// u = u₀ + c ζ, c = (u₁ − u₀)/L₀ (eq. J23), L₀ the rail's arc length. The rail depends on the
/// body's frame only: one segment, one block, whatever the knot spans.
///
/// Derivatives (eqs. J1–J4 with the point a = c(ζ) moving along the body):
///   x_ζ = R c_ζ,  x_ζζ = R c_ζζ,  ∂x/∂Δ = [I, −R c̃],
///   ∂((∂x/∂(ζ, Δ))ᵀ f)/∂(ζ, Δ):  (ζ, φ) = (c_ζ × Rᵀf)ᵀ,  (φ, ζ) = c_ζ × Rᵀf,  (φ, φ) = c̃ (Rᵀf)~,
///   ẍ − x_ζ ζ̈ − (∂x/∂Δ) v̇ = x_ζζ ζ̇² + 2ζ̇ R (Ω × c_ζ) + R (Ω × (Ω × c)).

#include <spar/core/curve.hpp>
#include <spar/core/model.hpp>
#include <spar/iga/nurbs_curve.hpp>

#include <Eigen/Core>

#include <array>
#include <memory>

namespace spar::core {

class RigidRail final : public Curve {
public:
  /// The curve `curve` (body coordinates) fixed in frame block `frame` of `model`. Throws
  /// spar::Error for a block that is not a frame of the model or a curve of zero length.
  RigidRail(const Model& model, int frame, iga::NurbsCurve<3> curve);

  /// L₀.
  double length() const override { return length_; }
  int block_count() const override { return 1; }
  int block(int /*i*/) const override { return frame_; }
  int segment_count() const override { return 1; }
  int segment_at(double /*zeta*/) const override { return 0; }
  CurveBlocks segment_blocks(int /*first*/, int /*last*/) const override { return {0, 0}; }

private:
  /// c, c_ζ, c_ζζ (body coordinates, up to `order`) at any finite ζ: beyond an end the end's
  /// tangent line (eq. J29).
  std::array<Eigen::Vector3d, max_curve_derivative + 1> body_point(double zeta, int order) const;

  CurvePoint compute_point(const Configuration& q, double zeta, int order) const override;
  void compute_jacobian(const Configuration& q, const CurvePoint& p, const Eigen::Matrix3d& weight,
                        Eigen::Ref<Eigen::MatrixXd> B, int first_row, int first_column) const override;
  void compute_multiplier_tangent(const Configuration& q, const CurvePoint& p, const Eigen::Vector3d& f,
                                  Eigen::Ref<Eigen::MatrixXd> K, int zeta_index, int first_column) const override;
  void compute_acceleration_terms(const Configuration& q, const CurvePoint& p, const Eigen::VectorXd& velocity,
                                  double zeta_rate, Eigen::Vector3d& terms) const override;

  int frame_;
  iga::NurbsCurve<3> curve_;
  double length_ = 0.0;
  double parameter_per_zeta_ = 0.0;  ///< c = du/dζ
};

/// The rail `curve` (body coordinates, relative to the centre of mass) fixed in rigid body `body`
/// of `model` (core::rigid_body(model, body)). Throws spar::Error for a body that does not exist
/// or a curve of zero length.
std::shared_ptr<const Curve> rigid_body_rail(const Model& model, int body, const iga::NurbsCurve<3>& curve);

}  // namespace spar::core
