#pragma once
// A user's own element kind, written against the installed spar package only: a linear
// spring–damper between the positions of two frame blocks (docs/model.md, "Adding an element in
// your own project"). With d = x_a − x_b, l = |d|, e = d/l, the relative velocity w = ẋ_a − ẋ_b
// and the rate of stretch l̇ = e·w, its tension is
//     N = k (l − L0) + c l̇,
// its residual (f_int, rows x_a, φ_a, x_b, φ_b) r = [N e; 0; −N e; 0] and its strain energy
// ½ k (l − L0)². The rotations of the frames do not enter: only the translation rows and columns
// of K and C are non-zero.
#include <spar/core/element.hpp>

#include <string>
#include <vector>

namespace plugin {

struct SpringDamperParameters {
  int block_a = 0, block_b = 1;  ///< two distinct frame blocks; the element acts on their positions
  double stiffness = 0.0;        ///< k ≥ 0, N/m
  double damping = 0.0;          ///< c ≥ 0, N s/m
  double rest_length = 0.0;      ///< L0 ≥ 0, m
};

class SpringDamper final : public spar::core::Element {
public:
  /// Throws spar::Error for equal blocks, or a negative or non-finite k, c or L0.
  explicit SpringDamper(const SpringDamperParameters& parameters);

  const std::vector<int>& blocks() const override { return blocks_; }
  std::string name() const override;
  /// With c > 0 the damper's force c l̇ e is a dissipative force: the integrator books its work as
  /// physical dissipation (ElementOutput::dissipative_force), not as its own numerical one.
  bool has_dissipation() const override { return damping_ > 0.0; }

private:
  void compute(const spar::core::ElementInput& in, const spar::core::ElementRequest& request,
               spar::core::ElementOutput& out) const override;

  std::vector<int> blocks_;
  double stiffness_, damping_, rest_length_;
};

}  // namespace plugin
