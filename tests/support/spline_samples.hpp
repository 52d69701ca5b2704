#pragma once
// Seeded random knot vectors and NURBS curves for property tests: non-uniform interior knots with
// repeated values, and weights in [0.5, 2] so that rational effects are visible.
#include <spar/iga/knot_vector.hpp>
#include <spar/iga/nurbs_curve.hpp>

#include <Eigen/Core>

#include <random>
#include <vector>

namespace spar::test {

class SplineSamples {
public:
  explicit SplineSamples(unsigned seed) : engine_(seed) {}

  double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(engine_); }

  /// Degree p on [first, last] with `elements` non-uniform elements; each interior knot is
  /// repeated 1 … max_multiplicity times.
  iga::KnotVector knot_vector(int p, int elements, int max_multiplicity = 1, double first = 0.0,
                              double last = 1.0) {
    std::vector<double> breaks{first};
    for (int e = 1; e < elements; ++e) breaks.push_back(first + (last - first) * (e + uniform(-0.3, 0.3)) / elements);
    breaks.push_back(last);
    std::vector<double> knots(p + 1, first);
    for (int e = 1; e < elements; ++e) {
      const int repeat = 1 + static_cast<int>(engine_() % static_cast<unsigned>(max_multiplicity));
      knots.insert(knots.end(), repeat, breaks[e]);
    }
    knots.insert(knots.end(), p + 1, last);
    return iga::KnotVector(knots, p);
  }

  /// A curve on `knots` with random control points in [−1, 1]^Dim and weights in [0.5, 2]
  /// (all 1 when rational is false).
  template <int Dim>
  iga::NurbsCurve<Dim> curve(const iga::KnotVector& knots, bool rational = true) {
    const int n = knots.basis_count();
    typename iga::NurbsCurve<Dim>::Points points(Dim, n);
    for (int i = 0; i < n; ++i)
      for (int d = 0; d < Dim; ++d) points(d, i) = uniform(-1.0, 1.0);
    Eigen::VectorXd weights = Eigen::VectorXd::Ones(n);
    if (rational)
      for (int i = 0; i < n; ++i) weights(i) = uniform(0.5, 2.0);
    return iga::NurbsCurve<Dim>(knots, points, weights);
  }

  /// A parameter inside element e at distance ≥ margin from its ends.
  double inside(const iga::KnotVector& knots, int e, double margin) {
    const iga::Element element = knots.element(e);
    return uniform(element.first + margin, element.last - margin);
  }

private:
  std::mt19937 engine_;
};

}  // namespace spar::test
