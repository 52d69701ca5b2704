// The tangent operator T, its inverse and their first and second directional derivatives:
// each against central finite differences of its definition, computed in long double so that
// the check is ~1e-10 sharp, and against the identities that tie them together.
#include <spar/lie/exp.hpp>
#include <spar/lie/log.hpp>
#include <spar/lie/tangent.hpp>

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <vector>

#include "random_rotations.hpp"
#include "tolerances.hpp"

using namespace spar;
using Vector3L = Eigen::Matrix<long double, 3, 1>;
using Matrix3L = Eigen::Matrix<long double, 3, 3>;

namespace {

// Angles of the issue: both sides of every switch point, near 0 and near π.
const std::vector<double> angles = {0.0, 1e-12, 1e-8, 1e-6, 1e-4, 1e-2, 0.25, 0.5,
                                    1.0, 2.0,   2.25, 3.0,  std::numbers::pi - 1e-6};

// Central differences in long double: step 1e-6 gives truncation ~1e-13 and round-off ~1e-13.
constexpr long double fd_step = 1e-6L;
// Tolerance of a long double central difference against an analytic double result.
constexpr double fd_tolerance = 1e-10;

template <class F>
Matrix3L central_difference(F&& f, const Vector3L& theta) {
  Matrix3L J;
  for (int i = 0; i < 3; ++i) {
    Vector3L plus = theta, minus = theta;
    plus(i) += fd_step;
    minus(i) -= fd_step;
    J.col(i) = (f(plus) - f(minus)) / (2 * fd_step);
  }
  return J;
}

double relative_difference(const Eigen::Matrix3d& analytic, const Matrix3L& reference) {
  const long double scale = std::max(reference.norm(), 1.0L);
  return static_cast<double>((analytic.cast<long double>() - reference).norm() / scale);
}

std::vector<Eigen::Vector3d> sample_rotation_vectors() {
  test::RandomRotations random(11);
  std::vector<Eigen::Vector3d> samples;
  for (double angle : angles)
    for (int k = 0; k < 3; ++k) samples.push_back(angle * random.axis());
  for (int k = 0; k < 20; ++k) samples.push_back(random.rotation_vector());
  return samples;
}

}  // namespace

TEST_CASE("tangent is the right-trivialized differential of exp", "[lie][tangent]") {
  // exp(Θ + δ) = exp(Θ) exp(T(Θ) δ) + O(δ²): the column i of T is d/dε log(exp(Θ)ᵀ exp(Θ + ε eᵢ)).
  for (const Eigen::Vector3d& theta : sample_rotation_vectors()) {
    const Vector3L theta_l = theta.cast<long double>();
    const Matrix3L R_transpose = lie::exp(theta_l).transpose();
    const Matrix3L reference = central_difference(
        [&](const Vector3L& t) { return Vector3L(lie::log(Matrix3L(R_transpose * lie::exp(t)))); },
        theta_l);
    INFO("theta = " << theta.transpose());
    CHECK(relative_difference(lie::tangent(theta), reference) <= fd_tolerance);
  }
}

TEST_CASE("tangent satisfies T theta = theta, T^T = T(-theta), exp(theta) T = T^T",
          "[lie][tangent]") {
  for (const Eigen::Vector3d& theta : sample_rotation_vectors()) {
    const Eigen::Matrix3d T = lie::tangent(theta);
    INFO("theta = " << theta.transpose());
    CHECK((T * theta - theta).norm() <= 1e-15 * (1 + theta.norm()));
    CHECK((T.transpose() - lie::tangent(Eigen::Vector3d(-theta))).norm() <= 1e-15);
    CHECK((lie::exp(theta) * T - T.transpose()).norm() <= 2e-15);
  }
}

TEST_CASE("tangent and its inverse are exact to round-off against long double", "[lie][tangent]") {
  for (const Eigen::Vector3d& theta : sample_rotation_vectors()) {
    const Vector3L theta_l = theta.cast<long double>();
    INFO("theta = " << theta.transpose());
    CHECK(relative_difference(lie::tangent(theta), lie::tangent(theta_l)) <= 1e-15);
    CHECK(relative_difference(lie::tangent_inverse(theta), lie::tangent_inverse(theta_l)) <= 1e-15);
  }
}

TEST_CASE("tangent_inverse times tangent is the identity to 1e-13", "[lie][tangent]") {
  for (const Eigen::Vector3d& theta : sample_rotation_vectors()) {
    INFO("theta = " << theta.transpose());
    const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
    CHECK((lie::tangent_inverse(theta) * lie::tangent(theta) - I).norm() <= 1e-13);
    CHECK((lie::tangent(theta) * lie::tangent_inverse(theta) - I).norm() <= 1e-13);
  }
}

TEST_CASE("exp_and_tangent equals exp and tangent", "[lie][tangent]") {
  for (const Eigen::Vector3d& theta : sample_rotation_vectors()) {
    const auto both = lie::exp_and_tangent(theta);
    CHECK((both.rotation - lie::exp(theta)).norm() <= 1e-15);
    CHECK((both.tangent - lie::tangent(theta)).norm() <= 1e-15);
  }
}

TEST_CASE("first derivatives of T a, T^T a, T^-1 a, T^-T a match finite differences",
          "[lie][tangent]") {
  const Eigen::Vector3d a(0.7, -1.3, 0.4);
  const Vector3L a_l = a.cast<long double>();
  for (const Eigen::Vector3d& theta : sample_rotation_vectors()) {
    const Vector3L theta_l = theta.cast<long double>();
    INFO("theta = " << theta.transpose());
    CHECK(relative_difference(
              lie::tangent_derivative(theta, a),
              central_difference([&](const Vector3L& t) { return Vector3L(lie::tangent(t) * a_l); },
                                 theta_l)) <= fd_tolerance);
    CHECK(relative_difference(lie::tangent_transpose_derivative(theta, a),
                              central_difference(
                                  [&](const Vector3L& t) {
                                    return Vector3L(lie::tangent(t).transpose() * a_l);
                                  },
                                  theta_l)) <= fd_tolerance);
    CHECK(relative_difference(lie::tangent_inverse_derivative(theta, a),
                              central_difference(
                                  [&](const Vector3L& t) {
                                    return Vector3L(lie::tangent_inverse(t) * a_l);
                                  },
                                  theta_l)) <= fd_tolerance);
    CHECK(relative_difference(lie::tangent_inverse_transpose_derivative(theta, a),
                              central_difference(
                                  [&](const Vector3L& t) {
                                    return Vector3L(lie::tangent_inverse(t).transpose() * a_l);
                                  },
                                  theta_l)) <= fd_tolerance);
  }
}

TEST_CASE("second derivatives of T a and T^T a match finite differences", "[lie][tangent]") {
  // H(Θ; a, b) = ∂/∂Θ [ (∂(T a)/∂Θ) b ]: for b = Θ′ this is the derivative of T′a, the paper's H.
  const Eigen::Vector3d a(0.7, -1.3, 0.4), b(-0.2, 0.9, 1.1);
  const Vector3L a_l = a.cast<long double>(), b_l = b.cast<long double>();
  for (const Eigen::Vector3d& theta : sample_rotation_vectors()) {
    const Vector3L theta_l = theta.cast<long double>();
    INFO("theta = " << theta.transpose());
    CHECK(relative_difference(lie::tangent_second_derivative(theta, a, b),
                              central_difference(
                                  [&](const Vector3L& t) {
                                    return Vector3L(lie::tangent_derivative(t, a_l) * b_l);
                                  },
                                  theta_l)) <= fd_tolerance);
    CHECK(relative_difference(lie::tangent_transpose_second_derivative(theta, a, b),
                              central_difference(
                                  [&](const Vector3L& t) {
                                    return Vector3L(lie::tangent_transpose_derivative(t, a_l) * b_l);
                                  },
                                  theta_l)) <= fd_tolerance);
  }
}

TEST_CASE("tangent_hessian is the symmetric Hessian of m^T T(theta) b", "[lie][tangent]") {
  // Checked against central differences of its gradient ∂(mᵀT b)/∂Θ = tangent_derivative(Θ, b)ᵀ m.
  const Eigen::Vector3d m(0.7, -1.3, 0.4), b(-0.2, 0.9, 1.1);
  const Vector3L m_l = m.cast<long double>(), b_l = b.cast<long double>();
  for (const Eigen::Vector3d& theta : sample_rotation_vectors()) {
    const Eigen::Matrix3d H = lie::tangent_hessian(theta, m, b);
    INFO("theta = " << theta.transpose());
    CHECK((H - H.transpose()).norm() <= test::round_off_3x3);
    CHECK(relative_difference(H, central_difference(
                                     [&](const Vector3L& t) {
                                       return Vector3L(lie::tangent_derivative(t, b_l).transpose() * m_l);
                                     },
                                     Vector3L(theta.cast<long double>()))) <= fd_tolerance);
  }
}

TEST_CASE("tangent_gradient is tangent_derivative(theta, b)^T m without the matrix", "[lie][tangent]") {
  // The same coefficient functions contracted in another order: equal to round-off on every
  // sample angle (near 0, both sides of each series switch, near pi), and against long-double
  // central differences of mᵀ T(Θ) b.
  const Eigen::Vector3d m(0.7, -1.3, 0.4), b(-0.2, 0.9, 1.1);
  const Vector3L m_l = m.cast<long double>(), b_l = b.cast<long double>();
  for (const Eigen::Vector3d& theta : sample_rotation_vectors()) {
    INFO("theta = " << theta.transpose());
    const Eigen::Vector3d g = lie::tangent_gradient(theta, m, b);
    const Eigen::Vector3d reference = lie::tangent_derivative(theta, b).transpose() * m;
    CHECK((g - reference).norm() <= 1e-14 * std::max(1.0, reference.norm()));
    Vector3L fd;
    for (int i = 0; i < 3; ++i) {
      Vector3L plus = theta.cast<long double>(), minus = plus;
      plus(i) += fd_step;
      minus(i) -= fd_step;
      fd(i) = (m_l.dot(lie::tangent(plus) * b_l) - m_l.dot(lie::tangent(minus) * b_l)) / (2 * fd_step);
    }
    CHECK(static_cast<double>((g.cast<long double>() - fd).norm() / std::max(fd.norm(), 1.0L)) <= fd_tolerance);
  }
}

TEST_CASE("tangent_inverse refuses angles of 2 pi and beyond", "[lie][tangent][errors]") {
  const Eigen::Vector3d full_turn(2 * std::numbers::pi, 0.0, 0.0);
  CHECK_THROWS_AS(lie::tangent_inverse(full_turn), Error);
  CHECK_THROWS_WITH(lie::tangent_inverse(full_turn), Catch::Contains("singular"));
  CHECK_NOTHROW(lie::tangent_inverse(Eigen::Vector3d(6.0, 0.0, 0.0)));
}
