#include <spar/core/configuration.hpp>
#include <spar/error.hpp>
#include <spar/lie/exp.hpp>

#include <string>

namespace spar::core {

int Configuration::add_node(const Eigen::Vector3d& x, const Eigen::Matrix3d& R) {
  position.push_back(x);
  rotation.push_back(R);
  return node_count() - 1;
}

void Configuration::apply_increment(const Eigen::Ref<const Eigen::VectorXd>& delta) {
  if (delta.size() != dof_count())
    throw Error("increment has " + std::to_string(delta.size()) + " entries for " +
                    std::to_string(dof_count()) + " degrees of freedom",
                "core::Configuration::apply_increment", "pass one entry per degree of freedom");
  for (int k = 0; k < node_count(); ++k) {
    position[k] += delta.segment<3>(dofs_per_node * k);
    rotation[k] = lie::right_plus(rotation[k], delta.segment<3>(dofs_per_node * k + 3));
  }
}

}  // namespace spar::core
