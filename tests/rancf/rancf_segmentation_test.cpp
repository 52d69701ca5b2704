// Segmentation of an ALE-RANCF element (000 §4.1, docs/rancf.md eqs. R20–R24): nodal coordinates,
// weights, position and velocity fields unchanged to round-off; energies unchanged to the
// quadrature error; the velocity operator J and the convective acceleration against central
// differences of the split itself.
#include <spar/elements/cable/rancf_cable_element.hpp>
#include <spar/elements/cable/rancf_segmentation.hpp>
#include <spar/error.hpp>
#include <spar/iga/rational_bezier.hpp>

#include <catch2/catch.hpp>

#include <cmath>

#include "rancf_fixtures.hpp"

using namespace spar;

namespace {

template <int Dim>
using Vec = Eigen::Matrix<double, Dim, 1>;

/// One element's data: e, x_A, x_B, weights, and rates [ė, ẋ_A, ẋ_B].
template <int Dim>
struct Segment {
  Eigen::Matrix<double, 4 * Dim, 1> e;
  double x_a, x_b;
  Eigen::Vector4d w;
  Eigen::Matrix<double, 4 * Dim + 2, 1> rates;
};

/// Position and material velocity at material coordinate x (000 eqs. (12)–(14)):
/// r = Σ σ_k e_k, ṙ = Σ σ_k ė_k + R_u u̇ + R_l l̇, u̇ = −((1 − u) ẋ_A + u ẋ_B)/l.
template <int Dim>
std::pair<Vec<Dim>, Vec<Dim>> field_at(const Segment<Dim>& s, double x) {
  const double l = s.x_b - s.x_a, u = (x - s.x_a) / l;
  const Eigen::Matrix<double, 4, 4> sh = iga::rancf_shape_function_derivatives(u, s.w);
  Vec<Dim> r = Vec<Dim>::Zero(), r_dot = Vec<Dim>::Zero(), R_u = Vec<Dim>::Zero(), R_l = Vec<Dim>::Zero();
  for (int k = 0; k < 4; ++k) {
    const double scale = k % 2 == 1 ? l : 1.0;
    r += scale * sh(k, 0) * s.e.template segment<Dim>(k * Dim);
    r_dot += scale * sh(k, 0) * s.rates.template segment<Dim>(k * Dim);
    R_u += scale * sh(k, 1) * s.e.template segment<Dim>(k * Dim);
    if (k % 2 == 1) R_l += sh(k, 0) * s.e.template segment<Dim>(k * Dim);
  }
  const double x_a_dot = s.rates(4 * Dim), x_b_dot = s.rates(4 * Dim + 1);
  r_dot += R_u * (-((1 - u) * x_a_dot + u * x_b_dot) / l) + R_l * (x_b_dot - x_a_dot);
  return {r, r_dot};
}

template <int Dim>
Segment<Dim> random_segment(unsigned seed) {
  const test::RancfState s = test::random_rancf_state<Dim>(seed, Eigen::Vector4d(1.0, 0.7, 1.4, 1.1), true);
  return {s.q.values.head(4 * Dim), s.q.values(4 * Dim), s.q.values(4 * Dim + 1),
          s.parameters.weights, s.v};
}

/// The two halves after splitting at u_H with rates mapped by J.
template <int Dim>
std::pair<Segment<Dim>, Segment<Dim>> halves(const Segment<Dim>& s, const core::RancfSplit<Dim>& split) {
  constexpr int D = Dim;
  const Eigen::Matrix<double, 2 * D + 1, 1> node_rates = split.jacobian * s.rates;
  Segment<Dim> left, right;
  left.e << s.e.template head<2 * D>(), split.node.template head<2 * D>();
  right.e << split.node.template head<2 * D>(), s.e.template tail<2 * D>();
  left.x_a = s.x_a;
  left.x_b = right.x_a = split.node(2 * D);
  right.x_b = s.x_b;
  left.w = split.left_weights;
  right.w = split.right_weights;
  left.rates << s.rates.template head<2 * D>(), node_rates.template head<2 * D>(), s.rates(4 * D), node_rates(2 * D);
  right.rates << node_rates.template head<2 * D>(), s.rates.template segment<2 * D>(2 * D), node_rates(2 * D),
      s.rates(4 * D + 1);
  return {left, right};
}

template <int Dim>
void check_exactness(double u_h) {
  const Segment<Dim> s = random_segment<Dim>(21);
  const core::RancfSplit<Dim> split = core::split_rancf_element<Dim>(s.e, s.x_a, s.x_b, s.w, u_h, s.rates);
  const auto [left, right] = halves(s, split);
  const double l = s.x_b - s.x_a;
  INFO("Dim " << Dim << ", u_H " << u_h);
  // Round-off: the de Casteljau triangle and the conversions (000 eqs. (5), (6)) take a few dozen
  // operations on O(1) numbers, a few ulps each; 1e-14 absolute on O(1) coordinates.
  constexpr double tol = 1e-14;
  // Eq. (27): every node of the halves from the Bézier halves, against the old nodes and H.
  const iga::RationalBezier<Dim> curve = iga::bezier_from_rancf<Dim>({s.e, s.w, l});
  const iga::BezierSplit<Dim> bz = iga::split(curve, u_h);
  const iga::RancfElement<Dim> ah = iga::rancf_from_bezier(bz.left, u_h * l);
  const iga::RancfElement<Dim> hb = iga::rancf_from_bezier(bz.right, (1 - u_h) * l);
  CHECK((ah.e.template head<2 * Dim>() - s.e.template head<2 * Dim>()).cwiseAbs().maxCoeff() <= tol);
  CHECK((hb.e.template tail<2 * Dim>() - s.e.template tail<2 * Dim>()).cwiseAbs().maxCoeff() <= tol);
  CHECK((hb.e.template head<2 * Dim>() - ah.e.template tail<2 * Dim>()).cwiseAbs().maxCoeff() <= tol);
  // r_H and r_x^H are the old field and slope at x_H.
  const auto [r_h, v_h] = field_at(s, split.node(2 * Dim));
  CHECK((split.node.template head<Dim>() - r_h).cwiseAbs().maxCoeff() <= tol);
  CHECK(std::fabs(split.node(2 * Dim) - (s.x_a + u_h * l)) <= tol);
  // Position and velocity fields at 101 material points (000 eqs. (23), (25)).
  double worst_r = 0.0, worst_v = 0.0;
  for (int i = 0; i <= 100; ++i) {
    const double x = s.x_a + l * i / 100.0;
    const auto [r_old, v_old] = field_at(s, x);
    const auto [r_new, v_new] = field_at(x <= left.x_b ? left : right, x);
    worst_r = std::max(worst_r, (r_new - r_old).cwiseAbs().maxCoeff());
    worst_v = std::max(worst_v, (v_new - v_old).cwiseAbs().maxCoeff() / s.rates.cwiseAbs().maxCoeff());
  }
  INFO("worst position change " << worst_r << ", worst velocity change " << worst_v);
  CHECK(worst_r <= tol);
  CHECK(worst_v <= 1e-13);  // velocities: |ṙ| ~ 10 |q̇|, so a few more ulps relative to q̇
}

}  // namespace

TEST_CASE("segmentation keeps nodes, geometry, parameterization and velocity field exactly",
          "[rancf][segmentation]") {
  for (double u_h : {0.5, 0.13, 0.81}) {
    check_exactness<2>(u_h);
    check_exactness<3>(u_h);
  }
}

namespace {

/// Φ(q): the new node [r_H, r_x^H, x_H] by the Bézier path.
template <int Dim>
Eigen::Matrix<double, 2 * Dim + 1, 1> new_node(const Eigen::Matrix<double, 4 * Dim + 2, 1>& q,
                                               const Eigen::Vector4d& w, double u_h) {
  return core::split_rancf_element<Dim>(q.template head<4 * Dim>(), q(4 * Dim), q(4 * Dim + 1), w, u_h,
                                        Eigen::Matrix<double, 4 * Dim + 2, 1>::Zero())
      .node;
}

template <int Dim>
void check_operator() {
  const Segment<Dim> s = random_segment<Dim>(33);
  const double u_h = 0.37;
  Eigen::Matrix<double, 4 * Dim + 2, 1> q;
  q << s.e, s.x_a, s.x_b;
  const core::RancfSplit<Dim> split = core::split_rancf_element<Dim>(s.e, s.x_a, s.x_b, s.w, u_h, s.rates);
  const double h = 1e-5;
  Eigen::Matrix<double, 2 * Dim + 1, 4 * Dim + 2> J;
  for (int j = 0; j < 4 * Dim + 2; ++j) {
    Eigen::Matrix<double, 4 * Dim + 2, 1> dq = Eigen::Matrix<double, 4 * Dim + 2, 1>::Zero();
    dq(j) = h;
    J.col(j) = (new_node<Dim>(q + dq, s.w, u_h) - new_node<Dim>(q - dq, s.w, u_h)) / (2 * h);
  }
  // Central differences, h = 1e-5: truncation ~h² = 1e-10 on O(1) derivatives; 1e-8.
  INFO("Dim " << Dim);
  CHECK((split.jacobian - J).cwiseAbs().maxCoeff() <= 1e-8);
  // d²Φ(q + t q̇)/dt² = J̇ q̇ (q̈ = 0): second central difference, h = 1e-4: truncation h² and
  // round-off ε/h² ~ 2e-8; 1e-6.
  const double t = 1e-4;
  const Eigen::Matrix<double, 2 * Dim + 1, 1> second =
      (new_node<Dim>(q + t * s.rates, s.w, u_h) - 2 * new_node<Dim>(q, s.w, u_h) +
       new_node<Dim>(q - t * s.rates, s.w, u_h)) / (t * t);
  CHECK((split.convective_acceleration - second).cwiseAbs().maxCoeff() <=
        1e-6 * second.cwiseAbs().maxCoeff());
}

}  // namespace

TEST_CASE("segmentation: H held at its material point gets the material velocity and slope rate",
          "[rancf][segmentation]") {
  const Segment<3> s = random_segment<3>(35);
  const core::RancfSplit<3> split = core::split_rancf_element<3>(s.e, s.x_a, s.x_b, s.w, 0.42, s.rates);
  const Eigen::Matrix<double, 7, 1> rates = split.material_jacobian * s.rates;
  const double x_h = split.node(6);
  // The material velocity at x_H (000 eq. (14)) and the rate of r_x at fixed x_H by central
  // differences in time along q + t q̇ (h = 1e-6: ~1e-10 truncation and round-off; 1e-8).
  const auto [r_h, v_h] = field_at(s, x_h);
  CHECK((rates.head<3>() - v_h).cwiseAbs().maxCoeff() <= 1e-13 * v_h.norm());
  const auto slope_at = [&](double t) {
    Segment<3> moved = s;
    moved.e += t * s.rates.head<12>();
    moved.x_a += t * s.rates(12);
    moved.x_b += t * s.rates(13);
    return core::split_rancf_element<3>(moved.e, moved.x_a, moved.x_b, moved.w,
                                        (x_h - moved.x_a) / (moved.x_b - moved.x_a), s.rates)
        .node.segment<3>(3)
        .eval();
  };
  const double h = 1e-6;
  const Eigen::Vector3d slope_rate = (slope_at(h) - slope_at(-h)) / (2 * h);
  CHECK((rates.segment<3>(3) - slope_rate).cwiseAbs().maxCoeff() <= 1e-8 * slope_rate.norm());
  CHECK(rates(6) == 0.0);
}

TEST_CASE("segmentation: velocity operator J and convective acceleration against differences",
          "[rancf][segmentation]") {
  check_operator<2>();
  check_operator<3>();
}

namespace {

/// The energies of one element (ALE) at rates [ė, ẋ_A, ẋ_B] with `points` Gauss points.
template <int Dim>
core::ElementEnergy energies(const Segment<Dim>& s, int points) {
  core::Configuration q;
  core::RancfCableParameters p;
  p.node_a = q.add_vector(s.e.template head<2 * Dim>());
  p.node_b = q.add_vector(s.e.template tail<2 * Dim>());
  p.material_a = q.add_vector(Eigen::VectorXd::Constant(1, s.x_a));
  p.material_b = q.add_vector(Eigen::VectorXd::Constant(1, s.x_b));
  p.section = test::rancf_test_section();
  p.weights = s.w;
  p.quadrature_points = points;
  const core::AleRancfCableElement<Dim> element(p);
  const Eigen::VectorXd v = s.rates, a = Eigen::VectorXd::Zero(v.size());
  return test::evaluate_all(element, q, &v, &a, Eigen::Vector3d(0.0, -9.81, 0.0)).energy;
}

template <int Dim>
double energy_change(int points) {
  const Segment<Dim> s = random_segment<Dim>(21);
  const core::RancfSplit<Dim> split = core::split_rancf_element<Dim>(s.e, s.x_a, s.x_b, s.w, 0.37, s.rates);
  const auto [left, right] = halves(s, split);
  const core::ElementEnergy before = energies(s, points), a = energies(left, points), b = energies(right, points);
  const double total_before = before.kinetic + before.strain + before.gravity;
  const double change = std::fabs(a.kinetic + b.kinetic + a.strain + b.strain + a.gravity + b.gravity - total_before);
  return change / (std::fabs(before.kinetic) + std::fabs(before.strain) + std::fabs(before.gravity));
}

}  // namespace

TEST_CASE("segmentation changes the energies only by the quadrature error", "[rancf][segmentation]") {
  // The exact integrals are unchanged (same fields, same velocities); the Gauss sums of the
  // rational integrands are not. This element is strongly deformed (slopes perturbed by 0.1, so
  // its bending integrand |r_u × r_uu|²/|r_u|⁶ varies fast): the change is 5e-2 with 5 points
  // and falls geometrically with the number of points — the quadrature error, nothing else.
  double previous2 = 1.0, previous3 = 1.0;
  for (int points : {5, 8, 12, 16}) {
    const double change2 = energy_change<2>(points), change3 = energy_change<3>(points);
    INFO(points << " points: relative energy change " << change2 << " (2D), " << change3 << " (3D)");
    CHECK(change2 <= 0.2 * previous2);
    CHECK(change3 <= 0.2 * previous3);
    previous2 = change2;
    previous3 = change3;
  }
  CHECK(previous2 <= 1e-8);
  CHECK(previous3 <= 1e-8);
}

TEST_CASE("segmentation rejects u_H outside (0, 1)", "[rancf][segmentation]") {
  const Segment<2> s = random_segment<2>(1);
  CHECK_THROWS_AS(core::split_rancf_element<2>(s.e, s.x_a, s.x_b, s.w, 1.0, s.rates), Error);
  CHECK_THROWS_AS(core::split_rancf_element<2>(s.e, s.x_b, s.x_a, s.w, 0.5, s.rates), Error);
}
