// The section resultants of a geometrically exact beam at its Gauss points (docs/beam.md B16).
#include <spar/elements/beam/beam_element.hpp>
#include <spar/elements/beam/section_resultants.hpp>
#include <spar/error.hpp>

#include <string>

namespace spar::core {

SectionPoints section_points(const GeometricallyExactBeam& beam) {
  SectionPoints points;
  std::vector<double> parameter;
  for (int e = 0; e < beam.element_count(); ++e) {
    const std::vector<BeamGaussPoint>& gauss_points = beam.element(e).gauss_points;
    for (std::size_t g = 0; g < gauss_points.size(); ++g) {
      if (gauss_points[g].part != 0) continue;
      points.element.push_back(e);
      points.gauss_point.push_back(static_cast<int>(g));
      parameter.push_back(gauss_points[g].parameter);
    }
  }
  const auto n = static_cast<Eigen::Index>(parameter.size());
  points.parameter = Eigen::Map<const Eigen::VectorXd>(parameter.data(), n);
  points.arc_length.resize(n);
  const iga::NurbsCurve<3>& reference = beam.reference_centerline();
  const double start = reference.knots().first();
  for (Eigen::Index i = 0; i < n; ++i) points.arc_length(i) = reference.arc_length(start, points.parameter(i));
  return points;
}

SectionResultants section_resultants(const GeometricallyExactBeam& beam, const Configuration& q) {
  return section_resultants(beam, q, section_points(beam));
}

SectionResultants section_resultants(const GeometricallyExactBeam& beam, const Configuration& q,
                                     const SectionPoints& points) {
  beam.require_nodes(q, "section_resultants");
  const Eigen::Matrix<double, 6, 6> C = beam.stiffness().matrix();
  const Eigen::Index n = points.parameter.size();
  if (static_cast<Eigen::Index>(points.element.size()) != n || static_cast<Eigen::Index>(points.gauss_point.size()) != n)
    throw Error("the section points hold " + std::to_string(points.element.size()) + " elements, " +
                    std::to_string(points.gauss_point.size()) + " Gauss points and " + std::to_string(n) + " parameters",
                "core::section_resultants", "pass core::section_points(beam) of this beam");
  SectionResultants r{Eigen::MatrixXd(n, 3), Eigen::MatrixXd(n, 3), Eigen::MatrixXd(n, 3), Eigen::MatrixXd(n, 3),
                      Eigen::MatrixXd(n, 3)};
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const BeamStrains strains = beam_strains(beam, points.element[k], points.gauss_point[k], q);
    Eigen::Matrix<double, 6, 1> strain;
    strain << strains.translational, strains.curvature;
    // 003 eq. 15: (n, m) = C (γ, κ), in the section frame.
    const Eigen::Matrix<double, 6, 1> stress = C * strain;
    const Eigen::Matrix3d& R = strains.rotation;
    // 003 eq. 39: x = Σ N_I x_I with the Gauss point's shape functions.
    const BeamElement& element = beam.element(points.element[k]);
    const BeamGaussPoint& gp = element.gauss_points[static_cast<std::size_t>(points.gauss_point[k])];
    Eigen::Vector3d x = Eigen::Vector3d::Zero();
    for (int I = 0; I <= beam.degree(); ++I)
      x += gp.shape[static_cast<std::size_t>(I)] * q.position[static_cast<std::size_t>(beam.node(element.first_control_point + I))];
    r.position.row(i) = x.transpose();
    r.material_force.row(i) = stress.head<3>().transpose();
    r.material_moment.row(i) = stress.tail<3>().transpose();
    r.force.row(i) = (R * stress.head<3>()).transpose();
    r.moment.row(i) = (R * stress.tail<3>()).transpose();
  }
  return r;
}

}  // namespace spar::core
