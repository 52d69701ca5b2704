#pragma once
/// \file
/// Sparse assembly with a pattern computed once.
///
/// A model's iteration matrix has a sparsity pattern fixed by its topology: every element couples
/// its own dofs (a square "element block"), every constraint couples its multiplier rows with the
/// dofs it constrains (a rectangular "coupling block" together with its transpose, which gives the
/// saddle-point matrix [K Bᵀ; B 0] its symmetric structure). SparsePattern builds the compressed
/// column structure once from that list of blocks and records, for every entry of every block,
/// its position in the value array. Assembly then scatters each dense block with no search and no
/// allocation, and the structure never changes, so a solver's symbolic factorization is reused
/// for every Newton iteration and every time step.

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <cstddef>
#include <functional>
#include <vector>

namespace spar::core {

/// The sparse matrix type of assembled systems: column-major, `int` indices (what KLU and UMFPACK
/// take without conversion).
using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

/// The global dofs of one dense block of the pattern. Build one with `element` or `coupling`.
struct PatternBlock {
  /// The global row indices of the block.
  std::vector<int> rows;
  /// The global column indices of the block.
  std::vector<int> cols;
  /// True for a coupling block: the transpose position (cols × rows) belongs to the block too.
  bool with_transpose = false;

  /// A square block dofs × dofs: the stiffness, mass or damping coupling of one element.
  static PatternBlock element(std::vector<int> dofs);
  /// A rectangular block rows × cols plus its transpose position cols × rows: a constraint
  /// Jacobian B (rows = its multipliers, cols = the dofs it constrains) and Bᵀ.
  static PatternBlock coupling(std::vector<int> rows, std::vector<int> cols);
};

/// How SparsePattern::assemble runs the blocks.
enum class AssemblyExecution {
  serial,   ///< one thread, blocks in colour order
  parallel  ///< OpenMP threads, one colour at a time (the result is bitwise the serial one)
};

/// Computes the dense matrix of block `block_id` into `K`, which arrives sized rows × cols of
/// that block and zeroed. Called concurrently from several threads by a parallel assembly, each
/// with its own `K`, so it must not write shared state.
using BlockCompute = std::function<void(int block_id, Eigen::MatrixXd& K)>;

/// The compressed sparse structure of an n × n system built once from a list of dense blocks,
/// with the value position of every block entry precomputed, and the matrix it owns.
///
/// The diagonal is always in the pattern (so Dirichlet rows can hold their 1). Block ids are the
/// indices into the list given to the constructor. Duplicate dofs within a block are allowed:
/// their contributions are summed, as in A += Pᵀ K P.
class SparsePattern {
public:
  /// Builds the structure of an n × n matrix holding every block and the diagonal, with all values
  /// zero. Throws spar::Error if n < 0, or a block's row or column index is outside [0, n).
  SparsePattern(int size, const std::vector<PatternBlock>& blocks);

  /// The number of rows (= columns) of the matrix.
  int size() const noexcept { return static_cast<int>(matrix_.rows()); }
  /// The number of blocks given to the constructor.
  int block_count() const noexcept { return static_cast<int>(blocks_.size()); }
  /// The global dofs of block `block_id` (unchecked).
  const PatternBlock& block(int block_id) const noexcept { return blocks_[block_id]; }
  /// The number of stored entries (structural nonzeros) of the matrix.
  int nonzeros() const noexcept { return static_cast<int>(matrix_.nonZeros()); }

  /// The assembled matrix: compressed, fixed structure, current values.
  const SparseMatrix& matrix() const noexcept { return matrix_; }

  /// Sets every value to zero, keeping the structure.
  void set_zero() noexcept;

  /// Adds the dense block K into the matrix at the positions of block `block_id`:
  /// A(rows, cols) += K, and for a coupling block also A(cols, rows) += Kᵀ. No search, no
  /// allocation. Throws spar::Error if `block_id` is out of range or K is not rows × cols.
  void add_block(int block_id, const Eigen::Ref<const Eigen::MatrixXd>& K);

  /// Adds the two halves of a coupling block whose values are not each other's transpose
  /// (e.g. B·T and Bᵀ of a Lie-group iteration matrix): A(rows, cols) += K and
  /// A(cols, rows) += K_transpose_position. Throws spar::Error if `block_id` is out of range or
  /// not a coupling block, or if K is not rows × cols or K_transpose_position not cols × rows.
  void add_block(int block_id, const Eigen::Ref<const Eigen::MatrixXd>& K,
                 const Eigen::Ref<const Eigen::MatrixXd>& K_transpose_position);

  /// Assembles the whole matrix: set_zero(), then for every block calls `compute(block_id, K)`
  /// and add_block(block_id, K). The parallel execution runs the blocks of one colour at a time
  /// on OpenMP threads, each thread with its own workspace K; blocks of one colour share no dof,
  /// so no two threads write the same value and no lock is taken. Both executions add the blocks
  /// in the same order, so they give bitwise identical matrices. An exception thrown by `compute`
  /// (or a K it resized) is rethrown on the calling thread once every block has been visited; the
  /// values are then incomplete.
  void assemble(const BlockCompute& compute,
                AssemblyExecution execution = AssemblyExecution::parallel);

  /// The number of colours of the block colouring used by the parallel assembly: blocks of one
  /// colour share no dof.
  int colour_count() const noexcept { return static_cast<int>(colour_starts_.size()) - 1; }

  /// Imposes homogeneous Dirichlet conditions (zero increments) on `fixed_dofs`: zeroes their rows
  /// and columns in the values, puts 1 on their diagonal and 0 in `rhs`. The structure is
  /// unchanged, so the symbolic factorization stays valid. Throws spar::Error if a dof is outside
  /// [0, n) or `rhs` does not have n entries. Repeated dofs are allowed.
  void apply_dirichlet(const std::vector<int>& fixed_dofs, Eigen::Ref<Eigen::VectorXd> rhs);

private:
  void scatter(int block_id, const Eigen::Ref<const Eigen::MatrixXd>& K,
               const Eigen::Ref<const Eigen::MatrixXd>& K_transpose_position, bool transpose_of_K);
  void check_block_id(int block_id, const char* where) const;
  void colour_blocks();

  SparseMatrix matrix_;
  std::vector<PatternBlock> blocks_;
  /// positions_[block_offsets_[b] + j·m + i] is the value index of entry (i, j) of block b
  /// (m = its row count); for a coupling block, the next m·n entries hold the value index of
  /// A(cols[j], rows[i]) at the same offset j·m + i.
  std::vector<int> positions_;
  std::vector<std::size_t> block_offsets_;
  /// The value index of every diagonal entry.
  std::vector<int> diagonal_positions_;
  /// Blocks sorted by colour: colour c holds colour_order_[colour_starts_[c] .. colour_starts_[c+1]).
  std::vector<int> colour_order_;
  std::vector<int> colour_starts_;
  /// One dense workspace per OpenMP thread, reused across assemblies.
  std::vector<Eigen::MatrixXd> workspaces_;
};

}  // namespace spar::core
