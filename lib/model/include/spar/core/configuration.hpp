#pragma once
/// \file
/// The configuration space of a model: a product of coordinate blocks of two kinds, and the
/// update rule q ⊕ Δ that every solver and joint asks for, and its inverse q ⊖ q₀ (docs/model.md
/// eqs. M1–M3).
///
/// - A *frame* block is a point of R³ × SO(3): a position x (inertial) and a rotation R. It has
///   six increments, three translations (inertial) then three rotations (material,
///   right-trivialized): x ← x + Δx, R ← R exp(Δφ). Beam control points and rigid bodies are
///   frames.
/// - A *vector* block is a point of Rⁿ with n additive increments: an ANCF node (r, r_x, …), a
///   sliding joint's coordinate ζ, an element's internal coordinates.
///
/// Increments, velocities, accelerations and generalized forces all live in one global "tangent"
/// layout: block after block, each block's entries at its `offset`. For a frame block the velocity
/// is (ẋ inertial, Ω material); for a vector block it is ṗ.

#include <Eigen/Core>

#include <vector>

namespace spar::core {

/// Increments of a frame block: 3 translations + 3 rotations.
inline constexpr int frame_dofs = 6;

enum class BlockKind { frame, vector };

/// Where a block sits in the global tangent layout.
struct Block {
  BlockKind kind = BlockKind::frame;
  int size = frame_dofs;  ///< number of increments (6 for a frame, n for a vector)
  int offset = 0;         ///< index of its first increment in the global layout
};

/// The coordinates of every block.
struct Configuration {
  std::vector<Block> blocks;
  /// Per block: x of a frame (a vector block keeps zero here).
  std::vector<Eigen::Vector3d> position;
  /// Per block: R of a frame (a vector block keeps the identity here).
  std::vector<Eigen::Matrix3d> rotation;
  /// dof_count() entries: the coordinates of every vector block at its offset (frame entries
  /// stay zero).
  Eigen::VectorXd values;

  int block_count() const { return static_cast<int>(blocks.size()); }
  int dof_count() const { return static_cast<int>(values.size()); }
  bool is_frame(int b) const { return blocks[b].kind == BlockKind::frame; }

  /// Appends a frame block (x, R); returns its index. R must be a rotation (not checked here).
  int add_frame(const Eigen::Vector3d& x, const Eigen::Matrix3d& R);
  /// Appends a vector block with coordinates p (n ≥ 1 entries); returns its index.
  int add_vector(const Eigen::Ref<const Eigen::VectorXd>& p);

  /// The coordinates of vector block b (its `size` entries of `values`).
  Eigen::Ref<Eigen::VectorXd> vector(int b) { return values.segment(blocks[b].offset, blocks[b].size); }
  Eigen::Ref<const Eigen::VectorXd> vector(int b) const {
    return values.segment(blocks[b].offset, blocks[b].size);
  }

  /// q ← q ⊕ Δ (eq. M1): frames x += Δx, R ← R exp(Δφ); vectors p += Δp. Δ has dof_count()
  /// entries. Throws spar::Error for a wrong size.
  void apply_increment(const Eigen::Ref<const Eigen::VectorXd>& delta);
  /// q ← start ⊕ Δ without accumulating round-off from earlier increments (what Newton
  /// iterations of one step use). `start` must have the layout of *this.
  void assign_increment(const Configuration& start, const Eigen::Ref<const Eigen::VectorXd>& delta);
  /// The largest rotation increment |Δφ| of any frame block in Δ: exp cannot tell Δφ from
  /// Δφ(1 + 2πk/|Δφ|), so a step whose increment reaches π has left the chart (eq. M2).
  double largest_rotation(const Eigen::Ref<const Eigen::VectorXd>& delta) const;
  /// q ⊖ start, the inverse of ⊕ (eq. M1): the increment Δ with start ⊕ Δ = q. Frames
  /// Δx = x − x₀ and Δφ = log(R₀ᵀR) with |Δφ| ≤ π (docs/conventions.md eq. C13; at a relative turn
  /// of π either sign); vectors Δp = p − p₀. Inside the chart, (start ⊕ Δ) ⊖ start = Δ for every
  /// |Δφ| < π (eq. M2). Throws spar::Error when `start` has another layout, or (lie::log) when a
  /// frame's R is no rotation.
  Eigen::VectorXd increment_from(const Configuration& start) const;
};

/// The global tangent-layout indices of the given blocks, block after block: the row and column
/// indices of an element or a joint acting on them.
std::vector<int> block_dofs(const Configuration& q, const std::vector<int>& blocks);

/// The total number of increments of the given blocks.
int block_dof_count(const Configuration& q, const std::vector<int>& blocks);

/// local ← the entries of the global tangent-layout vector `global` at the given blocks, block
/// after block (an element's velocity from the model's). `local` must have block_dof_count entries.
void gather(const Configuration& q, const std::vector<int>& blocks, const Eigen::VectorXd& global,
            Eigen::Ref<Eigen::VectorXd> local);

/// Right-multiplies the rotation columns of every frame block among `blocks` (columns in the
/// local order of block_dofs) by the tangent operator T(Δφ) of that block's entry in the global
/// increment Δ (eq. M3: the derivative of q_n ⊕ Δ in the direction of a change of Δ is
/// q ⊕ T(Δφ) δ for frames, the identity for vectors). Allocates nothing.
void apply_tangent_operator(const Configuration& q, const std::vector<int>& blocks,
                            const Eigen::VectorXd& increment, Eigen::Ref<Eigen::MatrixXd> K);

}  // namespace spar::core
