#include <spar/joints/sliding_node_slopes.hpp>

#include <spar/error.hpp>

#include <string>

namespace spar::joints {

SlidingNodeSlopes::SlidingNodeSlopes(int left, int right, int dimension, SlopeCondition condition,
                                     const core::Configuration& q)
    : blocks_{left, right}, dimension_(dimension), condition_(condition) {
  constexpr const char* where = "joints::SlidingNodeSlopes";
  if (dimension != 2 && dimension != 3)
    throw Error("dimension " + std::to_string(dimension), where, "give 2 (planar) or 3 (spatial)");
  for (int block : blocks_)
    if (block < 0 || block >= q.block_count() || q.is_frame(block) || q.blocks[block].size != 2 * dimension)
      throw Error("block " + std::to_string(block) + " is not a node block [r, r_x] of " +
                      std::to_string(2 * dimension) + " entries",
                  where, "give the two node blocks of the sliding node, one per side");
  if (left == right)
    throw Error("the two sides are the same block " + std::to_string(left), where,
                "give the sliding node a second node block for the right-hand element");
}

int SlidingNodeSlopes::equation_count() const {
  return dimension_ + (condition_ == SlopeCondition::continuous ? dimension_ : 1);
}

void SlidingNodeSlopes::compute_value(const core::Configuration& q, double, Eigen::Ref<Eigen::VectorXd> phi) const {
  const int d = dimension_;
  const auto a = q.vector(blocks_[0]), b = q.vector(blocks_[1]);
  phi.head(d) = a.head(d) - b.head(d);
  if (condition_ == SlopeCondition::continuous)
    phi.segment(d, d) = a.tail(d) - b.tail(d);
  else
    phi(d) = 0.5 * (a.tail(d).squaredNorm() - b.tail(d).squaredNorm());
}

void SlidingNodeSlopes::compute_jacobian(const core::Configuration& q, double, Eigen::Ref<Eigen::MatrixXd> B) const {
  const int d = dimension_;
  for (int i = 0; i < d; ++i) {
    B(i, i) = 1.0;
    B(i, 2 * d + i) = -1.0;
  }
  if (condition_ == SlopeCondition::continuous) {
    for (int i = 0; i < d; ++i) {
      B(d + i, d + i) = 1.0;
      B(d + i, 3 * d + i) = -1.0;
    }
  } else {
    B.block(d, d, 1, d) = q.vector(blocks_[0]).tail(d).transpose();
    B.block(d, 3 * d, 1, d) = -q.vector(blocks_[1]).tail(d).transpose();
  }
}

void SlidingNodeSlopes::compute_multiplier_tangent(const core::Configuration&, double,
                                                   const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                                   Eigen::Ref<Eigen::MatrixXd> K) const {
  if (condition_ == SlopeCondition::continuous) return;
  const int d = dimension_;
  for (int i = 0; i < d; ++i) {
    K(d + i, d + i) = lambda(d);
    K(3 * d + i, 3 * d + i) = -lambda(d);
  }
}

void SlidingNodeSlopes::compute_acceleration_terms(const core::Configuration& q, const Eigen::VectorXd& velocity,
                                                   double, Eigen::Ref<Eigen::VectorXd> c) const {
  if (condition_ == SlopeCondition::continuous) return;
  const int d = dimension_;
  const auto rate = [&](int block) { return velocity.segment(q.blocks[block].offset + d, d); };
  c(d) = rate(blocks_[0]).squaredNorm() - rate(blocks_[1]).squaredNorm();
}

}  // namespace spar::joints
