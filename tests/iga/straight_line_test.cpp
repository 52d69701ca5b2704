// iga::straight_line: a linear parameterization of the segment for every degree.
#include <spar/iga/straight_line.hpp>

#include <catch2/catch.hpp>

using namespace spar;

TEST_CASE("straight_line is linearly parameterized for every degree", "[iga]") {
  const Eigen::Vector3d a(1.0, -2.0, 0.5), b(3.0, 1.0, -1.5);
  for (int degree = 1; degree <= 5; ++degree) {
    const iga::NurbsCurve<3> line = iga::straight_line<3>(a, b, 7, degree);
    CHECK(line.knots().element_count() == 7);
    for (int i = 0; i <= 100; ++i) {
      const double u = i / 100.0;
      // Greville control points reproduce the linear map exactly up to round-off.
      CHECK((line.point(u) - (a + u * (b - a))).norm() <= 1e-14);
      CHECK((line.derivatives(u, 1).col(1) - (b - a)).norm() <= 1e-13);
    }
  }
  CHECK_THROWS_WITH(iga::straight_line<3>(a, a, 2, 2), Catch::Contains("zero length"));
}
