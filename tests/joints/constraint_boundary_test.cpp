// The Constraint interface's boundary (joints/constraint.hpp): every evaluation hands the joint's
// compute_* its output zeroed, so a joint that writes only its non-zero entries returns the right
// B, K_λ, c, Φ and Φ_t whatever the caller's buffer held; and bad input — a configuration without
// the joint's blocks, a non-finite time, mis-sized outputs, multipliers or velocities, non-finite
// multipliers or velocities — raises an error naming the evaluation, the joint and the field.
#include <spar/error.hpp>
#include <spar/joints/sliding_node_slopes.hpp>
#include <spar/joints/spherical_joint.hpp>

#include <catch2/catch.hpp>

#include <limits>
#include <string>
#include <vector>

#include "constraint_checks.hpp"

using namespace spar;

namespace {

constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();

/// A joint written as the interface allows, entry by entry: it never touches its zero entries.
/// Blocks: a 2-vector p and a frame (x, R);
///   Φ = (p₀²/2, p₁ − x₂),  B = [p₀ 0 | 0 0 0 0 0 0; 0 1 | 0 0 −1 0 0 0],
///   K_λ = λ₀ e₀e₀ᵀ,  c = (ṗ₀², 0).
class SparseLink final : public joints::Constraint {
public:
  SparseLink(int vector, int frame) : blocks_{vector, frame} {}
  int equation_count() const override { return 2; }
  const std::vector<int>& blocks() const override { return blocks_; }

private:
  void compute_value(const core::Configuration& q, double, Eigen::Ref<Eigen::VectorXd> phi) const override {
    phi(0) = 0.5 * p(q)(0) * p(q)(0);
    phi(1) = p(q)(1) - q.position[blocks_[1]](2);
  }
  void compute_jacobian(const core::Configuration& q, double, Eigen::Ref<Eigen::MatrixXd> B) const override {
    B(0, 0) = p(q)(0);
    B(1, 1) = 1.0;
    B(1, 4) = -1.0;
  }
  void compute_multiplier_tangent(const core::Configuration&, double, const Eigen::Ref<const Eigen::VectorXd>& lambda,
                                  Eigen::Ref<Eigen::MatrixXd> K) const override {
    K(0, 0) = lambda(0);
  }
  void compute_acceleration_terms(const core::Configuration& q, const Eigen::VectorXd& velocity, double,
                                  Eigen::Ref<Eigen::VectorXd> c) const override {
    const double rate = velocity(q.blocks[blocks_[0]].offset);
    c(0) = rate * rate;
  }
  Eigen::Ref<const Eigen::VectorXd> p(const core::Configuration& q) const { return q.vector(blocks_[0]); }

  std::vector<int> blocks_;
};

/// A frame, the 2-vector p = (0.7, −0.2), another frame: the link acts on blocks 1 and 2.
core::Configuration three_blocks() {
  core::Configuration q;
  q.add_frame(Eigen::Vector3d(1, 2, 3), Eigen::Matrix3d::Identity());
  q.add_vector(Eigen::Vector2d(0.7, -0.2));
  q.add_frame(Eigen::Vector3d(-0.4, 0.5, 0.9), Eigen::Matrix3d::Identity());
  return q;
}

}  // namespace

TEST_CASE("a joint that writes only its non-zeros gets zeroed outputs, whatever the buffer held",
          "[joints][errors]") {
  const core::Configuration q = three_blocks();
  const SparseLink link(1, 2);
  Eigen::MatrixXd B = Eigen::MatrixXd::Constant(2, 8, not_a_number);
  link.jacobian(q, 0.0, B);
  Eigen::MatrixXd expected_B = Eigen::MatrixXd::Zero(2, 8);
  expected_B(0, 0) = 0.7;
  expected_B(1, 1) = 1.0;
  expected_B(1, 4) = -1.0;
  CHECK(B == expected_B);
  // Again with the last call's garbage of another size's worth: B of a joint evaluated before.
  B.setConstant(123.0);
  link.jacobian(q, 0.0, B);
  CHECK(B == expected_B);

  Eigen::MatrixXd K = Eigen::MatrixXd::Constant(8, 8, not_a_number);
  link.multiplier_tangent(q, 0.0, Eigen::Vector2d(1.5, -3.0), K);
  Eigen::MatrixXd expected_K = Eigen::MatrixXd::Zero(8, 8);
  expected_K(0, 0) = 1.5;
  CHECK(K == expected_K);

  Eigen::VectorXd velocity = Eigen::VectorXd::LinSpaced(q.dof_count(), 1.0, 14.0);
  Eigen::VectorXd c = Eigen::VectorXd::Constant(2, not_a_number), phi = c, phi_t = c;
  link.acceleration_terms(q, velocity, 0.0, c);
  CHECK(c == Eigen::Vector2d(7.0 * 7.0, 0.0));  // ṗ₀ is the 7th global entry
  link.value(q, 0.0, phi);
  CHECK(phi == Eigen::Vector2d(0.5 * 0.7 * 0.7, -0.2 - 0.9));
  link.time_derivative(q, 0.0, phi_t);  // the default: no explicit time dependence
  CHECK(phi_t == Eigen::Vector2d::Zero());

  // The derivatives are right too (the checker sees only the public, zeroing interface).
  test::RandomRotations random(611);
  test::check_derivatives(link, q, 0.0, random);
}

TEST_CASE("library joints that accumulate or write only some entries ignore the buffer's garbage",
          "[joints]") {
  // The spherical joint adds its blocks into B and K_λ; the sliding node writes single entries.
  test::RandomRotations random(612);
  const core::Configuration frames = test::random_configuration(3, random);
  const joints::SphericalJoint spherical(joints::Attachment{.node = 2, .offset = Eigen::Vector3d(0.1, 0.2, 0.3)},
                                         joints::Attachment{.node = 0}, frames);
  core::Configuration nodes;
  nodes.add_vector(Eigen::Vector4d(0.1, 0.2, 1.0, 0.1));
  nodes.add_vector(Eigen::Vector4d(0.1, 0.2, 0.9, -0.3));
  const joints::SlidingNodeSlopes hinge(0, 1, 2, joints::SlopeCondition::discontinuous, nodes);
  const auto check = [](const joints::Constraint& joint, const core::Configuration& q) {
    const int m = joint.equation_count();
    const Eigen::Index n = test::local_dofs(joint, q);
    const Eigen::VectorXd lambda = Eigen::VectorXd::LinSpaced(m, 0.5, 1.5);
    const Eigen::VectorXd velocity = Eigen::VectorXd::LinSpaced(q.dof_count(), -1.0, 1.0);
    Eigen::MatrixXd B_clean = Eigen::MatrixXd::Zero(m, n), B_dirty = Eigen::MatrixXd::Constant(m, n, not_a_number);
    joint.jacobian(q, 0.0, B_clean);
    joint.jacobian(q, 0.0, B_dirty);
    CHECK(B_dirty == B_clean);
    Eigen::MatrixXd K_clean = Eigen::MatrixXd::Zero(n, n), K_dirty = Eigen::MatrixXd::Constant(n, n, not_a_number);
    joint.multiplier_tangent(q, 0.0, lambda, K_clean);
    joint.multiplier_tangent(q, 0.0, lambda, K_dirty);
    CHECK(K_dirty == K_clean);
    Eigen::VectorXd c_clean = Eigen::VectorXd::Zero(m), c_dirty = Eigen::VectorXd::Constant(m, not_a_number);
    joint.acceleration_terms(q, velocity, 0.0, c_clean);
    joint.acceleration_terms(q, velocity, 0.0, c_dirty);
    CHECK(c_dirty == c_clean);
  };
  check(spherical, frames);
  check(hinge, nodes);
}

namespace {

/// The message of the spar::Error that `call` raises (empty when it raises none), and whether it
/// is an InputError (bad input, which a solver passes on) or a plain Error (a non-finite iterate,
/// which a solver answers with a shorter step).
struct Raised {
  std::string message;
  bool input_error = false;
};

template <class Call>
Raised raised(Call&& call) {
  try {
    call();
  } catch (const InputError& error) {
    return {error.what(), true};
  } catch (const Error& error) {
    return {error.what(), false};
  }
  return {};
}

}  // namespace

TEST_CASE("bad input to a joint's evaluations names the evaluation, the joint and the field",
          "[joints][errors]") {
  const core::Configuration q = three_blocks();
  const SparseLink link(1, 2);
  Eigen::VectorXd phi(2), c(2);
  Eigen::MatrixXd B(2, 8), K(8, 8);
  const Eigen::Vector2d lambda(1.0, 2.0);
  const Eigen::VectorXd velocity = Eigen::VectorXd::Zero(q.dof_count());

  struct Case {
    const char* name;
    Raised result;
    const char* evaluation;  ///< "value": the message names joints::Constraint::value
    const char* words;       ///< in the message, besides the evaluation and the joint's type
    bool input_error;
  };
  core::Configuration two_blocks;
  two_blocks.add_frame(Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity());
  two_blocks.add_vector(Eigen::Vector2d(0.7, -0.2));
  Eigen::VectorXd short_phi(1), long_c(3), short_lambda(1), long_velocity(q.dof_count() + 1);
  Eigen::MatrixXd B_six_per_block(2, 12), K_wide(8, 9);
  Eigen::VectorXd nan_velocity = velocity, nan_elsewhere = velocity;
  nan_velocity(q.blocks[2].offset + 4) = not_a_number;  // a rotation rate of the link's frame
  nan_elsewhere(2) = not_a_number;                      // block 0, not the link's
  const std::vector<Case> cases = {
      {"a configuration without block 2", raised([&] { link.value(two_blocks, 0.0, phi); }),
       "value", "the configuration has 2 blocks but the joint acts on block 2", true},
      {"a non-finite time", raised([&] { link.jacobian(q, not_a_number, B); }),
       "jacobian", "the time is nan", true},
      {"Φ of 1 entry", raised([&] { link.value(q, 0.0, short_phi); }),
       "value", "the output vector has 1 entries, expected 2", true},
      {"B sized 6 per block", raised([&] { link.jacobian(q, 0.0, B_six_per_block); }),
       "jacobian", "the Jacobian B is 2×12, expected 2×8", true},
      {"K not square", raised([&] { link.multiplier_tangent(q, 0.0, lambda, K_wide); }),
       "multiplier_tangent", "the multiplier tangent K is 8×9, expected 8×8", true},
      {"λ of 1 entry", raised([&] { link.multiplier_tangent(q, 0.0, short_lambda, K); }),
       "multiplier_tangent", "the multiplier vector has 1 entries, expected 2", true},
      {"a non-finite λ", raised([&] { link.multiplier_tangent(q, 0.0, Eigen::Vector2d(1.0, not_a_number), K); }),
       "multiplier_tangent", "the multiplier vector has a non-finite entry (nan) at index 1", false},
      {"a velocity of the wrong size", raised([&] { link.acceleration_terms(q, long_velocity, 0.0, c); }),
       "acceleration_terms", "the velocity vector has 15 entries, expected 14", true},
      {"a non-finite velocity at the joint's frame", raised([&] { link.acceleration_terms(q, nan_velocity, 0.0, c); }),
       "acceleration_terms", "the velocity vector has a non-finite entry (nan) at dof 12", false},
      {"c of 3 entries", raised([&] { link.acceleration_terms(q, velocity, 0.0, long_c); }),
       "acceleration_terms", "the output vector has 3 entries, expected 2", true},
      {"Φ_t of 1 entry", raised([&] { link.time_derivative(q, 0.0, short_phi); }),
       "time_derivative", "the output vector has 1 entries, expected 2", true},
  };
  for (const Case& bad : cases) {
    INFO(bad.name << ": " << bad.result.message);
    CHECK_THAT(bad.result.message, Catch::Contains(std::string("joints::Constraint::") + bad.evaluation + " (") &&
                                       Catch::Contains("SparseLink)") && Catch::Contains(bad.words));
    CHECK(bad.result.input_error == bad.input_error);
  }
  // A non-finite velocity of a block the joint does not read is none of its business.
  CHECK_NOTHROW(link.acceleration_terms(q, nan_elsewhere, 0.0, c));
}
