// Merging of two ALE-RANCF elements (000 §4.2, docs/rancf.md eqs. R25–R29): the weights of
// eqs. (31)–(38), exact recovery of a split element in 3D, the merged curve through the deleted
// node in 2D, the fallback, and the geometry and energy change of a merge, RANCF against ANCF.
#include <spar/elements/cable/rancf_cable_element.hpp>
#include <spar/elements/cable/rancf_merging.hpp>
#include <spar/elements/cable/rancf_segmentation.hpp>
#include <spar/error.hpp>
#include <spar/iga/rational_bezier.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "rancf_fixtures.hpp"

using namespace spar;

namespace {

template <int Dim>
using Vec = Eigen::Matrix<double, Dim, 1>;

template <int Dim>
Vec<Dim> position(const Eigen::Matrix<double, 4 * Dim, 1>& e, const Eigen::Vector4d& w, double l, double u) {
  const Eigen::Vector4d s = iga::rancf_shape_functions(u, w, l);
  Vec<Dim> r = Vec<Dim>::Zero();
  for (int k = 0; k < 4; ++k) r += s(k) * e.template segment<Dim>(k * Dim);
  return r;
}

}  // namespace

TEST_CASE("merging the halves of a split 3D element recovers its weights and geometry", "[rancf][merging]") {
  // In 3D eq. (R26) is square; for a non-planar element it has the one solution k = w/w3.
  const test::RancfState s = test::random_rancf_state<3>(41, Eigen::Vector4d(1.0, 0.7, 1.4, 1.1), true);
  const Eigen::Matrix<double, 12, 1> e = s.q.values.head(12);
  const double x_a = s.q.values(12), x_b = s.q.values(13), l = x_b - x_a;
  const core::RancfSplit<3> split =
      core::split_rancf_element<3>(e, x_a, x_b, s.parameters.weights, 0.37, s.v);
  const core::RancfMergeWeights merged =
      core::merge_rancf_weights<3>(e, split.node.head<3>(), x_a, split.node(6), x_b);
  INFO("merged weights " << merged.weights.transpose());
  CHECK_FALSE(merged.fallback);
  // Round-off of a 3×3 solve with condition number ~1e2 on O(1) data: 1e-12.
  CHECK((merged.weights - s.parameters.weights / s.parameters.weights(3)).cwiseAbs().maxCoeff() <= 1e-12);
  CHECK(merged.miss <= 1e-13);
  double worst = 0.0;
  for (int i = 0; i <= 50; ++i)
    worst = std::max(worst, (position<3>(e, merged.weights, l, i / 50.0) -
                             position<3>(e, s.parameters.weights, l, i / 50.0)).norm());
  CHECK(worst <= 1e-12);
}

TEST_CASE("merged 2D element passes through the deleted node (000 eq. (32))", "[rancf][merging]") {
  // 2 equations, 3 unknowns: the minimum-norm solution satisfies eq. (32) exactly.
  const test::RancfState s = test::random_rancf_state<2>(43, Eigen::Vector4d(1.0, 0.9, 1.2, 1.0), true);
  const Eigen::Matrix<double, 8, 1> e = s.q.values.head(8);
  const double x_a = s.q.values(8), x_b = s.q.values(9);
  const core::RancfSplit<2> split = core::split_rancf_element<2>(e, x_a, x_b, s.parameters.weights, 0.6, s.v);
  const core::RancfMergeWeights merged =
      core::merge_rancf_weights<2>(e, split.node.head<2>(), x_a, split.node(4), x_b);
  INFO("merged weights " << merged.weights.transpose());
  CHECK_FALSE(merged.fallback);
  CHECK(merged.miss <= 1e-13);
}

TEST_CASE("merging falls back to unit weights when a weight would not be positive", "[rancf][merging]") {
  // A straight element A = 0, B = e_1 with tangent slopes and the deleted node far off to the
  // side at ū_H = 1/2: no positive weights put the curve there (the curve stays in the convex
  // hull of P0 … P3, all on the X axis).
  Eigen::Matrix<double, 8, 1> e;
  e << 0, 0, 1, 0, 1, 0, 1, 0;
  const core::RancfMergeWeights merged = core::merge_rancf_weights<2>(e, Eigen::Vector2d(0.5, 0.3), 0.0, 0.5, 1.0);
  CHECK(merged.fallback);
  CHECK(merged.weights == Eigen::Vector4d::Ones());
  CHECK(merged.miss > 0.29);
  CHECK_THROWS_AS(core::merge_rancf_weights<2>(e, Eigen::Vector2d(0.5, 0.3), 0.0, 1.2, 1.0), Error);
}

namespace {

struct MergeChange {
  double geometry = 0.0;  ///< max |r_after(x) − r_before(x)| over the merged element
  double energy = 0.0;    ///< |E_after − E_before| / E_before (kinetic + strain)
};

/// A quarter circle of radius 1 spinning at ω = 2 rad/s about its centre, as two elements AH, HB
/// with nodes on the circle at arc lengths 0, 0.4·π/2, π/2 (tangent slopes, material coordinate
/// = arc length, unit weights: ALE-ANCF), merged into one element with `rancf` ? the weights of
/// eqs. (31)–(38) : unit weights. Nodes A and B keep their rates (the truncation).
MergeChange arc_merge(bool rancf) {
  const double L = std::numbers::pi / 2, x_h = 0.4 * L, omega = 2.0;
  const auto node = [](double x) {
    Eigen::Vector4d n(std::cos(x), std::sin(x), -std::sin(x), std::cos(x));
    return n;
  };
  const auto node_rate = [&](double x) {  // ω e_z × (r, r_x)
    const Eigen::Vector4d n = node(x);
    return Eigen::Vector4d(-omega * n(1), omega * n(0), -omega * n(3), omega * n(2));
  };
  const auto energy = [&](const std::vector<double>& xs, const Eigen::Vector4d& weights) {
    double total = 0.0;
    for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
      core::Configuration q;
      core::RancfCableParameters p;
      p.node_a = q.add_vector(node(xs[i]));
      p.node_b = q.add_vector(node(xs[i + 1]));
      p.material_a = q.add_vector(Eigen::VectorXd::Constant(1, xs[i]));
      p.material_b = q.add_vector(Eigen::VectorXd::Constant(1, xs[i + 1]));
      p.section = test::rancf_test_section();
      p.weights = xs.size() == 2 ? weights : Eigen::Vector4d::Ones();
      Eigen::VectorXd v(10), a = Eigen::VectorXd::Zero(10);
      v << node_rate(xs[i]), node_rate(xs[i + 1]), 0.0, 0.0;
      const core::AleRancfCableElement<2> element(p);
      const core::ElementEnergy E = test::evaluate_all(element, q, &v, &a, Eigen::Vector3d::Zero()).energy;
      total += E.kinetic + E.strain;
    }
    return total;
  };
  Eigen::Matrix<double, 8, 1> e_ab;
  e_ab << node(0.0), node(L);
  const Eigen::Vector4d weights =
      rancf ? core::merge_rancf_weights<2>(e_ab, node(x_h).head<2>(), 0.0, x_h, L).weights
            : Eigen::Vector4d::Ones().eval();
  Eigen::Matrix<double, 8, 1> e_ah, e_hb;
  e_ah << node(0.0), node(x_h);
  e_hb << node(x_h), node(L);
  MergeChange change;
  for (int i = 0; i <= 200; ++i) {
    const double x = L * i / 200.0;
    const Vec<2> before = x <= x_h ? position<2>(e_ah, Eigen::Vector4d::Ones(), x_h, x / x_h)
                                   : position<2>(e_hb, Eigen::Vector4d::Ones(), L - x_h, (x - x_h) / (L - x_h));
    change.geometry = std::max(change.geometry, (position<2>(e_ab, weights, L, x / L) - before).norm());
  }
  const double before = energy({0.0, x_h, L}, Eigen::Vector4d::Ones());
  change.energy = std::fabs(energy({0.0, L}, weights) - before) / before;
  return change;
}

}  // namespace

TEST_CASE("a merge moves a spinning arc less with RANCF weights than with ANCF ones", "[rancf][merging]") {
  // 000 §4.2's claim, measured: geometry and energy change of merging two ANCF elements on a
  // quarter circle (docs/rancf.md, "Merging").
  const MergeChange rancf = arc_merge(true), ancf = arc_merge(false);
  INFO("ALE-RANCF merge: geometry " << rancf.geometry << ", energy " << rancf.energy
                                    << "; ALE-ANCF merge: geometry " << ancf.geometry << ", energy " << ancf.energy);
  CHECK(rancf.geometry < ancf.geometry);
  CHECK(rancf.energy < ancf.energy);
}

TEST_CASE("merging keeps the weights within a bound by shrinking them towards 1", "[rancf][merging]") {
  // An arch A = 0, B = e_1 with slopes (1, ±1) and the deleted node well inside it, near the
  // chord: the minimum-norm solution reaches it with k0 = 0.14 (1.12 and 1.41 for k1, k2).
  Eigen::Matrix<double, 8, 1> e;
  e << 0, 0, 1, 1, 1, 0, 1, -1;
  const Eigen::Vector2d r_h(0.3, 0.1);
  const core::RancfMergeWeights free = core::merge_rancf_weights<2>(e, r_h, 0.0, 0.3, 1.0);
  INFO("unbounded weights " << free.weights.transpose());
  REQUIRE_FALSE(free.fallback);
  REQUIRE_FALSE(free.bounded);
  REQUIRE(std::max(free.weights.maxCoeff(), 1.0 / free.weights.minCoeff()) > 4.0);
  const core::RancfMergeWeights bounded = core::merge_rancf_weights<2>(e, r_h, 0.0, 0.3, 1.0, 4.0);
  INFO("bounded weights " << bounded.weights.transpose());
  CHECK(bounded.bounded);
  CHECK(bounded.weights.maxCoeff() <= 4.0 * (1 + 1e-15));
  CHECK(bounded.weights.minCoeff() >= 0.25 * (1 - 1e-15));
  // On the segment from the unit weights to the free ones, with one weight on the bound.
  const Eigen::Vector3d x = free.weights.head<3>() - Eigen::Vector3d::Ones();
  const Eigen::Vector3d y = bounded.weights.head<3>() - Eigen::Vector3d::Ones();
  const double t = y.dot(x) / x.squaredNorm();
  CHECK(t > 0.0);
  CHECK(t < 1.0);
  CHECK((y - t * x).norm() <= 1e-14 * x.norm());
  CHECK(std::min(std::abs(bounded.weights.head<3>().maxCoeff() - 4.0),
                 std::abs(bounded.weights.head<3>().minCoeff() - 0.25)) <= 1e-14);
  // Bounded, the merged curve misses H by more than the exact fit.
  CHECK(free.miss <= 1e-12);
  CHECK(bounded.miss > 1e-6);
  CHECK_THROWS_AS(core::merge_rancf_weights<2>(e, r_h, 0.0, 0.3, 1.0, 0.5), Error);
}
