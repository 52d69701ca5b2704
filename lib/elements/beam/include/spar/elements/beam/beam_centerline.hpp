#pragma once
/// \file
/// A geometrically exact beam's centerline as a core::Curve (docs/joints.md §2.5): the NURBS
/// interpolation of its control points' positions, x(u) = Σ_I N_I(u) x_I (003 eq. 53), with the
/// curve parameter rescaled to metres, u = u₀ + c ζ, c = (u₁ − u₀)/L₀ (eq. J23). Its segments are
/// the beam's elements, its blocks the control points' frames (their rotations do not enter).

#include <spar/core/curve.hpp>
#include <spar/core/model.hpp>
#include <spar/elements/beam/beam.hpp>

#include <memory>

namespace spar::core {

class BeamCenterline final : public LinearCurve {
public:
  /// The centerline of `beam`, which must outlive the curve. L₀ is the reference centerline's arc
  /// length.
  explicit BeamCenterline(const GeometricallyExactBeam& beam);

  /// L₀.
  double length() const override { return length_; }
  int block_count() const override { return beam_->control_point_count(); }
  /// The node of control point i.
  int block(int i) const override { return beam_->node(i); }
  int segment_count() const override { return beam_->element_count(); }
  /// The element holding u(ζ) (GeometricallyExactBeam::centerline_point's rule at knots).
  int segment_at(double zeta) const override;
  /// Control points first(first) … first(last) + p.
  CurveBlocks segment_blocks(int first, int last) const override;

private:
  /// N_I(u) with d^k/dζ^k = c^k d^k/du^k, coefficients x_I at columns 6 I.
  void compute_basis(double zeta, int order, CurvePoint& p) const override;
  double parameter(double zeta) const;

  const GeometricallyExactBeam* beam_;
  double length_ = 0.0;
  double parameter_per_zeta_ = 0.0;  ///< c = du/dζ
};

/// The centerline of beam b of `model` (core::beam(model, b)), which must outlive the curve.
/// Throws spar::Error for a beam that does not exist.
std::shared_ptr<const Curve> beam_centerline(const Model& model, int b);

}  // namespace spar::core
