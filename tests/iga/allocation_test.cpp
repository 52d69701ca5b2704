// The basis kernels and curve evaluation allocate nothing: every global operator new in this
// test executable is counted, and a batch of evaluations must leave the counter unchanged.
#include <spar/iga/basis.hpp>
#include <spar/iga/nurbs_curve.hpp>

#include <catch2/catch.hpp>

#include "allocation_counter.hpp"

TEST_CASE("basis kernels and curve evaluation do not allocate", "[iga][allocation]") {
  using namespace spar::iga;
  const KnotVector U = KnotVector::open_uniform(8, 3, 2);
  const NurbsCurve<3> curve(U, NurbsCurve<3>::Points::Random(3, U.basis_count()),
                            Eigen::VectorXd::Constant(U.basis_count(), 1.5));
  BasisTable N;
  double sink = 0.0;
  const long before = spar::test::allocation_count();
  for (int i = 0; i <= 100; ++i) {
    const double u = i / 100.0;
    const int span = U.find_span(u);
    basis_derivatives(U, span, u, 3, N);
    sink += N.sum();
    rational_basis_derivatives(U, span, u, 3, curve.weights(), N);
    sink += N.sum();
    sink += curve.derivatives(u, 3).sum() + curve.point(u).sum();
  }
  const long after = spar::test::allocation_count();
  CHECK(after == before);
  CHECK(std::isfinite(sink));
}
