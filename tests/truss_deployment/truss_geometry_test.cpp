// The truss unit's geometry (examples/truss_deployment/truss_model.hpp, README "Geometry") and its
// joints at t = 0 (the deployment laws, joints::motion_law: tests/joints/motion_law_test.cpp).
#include "truss_model.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

using namespace spar;
using examples::TrussParameters;

namespace {

constexpr double pi = std::numbers::pi;

/// Every constraint's |Φ|∞ at (q, t).
double largest_violation(const examples::TrussUnit& unit, double t) {
  double largest = 0.0;
  for (const auto& joint : unit.joints) {
    Eigen::VectorXd phi(joint->equation_count());
    joint->value(unit.model.state(), t, phi);
    if (phi.size() > 0) largest = std::max(largest, phi.lpNorm<Eigen::Infinity>());
  }
  return largest;
}

}  // namespace

TEST_CASE("truss geometry: the side diagonal's slide distance solves the sheared face, and locks at a when deployed",
          "[truss]") {
  const TrussParameters p;
  for (const double beta : {5.0, 30.0, 47.5, 75.0, 90.0}) {
    const double b = beta * pi / 180.0, s = examples::slide_distance(b, p);
    // |b d + s e_z| = √(a² + b²) (the diagonal's length) for bay 0's rising bars: exact up to
    // round-off of numbers of size 4.
    const Eigen::Vector3d diagonal = p.bar_length * examples::bar_direction(0, b) + s * Eigen::Vector3d::UnitZ();
    CHECK(std::abs(diagonal.norm() - std::sqrt(20.0)) <= 1e-14);
    CHECK(std::abs(examples::angle_from_slide(s, p) - b) <= 1e-7);  // acos near 90°: 1e-7 rad of 1e-15
  }
  CHECK(std::abs(examples::slide_distance(pi / 2, p) - p.frame_side) <= 1e-15);
  CHECK(std::abs(examples::slide_distance(5.0 * pi / 180.0, p) - 0.473748097) <= 1e-9);
  // Deployed: frames at X = 0, 4, 8 and frame 2 level with frame 0 (the Z fold), D at (8, 0, 2).
  CHECK((examples::corner(2, 0, 1, pi / 2, p) - Eigen::Vector3d(8, 0, 2)).norm() <= 1e-14);
  CHECK((examples::corner(1, 0, 0, 5.0 * pi / 180.0, p) - Eigen::Vector3d(4 * std::sin(5 * pi / 180), 0, 4 * std::cos(5 * pi / 180))).norm() <= 1e-14);
}

TEST_CASE("truss geometry: a top or bottom diagonal turns against the frames, so clamping it would weld the bay",
          "[truss]") {
  // 003 says the top and bottom diagonals are clamped to the frames. The frames translate (the
  // bay is a parallelogram linkage), and the face diagonal from corner (y 0, z) of frame k to
  // corner (y 1, z) of frame k + 1 turns about Y with the bars: its direction at β is its
  // direction at β₀ turned by β − β₀ about Y. A clamp keeps its rotation relative to the frame, so
  // it would hold β = β₀. The model joins these diagonals with hinges about Y (README, "Decisions").
  const TrussParameters p;
  const auto direction = [&](double beta) {
    return (examples::corner(1, 1, 1, beta, p) - examples::corner(0, 0, 1, beta, p)).normalized();
  };
  const double beta0 = p.initial_angle, beta1 = 60.0 * pi / 180.0;
  const Eigen::Vector3d turned = Eigen::AngleAxisd(beta1 - beta0, Eigen::Vector3d::UnitY()) * direction(beta0);
  CHECK((turned - direction(beta1)).norm() <= 1e-14);
  CHECK(std::acos(direction(beta0).dot(direction(beta1))) > 0.5);  // far from a rigid attachment
}

TEST_CASE("truss model: 28 members and every joint satisfied at t = 0 to 1e-12", "[truss]") {
  for (const int elements : {1, 4}) {
    TrussParameters p;
    p.elements = elements;
    examples::TrussUnit unit = examples::build_truss_unit(p);
    CHECK(unit.members.size() == 28);
    // 8 corner clamps (frames 1, 2), 8 cross-bars and 4 face diagonals hinged at both ends,
    // 4 side-diagonal hinges, 4 sliding joints.
    CHECK(unit.joints.size() == 8 + 16 + 8 + 4 + 4);
    CHECK(largest_violation(unit, 0.0) <= 1e-12);
    for (const auto& slider : unit.sliders) {
      CHECK(std::abs(slider.joint->zeta(unit.model.state()) - (slider.bay == 0 ? 0.4737481 : 2 - 0.4737481)) <= 1e-7);
      CHECK(slider.joint->event_distance(unit.model.state()) > 0.47);
    }
    examples::add_deployment_drivers(unit, "cosine", 20.0);
    CHECK(unit.joints.size() == 40 + 4);
    CHECK(largest_violation(unit, 0.0) <= 1e-12);
    CHECK(unit.model.state().position[unit.d_node].isApprox(Eigen::Vector3d(8 * std::sin(p.initial_angle), 0, 2), 1e-14));
  }
}

TEST_CASE("truss model: 003's linear law from rest starts impulsively in the default mass metric", "[truss]") {
  // The linear law (003 eq. 54) turns the drivers at a finite rate from t = 0 while the unit is
  // at rest: the initial assembly must give velocities, and the metric decides which. The mass
  // metric (DynamicOptions' default, τ = 0) gives the impulse through the drivers: the driven
  // hinges jump to the law's rate and the members follow as far as the joints force them — 003's
  // rate jump at t = 0, whose ringing its Figures 10–11 show. τ = 1 s (M + τ²K) instead gives the
  // whole unit the rigid deployment motion: a velocity change many times larger (measured, one
  // element per member: 0.0742 against 0.565 m/s; bound: 3 times; with 4 elements 0.074 against
  // 0.56 m/s, and D_x(2 s) 1.748 against 1.861 m). The cosine
  // law starts at rate 0: consistent as built, both metrics leave it bit for bit. docs/dynamics.md
  // D6a: why τ = 0 stays the default.
  auto velocity_change = [](const std::string& law, double tau) {
    examples::TrussParameters p;
    p.elements = 1;
    examples::TrussUnit unit = examples::build_truss_unit(p);
    examples::add_deployment_drivers(unit, law, 20.0);
    solvers::GeneralizedAlpha integrator(unit.model, std::move(unit.joints),
                                         {.time_step = 5e-3, .constraint_tolerance = 1e-10,
                                          .initial_velocity_stiffness_time = tau});
    integrator.initialize();
    return integrator.initial_assembly().largest_velocity_change;
  };
  CHECK(solvers::DynamicOptions{}.initial_velocity_stiffness_time == 0.0);
  const double impulsive = velocity_change("linear", 0.0), rigid = velocity_change("linear", 1.0);
  INFO("largest velocity change of the linear law's start: " << impulsive << " (mass metric), " << rigid
                                                              << " (tau = 1 s)");
  CHECK(impulsive > 0.0);
  CHECK(rigid > 3.0 * impulsive);
  CHECK(velocity_change("cosine", 0.0) == 0.0);
  CHECK(velocity_change("cosine", 1.0) == 0.0);
}
