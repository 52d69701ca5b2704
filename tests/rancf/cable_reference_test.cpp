// Curved stress-free cables (elements/cable/cable_reference.hpp, docs/rancf.md "Curved cables"): the exact
// arc of 000 eq. (43) cut at any breakpoints with one slope per node, reference strains and their
// material derivatives against differences, elements built on the reference free of stress, the
// Jacobians of both elements with a reference against central differences, and clear errors.
#include <spar/elements/cable/cable_reference.hpp>
#include <spar/elements/cable/rancf_cable_element.hpp>
#include <spar/elements/cable/rancf_segmentation.hpp>
#include <spar/elements/cable/sliding_cable.hpp>
#include <spar/error.hpp>
#include <spar/solvers/generalized_alpha.hpp>
#include <spar/iga/rational_bezier.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rancf_fixtures.hpp"

using namespace spar;
using Catch::Contains;

namespace {

constexpr double pi = std::numbers::pi;

/// The lower semicircle of radius 2 m from (0, 0) to (4, 0) through (2, −2) (000 §6.3).
iga::CircularArc<2> lower_semicircle() {
  iga::CircularArc<2> arc;
  arc.center = Eigen::Vector2d(2.0, 0.0);
  arc.radius = 2.0;
  arc.start_angle = pi;
  arc.sweep = pi;
  return arc;
}

/// The point of element k of `reference` at u, from its nodes and weights as a RANCF element
/// holds them (000 eqs. (6), (9)).
Eigen::Vector2d element_point(const core::CableReference& reference, int k, double u) {
  const double l = reference.breakpoints()[k + 1] - reference.breakpoints()[k];
  const Eigen::Vector4d s = iga::rancf_shape_functions(u, reference.weights(k), l);
  const Eigen::Vector4d a = reference.node(k), b = reference.node(k + 1);
  return s(0) * a.head<2>() + s(1) * a.tail<2>() + s(2) * b.head<2>() + s(3) * b.tail<2>();
}

/// A curve that is not an arc: its strains vary along it, so every term of eq. R5a is exercised.
core::CableReference wavy_reference() {
  iga::RationalBezier<2> piece{iga::RationalBezier<2>::Points(2, 4), Eigen::Vector4d(1.0, 0.8, 1.3, 0.9)};
  piece.points << 0.0, 0.7, 1.5, 2.1, 0.0, 0.3, -0.2, 0.1;
  return core::CableReference({piece}, {0.0, 2.0});
}

}  // namespace

TEST_CASE("the exact arc reference: nodes on the circle, 000 eq. (43)'s weights and slopes",
          "[rancf][reference][validation]") {
  const iga::CircularArc<2> arc = lower_semicircle();
  const double R = arc.radius, L = pi * R;
  const int N = 8;
  std::vector<double> uniform;
  for (int i = 0; i <= N; ++i) uniform.push_back(i * L / N);
  const core::CableReference reference = core::CableReference::circular_arc(arc, uniform);
  const double theta = pi / N;
  for (int i = 0; i <= N; ++i) {
    const Eigen::Vector4d node = reference.node(i);
    // Round-off of a few trigonometric evaluations on coordinates of size R.
    CHECK(std::abs((node.head<2>() - arc.center).norm() - R) <= 1e-14 * R);
    CHECK(node.tail<2>().norm() == Approx(2 * std::sin(theta / 2) / theta).epsilon(1e-13));
  }
  // The chain's factors go through logarithms and exponentials of the end speeds: 1e-13.
  for (int k = 0; k < N; ++k) {
    CHECK(reference.weights(k)(1) == Approx((1 + 2 * std::cos(theta / 2)) / 3).epsilon(1e-13));
    CHECK(reference.weights(k)(2) == Approx((1 + 2 * std::cos(theta / 2)) / 3).epsilon(1e-13));
    CHECK(reference.weights(k)(3) == Approx(1.0).epsilon(1e-13));
  }
  // Breakpoints of a sliding cable's first mesh (two unequal elements around the slider): each
  // element, from the shared nodal slopes and its own weights, is still the exact arc, and the
  // slopes' magnitudes differ from eq. (43)'s only by the reparameterization that makes them shared.
  const std::vector<double> uneven = {0.0, L / 16, 2 * L / N, 3 * L / N, 4 * L / N, 5 * L / N,
                                      6 * L / N, 7 * L / N, L};
  const core::CableReference chained = core::CableReference::circular_arc(arc, uneven);
  for (int k = 0; k < chained.elements(); ++k)
    for (int j = 0; j <= 20; ++j) {
      const Eigen::Vector2d p = element_point(chained, k, j / 20.0);
      CHECK(std::abs((p - arc.center).norm() - R) <= 1e-14 * R);
    }
  // Curvature 1/R everywhere (counter-clockwise: positive); ε₀ between the node value and 0.
  for (double x = 0.013; x < L; x += 0.097) {
    const core::ReferenceStrain<double> strain = chained.at(x);
    CHECK(strain.curvature == Approx(1 / R).epsilon(1e-13));
    CHECK(std::abs(strain.curvature_slope) <= 1e-12 / (R * R));
    CHECK(std::abs(strain.axial) <= 0.02);  // |r_x| within 2 % of 1 for spans of up to 3π/16
  }
}

TEST_CASE("reference strains: x-derivatives against differences, and through dual numbers",
          "[rancf][reference]") {
  const core::CableReference reference = wavy_reference();
  const double h = 1e-6;
  for (double x : {0.1, 0.55, 1.0, 1.7, 1.95}) {
    const core::ReferenceStrain<double> at = reference.at(x), plus = reference.at(x + h),
                                        minus = reference.at(x - h);
    INFO("x = " << x);
    // Central differences, h = 1e-6 on O(1) strains: 1e-8 covers truncation and round-off.
    CHECK(at.axial_slope == Approx((plus.axial - minus.axial) / (2 * h)).margin(1e-8));
    CHECK(at.curvature_slope == Approx((plus.curvature - minus.curvature) / (2 * h)).margin(1e-8));
    const core::ReferenceStrain<core::Dual<1>> dual = reference.at(core::Dual<1>::variable(x, 0));
    CHECK(dual.axial.value == at.axial);
    CHECK(dual.axial.grad(0) == Approx(at.axial_slope).epsilon(1e-13));
    CHECK(dual.curvature.grad(0) == Approx(at.curvature_slope).epsilon(1e-12));
    CHECK(dual.axial_slope.grad(0) == Approx((plus.axial_slope - minus.axial_slope) / (2 * h)).margin(1e-7));
    CHECK(dual.curvature_slope.grad(0) ==
          Approx((plus.curvature_slope - minus.curvature_slope) / (2 * h)).margin(1e-6));
  }
}

TEST_CASE("cables built on their reference are free of stress", "[rancf][reference]") {
  const iga::CircularArc<2> arc = lower_semicircle();
  const double L = pi * arc.radius, EA = 2.5e5;
  core::Model model;
  core::SlidingCable<2> cable(model, {.length = L, .elements = 8,
                                      .section = {.axial_stiffness = EA, .bending_stiffness = 25.0,
                                                  .mass_per_length = 9.0},
                                      .slider_position = L / 16, .slider_mass = 0.8,
                                      .shape = [&](const std::vector<double>& x) {
                                        return core::CableReference::circular_arc(arc, x);
                                      }});
  core::ElementInput in;
  in.q = &model.state();
  const core::ElementRequest request{.residual = true, .energy = true};
  double largest = 0.0;
  for (int i = 0; i < model.element_count(); ++i) {
    const core::Element& element = model.element(i);
    core::ElementOutput out;
    out.reset(core::block_dof_count(model.state(), element.blocks()), request);
    element.evaluate(in, request, out);
    largest = std::max(largest, out.residual.cwiseAbs().maxCoeff());
    CHECK(out.energy.strain <= 1e-20 * EA * L);
  }
  // Forces of size EA·(round-off of the slopes, 1e-16): 1e-9 EA is far below 000's strains.
  CHECK(largest <= 1e-9 * EA);
  // The same cable without reference strains is prestressed: κ = 1/R against 0, ε = −0.4 %.
  core::Model straight_strains;
  const Eigen::Vector4d a = cable.reference()->node(2), b = cable.reference()->node(3);
  const int node_a = straight_strains.add_vector(a), node_b = straight_strains.add_vector(b);
  const core::RancfCableElement<2> bare({.node_a = node_a, .node_b = node_b, .length = L / 8,
                                         .section = {.axial_stiffness = EA, .bending_stiffness = 25.0,
                                                     .mass_per_length = 9.0},
                                         .weights = cable.weights(2)});
  core::ElementOutput out;
  in.q = &straight_strains.state();
  out.reset(8, request);
  bare.evaluate(in, request, out);
  CHECK(out.energy.strain > 0.5 * 25.0 * (L / 8) / (arc.radius * arc.radius) * 0.99);
}

TEST_CASE("RANCF and ALE-RANCF with a reference: Jacobians against central differences",
          "[rancf][reference]") {
  const auto reference = std::make_shared<const core::CableReference>(wavy_reference());
  const Eigen::Vector3d gravity(0.3, -9.81, 0.0);
  // test::rancf_check_options, as in rancf_element_test: h = 1e-6 on O(1) coordinates, 1e-7
  // relative leaves a wide margin. In statics the residual is the gradient of the potential U + V:
  // the potential check differentiates the energies the element reports, including through ε₀(x_g),
  // κ₀(x_g) in x_A and x_B.
  for (bool dynamic : {false, true}) {
    test::RancfState s = test::random_rancf_state<2>(11, Eigen::Vector4d(1.0, 0.8, 1.3, 0.9), true);
    s.parameters.reference = reference;
    const core::AleRancfCableElement<2> ale(s.parameters);
    INFO("ALE, dynamic " << dynamic);
    test::check_rancf_derivatives(ale, s, gravity, dynamic, !dynamic);
    // The material coordinates enter through ε₀(x_g), κ₀(x_g): the force on x_A, x_B differs
    // from the element without a reference (a term that vanished would make them equal).
    test::RancfState bare = s;
    bare.parameters.reference = nullptr;
    const core::AleRancfCableElement<2> plain(bare.parameters);
    const core::ElementOutput without = test::evaluate_all(plain, s.q, nullptr, nullptr, gravity);
    CHECK(std::abs(without.residual(8) - test::evaluate_all(ale, s.q, nullptr, nullptr, gravity).residual(8)) >
          1e-3 * without.residual.cwiseAbs().maxCoeff());
  }
  test::RancfState s = test::random_rancf_state<2>(7, Eigen::Vector4d(1.0, 0.8, 1.3, 0.9), false);
  s.parameters.reference = reference;
  s.parameters.material_start = 0.4;
  const core::RancfCableElement<2> fixed(s.parameters);
  test::check_rancf_derivatives(fixed, s, gravity, true);
}

TEST_CASE("a segmentation with a reference changes the strain energy only by the quadrature error",
          "[rancf][reference][segmentation]") {
  // The split halves carry the same material, hence the same ε₀(x), κ₀(x): the exact strain
  // energy is unchanged and the Gauss sums converge to it (cf. rancf_segmentation_test).
  const auto reference = std::make_shared<const core::CableReference>(wavy_reference());
  double previous = 1.0;
  for (int points : {5, 8, 12, 16}) {
    test::RancfState s = test::random_rancf_state<2>(5, Eigen::Vector4d(1.0, 0.7, 1.4, 1.1), true);
    s.parameters.reference = reference;
    s.parameters.quadrature_points = points;
    const core::AleRancfCableElement<2> whole(s.parameters);
    const double before = test::evaluate_all(whole, s.q, nullptr, nullptr, Eigen::Vector3d::Zero()).energy.strain;
    const Eigen::VectorXd values = s.q.values;
    const core::RancfSplit<2> split = core::split_rancf_element<2>(
        values.head<8>(), values(8), values(9), s.parameters.weights, 0.37, Eigen::Matrix<double, 10, 1>::Zero());
    double after = 0.0;
    for (int half = 0; half < 2; ++half) {
      test::RancfState t = s;
      const Eigen::VectorXd h_node = split.node.head<4>();
      if (half == 0) t.q.vector(t.parameters.node_b) = h_node, t.q.vector(t.parameters.material_b)(0) = split.node(4);
      else t.q.vector(t.parameters.node_a) = h_node, t.q.vector(t.parameters.material_a)(0) = split.node(4);
      t.parameters.weights = half == 0 ? split.left_weights : split.right_weights;
      const core::AleRancfCableElement<2> part(t.parameters);
      after += test::evaluate_all(part, t.q, nullptr, nullptr, Eigen::Vector3d::Zero()).energy.strain;
    }
    const double change = std::abs(after - before) / before;
    INFO(points << " Gauss points: relative change " << change);
    CHECK(change <= 0.2 * previous);
    previous = change;
  }
  CHECK(previous <= 1e-8);
}

TEST_CASE("cable references reject what they cannot represent", "[rancf][reference]") {
  const iga::CircularArc<2> arc = lower_semicircle();
  const double L = pi * arc.radius;
  CHECK_THROWS_WITH(core::CableReference::circular_arc(arc, {0.0, L}), Contains("less than π"));
  CHECK_THROWS_WITH(core::CableReference::circular_arc(arc, {0.0, 1.0, 2.0}), Contains("arc length"));
  iga::RationalBezier<2> first{iga::RationalBezier<2>::Points(2, 2), Eigen::Vector2d::Ones()};
  iga::RationalBezier<2> second = first;
  first.points << 0.0, 1.0, 0.0, 0.0;
  second.points << 1.0, 2.0, 0.0, 0.5;  // a kink at the shared node
  CHECK_THROWS_WITH(core::CableReference({first, second}, {0.0, 1.0, 2.1}), Contains("kink"));
  second.points << 1.1, 2.1, 0.0, 0.0;  // a gap
  CHECK_THROWS_WITH(core::CableReference({first, second}, {0.0, 1.0, 2.0}), Contains("gap"));
  CHECK_THROWS_WITH(core::CableReference({first}, {0.0, 1.0, 2.0}), Contains("one piece per span"));
  CHECK_THROWS_WITH(core::CableReference({first, first}, {0.0, 1.0, 1.0}), Contains("do not increase"));
  // A spatial cable has no reference curvature direction.
  test::RancfState s = test::random_rancf_state<3>(1, Eigen::Vector4d::Ones(), false);
  s.parameters.reference = std::make_shared<const core::CableReference>(wavy_reference());
  CHECK_THROWS_WITH(core::RancfCableElement<3>(s.parameters), Contains("spatial"));
  core::Model model;
  CHECK_THROWS_WITH(core::SlidingCable<3>(model, {.shape = [](const std::vector<double>&) { return wavy_reference(); }}),
                    Contains("spatial"));
  CHECK_THROWS_WITH(core::SlidingCable<2>(model, {.length = 2.0, .elements = 4,
                                                  .section = {.axial_stiffness = 1.0, .mass_per_length = 1.0},
                                                  .shape = [](const std::vector<double>&) { return wavy_reference(); }}),
                    Contains("breakpoints"));
}

TEST_CASE("a semicircle on its reference, without gravity, stays at rest in dynamics", "[rancf][reference]") {
  // The assembled model of 000 §6.3 (pinned ends, sliding node, ALE elements next to it) is an
  // equilibrium at t = 0 when the arc is its own stress-free shape: 50 steps move nothing.
  const iga::CircularArc<2> arc = lower_semicircle();
  const double L = pi * arc.radius;
  core::Model model;
  core::SlidingCable<2> cable(model, {.length = L, .elements = 8,
                                      .section = {.axial_stiffness = 2.5e5, .bending_stiffness = 25.0,
                                                  .mass_per_length = 9.0},
                                      .slider_position = L / 16, .slider_mass = 0.8,
                                      .shape = [&](const std::vector<double>& x) {
                                        return core::CableReference::circular_arc(arc, x);
                                      }});
  std::vector<int> fixed = cable.fixed_dofs(model.state());
  for (int end : {cable.chain().front(), cable.chain().back()})
    for (int i = 0; i < 2; ++i) fixed.push_back(model.state().blocks[end].offset + i);
  std::sort(fixed.begin(), fixed.end());
  model.set_fixed_dofs(fixed);
  const Eigen::VectorXd start = model.state().values;
  solvers::GeneralizedAlpha integrator(model, {}, {.time_step = 1e-3, .tolerance = 1e-16, .residual_tolerance = 1e-9});
  integrator.initialize();
  for (int step = 0; step < 50; ++step) integrator.step();
  // Residual forces of size 1e-9 EA at most (see above) move nothing measurable in 0.05 s.
  CHECK((model.state().values - start).cwiseAbs().maxCoeff() <= 1e-12);
}
