#pragma once
// The point data the examples write along their beams' centerlines (ResultsLayout::
// centerline_fields), so ParaView can colour the rods: the reference arc length from the root
// and the velocity, both at the points of a core::CenterlineSampler.
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

/// Reference arc length from the root at the sampler's points: the cumulative chord lengths of
/// the sampled reference centerline (exact for a straight beam), points × 1.
inline Eigen::MatrixXd reference_arc_length(const core::CenterlineSampler& points, const core::Configuration& reference) {
  const Eigen::MatrixXd x0 = points.positions(reference);
  Eigen::MatrixXd s = Eigen::MatrixXd::Zero(points.size(), 1);
  for (int i = 1; i < points.size(); ++i) s(i, 0) = s(i - 1, 0) + (x0.row(i) - x0.row(i - 1)).norm();
  return s;
}

/// One beam's fields for ResultsStep::centerline_fields, in centerline_field_layout() order.
inline std::vector<Eigen::MatrixXd> centerline_fields(const core::CenterlineSampler& points,
                                                      const Eigen::MatrixXd& arc_length, const core::Configuration& q,
                                                      const Eigen::VectorXd& velocity) {
  return {arc_length, points.velocities(q, velocity)};
}

}  // namespace spar::examples
