#pragma once
// Private to spar_core: the Crisfield–Jelenić interpolation shared by the beam's kernel and its
// field evaluation (003 eqs. 39–42).

#include <spar/elements/beam/beam.hpp>
#include <spar/core/configuration.hpp>

#include <Eigen/Core>

#include <array>

namespace spar::core::detail {

/// The element's reference rotation R_r (its first control point, 003 §3.2) and the relative
/// rotations ψ_I = log(R_rᵀ R_I) of its k control points (ψ_0 = 0).
struct RelativeRotations {
  int node_count = 0;
  Eigen::Matrix3d reference;
  std::array<Eigen::Vector3d, max_beam_element_nodes> psi;
};

/// Computes the relative rotations of element e in q; throws spar::Error when one reaches π.
RelativeRotations relative_rotations(const GeometricallyExactBeam& beam, int e,
                                     const Configuration& q);

/// The interpolated fields at a point with shape functions N, dN/dS (003 eqs. 39–41).
struct InterpolatedFields {
  Eigen::Vector3d theta;        ///< Θ = Σ N_I ψ_I
  Eigen::Vector3d theta_prime;  ///< Θ′ = Σ N_I′ ψ_I
  Eigen::Vector3d x_prime;      ///< x′ = Σ N_I′ x_I
};

template <class Shape>
InterpolatedFields interpolate(const GeometricallyExactBeam& beam, int e, const Configuration& q,
                               const RelativeRotations& rel, const Shape& N, const Shape& dN) {
  InterpolatedFields f{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
  const int first = beam.node(beam.element(e).first_control_point);
  for (int I = 0; I < rel.node_count; ++I) {
    f.theta += N[I] * rel.psi[I];
    f.theta_prime += dN[I] * rel.psi[I];
    f.x_prime += dN[I] * q.position[first + I];
  }
  return f;
}

}  // namespace spar::core::detail
