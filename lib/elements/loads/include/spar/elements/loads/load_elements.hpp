#pragma once
/// \file
/// External loads as Elements (003 eq. 33): a concentrated force or moment on a frame block, and
/// a force or moment per unit length on one element of a beam. Each enters the residual as −f_ext
/// and, on an energy request, reports f_ext for the energy balance (docs/dynamics.md D8).
///
/// Scale: the load factor λ in statics; history(t) in dynamics (1 without a history).

#include <spar/core/element.hpp>
#include <spar/elements/beam/beam.hpp>
#include <spar/elements/loads/loads.hpp>

#include <functional>
#include <string>
#include <vector>

namespace spar::core {

/// The factor on a load: λ in statics, λ·history(t) in dynamics. Throws spar::InputError for a
/// history that is not finite at t, in statics too (at ElementInput::time, 0 in solve_static,
/// where a dynamic run from the static state starts), though statics does not apply it.
double load_scale(const ElementInput& in, const std::function<double(double)>& history);

/// A NodalForce or NodalMoment on one frame block.
class NodalLoadElement final : public Element {
public:
  NodalLoadElement(const Load& load, std::function<double(double)> history, int load_index);

  const std::vector<int>& blocks() const override { return blocks_; }
  std::string name() const override { return "load " + std::to_string(load_index_); }
  bool has_external_force() const override { return true; }
  bool has_potential() const override { return !is_moment(load_); }
  const Load& load() const { return load_; }

private:
  void compute(const ElementInput& in, const ElementRequest& request,
               ElementOutput& out) const override;
  Load load_;
  std::function<double(double)> history_;
  int load_index_;
  std::vector<int> blocks_;
};

/// A DistributedForce or DistributedMoment on element e of a beam (consistent nodal forces,
/// docs/beam.md B14 for the moment).
class DistributedLoadElement final : public Element {
public:
  DistributedLoadElement(const Load& load, const GeometricallyExactBeam& beam, int e,
                         std::function<double(double)> history, int load_index);

  const std::vector<int>& blocks() const override { return blocks_; }
  std::string name() const override {
    return "load " + std::to_string(load_index_) + " on element " + std::to_string(element_);
  }
  bool has_external_force() const override { return true; }
  bool has_potential() const override { return !is_moment(load_); }
  const Load& load() const { return load_; }

private:
  void compute(const ElementInput& in, const ElementRequest& request,
               ElementOutput& out) const override;
  Load load_;
  const GeometricallyExactBeam* beam_;
  int element_;
  std::function<double(double)> history_;
  int load_index_;
  std::vector<int> blocks_;
  std::vector<double> shape_integrals_;
};

}  // namespace spar::core
