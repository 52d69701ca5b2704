// The sliding joint in statics (003 eqs. 50–51; docs/joints.md §2.5): a weight hung on a curved
// flexible carrier finds its equilibrium where the carrier's tangent is horizontal, through the
// frictionless condition x_B,ζ · λ = 0 alone (ζ has no stiffness and no mass). At λ = 0 that
// makes the tangent singular (ζ's only entry is −x_B,ζζ·λ): without the static solver's
// balancing multipliers at the first load step, every load step fails with a singular tangent,
// however small (seen: "did not converge from load factor 0 to 9.8e-05").
#include <spar/spar.hpp>
#include <spar/joints/sliding_joint.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace spar;

TEST_CASE("sliding joint in statics: a weight on a clamped circular carrier settles at its lowest point",
          "[statics][sliding]") {
  constexpr double pi = std::numbers::pi;
  core::Model model;
  // The carrier: a 200° arc of radius 1 m in the X-Z plane, lowest at the origin, clamped at both
  // ends; a steel 1 × 1 cm bar (its sag under 9.81 N is symmetric). The exact arc is three
  // rational quadratic pieces joined with double knots (C⁰ in the parameter); the lowest point is
  // the middle of the middle piece. (With two pieces it would sit on the knot, where x_B,ζζ jumps:
  // Newton then bounces between the pieces' linearizations and never settles.)
  const iga::CircularArc<3> arc{.center = Eigen::Vector3d(0, 0, 1), .x_axis = Eigen::Vector3d::UnitX(),
                                .y_axis = Eigen::Vector3d::UnitZ(), .radius = 1.0,
                                .start_angle = -190.0 * pi / 180.0, .sweep = 200.0 * pi / 180.0};
  const core::Material steel{.young_modulus = 2.1e11, .poisson_ratio = 0.3, .density = 7850};
  const core::CrossSection bar = core::CrossSection::rectangle(0.01, 0.01, 0.3);
  const int carrier = core::add_beam(model, {.centerline = iga::circular_arc(arc),
                                      .stiffness = core::SectionStiffness::from(steel, bar),
                                      .section_axis_hint = Eigen::Vector3d::UnitY()});
  const core::GeometricallyExactBeam& beam = core::beam(model, carrier);
  model.fix(beam.node(0));
  model.fix(beam.node(beam.control_point_count() - 1));
  // The weight: 1 kg at ζ₀ = 0.4 L₀ on the carrier (a point: its rotation fixed), gravity −Z.
  const double length = 200.0 * pi / 180.0;
  joints::SlidingJointParameters parameters{.carrier = core::beam_centerline(model, carrier), .zeta = 0.4 * length, .name = "weight"};
  const double u0 = 0.4;  // the arc's parameter is symmetric about its middle, u = 0.5 (ζ = L₀/2)
  REQUIRE(iga::circular_arc(arc).knots().basis_count() == 7);  // three pieces
  const Eigen::Vector3d start = beam.position_at(model.state(), u0);
  const int weight = core::rigid_body(model, core::add_rigid_body(model,
      {.center_of_mass = start, .mass = 1.0, .inertia = 1e-4 * Eigen::Matrix3d::Identity()})).node;
  model.fix(weight, core::Fix::rotations);
  model.set_gravity(Eigen::Vector3d(0, 0, -9.81));
  parameters.slider = joints::Attachment{weight};
  joints::SlidingJoint joint(parameters, model);
  REQUIRE(std::abs(joint.carrier_length() - length) <= 1e-12);
  REQUIRE((joint.carrier_point(model.state()) - start).norm() <= 1e-12);  // assembled start

  const solvers::StaticReport report = solvers::solve_static(model, {}, {&joint});
  const core::Configuration& q = model.state();
  // By symmetry the loaded carrier's lowest point stays at its middle: ζ = L₀/2 and the weight at
  // X = 0, to the Newton tolerance.
  CHECK(std::abs(joint.zeta(q) - 0.5 * length) <= 1e-9);
  CHECK(std::abs(q.position[weight].x()) <= 1e-9);
  CHECK((q.position[weight] - joint.carrier_point(q)).norm() <= 1e-10);
  // The multiplier carries the weight, and is normal to the carrier (the frictionless condition).
  REQUIRE(report.multipliers.size() == 3);
  CHECK(std::abs(report.multipliers.norm() - 9.81) <= 1e-9);
  CHECK(std::abs(report.multipliers.x()) <= 1e-9);
  // The carrier sagged under the weight, by less than a millimetre (EI = 175 N m², 9.81 N).
  CHECK(q.position[weight].z() < 0.0);
  CHECK(q.position[weight].z() > -1e-3);
}
