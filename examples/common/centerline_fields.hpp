#pragma once
// The point data the examples write along their beams' centerlines (ResultsLayout::
// centerline_fields), so ParaView can colour the rods: the reference arc length from the root
// and the velocity, both at the points of GeometricallyExactBeam::sample_centerline.
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

/// Reference arc length from the root at the `points` sample parameters: the cumulative chord
/// lengths of the sampled reference centerline (exact for a straight beam), points × 1.
inline Eigen::MatrixXd reference_arc_length(const core::GeometricallyExactBeam& beam,
                                            const core::Configuration& reference, int points) {
  const Eigen::MatrixXd x0 = beam.sample_centerline(reference, points);
  Eigen::MatrixXd s = Eigen::MatrixXd::Zero(points, 1);
  for (int i = 1; i < points; ++i) s(i, 0) = s(i - 1, 0) + (x0.row(i) - x0.row(i - 1)).norm();
  return s;
}

/// Velocity ẋ(u) of the centerline at the `points` sample parameters, points × 3. The centerline
/// x(u) = Σ N_I(u) x_I is linear in the node positions (003 eq. 39), so ẋ(u) = Σ N_I(u) ẋ_I is the
/// centerline sampled with each node's ẋ (the first 3 of its 6 velocity entries) in place of x_I.
inline Eigen::MatrixXd centerline_velocity(const core::GeometricallyExactBeam& beam, const core::Configuration& q,
                                           const Eigen::VectorXd& velocity, int points) {
  core::Configuration rates = q;
  for (int I = 0; I < beam.control_point_count(); ++I)
    rates.position[beam.node(I)] = velocity.segment<3>(q.blocks[beam.node(I)].offset);
  return beam.sample_centerline(rates, points);
}

/// One beam's fields for ResultsStep::centerline_fields, in centerline_field_layout() order.
inline std::vector<Eigen::MatrixXd> centerline_fields(const core::GeometricallyExactBeam& beam,
                                                      const Eigen::MatrixXd& arc_length, const core::Configuration& q,
                                                      const Eigen::VectorXd& velocity) {
  return {arc_length, centerline_velocity(beam, q, velocity, static_cast<int>(arc_length.rows()))};
}

}  // namespace spar::examples
