#include <spar/elements/beam/beam.hpp>
#include <spar/elements/beam/centerline_sampler.hpp>
#include <spar/elements/beam/beam_element.hpp>

#include "beam_interpolation.hpp"

#include <spar/error.hpp>
#include <spar/iga/quadrature.hpp>
#include <spar/lie/lie.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace spar::core {

namespace {

constexpr const char* where = "core::GeometricallyExactBeam";

/// The reference rotation at each control point: A₁ the unit tangent at its Greville abscissa,
/// A₃ the hint made orthogonal to A₁, A₂ = A₃ × A₁.
std::vector<Eigen::Matrix3d> frames_from_tangent(const iga::NurbsCurve<3>& curve,
                                                 const Eigen::Vector3d& hint) {
  std::vector<Eigen::Matrix3d> frames;
  for (double u : curve.knots().greville()) {
    const Eigen::Vector3d a1 = curve.unit_tangent(u);
    Eigen::Vector3d a3 = hint - hint.dot(a1) * a1;
    if (a3.norm() < 1e-8 * hint.norm())
      throw Error("the section axis hint is parallel to the centerline at u = " +
                      std::to_string(u),
                  where, "give a section_axis_hint that is not tangent to the beam");
    a3.normalize();
    Eigen::Matrix3d R;
    R << a1, a3.cross(a1), a3;
    frames.push_back(R);
  }
  return frames;
}

/// Refuses a control polygon with two coincident consecutive points or one that folds straight
/// back on itself (the legs to and from a point antiparallel): the centerline's tangent vanishes
/// there, or reverses — a cusp, or inside a C⁰ knot a hairpin of two elements on top of each
/// other — and the reference frames from the tangent turn by π (issue 29). The centerline's
/// derivative is Σ_k S_k (P_{k+1} − P_k) with S_k ≥ 0 (the tail sums of a totally positive basis
/// are non-decreasing), so these are where C′ can vanish in a quadratic. "Coincident" and
/// "antiparallel" are within the round-off of the points' coordinates, 4u·|P|∞ per leg.
void check_control_polygon(const iga::NurbsCurve<3>& curve) {
  const auto& P = curve.control_points();
  constexpr double roundoff = 2 * std::numeric_limits<double>::epsilon();
  const auto size = [&](Eigen::Index i) { return P.col(i).cwiseAbs().maxCoeff(); };
  for (Eigen::Index i = 0; i + 1 < P.cols(); ++i) {
    const Eigen::Vector3d leg = P.col(i + 1) - P.col(i);
    if (leg.norm() <= roundoff * std::max(size(i), size(i + 1)))
      throw Error("control points " + std::to_string(i) + " and " + std::to_string(i + 1) +
                      " coincide: the centerline's tangent vanishes between them",
                  where, "remove one of the two (a corner is made by repeating a knot, not a control point)");
    if (i + 2 == P.cols()) break;
    const Eigen::Vector3d next = P.col(i + 2) - P.col(i + 1);
    const double scale = std::max({size(i), size(i + 1), size(i + 2)});
    if (leg.dot(next) < 0.0 && leg.cross(next).norm() <= roundoff * scale * (leg.norm() + next.norm()))
      throw Error("the control polygon folds back on itself at control point " + std::to_string(i + 1) +
                      ": the legs to and from it point in opposite directions, so the centerline's tangent "
                      "reverses there",
                  where, "give a centerline that does not turn back on itself");
  }
}

}  // namespace

GeometricallyExactBeam::GeometricallyExactBeam(const BeamParameters& parameters,
                                               Configuration& configuration)
    : centerline_(parameters.centerline),
      degree_(parameters.centerline.degree()),
      control_point_count_(static_cast<int>(parameters.centerline.control_points().cols())),
      stiffness_(parameters.stiffness),
      inertia_(parameters.inertia) {
  stiffness_.validate();
  inertia_.validate();
  if (degree_ < 1)
    throw Error("a beam needs degree p >= 1, got " + std::to_string(degree_), where,
                "use a linear or higher-degree centerline");
  std::vector<Eigen::Matrix3d> frames = parameters.reference_rotations;
  if (frames.empty()) frames = frames_from_tangent(centerline_, parameters.section_axis_hint);
  if (static_cast<int>(frames.size()) != control_point_count_)
    throw Error("got " + std::to_string(frames.size()) + " reference rotations for " +
                    std::to_string(control_point_count_) + " control points",
                where, "give one reference rotation per control point, or none");
  for (const Eigen::Matrix3d& R : frames) lie::check_rotation(R, where);

  // The elements first: their refusals (a Gauss rule too large, a centerline of zero speed) must
  // leave the configuration without the beam's nodes.
  build_elements(parameters.quadrature_points);
  check_control_polygon(centerline_);
  first_node_ = configuration.block_count();
  for (int I = 0; I < control_point_count_; ++I)
    configuration.add_frame(centerline_.control_points().col(I), frames[I]);
  compute_reference_strains(configuration);
}

void GeometricallyExactBeam::missing_element(int e) const {
  throw Error("element " + std::to_string(e) + " does not exist (the beam has " + std::to_string(element_count()) + ")",
              where, "use an index in [0, element_count())");
}

int GeometricallyExactBeam::node(int control_point) const {
  if (control_point < 0 || control_point >= control_point_count_)
    throw Error("control point " + std::to_string(control_point) + " does not exist (the beam has " +
                    std::to_string(control_point_count_) + ")",
                where, "use an index in [0, control_point_count())");
  return first_node_ + control_point;
}

// Gauss points per element: p + 1 (full integration), or for p = 1 selective reduced integration:
// the shear part of C at one point, the rest at two (003 §3.2).
void GeometricallyExactBeam::build_elements(int quadrature_points) {
  if (quadrature_points < 0 || quadrature_points > iga::max_gauss_points)
    throw Error("BeamParameters::quadrature_points = " + std::to_string(quadrature_points) +
                    " is outside [0, " + std::to_string(iga::max_gauss_points) + "]",
                where, "give 0 (automatic: p + 1) or a count up to " + std::to_string(iga::max_gauss_points));
  const Eigen::Matrix<double, 6, 6> C = stiffness_.matrix();
  struct Part {
    int points;
    int index;
  };
  std::vector<Part> parts;
  if (quadrature_points == 0 && degree_ == 1) {
    Eigen::Matrix<double, 6, 6> shear = Eigen::Matrix<double, 6, 6>::Zero();
    shear.block<2, 2>(1, 1) = C.block<2, 2>(1, 1);
    constitutive_ = {C - shear, shear};
    parts = {{2, 0}, {1, 1}};
  } else {
    constitutive_ = {C};
    parts = {{quadrature_points == 0 ? degree_ + 1 : quadrature_points, 0}};
  }

  const iga::KnotVector& U = centerline_.knots();
  iga::BasisTable table;
  for (int e = 0; e < U.element_count(); ++e) {
    const iga::Element span = U.element(e);
    BeamElement element;
    element.first_control_point = span.span - degree_;
    const double half_length = 0.5 * (span.last - span.first);
    // The reference data at point g of `rule` on this element.
    const auto gauss_point = [&](const iga::GaussRule& rule, std::size_t g, int part) {
      const double u = span.first + (rule.points[g] + 1.0) * half_length;
      iga::rational_basis_derivatives(U, span.span, u, 1, centerline_.weights(), table);
      const double jacobian = centerline_.derivatives(u, 1).col(1).norm();  // dS/du
      if (!(jacobian > 0.0))
        throw Error("the centerline has zero speed at u = " + std::to_string(u), where,
                    "give a regular centerline (no coincident control points)");
      BeamGaussPoint gp;
      gp.parameter = u;
      gp.weight = rule.weights[g] * half_length * jacobian;
      gp.part = part;
      for (int I = 0; I <= degree_; ++I) {
        gp.shape[I] = table(0, I);
        gp.shape_derivative[I] = table(1, I) / jacobian;
      }
      return gp;
    };
    for (const Part& part : parts) {
      const iga::GaussRule rule = iga::gauss_legendre(part.points);
      for (std::size_t g = 0; g < rule.points.size(); ++g)
        element.gauss_points.push_back(gauss_point(rule, g, part.index));
    }
    // Consistent mass coefficients with p + 1 points whatever the stiffness quadrature: exact for
    // N_I N_J of degree 2p on a uniformly parameterized centerline. (They took the stiffness
    // points, so a reduced `quadrature_points` under-integrated the mass: one p = 2 element with
    // 2 points had a singular mass matrix, and modal analysis gave negative frequencies.)
    const iga::GaussRule mass_rule = iga::gauss_legendre(degree_ + 1);
    element.mass_coefficients = Eigen::MatrixXd::Zero(degree_ + 1, degree_ + 1);
    for (std::size_t g = 0; g < mass_rule.points.size(); ++g) {
      const BeamGaussPoint gp = gauss_point(mass_rule, g, 0);
      for (int I = 0; I <= degree_; ++I)
        for (int J = 0; J <= degree_; ++J)
          element.mass_coefficients(I, J) += gp.weight * gp.shape[I] * gp.shape[J];
    }
    elements_.push_back(std::move(element));
  }
}

// γ₀ and κ₀ are the strains of the reference configuration under the same interpolation, so the
// reference configuration is stress-free exactly, straight or curved (003 eq. 8).
void GeometricallyExactBeam::compute_reference_strains(const Configuration& reference) {
  for (int e = 0; e < element_count(); ++e)
    for (std::size_t g = 0; g < elements_[e].gauss_points.size(); ++g) {
      const BeamStrains total = beam_strains(*this, e, static_cast<int>(g), reference);
      BeamGaussPoint& gp = elements_[e].gauss_points[g];
      gp.reference_translational_strain = total.translational;
      gp.reference_curvature = total.curvature;
    }
}

CenterlinePoint GeometricallyExactBeam::centerline_point(double u, int order) const {
  constexpr const char* here = "core::GeometricallyExactBeam::centerline_point";
  iga::detail::check_derivative_order(order, here);
  const iga::KnotVector& U = centerline_.knots();
  if (!(u >= U.first() && u <= U.last()))
    throw Error("u = " + std::to_string(u) + " is outside the knot range [" +
                    std::to_string(U.first()) + ", " + std::to_string(U.last()) + "]",
                here, "give a parameter inside the beam's knot range");
  CenterlinePoint point;
  point.parameter = u;
  point.order = order;
  const int span = U.find_span(u);
  point.first_control_point = span - degree_;
  // Elements are ordered by their first control point; the span found is one of them.
  const auto found = std::lower_bound(
      elements_.begin(), elements_.end(), point.first_control_point,
      [](const BeamElement& e, int first) { return e.first_control_point < first; });
  point.element = static_cast<int>(found - elements_.begin());
  iga::rational_basis_derivatives(U, span, u, order, centerline_.weights(), point.shape);
  return point;
}

void GeometricallyExactBeam::require_nodes(const Configuration& q, const char* function) const {
  const int nodes = static_cast<int>(std::min(q.position.size(), q.rotation.size()));
  if (nodes < first_node_ + control_point_count_)
    throw Error("the configuration has " + std::to_string(nodes) + " frame nodes, the beam's are " +
                    std::to_string(first_node_) + " … " + std::to_string(first_node_ + control_point_count_ - 1),
                std::string(where) + "::" + function, "pass the model's state (model.state()) or a copy of it");
}

Eigen::Vector3d GeometricallyExactBeam::centerline_derivative(const Configuration& q,
                                                              const CenterlinePoint& point,
                                                              int k) const {
  require_nodes(q, "centerline_derivative");
  const int first = node(point.first_control_point);
  Eigen::Vector3d x = Eigen::Vector3d::Zero();
  for (int I = 0; I <= degree_; ++I) x += point.shape(k, I) * q.position[first + I];
  return x;
}

Eigen::Vector3d GeometricallyExactBeam::position_at(const Configuration& q, double u) const {
  return centerline_derivative(q, centerline_point(u, 0), 0);
}

Eigen::MatrixXd GeometricallyExactBeam::sample_centerline(const Configuration& q, int points) const {
  return CenterlineSampler(*this, points).positions(q);
}

Eigen::Matrix3d GeometricallyExactBeam::rotation_at(const Configuration& q, double u) const {
  require_nodes(q, "rotation_at");
  const CenterlinePoint point = centerline_point(u, 0);
  const detail::RelativeRotations rel = detail::relative_rotations(*this, point.element, q);
  Eigen::Vector3d theta = Eigen::Vector3d::Zero();
  for (int I = 0; I <= degree_; ++I) theta += point.shape(0, I) * rel.psi[I];
  return rel.reference * lie::exp(theta);  // 003 eq. 42
}

}  // namespace spar::core
