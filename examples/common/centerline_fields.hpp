#pragma once
// The point data the examples write along their beams' centerlines (ResultsLayout::
// centerline_fields), so ParaView can colour the rods: the reference arc length from the root
// and the velocity, both at the points of a core::CenterlineSampler (RecordedCenterline).
#include <spar/spar.hpp>

#include <vector>

namespace spar::examples {

/// The fields, in the order centerline_fields() fills them.
inline std::vector<core::CenterlineField> centerline_field_layout() {
  return {{.name = "arc_length", .unit = "m",
           .description = "arc length from the root on the reference centerline (sums of the sample's chords: "
                          "exact for straight beams)"},
          {.name = "velocity", .unit = "m/s",
           .description = "velocity of the centerline point, inertial frame", .components = 3}};
}

/// One beam's centerline as the results file records it: its sample points (the NURBS basis
/// computed once) and their reference arc lengths from the root.
class RecordedCenterline {
public:
  /// `points` samples of `beam`; the arc lengths are the cumulative chord lengths of the sampled
  /// `reference` centerline (exact for a straight beam).
  RecordedCenterline(const core::GeometricallyExactBeam& beam, int points, const core::Configuration& reference)
      : points_(beam, points), arc_length_(Eigen::MatrixXd::Zero(points, 1)) {
    const Eigen::MatrixXd x0 = points_.positions(reference);
    for (int i = 1; i < points; ++i) arc_length_(i, 0) = arc_length_(i - 1, 0) + (x0.row(i) - x0.row(i - 1)).norm();
  }

  /// The centerline in q, points × 3 (ResultsStep::centerlines).
  Eigen::MatrixXd positions(const core::Configuration& q) const { return points_.positions(q); }
  /// The fields in centerline_field_layout() order (ResultsStep::centerline_fields).
  std::vector<Eigen::MatrixXd> fields(const core::Configuration& q, const Eigen::VectorXd& velocity) const {
    return {arc_length_, points_.velocities(q, velocity)};
  }

private:
  core::CenterlineSampler points_;
  Eigen::MatrixXd arc_length_;
};

}  // namespace spar::examples
