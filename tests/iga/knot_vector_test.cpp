// Knot vectors: validation messages, span search (including the right end), elements, Greville
// abscissae and the open-uniform constructor.
#include <spar/error.hpp>
#include <spar/iga/knot_vector.hpp>

#include <catch2/catch.hpp>

#include <limits>
#include <vector>

using spar::iga::KnotVector;
using Catch::Contains;

TEST_CASE("knot vector accessors on The NURBS Book example 2.3", "[iga]") {
  const KnotVector U({0, 0, 0, 1, 2, 3, 4, 4, 5, 5, 5}, 2);
  CHECK(U.degree() == 2);
  CHECK(U.basis_count() == 8);
  CHECK(U.unique_knots() == std::vector<double>{0, 1, 2, 3, 4, 5});
  CHECK(U.element_count() == 5);
  CHECK(U.multiplicity(4.0) == 2);
  CHECK(U.multiplicity(2.5) == 0);
  // Spans: u = 5/2 is in span 4 (the book's value); knots belong to the span on their right;
  // the right end belongs to the last non-zero span.
  CHECK(U.find_span(2.5) == 4);
  CHECK(U.find_span(0.0) == 2);
  CHECK(U.find_span(1.0) == 3);
  CHECK(U.find_span(4.0) == 7);
  CHECK(U.find_span(5.0) == 7);
  for (int e = 0; e < U.element_count(); ++e) {
    const auto element = U.element(e);
    CHECK(element.first == U.unique_knots()[e]);
    CHECK(element.last == U.unique_knots()[e + 1]);
    CHECK(U.find_span(0.5 * (element.first + element.last)) == element.span);
  }
  // Greville abscissae are averages of p consecutive knots (exact in binary for these values).
  CHECK(U.greville() == std::vector<double>{0, 0.5, 1.5, 2.5, 3.5, 4, 4.5, 5});
}

TEST_CASE("open-uniform knot vectors have the requested continuity", "[iga]") {
  const KnotVector c2 = KnotVector::open_uniform(4, 3, 2, 1.0, 3.0);
  CHECK(c2.knots() == std::vector<double>{1, 1, 1, 1, 1.5, 2, 2.5, 3, 3, 3, 3});
  CHECK(c2.basis_count() == 7);
  const KnotVector c0 = KnotVector::open_uniform(2, 3, 0);
  CHECK(c0.knots() == std::vector<double>{0, 0, 0, 0, 0.5, 0.5, 0.5, 1, 1, 1, 1});
  const KnotVector discontinuous = KnotVector::open_uniform(2, 2, -1);
  CHECK(discontinuous.multiplicity(0.5) == 3);
  CHECK(discontinuous.element_count() == 2);
  CHECK_THROWS_WITH(KnotVector::open_uniform(3, 2, 2), Contains("continuity"));
  CHECK_THROWS_WITH(KnotVector::open_uniform(0, 2, 1), Contains("elements, got 0"));
}

TEST_CASE("invalid knot vectors and parameters raise spar::Error naming the problem", "[iga]") {
  CHECK_THROWS_AS(KnotVector({0, 0, 1, 0.5, 1, 1}, 1), spar::Error);
  CHECK_THROWS_WITH(KnotVector({0, 0, 1, 0.5, 1, 1}, 1), Contains("decreasing knots"));
  CHECK_THROWS_WITH(KnotVector({0, 0, 0, 0.5, 0.5, 0.5, 0.5, 1, 1, 1}, 2),
                    Contains("multiplicity 4 of the interior knot 0.5 is above p+1"));
  CHECK_THROWS_WITH(KnotVector({0, 0, 1, 1, 1}, 2), Contains("too few"));
  CHECK_THROWS_WITH(KnotVector({0, 0, 0.5, 1, 1, 1}, 2), Contains("end multiplicities"));
  CHECK_THROWS_WITH(KnotVector({0, 0, 0, 0, 1, 1, 1}, 2), Contains("end multiplicities"));
  CHECK_THROWS_WITH(KnotVector({0, 0, 1, 1}, 9), Contains("degree 9"));
  const KnotVector U({0, 0, 0, 1, 1, 1}, 2);
  CHECK_THROWS_WITH(U.find_span(1.0 + 1e-15), Contains("outside the knot range"));
  CHECK_THROWS_WITH(U.find_span(-0.1), Contains("outside the knot range"));
  CHECK_THROWS_WITH(U.find_span(std::numeric_limits<double>::quiet_NaN()),
                    Contains("outside the knot range"));
  CHECK_THROWS_WITH(U.element(1), Contains("does not exist"));
}
