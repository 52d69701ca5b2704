#include <spar/elements/beam/centerline_sampler.hpp>

#include <spar/error.hpp>

#include <string>

namespace spar::core {

CenterlineSampler::CenterlineSampler(const GeometricallyExactBeam& beam, int points)
    : beam_(&beam), degree_(beam.degree()) {
  if (points < 2)
    throw Error("a centerline sample needs at least 2 points, got " + std::to_string(points),
                "core::CenterlineSampler", "ask for 2 or more points");
  const iga::KnotVector& U = beam.reference_centerline().knots();
  first_node_.reserve(static_cast<std::size_t>(points));
  shape_.reserve(static_cast<std::size_t>(points) * static_cast<std::size_t>(degree_ + 1));
  for (int i = 0; i < points; ++i) {
    const CenterlinePoint point = beam.centerline_point(U.first() + (U.last() - U.first()) * i / (points - 1), 0);
    // The point's control points are the beam's (centerline_point found them), so its nodes are
    // first_node() + index, taken without node()'s range check.
    first_node_.push_back(beam.first_node() + point.first_control_point);
    for (int I = 0; I <= degree_; ++I) shape_.push_back(point.shape(0, I));
  }
}

template <class NodeValue>
Eigen::MatrixXd CenterlineSampler::combine(const NodeValue& value) const {
  Eigen::MatrixXd samples(size(), 3);
  const double* N = shape_.data();
  for (int i = 0; i < size(); ++i, N += degree_ + 1) {
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    for (int I = 0; I <= degree_; ++I) x += N[I] * value(first_node_[i] + I);
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
