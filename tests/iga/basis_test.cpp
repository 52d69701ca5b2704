// B-spline and NURBS basis functions: The NURBS Book's worked example, partition of unity and
// non-negativity, and every derivative against central finite differences of the next lower one.
#include <spar/error.hpp>
#include <spar/iga/basis.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "spline_samples.hpp"

using namespace spar::iga;
using Catch::Contains;

namespace {

// Central differences with a step h = 1e-5·L relative to the element length L: the k-th
// derivative scales like L^−k, so the truncation error h²/6·|N^(k+2)| ≈ 2e-11·|N^(k)| and the
// round-off eps/h·|N^(k−1)| ≈ 1e-11·L^−k·L stay far below the 1e-6 relative tolerance even
// for the short, rational p = 5 elements.
constexpr double fd_relative_step = 1e-5;
constexpr double fd_tolerance = 1e-6;

template <class Evaluate>
void check_against_finite_differences(const KnotVector& U, Evaluate&& evaluate, int order_max,
                                      spar::test::SplineSamples& samples) {
  const int p = U.degree();
  for (int e = 0; e < U.element_count(); ++e)
    for (int sample = 0; sample < 5; ++sample) {
      const auto element = U.element(e);
      const double fd_step = fd_relative_step * (element.last - element.first);
      const double u = samples.inside(U, e, 10 * fd_step);
      const int span = element.span;
      BasisTable at, plus, minus;
      evaluate(span, u, order_max, at);
      evaluate(span, u + fd_step, order_max, plus);
      evaluate(span, u - fd_step, order_max, minus);
      for (int k = 1; k <= order_max; ++k) {
        const Eigen::RowVectorXd fd =
            (plus.row(k - 1).head(p + 1) - minus.row(k - 1).head(p + 1)) / (2 * fd_step);
        const double scale = std::max(1.0, at.row(k).head(p + 1).cwiseAbs().maxCoeff());
        INFO("p = " << p << ", k = " << k << ", u = " << u);
        CHECK((at.row(k).head(p + 1) - fd).cwiseAbs().maxCoeff() <= fd_tolerance * scale);
      }
    }
}

}  // namespace

TEST_CASE("basis values and derivatives of The NURBS Book example 2.3 at u = 5/2",
          "[iga][validation]") {
  // P&T ex. 2.3/2.4: N_{2,2} = 1/8, N_{3,2} = 3/4, N_{4,2} = 1/8; first derivatives −1/2, 0, 1/2;
  // second derivatives 1, −2, 1. All are dyadic rationals, so the comparison is exact to eps.
  const KnotVector U({0, 0, 0, 1, 2, 3, 4, 4, 5, 5, 5}, 2);
  const int span = U.find_span(2.5);
  REQUIRE(span == 4);
  BasisTable N;
  basis_derivatives(U, span, 2.5, 3, N);
  const Eigen::Matrix<double, 4, 3> expected{
      {0.125, 0.75, 0.125}, {-0.5, 0.0, 0.5}, {1.0, -2.0, 1.0}, {0.0, 0.0, 0.0}};
  CHECK((N.topLeftCorner<4, 3>() - expected).cwiseAbs().maxCoeff() <= 1e-15);
  CHECK(N.rightCols<max_degree - 2>().isZero(0.0));
}

TEST_CASE("partition of unity and non-negativity on 10^4 points", "[iga]") {
  spar::test::SplineSamples samples(3);
  for (int p = 1; p <= 5; ++p) {
    const KnotVector U = samples.knot_vector(p, 7, p);
    const Eigen::VectorXd weights = samples.curve<2>(U).weights();
    double worst_sum = 0.0, worst_derivative_sum = 0.0, most_negative = 0.0;
    for (int i = 0; i <= 10000; ++i) {
      const double u = U.first() + (U.last() - U.first()) * i / 10000.0;
      const int span = U.find_span(u);
      BasisTable N, R;
      basis_derivatives(U, span, u, 3, N);
      rational_basis_derivatives(U, span, u, 3, weights, R);
      for (const BasisTable* table : {&N, &R}) {
        worst_sum = std::max(worst_sum, std::abs(table->row(0).sum() - 1.0));
        most_negative = std::min(most_negative, table->row(0).minCoeff());
        for (int k = 1; k <= 3; ++k)
          worst_derivative_sum = std::max(
              worst_derivative_sum,
              std::abs(table->row(k).sum()) / std::max(1.0, table->row(k).cwiseAbs().maxCoeff()));
      }
    }
    INFO("p = " << p);
    // Sums of p+1 non-negative terms ≤ 1: round-off only.
    CHECK(worst_sum <= 1e-14);
    // A2.2 forms each value from sums and products of non-negative numbers: exactly ≥ 0.
    CHECK(most_negative == 0.0);
    // Derivatives of a partition of unity sum to zero; cancellation of terms up to ~1e3.
    CHECK(worst_derivative_sum <= 1e-12);
  }
}

TEST_CASE("B-spline derivatives of every order up to p match finite differences, p = 1 … 5", "[iga]") {
  spar::test::SplineSamples samples(5);
  for (int p = 1; p <= 5; ++p) {
    const KnotVector U = samples.knot_vector(p, 5, p);
    check_against_finite_differences(
        U,
        [&](int span, double u, int order, BasisTable& out) {
          basis_derivatives(U, span, u, order, out);
        },
        p, samples);
  }
}

TEST_CASE("NURBS derivatives match finite differences for p = 1 … 5", "[iga]") {
  spar::test::SplineSamples samples(7);
  for (int p = 1; p <= 5; ++p) {
    const KnotVector U = samples.knot_vector(p, 5, p);
    const Eigen::VectorXd weights = samples.curve<3>(U).weights();
    // Rational functions have non-zero derivatives above p: check one order beyond it.
    check_against_finite_differences(
        U,
        [&](int span, double u, int order, BasisTable& out) {
          rational_basis_derivatives(U, span, u, order, weights, out);
        },
        p + 1, samples);
  }
}

TEST_CASE("derivatives above the degree vanish and unit weights give the B-spline basis",
          "[iga]") {
  const KnotVector U = KnotVector::open_uniform(3, 2, 1);
  BasisTable N, R;
  basis_derivatives(U, U.find_span(0.4), 0.4, 3, N);
  CHECK(N.row(3).isZero(0.0));
  rational_basis_derivatives(U, U.find_span(0.4), 0.4, 3, Eigen::VectorXd::Ones(U.basis_count()), R);
  CHECK((N - R).cwiseAbs().maxCoeff() <= 1e-14);
}

TEST_CASE("basis kernels reject bad orders, spans and weight counts", "[iga]") {
  const KnotVector U = KnotVector::open_uniform(3, 2, 1);
  BasisTable N;
  CHECK_THROWS_WITH(basis_derivatives(U, U.find_span(0.5), 0.5, max_derivative_order + 1, N),
                    Contains("order 8"));
  CHECK_THROWS_WITH(basis_derivatives(U, 1, 0.5, 1, N), Contains("span 1"));
  CHECK_THROWS_WITH(rational_basis_derivatives(U, 2, 0.1, 1, Eigen::VectorXd::Ones(3), N),
                    Contains("3 weights for 5 basis functions"));
}
