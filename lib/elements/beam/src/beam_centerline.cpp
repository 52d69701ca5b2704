#include <spar/elements/beam/beam_centerline.hpp>

#include <algorithm>

namespace spar::core {

BeamCenterline::BeamCenterline(const GeometricallyExactBeam& beam) : beam_(&beam) {
  const iga::KnotVector& U = beam.reference_centerline().knots();
  length_ = beam.reference_centerline().arc_length(U.first(), U.last());
  parameter_per_zeta_ = (U.last() - U.first()) / length_;
}

// u = u₀ + c ζ (eq. J23), kept inside the knot range.
double BeamCenterline::parameter(double zeta) const {
  const iga::KnotVector& U = beam_->reference_centerline().knots();
  return std::clamp(U.first() + parameter_per_zeta_ * zeta, U.first(), U.last());
}

int BeamCenterline::segment_at(double zeta) const { return beam_->centerline_point(parameter(zeta), 0).element; }

CurveBlocks BeamCenterline::segment_blocks(int first, int last) const {
  return {beam_->element(first).first_control_point, beam_->element(last).first_control_point + beam_->degree()};
}

// 003 eq. 53 with eq. J23: d^k x/dζ^k = c^k Σ_I N_I^(k)(u) x_I.
void BeamCenterline::compute_basis(double zeta, int order, CurvePoint& p) const {
  const CenterlinePoint point = beam_->centerline_point(parameter(zeta), order);
  p.segment = point.element;
  p.first_block = point.first_control_point;
  p.block_count = beam_->degree() + 1;
  p.coefficient_count = p.block_count;
  const int first = beam_->node(point.first_control_point);
  for (int I = 0; I < p.block_count; ++I) p.coefficients[I] = {.block = first + I, .coordinate = 0, .column = frame_dofs * I};
  p.shape = point.shape;
  double scale = 1.0;
  for (int k = 1; k <= order; ++k) {
    scale *= parameter_per_zeta_;
    p.shape.row(k) *= scale;
  }
}

std::shared_ptr<const Curve> beam_centerline(const Model& model, int b) {
  return std::make_shared<BeamCenterline>(beam(model, b));
}

}  // namespace spar::core
