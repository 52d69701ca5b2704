#include <spar/error.hpp>
#include <spar/iga/detail/text.hpp>
#include <spar/iga/knot_operations.hpp>

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

KnotOperator degree_elevation_operator(const KnotVector& U, int t) {
  constexpr const char* where = "iga::degree_elevation_operator";
  const int p = U.degree();
  const int count = U.basis_count();
  if (t < 0 || t > max_degree - p)  // not p + t > max_degree: t near INT_MAX overflowed past the check
    throw Error("elevating degree " + std::to_string(p) + " by " + std::to_string(t) +
                    " is outside 0 … max_degree = " + std::to_string(max_degree),
                where, "elevate by 0 ≤ t ≤ max_degree − p");
  if (t == 0) return {U, Rows::Identity(count, count)};
  // A5.9 assumes interior multiplicities ≤ p: at p + 1 (a discontinuity) it read past its
  // Bézier-point arrays (found by the fuzz test, tests/input/fuzz_test.cpp).
  for (const double u : U.unique_knots())
    if (u != U.first() && u != U.last() && U.multiplicity(u) > p)
      throw Error("the interior knot " + detail::number(u) + " has multiplicity p + 1 = " + std::to_string(p + 1) +
                      " (the curve is discontinuous there); degree elevation needs multiplicities <= p",
                  where, "elevate the pieces on either side of the discontinuity separately");
  const std::vector<double>& knots = U.knots();
  const int m = static_cast<int>(knots.size()) - 1;
  const int ph = p + t;
  const int ph2 = ph / 2;
  const int distinct = static_cast<int>(U.unique_knots().size());
  const int new_knot_count = m + 1 + t * distinct;
  const int new_count = new_knot_count - ph - 1;

  // Coefficients of degree elevation of a Bézier segment: bezalfs(i, j) = C(p,j)C(t,i−j)/C(ph,i).
  Rows bezalfs = Rows::Zero(ph + 1, p + 1);
  bezalfs(0, 0) = bezalfs(ph, p) = 1.0;
  for (int i = 1; i <= ph2; ++i) {
    const double inverse = 1.0 / binomial(ph, i);
    for (int j = std::max(0, i - t); j <= std::min(p, i); ++j)
      bezalfs(i, j) = inverse * binomial(p, j) * binomial(t, i - j);
  }
  for (int i = ph2 + 1; i <= ph - 1; ++i)
    for (int j = std::max(0, i - t); j <= std::min(p, i); ++j)
      bezalfs(i, j) = bezalfs(ph - i, p - j);

  // A5.9 applied to the rows of the identity.
  const Rows P = Rows::Identity(count, count);
  Rows Q = Rows::Zero(new_count, count);
  Rows bpts = P.topRows(p + 1);
  Rows ebpts = Rows::Zero(ph + 1, count);
  Rows next_bpts = Rows::Zero(std::max(p - 1, 1), count);
  std::vector<double> Uh(new_knot_count);
  std::vector<double> alfs(std::max(p - 1, 1));
  int mh = ph, kind = ph + 1;
  int r = -1, a = p, b = p + 1, cind = 1;
  double ua = knots[0];
  Q.row(0) = P.row(0);
  for (int i = 0; i <= ph; ++i) Uh[i] = ua;
  while (b < m) {
    const int i0 = b;
    while (b < m && knots[b] == knots[b + 1]) ++b;
    const int mul = b - i0 + 1;
    mh += mul + t;
    const double ub = knots[b];
    const int oldr = r;
    r = p - mul;
    const int lbz = oldr > 0 ? (oldr + 2) / 2 : 1;
    const int rbz = r > 0 ? ph - (r + 1) / 2 : ph;
    if (r > 0) {
      // Insert ub r times to end the current Bézier segment.
      const double numer = ub - ua;
      for (int k = p; k > mul; --k) alfs[k - mul - 1] = numer / (knots[a + k] - ua);
      for (int j = 1; j <= r; ++j) {
        const int save = r - j, s = mul + j;
        for (int k = p; k >= s; --k)
          bpts.row(k) = alfs[k - s] * bpts.row(k) + (1.0 - alfs[k - s]) * bpts.row(k - 1);
        next_bpts.row(save) = bpts.row(p);
      }
    }
    // Degree elevate the Bézier segment.
    for (int i = lbz; i <= ph; ++i) {
      ebpts.row(i).setZero();
      for (int j = std::max(0, i - t); j <= std::min(p, i); ++j)
        ebpts.row(i) += bezalfs(i, j) * bpts.row(j);
    }
    if (oldr > 1) {
      // Remove the knot ua oldr − 1 times again.
      int first = kind - 2, last = kind;
      const double den = ub - ua;
      const double bet = (ub - Uh[kind - 1]) / den;
      for (int tr = 1; tr < oldr; ++tr) {
        int i = first, j = last, kj = j - kind + 1;
        while (j - i > tr) {
          if (i < cind) {
            const double alf = (ub - Uh[i]) / (ua - Uh[i]);
            Q.row(i) = alf * Q.row(i) + (1.0 - alf) * Q.row(i - 1);
          }
          if (j >= lbz) {
            if (j - tr <= kind - ph + oldr) {
              const double gam = (ub - Uh[j - tr]) / den;
              ebpts.row(kj) = gam * ebpts.row(kj) + (1.0 - gam) * ebpts.row(kj + 1);
            } else {
              ebpts.row(kj) = bet * ebpts.row(kj) + (1.0 - bet) * ebpts.row(kj + 1);
            }
          }
          ++i;
          --j;
          --kj;
        }
        --first;
        ++last;
      }
    }
    if (a != p)
      for (int i = 0; i < ph - oldr; ++i) Uh[kind++] = ua;
    for (int j = lbz; j <= rbz; ++j) Q.row(cind++) = ebpts.row(j);
    if (b < m) {
      for (int j = 0; j < r; ++j) bpts.row(j) = next_bpts.row(j);
      for (int j = r; j <= p; ++j) bpts.row(j) = P.row(b - p + j);
      a = b;
      ++b;
      ua = ub;
    } else {
      for (int i = 0; i <= ph; ++i) Uh[kind + i] = ub;
    }
  }
  if (mh - ph != new_count)
    throw Error("internal inconsistency in degree elevation", where, "report this as a bug");
  return {KnotVector(std::move(Uh), ph), std::move(Q)};
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
