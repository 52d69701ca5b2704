#include <spar/joints/reaction.hpp>

#include <spar/error.hpp>

#include <Eigen/Geometry>

#include <string>

namespace spar::joints {

Wrench reaction(const Constraint& constraint, const core::Configuration& q, double t,
                const Eigen::Ref<const Eigen::VectorXd>& lambda, int node, const Eigen::Vector3d& point) {
  const char* where = "joints::reaction";
  const std::vector<int>& blocks = constraint.blocks();
  if (lambda.size() != constraint.equation_count())
    throw Error("the constraint has " + std::to_string(constraint.equation_count()) + " equations, lambda " +
                    std::to_string(lambda.size()) + " entries",
                where, "give the constraint's own multipliers (GeneralizedAlpha::multipliers(constraint))");
  int column = 0;
  std::size_t i = 0;
  for (; i < blocks.size() && blocks[i] != node; ++i) column += q.blocks[blocks[i]].size;
  if (i == blocks.size() || !q.is_frame(node))
    throw Error("block " + std::to_string(node) + " is not a frame block of the constraint", where,
                "give one of the constraint's frame blocks (its blocks())");
  Eigen::MatrixXd B(constraint.equation_count(), core::block_dof_count(q, blocks));
  constraint.jacobian(q, t, B);
  // g = −B_nodeᵀ λ: force (inertial) and moment about x (material).
  const Eigen::Matrix<double, 6, 1> g = -B.middleCols<6>(column).transpose() * lambda;
  Wrench w;
  w.force = g.head<3>();
  w.moment = q.rotation[node] * g.tail<3>() + (q.position[node] - point).cross(w.force);
  return w;
}

}  // namespace spar::joints
