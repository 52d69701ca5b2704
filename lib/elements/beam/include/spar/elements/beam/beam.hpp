#pragma once
/// \file
/// The geometrically exact (Simo–Reissner) beam on a NURBS centerline, in the local-frame
/// Lie-group formulation of 003 §2–3 (docs/beam.md). This class is the constant model: mesh,
/// section, reference frames and the per-Gauss-point reference data. The state lives in a
/// core::Configuration (one node per control point); the kernel is core::evaluate_beam_element.

#include <spar/core/configuration.hpp>
#include <spar/core/cross_section.hpp>
#include <spar/core/model.hpp>
#include <spar/iga/basis.hpp>
#include <spar/iga/nurbs_curve.hpp>

#include <Eigen/Core>

#include <array>
#include <optional>
#include <vector>

namespace spar::core {

/// Most control points of one beam element (degree ≤ iga::max_degree).
inline constexpr int max_beam_element_nodes = iga::max_degree + 1;

/// What a beam is built from.
struct BeamParameters {
  /// The reference centerline; its control points become the beam's nodes, its knot spans the
  /// elements, its basis the interpolation of positions (003 eq. 39) and rotations (eq. 40).
  iga::NurbsCurve<3> centerline;
  /// Section stiffness C (003 eq. 15).
  SectionStiffness stiffness;
  /// Section inertia per unit length (003 eqs. 30–31); zero for a massless (statics) beam.
  SectionInertia inertia;
  /// Reference rotation of each control point (columns: A₁ along the beam, A₂, A₃ section axes).
  /// When empty they are built from the centerline's unit tangent at the Greville abscissae and
  /// `section_axis_hint` (A₃ = the hint made orthogonal to A₁).
  std::vector<Eigen::Matrix3d> reference_rotations;
  Eigen::Vector3d section_axis_hint = Eigen::Vector3d::UnitZ();
  /// Gauss points per element for the internal forces (at most iga::max_gauss_points); 0 chooses
  /// p + 1, and for p = 1 selective reduced integration (one point for the two shears, two for
  /// everything else; 003 §3.2). The mass coefficients always take p + 1 points (exact).
  /// Which to choose for a slender beam: docs/guide.md §2, "Choosing elements and degree".
  int quadrature_points = 0;
};

/// Reference data of one Gauss point of a beam element.
struct BeamGaussPoint {
  double parameter = 0.0;  ///< u, the point's knot parameter
  double weight = 0.0;  ///< quadrature weight × dS/dξ (reference arc length per unit ξ)
  int part = 0;         ///< which constitutive part C_part is integrated here (see constitutive())
  std::array<double, max_beam_element_nodes> shape{};             ///< N_I
  std::array<double, max_beam_element_nodes> shape_derivative{};  ///< dN_I/dS
  Eigen::Vector3d reference_translational_strain = Eigen::Vector3d::Zero();  ///< R₀ᵀx₀′
  Eigen::Vector3d reference_curvature = Eigen::Vector3d::Zero();             ///< κ₀
};

/// A point of the centerline at parameter u as a combination of control points (003 eq. 53,
/// docs/beam.md eq. B15): x(u) = Σ_I N_I(u) x_{first+I}, d^k x/du^k = Σ_I N_I^(k)(u) x_{first+I}.
/// The weights are also the derivatives of the point with respect to the control points,
/// ∂x/∂x_I = N_I I₃ and ∂(d^k x/du^k)/∂x_I = N_I^(k) I₃ (the centerline's position does not
/// depend on the rotations). What a joint gripping the centerline (a sliding joint) needs.
struct CenterlinePoint {
  double parameter = 0.0;       ///< u
  int element = 0;              ///< the beam element (non-zero knot span) holding u
  int first_control_point = 0;  ///< the point depends on control points first … first + degree
  int order = 0;                ///< the highest derivative in `shape`
  /// shape(k, I) = d^k N_{first+I}/du^k for k = 0 … order, I = 0 … degree (NURBS basis).
  iga::BasisTable shape = iga::BasisTable::Zero();
};

/// One element: its first control point (global node = first_node() + first_control_point) and
/// its Gauss points.
struct BeamElement {
  int first_control_point = 0;
  std::vector<BeamGaussPoint> gauss_points;
  /// m_IJ = ∫ N_I N_J dS over the element (k × k): the consistent mass coefficients.
  Eigen::MatrixXd mass_coefficients;
};

class GeometricallyExactBeam {
public:
  /// Builds the beam and appends its nodes (control points, reference rotations) to
  /// `configuration`. Throws spar::Error for invalid stiffness, degree, frames or quadrature.
  GeometricallyExactBeam(const BeamParameters& parameters, Configuration& configuration);

  int degree() const { return degree_; }
  int control_point_count() const { return control_point_count_; }
  int element_count() const { return static_cast<int>(elements_.size()); }
  /// Global index of the beam's first node; control point I is node first_node() + I.
  int first_node() const { return first_node_; }
  /// Global node of control point I.
  int node(int control_point) const;
  /// Element e; throws spar::Error for e outside [0, element_count()).
  const BeamElement& element(int e) const {
    if (e < 0 || e >= element_count()) missing_element(e);
    return elements_[e];
  }
  const iga::NurbsCurve<3>& reference_centerline() const { return centerline_; }
  /// The constitutive matrices integrated by the Gauss points (C for p ≥ 2; for p = 1 with
  /// selective integration, C without the shear block and the shear block alone).
  const std::vector<Eigen::Matrix<double, 6, 6>>& constitutive() const { return constitutive_; }
  const SectionStiffness& stiffness() const { return stiffness_; }
  const SectionInertia& inertia() const { return inertia_; }

  /// The point x(u) and the rotation R(u) of the centerline at parameter u in a configuration,
  /// by the same interpolation as the strains (003 eqs. 39, 40, 42).
  Eigen::Vector3d position_at(const Configuration& q, double u) const;
  Eigen::Matrix3d rotation_at(const Configuration& q, double u) const;
  /// The centerline point at parameter u with its basis derivatives up to `order`
  /// (0 ≤ order ≤ iga::max_derivative_order): the element is found by u itself, so any u of the
  /// knot range works, across element boundaries; at an interior knot the element on its right is
  /// used (the left one at the last knot). Throws spar::Error for u outside the knot range.
  CenterlinePoint centerline_point(double u, int order) const;
  /// d^k x/du^k = Σ_I shape(k, I) x_I in configuration q (k ≤ point.order).
  Eigen::Vector3d centerline_derivative(const Configuration& q, const CenterlinePoint& point,
                                        int k) const;
  /// The centerline at `points` ≥ 2 parameters equally spaced over the knot range, one row each
  /// (what results files and plots draw).
  /// (core::CenterlineSampler does this for many states at the cost of one.)
  Eigen::MatrixXd sample_centerline(const Configuration& q, int points) const;
  /// Throws spar::Error naming `function` unless q holds the beam's nodes (a configuration of
  /// another model, or an empty one, would be read out of bounds).
  void require_nodes(const Configuration& q, const char* function) const;

private:
  void build_elements(int quadrature_points);
  [[noreturn]] void missing_element(int e) const;
  void compute_reference_strains(const Configuration& reference);

  iga::NurbsCurve<3> centerline_;
  int degree_;
  int control_point_count_;
  int first_node_ = 0;
  SectionStiffness stiffness_;
  SectionInertia inertia_;
  std::vector<Eigen::Matrix<double, 6, 6>> constitutive_;
  std::vector<BeamElement> elements_;
};

/// Adds a beam to `model` (the beam family's builder): its control points become frame blocks,
/// each knot span a GeometricallyExactBeamElement. Returns the beam's index.
int add_beam(Model& model, const BeamParameters& parameters);
/// The beams added to `model` so far.
int beam_count(const Model& model);
/// Beam b of `model`; throws spar::Error for an index that does not exist.
const GeometricallyExactBeam& beam(const Model& model, int b);

}  // namespace spar::core
