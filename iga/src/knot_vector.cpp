#include <spar/error.hpp>
#include <spar/iga/detail/text.hpp>
#include <spar/iga/knot_vector.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace spar::iga {

namespace {

constexpr const char* where = "iga::KnotVector";

}  // namespace

KnotVector::KnotVector(std::vector<double> knots, int degree)
    : knots_(std::move(knots)), degree_(degree) {
  using detail::number;
  if (degree_ < 0 || degree_ > max_degree)
    throw Error("degree " + std::to_string(degree_) + " is outside 0 … " +
                    std::to_string(max_degree),
                where, "use a degree between 0 and iga::max_degree");
  if (knots_.size() > static_cast<std::size_t>(max_knots))
    throw Error(std::to_string(knots_.size()) + " knots are more than iga::max_knots = " + std::to_string(max_knots),
                where, "use fewer elements");
  const int p = degree_;
  const int size = static_cast<int>(knots_.size());
  if (size < 2 * p + 2)
    throw Error("too few knots: " + std::to_string(size) + " knots give fewer than p+1 = " +
                    std::to_string(p + 1) + " basis functions (too few control points)",
                where, "a clamped knot vector of degree p needs at least 2p+2 knots");
  for (int i = 0; i < size; ++i)
    if (!std::isfinite(knots_[i]))
      throw Error("knot " + std::to_string(i) + " is not finite", where,
                  "give finite knot values");
  for (int i = 1; i < size; ++i)
    if (knots_[i] < knots_[i - 1])
      throw Error("decreasing knots: u_" + std::to_string(i) + " = " + number(knots_[i]) +
                      " < u_" + std::to_string(i - 1) + " = " + number(knots_[i - 1]),
                  where, "sort the knots in non-decreasing order");
  if (!(knots_.front() < knots_.back()))
    throw Error("the knot range is empty (first knot = last knot)", where,
                "give distinct first and last knots");
  // Distinct knots closer than min_knot_gap of the range are a repeated knot mistyped, or a span
  // so short that its basis functions and every refinement of it are round-off (found by the
  // fuzz test: a span of 5e-324 h-refined to a curve 13 % away from the original).
  const double min_gap = min_knot_gap * (knots_.back() - knots_.front());
  for (int i = 1; i < size; ++i)
    if (knots_[i] != knots_[i - 1] && knots_[i] - knots_[i - 1] < min_gap)
      throw Error("the knots u_" + std::to_string(i - 1) + " = " + number(knots_[i - 1]) + " and u_" +
                      std::to_string(i) + " = " + number(knots_[i]) + " differ by less than " +
                      number(min_knot_gap) + " of the knot range",
                  where, "repeat the knot exactly, or space the knots further apart");
  const int first_multiplicity = multiplicity(knots_.front());
  const int last_multiplicity = multiplicity(knots_.back());
  if (first_multiplicity != p + 1 || last_multiplicity != p + 1)
    throw Error("end multiplicities are " + std::to_string(first_multiplicity) + " and " +
                    std::to_string(last_multiplicity) + ", not p+1 = " + std::to_string(p + 1),
                where, "repeat the first and the last knot exactly p+1 times (clamped knots)");
  for (int i = 0; i < size;) {
    int j = i;
    while (j + 1 < size && knots_[j + 1] == knots_[i]) ++j;
    if (j - i + 1 > p + 1)
      throw Error("multiplicity " + std::to_string(j - i + 1) + " of the interior knot " +
                      number(knots_[i]) + " is above p+1 = " + std::to_string(p + 1),
                  where, "repeat an interior knot at most p+1 times");
    if (j + 1 < size) element_spans_.push_back(j);
    i = j + 1;
  }
}

KnotVector KnotVector::open_uniform(int elements, int degree, int continuity, double first,
                                    double last) {
  if (elements < 1 || elements > max_knots / (max_degree + 1))
    throw Error("open_uniform needs 1 to " + std::to_string(max_knots / (max_degree + 1)) + " elements, got " +
                    std::to_string(elements),
                "iga::KnotVector::open_uniform", "ask for one element or more, within the limit");
  if (degree < 0 || degree > max_degree)
    throw Error("degree " + std::to_string(degree) + " is outside 0 … " + std::to_string(max_degree),
                "iga::KnotVector::open_uniform", "use a degree between 0 and iga::max_degree");
  if (continuity < -1 || continuity > degree - 1)
    throw Error("continuity C^" + std::to_string(continuity) + " is impossible for degree " +
                    std::to_string(degree),
                "iga::KnotVector::open_uniform", "choose −1 ≤ continuity ≤ degree − 1");
  if (!(first < last))
    throw Error("the parameter range [" + detail::number(first) + ", " + detail::number(last) +
                    "] is empty",
                "iga::KnotVector::open_uniform", "give first < last");
  const int repeat = degree - continuity;
  std::vector<double> knots(degree + 1, first);
  for (int e = 1; e < elements; ++e) {
    // Interpolate from both ends so that the knots are symmetric about the midpoint.
    const double t = static_cast<double>(e) / elements;
    const double u = (1.0 - t) * first + t * last;
    knots.insert(knots.end(), repeat, u);
  }
  knots.insert(knots.end(), degree + 1, last);
  return KnotVector(std::move(knots), degree);
}

int KnotVector::find_span(double u) const {
  if (!(u >= first() && u <= last()))
    throw Error("parameter u = " + detail::number(u) + " is outside the knot range [" +
                    detail::number(first()) + ", " + detail::number(last()) + "]",
                "iga::KnotVector::find_span", "evaluate inside the knot range");
  const int n = basis_count();
  if (u >= knots_[n]) return n - 1;
  // A2.1 by bisection: the last index s with U[s] ≤ u; the clamped start guarantees s ≥ p.
  const auto above = std::upper_bound(knots_.begin() + degree_, knots_.begin() + n + 1, u);
  return static_cast<int>(above - knots_.begin()) - 1;
}

int KnotVector::multiplicity(double u) const {
  const auto range = std::equal_range(knots_.begin(), knots_.end(), u);
  return static_cast<int>(range.second - range.first);
}

std::vector<double> KnotVector::unique_knots() const {
  std::vector<double> unique(knots_);
  unique.erase(std::unique(unique.begin(), unique.end()), unique.end());
  return unique;
}

Element KnotVector::element(int e) const {
  if (e < 0 || e >= element_count())
    throw Error("element " + std::to_string(e) + " does not exist (the knot vector has " +
                    std::to_string(element_count()) + " elements)",
                "iga::KnotVector::element", "use 0 ≤ e < element_count()");
  const int span = element_spans_[e];
  return Element{knots_[span], knots_[span + 1], span};
}

std::vector<double> KnotVector::greville() const {
  const int n = basis_count();
  std::vector<double> abscissae(n);
  for (int i = 0; i < n; ++i) {
    if (degree_ == 0) {
      abscissae[i] = 0.5 * (knots_[i] + knots_[i + 1]);
      continue;
    }
    double sum = 0.0;
    for (int k = 1; k <= degree_; ++k) sum += knots_[i + k];
    abscissae[i] = sum / degree_;
  }
  return abscissae;
}

}  // namespace spar::iga
