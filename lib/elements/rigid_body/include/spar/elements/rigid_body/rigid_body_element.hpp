#pragma once
/// \file
/// A rigid body as an Element: one frame block at its centre of mass, M = diag(m I, J),
/// f_gyr = (0, Ω × JΩ) (core/frame_inertia.hpp), and its weight m g.

#include <spar/core/element.hpp>
#include <spar/elements/rigid_body/rigid_body.hpp>

#include <string>
#include <vector>

namespace spar::core {

class RigidBodyElement final : public Element {
public:
  RigidBodyElement(const RigidBody& body, int body_index);

  const std::vector<int>& blocks() const override { return blocks_; }
  std::string name() const override { return "rigid body " + std::to_string(body_index_); }

private:
  void compute(const ElementInput& in, const ElementRequest& request,
               ElementOutput& out) const override;
  RigidBody body_;
  int body_index_;
  std::vector<int> blocks_;
};

}  // namespace spar::core
