#include <spar/core/section_integrals.hpp>

#include <spar/error.hpp>

#include <cmath>
#include <numbers>
#include <string>

namespace spar::core {

namespace {

/// ∫_lo^hi t^a dt.
double power_integral(int a, double lo, double hi) {
  return (std::pow(hi, a + 1) - std::pow(lo, a + 1)) / (a + 1);
}

/// Binomial coefficient C(n, k) for n ≤ 4.
double binomial(int n, int k) {
  double c = 1.0;
  for (int i = 1; i <= k; ++i) c = c * (n - k + i) / i;
  return c;
}

}  // namespace

double SectionIntegrals::moment(int a, int b) const {
  if (a < 0 || b < 0 || a + b > max_order)
    throw Error("moment order (" + std::to_string(a) + ", " + std::to_string(b) + ") out of range",
                "core::SectionIntegrals::moment", "ask for a, b >= 0 with a + b <= 4");
  return moments_[a][b];
}

void SectionIntegrals::validate(const char* where) const {
  for (const auto& row : moments_)
    for (double m : row)
      if (!std::isfinite(m)) throw Error("a section integral is not finite", where, "check the section's data");
  if (!(area() > 0.0))
    throw Error("the section's area is " + std::to_string(area()), where,
                "give positive dimensions (polygon vertices counter-clockwise)");
}

SectionIntegrals SectionIntegrals::from_moments(const Moments& m) {
  for (int a = 0; a <= max_order; ++a)
    for (int b = max_order + 1 - a; b <= max_order; ++b)
      if (m[a][b] != 0.0)
        throw Error("moment (" + std::to_string(a) + ", " + std::to_string(b) + ") is beyond order 4",
                    "core::SectionIntegrals::from_moments", "give only the moments with a + b <= 4");
  SectionIntegrals s;
  s.moments_ = m;
  s.validate("core::SectionIntegrals::from_moments");
  return s;
}

SectionIntegrals SectionIntegrals::second_order(double area, double second_moment_y,
                                                double second_moment_z, double product_moment) {
  SectionIntegrals s;
  s.moments_[0][0] = area;
  s.moments_[0][2] = second_moment_y;
  s.moments_[2][0] = second_moment_z;
  s.moments_[1][1] = product_moment;
  s.validate("core::SectionIntegrals::second_order");
  if (!(second_moment_y > 0.0 && second_moment_z > 0.0 &&
        second_moment_y * second_moment_z > product_moment * product_moment))
    throw Error("I_y, I_z, I_yz do not form a positive definite second-moment matrix",
                "core::SectionIntegrals::second_order", "give I_y > 0, I_z > 0, I_y I_z > I_yz^2");
  return s;
}

SectionIntegrals SectionIntegrals::circle(double radius, const Eigen::Vector2d& center) {
  if (!(radius > 0.0))
    throw Error("the radius is " + std::to_string(radius), "core::SectionIntegrals::circle",
                "give a positive radius");
  // About the centre only even moments survive: ∫ u^a v^b dA over the disc
  // = 2 Γ((a+1)/2) Γ((b+1)/2) / Γ((a+b)/2 + 1) · R^(a+b+2)/(a+b+2).
  std::array<std::array<double, max_order + 1>, max_order + 1> centred{};
  for (int a = 0; a <= max_order; a += 2)
    for (int b = 0; a + b <= max_order; b += 2)
      centred[a][b] = 2.0 * std::tgamma((a + 1) / 2.0) * std::tgamma((b + 1) / 2.0) /
                      std::tgamma((a + b) / 2.0 + 1.0) * std::pow(radius, a + b + 2) / (a + b + 2);
  // Moments about the origin of a shifted disc: y = c_y + u, z = c_z + v, expanded binomially.
  SectionIntegrals s;
  for (int a = 0; a <= max_order; ++a)
    for (int b = 0; a + b <= max_order; ++b)
      for (int i = 0; i <= a; ++i)
        for (int j = 0; j <= b; ++j)
          s.moments_[a][b] += binomial(a, i) * binomial(b, j) * std::pow(center.x(), a - i) *
                              std::pow(center.y(), b - j) * centred[i][j];
  s.validate("core::SectionIntegrals::circle");
  return s;
}

SectionIntegrals SectionIntegrals::rectangle(double width, double height, const Eigen::Vector2d& center) {
  if (!(width > 0.0 && height > 0.0))
    throw Error("the rectangle is " + std::to_string(width) + " x " + std::to_string(height),
                "core::SectionIntegrals::rectangle", "give positive width and height");
  SectionIntegrals s;
  for (int a = 0; a <= max_order; ++a)
    for (int b = 0; a + b <= max_order; ++b)
      s.moments_[a][b] = power_integral(a, center.x() - width / 2, center.x() + width / 2) *
                         power_integral(b, center.y() - height / 2, center.y() + height / 2);
  s.validate("core::SectionIntegrals::rectangle");
  return s;
}

SectionIntegrals SectionIntegrals::polygon(const std::vector<Eigen::Vector2d>& vertices) {
  if (vertices.size() < 3)
    throw Error("a polygon needs at least 3 vertices, got " + std::to_string(vertices.size()),
                "core::SectionIntegrals::polygon", "list the vertices counter-clockwise");
  // Green's theorem: ∫∫ y^a z^b dA = ∮ y^(a+1) z^b / (a+1) dz. On an edge y = y0 + t Δy,
  // z = z0 + t Δz the integrand is a polynomial of degree a + b + 1 ≤ 5 in t: three-point
  // Gauss–Legendre on [0, 1] is exact (docs/ancf.md eq. A10).
  const double s3 = std::sqrt(3.0 / 5.0);
  const std::array<double, 3> t{0.5 * (1 - s3), 0.5, 0.5 * (1 + s3)};
  const std::array<double, 3> w{5.0 / 18, 8.0 / 18, 5.0 / 18};
  SectionIntegrals s;
  for (std::size_t k = 0; k < vertices.size(); ++k) {
    const Eigen::Vector2d& p0 = vertices[k];
    const Eigen::Vector2d d = vertices[(k + 1) % vertices.size()] - p0;
    for (int g = 0; g < 3; ++g) {
      const Eigen::Vector2d p = p0 + t[g] * d;
      for (int a = 0; a <= max_order; ++a)
        for (int b = 0; a + b <= max_order; ++b)
          s.moments_[a][b] += w[g] * std::pow(p.x(), a + 1) * std::pow(p.y(), b) / (a + 1) * d.y();
    }
  }
  s.validate("core::SectionIntegrals::polygon");
  return s;
}

SectionIntegrals SectionIntegrals::operator+(const SectionIntegrals& other) const {
  SectionIntegrals s = *this;
  for (int a = 0; a <= max_order; ++a)
    for (int b = 0; a + b <= max_order; ++b) s.moments_[a][b] += other.moments_[a][b];
  return s;
}

SectionIntegrals SectionIntegrals::truncated_to_second_order() const {
  return second_order(area(), second_moment_y(), second_moment_z(), product_moment());
}

}  // namespace spar::core
