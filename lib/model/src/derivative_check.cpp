#include <spar/core/derivative_check.hpp>
#include <spar/error.hpp>

#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

namespace spar::core {

DerivativeComparison compare_derivative(std::string name, const Eigen::Ref<const Eigen::MatrixXd>& analytic,
                                        const Eigen::Ref<const Eigen::MatrixXd>& finite_difference,
                                        double tolerance, double scale_floor) {
  if (analytic.rows() != finite_difference.rows() || analytic.cols() != finite_difference.cols())
    throw InputError(name + " is " + std::to_string(analytic.rows()) + "x" + std::to_string(analytic.cols()) +
                         ", its finite difference " + std::to_string(finite_difference.rows()) + "x" +
                         std::to_string(finite_difference.cols()),
                     "core::compare_derivative", "compare a derivative with the difference of the same function");
  DerivativeComparison result{.name = std::move(name), .tolerance = tolerance};
  const auto report = [&](Eigen::Index i, Eigen::Index j) {
    result.row = i;
    result.column = j;
    result.analytic = analytic(i, j);
    result.finite_difference = finite_difference(i, j);
  };
  double largest = scale_floor, worst = -1.0;
  for (Eigen::Index j = 0; j < analytic.cols(); ++j)
    for (Eigen::Index i = 0; i < analytic.rows(); ++i) {
      if (!std::isfinite(analytic(i, j)) || !std::isfinite(finite_difference(i, j))) {
        report(i, j);
        result.scale = std::numeric_limits<double>::quiet_NaN();
        result.error = std::numeric_limits<double>::infinity();
        return result;
      }
      largest = std::max(largest, std::abs(finite_difference(i, j)));
      const double difference = std::abs(analytic(i, j) - finite_difference(i, j));
      if (difference > worst) {
        worst = difference;
        report(i, j);
      }
    }
  result.scale = largest;
  if (worst > 0.0) result.error = largest > 0.0 ? worst / largest : std::numeric_limits<double>::infinity();
  return result;
}

bool DerivativeCheck::passed() const {
  for (const DerivativeComparison& c : comparisons)
    if (!c.passed()) return false;
  return true;
}

const DerivativeComparison& DerivativeCheck::worst() const {
  if (comparisons.empty())
    throw InputError("the check holds no comparison", "core::DerivativeCheck::worst (" + subject + ")",
                     "ask a result of core::check_element or joints::check_constraint");
  // error / tolerance; a zero error is 0 even for a zero tolerance.
  const auto ratio = [](const DerivativeComparison& c) { return c.error == 0.0 ? 0.0 : c.error / c.tolerance; };
  const DerivativeComparison* worst = &comparisons.front();
  for (const DerivativeComparison& c : comparisons)
    if (ratio(c) > ratio(*worst)) worst = &c;
  return *worst;
}

std::string DerivativeCheck::description() const {
  std::ostringstream text;
  text.precision(10);
  text << subject << ": " << (passed() ? "passed" : "FAILED");
  for (const DerivativeComparison& c : comparisons) {
    text << "\n  " << c.name << ": ";
    if (c.row < 0) {
      text << "empty";
      continue;
    }
    text << "worst entry (" << c.row << ", " << c.column << "): analytic " << c.analytic << ", finite difference "
         << c.finite_difference << ", error " << c.error << " of scale " << c.scale << ", tolerance "
         << c.tolerance << (c.passed() ? " - passed" : " - FAILED");
  }
  return text.str();
}

}  // namespace spar::core
