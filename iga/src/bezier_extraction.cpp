#include <spar/error.hpp>
#include <spar/iga/bezier_extraction.hpp>
#include <spar/iga/quadrature.hpp>

#include <string>

namespace spar::iga {

std::vector<Eigen::MatrixXd> bezier_extraction(const KnotVector& U) {
  const int p = U.degree();
  const std::vector<double>& knots = U.knots();
  const int last = static_cast<int>(knots.size()) - 1;
  const Eigen::MatrixXd identity = Eigen::MatrixXd::Identity(p + 1, p + 1);
  std::vector<Eigen::MatrixXd> operators{identity};
  std::vector<double> alphas(p + 1);
  // Borden et al. 2011, Algorithm 1, with 0-based indices: a = last index of the element's left
  // knot, b runs over the right knot's repetitions. Each interior knot is raised to multiplicity
  // p by knot insertion; the insertion coefficients build the current element's operator and the
  // overlapping part of the next one.
  int a = p, b = p + 1;
  while (true) {
    const int i = b;
    while (b < last && knots[b + 1] == knots[b]) ++b;
    if (b == last) break;
    const int multiplicity = b - i + 1;
    Eigen::MatrixXd next = identity;
    if (multiplicity < p) {
      Eigen::MatrixXd& current = operators.back();
      const double numerator = knots[b] - knots[a];
      for (int j = p; j > multiplicity; --j)
        alphas[j - multiplicity - 1] = numerator / (knots[a + j] - knots[a]);
      const int r = p - multiplicity;
      for (int j = 1; j <= r; ++j) {
        const int save = r - j, s = multiplicity + j;
        for (int k = p; k >= s; --k) {
          const double alpha = alphas[k - s];
          current.col(k) = alpha * current.col(k) + (1.0 - alpha) * current.col(k - 1);
        }
        next.block(save, save, j + 1, 1) = current.block(p - j, p, j + 1, 1);
      }
    }
    operators.push_back(std::move(next));
    a = b;
    ++b;
  }
  return operators;
}

void bernstein_derivatives(int degree, double xi, int order, BasisTable& out) {
  // The Bernstein polynomials are the B-splines of the Bézier knot vector {0^(p+1), 1^(p+1)}.
  std::vector<double> knots(degree + 1, 0.0);
  knots.insert(knots.end(), degree + 1, 1.0);
  const KnotVector bezier(std::move(knots), degree);
  basis_derivatives(bezier, degree, xi, order, out);
}

namespace {

std::vector<ElementQuadrature> extraction_loop(const KnotVector& U, int points, int order,
                                               const double* weights) {
  detail::check_derivative_order(order, "iga::element_quadrature");
  const int p = U.degree();
  const GaussRule rule = gauss_legendre(points);
  const std::vector<Eigen::MatrixXd> operators = bezier_extraction(U);
  // The Bernstein tables at the Gauss points are the same on every element.
  std::vector<BasisTable> bernstein(points);
  for (int q = 0; q < points; ++q)
    bernstein_derivatives(p, 0.5 * (rule.points[q] + 1.0), order, bernstein[q]);
  std::vector<ElementQuadrature> loop;
  loop.reserve(U.element_count());
  for (int e = 0; e < U.element_count(); ++e) {
    const Element element = U.element(e);
    const double length = element.last - element.first;
    ElementQuadrature eq{e, element.span, element.span - p, element.first, element.last, {}, {},
                         std::vector<double>(points, 1.0), std::vector<BasisTable>(points)};
    for (int q = 0; q < points; ++q) {
      const double xi = 0.5 * (rule.points[q] + 1.0);
      eq.parameters.push_back(element.first + length * xi);
      eq.weights.push_back(0.5 * length * rule.weights[q]);
      BasisTable& N = eq.basis[q];
      N.setZero();
      double scale = 1.0;  // (dξ/du)^k
      for (int k = 0; k <= order; ++k) {
        N.row(k).head(p + 1) =
            scale * (operators[e] * bernstein[q].row(k).head(p + 1).transpose()).transpose();
        scale /= length;
      }
      if (weights) detail::rationalize(N, p, order, weights + element.span - p);
    }
    loop.push_back(std::move(eq));
  }
  return loop;
}

}  // namespace

std::vector<ElementQuadrature> element_quadrature(const KnotVector& U, int points, int order) {
  return extraction_loop(U, points, order, nullptr);
}

std::vector<ElementQuadrature> element_quadrature(const KnotVector& U, int points,
                                                  const Eigen::VectorXd& weights, int order) {
  if (weights.size() != U.basis_count())
    throw Error("there are " + std::to_string(weights.size()) + " weights for " +
                    std::to_string(U.basis_count()) + " basis functions",
                "iga::element_quadrature", "give one weight per basis function");
  return extraction_loop(U, points, order, weights.data());
}

}  // namespace spar::iga
