#pragma once
// An element that adds nothing to the equations and throws spar::Error when one coordinate of a
// vector block passes a limit, as a real element does at a configuration it cannot evaluate (a
// beam section turned by π). It counts its refusals, so a test can tell that an iterate reached
// it; the count is atomic because parallel assembly evaluates elements on several threads.
#include <spar/core/configuration.hpp>
#include <spar/core/element.hpp>
#include <spar/error.hpp>

#include <atomic>
#include <memory>
#include <string>
#include <vector>

namespace spar::test {

struct CoordinateLimitParameters {
  int block = 0;       ///< a vector block
  int coordinate = 0;  ///< which of its coordinates
  double limit = 0.0;  ///< evaluation throws when direction · p(coordinate) > limit
  double direction = 1.0;
};

class CoordinateLimit final : public core::Element {
public:
  /// `refusals` counts the throws (shared, so it outlives the element inside the model).
  CoordinateLimit(const CoordinateLimitParameters& p, std::shared_ptr<std::atomic<int>> refusals)
      : blocks_{p.block}, parameters_(p), refusals_(std::move(refusals)) {}

  const std::vector<int>& blocks() const override { return blocks_; }
  std::string name() const override { return "coordinate limit on block " + std::to_string(blocks_[0]); }

  void compute(const core::ElementInput& in, const core::ElementRequest&, core::ElementOutput&) const override {
    const double p = in.q->vector(blocks_[0])(parameters_.coordinate);
    if (parameters_.direction * p > parameters_.limit) {
      ++*refusals_;
      throw Error("coordinate " + std::to_string(parameters_.coordinate) + " = " + std::to_string(p) +
                      " is past the limit", "test::CoordinateLimit", "stay within the limit");
    }
  }

private:
  std::vector<int> blocks_;
  CoordinateLimitParameters parameters_;
  std::shared_ptr<std::atomic<int>> refusals_;
};

}  // namespace spar::test
