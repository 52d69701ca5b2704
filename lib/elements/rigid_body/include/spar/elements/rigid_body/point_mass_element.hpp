#pragma once
/// \file
/// A point mass on the position entries of a vector block (an ANCF/RANCF node [r, r_x], or a
/// free particle): kinetic energy ½ m |ṙ|², weight m g (planar: the first two components of g).
/// On a sliding node of ALE-RANCF cables it is the sliding lumped mass of paper 000 §§5–6.

#include <spar/core/element.hpp>

#include <string>
#include <vector>

namespace spar::core {

struct PointMassParameters {
  int block = -1;      ///< vector block whose first `dimension` entries are the position
  int dimension = 3;   ///< 2 or 3
  double mass = 0.0;   ///< kg, > 0
  std::string name = "point mass";
};

class PointMassElement final : public Element {
public:
  /// Throws spar::Error for a missing block, a dimension other than 2 or 3, or a mass ≤ 0.
  explicit PointMassElement(const PointMassParameters& parameters);

  const std::vector<int>& blocks() const override { return blocks_; }
  std::string name() const override { return parameters_.name; }

private:
  /// Throws spar::Error if the block is a frame or shorter than the dimension.
  void compute(const ElementInput& in, const ElementRequest& request,
               ElementOutput& out) const override;
  PointMassParameters parameters_;
  std::vector<int> blocks_;
};

}  // namespace spar::core
