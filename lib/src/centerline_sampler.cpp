#include <spar/core/centerline_sampler.hpp>

#include <spar/error.hpp>

#include <string>

namespace spar::core {

CenterlineSampler::CenterlineSampler(const GeometricallyExactBeam& beam, int points) : beam_(&beam) {
  if (points < 2)
    throw Error("a centerline sample needs at least 2 points, got " + std::to_string(points),
                "core::CenterlineSampler", "ask for 2 or more points");
  const iga::KnotVector& U = beam.reference_centerline().knots();
  points_.reserve(static_cast<std::size_t>(points));
  for (int i = 0; i < points; ++i)
    points_.push_back(beam.centerline_point(U.first() + (U.last() - U.first()) * i / (points - 1), 0));
}

template <class NodeValue>
Eigen::MatrixXd CenterlineSampler::combine(const NodeValue& value) const {
  Eigen::MatrixXd samples(size(), 3);
  // The points' control points are the beam's (centerline_point found them), so their nodes are
  // taken as first_node() + index without node()'s range check: an out-of-line call per product
  // was a third of the cost of a recorded state's centerlines.
  const int first_node = beam_->first_node(), degree = beam_->degree();
  for (int i = 0; i < size(); ++i) {
    const CenterlinePoint& point = points_[i];
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    for (int I = 0; I <= degree; ++I) x += point.shape(0, I) * value(first_node + point.first_control_point + I);
    samples.row(i) = x.transpose();
  }
  return samples;
}

Eigen::MatrixXd CenterlineSampler::positions(const Configuration& q) const {
  beam_->require_nodes(q, "CenterlineSampler::positions");
  return combine([&](int node) -> const Eigen::Vector3d& { return q.position[node]; });
}

Eigen::MatrixXd CenterlineSampler::velocities(const Configuration& q, const Eigen::VectorXd& velocity) const {
  beam_->require_nodes(q, "CenterlineSampler::velocities");
  if (velocity.size() != q.dof_count())
    throw Error("the velocity has " + std::to_string(velocity.size()) + " entries, the configuration " +
                    std::to_string(q.dof_count()) + " dofs",
                "core::CenterlineSampler::velocities", "pass the model's velocity in the global tangent layout");
  return combine([&](int node) { return Eigen::Vector3d(velocity.segment<3>(q.blocks[node].offset)); });
}

}  // namespace spar::core
