#pragma once
// The shared kernel of the RANCF and ALE-RANCF cable elements (paper 000; docs/rancf.md): the
// quadrature table, the field r(u) and its derivatives, the strain energy and the gravity
// potential with their gradients in (e, l), and the inertial force of a material point whose
// element moves through the material (ALE). Templated on the scalar so the elements can evaluate
// it with dual numbers (core/dual.hpp) for their exact Jacobians.

#include <spar/elements/cable/cable_reference.hpp>
#include <spar/core/dual.hpp>
#include <spar/elements/cable/rancf_cable_element.hpp>
#include <spar/iga/quadrature.hpp>
#include <spar/iga/rational_bezier.hpp>

#include <Eigen/Core>

#include <array>
#include <vector>

namespace spar::core::rancf {

template <class T, int Dim>
using Vec = Eigen::Matrix<T, Dim, 1>;

/// The four nodal vectors e = [r_A, r_x^A, r_B, r_x^B] (000 eq. (4)).
template <class T, int Dim>
using Nodal = std::array<Vec<T, Dim>, 4>;

inline std::vector<QuadraturePoint> quadrature_table(const Eigen::Vector4d& weights, int points) {
  const iga::GaussRule rule = iga::gauss_legendre(points);
  std::vector<QuadraturePoint> table(rule.points.size());
  for (std::size_t g = 0; g < table.size(); ++g) {
    table[g].u = 0.5 * (rule.points[g] + 1.0);
    table[g].weight = 0.5 * rule.weights[g];
    table[g].s = iga::rancf_shape_function_derivatives(table[g].u, weights);
  }
  return table;
}

/// σ_k^(d) of docs/rancf.md eq. (R3): the d-th u-derivative of s_k at the length l (s_2 and s_4
/// are proportional to l, 000 eq. (9)).
template <class T>
T sigma(const QuadraturePoint& p, int k, int d, const T& l) {
  return (k % 2 == 1) ? T(l * p.s(k, d)) : T(p.s(k, d));
}

/// R^(d)(u) = Σ_k σ_k^(d) e_k (eq. R3; 000 eqs. (7)–(9)).
template <class T, int Dim>
Vec<T, Dim> field(const QuadraturePoint& p, const Nodal<T, Dim>& e, const T& l, int d) {
  Vec<T, Dim> r = e[0] * T(p.s(0, d)) + e[2] * T(p.s(2, d));
  r += (e[1] * T(p.s(1, d)) + e[3] * T(p.s(3, d))) * l;
  return r;
}

/// ∂R^(d)/∂l at fixed u (eq. R3): ŝ_2^(d) r_x^A + ŝ_4^(d) r_x^B; R is linear in l.
template <class T, int Dim>
Vec<T, Dim> field_length_derivative(const QuadraturePoint& p, const Nodal<T, Dim>& e, int d) {
  return e[1] * T(p.s(1, d)) + e[3] * T(p.s(3, d));
}

/// The curvature numerator c = r_u × r_uu (eq. R4): a 1-vector (the scalar cross product) in 2D.
template <class T>
Eigen::Matrix<T, 1, 1> cross(const Vec<T, 2>& a, const Vec<T, 2>& b) {
  return Eigen::Matrix<T, 1, 1>(a(0) * b(1) - a(1) * b(0));
}
template <class T>
Eigen::Matrix<T, 3, 1> cross(const Vec<T, 3>& a, const Vec<T, 3>& b) {
  return Eigen::Matrix<T, 3, 1>(a(1) * b(2) - a(2) * b(1), a(2) * b(0) - a(0) * b(2),
                                a(0) * b(1) - a(1) * b(0));
}
/// (∂(a × b)/∂a)ᵀ c and (∂(a × b)/∂b)ᵀ c.
template <class T>
Vec<T, 2> cross_gradient_a(const Vec<T, 2>& b, const Eigen::Matrix<T, 1, 1>& c) {
  return Vec<T, 2>(b(1) * c(0), -b(0) * c(0));
}
template <class T>
Vec<T, 2> cross_gradient_b(const Vec<T, 2>& a, const Eigen::Matrix<T, 1, 1>& c) {
  return Vec<T, 2>(-a(1) * c(0), a(0) * c(0));
}
template <class T>
Vec<T, 3> cross_gradient_a(const Vec<T, 3>& b, const Eigen::Matrix<T, 3, 1>& c) {
  return cross(b, c);
}
template <class T>
Vec<T, 3> cross_gradient_b(const Vec<T, 3>& a, const Eigen::Matrix<T, 3, 1>& c) {
  return cross(c, a);
}

/// The strain energy U(e, l) = l ∫₀¹ [EA/2 (ε − ε₀)² + EI/2 |k − k₀|²] du of eq. (R5), with
/// ε = (|r_u|²/l² − 1)/2 (000 eq. (19), Cauchy–Green, r_x = r_u/l) and the curvature vector
/// k = r_x × r_xx/|r_x|³ = r_u × r_uu/|r_u|³ (|k| = κ of 000 eq. (19)); adds its gradient to
/// grad_e (per nodal vector) and grad_l. Without a reference (nullptr) ε₀ = 0 and k₀ = 0, as in
/// 000. With one (planar cables; elements/cable/cable_reference.hpp, docs/rancf.md eq. R5a), reference[g]
/// holds ε₀, κ₀ and their x-derivatives at the Gauss point's material coordinate
/// x_g = x_A + u_g l, and the explicit gradient Σ_g l w_g ∂W/∂x_g ∂x_g/∂(x_A, x_B) is added to
/// grad_material[0], [1] (∂x_g/∂x_A = 1 − u_g, ∂x_g/∂x_B = u_g; the ALE element's).
template <class T, int Dim>
T strain_energy(const RancfSection& section, const std::vector<QuadraturePoint>& table,
                const Nodal<T, Dim>& e, const T& l, Nodal<T, Dim>& grad_e, T& grad_l,
                const ReferenceStrain<T>* reference = nullptr, T* grad_material = nullptr) {
  using std::sqrt;
  T energy(0.0);
  const T inv_l2 = T(1.0) / (l * l);
  for (std::size_t g = 0; g < table.size(); ++g) {
    const QuadraturePoint& p = table[g];
    const Vec<T, Dim> r_u = field(p, e, l, 1);
    const Vec<T, Dim> r_uu = field(p, e, l, 2);
    const T s = r_u.squaredNorm();
    const T eps = T(0.5) * (s * inv_l2 - T(1.0));
    const T strain = reference ? T(eps - reference[g].axial) : eps;
    const auto c = cross(r_u, r_uu);
    const T inv_s3 = T(1.0) / (s * s * s);
    const T c2 = c.squaredNorm();
    T density = T(0.5 * section.axial_stiffness) * strain * strain +
                T(0.5 * section.bending_stiffness) * c2 * inv_s3;
    // ∂W/∂r_u, ∂W/∂r_uu, ∂W/∂l at fixed (r_u, r_uu).
    Vec<T, Dim> W_u = r_u * (T(section.axial_stiffness) * strain * inv_l2 -
                             T(3.0 * section.bending_stiffness) * c2 * inv_s3 / s) +
                      cross_gradient_a(r_uu, c) * (T(section.bending_stiffness) * inv_s3);
    Vec<T, Dim> W_uu = cross_gradient_b(r_u, c) * (T(section.bending_stiffness) * inv_s3);
    const T W_l = -T(section.axial_stiffness) * strain * s * inv_l2 / l;
    const T lw = l * p.weight;
    if constexpr (Dim == 2)
      if (reference) {
        // EI/2 |k − k₀|² = EI/2 (c²/s³ − 2 k₀ c s^{-3/2} + k₀²): the terms in k₀, and
        // ∂W/∂x_g = −EA (ε − ε₀) ε₀' − EI (k − k₀) κ₀'.
        const double EI = section.bending_stiffness;
        const Eigen::Matrix<T, 1, 1> k0(reference[g].curvature);
        const T inv_s15 = T(1.0) / (s * sqrt(s));
        const T k0_c = k0(0) * c(0);
        density += T(0.5 * EI) * (k0(0) * k0(0) - T(2.0) * k0_c * inv_s15);
        W_u += r_u * (T(3.0 * EI) * k0_c * inv_s15 / s) - cross_gradient_a(r_uu, k0) * (T(EI) * inv_s15);
        W_uu -= cross_gradient_b(r_u, k0) * (T(EI) * inv_s15);
        const T W_x = -T(section.axial_stiffness) * strain * reference[g].axial_slope -
                      T(EI) * (c(0) * inv_s15 - k0(0)) * reference[g].curvature_slope;
        grad_material[0] += lw * W_x * T(1.0 - p.u);
        grad_material[1] += lw * W_x * T(p.u);
      }
    energy += lw * density;
    for (int k = 0; k < 4; ++k)
      grad_e[k] += (W_u * sigma(p, k, 1, l) + W_uu * sigma(p, k, 2, l)) * lw;
    grad_l += p.weight * density +
              lw * (W_l + W_u.dot(field_length_derivative(p, e, 1)) +
                    W_uu.dot(field_length_derivative(p, e, 2)));
  }
  return energy;
}

/// The gravity potential V(e, l) = −ρA l ∫₀¹ g·r du of eq. (R6) (000 eq. (19), Q_g = −∂V/∂e);
/// adds its gradient to grad_e and grad_l. V = −ρA Σ w_g [l (s_1 g·r_A + s_3 g·r_B)
/// + l² (ŝ_2 g·r_x^A + ŝ_4 g·r_x^B)].
template <class T, int Dim>
T gravity_potential(double mass_per_length, const std::vector<QuadraturePoint>& table,
                    const Nodal<T, Dim>& e, const T& l, const Vec<double, Dim>& g,
                    Nodal<T, Dim>& grad_e, T& grad_l) {
  T linear(0.0), quadratic(0.0);
  Eigen::Vector4d shape_integral = Eigen::Vector4d::Zero();
  for (const QuadraturePoint& p : table) shape_integral += p.weight * p.s.col(0);
  std::array<T, 4> gdot;
  for (int k = 0; k < 4; ++k) gdot[k] = e[k].dot(g.template cast<T>());
  linear = T(shape_integral(0)) * gdot[0] + T(shape_integral(2)) * gdot[2];
  quadratic = T(shape_integral(1)) * gdot[1] + T(shape_integral(3)) * gdot[3];
  for (int k = 0; k < 4; ++k) {
    const T factor = (k % 2 == 1) ? T(l * l) : l;
    grad_e[k] -= g.template cast<T>() * (T(mass_per_length * shape_integral(k)) * factor);
  }
  grad_l -= T(mass_per_length) * (linear + T(2.0) * l * quadratic);
  return -T(mass_per_length) * (l * linear + l * l * quadratic);
}

/// The Kelvin–Voigt force of 000 eq. (17): the stresses EA c ε̇ and EI c k̇ with the rates taken
/// at a fixed material point (docs/rancf.md eq. R13). At the Gauss point u_g, whose material
/// coordinate changes at ẋ_g = (1 − u_g) ẋ_A + u_g ẋ_B, so u̇ = −ẋ_g/l at a fixed material point:
///   ṙ_u = R_u(ė) + R_ul l̇ + r_uu u̇,  ṙ_uu = R_uu(ė) + R_uul l̇ + r_uuu u̇,
///   ε̇ = r_u·ṙ_u/l² − |r_u|² l̇/l³,  k̇ = (ṙ_u × r_uu + r_u × ṙ_uu)/s^{3/2} − 3 (r_u·ṙ_u) c/s^{5/2},
/// s = |r_u|², c = r_u × r_uu. The force is ∂D/∂q̇ of the Rayleigh function
/// D = ½ c_KV l Σ_g w_g (EA ε̇² + EI |k̇|²) (the paper's (∂ε/∂q)ᵀ EA c ε̇ + (∂κ/∂q)ᵀ EI c κ̇ with
/// the curvature vector k in place of κ = |k|, whose derivative is singular for a straight
/// cable); q̇·f = 2D ≥ 0 is the dissipated power. For a fixed-length element pass zero material
/// rates. Adds to f_e, f_a, f_b; returns 2D.
template <class T, int Dim>
T viscous_force(const RancfSection& section, const std::vector<QuadraturePoint>& table,
                const Nodal<T, Dim>& e, const T& l, const Nodal<T, Dim>& e_dot, const T& x_a_dot,
                const T& x_b_dot, Nodal<T, Dim>& f_e, T& f_a, T& f_b) {
  using std::sqrt;
  const double c_kv = section.damping_coefficient;
  const T l_dot = x_b_dot - x_a_dot;
  const T inv_l = T(1.0) / l;
  T power(0.0);
  for (const QuadraturePoint& p : table) {
    const double u = p.u;
    const T u_dot = -(T(1.0 - u) * x_a_dot + T(u) * x_b_dot) * inv_l;
    const Vec<T, Dim> r_u = field(p, e, l, 1), r_uu = field(p, e, l, 2), r_uuu = field(p, e, l, 3);
    const Vec<T, Dim> R_ul = field_length_derivative(p, e, 1), R_uul = field_length_derivative(p, e, 2);
    const Vec<T, Dim> r_u_dot = field(p, e_dot, l, 1) + R_ul * l_dot + r_uu * u_dot;
    const Vec<T, Dim> r_uu_dot = field(p, e_dot, l, 2) + R_uul * l_dot + r_uuu * u_dot;
    const T s = r_u.squaredNorm();
    const T root_s = sqrt(s);
    const T inv_s15 = T(1.0) / (s * root_s);
    const auto c = cross(r_u, r_uu);
    const T r_u_rate = r_u.dot(r_u_dot);
    const T eps_dot = r_u_rate * inv_l * inv_l - s * l_dot * inv_l * inv_l * inv_l;
    const auto k_dot = ((cross(r_u_dot, r_uu) + cross(r_u, r_uu_dot)) * inv_s15 -
                        c * (T(3.0) * r_u_rate * inv_s15 / s))
                           .eval();
    // ∂D/∂ṙ_u, ∂D/∂ṙ_uu, ∂D/∂l̇ (explicit), per unit c_KV l w_g.
    const Vec<T, Dim> g_u = r_u * (T(section.axial_stiffness) * eps_dot * inv_l * inv_l) +
                            (cross_gradient_a(r_uu, k_dot) * inv_s15 -
                             r_u * (T(3.0) * c.dot(k_dot) * inv_s15 / s)) *
                                T(section.bending_stiffness);
    const Vec<T, Dim> g_uu = cross_gradient_b(r_u, k_dot) * (inv_s15 * T(section.bending_stiffness));
    const T g_l = -T(section.axial_stiffness) * eps_dot * s * inv_l * inv_l * inv_l;
    const T weight = T(c_kv * p.weight) * l;
    for (int k = 0; k < 4; ++k)
      f_e[k] += (g_u * sigma(p, k, 1, l) + g_uu * sigma(p, k, 2, l)) * weight;
    const T along_a = g_u.dot(R_ul) + g_uu.dot(R_uul) + g_l;
    const T convective = g_u.dot(r_uu) + g_uu.dot(r_uuu);
    f_a += weight * (-along_a - T(1.0 - u) * inv_l * convective);
    f_b += weight * (along_a - T(u) * inv_l * convective);
    power += weight * (T(section.axial_stiffness) * eps_dot * eps_dot +
                       T(section.bending_stiffness) * k_dot.squaredNorm());
  }
  return power;
}

/// The inertial force of an ALE-RANCF element and its kinetic energy (docs/rancf.md eqs. R7–R11).
/// A material point x sits at u = (x − x_A)/l, l = x_B − x_A (000 eq. (13)). At the Gauss point
/// u_g the curve point p = R(u_g; e, l) moves with the mesh, and the material point there, whose
/// material coordinate changes at ẋ_g = (1 − u_g) ẋ_A + u_g ẋ_B, has the velocity
///   V = ṗ − t ẋ_g,  t = R_u/l = r_x,  ṗ = R(ė) + R_l l̇              (R7, 000 eqs. (14)–(15))
/// i.e. V = N q̇ with N = [σ_k I, −R_l − (1 − u) t, R_l − u t]. The quadrature kinetic energy
///   T = ½ Σ_g c_g |V_g|²,  c_g = ρA l w_g                                      (R10)
/// is the one the element reports, and the force is its exact Euler–Lagrange expression
///   f = Σ_g c_g Nᵀ V̇ + c_g [(∂t/∂q)ᵀ V ẋ_g − a_g (ṫ·V)] + ċ_g Nᵀ V − ½ |V|² ∂c_g/∂q,   (R11)
///   V̇ = R(ë) + R_l l̈ + 2 R_l(ė) l̇ − ṫ ẋ_g − t ẍ_g,  ṫ = R_u(ė)/l + (R_ul/l − R_u/l²) l̇,
/// with a_g = ∂ẋ_g/∂q̇ ((1 − u_g) at x_A, u_g at x_B) and ∂c_g/∂(x_A, x_B) = ρA w_g (−1, 1). With
/// exact integration it equals 000 eqs. (17)–(19), M q̈ + Q_a, plus the boundary terms of the
/// moving integration limits, ρA [Nᵀṙ ẋ − ½|ṙ|² ∂x/∂q] at x_A and x_B (which cancel between two
/// elements meeting with a continuous slope); with quadrature it keeps the discrete system
/// Lagrangian, so the energy is conserved to the integrator's accuracy (docs/rancf.md).
/// Adds to f_e, f_a, f_b; returns T.
template <class T, int Dim>
T ale_inertia(double mass_per_length, const std::vector<QuadraturePoint>& table,
              const Nodal<T, Dim>& e, const T& x_a, const T& x_b, const Nodal<T, Dim>& e_dot,
              const T& x_a_dot, const T& x_b_dot, const Nodal<T, Dim>& e_acc, const T& x_a_acc,
              const T& x_b_acc, Nodal<T, Dim>& f_e, T& f_a, T& f_b) {
  const T l = x_b - x_a;
  const T l_dot = x_b_dot - x_a_dot;
  const T l_acc = x_b_acc - x_a_acc;
  const T inv_l = T(1.0) / l;
  T kinetic(0.0);
  for (const QuadraturePoint& p : table) {
    const double u = p.u;
    const T x_dot = T(1.0 - u) * x_a_dot + T(u) * x_b_dot;
    const T x_acc = T(1.0 - u) * x_a_acc + T(u) * x_b_acc;
    const Vec<T, Dim> R_u = field(p, e, l, 1);
    const Vec<T, Dim> R_l = field_length_derivative(p, e, 0);
    const Vec<T, Dim> t = R_u * inv_l;
    const Vec<T, Dim> t_l = (field_length_derivative(p, e, 1) - t) * inv_l;  // ∂t/∂l
    const Vec<T, Dim> t_dot = field(p, e_dot, l, 1) * inv_l + t_l * l_dot;
    const Vec<T, Dim> V = field(p, e_dot, l, 0) + R_l * l_dot - t * x_dot;
    const Vec<T, Dim> V_dot = field(p, e_acc, l, 0) + R_l * l_acc +
                              field_length_derivative(p, e_dot, 0) * (T(2.0) * l_dot) -
                              t_dot * x_dot - t * x_acc;
    const T c = T(mass_per_length * p.weight) * l;
    const T c_dot = T(mass_per_length * p.weight) * l_dot;
    const T half_v2 = T(0.5) * V.squaredNorm();
    // c Nᵀ V̇ + ċ Nᵀ V.
    const Vec<T, Dim> w = V_dot * c + V * c_dot;
    for (int k = 0; k < 4; ++k) f_e[k] += w * sigma(p, k, 0, l);
    const T R_l_w = R_l.dot(w), t_w = t.dot(w);
    f_a += -R_l_w - T(1.0 - u) * t_w;
    f_b += R_l_w - T(u) * t_w;
    // c [(∂t/∂q)ᵀ V ẋ_g − a_g (ṫ·V)]: ∂t/∂e_k = σ'_k/l, ∂t/∂x_A = −∂t/∂l, ∂t/∂x_B = ∂t/∂l.
    const T cx = c * x_dot;
    for (int k = 0; k < 4; ++k) f_e[k] += V * (cx * sigma(p, k, 1, l) * inv_l);
    const T t_l_V = cx * t_l.dot(V), t_dot_V = c * t_dot.dot(V);
    f_a += -t_l_V - T(1.0 - u) * t_dot_V;
    f_b += t_l_V - T(u) * t_dot_V;
    // − ½ |V|² ∂c/∂q.
    f_a += T(mass_per_length * p.weight) * half_v2;
    f_b -= T(mass_per_length * p.weight) * half_v2;
    kinetic += c * half_v2;
  }
  return kinetic;
}

/// The ALE-RANCF mass matrix M(q) = ρA l ∫₀¹ Nᵀ N du (000 eq. (19), eq. R9), local order
/// [e, x_A, x_B].
template <int Dim>
void ale_mass_matrix(double mass_per_length, const std::vector<QuadraturePoint>& table,
                     const Nodal<double, Dim>& e, double x_a, double x_b,
                     Eigen::Ref<Eigen::MatrixXd> M) {
  constexpr int n = 4 * Dim + 2;
  const double l = x_b - x_a;
  Eigen::Matrix<double, Dim, n> N;
  for (const QuadraturePoint& p : table) {
    const Vec<double, Dim> R_u = field(p, e, l, 1);
    const Vec<double, Dim> R_l = field_length_derivative(p, e, 0);
    for (int k = 0; k < 4; ++k)
      N.template middleCols<Dim>(k * Dim) = sigma(p, k, 0, l) * Eigen::Matrix<double, Dim, Dim>::Identity();
    N.col(4 * Dim) = -(1.0 - p.u) / l * R_u - R_l;  // eq. R7
    N.col(4 * Dim + 1) = -p.u / l * R_u + R_l;
    M.noalias() += (mass_per_length * l * p.weight) * N.transpose() * N;
  }
}

}  // namespace spar::core::rancf
