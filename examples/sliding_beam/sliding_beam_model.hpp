#pragma once
// The eccentric sliding beam of 003 §5.2, Table 3: shared by the example and its validation test.
#include <spar/spar.hpp>
#include <spar/joints/joints.hpp>

#include <memory>

namespace spar::examples {

/// The model (carrier, sliding beam, tip mass), its joints, and where things are.
struct SlidingBeam {
  core::Model model;
  solvers::ConstraintList joints;
  int carrier = 0, sliding = 0;  ///< beam indices
  int mass_node = 0;
  const joints::SlidingJoint* slide = nullptr;  ///< owned by `joints` (then by the integrator)
};

/// 003 Table 3: the carrier from A = (0, 3, 1) to B = (0, 0, 0) m with `carrier_elements`
/// C^{p−1} elements of degree `degree` (003: quadratic), pinned at both ends to the ground (spherical joints); the sliding beam
/// from A to M = (1, 3, 1) m with `sliding_elements`; both 0.01 × 0.01 m, E = 2e8 Pa, ν = 0.3,
/// ρ = 800 kg/m³; a 1 kg point mass at M (a rigid body pinned to the sliding beam's tip, its
/// rotational inertia — a 1 kg sphere of 1 cm radius — never loaded); the sliding beam's end at A
/// slides along the carrier (ζ₀ = 0) and locks at B (ζ = L); gravity 9.81 m/s² along −Z.
inline SlidingBeam build_sliding_beam(int carrier_elements, int sliding_elements, int degree = 2) {
  const Eigen::Vector3d A(0, 3, 1), B(0, 0, 0), M(1, 3, 1);
  const core::Material material{.young_modulus = 2e8, .poisson_ratio = 0.3, .density = 800};
  const core::CrossSection section = core::CrossSection::rectangle(0.01, 0.01, material.poisson_ratio);
  const core::SectionStiffness stiffness = core::SectionStiffness::from(material, section);
  const core::SectionInertia inertia = core::SectionInertia::from(material, section);
  SlidingBeam s;
  core::Model& model = s.model;
  s.carrier = core::add_beam(model, {.centerline = iga::straight_line<3>(A, B, carrier_elements, degree),
                              .stiffness = stiffness, .inertia = inertia,
                              .section_axis_hint = Eigen::Vector3d::UnitX()});
  s.sliding = core::add_beam(model, {.centerline = iga::straight_line<3>(A, M, sliding_elements, degree),
                              .stiffness = stiffness, .inertia = inertia});
  const core::GeometricallyExactBeam& carrier = core::beam(model, s.carrier);
  const core::GeometricallyExactBeam& sliding = core::beam(model, s.sliding);
  s.mass_node = core::rigid_body(model, core::add_rigid_body(model,
      {.center_of_mass = M, .mass = 1.0, .inertia = 4e-5 * Eigen::Matrix3d::Identity()})).node;
  model.set_gravity(Eigen::Vector3d(0, 0, -9.81));

  const core::Configuration& q0 = model.state();
  const int carrier_end = carrier.node(carrier.control_point_count() - 1);
  s.joints.push_back(std::make_unique<joints::SphericalJoint>(
      joints::attach_at(carrier.node(0), A, q0), joints::attach_at(-1, A, q0), q0));
  s.joints.push_back(std::make_unique<joints::SphericalJoint>(
      joints::attach_at(carrier_end, B, q0), joints::attach_at(-1, B, q0), q0));
  s.joints.push_back(std::make_unique<joints::SphericalJoint>(
      joints::attach_at(sliding.node(sliding.control_point_count() - 1), M, q0),
      joints::attach_at(s.mass_node, M, q0), q0));
  auto slide = std::make_unique<joints::SlidingJoint>(
      joints::SlidingJointParameters{.slider = joints::attach_at(sliding.node(0), A, model.state()),
                                     .carrier = core::beam_centerline(model, s.carrier), .zeta = 0.0, .upper_stop = (B - A).norm(),
                                     .name = "slider at A"},
      model);
  s.slide = slide.get();
  s.joints.push_back(std::move(slide));
  return s;
}

}  // namespace spar::examples
