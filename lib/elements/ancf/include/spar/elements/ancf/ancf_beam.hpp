#pragma once
/// \file
/// Building a straight ANCF beam in a model (docs/ancf.md §5): nodes as vector blocks of 12
/// (r, r_x, r_y, r_z) in the undeformed configuration, one AncfBeamElement per span (all equal, so
/// they share one set of constant tables), and dead forces on node positions.

#include <spar/core/cross_section.hpp>
#include <spar/core/model.hpp>
#include <spar/core/section_integrals.hpp>
#include <spar/elements/ancf/ancf_beam_element.hpp>
#include <spar/elements/loads/loads.hpp>

#include <Eigen/Core>

#include <vector>

namespace spar::core {

/// 24 coordinates (001 §2) or 30 with quadratic transverse gradients (001 §5).
enum class AncfElementKind { standard_24, higher_order_30 };

struct AncfBeamParameters {
  Eigen::Vector3d start = Eigen::Vector3d::Zero();
  Eigen::Vector3d end = Eigen::Vector3d::UnitX();
  /// The section's y axis (r_y in the reference configuration); its component along the beam is
  /// removed, z = x × y.
  Eigen::Vector3d y_direction = Eigen::Vector3d::UnitY();
  int elements = 1;
  AncfElementKind kind = AncfElementKind::standard_24;
  AncfForceMethod method = AncfForceMethod::gerstmayr;
  AncfLockingRemedy remedy = AncfLockingRemedy::none;
  /// Shear correction factor k of the transverse shear stresses, S_xy = 2kμ E_xy and
  /// S_xz = 2kμ E_xz (docs/ancf.md §7): 1 (default) is the plain St. Venant–Kirchhoff law of
  /// paper 001; a Timoshenko section's k (5/6 for a rectangle, or Cowper's,
  /// CrossSection::rectangle(...).shear_coefficient_2) gives its shear deflection F L/(k G A).
  /// It scales the torsional stiffness by k too (as in Chrono's ANCF 3243). 0 < k ≤ 1.
  double shear_factor = 1.0;
  Material material;
  SectionIntegrals section;
};

struct AncfBeam {
  AncfElementKind kind = AncfElementKind::standard_24;
  std::vector<int> nodes;           ///< vector blocks of 12, from start to end
  std::vector<int> element_blocks;  ///< the 30-coordinate elements' own blocks of 6 (else empty)
  std::vector<int> elements;        ///< model element indices
  double element_length = 0.0;
};

/// Adds the beam's blocks and elements. Throws spar::Error, before adding anything, for fewer
/// than one element, a zero-length beam, a y direction along the beam, an invalid material, a
/// section of no area (a default SectionIntegrals) or a shear factor outside (0, 1].
AncfBeam add_ancf_beam(Model& model, const AncfBeamParameters& parameters);

/// The position r of an ANCF node (the first three coordinates of its block). Throws spar::Error
/// for a block that is not a vector block of 12 (a frame, a block that does not exist).
Eigen::Vector3d ancf_node_position(const Configuration& q, int node);

/// Points r(x, 0, 0) of the reference line, `samples` ≥ 2 equally spaced from start to end (one
/// row each), from the Hermite interpolation of 001 eq. (5).
Eigen::MatrixXd sample_ancf_centerline(const Configuration& q, const AncfBeam& beam, int samples);

/// A dead force on an ANCF node's position (a VectorLoadElement with (f, 0, 0, 0)); returns the
/// element index. Throws for a block that is not a vector block of 12.
int add_ancf_nodal_force(Model& model, int node, const Eigen::Vector3d& force, LoadHistory history = {});

}  // namespace spar::core
