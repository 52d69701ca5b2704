#pragma once
/// \file
/// A cable with a sliding node and element length control (paper 000 §5; docs/rancf.md,
/// "Sliding node and length control").
///
/// The cable lies straight along +X from the origin, or along a given stress-free shape
/// (SlidingCableParameters::shape, planar cables: elements/cable/cable_reference.hpp). Every node is a vector block [r, r_x]; every
/// node has a scalar material-coordinate block, fixed (a Dirichlet dof) except at the sliding node.
/// The two elements next to the sliding node are ALE-RANCF, the others fixed-length RANCF; a point
/// mass on the sliding node is the lumped mass sliding without friction. The slope is continuous
/// across the sliding node (000 eq. (40), first case: one r_x per node, no constraint).
///
/// Initial mesh: elements of L_std = L/N, except that one interior node is left out so that the
/// two elements next to the sliding node span 2 L_std together; that sum is kept by every length
/// control event, so after the first event every element stays in [0.5, 1.5] L_std.
///
/// Length control (000 §5, Figure 7): when an element next to the sliding node exceeds
/// 1.5 L_std, a node H is inserted in it (de Casteljau, exact) so that the element away from the
/// sliding node is L_std, and the node next to the sliding node on the other side is deleted
/// (merge, least-squares weights or unit weights for ALE-ANCF). The node count and the block
/// layout stay the same: the deleted node's blocks are reused for H. Rates are carried by the map
/// P (new dofs × old dofs) for GeneralizedAlpha::remap: on H's rows the material velocity and
/// slope rate at x_H (RancfSplit::material_jacobian; H's material coordinate is fixed from then
/// on), the identity elsewhere (the merge keeps A's and B's rates). The caller then restarts the
/// accelerations (GeneralizedAlpha::initialize): the merged system's are not the mapped ones.

#include <spar/elements/cable/rancf_cable_element.hpp>
#include <spar/core/model.hpp>

#include <Eigen/Core>

#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace spar::core {

struct SlidingCableParameters {
  double length = 1.0;             ///< L (m)
  int elements = 5;                ///< N ≥ 3
  RancfSection section;
  double slider_position = 0.1;    ///< initial material coordinate of the sliding node (m)
  double slider_mass = 1.0;        ///< lumped mass (kg)
  bool rational = true;            ///< ALE-RANCF merges (least-squares weights) or ALE-ANCF (k = 1)
  /// Merged weights are kept in [1/b, b] (core::merge_rancf_weights; infinity: 000 as written).
  /// 4 removes the k = 9.3 of suspended_beam with 6 elements (largest energy jump 3.7e-2 → 2.0e-2
  /// of the kinetic energy) and leaves every other run of examples/ unchanged (docs/rancf.md).
  double max_merge_weight = 4.0;
  int quadrature_points = 5;
  /// Reserve a free-particle block for the mass to leave the cable at a free end (release()).
  bool detachable = false;
  /// The sliding node holds a node block per side (000 eq. (39)): the element left of it uses
  /// chain()[slider()], the one right of it right_slider_node(); the caller couples them with
  /// joints::SlidingNodeSlopes (000 eq. (40): continuous or discontinuous slopes). False: one node
  /// block, the slopes continuous by construction. Not with `detachable`.
  bool two_sided_slider = false;
  /// The stress-free shape cut at the initial mesh's material breakpoints (N + 1 coordinates from
  /// 0 to L), e.g. CableReference::circular_arc (000 §6.3). Empty: straight along +X from the
  /// origin with no reference strains (000 as written). Planar cables only.
  std::function<CableReference(const std::vector<double>& breakpoints)> shape;
};

/// The coordinates [r, r_x] fixed at each end of a cable, counted from the first of the end node's
/// block: Dim pins the position, 2·Dim clamps the slope too (SlidingCable::fix_supports).
struct CableSupports {
  int left = 0, right = 0;
};

/// One length-control event.
struct LengthControlEvent {
  double time = 0.0;
  std::string description;
  int grown_element = -1;              ///< index (along the chain) of the element that was split
  Eigen::Vector4d grown_weights;       ///< its weights before the split
  Eigen::Vector4d merged_near_weights; ///< before the merge: the element next to the slider
  Eigen::Vector4d merged_far_weights;  ///< before the merge: the element beyond the deleted node
  Eigen::Vector4d split_weights_far;   ///< the new fixed-length element (normalized, w3 = 1)
  Eigen::Vector4d split_weights_near;  ///< the new ALE element next to the sliding node
  Eigen::Vector4d merged_weights;      ///< the merged ALE element (k0, k1, k2, 1)
  bool merge_fallback = false;         ///< 000 eq. (38) fell back to k = 1
  bool merge_bounded = false;          ///< the weights were shrunk to max_merge_weight
  double merge_miss = 0.0;             ///< |r̄(ū_H) − r_H| of the merged element
};

template <int Dim>
class SlidingCable {
public:
  /// Adds the cable's blocks and elements to `model` (straight along +X from the origin, or on
  /// parameters.shape) and the point mass. Throws spar::Error for N < 3, a slider not strictly
  /// inside the cable, or a shape that does not span [0, L] in N pieces (or on a spatial cable).
  SlidingCable(Model& model, const SlidingCableParameters& parameters);

  /// Node blocks [r, r_x] in order along the cable (changes at events).
  const std::vector<int>& chain() const { return chain_; }
  /// Material-coordinate blocks, parallel to chain().
  const std::vector<int>& materials() const { return materials_; }
  /// Position of the sliding node in chain() (−1 once the mass has left).
  int slider() const { return slider_; }
  /// The sliding node's block for the element right of it (two_sided_slider), else −1.
  int right_slider_node() const { return right_slider_node_; }
  double standard_length() const { return standard_length_; }
  /// The reference length of element k (between chain()[k] and chain()[k + 1]).
  double element_length(const Configuration& q, int k) const;
  /// The shortest and the longest element over L_std among those length control keeps in
  /// [0.5, 1.5] L_std once it has acted (000 §5): every element but, while the sliding node is
  /// next to an end element (no node left to delete on that side), the two next to it.
  std::pair<double, double> controlled_length_ratios(const Configuration& q) const;
  /// The weights of element k.
  const Eigen::Vector4d& weights(int k) const { return weights_[k]; }
  /// The stress-free shape, or null for a straight cable.
  const std::shared_ptr<const CableReference>& reference() const { return reference_; }
  /// The centreline: `per_element` points per element plus the last end, (N·per_element + 1) × 3
  /// (z = 0 in 2D), along the cable.
  Eigen::MatrixXd sample_centerline(const Configuration& q, int per_element) const;
  /// The same padded to `rows` rows by repeating the last point: a constant size across release(),
  /// which leaves the cable one element shorter (a results file's fixed-size centerline dataset).
  Eigen::MatrixXd sample_centerline(const Configuration& q, int per_element, Eigen::Index rows) const;
  /// The deformed length Σ ∫ |r_x| dx (8 Gauss points per element).
  double deformed_length(const Configuration& q) const;
  /// The global dofs to fix (the supports are the caller's): the material coordinates of every
  /// node but the sliding one (after release(): of every node) and, while the mass is on the
  /// cable, the reserved particle block.
  std::vector<int> fixed_dofs(const Configuration& q) const;
  /// Fixes fixed_dofs() and the `supports` at the current end nodes (Model::set_fixed_dofs). Call
  /// it again after release(), which changes both. Throws spar::Error for a count outside [0, 2·Dim].
  void fix_supports(Model& model, const CableSupports& supports) const;

  /// The particle block (Dim entries) reserved for the released mass, or −1.
  int particle() const { return particle_; }
  bool released() const { return released_; }
  /// Where the mass is: the sliding node's position r, or the particle's once released.
  Eigen::Matrix<double, Dim, 1> mass_position(const Configuration& q) const;
  /// The sliding node's material coordinate x (m from the cable's first end); NaN once released.
  double slider_coordinate(const Configuration& q) const;
  /// The length below which the element between the sliding node and a free end is given up and
  /// the mass released (release()): 0.1 L_std, or four steps of the sliding node's travel at its
  /// material rate. A shorter ALE element has bending frequencies (EI/l³) the step no longer
  /// follows: at 0.05 L_std the ALE-ANCF falling beam (40 elements, h = 2.5e-4) gained 44 J of
  /// kinetic energy in its last step on the beam (docs/rancf.md, "Release").
  double release_length(double time_step, double material_rate) const;
  /// Whether the sliding node is next to the end element at `end` (0 or chain().size() − 1) and
  /// that element is shorter than `min_length`.
  bool near_end(const Configuration& q, int end, double min_length) const;
  /// The mass leaves the cable (docs/rancf.md, "Release"): it becomes a free particle with the
  /// sliding node's position and velocity; the sliding node becomes the cable's end — the short
  /// element beyond it is removed from the model with its material, the old end node's blocks are
  /// fixed from then on, the inner element keeps its weights and current length — and is held at
  /// its material point (rates: the material velocity and slope rate there). The chain loses one
  /// node. Sets P (new × old dofs) for GeneralizedAlpha::remap; the caller then refixes the dofs
  /// (fixed_dofs) and restarts the accelerations. Throws spar::Error without a reserved particle
  /// block, twice, or when the slider is not next to an end element.
  void release(Model& model, Eigen::MatrixXd& P);

  /// Inserts/deletes nodes when an element next to the sliding node exceeds 1.5 L_std and a node
  /// can be deleted on the other side; returns the event and sets P (new × old dofs) for
  /// GeneralizedAlpha::remap, or returns nothing. P maps accelerations by J too, without the
  /// convective term J̇ q̇ of the split (docs/rancf.md eq. R23).
  std::optional<LengthControlEvent> control_length(Model& model, double time, Eigen::MatrixXd& P);

private:
  std::unique_ptr<Element> make_element(const Configuration& q, int k, bool ale) const;
  /// The node block element k uses at chain position `position` (k or k + 1).
  int node_block(int position, int k) const;

  SlidingCableParameters parameters_;
  double standard_length_ = 0.0;
  std::vector<int> chain_, materials_, element_index_;
  std::vector<Eigen::Vector4d> weights_;
  std::vector<double> fixed_lengths_;
  std::shared_ptr<const CableReference> reference_;
  int slider_ = 0;
  int particle_ = -1;
  int mass_element_ = -1;
  bool released_ = false;
  int dead_node_ = -1, dead_material_ = -1;  ///< the sliding node's blocks after release()
  int right_slider_node_ = -1;
};

extern template class SlidingCable<2>;
extern template class SlidingCable<3>;

}  // namespace spar::core
