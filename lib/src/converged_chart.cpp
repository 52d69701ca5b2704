#include <spar/core/converged_chart.hpp>
#include <spar/lie/tangent.hpp>

namespace spar::core {

void pull_back_to_converged_chart(const std::vector<Eigen::Vector3d>& phi, NodalContribution& c) {
  const int k = static_cast<int>(c.nodes.size());
  const bool with_tangent = c.tangent.size() > 0;
  for (int I = 0; I < k; ++I) {
    const Eigen::Vector3d& phi_I = phi[c.nodes[I]];
    const Eigen::Matrix3d T = lie::tangent(phi_I);
    const Eigen::Vector3d f_rot = c.force.segment<3>(6 * I + 3);
    c.force.segment<3>(6 * I + 3) = T.transpose() * f_rot;
    if (!with_tangent) continue;
    c.tangent.middleRows<3>(6 * I + 3) = T.transpose() * c.tangent.middleRows<3>(6 * I + 3);
    c.tangent.middleCols<3>(6 * I + 3) = c.tangent.middleCols<3>(6 * I + 3) * T;
    c.tangent.block<3, 3>(6 * I + 3, 6 * I + 3) += lie::tangent_transpose_derivative(phi_I, f_rot);
  }
}

}  // namespace spar::core
