#include <spar/error.hpp>
#include <spar/iga/bezier_extraction.hpp>
#include <spar/iga/detail/text.hpp>
#include <spar/iga/knot_operations.hpp>

#include <Eigen/SparseCore>
#include <Eigen/SparseQR>

#include <algorithm>
#include <string>

namespace spar::iga {

namespace {

using Rows = Eigen::MatrixXd;

void check_interior(const KnotVector& U, double u, const char* where) {
  if (!(u > U.first() && u < U.last()))
    throw Error("knot " + detail::number(u) + " is not strictly inside the knot range (" +
                    detail::number(U.first()) + ", " + detail::number(U.last()) + ")",
                where, "insert knots between the first and the last knot");
}

double binomial(int n, int k) {
  double value = 1.0;
  for (int i = 1; i <= k; ++i) value = value * (n - k + i) / i;
  return value;
}

}  // namespace

KnotOperator knot_insertion_operator(const KnotVector& U, double u, int times) {
  constexpr const char* where = "iga::knot_insertion_operator";
  check_interior(U, u, where);
  const int p = U.degree();
  const int s = U.multiplicity(u);
  if (times < 1 || times > p - s)  // not s + times > p: times near INT_MAX overflowed past the check
    throw Error("inserting " + detail::number(u) + " " + std::to_string(times) +
                    " times would give multiplicity " + std::to_string(static_cast<long long>(s) + times) +
                    " (allowed: 1 … p = " + std::to_string(p) + ")",
                where, "insert at least once and at most p − multiplicity times");
  const std::vector<double>& UP = U.knots();
  const int n = U.basis_count();
  const int k = U.find_span(u);
  const int r = times;
  std::vector<double> UQ(UP.begin(), UP.begin() + k + 1);
  UQ.insert(UQ.end(), r, u);
  UQ.insert(UQ.end(), UP.begin() + k + 1, UP.end());

  // A5.1 applied to the rows of the identity: row i of the result is new control point i as a
  // combination of the old ones.
  const Rows P = Rows::Identity(n, n);
  Rows Q(n + r, n);
  Q.topRows(k - p + 1) = P.topRows(k - p + 1);
  Q.bottomRows(n - k + s) = P.bottomRows(n - k + s);
  Rows R = P.middleRows(k - p, p - s + 1);
  int L = k - p;
  for (int j = 1; j <= r; ++j) {
    L = k - p + j;
    for (int i = 0; i <= p - j - s; ++i) {
      const double alpha = (u - UP[L + i]) / (UP[i + k + 1] - UP[L + i]);
      R.row(i) = alpha * R.row(i + 1) + (1.0 - alpha) * R.row(i);
    }
    Q.row(L) = R.row(0);
    Q.row(k + r - j - s) = R.row(p - j - s);
  }
  for (int i = L + 1; i < k - s; ++i) Q.row(i) = R.row(i - L);
  return {KnotVector(std::move(UQ), p), std::move(Q)};
}

KnotOperator knot_refinement_operator(const KnotVector& U, const std::vector<double>& X) {
  constexpr const char* where = "iga::knot_refinement_operator";
  const int p = U.degree();
  const int count = U.basis_count();
  if (X.empty()) return {U, Rows::Identity(count, count)};
  if (X.size() > static_cast<std::size_t>(max_knots) - U.knots().size())
    throw Error(std::to_string(X.size()) + " knots to insert would exceed iga::max_knots = " + std::to_string(max_knots),
                where, "insert fewer knots");
  for (std::size_t j = 0; j < X.size(); ++j) {
    check_interior(U, X[j], where);
    if (j > 0 && X[j] < X[j - 1])
      throw Error("decreasing knots to insert: " + detail::number(X[j]) + " after " +
                      detail::number(X[j - 1]),
                  where, "sort the knots to insert");
  }
  const std::vector<double>& knots = U.knots();
  // A5.4 with the book's indices: n = last control point index, m = last knot index,
  // r = last index of X; applied to the rows of the identity.
  const int n = count - 1;
  const int m = n + p + 1;
  const int r = static_cast<int>(X.size()) - 1;
  const int a = U.find_span(X.front());
  const int b = U.find_span(X.back()) + 1;
  const Rows P = Rows::Identity(count, count);
  Rows Q = Rows::Zero(n + r + 2, count);
  std::vector<double> Ubar(m + r + 2);
  for (int j = 0; j <= a - p; ++j) Q.row(j) = P.row(j);
  for (int j = b - 1; j <= n; ++j) Q.row(j + r + 1) = P.row(j);
  for (int j = 0; j <= a; ++j) Ubar[j] = knots[j];
  for (int j = b + p; j <= m; ++j) Ubar[j + r + 1] = knots[j];
  int i = b + p - 1;
  int k = b + p + r;
  for (int j = r; j >= 0; --j) {
    while (X[j] <= knots[i] && i > a) {
      Q.row(k - p - 1) = P.row(i - p - 1);
      Ubar[k] = knots[i];
      --k;
      --i;
    }
    Q.row(k - p - 1) = Q.row(k - p);
    for (int l = 1; l <= p; ++l) {
      const int ind = k - p + l;
      double alpha = Ubar[k + l] - X[j];
      if (alpha == 0.0) {
        Q.row(ind - 1) = Q.row(ind);
      } else {
        // The first printing of the book has U[i−l+1] here; the convex-combination weight of
        // the knot span [U[i−p+l], Ubar[k+l]] needs U[i−p+l] (checked against A5.1 in the tests).
        alpha /= Ubar[k + l] - knots[i - p + l];
        Q.row(ind - 1) = alpha * Q.row(ind - 1) + (1.0 - alpha) * Q.row(ind);
      }
    }
    Ubar[k] = X[j];
    --k;
  }
  return {KnotVector(std::move(Ubar), p), std::move(Q)};
}

namespace {

// The exact zeros of the elevation operator T (new control point i from old j), which the QR
// solve leaves as round-off: a weight of 1e300 times 1e-17 is no zero (found by the seeded fuzz
// test). Column j is the elevated N_j, whose knots u_j … u_{j+p+1} each gain t repetitions: a run
// [low, high] of Û, so T(i, j) ≠ 0 only for the N̂_i whose knots û_i … û_{i+p+t+1} lie in that run.
void keep_elevation_structure(const KnotVector& U, const KnotVector& Uh, Rows& T) {
  const int p = U.degree(), ph = Uh.degree(), t = ph - p;
  const std::vector<double>& u = U.knots();
  const std::vector<double>& uh = Uh.knots();
  for (int j = 0; j < T.cols(); ++j) {
    const double a = u[j], b = u[j + p + 1];
    const auto local = [&](double value) {
      return static_cast<int>(std::count(u.begin() + j, u.begin() + j + p + 2, value));
    };
    // The last (local multiplicity + t) copies of a in Û, the first ones of b.
    const int low = static_cast<int>(std::upper_bound(uh.begin(), uh.end(), a) - uh.begin()) - (local(a) + t);
    const int high = static_cast<int>(std::lower_bound(uh.begin(), uh.end(), b) - uh.begin()) + (local(b) + t) - 1;
    for (int i = 0; i < T.rows(); ++i)
      if (i < low || i + ph + 1 > high) T(i, j) = 0.0;
  }
}

}  // namespace

// Degree elevation through the Bézier form of each element, in three steps:
//   1. the Bézier points of element e of U are C_eᵀ P_e (C_e its extraction operator, P_e its
//      p + 1 control points; knot insertion, convex combinations),
//   2. elevated to degree p + t: E_e = Λ C_eᵀ P_e with Λ(i, j) = C(p, j) C(t, i − j) / C(p + t, i)
//      (The NURBS Book eq. 5.36),
//   3. the control points Q on the elevated knot vector Û (each distinct knot repeated t times
//      more) solve Ĉ_eᵀ Q_e = E_e for every element at once: an overdetermined but consistent
//      sparse system, solved by QR.
// The result is A5.9's in exact arithmetic. A5.9 itself goes back from step 2 by knot removal,
// whose factors (u_b − U_i)/(u_a − U_i) extrapolate where neighbouring spans differ in length: a
// knot 1.3e-5 from the end next to a span of 0.84 (p = 6 → 7) moved the curve by 7e-8 of its size
// (found by libFuzzer, fuzz/spline_fuzzer). The system of step 3 is as well conditioned as the
// B-spline basis itself, which de Boor's stability bound makes independent of the knot spacing.
KnotOperator degree_elevation_operator(const KnotVector& U, int t) {
  constexpr const char* where = "iga::degree_elevation_operator";
  const int p = U.degree();
  const int count = U.basis_count();
  if (t < 0 || t > max_degree - p)  // not p + t > max_degree: t near INT_MAX overflowed past the check
    throw Error("elevating degree " + std::to_string(p) + " by " + std::to_string(t) +
                    " is outside 0 … max_degree = " + std::to_string(max_degree),
                where, "elevate by 0 ≤ t ≤ max_degree − p");
  if (t == 0) return {U, Rows::Identity(count, count)};
  // A curve with a discontinuity is refused (kept from A5.9, which read past its arrays there:
  // found by the fuzz test); elevating each piece is the way.
  for (const double u : U.unique_knots())
    if (u != U.first() && u != U.last() && U.multiplicity(u) > p)
      throw Error("the interior knot " + detail::number(u) + " has multiplicity p + 1 = " + std::to_string(p + 1) +
                      " (the curve is discontinuous there); degree elevation needs multiplicities <= p",
                  where, "elevate the pieces on either side of the discontinuity separately");
  const int ph = p + t;
  std::vector<double> elevated_knots;
  for (const double u : U.unique_knots()) elevated_knots.insert(elevated_knots.end(), U.multiplicity(u) + t, u);
  KnotVector Uh(std::move(elevated_knots), ph);

  // Λ: the Bézier points of degree ph of a Bézier segment of degree p.
  Rows elevation = Rows::Zero(ph + 1, p + 1);
  for (int i = 0; i <= ph; ++i)
    for (int j = std::max(0, i - t); j <= std::min(p, i); ++j)
      elevation(i, j) = binomial(p, j) * binomial(t, i - j) / binomial(ph, i);

  const std::vector<Eigen::MatrixXd> C = bezier_extraction(U), Ch = bezier_extraction(Uh);
  const int elements = U.element_count();
  Eigen::SparseMatrix<double> system(elements * (ph + 1), Uh.basis_count());
  Rows elevated_bezier = Rows::Zero(elements * (ph + 1), count);
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(static_cast<std::size_t>(elements) * (ph + 1) * (ph + 1));
  for (int e = 0; e < elements; ++e) {
    const int row = e * (ph + 1);
    // Bézier point i of the elevated element: Σ_a Ĉ_e(a, i) Q_{ŝ−ph+a}.
    const int first_elevated = Uh.element(e).span - ph;
    for (int a = 0; a <= ph; ++a)
      for (int i = 0; i <= ph; ++i)
        if (Ch[e](a, i) != 0.0) entries.emplace_back(row + i, first_elevated + a, Ch[e](a, i));
    // ... equals row i of Λ C_eᵀ applied to P_{s−p}, …, P_s.
    elevated_bezier.block(row, U.element(e).span - p, ph + 1, p + 1) = elevation * C[e].transpose();
  }
  system.setFromTriplets(entries.begin(), entries.end());
  system.makeCompressed();
  Eigen::SparseQR<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> qr(system);
  if (qr.info() != Eigen::Success || qr.rank() != Uh.basis_count())
    throw Error("the elevated Bézier extraction has rank " + std::to_string(qr.rank()) + " of " +
                    std::to_string(Uh.basis_count()),
                where, "report this as a bug, with the knot vector");
  Rows Q = qr.solve(elevated_bezier);
  keep_elevation_structure(U, Uh, Q);
  return {std::move(Uh), std::move(Q)};
}

std::vector<double> uniform_refinement_knots(const KnotVector& U, int elements_per_span) {
  if (elements_per_span < 1 || elements_per_span > max_knots / U.element_count())
    throw Error("elements_per_span = " + std::to_string(elements_per_span) + " is outside 1 … " +
                    std::to_string(max_knots / U.element_count()) + " (iga::max_knots over " +
                    std::to_string(U.element_count()) + " elements)",
                "iga::uniform_refinement_knots", "split every element into one part or more, within the limit");
  std::vector<double> X;
  for (int e = 0; e < U.element_count(); ++e) {
    const Element element = U.element(e);
    for (int i = 1; i < elements_per_span; ++i) {
      const double t = static_cast<double>(i) / elements_per_span;
      X.push_back((1.0 - t) * element.first + t * element.last);
    }
  }
  return X;
}

}  // namespace spar::iga
