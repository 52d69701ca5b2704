#include "spline_case.hpp"

#include <spar/iga/iga.hpp>

#include <algorithm>
#include <optional>

namespace spar::fuzz {

namespace {

/// A clamped knot vector of degree p, sometimes broken (unsorted, wrong end multiplicity, NaN).
std::vector<double> fuzz_knots(FuzzSource& f, int p) {
  const int interior = f.integer(0, 6);
  std::vector<double> knots(std::max(p, 0) + 1, 0.0);
  for (int i = 0; i < interior; ++i) {
    const double u = f.uniform(0.0, 1.0);
    const int repeat = f.integer(1, std::max(p, 1) + (f.chance(0.05) ? 1 : 0));
    knots.insert(knots.end(), repeat, u);
  }
  knots.insert(knots.end(), std::max(p, 0) + 1, 1.0);
  if (!f.chance(0.1)) std::sort(knots.begin(), knots.end());
  for (double& u : knots) u = f.value(u, 0.02);
  if (f.chance(0.05) && !knots.empty()) knots.pop_back();
  if (f.chance(0.05)) knots.push_back(f.value(1.0, 0.5));
  return knots;
}

/// "{ 0, 0.5, 1 }" for the log.
std::string listed(const std::vector<double>& values) {
  std::ostringstream out;
  out << "{";
  for (std::size_t i = 0; i < values.size(); ++i) out << (i ? ", " : " ") << values[i];
  out << " }";
  return out.str();
}

/// The largest distance between two curves at `samples` parameters over the knot range,
/// relative to the size of the control net; parameters where either curve's evaluation overflows
/// (a spar::Error) are skipped.
double curve_difference(const iga::NurbsCurve<3>& a, const iga::NurbsCurve<3>& b, int samples) {
  const double scale = std::max(1.0, a.control_points().cwiseAbs().maxCoeff());
  double difference = 0.0;
  for (int i = 0; i <= samples; ++i) {
    const double u = a.knots().first() + (a.knots().last() - a.knots().first()) * i / samples;
    try {
      difference = std::max(difference, (a.point(u) - b.point(u)).cwiseAbs().maxCoeff() / scale);
    } catch (const Error&) {
    }
  }
  return difference;
}

/// The curve keeps its shape through `operation` (a RefinedCurve), if the operation is accepted.
template <class Operation>
bool keeps_curve(const iga::NurbsCurve<3>& curve, Operation&& operation, const char* what, CaseLog& log) {
  std::optional<iga::RefinedCurve<3>> refined;
  if (!accepted([&] { refined.emplace(operation()); }, what, log)) return false;
  const double difference = curve_difference(curve, refined->curve, 20);
  log.check(difference <= 1e-10, std::string(what) + " moved the curve by " + significant(difference));
  return true;
}

/// Evaluation, insertion, refinement, elevation and h-refinement of a curve that was built.
bool curve_properties(FuzzSource& f, const iga::KnotVector& U, const iga::NurbsCurve<3>& curve, int p,
                      CaseLog& log) {
  // Evaluation: inside, at the ends, outside the knot range and at NaN.
  for (int k = 0; k < 3; ++k) {
    const double u = log.note("evaluate at", f.value(f.uniform(U.first(), U.last()), 0.1));
    const int order = log.note("derivative order", f.chance(0.05) ? f.integer(-1, 12) : f.integer(0, 2));
    iga::NurbsCurve<3>::Derivatives d;
    if (accepted([&] { d = curve.derivatives(u, order); }, "NurbsCurve::derivatives", log))
      log.check(d.allFinite(), "NurbsCurve::derivatives returned a non-finite value");
  }
  const double u = log.note("insert", f.value(f.uniform(U.first(), U.last()), 0.05));
  const int times = log.note("times", f.chance(0.05) ? f.count(1, 1.0) : f.integer(1, p + 1));
  const bool inserted = keeps_curve(curve, [&] { return iga::insert_knot(curve, u, times); }, "insert_knot", log);

  std::vector<double> X(f.integer(0, 4));
  for (double& x : X) x = f.value(f.uniform(U.first(), U.last()), 0.03);
  if (!f.chance(0.05)) std::sort(X.begin(), X.end());
  log.note("refine with", listed(X));
  keeps_curve(curve, [&] { return iga::refine_knots(curve, X); }, "refine_knots", log);

  const int t = log.note("elevate by", f.chance(0.05) ? f.count(1, 1.0) : f.integer(0, 2));
  keeps_curve(curve, [&] { return iga::elevate_degree(curve, t); }, "elevate_degree", log);

  const int per_span = log.note("h-refine by", f.chance(0.05) ? f.count(2, 1.0) : f.integer(1, 3));
  keeps_curve(curve, [&] { return iga::h_refine(curve, per_span); }, "h_refine", log);
  return inserted;
}

}  // namespace

SplineOutcome spline_case(FuzzSource& f, CaseLog& log) {
  SplineOutcome outcome;
  const int p = log.note("degree", f.chance(0.05) ? f.integer(-2, 10) : f.integer(1, 4));
  const std::vector<double> knots = fuzz_knots(f, p);
  log.note("knots", listed(knots));
  std::optional<iga::KnotVector> U;
  if (accepted([&] { U.emplace(knots, p); }, "KnotVector", log)) {
    const int n = U->basis_count() + (f.chance(0.03) ? f.integer(-1, 1) : 0);
    Eigen::Matrix3Xd points(3, std::max(n, 0));
    Eigen::VectorXd weights(std::max(n, 0) + (f.chance(0.03) ? 1 : 0));
    for (int i = 0; i < points.cols(); ++i) points.col(i) = f.vector(10.0, 0.01);
    for (int i = 0; i < weights.size(); ++i) weights(i) = f.value(f.uniform(0.2, 5.0), 0.01);
    log.note("control points", points);
    log.note("weights", weights.transpose());
    std::optional<iga::NurbsCurve<3>> curve;
    if (accepted([&] { curve.emplace(*U, points, weights); }, "NurbsCurve", log)) {
      outcome.curve = true;
      outcome.refined = curve_properties(f, *U, *curve, p, log);
      // Extraction: Σ_a N_a = 1 = Σ_b B_b, so every column of every operator sums to 1.
      std::vector<Eigen::MatrixXd> C;
      if (accepted([&] { C = iga::bezier_extraction(*U); }, "bezier_extraction", log))
        for (const Eigen::MatrixXd& Ce : C)
          log.check((Ce.colwise().sum().array() - 1.0).abs().maxCoeff() <= 1e-12,
                    "a column of a Bézier extraction operator does not sum to 1");
    }
  }
  // An open-uniform vector of any requested size, degree and continuity.
  const int elements = log.note("open_uniform elements", f.count(f.integer(1, 20)));
  const int degree = log.note("open_uniform degree", f.count(f.integer(0, 5)));
  const int continuity = log.note("open_uniform continuity", f.integer(-2, 5));
  const double first = log.note("open_uniform first", f.value(0.0));
  const double last = log.note("open_uniform last", f.value(1.0));
  accepted([&] { iga::KnotVector::open_uniform(elements, degree, continuity, first, last); }, "open_uniform", log);
  return outcome;
}

}  // namespace spar::fuzz
