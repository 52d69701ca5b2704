// What a driver of a sliding-mass cable needs beside the cable (paper 000 §5–6, docs/rancf.md):
// RancfSection::circular, SlidingCable::fix_supports and controlled_length_ratios,
// CableReference::polynomial_interpolant, and the length-control summaries of
// elements/cable/length_control_log.hpp (000 Table 2, eq. (42)), each against values computed
// here by hand or from the cable's own accessors.
#include <spar/elements/cable/cable_reference.hpp>
#include <spar/elements/cable/length_control_log.hpp>
#include <spar/elements/cable/sliding_cable.hpp>
#include <spar/error.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

using namespace spar;
using Catch::Contains;

namespace {

constexpr double pi = std::numbers::pi;

/// 000 §6.2's suspended beam: L = 1 m, N elements, the slider at `slider_position`.
core::SlidingCable<2> suspended(core::Model& model, int elements, double slider_position) {
  return core::SlidingCable<2>(model, {.length = 1.0, .elements = elements,
                                       .section = core::RancfSection::circular(0.01, 20e6, 7200),
                                       .slider_position = slider_position, .slider_mass = 5.0});
}

core::LengthControlEvent event_with_merged_weights(double k0, double k1, double k2) {
  core::LengthControlEvent e;
  e.merged_weights = Eigen::Vector4d(k0, k1, k2, 1.0);
  return e;
}

}  // namespace

TEST_CASE("RancfSection::circular: EA, EI and rho A of a solid rod", "[rancf]") {
  const double r = 0.01, E = 20e6, rho = 7200;
  const core::RancfSection section = core::RancfSection::circular(r, E, rho);
  // A = π r², I = π r⁴/4, computed in another order: a few roundings apart.
  CHECK(section.axial_stiffness == Approx(E * pi * r * r).epsilon(1e-15));
  CHECK(section.bending_stiffness == Approx(E * pi * std::pow(r, 4) / 4).epsilon(1e-15));
  CHECK(section.mass_per_length == Approx(rho * pi * r * r).epsilon(1e-15));
  CHECK(section.damping_coefficient == 0.0);
}

TEST_CASE("weight_statistics: 000 Table 2's set of merged weights and its sigma (eq. 42)", "[rancf]") {
  const std::vector<core::LengthControlEvent> events = {event_with_merged_weights(1.2, 0.9, 1.0),
                                                        event_with_merged_weights(0.8, 1.1, 1.5)};
  const core::WeightStatistics statistics = core::weight_statistics(events);
  CHECK(statistics.count == 6u);
  CHECK(statistics.max == 1.5);
  CHECK(statistics.min == 0.8);
  // σ² = (0.04 + 0.01 + 0 + 0.04 + 0.01 + 0.25)/6; the decimal weights round, hence 1e-14.
  CHECK(statistics.sigma == Approx(std::sqrt(0.35 / 6)).epsilon(1e-14));

  const core::WeightStatistics none = core::weight_statistics({});
  CHECK(none.count == 0u);
  CHECK(none.max == 1.0);
  CHECK(none.min == 1.0);
  CHECK(none.sigma == 0.0);
}

TEST_CASE("length_control_log: one row of 29 columns per event, in the documented order", "[rancf]") {
  core::LengthControlEvent e;
  e.time = 0.25;
  e.grown_element = 3;
  e.grown_weights = Eigen::Vector4d(1, 2, 3, 4);
  e.merged_near_weights = Eigen::Vector4d(5, 6, 7, 8);
  e.merged_far_weights = Eigen::Vector4d(9, 10, 11, 12);
  e.split_weights_far = Eigen::Vector4d(13, 14, 15, 16);
  e.split_weights_near = Eigen::Vector4d(17, 18, 19, 20);
  e.merged_weights = Eigen::Vector4d(21, 22, 23, 24);
  e.merge_fallback = false;
  e.merge_bounded = true;
  e.merge_miss = 1e-7;
  const Eigen::MatrixXd log = core::length_control_log({e, e});
  REQUIRE(log.rows() == 2);
  REQUIRE(log.cols() == 29);
  CHECK(log(1, 0) == 0.25);
  CHECK(log(1, 1) == 3.0);
  for (int i = 0; i < 24; ++i) CHECK(log(1, 2 + i) == i + 1.0);  // the six weight vectors
  CHECK(log(1, 26) == 0.0);
  CHECK(log(1, 27) == 1.0);
  CHECK(log(1, 28) == 1e-7);
  CHECK(core::length_control_log({}).rows() == 0);
}

TEST_CASE("SlidingCable::fix_supports: the cable's own fixed dofs and the ends' leading coordinates", "[rancf]") {
  core::Model model;
  const core::SlidingCable<2> cable = suspended(model, 6, 0.1);
  cable.fix_supports(model, {.left = 4, .right = 2});  // clamped left, pinned right
  std::vector<int> expected = cable.fixed_dofs(model.state());
  for (int i = 0; i < 4; ++i) expected.push_back(model.state().blocks[cable.chain().front()].offset + i);
  for (int i = 0; i < 2; ++i) expected.push_back(model.state().blocks[cable.chain().back()].offset + i);
  std::sort(expected.begin(), expected.end());
  CHECK(model.fixed_dofs() == expected);

  CHECK_THROWS_WITH(cable.fix_supports(model, {.left = 5}), Contains("fix 0 to 4 coordinates"));
  CHECK_THROWS_WITH(cable.fix_supports(model, {.right = -1}), Contains("fix 0 to 4 coordinates"));
}

TEST_CASE("SlidingCable::controlled_length_ratios: all elements but the slider's two next to an end", "[rancf]") {
  // The initial mesh: elements of L_std but the two next to the slider, which span 2 L_std.
  const auto all_ratios = [](const core::SlidingCable<2>& cable, const core::Configuration& q) {
    std::vector<double> ratios;
    for (int k = 0; k + 1 < static_cast<int>(cable.chain().size()); ++k)
      ratios.push_back(cable.element_length(q, k) / cable.standard_length());
    return ratios;
  };
  {  // The slider at 0.1 m is next to the left end element: its two elements (0.6, 1.4 L_std) are left out.
    core::Model model;
    const core::SlidingCable<2> cable = suspended(model, 6, 0.1);
    const auto [shortest, longest] = cable.controlled_length_ratios(model.state());
    CHECK(std::ranges::min(all_ratios(cable, model.state())) == Approx(0.6).epsilon(1e-12));
    CHECK(shortest == Approx(1.0).epsilon(1e-12));
    CHECK(longest == Approx(1.0).epsilon(1e-12));
  }
  {  // In the middle every element counts.
    core::Model model;
    const core::SlidingCable<2> cable = suspended(model, 6, 0.45);
    const std::vector<double> ratios = all_ratios(cable, model.state());
    const auto [shortest, longest] = cable.controlled_length_ratios(model.state());
    CHECK(shortest == std::ranges::min(ratios));
    CHECK(longest == std::ranges::max(ratios));
    CHECK(shortest < 0.99);
    CHECK(longest > 1.01);
  }
}

TEST_CASE("CableReference::polynomial_interpolant: unit weights, the arc's nodes, unit slopes there", "[rancf]") {
  const double R = 2.0, L = pi * R;
  const iga::CircularArc<2> arc{.center = Eigen::Vector2d(R, 0.0), .radius = R, .start_angle = pi, .sweep = pi};
  std::vector<double> x;
  for (int i = 0; i <= 8; ++i) x.push_back(L * i / 8);
  const core::CableReference exact = core::CableReference::circular_arc(arc, x);
  const core::CableReference polynomial = exact.polynomial_interpolant();
  REQUIRE(polynomial.elements() == 8);
  CHECK(polynomial.breakpoints() == exact.breakpoints());
  for (int i = 0; i <= 8; ++i) {
    const Eigen::Vector4d a = exact.node(i), b = polynomial.node(i);
    INFO("node " << i);
    CHECK((b.head<2>() - a.head<2>()).norm() <= 1e-12 * R);
    CHECK((b.tail<2>() - a.tail<2>().normalized()).norm() <= 1e-12);  // |r_x| = 1 along the arc's tangent
    CHECK(std::abs(polynomial.at(x[i]).axial) <= 1e-12);              // so no reference stretch at the node
  }
  for (int k = 0; k < 8; ++k) CHECK((polynomial.weights(k) - Eigen::Vector4d::Ones()).norm() <= 1e-12);
}

TEST_CASE("SlidingCable: the mass, the slider's coordinate and a padded centerline across release()", "[rancf]") {
  // A detachable cable whose slider starts next to its right end element, so that it can be
  // released at once.
  core::Model model;
  core::SlidingCable<2> cable(model, {.length = 1.0, .elements = 6,
                                      .section = core::RancfSection::circular(0.01, 20e6, 7200),
                                      .slider_position = 0.95, .slider_mass = 0.8, .detachable = true});
  const core::Configuration& q = model.state();
  const Eigen::Vector2d node = q.vector(cable.chain()[cable.slider()]).head<2>();
  CHECK(cable.mass_position(q) == node);
  CHECK(cable.slider_coordinate(q) == Approx(0.95).epsilon(1e-15));
  const Eigen::MatrixXd before = cable.sample_centerline(q, 10);
  REQUIRE(before.rows() == 61);
  CHECK(cable.sample_centerline(q, 10, 61) == before);  // nothing to pad

  Eigen::MatrixXd P;
  cable.release(model, P);
  CHECK(cable.mass_position(q) == node);  // the particle, where the sliding node was
  CHECK(std::isnan(cable.slider_coordinate(q)));
  const Eigen::MatrixXd after = cable.sample_centerline(q, 10);
  REQUIRE(after.rows() == 51);  // one element less
  const Eigen::MatrixXd padded = cable.sample_centerline(q, 10, 61);
  CHECK(padded.topRows(51) == after);
  for (Eigen::Index i = 51; i < 61; ++i) CHECK(padded.row(i) == after.row(50));
  CHECK_THROWS_WITH(cable.sample_centerline(q, 10, 50), Contains("at least"));
}
