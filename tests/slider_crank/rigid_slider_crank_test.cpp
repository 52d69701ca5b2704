// The Lagrange multipliers are the numbers users publish as joint forces and driving torques:
// here those of a rigid slider-crank driven at constant crank speed, against its closed-form
// kinematics and the Newton–Euler balance of its three bodies (an independent reference: no
// matrix of spar enters it); and the accelerations they balance, the slider's and the coupler's
// angular one, against the same kinematics.
#include <spar/joints/joints.hpp>
#include <spar/solvers/generalized_alpha.hpp>
#include <spar/spar.hpp>

#include <Eigen/LU>
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

using namespace spar;

namespace {

// Steel rods 0.03 × 0.03 m as in 003 §5.1 (rigid here), the 0.1 kg slider; the crank turns at
// ω = 20 rad/s about Z from the X axis, gravity along −Y in the plane of motion.
constexpr double L1 = 0.3, L2 = 0.6, side = 0.03, density = 7850, omega = 20.0, g = 9.81;
constexpr double m1 = density * side * side * L1, m2 = density * side * side * L2, m3 = 0.1;

/// The planar 2D cross product r × F (its Z component).
double cross(const Eigen::Vector2d& r, const Eigen::Vector2d& F) { return r.x() * F.y() - r.y() * F.x(); }

/// Reactions at crank angle θ = ω t: F_A on the coupler from the crank, F_B on the slider from the
/// coupler, the rail's normal force N on the slider and the driving torque τ on the crank; and the
/// accelerations they go with: the slider's a_B (along X) and the coupler's angular φ̈ (about Z).
struct Reactions {
  Eigen::Vector2d F_A, F_B;
  double N = 0.0, tau = 0.0;
  double slider_acceleration = 0.0, coupler_angular_acceleration = 0.0;
};

/// Closed-form kinematics (L1 sin θ + L2 sin φ = 0 and its time derivatives, θ̈ = 0) and
/// Newton–Euler for the slider (x, y), the coupler (x, y, moment about its centre) and the crank
/// (moment about the pivot, where the ground's force has no arm): six linear equations in
/// (F_A, F_B, N, τ).
Reactions newton_euler(double t) {
  const double theta = omega * t, phi = std::asin(-L1 * std::sin(theta) / L2);
  const double phi_dot = -L1 * std::cos(theta) * omega / (L2 * std::cos(phi));
  const double phi_ddot =
      (L1 * std::sin(theta) * omega * omega + L2 * std::sin(phi) * phi_dot * phi_dot) / (L2 * std::cos(phi));
  const Eigen::Vector2d e1(std::cos(theta), std::sin(theta)), e2(std::cos(phi), std::sin(phi));
  const Eigen::Vector2d n2(-std::sin(phi), std::cos(phi));
  const Eigen::Vector2d A = L1 * e1, G1 = 0.5 * L1 * e1, G2 = A + 0.5 * L2 * e2, B = A + L2 * e2;
  const Eigen::Vector2d a_A = -omega * omega * A;
  const Eigen::Vector2d a_G2 = a_A + 0.5 * L2 * (phi_ddot * n2 - phi_dot * phi_dot * e2);
  const Eigen::Vector2d a_B = a_A + L2 * (phi_ddot * n2 - phi_dot * phi_dot * e2);
  const Eigen::Vector2d gravity(0.0, -g);
  const double I2 = m2 * (L2 * L2 + side * side) / 12;  // the coupler (a square bar) about Z
  // Unknowns u = (F_Ax, F_Ay, F_Bx, F_By, N, τ).
  Eigen::Matrix<double, 6, 6> E = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 6, 1> rhs;
  E(0, 2) = 1;  // slider x: F_Bx = m₃ a_Bx
  rhs(0) = m3 * a_B.x();
  E(1, 3) = 1;  // slider y: F_By + N + m₃ g_y = 0 (it stays on the rail)
  E(1, 4) = 1;
  rhs(1) = -m3 * gravity.y();
  E(2, 0) = 1;  // coupler x: F_Ax − F_Bx + m₂ g_x = m₂ a_G2x
  E(2, 2) = -1;
  rhs(2) = m2 * (a_G2.x() - gravity.x());
  E(3, 1) = 1;  // coupler y
  E(3, 3) = -1;
  rhs(3) = m2 * (a_G2.y() - gravity.y());
  // coupler moment about G2: (A − G2) × F_A − (B − G2) × F_B = I₂ φ̈
  E(4, 0) = -(A - G2).y();
  E(4, 1) = (A - G2).x();
  E(4, 2) = (B - G2).y();
  E(4, 3) = -(B - G2).x();
  rhs(4) = I2 * phi_ddot;
  // crank moment about the pivot: τ − A × F_A + G1 × m₁g = I_O θ̈ = 0
  E(5, 5) = 1;
  E(5, 0) = A.y();
  E(5, 1) = -A.x();
  rhs(5) = -cross(G1, m1 * gravity);
  const Eigen::Matrix<double, 6, 1> u = E.fullPivLu().solve(rhs);
  return {u.head<2>(), u.segment<2>(2), u(4), u(5), a_B.x(), phi_ddot};
}

/// Integrates the rigid mechanism with step h to t_end and returns the largest differences of the
/// multipliers from the Newton–Euler reactions and of the accelerations from the kinematics over
/// the steps from t_from on, relative to the largest reaction (acceleration) of the run, and the
/// largest constraint residual of the run.
struct MultiplierErrors {
  double torque = 0.0, coupler_force = 0.0, slider_force = 0.0, constraint = 0.0;
  double slider_acceleration = 0.0, coupler_angular_acceleration = 0.0;
  solvers::Energies energies;  ///< at the end of the run
};

/// The observed order of one error between two runs whose step sizes differ by 2.
double order(const MultiplierErrors& coarse, const MultiplierErrors& fine, double MultiplierErrors::*error) {
  return std::log2(coarse.*error / fine.*error);
}

MultiplierErrors run(double h, double t_from, double t_end, bool perturbed_start = false) {
  core::Model model;
  const auto rod = [](double m, double L) {
    // A square bar, body X along it: m s²/6 about X, m (L² + s²)/12 about Y and Z.
    return Eigen::Vector3d(m * side * side / 6, m * (L * L + side * side) / 12, m * (L * L + side * side) / 12)
        .asDiagonal()
        .toDenseMatrix();
  };
  const int crank = core::rigid_body(model, core::add_rigid_body(model,
      {.center_of_mass = Eigen::Vector3d(L1 / 2, 0, 0), .mass = m1, .inertia = rod(m1, L1)})).node;
  const int coupler = core::rigid_body(model, core::add_rigid_body(model,
      {.center_of_mass = Eigen::Vector3d(L1 + L2 / 2, 0, 0), .mass = m2, .inertia = rod(m2, L2)})).node;
  const int slider = core::rigid_body(model, core::add_rigid_body(model,
      {.center_of_mass = Eigen::Vector3d(L1 + L2, 0, 0), .mass = m3,
       .inertia = Eigen::Matrix3d::Identity() * m3 * 0.02 * 0.02 / 6})).node;
  model.set_gravity(Eigen::Vector3d(0, -g, 0));
  const core::Configuration& q0 = model.state();
  const Eigen::Vector3d O(0, 0, 0), A(L1, 0, 0), B(L1 + L2, 0, 0);
  solvers::ConstraintList joints;
  joints.push_back(std::make_unique<joints::AngleDriver>(crank, Eigen::Vector3d::UnitZ(),
                                                         joints::TimeFunction::linear(omega), q0));
  joints.push_back(std::make_unique<joints::SphericalJoint>(joints::attach_at(crank, O, q0),
                                                            joints::Attachment{-1, O}, q0));
  joints.push_back(std::make_unique<joints::SphericalJoint>(joints::attach_at(crank, A, q0),
                                                            joints::attach_at(coupler, A, q0), q0));
  joints.push_back(std::make_unique<joints::SphericalJoint>(joints::attach_at(coupler, B, q0),
                                                            joints::attach_at(slider, B, q0), q0));
  joints.push_back(std::make_unique<joints::PrismaticJoint>(joints::Attachment{slider}, O,
                                                            Eigen::Vector3d::UnitX(), true, q0));
  solvers::GeneralizedAlpha integrator(model, std::move(joints),
                                       {.time_step = h, .spectral_radius = 0.9, .tolerance = 1e-20,
                                        .constraint_tolerance = 1e-12, .residual_tolerance = 1e-10,
                                        .perturbed_starting_values = perturbed_start});
  // Consistent velocities at θ = 0: φ = 0, φ̇ = −ω L1/L2, the coupler's centre at ω L1/2 along Y,
  // the slider at rest.
  integrator.set_velocity(crank, Eigen::Vector3d(0, omega * L1 / 2, 0), Eigen::Vector3d(0, 0, omega));
  integrator.set_velocity(coupler, Eigen::Vector3d(0, omega * L1 / 2, 0), Eigen::Vector3d(0, 0, -omega * L1 / L2));
  integrator.set_velocity(slider, Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero());
  integrator.initialize();

  MultiplierErrors errors;
  double scale_force = 0.0, scale_torque = 0.0;
  std::vector<double> times;
  std::vector<Reactions> reference;
  std::vector<Eigen::VectorXd> multipliers;
  // v̇ of the slider's translation along X and of the coupler's material rotation about Z (its
  // body Z stays the inertial Z in the plane motion, so Ω̇_z = φ̈).
  const int slider_x = model.state().blocks[slider].offset, coupler_z = model.state().blocks[coupler].offset + 5;
  std::vector<Eigen::Vector2d> accelerations;
  const auto record = [&] {
    times.push_back(integrator.time());
    reference.push_back(newton_euler(integrator.time()));
    multipliers.push_back(integrator.multipliers());
    accelerations.emplace_back(integrator.acceleration()(slider_x), integrator.acceleration()(coupler_z));
    errors.constraint = std::max(errors.constraint, integrator.constraint_residual());
  };
  record();
  while (integrator.time() < t_end - 0.5 * h) {
    integrator.step();
    record();
  }
  errors.energies = integrator.energies();
  double scale_slider = 0.0, scale_coupler = 0.0;
  for (const Reactions& r : reference) {
    scale_force = std::max({scale_force, r.F_A.norm(), r.F_B.norm()});
    scale_torque = std::max(scale_torque, std::abs(r.tau));
    scale_slider = std::max(scale_slider, std::abs(r.slider_acceleration));
    scale_coupler = std::max(scale_coupler, std::abs(r.coupler_angular_acceleration));
  }
  for (std::size_t k = 0; k < reference.size(); ++k) {
    if (times[k] < t_from - 0.5 * h) continue;
    // −Bᵀλ is the constraint force on the blocks (M v̇ + Bᵀλ = −f). Driver: B = (Rᵀn)ᵀ in the
    // crank's rotation columns at φ = f, so the torque on the crank is −λ₀. Spherical joint
    // Φ = p_a − p_b: the force on b (coupler at A, slider at B) is +λ.
    const Eigen::VectorXd& lambda = multipliers[k];
    const Reactions& r = reference[k];
    errors.torque = std::max(errors.torque, std::abs(-lambda(0) - r.tau) / scale_torque);
    errors.coupler_force = std::max(
        errors.coupler_force, (Eigen::Vector3d(r.F_A.x(), r.F_A.y(), 0) - lambda.segment<3>(4)).norm() / scale_force);
    errors.slider_force = std::max(
        errors.slider_force, (Eigen::Vector3d(r.F_B.x(), r.F_B.y(), 0) - lambda.segment<3>(7)).norm() / scale_force);
    errors.slider_acceleration = std::max(
        errors.slider_acceleration, std::abs(accelerations[k](0) - r.slider_acceleration) / scale_slider);
    errors.coupler_angular_acceleration =
        std::max(errors.coupler_angular_acceleration,
                 std::abs(accelerations[k](1) - r.coupler_angular_acceleration) / scale_coupler);
  }
  return errors;
}

}  // namespace

TEST_CASE("rigid slider-crank: multipliers are the Newton-Euler joint forces and driving torque",
          "[dynamics][slider_crank][validation]") {
  // Two regimes, both measured over the first 0.08 s (1.6 rad of crank):
  //  - from t = 0 the multipliers carry a start-up error that alternates in sign from step to step
  //    and decays as ρ∞ = 0.9 per step, of size O(h): the index-3 method started from consistent
  //    accelerations but unperturbed α-accelerations (Arnold, Brüls & Cardona 2015). Measured
  //    largest torque error 4.0e-2, 2.1e-2, 1.0e-2, 5.2e-3 of the largest torque (85.6 N m) for
  //    h = 1e-3 … 1.25e-4, i.e. 40 to 41.7 h/s: bounded here by 50 h/s (a start-up that grew or
  //    stopped decaying would exceed it);
  //  - once it has decayed (from t = 0.04 s: 160 steps at h = 2.5e-4, 0.9¹⁶⁰ ≈ 5e-8), the
  //    multipliers converge with order 2: torque 1.14e-5 → 2.85e-6, force at A 5.9e-6 → 1.5e-6,
  //    at B 1.4e-6 → 3.6e-7 (ratios 4.0) for h = 2.5e-4 → 1.25e-4. Checked: order ≥ 1.8 and the
  //    errors at 1.25e-4 ≤ 1e-5 (a wrong sign, joint or arm is off by O(1)).
  // The accelerations v̇ share both regimes: from t = 0 the coupler's φ̈ is off by 8.7e-3 → 4.3e-3
  // of its largest value (35 h/s; the slider's by 1.5e-5 → 3.7e-6), bound 50 h/s; from t = 0.04 s
  // the slider's a_B by 8.2e-6 → 2.0e-6 and φ̈ by 8.4e-6 → 2.1e-6 (ratios 4.0), checked as the
  // multipliers (a dropped centripetal term of the kinematics is off by O(1)).
  std::vector<MultiplierErrors> settled;
  for (const double h : {2.5e-4, 1.25e-4}) {
    const MultiplierErrors e = run(h, 0.04, 0.08), from_start = run(h, 0.0, 0.08);
    INFO("h = " << h << ": from t = 0.04 s, torque " << e.torque << ", force at A " << e.coupler_force
                << ", force at B " << e.slider_force << ", slider acceleration " << e.slider_acceleration
                << ", coupler angular acceleration " << e.coupler_angular_acceleration << "; from t = 0, torque "
                << from_start.torque << ", slider acceleration " << from_start.slider_acceleration
                << ", coupler angular acceleration " << from_start.coupler_angular_acceleration
                << "; constraint residual " << e.constraint);
    CHECK(from_start.torque <= 50 * h);
    CHECK(from_start.coupler_force <= 50 * h);
    CHECK(from_start.slider_force <= 50 * h);
    CHECK(from_start.slider_acceleration <= 50 * h);
    CHECK(from_start.coupler_angular_acceleration <= 50 * h);
    CHECK(e.constraint <= 1e-12);
    settled.push_back(e);
  }
  const MultiplierErrors& coarse = settled.front();
  const MultiplierErrors& fine = settled.back();
  INFO("orders: torque " << order(coarse, fine, &MultiplierErrors::torque) << ", force at A "
                         << order(coarse, fine, &MultiplierErrors::coupler_force) << ", force at B "
                         << order(coarse, fine, &MultiplierErrors::slider_force) << ", slider acceleration "
                         << order(coarse, fine, &MultiplierErrors::slider_acceleration)
                         << ", coupler angular acceleration "
                         << order(coarse, fine, &MultiplierErrors::coupler_angular_acceleration));
  CHECK(order(coarse, fine, &MultiplierErrors::torque) >= 1.8);
  CHECK(order(coarse, fine, &MultiplierErrors::coupler_force) >= 1.8);
  CHECK(order(coarse, fine, &MultiplierErrors::slider_force) >= 1.8);
  CHECK(fine.torque <= 1e-5);
  CHECK(fine.coupler_force <= 1e-5);
  CHECK(fine.slider_force <= 1e-5);
  CHECK(order(coarse, fine, &MultiplierErrors::slider_acceleration) >= 1.8);
  CHECK(order(coarse, fine, &MultiplierErrors::coupler_angular_acceleration) >= 1.8);
  CHECK(fine.slider_acceleration <= 1e-5);
  CHECK(fine.coupler_angular_acceleration <= 1e-5);
}

TEST_CASE("rigid slider-crank: with perturbed starting values the multipliers are second order from the "
          "first step", "[dynamics][slider_crank][validation]") {
  // DynamicOptions::perturbed_starting_values (docs/dynamics.md D6d) start the method on its
  // smooth solution, a₀ = v̇₀ + Δ_α h v̈₀ and v₀ + (1/6 − β − Δ_α/2) h² v̈₀, and remove the O(h)
  // start-up transient of the test above. Measured over the whole run from t = 0, the first steps
  // included, for h = 2.5e-4 → 1.25e-4: torque 1.7e-5 → 2.9e-6, force at A 5.2e-5 → 1.3e-5, at B
  // → 4.4e-7 of the largest reaction (orders 2.5, 2.0, 2.3), where the unperturbed start gives
  // 1.0e-2 → 5.2e-3 (order 1). With a₀ alone perturbed the errors do not move (5.2e-3): the O(h²)
  // velocity offset, amplified by the index-3 position equation, is the transient's source.
  // Checked: order ≥ 1.8 and the errors at 1.25e-4 ≤ 5e-5, 4 times the largest measured and 100
  // times below the unperturbed start's.
  std::vector<MultiplierErrors> from_start;
  for (const double h : {2.5e-4, 1.25e-4}) {
    const MultiplierErrors e = run(h, 0.0, 0.08, true);
    INFO("h = " << h << ": from t = 0, torque " << e.torque << ", force at A " << e.coupler_force
                << ", force at B " << e.slider_force << "; constraint residual " << e.constraint);
    CHECK(e.constraint <= 1e-12);
    from_start.push_back(e);
  }
  const MultiplierErrors& coarse = from_start.front();
  const MultiplierErrors& fine = from_start.back();
  INFO("orders from t = 0: torque " << order(coarse, fine, &MultiplierErrors::torque) << ", force at A "
                                    << order(coarse, fine, &MultiplierErrors::coupler_force) << ", force at B "
                                    << order(coarse, fine, &MultiplierErrors::slider_force) << "; at h = 1.25e-4: "
                                    << fine.torque << ", " << fine.coupler_force << ", " << fine.slider_force);
  CHECK(order(coarse, fine, &MultiplierErrors::torque) >= 1.8);
  CHECK(order(coarse, fine, &MultiplierErrors::coupler_force) >= 1.8);
  CHECK(order(coarse, fine, &MultiplierErrors::slider_force) >= 1.8);
  CHECK(fine.torque <= 5e-5);
  CHECK(fine.coupler_force <= 5e-5);
  CHECK(fine.slider_force <= 5e-5);
}

TEST_CASE("rigid slider-crank: the driver's work is booked, and the energy created is the method's error",
          "[dynamics][slider_crank][energy-alarm]") {
  // The crank's driver works on the mechanism (the coupler's kinetic energy and the bodies' height
  // change over 1.6 rad of crank): what the energy gained is its work, so the energy created
  // (docs/dynamics.md D8a) is the integrator's error alone, second order in h. Measured over 0.08 s:
  // work 60.6 J (scale 178 J); created 7.5e-4 and 1.9e-4 J at h = 2.5e-4 and 1.25e-4 (order 2.0).
  const MultiplierErrors coarse = run(2.5e-4, 0.0, 0.08), fine = run(1.25e-4, 0.0, 0.08);
  const solvers::Energies& e = fine.energies;
  INFO("external work " << e.external_work << " J, scale " << e.scale << " J, created " << coarse.energies.created
                        << " -> " << e.created << " J");
  CHECK(std::abs(e.external_work) > 0.1 * e.scale);
  CHECK(std::abs(e.created) < 1e-5 * e.scale);
  CHECK(std::log2(std::abs(coarse.energies.created / e.created)) > 1.8);
}
