// q ⊖ q₀ (Configuration::increment_from), the inverse of q ⊕ Δ (docs/model.md eq. M1): round
// trips both ways on mixed layouts of frames and vector blocks, relative turns near and at π.
#include <spar/core/configuration.hpp>
#include <spar/error.hpp>
#include <spar/lie/exp.hpp>

#include "random_rotations.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

using namespace spar;

namespace {

constexpr double epsilon = std::numeric_limits<double>::epsilon();

Eigen::Vector3d random_vector(test::RandomRotations& random, double size) {
  return Eigen::Vector3d(random.uniform(-size, size), random.uniform(-size, size), random.uniform(-size, size));
}

/// Frames and vector blocks interleaved (vector blocks of 1, 3 and 12 entries), positions and
/// coordinates up to `size`, rotations anywhere.
core::Configuration random_configuration(test::RandomRotations& random, double size) {
  core::Configuration q;
  for (int k = 0; k < 3; ++k) {
    q.add_frame(random_vector(random, size), lie::exp(random.rotation_vector()));
    q.add_vector(Eigen::VectorXd::NullaryExpr(k == 2 ? 12 : 2 * k + 1, [&] { return random.uniform(-size, size); }));
  }
  q.add_frame(random_vector(random, size), lie::exp(random.rotation_vector()));
  return q;
}

/// q moved by any amount: frames turned relative to q by a rotation vector of `random` (one in four
/// within 1e-10 of π, one in four near 0), positions and coordinates anywhere within `size`.
core::Configuration moved(const core::Configuration& q, test::RandomRotations& random, double size) {
  core::Configuration p = q;
  for (int b = 0; b < q.block_count(); ++b) {
    if (q.is_frame(b)) {
      p.position[b] = random_vector(random, size);
      p.rotation[b] = q.rotation[b] * lie::exp(random.rotation_vector());
    } else {
      for (Eigen::Index i = 0; i < p.vector(b).size(); ++i) p.vector(b)(i) = random.uniform(-size, size);
    }
  }
  return p;
}

/// The largest difference of two configurations of one layout: max |x − x'| over entries of
/// positions and vector coordinates, and max ‖R − R'‖_F over frames.
struct Gap {
  double coordinates = 0.0, rotations = 0.0;
};

Gap gap(const core::Configuration& a, const core::Configuration& b) {
  Gap g;
  for (int k = 0; k < a.block_count(); ++k) {
    if (a.is_frame(k)) {
      g.coordinates = std::max(g.coordinates, (a.position[k] - b.position[k]).cwiseAbs().maxCoeff());
      g.rotations = std::max(g.rotations, (a.rotation[k] - b.rotation[k]).norm());
    } else {
      g.coordinates = std::max(g.coordinates, (a.vector(k) - b.vector(k)).cwiseAbs().maxCoeff());
    }
  }
  return g;
}

}  // namespace

TEST_CASE("q0 + (q1 - q0) = q1 to round-off, relative turns near pi included", "[core][configuration]") {
  // Positions and coordinates up to 10: x0 + (x1 − x0) rounds twice, at most 2 ulps of 10 with
  // the bits x1 − x0 loses, so 4 ε · 10. Rotations: R0 exp(log(R0ᵀ R1)) against R1 is
  // exp(log(R)) = R, which holds to 1e-14 (tests/lie/exp_log_test.cpp), for R = R0ᵀ R1 and times
  // R0, two 3 × 3 products of a few ulps each (2.7e-15 measured); also where R0ᵀR1 turns by
  // π − 1e-10 (log through the quaternion keeps its digits there).
  const double size = 10.0;
  test::RandomRotations random(30);
  Gap worst;
  for (int trial = 0; trial < 2000; ++trial) {
    const core::Configuration q0 = random_configuration(random, size);
    const core::Configuration q1 = moved(q0, random, size);
    core::Configuration back = q0;
    back.assign_increment(q0, q1.increment_from(q0));
    const Gap g = gap(back, q1);
    worst.coordinates = std::max(worst.coordinates, g.coordinates);
    worst.rotations = std::max(worst.rotations, g.rotations);
  }
  INFO("worst coordinate gap " << worst.coordinates << ", worst rotation gap " << worst.rotations);
  CHECK(worst.coordinates <= 4 * epsilon * size);
  CHECK(worst.rotations <= 1e-14);
}

TEST_CASE("a relative turn of exactly pi comes back as a turn of pi that lands on q1", "[core][configuration]") {
  // At π both ±Θ are logs of R0ᵀR1 (lie::log picks one): the difference has angle π and either
  // sign leads back to q1. The axis (1, 2, −2)/3 is exact to round-off in exp.
  test::RandomRotations random(31);
  const core::Configuration q0 = random_configuration(random, 1.0);
  core::Configuration q1 = q0;
  const Eigen::Vector3d axis = Eigen::Vector3d(1, 2, -2) / 3.0;
  for (int b = 0; b < q1.block_count(); ++b)
    if (q1.is_frame(b)) q1.rotation[b] = q0.rotation[b] * lie::exp(std::numbers::pi * axis);
  const Eigen::VectorXd delta = q1.increment_from(q0);
  core::Configuration back = q0;
  back.assign_increment(q0, delta);
  for (int b = 0; b < q1.block_count(); ++b)
    if (q1.is_frame(b)) {
      const Eigen::Vector3d phi = delta.segment<3>(q1.blocks[b].offset + 3);
      CHECK(std::fabs(phi.norm() - std::numbers::pi) <= 4 * epsilon * std::numbers::pi);
      CHECK(std::fabs(std::fabs(phi.normalized().dot(axis)) - 1.0) <= 4 * epsilon);
    }
  CHECK(gap(back, q1).rotations <= 1e-14);  // as in the round trip above
  CHECK(gap(back, q1).coordinates == 0.0);
}

TEST_CASE("(q0 + delta) - q0 = delta to round-off for rotation increments below pi", "[core][configuration]") {
  // The inverse holds inside the chart, |Δφ| < π (docs/model.md eq. M2); RandomRotations puts one
  // increment in four within 1e-10 of π. Rotations: log(R0ᵀ R0 exp(Δφ)) against Δφ is
  // lie::log(exp(θ)) − θ (≤ 1e-14 (|θ| + 1), tests/lie/exp_log_test.cpp) with the round-off of
  // R0ᵀR0 = I + O(ε) on top, which moves the angle by O(ε) even at π − 1e-10 (2 atan2(|v|, w) is
  // well conditioned there). Positions and coordinates: (x + Δ) − x rounds twice, 4 ε (|x| + |Δ|).
  const double size = 10.0;
  test::RandomRotations random(32);
  double worst_rotation = 0.0, worst_coordinate = 0.0;
  for (int trial = 0; trial < 2000; ++trial) {
    const core::Configuration q0 = random_configuration(random, size);
    Eigen::VectorXd delta(q0.dof_count());
    for (int b = 0; b < q0.block_count(); ++b) {
      const core::Block& block = q0.blocks[b];
      for (int i = 0; i < block.size; ++i) delta(block.offset + i) = random.uniform(-size, size);
      if (q0.is_frame(b)) delta.segment<3>(block.offset + 3) = random.rotation_vector();
    }
    core::Configuration q1 = q0;
    q1.apply_increment(delta);
    const Eigen::VectorXd back = q1.increment_from(q0);
    for (int b = 0; b < q0.block_count(); ++b) {
      const core::Block& block = q0.blocks[b];
      if (q0.is_frame(b)) {
        const Eigen::Vector3d phi = delta.segment<3>(block.offset + 3);
        worst_rotation =
            std::max(worst_rotation, (back.segment<3>(block.offset + 3) - phi).norm() / (phi.norm() + 1.0));
        worst_coordinate = std::max(worst_coordinate,
                                    (back.segment<3>(block.offset) - delta.segment<3>(block.offset)).cwiseAbs().maxCoeff());
      } else {
        worst_coordinate = std::max(
            worst_coordinate,
            (back.segment(block.offset, block.size) - delta.segment(block.offset, block.size)).cwiseAbs().maxCoeff());
      }
    }
  }
  INFO("worst rotation error " << worst_rotation << ", worst coordinate error " << worst_coordinate);
  CHECK(worst_rotation <= 1e-14);
  CHECK(worst_coordinate <= 4 * epsilon * 2 * size);
}

TEST_CASE("q - q0 refuses configurations of different layouts", "[core][configuration][errors]") {
  core::Configuration a, b, c;
  a.add_frame(Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity());
  b.add_frame(Eigen::Vector3d::Zero(), Eigen::Matrix3d::Identity());
  b.add_vector(Eigen::VectorXd::Ones(2));
  c.add_vector(Eigen::VectorXd::Zero(6));  // a frame's dof count, another kind of block
  CHECK_THROWS_AS(a.increment_from(b), Error);
  CHECK_THROWS_WITH(b.increment_from(a), Catch::Contains("layout"));
  CHECK_THROWS_WITH(a.increment_from(c), Catch::Contains("layout"));
  CHECK(a.increment_from(a) == Eigen::VectorXd::Zero(6));
}
