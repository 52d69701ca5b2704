// The hot path of SparsePattern allocates nothing: every global operator new in this test
// executable is counted, and a batch of add_block and set_zero calls must leave the counter
// unchanged.
#include <spar/solvers/sparse_assembly.hpp>

#include <catch2/catch.hpp>

#include "allocation_counter.hpp"

TEST_CASE("add_block and set_zero do not allocate", "[core][sparse_pattern][allocation]") {
  using spar::solvers::PatternBlock;
  spar::solvers::SparsePattern pattern(
      6, {PatternBlock::element({0, 1, 2, 3}), PatternBlock::coupling({5}, {1, 2})});
  const Eigen::MatrixXd K = Eigen::MatrixXd::Ones(4, 4);
  const Eigen::MatrixXd B = Eigen::MatrixXd::Ones(1, 2);
  const Eigen::MatrixXd B_transpose_position = Eigen::MatrixXd::Ones(2, 1);
  const long before = spar::test::allocation_count();
  for (int i = 0; i < 100; ++i) {
    pattern.set_zero();
    pattern.add_block(0, K);
    pattern.add_block(1, B);
    pattern.add_block(1, B, B_transpose_position);
  }
  const long after = spar::test::allocation_count();
  CHECK(after == before);
  CHECK(pattern.matrix().coeff(1, 1) == 1.0);
  CHECK(pattern.matrix().coeff(5, 1) == 2.0);
}
