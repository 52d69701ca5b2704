#pragma once
// A mass on a spring whose first few tangent evaluations break the Newton iteration in one of the
// three ways the solvers must survive: a non-finite residual, a non-finite iteration matrix, or a
// finite residual and matrix whose solution overflows (a nearly singular tangent at an iterate).
// Afterwards it is sound, so a test can watch the step (or load step) cut back and then succeed.
//
// Sound, on a 1-coordinate vector block x: r = m ẍ + k (x − λ s), the spring's anchor at λ s
// (λ the load factor: 1 in dynamics, so x oscillates about s; x = λ s in statics, exact in one
// Newton iteration). M = m, K = k, no damping; kinetic ½ m ẋ², strain ½ k (x − λ s)².
//
// Broken: each evaluation that asks for the stiffness (every Newton iteration that builds its
// matrix, in statics and dynamics; not the mass-only start of a dynamic run) counts, and the first
// `failures` of them give
//   - residual: r = +inf;
//   - matrix:   K = NaN;
//   - increment: r = 1e300 with M = K = 1e-300, both finite: Newton's increment r/M overflows to inf.
// The count is atomic because parallel assembly evaluates elements on several threads.
#include <spar/core/configuration.hpp>
#include <spar/core/element.hpp>
#include <spar/error.hpp>

#include <atomic>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace spar::test {

enum class BrokenPart { residual, matrix, increment };

struct NonFiniteIterateParameters {
  int block = 0;             ///< a vector block of 1 coordinate
  double mass = 1.0;         ///< m, kg
  double stiffness = 100.0;  ///< k, N/m
  double anchor = 0.1;       ///< s, m: the spring's anchor at load factor 1
  BrokenPart broken = BrokenPart::increment;
  int failures = 0;          ///< how many stiffness evaluations are broken, from the first
};

class NonFiniteIterate final : public core::Element {
public:
  /// `evaluations` counts the stiffness evaluations (shared, so it outlives the element inside the
  /// model).
  NonFiniteIterate(const NonFiniteIterateParameters& p, std::shared_ptr<std::atomic<int>> evaluations)
      : blocks_{p.block}, p_(p), evaluations_(std::move(evaluations)) {}

  const std::vector<int>& blocks() const override { return blocks_; }
  std::string name() const override { return "non-finite iterate on block " + std::to_string(blocks_[0]); }

  void compute(const core::ElementInput& in, const core::ElementRequest& request,
               core::ElementOutput& out) const override {
    const core::Configuration& q = *in.q;
    if (q.is_frame(blocks_[0]) || q.blocks[blocks_[0]].size != 1)
      throw Error("block " + std::to_string(blocks_[0]) + " is not a 1-coordinate vector block",
                  "test::NonFiniteIterate", "put the element on a vector block of 1 coordinate");
    const int offset = q.blocks[blocks_[0]].offset;
    const double stretch = q.vector(blocks_[0])(0) - in.load_factor * p_.anchor;
    const bool broken = request.stiffness && evaluations_->fetch_add(1) < p_.failures;
    double m = p_.mass, k = p_.stiffness;
    if (request.residual) {
      out.residual(0) = k * stretch;
      if (in.dynamic()) out.residual(0) += m * (*in.acceleration)(offset);
    }
    if (broken) {
      switch (p_.broken) {
        case BrokenPart::residual: out.residual(0) = std::numeric_limits<double>::infinity(); break;
        case BrokenPart::matrix: k = std::numeric_limits<double>::quiet_NaN(); break;
        case BrokenPart::increment:
          out.residual(0) = 1e300;
          m = k = 1e-300;
          break;
      }
    }
    if (request.stiffness) out.stiffness(0, 0) = k;
    if (request.mass) out.mass(0, 0) = m;
    if (in.dynamic()) out.energy.kinetic = 0.5 * p_.mass * std::pow((*in.velocity)(offset), 2);
    out.energy.strain = 0.5 * p_.stiffness * stretch * stretch;
  }

private:
  std::vector<int> blocks_;
  NonFiniteIterateParameters p_;
  std::shared_ptr<std::atomic<int>> evaluations_;
};

}  // namespace spar::test
