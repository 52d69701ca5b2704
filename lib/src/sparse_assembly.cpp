#include <spar/core/sparse_assembly.hpp>

#include <spar/error.hpp>

#include <omp.h>

#include <algorithm>
#include <exception>
#include <string>

namespace spar::core {

namespace {

constexpr const char* pattern_where = "core::SparsePattern";

void check_indices(const std::vector<int>& indices, int size, int block_id, const char* role) {
  for (int index : indices)
    if (index < 0 || index >= size)
      throw Error("block " + std::to_string(block_id) + " has " + role + " index " +
                      std::to_string(index) + " outside [0, " + std::to_string(size) + ")",
                  pattern_where, "give every block global dof indices of the n × n system");
}

/// The value index of entry (row, col) of a compressed column matrix whose structure holds it.
int value_position(const SparseMatrix& A, int row, int col) {
  const int* begin = A.innerIndexPtr() + A.outerIndexPtr()[col];
  const int* end = A.innerIndexPtr() + A.outerIndexPtr()[col + 1];
  return static_cast<int>(std::lower_bound(begin, end, row) - A.innerIndexPtr());
}

/// The dofs a block touches (rows ∪ cols), sorted and unique.
std::vector<int> touched_dofs(const PatternBlock& block) {
  std::vector<int> dofs = block.rows;
  dofs.insert(dofs.end(), block.cols.begin(), block.cols.end());
  std::sort(dofs.begin(), dofs.end());
  dofs.erase(std::unique(dofs.begin(), dofs.end()), dofs.end());
  return dofs;
}

}  // namespace

PatternBlock PatternBlock::element(std::vector<int> dofs) {
  PatternBlock block;
  block.rows = dofs;
  block.cols = std::move(dofs);
  return block;
}

PatternBlock PatternBlock::coupling(std::vector<int> rows, std::vector<int> cols) {
  PatternBlock block;
  block.rows = std::move(rows);
  block.cols = std::move(cols);
  block.with_transpose = true;
  return block;
}

SparsePattern::SparsePattern(int size, const std::vector<PatternBlock>& blocks) : blocks_(blocks) {
  if (size < 0)
    throw Error("negative matrix size " + std::to_string(size), pattern_where,
                "pass the number of dofs of the system");
  for (int b = 0; b < block_count(); ++b) {
    check_indices(blocks_[b].rows, size, b, "row");
    check_indices(blocks_[b].cols, size, b, "column");
  }

  // 1. The row indices of every column: the diagonal, then every block entry (and its transpose).
  std::vector<std::vector<int>> column_rows(size);
  for (int c = 0; c < size; ++c) column_rows[c].push_back(c);
  for (const PatternBlock& block : blocks_) {
    for (int col : block.cols)
      column_rows[col].insert(column_rows[col].end(), block.rows.begin(), block.rows.end());
    if (block.with_transpose)
      for (int row : block.rows)
        column_rows[row].insert(column_rows[row].end(), block.cols.begin(), block.cols.end());
  }
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
    for (int col : block.cols)
      for (int row : block.rows) positions_.push_back(value_position(matrix_, row, col));
    if (block.with_transpose)
      for (int col : block.cols)
        for (int row : block.rows) positions_.push_back(value_position(matrix_, col, row));
    block_offsets_.push_back(positions_.size());
  }
  diagonal_positions_.resize(size);
  for (int c = 0; c < size; ++c) diagonal_positions_[c] = value_position(matrix_, c, c);

  colour_blocks();
}

void SparsePattern::colour_blocks() {
  // Greedy colouring in block order: a block takes the smallest colour that no earlier block
  // sharing one of its dofs has.
  const int size = this->size();
  std::vector<std::vector<int>> dof_blocks(size);
  std::vector<std::vector<int>> block_dofs(blocks_.size());
  for (int b = 0; b < block_count(); ++b) {
    block_dofs[b] = touched_dofs(blocks_[b]);
    for (int dof : block_dofs[b]) dof_blocks[dof].push_back(b);
  }
  std::vector<int> colour(blocks_.size(), -1);
  std::vector<int> forbidden_by;  // forbidden_by[c] == b: colour c is taken by a neighbour of b
  int colours = 0;
  for (int b = 0; b < block_count(); ++b) {
    for (int dof : block_dofs[b])
      for (int neighbour : dof_blocks[dof])
        if (colour[neighbour] >= 0) forbidden_by[colour[neighbour]] = b;
    int c = 0;
    while (c < colours && forbidden_by[c] == b) ++c;
    if (c == colours) {
      ++colours;
      forbidden_by.push_back(-1);
    }
    colour[b] = c;
  }

  colour_starts_.assign(colours + 1, 0);
  for (int c : colour) ++colour_starts_[c + 1];
  for (int c = 0; c < colours; ++c) colour_starts_[c + 1] += colour_starts_[c];
  colour_order_.resize(blocks_.size());
  std::vector<int> next(colour_starts_.begin(), colour_starts_.end() - 1);
  for (int b = 0; b < block_count(); ++b) colour_order_[next[colour[b]]++] = b;
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
  check_block_id(block_id, "core::SparsePattern::add_block");
  scatter(block_id, K, K, true);
}

void SparsePattern::add_block(int block_id, const Eigen::Ref<const Eigen::MatrixXd>& K,
                              const Eigen::Ref<const Eigen::MatrixXd>& K_transpose_position) {
  check_block_id(block_id, "core::SparsePattern::add_block");
  const PatternBlock& block = blocks_[block_id];
  if (!block.with_transpose)
    throw Error("block " + std::to_string(block_id) + " is an element block",
                "core::SparsePattern::add_block",
                "pass one matrix for an element block; two are for a coupling block");
  if (K_transpose_position.rows() != static_cast<Eigen::Index>(block.cols.size()) ||
      K_transpose_position.cols() != static_cast<Eigen::Index>(block.rows.size()))
    throw Error("the transpose-position matrix of block " + std::to_string(block_id) + " is " +
                    std::to_string(K_transpose_position.rows()) + " × " +
                    std::to_string(K_transpose_position.cols()) + ", the block is " +
                    std::to_string(block.cols.size()) + " × " + std::to_string(block.rows.size()),
                "core::SparsePattern::add_block", "size it cols × rows of the block");
  scatter(block_id, K, K_transpose_position, false);
}

void SparsePattern::scatter(int block_id, const Eigen::Ref<const Eigen::MatrixXd>& K,
                            const Eigen::Ref<const Eigen::MatrixXd>& K_transpose_position,
                            bool transpose_of_K) {
  const PatternBlock& block = blocks_[block_id];
  const Eigen::Index rows = static_cast<Eigen::Index>(block.rows.size());
  const Eigen::Index cols = static_cast<Eigen::Index>(block.cols.size());
  if (K.rows() != rows || K.cols() != cols)
    throw Error("the matrix of block " + std::to_string(block_id) + " is " +
                    std::to_string(K.rows()) + " × " + std::to_string(K.cols()) +
                    ", the block is " + std::to_string(rows) + " × " + std::to_string(cols),
                "core::SparsePattern::add_block", "size it rows × cols of the block");
  double* values = matrix_.valuePtr();
  const int* position = positions_.data() + block_offsets_[block_id];
  for (Eigen::Index j = 0; j < cols; ++j)
    for (Eigen::Index i = 0; i < rows; ++i) values[*position++] += K(i, j);
  if (!block.with_transpose) return;
  // `position` now points at the value indices of A(cols[j], rows[i]), in the same (i, j) order.
  for (Eigen::Index j = 0; j < cols; ++j)
    for (Eigen::Index i = 0; i < rows; ++i)
      values[*position++] += transpose_of_K ? K(i, j) : K_transpose_position(j, i);
}

// Colouring rather than `omp atomic` adds: measured with bench_solvers (200 blocks of 24 × 24,
// 2 threads), the scatter alone took 79 µs coloured against 210 µs with atomics (137 µs serial);
// with a beam-like element kernel both assemble in ~0.7 ms (1.05 ms serial). Colouring also
// makes the sums' order fixed, so a parallel run reproduces the serial one bit for bit.
void SparsePattern::assemble(const BlockCompute& compute, AssemblyExecution execution) {
  set_zero();
  const bool parallel = execution == AssemblyExecution::parallel;
  const int threads = parallel ? omp_get_max_threads() : 1;
  if (static_cast<int>(workspaces_.size()) < threads) workspaces_.resize(threads);
  std::vector<std::exception_ptr> failures(threads);

#pragma omp parallel num_threads(threads) if (parallel)
  {
    const int thread = omp_get_thread_num();
    Eigen::MatrixXd& K = workspaces_[thread];
    for (int colour = 0; colour < colour_count(); ++colour) {
      // The implicit barrier at the end of the loop separates the colours.
#pragma omp for schedule(static)
      for (int k = colour_starts_[colour]; k < colour_starts_[colour + 1]; ++k) {
        if (failures[thread]) continue;
        const int block_id = colour_order_[k];
        const PatternBlock& block = blocks_[block_id];
        try {
          K.setZero(static_cast<Eigen::Index>(block.rows.size()),
                    static_cast<Eigen::Index>(block.cols.size()));
          compute(block_id, K);
          scatter(block_id, K, K, true);
        } catch (...) {
          failures[thread] = std::current_exception();
        }
      }
    }
  }
  for (const std::exception_ptr& failure : failures)
    if (failure) std::rethrow_exception(failure);
}

void SparsePattern::apply_dirichlet(const std::vector<int>& fixed_dofs,
                                    Eigen::Ref<Eigen::VectorXd> rhs) {
  const int size = this->size();
  if (rhs.size() != size)
    throw Error("right-hand side has " + std::to_string(rhs.size()) + " entries, the matrix " +
                    std::to_string(size) + " rows",
                "core::SparsePattern::apply_dirichlet", "pass the residual of this system");
  std::vector<char> fixed(size, 0);
  for (int dof : fixed_dofs) {
    if (dof < 0 || dof >= size)
      throw Error("fixed dof " + std::to_string(dof) + " outside [0, " + std::to_string(size) +
                      ")",
                  "core::SparsePattern::apply_dirichlet", "fix dofs of this system only");
    fixed[dof] = 1;
  }
  double* values = matrix_.valuePtr();
  const int* outer = matrix_.outerIndexPtr();
  const int* inner = matrix_.innerIndexPtr();
  for (int c = 0; c < size; ++c)
    for (int k = outer[c]; k < outer[c + 1]; ++k)
      if (fixed[c] || fixed[inner[k]]) values[k] = 0.0;
  for (int c = 0; c < size; ++c)
    if (fixed[c]) {
      values[diagonal_positions_[c]] = 1.0;
      rhs[c] = 0.0;
    }
}

}  // namespace spar::core
