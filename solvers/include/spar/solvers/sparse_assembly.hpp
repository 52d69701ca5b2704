#pragma once
/// \file
/// Sparse assembly with a pattern computed once.
///
/// A model's iteration matrix has a sparsity pattern fixed by its topology: every element couples
/// its own dofs, a dense square block dofs × dofs. A constraint is one such block too, over the
/// dofs it constrains followed by its multipliers: [K_λ Bᵀ; B 0] (solvers/src/system_assembly.cpp),
/// which gives the saddle-point matrix its symmetric structure. SparsePattern builds the compressed
/// column structure once from that list of blocks and records, for every entry of every block,
/// its position in the value array. Assembly then scatters each dense block with no search and no
/// allocation, and the structure never changes, so a solver's symbolic factorization is reused
/// for every Newton iteration and every time step.

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

namespace spar::solvers {

/// The sparse matrix type of assembled systems: column-major, `int` indices (what KLU and UMFPACK
/// take without conversion).
using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

/// One dense square block of the pattern: the global dofs it couples, which index both its rows
/// and its columns (entry (i, j) of the block adds to A(dofs[i], dofs[j])).
struct PatternBlock {
  std::vector<int> dofs;

  /// The block dofs × dofs of one element (or of one constraint, over its dofs and multipliers).
  static PatternBlock element(std::vector<int> dofs) { return PatternBlock{std::move(dofs)}; }
};

/// How SparsePattern::assemble runs the blocks. Every execution gives bitwise the same matrix.
enum class AssemblyExecution {
  serial,    ///< one thread: each block computed and added in block order
  parallel,  ///< the caller and helper threads compute the blocks (solvers/work_sharing.hpp), then sum
             ///< every value from its contributions in block order
  automatic  ///< parallel from `parallel_assembly_min_blocks` blocks up with > 1 thread, else serial;
             ///< the solvers, below that count, run serial or parallel as they time the two
};

/// The block count from which AssemblyExecution::automatic runs in parallel. Measured on a 2-core
/// machine with cubic beam elements (docs/performance.md, "Scaling"): from it on the second thread
/// always saves more than waking the helper and storing the blocks cost. Below it, it may or may
/// not (the slider-crank's 17 blocks: 23 against 39 µs on two idle cores, slower with a build
/// running on the other core), and the solvers time both (solvers/src/execution_choice.hpp).
inline constexpr int parallel_assembly_min_blocks = 200;

/// Computes the dense matrix of block `block_id` into `K`, which arrives sized n × n (n = the
/// block's dof count) and zeroed. Called concurrently from several threads by a parallel assembly, each
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
  /// zero. Throws spar::Error if n < 0, or a block's dof is outside [0, n).
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
  /// A(dofs, dofs) += K. No search, no allocation. Throws spar::Error if `block_id` is out of
  /// range or K is not n × n (n = the block's dof count).
  void add_block(int block_id, const Eigen::Ref<const Eigen::MatrixXd>& K);

  /// Assembles the whole matrix from every block's `compute(block_id, K)`.
  ///
  /// Serial: for every block in order, computes it into one workspace K and add_block()s it.
  /// Parallel: the calling thread and the helpers of WorkSharing::shared() compute the blocks in
  /// chunks taken on demand (a thread slowed by another process takes fewer, and none is waited
  /// for before it starts), each into its own workspace, and copy every block into its own slot
  /// of a block-value store; once every block is stored, they fill chunks of the matrix's values,
  /// each value the sum of its contributions in block order. The sums are those of the serial
  /// execution, in the same order, so both give bitwise identical matrices. The store and the
  /// value-to-contribution map (a double and a 32-bit index per block entry) are built at the
  /// first parallel assembly.
  ///
  /// An exception thrown by `compute` (or a K it resized) is rethrown on the calling thread once
  /// every thread has finished; the values are then incomplete.
  void assemble(const BlockCompute& compute,
                AssemblyExecution execution = AssemblyExecution::automatic);

  /// True when `execution` runs on more than one thread for this pattern (`automatic` resolved by
  /// the block count and WorkSharing::shared().thread_count(), i.e. OMP_NUM_THREADS).
  bool runs_parallel(AssemblyExecution execution) const noexcept;

  /// Imposes homogeneous Dirichlet conditions (zero increments) on `fixed_dofs`: zeroes their rows
  /// and columns in the values, puts 1 on their diagonal and 0 in `rhs`. The structure is
  /// unchanged, so the symbolic factorization stays valid. Throws spar::Error if a dof is outside
  /// [0, n) or `rhs` does not have n entries. Repeated dofs are allowed. The value indices of the
  /// fixed rows and columns are found once per list of fixed dofs and kept: a later call with the
  /// same list touches only those entries, not the whole matrix.
  void apply_dirichlet(const std::vector<int>& fixed_dofs, Eigen::Ref<Eigen::VectorXd> rhs);

private:
  void scatter(int block_id, const Eigen::Ref<const Eigen::MatrixXd>& K);
  void check_block_id(int block_id, const char* where) const;
  void assemble_serial(const BlockCompute& compute);
  void assemble_parallel(const BlockCompute& compute);
  void build_gather();
  void find_dirichlet_positions(const std::vector<int>& fixed_dofs);

  SparseMatrix matrix_;
  std::vector<PatternBlock> blocks_;
  /// positions_[block_offsets_[b] + j·n + i] is the value index of entry (i, j) of block b
  /// (n = its dof count): the entries of every block in the column-major order of its matrix.
  std::vector<int> positions_;
  std::vector<std::size_t> block_offsets_;
  /// The value index of every diagonal entry.
  std::vector<int> diagonal_positions_;
  /// apply_dirichlet: the fixed dofs last given, and the value indices of their rows and columns.
  std::vector<int> dirichlet_dofs_;
  std::vector<int> dirichlet_positions_;
  /// One dense workspace per thread of the team, reused across assemblies.
  std::vector<Eigen::MatrixXd> workspaces_;
  /// Parallel assembly: block b's dense matrix (column-major) at block_values_[block_offsets_[b]],
  /// so that block_values_[s] lands at positions_[s].
  std::vector<double> block_values_;
  /// Parallel assembly: value k of the matrix is the sum of block_values_[gather_sources_[s]] for
  /// s in [gather_starts_[k], gather_starts_[k+1]), in the order add_block() adds them.
  std::vector<std::size_t> gather_starts_;
  std::vector<std::uint32_t> gather_sources_;
};

}  // namespace spar::solvers
