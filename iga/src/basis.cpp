#include <spar/error.hpp>
#include <spar/iga/basis.hpp>

#include <algorithm>
#include <array>
#include <string>

namespace spar::iga {

namespace detail {

void rationalize(BasisTable& table, int degree, int order, const double* local_weights) {
  // Homogeneous form: A^(k)_j = w_j N^(k)_j, W^(k) = Σ_j A^(k)_j.
  std::array<double, max_derivative_order + 1> W{};
  for (int k = 0; k <= order; ++k) {
    for (int j = 0; j <= degree; ++j) table(k, j) *= local_weights[j];
    W[k] = table.row(k).head(degree + 1).sum();
  }
  // Quotient rule, lowest order first so that R^(k−l) is already rational (eq. 4.8).
  constexpr auto binomial = [] {
    std::array<std::array<double, max_derivative_order + 1>, max_derivative_order + 1> c{};
    for (int k = 0; k <= max_derivative_order; ++k) {
      c[k][0] = 1.0;
      for (int l = 1; l <= k; ++l) c[k][l] = c[k - 1][l - 1] + c[k - 1][l];
    }
    return c;
  }();
  const double inverse_weight = 1.0 / W[0];
  for (int k = 0; k <= order; ++k)
    for (int j = 0; j <= degree; ++j) {
      double value = table(k, j);
      for (int l = 1; l <= k; ++l) value -= binomial[k][l] * W[l] * table(k - l, j);
      table(k, j) = value * inverse_weight;
    }
}

}  // namespace detail

void basis_derivatives(const KnotVector& U, int span, double u, int order, BasisTable& out) {
  detail::check_derivative_order(order, "iga::basis_derivatives");
  const int p = U.degree();
  if (span < p || span >= U.basis_count())
    throw Error("span " + std::to_string(span) + " is not a span of the knot vector",
                "iga::basis_derivatives", "use KnotVector::find_span(u)");
  const double* knots = U.knots().data();
  const int n = std::min(order, p);
  out.setZero();

  // A2.2/A2.3: ndu holds the basis functions of all degrees (upper triangle) and the knot
  // differences (lower triangle).
  std::array<std::array<double, max_degree + 1>, max_degree + 1> ndu;
  std::array<double, max_degree + 1> left, right;
  ndu[0][0] = 1.0;
  for (int j = 1; j <= p; ++j) {
    left[j] = u - knots[span + 1 - j];
    right[j] = knots[span + j] - u;
    double saved = 0.0;
    for (int r = 0; r < j; ++r) {
      ndu[j][r] = right[r + 1] + left[j - r];
      const double temp = ndu[r][j - 1] / ndu[j][r];
      ndu[r][j] = saved + right[r + 1] * temp;
      saved = left[j - r] * temp;
    }
    ndu[j][j] = saved;
  }
  for (int j = 0; j <= p; ++j) out(0, j) = ndu[j][p];

  // A2.3: the k-th derivative of N_{span−p+r} from the coefficients a_{k,j} (two rows, swapped).
  std::array<std::array<double, max_degree + 1>, 2> a;
  for (int r = 0; r <= p; ++r) {
    int s1 = 0, s2 = 1;
    a[0][0] = 1.0;
    for (int k = 1; k <= n; ++k) {
      double d = 0.0;
      const int rk = r - k, pk = p - k;
      if (r >= k) {
        a[s2][0] = a[s1][0] / ndu[pk + 1][rk];
        d = a[s2][0] * ndu[rk][pk];
      }
      const int j1 = rk >= -1 ? 1 : -rk;
      const int j2 = r - 1 <= pk ? k - 1 : p - r;
      for (int j = j1; j <= j2; ++j) {
        a[s2][j] = (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][rk + j];
        d += a[s2][j] * ndu[rk + j][pk];
      }
      if (r <= pk) {
        a[s2][k] = -a[s1][k - 1] / ndu[pk + 1][r];
        d += a[s2][k] * ndu[r][pk];
      }
      out(k, r) = d;
      std::swap(s1, s2);
    }
  }
  // Multiply by p!/(p−k)!.
  double factor = p;
  for (int k = 1; k <= n; ++k) {
    out.row(k).head(p + 1) *= factor;
    factor *= p - k;
  }
}

void rational_basis_derivatives(const KnotVector& U, int span, double u, int order,
                                const Eigen::VectorXd& weights, BasisTable& out) {
  if (weights.size() != U.basis_count())
    throw Error("there are " + std::to_string(weights.size()) + " weights for " +
                    std::to_string(U.basis_count()) + " basis functions",
                "iga::rational_basis_derivatives", "give one weight per basis function");
  basis_derivatives(U, span, u, order, out);
  const int p = U.degree();
  detail::rationalize(out, p, order, weights.data() + span - p);
}

}  // namespace spar::iga
