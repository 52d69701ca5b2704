// SparsePattern: its structure and scatter against a dense matrix assembled by hand, Dirichlet
// conditions, serial against parallel assembly, and the errors it raises.
#include <spar/solvers/sparse_assembly.hpp>
#include <spar/solvers/work_sharing.hpp>

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>
#include <stdexcept>
#include <vector>

using namespace spar;
using solvers::PatternBlock;
using solvers::SparsePattern;

namespace {

/// A small model: two overlapping elements, one element with a repeated dof, and a constraint
/// on dofs 1 and 4 with multiplier 6, one block over [1, 4, 6] as the solvers build it.
const int small_size = 8;
std::vector<PatternBlock> small_blocks() {
  return {PatternBlock::element({0, 1, 2}), PatternBlock::element({2, 3, 4}),
          PatternBlock::element({5, 3, 5}), PatternBlock::element({1, 4, 6})};
}

Eigen::MatrixXd random_block(const PatternBlock& block, unsigned seed) {
  std::mt19937 generator(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::MatrixXd K(block.dofs.size(), block.dofs.size());
  for (Eigen::Index j = 0; j < K.cols(); ++j)
    for (Eigen::Index i = 0; i < K.rows(); ++i) K(i, j) = uniform(generator);
  return K;
}

/// D(dofs, dofs) += K, entry by entry in the order SparsePattern scatters them.
void add_dense(Eigen::MatrixXd& D, const PatternBlock& block, const Eigen::MatrixXd& K) {
  for (std::size_t j = 0; j < block.dofs.size(); ++j)
    for (std::size_t i = 0; i < block.dofs.size(); ++i) D(block.dofs[i], block.dofs[j]) += K(i, j);
}

bool same_values(const solvers::SparseMatrix& A, const solvers::SparseMatrix& B) {
  return A.nonZeros() == B.nonZeros() &&
         std::equal(A.valuePtr(), A.valuePtr() + A.nonZeros(), B.valuePtr());
}

/// A cubic B-spline beam: element e couples nodes e..e+3 with 6 dofs each (24 × 24 blocks),
/// followed by `constraints` constraint blocks, each over the 6 dofs of an evenly spaced node and
/// its one multiplier (numbered after the node dofs): 7 × 7.
struct BeamChain {
  int size;
  std::vector<PatternBlock> blocks;
};
BeamChain beam_chain(int elements, int constraints) {
  const int nodes = elements + 3;
  BeamChain chain{6 * nodes + constraints, {}};
  for (int e = 0; e < elements; ++e) {
    std::vector<int> dofs;
    for (int dof = 6 * e; dof < 6 * (e + 4); ++dof) dofs.push_back(dof);
    chain.blocks.push_back(PatternBlock::element(dofs));
  }
  for (int c = 0; c < constraints; ++c) {
    const int node = c * (nodes - 1) / std::max(constraints - 1, 1);
    std::vector<int> dofs;
    for (int dof = 6 * node; dof < 6 * node + 6; ++dof) dofs.push_back(dof);
    dofs.push_back(6 * nodes + c);
    chain.blocks.push_back(PatternBlock::element(dofs));
  }
  return chain;
}

}  // namespace

TEST_CASE("SparsePattern holds the diagonal and the blocks' positions, and nothing else",
          "[core][sparse_pattern]") {
  const SparsePattern pattern(small_size, small_blocks());
  Eigen::MatrixXi expected = Eigen::MatrixXi::Identity(small_size, small_size);
  for (const PatternBlock& block : small_blocks())
    for (int row : block.dofs)
      for (int col : block.dofs) expected(row, col) = 1;
  const solvers::SparseMatrix& A = pattern.matrix();
  CHECK(A.isCompressed());
  CHECK(A.rows() == small_size);
  CHECK(A.cols() == small_size);
  CHECK(pattern.nonzeros() == expected.sum());
  Eigen::MatrixXi stored = Eigen::MatrixXi::Zero(small_size, small_size);
  for (int c = 0; c < small_size; ++c)
    for (solvers::SparseMatrix::InnerIterator it(A, c); it; ++it) {
      stored(it.row(), it.col()) = 1;
      CHECK(it.value() == 0.0);
    }
  CHECK(stored == expected);
  // Dof 7 is in no block: only its diagonal.
  CHECK(stored.col(7).sum() == 1);
}

TEST_CASE("add_block scatters exactly like a dense assembly by hand", "[core][sparse_pattern]") {
  // The same additions happen in the same order on both sides, so the results agree bitwise.
  SparsePattern pattern(small_size, small_blocks());
  Eigen::MatrixXd reference = Eigen::MatrixXd::Zero(small_size, small_size);
  for (int pass = 0; pass < 2; ++pass)
    for (int b = 0; b < pattern.block_count(); ++b) {
      const Eigen::MatrixXd K = random_block(pattern.block(b), 10 * b + pass);
      pattern.add_block(b, K);
      add_dense(reference, pattern.block(b), K);
    }
  CHECK(Eigen::MatrixXd(pattern.matrix()) == reference);

  SECTION("set_zero zeroes the values and keeps the structure") {
    const int nonzeros = pattern.nonzeros();
    const int* row_indices = pattern.matrix().innerIndexPtr();
    pattern.set_zero();
    CHECK(pattern.nonzeros() == nonzeros);
    CHECK(pattern.matrix().innerIndexPtr() == row_indices);
    CHECK(Eigen::MatrixXd(pattern.matrix()).isZero(0.0));
  }
}

TEST_CASE("apply_dirichlet zeroes rows and columns, sets the diagonal to 1 and the rhs to 0",
          "[core][sparse_pattern]") {
  SparsePattern pattern(small_size, small_blocks());
  for (int b = 0; b < pattern.block_count(); ++b)
    pattern.add_block(b, random_block(pattern.block(b), b + 1));
  Eigen::MatrixXd expected(pattern.matrix());
  const std::vector<int> fixed = {2, 6, 2};
  for (int dof : fixed) {
    expected.row(dof).setZero();
    expected.col(dof).setZero();
    expected(dof, dof) = 1.0;
  }
  Eigen::VectorXd rhs = Eigen::VectorXd::LinSpaced(small_size, 1.0, 8.0);
  Eigen::VectorXd expected_rhs = rhs;
  expected_rhs(2) = expected_rhs(6) = 0.0;
  const int nonzeros = pattern.nonzeros();

  pattern.apply_dirichlet(fixed, rhs);
  CHECK(Eigen::MatrixXd(pattern.matrix()) == expected);
  CHECK(rhs == expected_rhs);
  CHECK(pattern.nonzeros() == nonzeros);

  CHECK_THROWS_WITH(pattern.apply_dirichlet({8}, rhs), Catch::Contains("fixed dof 8 outside"));
  Eigen::VectorXd short_rhs(3);
  CHECK_THROWS_WITH(pattern.apply_dirichlet({0}, short_rhs),
                    Catch::Contains("right-hand side has 3 entries"));
}

TEST_CASE("apply_dirichlet after a reassembly, with the same and with another list of dofs",
          "[core][sparse_pattern]") {
  // The positions of the fixed rows and columns are kept from one call to the next: a new list
  // must not be served from the old one's.
  SparsePattern pattern(small_size, small_blocks());
  const auto assemble = [&pattern] {
    pattern.set_zero();
    for (int b = 0; b < pattern.block_count(); ++b)
      pattern.add_block(b, random_block(pattern.block(b), b + 1));
  };
  const auto expected_for = [&pattern](const std::vector<int>& fixed) {
    Eigen::MatrixXd expected(pattern.matrix());
    for (int dof : fixed) {
      expected.row(dof).setZero();
      expected.col(dof).setZero();
      expected(dof, dof) = 1.0;
    }
    return expected;
  };
  Eigen::VectorXd rhs = Eigen::VectorXd::Ones(small_size);
  for (const std::vector<int>& fixed : {std::vector<int>{2, 6}, std::vector<int>{2, 6}, std::vector<int>{0, 7},
                                        std::vector<int>{}}) {
    assemble();
    const Eigen::MatrixXd expected = expected_for(fixed);
    pattern.apply_dirichlet(fixed, rhs);
    CHECK(Eigen::MatrixXd(pattern.matrix()) == expected);
  }
  CHECK_THROWS_WITH(pattern.apply_dirichlet({2, -1}, rhs), Catch::Contains("fixed dof -1 outside"));
  assemble();
  const Eigen::MatrixXd expected = expected_for({1});
  pattern.apply_dirichlet({1}, rhs);  // a refused list leaves nothing behind
  CHECK(Eigen::MatrixXd(pattern.matrix()) == expected);
}

TEST_CASE("serial and parallel assembly give bitwise identical matrices",
          "[core][sparse_pattern][openmp]") {
  // 250 cubic elements (past parallel_assembly_min_blocks) and 5 constraint blocks.
  const BeamChain chain = beam_chain(250, 5);
  SparsePattern serial(chain.size, chain.blocks);
  SparsePattern parallel(chain.size, chain.blocks);
  const solvers::BlockCompute compute = [&](int block_id, Eigen::MatrixXd& K) {
    K = random_block(chain.blocks[block_id], block_id);
  };
  serial.assemble(compute, solvers::AssemblyExecution::serial);
  for (int repeat = 0; repeat < 3; ++repeat) {
    parallel.assemble(compute, solvers::AssemblyExecution::parallel);
    CHECK(same_values(serial.matrix(), parallel.matrix()));
  }

  // Against a dense assembly in block order: the sums run in the same order, starting from 0,
  // so they agree bitwise.
  Eigen::MatrixXd reference = Eigen::MatrixXd::Zero(chain.size, chain.size);
  for (int b = 0; b < static_cast<int>(chain.blocks.size()); ++b) {
    const Eigen::MatrixXd K = random_block(chain.blocks[b], b);
    add_dense(reference, chain.blocks[b], K);
  }
  CHECK(Eigen::MatrixXd(serial.matrix()) == reference);
}

TEST_CASE("parallel assembly sums repeated dofs and overlapping blocks as add_block does",
          "[core][sparse_pattern][openmp]") {
  // Block 2 repeats dof 5: value (5, 5) sums four entries of one block. Blocks 0, 3 and 1, 3
  // overlap: (1, 1) sums entries of blocks 0 and 3, (4, 4) of blocks 1 and 3.
  SparsePattern by_hand(small_size, small_blocks());
  SparsePattern parallel(small_size, small_blocks());
  const std::vector<PatternBlock> blocks = small_blocks();
  for (int b = 0; b < static_cast<int>(blocks.size()); ++b)
    by_hand.add_block(b, random_block(blocks[b], 10 + b));
  parallel.assemble([&](int b, Eigen::MatrixXd& K) { K = random_block(blocks[b], 10 + b); },
                    solvers::AssemblyExecution::parallel);
  CHECK(same_values(by_hand.matrix(), parallel.matrix()));
}

TEST_CASE("automatic assembly runs in parallel from parallel_assembly_min_blocks blocks up",
          "[core][sparse_pattern][openmp]") {
  const bool threads = solvers::WorkSharing::shared().thread_count() > 1;
  const BeamChain below = beam_chain(solvers::parallel_assembly_min_blocks - 1, 0);
  const BeamChain at = beam_chain(solvers::parallel_assembly_min_blocks, 0);
  const SparsePattern small(below.size, below.blocks);
  const SparsePattern large(at.size, at.blocks);
  CHECK_FALSE(small.runs_parallel(solvers::AssemblyExecution::automatic));
  CHECK(large.runs_parallel(solvers::AssemblyExecution::automatic) == threads);
  CHECK(small.runs_parallel(solvers::AssemblyExecution::parallel) == threads);
  CHECK_FALSE(large.runs_parallel(solvers::AssemblyExecution::serial));
}

TEST_CASE("assemble rethrows a failure of the block computation", "[core][sparse_pattern]") {
  const BeamChain chain = beam_chain(20, 0);
  SparsePattern pattern(chain.size, chain.blocks);
  const auto execution = GENERATE(solvers::AssemblyExecution::serial, solvers::AssemblyExecution::parallel,
                                  solvers::AssemblyExecution::automatic);
  CHECK_THROWS_WITH(pattern.assemble(
                        [](int block_id, Eigen::MatrixXd&) {
                          if (block_id == 7) throw std::runtime_error("element 7 failed");
                        },
                        execution),
                    Catch::Contains("element 7 failed"));
  CHECK_THROWS_WITH(pattern.assemble([](int, Eigen::MatrixXd& K) { K.resize(3, 3); }, execution),
                    Catch::Contains("is 3 × 3, the block is 24 × 24"));
}

TEST_CASE("SparsePattern rejects bad sizes, indices and block ids", "[core][sparse_pattern]") {
  CHECK_THROWS_WITH(SparsePattern(-1, {}), Catch::Contains("negative matrix size -1"));
  CHECK_THROWS_WITH(SparsePattern(4, {PatternBlock::element({0, 4})}),
                    Catch::Contains("block 0 has dof 4 outside [0, 4)"));
  CHECK_THROWS_WITH(SparsePattern(4, {PatternBlock::element({1}), PatternBlock::element({0, -1})}),
                    Catch::Contains("block 1 has dof -1 outside [0, 4)"));

  SparsePattern pattern(small_size, small_blocks());
  CHECK_THROWS_WITH(pattern.add_block(4, Eigen::MatrixXd::Zero(1, 1)),
                    Catch::Contains("block id 4 outside [0, 4)"));
  CHECK_THROWS_WITH(pattern.add_block(0, Eigen::MatrixXd::Zero(3, 2)),
                    Catch::Contains("the matrix of block 0 is 3 × 2, the block is 3 × 3"));
}
