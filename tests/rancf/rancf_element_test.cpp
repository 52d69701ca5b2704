// The RANCF and ALE-RANCF cable elements (paper 000 §§2–3, docs/rancf.md): every Jacobian against
// central differences, the inertial force against the Euler–Lagrange equations of the element's
// own kinetic energy, equal weights against an independent plain ANCF cable, and the ALE element
// with fixed material coordinates against the fixed-length element.
#include <spar/elements/cable/rancf_cable_element.hpp>
#include <spar/error.hpp>
#include <spar/iga/quadrature.hpp>
#include <spar/iga/rational_bezier.hpp>

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include "rancf_fixtures.hpp"

using namespace spar;

namespace {

const Eigen::Vector3d gravity(0.3, -9.81, 0.7);
const Eigen::Vector4d uneven_weights(1.0, 0.8, 1.3, 0.9);

template <int Dim>
void check_fixed_stiffness() {
  for (const Eigen::Vector4d& w : {Eigen::Vector4d::Ones().eval(), uneven_weights}) {
    const test::RancfState s = test::random_rancf_state<Dim>(7, w, false);
    const core::RancfCableElement<Dim> element(s.parameters);
    INFO("Dim " << Dim << ", weights " << w.transpose());
    test::check_rancf_derivatives(element, s, gravity, true);
    // In statics K is the Hessian of the strain energy: symmetric to round-off.
    const core::ElementOutput statics = test::evaluate_all(element, s.q, nullptr, nullptr, gravity);
    CHECK((statics.stiffness - statics.stiffness.transpose()).cwiseAbs().maxCoeff() <=
          1e-12 * statics.stiffness.cwiseAbs().maxCoeff());
  }
}

template <int Dim>
void check_ale_jacobians(bool dynamic) {
  for (const Eigen::Vector4d& w : {Eigen::Vector4d::Ones().eval(), uneven_weights}) {
    const test::RancfState s = test::random_rancf_state<Dim>(11, w, true);
    const core::AleRancfCableElement<Dim> element(s.parameters);
    INFO("Dim " << Dim << ", weights " << w.transpose() << ", dynamic " << dynamic);
    test::check_rancf_derivatives(element, s, gravity, dynamic);
  }
}

}  // namespace

TEST_CASE("RANCF cable: stiffness and mass against central differences", "[rancf]") {
  check_fixed_stiffness<2>();
  check_fixed_stiffness<3>();
}

TEST_CASE("ALE-RANCF cable: stiffness, damping and mass against central differences", "[rancf]") {
  for (bool dynamic : {false, true}) {
    check_ale_jacobians<2>(dynamic);
    check_ale_jacobians<3>(dynamic);
  }
}

namespace {

/// The inertial part of the ALE residual must be d/dt(∂T/∂v) − ∂T/∂q of the kinetic energy the
/// element reports (docs/rancf.md eq. R11): ∂T/∂v = M(q) v with the element's own M, its time
/// derivative by central differences along q(t) = q + t v + t²a/2, v(t) = v + t a, and ∂T/∂q by
/// central differences of T.
template <int Dim>
void check_euler_lagrange() {
  test::RancfState s = test::random_rancf_state<Dim>(3, uneven_weights, true);
  s.parameters.section.damping_coefficient = 0.0;  // inertia alone
  const core::AleRancfCableElement<Dim> element(s.parameters);
  const Eigen::Vector3d no_gravity = Eigen::Vector3d::Zero();
  const auto out_at = [&](const core::Configuration& q, const Eigen::VectorXd& v) {
    return test::evaluate_all(element, q, &v, &s.a, no_gravity);
  };
  const core::ElementOutput at_rest_static = test::evaluate_all(element, s.q, nullptr, nullptr, no_gravity);
  const core::ElementOutput out = out_at(s.q, s.v);
  const Eigen::VectorXd inertia = out.residual - at_rest_static.residual;
  const double h = 1e-5;
  const int n = s.q.dof_count();
  Eigen::VectorXd momentum_rate = Eigen::VectorXd::Zero(n), dT_dq(n);
  for (double side : {1.0, -1.0}) {
    core::Configuration q = s.q;
    const double t = side * h;
    q.values += t * s.v + 0.5 * t * t * s.a;
    const Eigen::VectorXd v = s.v + t * s.a;
    momentum_rate += side * out_at(q, v).mass * v / (2 * h);
  }
  for (int j = 0; j < n; ++j) {
    double T[2];
    for (int side = 0; side < 2; ++side) {
      core::Configuration q = s.q;
      q.values(j) += side == 0 ? h : -h;
      T[side] = out_at(q, s.v).energy.kinetic;
    }
    dT_dq(j) = (T[0] - T[1]) / (2 * h);
  }
  const Eigen::VectorXd expected = momentum_rate - dT_dq;
  INFO("Dim " << Dim << "\ninertia  " << inertia.transpose() << "\nexpected " << expected.transpose());
  // h = 1e-5: truncation ~h² = 1e-10 relative, round-off ~1e-16/1e-5; 1e-7 as above.
  CHECK((inertia - expected).cwiseAbs().maxCoeff() <= 1e-7 * expected.cwiseAbs().maxCoeff());
  // T = ½ vᵀ M v.
  CHECK(std::fabs(out.energy.kinetic - 0.5 * s.v.dot(out.mass * s.v)) <= 1e-13 * out.energy.kinetic);
}

}  // namespace

TEST_CASE("ALE-RANCF cable: inertial force = Euler-Lagrange of its kinetic energy", "[rancf]") {
  check_euler_lagrange<2>();
  check_euler_lagrange<3>();
}

namespace {

/// An independent plain ANCF cable (Gerstmayr & Shabana; 000 eq. (10)): cubic Hermite shape
/// functions in x, ε = (r_xᵀr_x − 1)/2, κ² = |r_x × r_xx|²/|r_x|⁶, integrated by the same Gauss
/// rule. Residual (statics + gravity), mass matrix and energies.
template <int Dim>
struct PlainAncf {
  Eigen::VectorXd residual;
  Eigen::MatrixXd mass;
  double strain = 0.0, gravity = 0.0;
};

template <int Dim>
Eigen::Matrix<double, 3, 1> lift(const Eigen::Matrix<double, Dim, 1>& x) {
  Eigen::Vector3d y = Eigen::Vector3d::Zero();
  y.head<Dim>() = x;
  return y;
}

template <int Dim>
PlainAncf<Dim> plain_ancf(const Eigen::VectorXd& e, double l, const core::RancfSection& section,
                          const Eigen::Vector3d& g3, int points) {
  using Shape = Eigen::Matrix<double, Dim, 4 * Dim>;
  const Eigen::Matrix<double, Dim, 1> g = g3.head<Dim>();
  PlainAncf<Dim> out{Eigen::VectorXd::Zero(4 * Dim), Eigen::MatrixXd::Zero(4 * Dim, 4 * Dim)};
  const iga::GaussRule rule = iga::gauss_legendre(points);
  for (std::size_t i = 0; i < rule.points.size(); ++i) {
    const double xi = 0.5 * (rule.points[i] + 1.0), dx = 0.5 * rule.weights[i] * l;
    const Eigen::Vector4d s(1 - 3 * xi * xi + 2 * xi * xi * xi, l * (xi - 2 * xi * xi + xi * xi * xi),
                            3 * xi * xi - 2 * xi * xi * xi, l * (-xi * xi + xi * xi * xi));
    const Eigen::Vector4d s_x((-6 * xi + 6 * xi * xi) / l, 1 - 4 * xi + 3 * xi * xi,
                              (6 * xi - 6 * xi * xi) / l, -2 * xi + 3 * xi * xi);
    const Eigen::Vector4d s_xx((-6 + 12 * xi) / (l * l), (-4 + 6 * xi) / l, (6 - 12 * xi) / (l * l),
                               (-2 + 6 * xi) / l);
    Shape S, S_x, S_xx;
    for (int k = 0; k < 4; ++k) {
      S.template middleCols<Dim>(k * Dim) = s(k) * Eigen::Matrix<double, Dim, Dim>::Identity();
      S_x.template middleCols<Dim>(k * Dim) = s_x(k) * Eigen::Matrix<double, Dim, Dim>::Identity();
      S_xx.template middleCols<Dim>(k * Dim) = s_xx(k) * Eigen::Matrix<double, Dim, Dim>::Identity();
    }
    const Eigen::Matrix<double, Dim, 1> r = S * e, r_x = S_x * e, r_xx = S_xx * e;
    const double f = r_x.squaredNorm(), eps = 0.5 * (f - 1.0);
    const Eigen::Vector3d c = lift<Dim>(r_x).cross(lift<Dim>(r_xx));
    // ∂c/∂r_x = −[r_xx]×, ∂c/∂r_xx = [r_x]× (3D; the 2D case is the z-row).
    const Eigen::Vector3d dc_drx_c = lift<Dim>(r_xx).cross(c), dc_drxx_c = c.cross(lift<Dim>(r_x));
    const double k2 = c.squaredNorm() / (f * f * f);
    out.residual += dx * (section.axial_stiffness * eps * S_x.transpose() * r_x +
                          section.bending_stiffness * (S_x.transpose() * dc_drx_c.head<Dim>() / (f * f * f) +
                                                 S_xx.transpose() * dc_drxx_c.head<Dim>() / (f * f * f) -
                                                 3 * k2 / f * S_x.transpose() * r_x) -
                          section.mass_per_length * S.transpose() * g);
    out.mass += dx * section.mass_per_length * S.transpose() * S;
    out.strain += dx * 0.5 * (section.axial_stiffness * eps * eps + section.bending_stiffness * k2);
    out.gravity -= dx * section.mass_per_length * g.dot(r);
  }
  return out;
}

template <int Dim>
void check_against_plain_ancf() {
  // Weights all equal to 1.7, not 1: eq. (10) holds for any common value.
  test::RancfState s = test::random_rancf_state<Dim>(5, Eigen::Vector4d::Constant(1.7), false);
  s.parameters.section.damping_coefficient = 0.0;  // the reference is undamped
  const core::RancfCableElement<Dim> element(s.parameters);
  const core::ElementOutput out = test::evaluate_all(element, s.q, &s.v, &s.a, gravity);
  const PlainAncf<Dim> reference = plain_ancf<Dim>(s.q.values, s.parameters.length, s.parameters.section,
                                                   gravity, s.parameters.quadrature_points);
  const Eigen::VectorXd residual = out.residual - out.mass * s.a;  // statics + gravity
  INFO("Dim " << Dim);
  // Round-off: both sum the same ~40 terms of size ≤ max|r| per entry in different orders and
  // the rational shape functions carry a division by W(u) = 1.7: a few 1e-16 relative; 1e-13.
  CHECK((residual - reference.residual).cwiseAbs().maxCoeff() <=
        1e-13 * reference.residual.cwiseAbs().maxCoeff());
  CHECK((out.mass - reference.mass).cwiseAbs().maxCoeff() <= 1e-13 * reference.mass.cwiseAbs().maxCoeff());
  CHECK(std::fabs(out.energy.strain - reference.strain) <= 1e-13 * reference.strain);
  CHECK(std::fabs(out.energy.gravity - reference.gravity) <= 1e-13 * std::fabs(reference.gravity));
}

}  // namespace

TEST_CASE("RANCF cable with equal weights is the plain ANCF cable (000 eq. (10))", "[rancf]") {
  check_against_plain_ancf<2>();
  check_against_plain_ancf<3>();
}

namespace {

template <int Dim>
void check_ale_at_rest_equals_fixed() {
  test::RancfState s = test::random_rancf_state<Dim>(9, uneven_weights, true);
  const int n = 4 * Dim;
  // Material coordinates at rest: ẋ_A = ẋ_B = ẍ_A = ẍ_B = 0.
  s.v.tail<2>().setZero();
  s.a.tail<2>().setZero();
  core::RancfCableParameters fixed_parameters = s.parameters;
  fixed_parameters.length = s.q.values(n + 1) - s.q.values(n);
  const core::AleRancfCableElement<Dim> ale(s.parameters);
  const core::RancfCableElement<Dim> fixed(fixed_parameters);
  core::Configuration fixed_q;
  fixed_q.add_vector(s.q.vector(0));
  fixed_q.add_vector(s.q.vector(1));
  const Eigen::VectorXd v = s.v.head(n), a = s.a.head(n);
  const core::ElementOutput A = test::evaluate_all(ale, s.q, &s.v, &s.a, gravity);
  const core::ElementOutput F = test::evaluate_all(fixed, fixed_q, &v, &a, gravity);
  INFO("Dim " << Dim);
  // Same kernel arithmetic except l = x_B − x_A (exact) and the ALE terms multiplied by ẋ = 0:
  // round-off, 1e-13 relative.
  CHECK((A.residual.head(n) - F.residual).cwiseAbs().maxCoeff() <= 1e-13 * F.residual.cwiseAbs().maxCoeff());
  CHECK((A.stiffness.topLeftCorner(n, n) - F.stiffness).cwiseAbs().maxCoeff() <=
        1e-13 * F.stiffness.cwiseAbs().maxCoeff());
  CHECK((A.mass.topLeftCorner(n, n) - F.mass).cwiseAbs().maxCoeff() <= 1e-13 * F.mass.cwiseAbs().maxCoeff());
  CHECK(std::fabs(A.energy.kinetic - F.energy.kinetic) <= 1e-13 * F.energy.kinetic);
  CHECK(std::fabs(A.energy.strain - F.energy.strain) <= 1e-13 * F.energy.strain);
  CHECK(std::fabs(A.energy.gravity - F.energy.gravity) <= 1e-13 * std::fabs(F.energy.gravity));
}

}  // namespace

TEST_CASE("ALE-RANCF with fixed material coordinates is the fixed-length element", "[rancf]") {
  check_ale_at_rest_equals_fixed<2>();
  check_ale_at_rest_equals_fixed<3>();
}

TEST_CASE("RANCF elements reject invalid parameters and inverted elements", "[rancf]") {
  test::RancfState s = test::random_rancf_state<2>(1, uneven_weights, true);
  core::RancfCableParameters p = s.parameters;
  p.weights(2) = 0.0;
  CHECK_THROWS_AS(core::RancfCableElement<2>{p}, Error);
  p = s.parameters;
  p.quadrature_points = 1;
  CHECK_THROWS_AS(core::AleRancfCableElement<2>{p}, Error);
  p = s.parameters;
  p.material_b = -1;
  CHECK_THROWS_AS(core::AleRancfCableElement<2>{p}, Error);
  const core::AleRancfCableElement<2> element(s.parameters);
  s.q.values(9) = s.q.values(8) - 0.1;  // x_B < x_A
  CHECK_THROWS_AS(test::evaluate_all(element, s.q, &s.v, &s.a, gravity), Error);
}

namespace {

/// ε and the curvature vector k at material coordinate x (000 eqs. (12)–(13), (19)).
template <int Dim>
Eigen::Vector4d strains_at(const Eigen::VectorXd& q, const Eigen::Vector4d& w, double x) {
  const double x_a = q(4 * Dim), l = q(4 * Dim + 1) - x_a, u = (x - x_a) / l;
  const Eigen::Matrix4d sh = iga::rancf_shape_function_derivatives(u, w);
  Eigen::Vector3d r_u = Eigen::Vector3d::Zero(), r_uu = Eigen::Vector3d::Zero();
  for (int k = 0; k < 4; ++k) {
    const double scale = k % 2 == 1 ? l : 1.0;
    r_u.head<Dim>() += scale * sh(k, 1) * q.segment<Dim>(k * Dim);
    r_uu.head<Dim>() += scale * sh(k, 2) * q.segment<Dim>(k * Dim);
  }
  const double s = r_u.squaredNorm();
  Eigen::Vector4d out;
  out << 0.5 * (s / (l * l) - 1.0), r_u.cross(r_uu) / (s * std::sqrt(s));
  return out;
}

/// The Kelvin–Voigt force as ∂D/∂q̇ of D = ½ c l Σ_g w_g (EA ε̇² + EI |k̇|²), with the rates of
/// ε and k at the material points under the Gauss points by central differences in time along
/// q + t q̇ (independent of the element's formulas), and ∂D/∂q̇ by central differences (D is
/// quadratic in q̇: exact but for the inner differences).
template <int Dim>
Eigen::VectorXd viscous_reference(const test::RancfState& s) {
  const core::RancfSection& c = s.parameters.section;
  const iga::GaussRule rule = iga::gauss_legendre(s.parameters.quadrature_points);
  const double x_a = s.q.values(4 * Dim), l = s.q.values(4 * Dim + 1) - x_a;
  const auto dissipation = [&](const Eigen::VectorXd& rates) {
    double D = 0.0;
    for (std::size_t g = 0; g < rule.points.size(); ++g) {
      const double x = x_a + l * 0.5 * (rule.points[g] + 1.0), h = 1e-6;
      const Eigen::Vector4d rate = (strains_at<Dim>(s.q.values + h * rates, s.parameters.weights, x) -
                                    strains_at<Dim>(s.q.values - h * rates, s.parameters.weights, x)) / (2 * h);
      D += 0.5 * c.damping_coefficient * l * 0.5 * rule.weights[g] *
           (c.axial_stiffness * rate(0) * rate(0) + c.bending_stiffness * rate.tail<3>().squaredNorm());
    }
    return D;
  };
  Eigen::VectorXd f(s.v.size());
  for (int j = 0; j < s.v.size(); ++j) {
    Eigen::VectorXd plus = s.v, minus = s.v;
    plus(j) += 1.0;
    minus(j) -= 1.0;
    f(j) = (dissipation(plus) - dissipation(minus)) / 2.0;
  }
  return f;
}

template <int Dim>
void check_viscous_force() {
  test::RancfState s = test::random_rancf_state<Dim>(13, uneven_weights, true);
  const core::AleRancfCableElement<Dim> damped(s.parameters);
  test::RancfState undamped_state = s;
  undamped_state.parameters.section.damping_coefficient = 0.0;
  const core::AleRancfCableElement<Dim> undamped(undamped_state.parameters);
  const Eigen::VectorXd viscous = test::evaluate_all(damped, s.q, &s.v, &s.a, gravity).residual -
                                  test::evaluate_all(undamped, s.q, &s.v, &s.a, gravity).residual;
  const Eigen::VectorXd reference = viscous_reference<Dim>(s);
  INFO("Dim " << Dim << "\nviscous   " << viscous.transpose() << "\nreference " << reference.transpose());
  // Inner central differences with h = 1e-6 on O(1) strains: ~1e-10 truncation, ~1e-10
  // round-off, amplified by the unit outer step; 1e-6 relative is far below a wrong term.
  CHECK((viscous - reference).cwiseAbs().maxCoeff() <= 1e-6 * reference.cwiseAbs().maxCoeff());
  CHECK(s.v.dot(viscous) > 0.0);  // dissipates
}

}  // namespace

TEST_CASE("ALE-RANCF Kelvin-Voigt force: rates at fixed material points (000 eq. (17))", "[rancf]") {
  check_viscous_force<2>();
  check_viscous_force<3>();
}
