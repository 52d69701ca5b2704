#include <spar/core/converged_chart.hpp>
#include <spar/lie/tangent.hpp>

namespace spar::core {

// docs/beam.md eq. B13.
void pull_back_to_converged_chart(const Configuration& q, const std::vector<int>& blocks,
                                  const Eigen::VectorXd& chart, Eigen::Ref<Eigen::VectorXd> force,
                                  Eigen::MatrixXd* tangent) {
  Eigen::Index at = 0;
  for (const int b : blocks) {
    const Block& block = q.blocks[b];
    if (block.kind == BlockKind::frame) {
      const Eigen::Vector3d phi = chart.segment<3>(block.offset + 3);
      const Eigen::Matrix3d T = lie::tangent(phi);
      const Eigen::Vector3d f_rot = force.segment<3>(at + 3);
      force.segment<3>(at + 3) = T.transpose() * f_rot;
      if (tangent) {
        tangent->middleRows<3>(at + 3) = T.transpose() * tangent->middleRows<3>(at + 3);
        tangent->middleCols<3>(at + 3) = tangent->middleCols<3>(at + 3) * T;
        tangent->block<3, 3>(at + 3, at + 3) += lie::tangent_transpose_derivative(phi, f_rot);
      }
    }
    at += block.size;
  }
}

}  // namespace spar::core
