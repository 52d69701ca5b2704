#pragma once
// A tether whose tension saturates, T(z) = T_max tanh(k z / T_max), holding a dead load λ F on a
// 1-vector block z (statics only): r = T(z) − λ F, K = k / cosh²(k z / T_max). Past λ F = T_max
// there is no equilibrium, and Newton's iterates run away until the tangent underflows to exactly
// zero (cosh overflows beyond k z / T_max ≈ 710): a singular iteration matrix at an iterate, as a
// cable going slack or a yielding link gives.
#include <spar/core/configuration.hpp>
#include <spar/core/element.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace spar::test {

struct SaturatingTetherParameters {
  int block = 0;             ///< 1-vector block: the elongation z, m
  double stiffness = 1.0;    ///< k, N/m
  double max_tension = 1.0;  ///< T_max, N
  double load = 1.0;         ///< F, N (scaled by the load factor)
};

class SaturatingTether final : public core::Element {
public:
  explicit SaturatingTether(const SaturatingTetherParameters& p) : blocks_{p.block}, p_(p) {}

  const std::vector<int>& blocks() const override { return blocks_; }
  std::string name() const override { return "saturating tether"; }

  void compute(const core::ElementInput& in, const core::ElementRequest& request,
               core::ElementOutput& out) const override {
    const double x = p_.stiffness * in.q->vector(blocks_[0])(0) / p_.max_tension;
    if (request.residual) out.residual(0) = p_.max_tension * std::tanh(x) - in.load_factor * p_.load;
    if (request.stiffness) {
      const double c = std::cosh(x);
      out.stiffness(0, 0) = p_.stiffness / (c * c);
    }
  }

  /// The equilibrium elongation under the load λ F < T_max.
  double equilibrium(double load_factor) const {
    return p_.max_tension / p_.stiffness * std::atanh(load_factor * p_.load / p_.max_tension);
  }

private:
  std::vector<int> blocks_;
  SaturatingTetherParameters p_;
};

}  // namespace spar::test
