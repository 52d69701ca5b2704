#include <spar/solvers/sparse_assembly.hpp>

#include <spar/solvers/work_sharing.hpp>
#include <spar/error.hpp>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <string>

namespace spar::solvers {

namespace {

constexpr const char* pattern_where = "solvers::SparsePattern";

void check_dofs(const PatternBlock& block, int size, int block_id) {
  for (int dof : block.dofs)
    if (dof < 0 || dof >= size)
      throw Error("block " + std::to_string(block_id) + " has dof " + std::to_string(dof) +
                      " outside [0, " + std::to_string(size) + ")",
                  pattern_where, "give every block global dof indices of the n × n system");
}

/// The value index of entry (row, col) of a compressed column matrix whose structure holds it.
int value_position(const SparseMatrix& A, int row, int col) {
  const int* begin = A.innerIndexPtr() + A.outerIndexPtr()[col];
  const int* end = A.innerIndexPtr() + A.outerIndexPtr()[col + 1];
  return static_cast<int>(std::lower_bound(begin, end, row) - A.innerIndexPtr());
}

/// Throws spar::Error unless K is n × n, n the dof count of `block`.
void check_block_matrix(int block_id, const PatternBlock& block,
                        const Eigen::Ref<const Eigen::MatrixXd>& K) {
  const auto n = static_cast<Eigen::Index>(block.dofs.size());
  if (K.rows() != n || K.cols() != n)
    throw Error("the matrix of block " + std::to_string(block_id) + " is " +
                    std::to_string(K.rows()) + " × " + std::to_string(K.cols()) +
                    ", the block is " + std::to_string(n) + " × " + std::to_string(n),
                "solvers::SparsePattern::add_block", "size it n × n, n the block's dof count");
}

/// Sizes K n × n for `block` and zeroes it.
void reset_block_matrix(const PatternBlock& block, Eigen::MatrixXd& K) {
  const auto n = static_cast<Eigen::Index>(block.dofs.size());
  K.setZero(n, n);
}

}  // namespace

SparsePattern::SparsePattern(int size, const std::vector<PatternBlock>& blocks) : blocks_(blocks) {
  if (size < 0)
    throw Error("negative matrix size " + std::to_string(size), pattern_where,
                "pass the number of dofs of the system");
  for (int b = 0; b < block_count(); ++b) check_dofs(blocks_[b], size, b);

  // 1. The row indices of every column: the diagonal, then every block entry.
  std::vector<std::vector<int>> column_rows(size);
  for (int c = 0; c < size; ++c) column_rows[c].push_back(c);
  for (const PatternBlock& block : blocks_)
    for (int col : block.dofs)
      column_rows[col].insert(column_rows[col].end(), block.dofs.begin(), block.dofs.end());
  std::size_t nonzeros = 0;
  for (std::vector<int>& rows : column_rows) {
    std::sort(rows.begin(), rows.end());
    rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
    nonzeros += rows.size();
  }

  // 2. The compressed column structure, values zero.
  matrix_.resize(size, size);
  matrix_.resizeNonZeros(static_cast<Eigen::Index>(nonzeros));
  int* outer = matrix_.outerIndexPtr();
  int* inner = matrix_.innerIndexPtr();
  outer[0] = 0;
  for (int c = 0; c < size; ++c) {
    std::copy(column_rows[c].begin(), column_rows[c].end(), inner + outer[c]);
    outer[c + 1] = outer[c] + static_cast<int>(column_rows[c].size());
  }
  set_zero();

  // 3. The value index of every block entry, in the column-major order of the dense block.
  block_offsets_.reserve(blocks_.size() + 1);
  block_offsets_.push_back(0);
  for (const PatternBlock& block : blocks_) {
    for (int col : block.dofs)
      for (int row : block.dofs) positions_.push_back(value_position(matrix_, row, col));
    block_offsets_.push_back(positions_.size());
  }
  diagonal_positions_.resize(size);
  for (int c = 0; c < size; ++c) diagonal_positions_[c] = value_position(matrix_, c, c);
}

void SparsePattern::set_zero() noexcept {
  std::fill_n(matrix_.valuePtr(), matrix_.nonZeros(), 0.0);
}

void SparsePattern::check_block_id(int block_id, const char* where) const {
  if (block_id < 0 || block_id >= block_count())
    throw Error("block id " + std::to_string(block_id) + " outside [0, " +
                    std::to_string(block_count()) + ")",
                where, "use the index of the block in the list given to the constructor");
}

void SparsePattern::add_block(int block_id, const Eigen::Ref<const Eigen::MatrixXd>& K) {
  check_block_id(block_id, "solvers::SparsePattern::add_block");
  scatter(block_id, K);
}

void SparsePattern::scatter(int block_id, const Eigen::Ref<const Eigen::MatrixXd>& K) {
  const PatternBlock& block = blocks_[block_id];
  check_block_matrix(block_id, block, K);
  const auto n = static_cast<Eigen::Index>(block.dofs.size());
  double* values = matrix_.valuePtr();
  const int* position = positions_.data() + block_offsets_[block_id];
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::Index i = 0; i < n; ++i) values[*position++] += K(i, j);
}

bool SparsePattern::runs_parallel(AssemblyExecution execution) const noexcept {
  switch (execution) {
    case AssemblyExecution::serial: return false;
    case AssemblyExecution::parallel: return WorkSharing::shared().thread_count() > 1;
    case AssemblyExecution::automatic:
      return block_count() >= parallel_assembly_min_blocks &&
             WorkSharing::shared().thread_count() > 1;
  }
  return false;
}

void SparsePattern::assemble(const BlockCompute& compute, AssemblyExecution execution) {
  if (runs_parallel(execution))
    assemble_parallel(compute);
  else
    assemble_serial(compute);
}

void SparsePattern::assemble_serial(const BlockCompute& compute) {
  set_zero();
  if (workspaces_.empty()) workspaces_.resize(1);
  Eigen::MatrixXd& K = workspaces_.front();
  for (int block_id = 0; block_id < block_count(); ++block_id) {
    reset_block_matrix(blocks_[block_id], K);
    compute(block_id, K);
    scatter(block_id, K);
  }
}

void SparsePattern::build_gather() {
  // 1. The block-value store: every block's entries, column-major, at its offset in positions_.
  if (positions_.size() > std::numeric_limits<std::uint32_t>::max())
    throw Error("the blocks hold " + std::to_string(positions_.size()) +
                    " entries, more than a parallel assembly indexes (2^32)",
                "solvers::SparsePattern::assemble", "assemble serially (AssemblyExecution::serial)");
  block_values_.assign(positions_.size(), 0.0);

  // 2. For every matrix value, its contributions in the order scatter() adds them: blocks in
  //    order; within a block, the entries (i, j) column by column. positions_ lists exactly
  //    these, block after block, so its index s is the order, and block_values_[s] the value
  //    added at positions_[s]. A counting sort keeps that order within a value.
  const std::size_t values = static_cast<std::size_t>(nonzeros());
  gather_starts_.assign(values + 1, 0);
  for (int position : positions_) ++gather_starts_[static_cast<std::size_t>(position) + 1];
  for (std::size_t k = 0; k < values; ++k) gather_starts_[k + 1] += gather_starts_[k];
  gather_sources_.resize(positions_.size());
  std::vector<std::size_t> next(gather_starts_.begin(), gather_starts_.end() - 1);
  for (std::size_t s = 0; s < positions_.size(); ++s)
    gather_sources_[next[positions_[s]]++] = static_cast<std::uint32_t>(s);
}

// With another process on a core, an OpenMP team (one barrier per colour of a block colouring,
// the scheme before) waited at every barrier for its descheduled thread while the others spun:
// runs of a cantilevered beam took up to 12× the serial time (docs/performance.md, "Scaling").
// Here the blocks go to whichever thread is free (solvers/work_sharing.hpp), and where each block
// lands is fixed, so the schedule does not change the result.
void SparsePattern::assemble_parallel(const BlockCompute& compute) {
  if (gather_starts_.empty()) build_gather();
  WorkSharing& team = WorkSharing::shared();
  if (static_cast<int>(workspaces_.size()) < team.thread_count())
    workspaces_.resize(team.thread_count());
  // At most 64 beam elements (~0.5 ms) per chunk.
  const int chunk = team.chunk_for(block_count(), 64);
  team.for_each_chunk(block_count(), chunk, [&](int begin, int end, int thread) {
    Eigen::MatrixXd& K = workspaces_[thread];
    for (int block_id = begin; block_id < end; ++block_id) {
      const PatternBlock& block = blocks_[block_id];
      reset_block_matrix(block, K);
      compute(block_id, K);
      check_block_matrix(block_id, block, K);
      std::copy_n(K.data(), K.size(), block_values_.data() + block_offsets_[block_id]);
    }
  });
  // Every block is stored: each value is set_zero() and the serial additions, in their order.
  double* values = matrix_.valuePtr();
  team.for_each_chunk(nonzeros(), 16384, [&](int begin, int end, int) {
    for (int k = begin; k < end; ++k) {
      double sum = 0.0;
      for (std::size_t s = gather_starts_[k]; s < gather_starts_[k + 1]; ++s)
        sum += block_values_[gather_sources_[s]];
      values[k] = sum;
    }
  });
}

void SparsePattern::apply_dirichlet(const std::vector<int>& fixed_dofs,
                                    Eigen::Ref<Eigen::VectorXd> rhs) {
  const int size = this->size();
  if (rhs.size() != size)
    throw Error("right-hand side has " + std::to_string(rhs.size()) + " entries, the matrix " +
                    std::to_string(size) + " rows",
                "solvers::SparsePattern::apply_dirichlet", "pass the residual of this system");
  if (fixed_dofs != dirichlet_dofs_) find_dirichlet_positions(fixed_dofs);
  double* values = matrix_.valuePtr();
  for (const int k : dirichlet_positions_) values[k] = 0.0;
  for (const int dof : fixed_dofs) {
    values[diagonal_positions_[dof]] = 1.0;
    rhs[dof] = 0.0;
  }
}

void SparsePattern::find_dirichlet_positions(const std::vector<int>& fixed_dofs) {
  const int size = this->size();
  std::vector<char> fixed(size, 0);
  for (int dof : fixed_dofs) {
    if (dof < 0 || dof >= size)
      throw Error("fixed dof " + std::to_string(dof) + " outside [0, " + std::to_string(size) +
                      ")",
                  "solvers::SparsePattern::apply_dirichlet", "fix dofs of this system only");
    fixed[dof] = 1;
  }
  const int* outer = matrix_.outerIndexPtr();
  const int* inner = matrix_.innerIndexPtr();
  dirichlet_positions_.clear();
  for (int c = 0; c < size; ++c)
    for (int k = outer[c]; k < outer[c + 1]; ++k)
      if (fixed[c] || fixed[inner[k]]) dirichlet_positions_.push_back(k);
  dirichlet_dofs_ = fixed_dofs;
}

}  // namespace spar::solvers
