// The hot path of SparsePattern allocates nothing: every global operator new in this test
// executable is counted, and a batch of add_block and set_zero calls must leave the counter
// unchanged.
#include <spar/solvers/sparse_assembly.hpp>

#include <catch2/catch.hpp>

#include "allocation_counter.hpp"

TEST_CASE("add_block and set_zero do not allocate", "[core][sparse_pattern][allocation]") {
  using spar::solvers::PatternBlock;
  // An element on dofs 0–3 and a constraint on dofs 1, 2 with multiplier 5 (its block over
  // [1, 2, 5], as the solvers build it).
  spar::solvers::SparsePattern pattern(
      6, {PatternBlock::element({0, 1, 2, 3}), PatternBlock::element({1, 2, 5})});
  const Eigen::MatrixXd K = Eigen::MatrixXd::Ones(4, 4);
  const Eigen::MatrixXd C = Eigen::MatrixXd::Ones(3, 3);
  const long before = spar::test::allocation_count();
  for (int i = 0; i < 100; ++i) {
    pattern.set_zero();
    pattern.add_block(0, K);
    pattern.add_block(1, C);
    pattern.add_block(1, C);
  }
  const long after = spar::test::allocation_count();
  CHECK(after == before);
  CHECK(pattern.matrix().coeff(1, 1) == 3.0);
  CHECK(pattern.matrix().coeff(5, 1) == 2.0);
}
