#include <spar/core/configuration.hpp>
#include <spar/error.hpp>
#include <spar/lie/exp.hpp>
#include <spar/lie/log.hpp>
#include <spar/lie/tangent.hpp>

#include <string>

namespace spar::core {

namespace {

void append_block(Configuration& q, BlockKind kind, int size) {
  q.blocks.push_back({kind, size, q.dof_count()});
  q.values.conservativeResize(q.dof_count() + size);
}

void check_increment_size(const Configuration& q, Eigen::Index size, const char* where) {
  if (size != q.dof_count())
    throw Error("increment has " + std::to_string(size) + " entries for " +
                    std::to_string(q.dof_count()) + " degrees of freedom",
                where, "pass one entry per degree of freedom of the configuration");
}

}  // namespace

int Configuration::add_frame(const Eigen::Vector3d& x, const Eigen::Matrix3d& R) {
  const int b = block_count();
  append_block(*this, BlockKind::frame, frame_dofs);
  values.tail<frame_dofs>().setZero();
  position.push_back(x);
  rotation.push_back(R);
  return b;
}

int Configuration::add_vector(const Eigen::Ref<const Eigen::VectorXd>& p) {
  if (p.size() < 1)
    throw Error("a vector block needs at least one coordinate", "core::Configuration::add_vector",
                "pass the block's initial coordinates");
  const int b = block_count();
  append_block(*this, BlockKind::vector, static_cast<int>(p.size()));
  values.tail(p.size()) = p;
  position.push_back(Eigen::Vector3d::Zero());
  rotation.push_back(Eigen::Matrix3d::Identity());
  return b;
}

// docs/model.md eq. M1.
void Configuration::apply_increment(const Eigen::Ref<const Eigen::VectorXd>& delta) {
  check_increment_size(*this, delta.size(), "core::Configuration::apply_increment");
  for (int b = 0; b < block_count(); ++b) {
    const Block& block = blocks[b];
    if (block.kind == BlockKind::frame) {
      position[b] += delta.segment<3>(block.offset);
      rotation[b] = lie::right_plus(rotation[b], delta.segment<3>(block.offset + 3));
    } else {
      values.segment(block.offset, block.size) += delta.segment(block.offset, block.size);
    }
  }
}

void Configuration::assign_increment(const Configuration& start,
                                     const Eigen::Ref<const Eigen::VectorXd>& delta) {
  check_increment_size(start, delta.size(), "core::Configuration::assign_increment");
  for (int b = 0; b < block_count(); ++b) {
    const Block& block = blocks[b];
    if (block.kind == BlockKind::frame) {
      position[b] = start.position[b] + delta.segment<3>(block.offset);
      rotation[b] = lie::right_plus(start.rotation[b], delta.segment<3>(block.offset + 3));
    } else {
      values.segment(block.offset, block.size) =
          start.values.segment(block.offset, block.size) + delta.segment(block.offset, block.size);
    }
  }
}

// docs/model.md eq. M2.
double Configuration::largest_rotation(const Eigen::Ref<const Eigen::VectorXd>& delta) const {
  double largest = 0.0;
  for (const Block& block : blocks)
    if (block.kind == BlockKind::frame)
      largest = std::max(largest, delta.segment<3>(block.offset + 3).norm());
  return largest;
}

// docs/model.md eq. M1, inverted; docs/conventions.md eq. C13.
Eigen::VectorXd Configuration::increment_from(const Configuration& start) const {
  bool same_layout = start.block_count() == block_count() && start.dof_count() == dof_count();
  for (int b = 0; same_layout && b < block_count(); ++b)
    same_layout = start.blocks[b].kind == blocks[b].kind && start.blocks[b].size == blocks[b].size;
  if (!same_layout)
    throw Error("the configurations have another layout (" + std::to_string(block_count()) + " blocks of " +
                    std::to_string(dof_count()) + " dofs against " + std::to_string(start.block_count()) +
                    " blocks of " + std::to_string(start.dof_count()) + ", or blocks of other kinds)",
                "core::Configuration::increment_from",
                "subtract configurations of one layout (after Model::replace_state, the new layout's)");
  Eigen::VectorXd delta(dof_count());
  for (int b = 0; b < block_count(); ++b) {
    const Block& block = blocks[b];
    if (block.kind == BlockKind::frame) {
      delta.segment<3>(block.offset) = position[b] - start.position[b];
      delta.segment<3>(block.offset + 3) = lie::log(start.rotation[b].transpose() * rotation[b]);
    } else {
      delta.segment(block.offset, block.size) = vector(b) - start.vector(b);
    }
  }
  return delta;
}

std::vector<int> block_dofs(const Configuration& q, const std::vector<int>& blocks) {
  std::vector<int> dofs;
  dofs.reserve(static_cast<std::size_t>(block_dof_count(q, blocks)));
  for (const int b : blocks)
    for (int i = 0; i < q.blocks[b].size; ++i) dofs.push_back(q.blocks[b].offset + i);
  return dofs;
}

int block_dof_count(const Configuration& q, const std::vector<int>& blocks) {
  int count = 0;
  for (const int b : blocks) count += q.blocks[b].size;
  return count;
}

void gather(const Configuration& q, const std::vector<int>& blocks, const Eigen::VectorXd& global,
            Eigen::Ref<Eigen::VectorXd> local) {
  Eigen::Index at = 0;
  for (const int b : blocks) {
    const Block& block = q.blocks[b];
    local.segment(at, block.size) = global.segment(block.offset, block.size);
    at += block.size;
  }
}

// docs/model.md eq. M3 (Brüls, Cardona & Arnold 2012: K T(hΔq)).
void apply_tangent_operator(const Configuration& q, const std::vector<int>& blocks,
                            const Eigen::VectorXd& increment, Eigen::Ref<Eigen::MatrixXd> K) {
  Eigen::Index column = 0;
  for (const int b : blocks) {
    const Block& block = q.blocks[b];
    if (block.kind == BlockKind::frame) {
      const Eigen::Vector3d theta = increment.segment<3>(block.offset + 3);
      if (theta.squaredNorm() != 0.0) {
        const Eigen::Matrix3d T = lie::tangent(theta);
        // Four rows at a time: Eigen computes a 4 × 3 block times T column by column in packets
        // of rows, where one row at a time is a scalar dot product per entry (the same sums).
        Eigen::Index row = 0;
        for (; row + 4 <= K.rows(); row += 4) {
          const Eigen::Matrix<double, 4, 3> entries = K.block<4, 3>(row, column + 3);
          K.block<4, 3>(row, column + 3).noalias() = entries.lazyProduct(T);
        }
        for (; row < K.rows(); ++row) {
          const Eigen::RowVector3d entries = K.block<1, 3>(row, column + 3);
          K.block<1, 3>(row, column + 3) = entries * T;
        }
      }
    }
    column += block.size;
  }
}

}  // namespace spar::core
