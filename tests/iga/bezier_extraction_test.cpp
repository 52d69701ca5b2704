// Bézier extraction (Borden et al. 2011) and the element loop: the published operators, the
// global basis reproduced on every element, and the arc-length mapping on a circle.
#include <spar/error.hpp>
#include <spar/iga/bezier_extraction.hpp>
#include <spar/iga/circular_arc.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "spline_samples.hpp"

using namespace spar::iga;

TEST_CASE("extraction operators of Borden et al. 2011's cubic example", "[iga][validation]") {
  // Borden et al. 2011, §2.3: U = {0,0,0,0,1,2,3,4,4,4,4}, p = 3; the first operator and the
  // interior ones (exact fractions, compared to round-off).
  const auto C = bezier_extraction(KnotVector({0, 0, 0, 0, 1, 2, 3, 4, 4, 4, 4}, 3));
  REQUIRE(C.size() == 4);
  Eigen::Matrix4d first, interior, final;
  first << 1, 0, 0, 0, 0, 1, 0.5, 0.25, 0, 0, 0.5, 7.0 / 12, 0, 0, 0, 1.0 / 6;
  interior << 0.25, 0, 0, 0, 7.0 / 12, 2.0 / 3, 1.0 / 3, 1.0 / 6, 1.0 / 6, 1.0 / 3, 2.0 / 3,
      2.0 / 3, 0, 0, 0, 1.0 / 6;
  final << 1.0 / 6, 0, 0, 0, 7.0 / 12, 0.5, 0, 0, 0.25, 0.5, 1, 0, 0, 0, 0, 1;
  CHECK((C[0] - first).cwiseAbs().maxCoeff() <= 1e-15);
  CHECK((C[1] - interior).cwiseAbs().maxCoeff() <= 1e-15);
  CHECK((C[3] - final).cwiseAbs().maxCoeff() <= 1e-15);
}

TEST_CASE("Bézier extraction reproduces the global basis on every element", "[iga]") {
  spar::test::SplineSamples samples(43);
  for (int p = 1; p <= 5; ++p) {
    const KnotVector U = samples.knot_vector(p, 6, p);
    const Eigen::VectorXd weights = samples.curve<2>(U).weights();
    const auto C = bezier_extraction(U);
    REQUIRE(static_cast<int>(C.size()) == U.element_count());
    for (const auto& Ce : C)  // Σ_a N_a = 1 = Σ_b B_b: every column of C_e sums to 1.
      CHECK((Ce.colwise().sum().array() - 1.0).abs().maxCoeff() <= 1e-14);
    for (bool rational : {false, true}) {
      const auto loop = rational ? element_quadrature(U, p + 2, weights, 3)
                                 : element_quadrature(U, p + 2, 3);
      REQUIRE(static_cast<int>(loop.size()) == U.element_count());
      double total = 0.0;
      for (const ElementQuadrature& element : loop) {
        CHECK(element.span == U.element(element.element).span);
        CHECK(element.first_basis == element.span - p);
        for (std::size_t q = 0; q < element.parameters.size(); ++q) {
          BasisTable reference;
          if (rational)
            rational_basis_derivatives(U, element.span, element.parameters[q], 3, weights, reference);
          else
            basis_derivatives(U, element.span, element.parameters[q], 3, reference);
          const double scale = std::max(1.0, reference.cwiseAbs().maxCoeff());
          INFO("p = " << p << ", rational = " << rational << ", element " << element.element);
          // Two algorithms for the same polynomials: round-off relative to the largest entry.
          CHECK((element.basis[q] - reference).cwiseAbs().maxCoeff() <= 1e-12 * scale);
          total += element.weights[q];
        }
      }
      CHECK(total == Approx(U.last() - U.first()).epsilon(1e-14));
    }
  }
}

TEST_CASE("the arc-length element loop on a circle gives the unit tangent and curvature",
          "[iga][validation]") {
  // On a reference curve C = Σ R_i P_i: Σ R_i,s P_i = t and Σ R_i,ss P_i = −(1/R) radial.
  constexpr double pi = std::numbers::pi;
  CircularArc<2> spec;
  spec.radius = 1.5;
  spec.sweep = 1.5 * pi;
  const NurbsCurve<2> arc = circular_arc(spec);
  const auto loop = arc_length_quadrature(arc, 6);
  double length = 0.0;
  for (const ElementQuadrature& element : loop)
    for (std::size_t q = 0; q < element.parameters.size(); ++q) {
      const auto& P = arc.control_points();
      const Eigen::Vector2d x = P.middleCols(element.first_basis, 3) *
                                element.basis[q].row(0).head(3).transpose();
      const Eigen::Vector2d t = P.middleCols(element.first_basis, 3) *
                                element.basis[q].row(1).head(3).transpose();
      const Eigen::Vector2d k = P.middleCols(element.first_basis, 3) *
                                element.basis[q].row(2).head(3).transpose();
      // Derivatives of a rational quadratic of size ~R: round-off amplified by J'/J terms.
      CHECK(std::abs(t.norm() - 1.0) <= 1e-14);
      CHECK((k + x / (spec.radius * spec.radius)).norm() <= 1e-13);
      // The speed |C′(u)| of the curve evaluated directly, vs the element loop's: both are sums of
      // a few products of O(1) basis values and control points of size R, so 1e-14 relative.
      CHECK(element.jacobians[q] == Approx(arc.derivatives(element.parameters[q], 1).col(1).norm()).epsilon(1e-14));
      length += element.weights[q];
    }
  // 6 Gauss points per 90° piece integrate the rational speed |C′| to ~1e-9 (not exact).
  CHECK(length == Approx(spec.radius * spec.sweep).epsilon(1e-8));
}
