#pragma once
// The slow reference path for the ANCF beam elements (docs/ancf.md §4): section quadrature rules
// and a direct Gauss volume integration of the same St. Venant–Kirchhoff strain energy, written
// from 001 eqs. (5) and (55) literally (the 3D shape functions S(x, y, z), differentiated by the
// complex step), independent of the elements' section-integral kernel.
#include <spar/elements/ancf/ancf_beam_element.hpp>

#include <Eigen/Core>

#include <cmath>
#include <complex>
#include <numbers>
#include <vector>

namespace spar::test {

/// Points (y, z) and weights of a section quadrature.
using SectionQuadrature = std::vector<Eigen::Vector3d>;

/// 3-point Gauss–Legendre on [0, 1] (exact to degree 5).
inline void gauss3(double (&t)[3], double (&w)[3]) {
  const double s = std::sqrt(3.0 / 5.0);
  t[0] = 0.5 * (1 - s), t[1] = 0.5, t[2] = 0.5 * (1 + s);
  w[0] = 5.0 / 18, w[1] = 8.0 / 18, w[2] = 5.0 / 18;
}

/// Exact to degree 5 in y and z.
inline SectionQuadrature rectangle_quadrature(double width, double height, Eigen::Vector2d c = {0, 0}) {
  double t[3], w[3];
  gauss3(t, w);
  SectionQuadrature q;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      q.emplace_back(c.x() + (t[i] - 0.5) * width, c.y() + (t[j] - 0.5) * height, w[i] * w[j] * width * height);
  return q;
}

/// Polar rule: radial 3-point Gauss (exact for r^k r dr, k ≤ 4), 8 equal angles (exact for
/// trigonometric degree < 8): exact for polynomials of degree ≤ 4.
inline SectionQuadrature circle_quadrature(double radius, Eigen::Vector2d c = {0, 0}) {
  double t[3], w[3];
  gauss3(t, w);
  SectionQuadrature q;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 8; ++k) {
      const double r = t[i] * radius, phi = 2 * std::numbers::pi * k / 8;
      q.emplace_back(c.x() + r * std::cos(phi), c.y() + r * std::sin(phi),
                     w[i] * radius * r * 2 * std::numbers::pi / 8);
    }
  return q;
}

/// Signed fan of triangles from vertex 0, each by the collapsed (Duffy) 3 × 3 Gauss rule: exact
/// for polynomials of degree ≤ 4 on any simple polygon.
inline SectionQuadrature polygon_quadrature(const std::vector<Eigen::Vector2d>& v) {
  double t[3], w[3];
  gauss3(t, w);
  SectionQuadrature q;
  for (std::size_t k = 1; k + 1 < v.size(); ++k) {
    const Eigen::Vector2d A = v[0], B = v[k], C = v[k + 1];
    const double twice_area = (B - A).x() * (C - A).y() - (B - A).y() * (C - A).x();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const double s = t[i], u = t[j];
        const Eigen::Vector2d p = A + s * (B - A) + s * u * (C - B);
        q.emplace_back(p.x(), p.y(), w[i] * w[j] * s * twice_area);
      }
  }
  return q;
}

inline double quadrature_moment(const SectionQuadrature& q, int a, int b) {
  double m = 0.0;
  for (const Eigen::Vector3d& p : q) m += p.z() * std::pow(p.x(), a) * std::pow(p.y(), b);
  return m;
}

/// The scalar shape functions S_k(x, y, z) of 001 eq. (5) (8 functions) or eq. (55) (10).
template <int transverse, class T>
std::array<T, 4 + 2 * transverse> literal_shape(T x, T y, T z, double l) {
  const T xi = x / l, eta = y / l, zeta = z / l;
  std::array<T, 4 + 2 * transverse> S;
  S[0] = 1.0 - 3.0 * xi * xi + 2.0 * xi * xi * xi;
  S[1] = l * (xi - 2.0 * xi * xi + xi * xi * xi);
  S[4] = 3.0 * xi * xi - 2.0 * xi * xi * xi;
  S[5] = l * (-xi * xi + xi * xi * xi);
  if constexpr (transverse == 2) {
    S[2] = l * (eta - xi * eta);
    S[3] = l * (zeta - xi * zeta);
    S[6] = l * xi * eta;
    S[7] = l * xi * zeta;
  } else {
    S[2] = l * (1.0 - xi * xi) * eta;
    S[3] = l * (1.0 - xi * xi) * zeta;
    S[6] = l * xi * xi * eta;
    S[7] = l * xi * xi * zeta;
    S[8] = (xi - xi * xi) * l * l * eta;
    S[9] = (xi - xi * xi) * l * l * zeta;
  }
  return S;
}

template <int transverse>
struct VolumeReference {
  using Element = core::AncfBeamElement<transverse>;
  static constexpr int n = 4 + 2 * transverse, dofs = 3 * n;
  double energy = 0.0;
  Eigen::Matrix<double, dofs, 1> force = Eigen::Matrix<double, dofs, 1>::Zero();
  Eigen::Matrix<double, dofs, dofs> stiffness = Eigen::Matrix<double, dofs, dofs>::Zero();
  Eigen::Matrix<double, dofs, dofs> mass = Eigen::Matrix<double, dofs, dofs>::Zero();
};

/// Energy, force (∫ Σ_α S_αᵀ P e_α dV), stiffness and mass (∫ ρ SᵀS dV) by 5-point Gauss along
/// the axis times the section rule, at every point straight from the definitions.
template <int transverse>
VolumeReference<transverse> volume_reference(const core::AncfBeamElement<transverse>& element,
                                             const SectionQuadrature& section,
                                             const Eigen::Matrix<double, 3 * (4 + 2 * transverse), 1>& e) {
  using Ref = VolumeReference<transverse>;
  constexpr int n = Ref::n;
  const auto& t = element.tables();
  const double l = t.length, lambda = t.law.lambda, mu = t.law.mu, h = 1e-30;
  // The shear factor's (k − 1)μ on the transverse shear entries xy, xz (docs/ancf.md eq. A22).
  const double excess = (t.law.shear_factor - 1) * mu;
  const Eigen::Matrix3d shear = (Eigen::Matrix3d() << 0, 1, 1, 1, 0, 0, 1, 0, 0).finished();
  Ref out;
  const double gx[5] = {-0.906179845938664, -0.5384693101056831, 0.0, 0.5384693101056831, 0.906179845938664};
  const double gw[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889, 0.4786286704993665,
                        0.2369268850561891};
  for (int g = 0; g < 5; ++g)
    for (const Eigen::Vector3d& p : section) {
      const double x = 0.5 * (gx[g] + 1) * l, y = p.x(), z = p.y(), w = 0.5 * gw[g] * l * p.z();
      // Complex-step derivatives of the literal shape functions: ∂S/∂x_α = Im S(x + ih e_α)/h.
      Eigen::Matrix<double, n, 3> dS;
      Eigen::Matrix<double, n, 1> S;
      for (int a = 0; a < 3; ++a) {
        const std::complex<double> X(x, a == 0 ? h : 0), Y(y, a == 1 ? h : 0), Z(z, a == 2 ? h : 0);
        const auto s = literal_shape<transverse>(X, Y, Z, l);
        for (int k = 0; k < n; ++k) {
          dS(k, a) = s[k].imag() / h;
          S(k) = s[k].real();
        }
      }
      Eigen::Matrix3d F = Eigen::Matrix3d::Zero();
      for (int k = 0; k < n; ++k) F += e.template segment<3>(3 * k) * dS.row(k);
      const Eigen::Matrix3d E = 0.5 * (F.transpose() * F - Eigen::Matrix3d::Identity());
      const Eigen::Matrix3d Sp =
          lambda * E.trace() * Eigen::Matrix3d::Identity() + 2 * mu * E + 2 * excess * shear.cwiseProduct(E);
      const Eigen::Matrix3d P = F * Sp;
      out.energy += w * 0.5 * E.cwiseProduct(Sp).sum();
      for (int k = 0; k < n; ++k) {
        out.force.template segment<3>(3 * k) += w * P * dS.row(k).transpose();
        for (int m = 0; m < n; ++m) {
          out.mass.template block<3, 3>(3 * k, 3 * m) += w * t.density * S(k) * S(m) * Eigen::Matrix3d::Identity();
          // ∂P/∂F contracted with the shape gradients: δ_ik S_JL + λ F_iJ F_kL + μ_JL F_iL F_kJ
          // + δ_JL Σ_γ μ_Jγ F_iγ F_kγ, with μ_JL = μ + (k − 1)μ X_JL.
          Eigen::Matrix3d K = Eigen::Matrix3d::Zero();
          for (int J = 0; J < 3; ++J)
            for (int L = 0; L < 3; ++L) {
              const double c = dS(k, J) * dS(m, L);
              if (c == 0.0) continue;
              K += c * (Sp(J, L) * Eigen::Matrix3d::Identity() + lambda * F.col(J) * F.col(L).transpose() +
                        (mu + excess * shear(J, L)) * F.col(L) * F.col(J).transpose());
              if (J == L)
                for (int a = 0; a < 3; ++a) K += c * (mu + excess * shear(J, a)) * F.col(a) * F.col(a).transpose();
            }
          out.stiffness.template block<3, 3>(3 * k, 3 * m) += w * K;
        }
      }
    }
  return out;
}

}  // namespace spar::test
