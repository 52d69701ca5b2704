#include <spar/joints/point_joint.hpp>

#include <spar/joints/attachment.hpp>

#include <algorithm>

namespace spar::joints {

namespace {
constexpr std::string_view name = "joints::PointJoint";
}  // namespace

PointJoint::PointJoint(const core::MaterialPoint& a, const Eigen::Vector3d& ground, const core::Configuration& q)
    : a_(a.clone()), ground_(finite_point(ground, "ground point", name)) {
  a.check(q, name);
  columns_a_ = place(a, q);
}

PointJoint::PointJoint(const core::MaterialPoint& a, const core::MaterialPoint& b, const core::Configuration& q)
    : a_(a.clone()), b_(b.clone()) {
  a.check(q, name);
  b.check(q, name);
  columns_a_ = place(a, q);
  columns_b_ = place(b, q);
}

std::vector<int> PointJoint::place(const core::MaterialPoint& p, const core::Configuration& q) {
  std::vector<int> columns;
  for (const int block : p.blocks()) {
    const auto it = std::find(blocks_.begin(), blocks_.end(), block);
    if (it != blocks_.end()) {
      columns.push_back(core::block_dof_count(q, std::vector<int>(blocks_.begin(), it)));
      continue;
    }
    blocks_.push_back(block);
    columns.push_back(columns_);
    columns_ += q.blocks[block].size;
  }
  return columns;
}

void PointJoint::compute_value(const core::Configuration& q, double /*t*/, Eigen::Ref<Eigen::VectorXd> phi) const {
  phi = a_->position(q) - (b_ ? b_->position(q) : ground_);
}

void PointJoint::compute_jacobian(const core::Configuration& q, double /*t*/, Eigen::Ref<Eigen::MatrixXd> B) const {
  const Eigen::Matrix3d identity = Eigen::Matrix3d::Identity();
  a_->add_jacobian(q, identity, B, 0, columns_a_);
  if (b_) b_->add_jacobian(q, Eigen::Matrix3d(-identity), B, 0, columns_b_);
}

void PointJoint::compute_multiplier_tangent(const core::Configuration& q, double /*t*/,
                                            const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                            Eigen::Ref<Eigen::MatrixXd> K) const {
  const Eigen::Vector3d force = lambda;
  a_->add_multiplier_tangent(q, force, K, columns_a_);
  if (b_) b_->add_multiplier_tangent(q, -force, K, columns_b_);
}

void PointJoint::compute_acceleration_terms(const core::Configuration& q, const Eigen::VectorXd& velocity,
                                            double /*t*/, Eigen::Ref<Eigen::VectorXd> c) const {
  c = a_->acceleration_terms(q, velocity);
  if (b_) c -= b_->acceleration_terms(q, velocity);
}

}  // namespace spar::joints
