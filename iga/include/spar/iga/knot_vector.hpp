#pragma once
/// \file
/// Open (clamped) knot vectors of B-spline and NURBS bases: validation, span search (The NURBS
/// Book A2.1), elements (non-zero knot spans), Greville abscissae and open-uniform construction.

#include <vector>

namespace spar::iga {

/// The largest polynomial degree of the fixed-size basis kernels (BasisTable).
inline constexpr int max_degree = 7;
/// The most knots of a knot vector (8·10⁷ doubles, 640 MB): a bound that keeps every count an int
/// and refuses a runaway element count at once instead of with std::bad_alloc.
inline constexpr int max_knots = 80'000'000;
/// The smallest gap between two distinct knots, relative to the knot range (about 4500 round-off
/// units at 1): closer knots are refused as a mistyped repeated knot or a span of round-off.
inline constexpr double min_knot_gap = 1e-12;

/// One element (non-zero knot span) of a knot vector: the parameter interval [first, last] and
/// the span index s with U[s] ≤ u < U[s+1]; its basis functions are N_{s−p}, …, N_s.
struct Element {
  double first;
  double last;
  int span;
};

/// A clamped knot vector U = {u_0, …, u_m} of degree p: non-decreasing, the first and the last
/// value each repeated exactly p+1 times, interior multiplicities ≤ p+1, at least p+1 basis
/// functions (m ≥ 2p+1), distinct knots at least min_knot_gap of the range apart. n = m − p basis
/// functions N_{0,p}, …, N_{n−1,p}.
class KnotVector {
public:
  /// Validates `knots` for `degree` (0 ≤ degree ≤ max_degree); throws spar::Error naming the
  /// problem (decreasing knots, wrong end multiplicity, interior multiplicity above p+1, too few
  /// knots, non-finite values, distinct knots closer than min_knot_gap).
  KnotVector(std::vector<double> knots, int degree);

  /// `elements` (≤ max_knots/(max_degree + 1)) equal elements on [first, last] of degree p and continuity C^k at the interior
  /// knots (each repeated p−k times), −1 ≤ k ≤ p−1.
  static KnotVector open_uniform(int elements, int degree, int continuity, double first = 0.0,
                                 double last = 1.0);

  int degree() const { return degree_; }
  /// n = number of knots − p − 1.
  int basis_count() const { return static_cast<int>(knots_.size()) - degree_ - 1; }
  const std::vector<double>& knots() const { return knots_; }
  double first() const { return knots_.front(); }
  double last() const { return knots_.back(); }

  /// The span s with U[s] ≤ u < U[s+1] by binary search (A2.1); at the right end u = last it is
  /// the last non-zero span. Throws spar::Error for u outside [first, last] or NaN.
  int find_span(double u) const;
  /// How many times u appears in the knot vector (0 if it is not a knot).
  int multiplicity(double u) const;

  /// The distinct knot values, increasing.
  std::vector<double> unique_knots() const;
  /// The number of non-zero knot spans.
  int element_count() const { return static_cast<int>(element_spans_.size()); }
  /// Element e (0 ≤ e < element_count()): its interval and span index.
  Element element(int e) const;
  /// The Greville abscissae ū_i = (u_{i+1} + … + u_{i+p}) / p, i = 0 … n−1 (for p = 0 the
  /// midpoints of the spans).
  std::vector<double> greville() const;

private:
  std::vector<double> knots_;
  int degree_;
  std::vector<int> element_spans_;
};

}  // namespace spar::iga
