#pragma once
/// \file
/// The stress resultants of a geometrically exact beam's sections (003 eq. 15; docs/beam.md B16):
/// the force and the moment that the part of the beam beyond a section (larger S) exerts on the
/// part before it, evaluated at the Gauss points where the elements integrate their energy.
///
///     const core::SectionPoints at = core::section_points(rod);       // u and S, once
///     const core::SectionResultants r = core::section_resultants(rod, model.state(), at);
///     // r.moment.row(i): the bending and twisting moment at S = at.arc_length(i), inertial frame

#include <spar/core/configuration.hpp>
#include <spar/elements/beam/beam.hpp>

#include <Eigen/Core>

#include <vector>

namespace spar::core {

/// Where section_resultants evaluates: element by element, the Gauss points of the stiffness's
/// first constitutive part (all of them for p ≥ 2; for p = 1 with selective reduced integration
/// the two points of everything but the shear, docs/beam.md B3), in order along the beam.
struct SectionPoints {
  std::vector<int> element;      ///< the element of each point
  std::vector<int> gauss_point;  ///< its index among the element's Gauss points
  Eigen::VectorXd parameter;     ///< u, the knot parameter
  Eigen::VectorXd arc_length;    ///< S, the reference arc length from the beam's start (m)
};

/// The resultants at the points of section_points, one row each.
struct SectionResultants {
  Eigen::MatrixXd position;         ///< x(S), inertial frame (m)
  Eigen::MatrixXd force;            ///< R n, inertial frame (N)
  Eigen::MatrixXd moment;           ///< R m, inertial frame (N m)
  Eigen::MatrixXd material_force;   ///< n = (axial, shear along A₂, shear along A₃), section frame (N)
  Eigen::MatrixXd material_moment;  ///< m = (torsion, bending about A₂, bending about A₃), section frame (N m)
};

/// The points of `beam` where section_resultants evaluates.
SectionPoints section_points(const GeometricallyExactBeam& beam);

/// (n, m) = C ε with the whole section stiffness C (003 eq. 15) and ε = (γ, κ) the strains at
/// each point (003 eqs. 8, 41), and their images R n, R m in the inertial frame. In equilibrium
/// they balance the loads beyond the section: a cantilever with a dead force F at its tip has
/// R n = F and R m = (x_tip − x(S)) × F at every section (tests/beam/section_resultants_test.cpp).
/// For p = 1 elements the shear force is that of the strain at the two points, which shear
/// locking stiffens (the energy integrates it at one point): prefer p ≥ 2 for shear forces.
/// Throws spar::Error unless q holds the beam's nodes.
SectionResultants section_resultants(const GeometricallyExactBeam& beam, const Configuration& q);
/// The same at `points`, section_points(beam) computed once (what a recording at every step
/// wants: the arc lengths cost a quadrature each).
SectionResultants section_resultants(const GeometricallyExactBeam& beam, const Configuration& q,
                                     const SectionPoints& points);

}  // namespace spar::core
