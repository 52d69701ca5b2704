#pragma once
// The flexible pendulum of examples/flexible_pendulum (same rod, same pin): a 1 m steel rule,
// 30 × 1 mm (E = 2.1e11 Pa, ν = 0.3, ρ = 7850 kg/m³), along +X from the origin, pinned there by a
// spherical joint, straight and at rest at t = 0, gravity (0, 0, −9.81) m/s²; it swings in the
// XZ plane and bends about its weak axis. Open-uniform C² cubic NURBS mesh.
#include <spar/core/model.hpp>
#include <spar/joints/spherical_joint.hpp>
#include <spar/solvers/generalized_alpha.hpp>
#include <spar/elements/beam/beam.hpp>

#include <memory>

#include "beam_fixtures.hpp"

namespace spar::test {

struct FlexiblePendulum {
  core::Model model;
  solvers::ConstraintList joints;
  double mass = 0.0;          ///< kg
  double energy_scale = 0.0;  ///< m g L / 2: the potential energy released down to the vertical
};

/// The pendulum with `elements` cubic elements; its tip is core::beam(model, 0).position_at(q, 1).
/// `stiffening` multiplies Young's modulus (1e6: a practically rigid rod of the same mass).
inline FlexiblePendulum flexible_pendulum(int elements, double stiffening = 1.0) {
  const double length = 1.0, width = 0.03, thickness = 0.001;
  const core::Material steel{.young_modulus = 2.1e11 * stiffening, .poisson_ratio = 0.3, .density = 7850};
  const core::CrossSection section = core::CrossSection::rectangle(width, thickness, steel.poisson_ratio);
  FlexiblePendulum p;
  core::add_beam(p.model, {.centerline = straight_centerline(length, elements, 3),
                    .stiffness = core::SectionStiffness::from(steel, section),
                    .inertia = core::SectionInertia::from(steel, section)});
  p.model.set_gravity(Eigen::Vector3d(0.0, 0.0, -9.81));
  p.joints.push_back(std::make_unique<joints::SphericalJoint>(
      joints::Attachment{.node = core::beam(p.model, 0).node(0), .offset = Eigen::Vector3d::Zero()},
      joints::Attachment{.node = -1, .offset = Eigen::Vector3d::Zero()}, p.model.state()));
  p.mass = steel.density * width * thickness * length;
  p.energy_scale = 0.5 * p.mass * 9.81 * length;
  return p;
}

}  // namespace spar::test
