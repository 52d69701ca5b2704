#pragma once
/// \file
/// A spatial RANCF / ANCF cable's centerline as a core::Curve (docs/rancf.md; docs/joints.md
/// §2.5): a chain of fixed-length RancfCableElement<3>, element k of reference length l_k
/// between node blocks [r_k, r_x,k] and [r_{k+1}, r_x,{k+1}], r(u) = S(u) e (000 eqs. (7)–(9);
/// with unit weights the ANCF cable). ζ is the material coordinate x ∈ [0, Σ l_k]; inside
/// element k, u = (x − X_k)/l_k and d/dζ = (1/l_k) d/du. Its segments are the elements, its
/// blocks the nodes.

#include <spar/core/curve.hpp>
#include <spar/core/model.hpp>

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace spar::core {

class CableCenterline final : public LinearCurve {
public:
  /// The cable of the chain of elements `elements` of `model` (indices of RancfCableElement<3>,
  /// from one end to the other, each starting at the node the previous one ends at). Throws
  /// spar::Error for no element, an index that is not a spatial fixed-length RANCF element, or a
  /// chain that is broken.
  CableCenterline(const Model& model, const std::vector<int>& elements);

  /// Σ l_k.
  double length() const override { return breakpoints_.back(); }
  int block_count() const override { return static_cast<int>(nodes_.size()); }
  int block(int i) const override { return nodes_[i]; }
  int segment_count() const override { return static_cast<int>(lengths_.size()); }
  /// The element holding x (the one after a node, the last one at the end).
  int segment_at(double zeta) const override;
  /// Nodes first … last + 1.
  CurveBlocks segment_blocks(int first, int last) const override { return {first, last + 1}; }

private:
  /// [s₁, s₂, s₃, s₄] of 000 eq. (9) and their x-derivatives, coefficients r_A, r_x^A, r_B, r_x^B.
  void compute_basis(double zeta, int order, CurvePoint& p) const override;

  std::vector<int> nodes_;
  std::vector<double> lengths_, breakpoints_;  ///< l_k; X_0 = 0 … X_N
  std::vector<Eigen::Vector4d> weights_;
};

/// The centerline of the cable made of `elements` of `model` (see CableCenterline), which must
/// outlive the curve.
std::shared_ptr<const Curve> cable_centerline(const Model& model, const std::vector<int>& elements);

}  // namespace spar::core
