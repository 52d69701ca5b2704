#include <spar/elements/ancf/ancf_points.hpp>

#include <spar/elements/ancf/ancf_beam_element.hpp>
#include <spar/error.hpp>

#include <string>

namespace spar::core {

namespace {

/// The map S(ξ, y, z) of one element kind on its blocks (node A, node B[, extra]).
template <int transverse>
LinearPoint element_point(const AncfBeam& beam, int element, double xi, const Eigen::Vector2d& yz) {
  using Shape = AncfShapeFunctions<transverse>;
  const auto ax = Shape::axial(xi, beam.element_length);
  const auto tr = Shape::transverse_values(xi, beam.element_length);
  Eigen::Matrix<double, 3, Shape::dofs> S = Eigen::Matrix<double, 3, Shape::dofs>::Zero();
  for (int k = 0; k < 4; ++k) S.template block<3, 3>(0, 3 * Shape::axial_vectors[k]).diagonal().setConstant(ax[k]);
  for (int k = 0; k < transverse; ++k) {
    S.template block<3, 3>(0, 3 * Shape::y_vectors[k]).diagonal().setConstant(yz.x() * tr[k]);
    S.template block<3, 3>(0, 3 * Shape::z_vectors[k]).diagonal().setConstant(yz.y() * tr[k]);
  }
  std::vector<int> blocks{beam.nodes[element], beam.nodes[element + 1]};
  std::vector<Eigen::MatrixXd> maps{S.leftCols(12), S.middleCols(12, 12)};
  if constexpr (transverse == 3) {
    blocks.push_back(beam.element_blocks[element]);
    maps.push_back(S.rightCols(6));
  }
  return LinearPoint(std::move(blocks), std::move(maps));
}

}  // namespace

LinearPoint ancf_node_point(const Configuration& q, int node) {
  if (node < 0 || node >= q.block_count() || q.is_frame(node) || q.blocks[node].size != 12)
    throw Error("block " + std::to_string(node) + " is not an ANCF node", "core::ancf_node_point",
                "give a node of core::add_ancf_beam");
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(3, 12);
  C.leftCols<3>().setIdentity();
  return LinearPoint({node}, {C});
}

LinearPoint ancf_element_point(const AncfBeam& beam, int element, double xi, const Eigen::Vector2d& yz) {
  if (element < 0 || element + 1 >= static_cast<int>(beam.nodes.size()) || !(xi >= 0.0 && xi <= 1.0))
    throw Error("element " + std::to_string(element) + " at xi = " + std::to_string(xi) + " is not on the beam",
                "core::ancf_element_point", "give an element of the beam and xi in [0, 1]");
  return beam.kind == AncfElementKind::standard_24 ? element_point<2>(beam, element, xi, yz)
                                                   : element_point<3>(beam, element, xi, yz);
}

}  // namespace spar::core
