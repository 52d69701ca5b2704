#pragma once
/// \file
/// A curve of the model that a joint can slide along (003 §4, eqs. 50–53; docs/joints.md §2.5):
/// the centerline of a beam or a cable, a rail fixed in a rigid body. Any element family offers
/// its own; the sliding joint grips this interface and names no element kind.
///
/// The curve's parameter ζ runs over [0, length()], a metre-sized coordinate (the reference arc
/// length where the reference curve is parameterized proportionally to it). Beyond an end ζ_e
/// the curve continues as the end's tangent line, x(ζ) = x(ζ_e) + x_ζ(ζ_e)(ζ − ζ_e) (eq. J29),
/// so that a Newton iterate that overshoots an end can be evaluated.
///
/// A curve depends on some blocks of the model, numbered 0 … block_count() − 1 along it (a beam's
/// control points, a cable's nodes, a rigid body's one frame). It is made of segments (elements,
/// knot spans) that each depend on a contiguous range of them, so a joint lists only the blocks
/// of the segments around ζ (its window) and changes them when ζ enters another segment.
///
/// Derivatives are in the blocks' local increments Δ (core/configuration.hpp: a frame's Δx
/// inertial and Δφ material, a vector block's entries). With f a fixed inertial vector, a curve
/// point x(ζ, q) gives a joint (docs/joints.md eqs. J25–J27):
///   x, x_ζ, x_ζζ                                   (point),
///   W ∂x/∂Δ                                        (add_jacobian),
///   ∂((∂x/∂(ζ, Δ))ᵀ f)/∂(ζ, Δ)                     (add_multiplier_tangent, eq. 52),
///   ẍ − x_ζ ζ̈ − (∂x/∂Δ) v̇ = x_ζζ ζ̇² + 2ζ̇ (∂x_ζ/∂Δ) v + (the convective part at fixed ζ)
///                                                  (add_acceleration_terms).

#include <spar/core/configuration.hpp>
#include <spar/iga/basis.hpp>

#include <Eigen/Core>

#include <array>

namespace spar::core {

/// The highest ζ-derivative of a curve point (the sliding joint's eq. 52 needs x_ζζ).
inline constexpr int max_curve_derivative = 2;

/// Most coefficient vectors of a point of a LinearCurve (a beam element's control points).
inline constexpr int max_curve_coefficients = iga::max_degree + 1;

/// A contiguous range of a curve's blocks, first … last (curve numbering).
struct CurveBlocks {
  int first = 0;
  int last = 0;
};

/// One coefficient vector P_i of a point of a LinearCurve: three coordinates of one of the
/// point's blocks.
struct CurveCoefficient {
  int block = 0;       ///< the model block (global index)
  int coordinate = 0;  ///< its first coordinate in the block: 0 for a frame (its position x)
  int column = 0;      ///< its first column counted from the point's first block's first column
};

/// A point of a curve at ζ in a configuration (Curve::point). Fixed size: no heap storage.
struct CurvePoint {
  double zeta = 0.0;
  int segment = 0;      ///< the segment holding ζ (the end segment beyond an end)
  int first_block = 0;  ///< the point depends on the curve's blocks first_block …
  int block_count = 0;  ///< … first_block + block_count − 1, at consecutive Jacobian columns
  int order = 0;        ///< x[0 … order] are computed
  /// d^k x/dζ^k, k = 0 … order (inertial).
  std::array<Eigen::Vector3d, max_curve_derivative + 1> x{};
  /// LinearCurve's description of the point, x^(k) = Σ_i shape(k, i) P_i: its coefficient
  /// vectors and their weights' ζ-derivatives (k ≤ max(order, 1)). Other curves leave them unused.
  int coefficient_count = 0;
  std::array<CurveCoefficient, max_curve_coefficients> coefficients{};
  iga::BasisTable shape = iga::BasisTable::Zero();
};

class Curve {
public:
  virtual ~Curve() = default;

  /// ζ runs over [0, length()].
  virtual double length() const = 0;
  /// The number of blocks the curve depends on, and the model block of the curve's block i.
  virtual int block_count() const = 0;
  virtual int block(int i) const = 0;
  /// The number of segments, and the segment holding ζ (clamped into [0, length()]; at a
  /// boundary between segments the one after it, the last one at length()).
  virtual int segment_count() const = 0;
  virtual int segment_at(double zeta) const = 0;
  /// The curve's blocks that the segments first … last depend on.
  virtual CurveBlocks segment_blocks(int first, int last) const = 0;

  // Evaluations: non-virtual, they check their input and do what is the same for every curve,
  // then call the curve's own compute_* below. None allocates.

  /// The point at ζ (any finite ζ: beyond an end, on the end's tangent line) with its
  /// ζ-derivatives up to `order` (0 … max_curve_derivative). Throws spar::Error for a non-finite
  /// ζ or an order out of range.
  CurvePoint point(const Configuration& q, double zeta, int order) const;
  /// Adds W ∂x/∂Δ (3 × the point's block columns) to B at rows first_row … first_row + 2 and at
  /// columns from first_column on, where the point's blocks sit one after another.
  void add_jacobian(const Configuration& q, const CurvePoint& p, const Eigen::Matrix3d& weight,
                    Eigen::Ref<Eigen::MatrixXd> B, int first_row, int first_column) const;
  /// Adds ∂((∂x/∂(ζ, Δ))ᵀ f)/∂(ζ, Δ) for a fixed inertial f (003 eq. 52 with f = −λ): x_ζζ·f at
  /// (zeta_index, zeta_index), then the curve's (ζ, Δ), (Δ, ζ) and (Δ, Δ) entries, the block
  /// columns from first_column on as in add_jacobian. Needs p.order = 2.
  void add_multiplier_tangent(const Configuration& q, const CurvePoint& p, const Eigen::Vector3d& f,
                              Eigen::Ref<Eigen::MatrixXd> K, int zeta_index, int first_column) const;
  /// Adds to `terms` the part of ẍ along a motion (ζ(t), q(t)) that is not proportional to ζ̈ or
  /// to the blocks' accelerations: x_ζζ ζ̇², then the curve's 2ζ̇ (∂x_ζ/∂Δ) v and convective
  /// terms; `velocity` is the model's global velocity. Needs p.order = 2.
  void add_acceleration_terms(const Configuration& q, const CurvePoint& p, const Eigen::VectorXd& velocity,
                              double zeta_rate, Eigen::Vector3d& terms) const;

private:
  /// The point at a finite ζ with x[0 … order] (order checked).
  virtual CurvePoint compute_point(const Configuration& q, double zeta, int order) const = 0;
  /// W ∂x/∂Δ into B (added).
  virtual void compute_jacobian(const Configuration& q, const CurvePoint& p, const Eigen::Matrix3d& weight,
                                Eigen::Ref<Eigen::MatrixXd> B, int first_row, int first_column) const = 0;
  /// Every entry of ∂((∂x/∂(ζ, Δ))ᵀ f)/∂(ζ, Δ) but (ζ, ζ), added.
  virtual void compute_multiplier_tangent(const Configuration& q, const CurvePoint& p, const Eigen::Vector3d& f,
                                          Eigen::Ref<Eigen::MatrixXd> K, int zeta_index,
                                          int first_column) const = 0;
  /// 2ζ̇ (∂x_ζ/∂Δ) v and the convective part of ẍ at fixed ζ, added to `terms`.
  virtual void compute_acceleration_terms(const Configuration& q, const CurvePoint& p,
                                          const Eigen::VectorXd& velocity, double zeta_rate,
                                          Eigen::Vector3d& terms) const = 0;
};

/// A curve linear in its blocks' coordinates, x(ζ) = Σ_i w_i(ζ) P_i with each P_i three
/// coordinates of a block: a frame's position (a beam's control points, 003 eq. 53) or three
/// entries of a vector block (an ANCF or RANCF cable's r and r_x, r = S e). Then
///   ∂x/∂P_i = w_i I₃,   the (ζ, P_i) and (P_i, ζ) multiplier-tangent entries w_i,ζ f,
///   the acceleration terms 2ζ̇ Σ_i w_i,ζ Ṗ_i,
/// nothing else (no (Δ, Δ) entries, no convective term). Beyond an end the weights continue
/// linearly, w_i(ζ_e) + w_i,ζ(ζ_e)(ζ − ζ_e) (eq. J29). A family implements compute_basis only.
class LinearCurve : public Curve {
private:
  /// Fills p.segment, p.first_block, p.block_count, p.coefficient_count, p.coefficients and the
  /// weights' ζ-derivatives p.shape(k, i), k = 0 … order, at ζ ∈ [0, length()].
  virtual void compute_basis(double zeta, int order, CurvePoint& p) const = 0;

  CurvePoint compute_point(const Configuration& q, double zeta, int order) const final;
  void compute_jacobian(const Configuration& q, const CurvePoint& p, const Eigen::Matrix3d& weight,
                        Eigen::Ref<Eigen::MatrixXd> B, int first_row, int first_column) const final;
  void compute_multiplier_tangent(const Configuration& q, const CurvePoint& p, const Eigen::Vector3d& f,
                                  Eigen::Ref<Eigen::MatrixXd> K, int zeta_index, int first_column) const final;
  void compute_acceleration_terms(const Configuration& q, const CurvePoint& p, const Eigen::VectorXd& velocity,
                                  double zeta_rate, Eigen::Vector3d& terms) const final;
};

}  // namespace spar::core
