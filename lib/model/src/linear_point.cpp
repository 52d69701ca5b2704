#include <spar/core/linear_point.hpp>

#include <spar/error.hpp>

#include <string>

namespace spar::core {

LinearPoint::LinearPoint(std::vector<int> blocks, std::vector<Eigen::MatrixXd> maps)
    : blocks_(std::move(blocks)), maps_(std::move(maps)) {
  constexpr const char* where = "core::LinearPoint";
  if (blocks_.empty() || blocks_.size() != maps_.size())
    throw Error("the point has " + std::to_string(blocks_.size()) + " blocks and " + std::to_string(maps_.size()) +
                    " maps",
                where, "give one 3 x size map per block");
  for (std::size_t k = 0; k < blocks_.size(); ++k)
    if (blocks_[k] < 0 || maps_[k].rows() != 3)
      throw Error("block " + std::to_string(blocks_[k]) + " with a map of " + std::to_string(maps_[k].rows()) +
                      " rows",
                  where, "give model blocks and 3 x size maps");
}

void LinearPoint::check(const Configuration& q, std::string_view where) const {
  for (std::size_t k = 0; k < blocks_.size(); ++k) {
    const int b = blocks_[k];
    if (b >= q.block_count() || q.is_frame(b) || maps_[k].cols() != q.blocks[b].size)
      throw Error("block " + std::to_string(b) + " is not a vector block matching its 3 x " +
                      std::to_string(maps_[k].cols()) + " map",
                  where, "build the point on the model's configuration (e.g. core::ancf_node_point)");
  }
}

Eigen::Vector3d LinearPoint::position(const Configuration& q) const {
  Eigen::Vector3d p = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < blocks_.size(); ++k) p.noalias() += maps_[k] * q.vector(blocks_[k]);  // no temporary
  return p;
}

void LinearPoint::add_jacobian(const Configuration& /*q*/, const Eigen::Matrix3d& weight,
                               Eigen::Ref<Eigen::MatrixXd> B, int first_row, const std::vector<int>& columns) const {
  for (std::size_t k = 0; k < blocks_.size(); ++k)
    for (Eigen::Index j = 0; j < maps_[k].cols(); ++j)
      B.block<3, 1>(first_row, columns[k] + j) += weight * Eigen::Vector3d(maps_[k].col(j));
}

void LinearPoint::add_multiplier_tangent(const Configuration& /*q*/, const Eigen::Vector3d& /*f*/,
                                         Eigen::Ref<Eigen::MatrixXd> /*K*/, const std::vector<int>& /*columns*/) const {}

Eigen::Vector3d LinearPoint::acceleration_terms(const Configuration& /*q*/, const Eigen::VectorXd& /*velocity*/) const {
  return Eigen::Vector3d::Zero();
}

}  // namespace spar::core
