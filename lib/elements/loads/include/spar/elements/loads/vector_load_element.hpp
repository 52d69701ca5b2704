#pragma once
/// \file
/// A dead generalized force on the coordinates of one vector block: a force on an ANCF node is
/// (f, 0, 0, 0) on its (r, r_x, r_y, r_z), the virtual work f · δr. Scaled by the load factor in
/// statics and by history(t) in dynamics (elements/loads/load_elements.hpp).

#include <spar/core/element.hpp>

#include <functional>
#include <string>
#include <vector>

namespace spar::core {

class VectorLoadElement final : public Element {
public:
  /// Throws spar::Error unless `block` is a vector block of q with force.size() coordinates and
  /// the force is finite.
  VectorLoadElement(const Configuration& q, int block, Eigen::VectorXd force,
                    std::function<double(double)> history, int load_index);

  const std::vector<int>& blocks() const override { return blocks_; }
  std::string name() const override { return "vector load " + std::to_string(load_index_); }
  bool has_external_force() const override { return true; }

private:
  void compute(const ElementInput& in, const ElementRequest& request,
               ElementOutput& out) const override;
  std::vector<int> blocks_;
  Eigen::VectorXd force_;
  std::function<double(double)> history_;
  int load_index_;
};

}  // namespace spar::core
