#pragma once
/// \file
/// The result of a finite-difference check of derivatives (core::check_element,
/// joints::check_constraint): for each derivative checked, its worst entry against the central
/// difference, with a pass or fail against the tolerance the user gave, and a printable
/// description.

#include <Eigen/Core>

#include <string>
#include <vector>

namespace spar::core {

/// One derivative (a matrix, or a vector as one column) against its finite difference: the entry
/// where they differ most. The error is relative to the derivative's scale, max(floor, max |FD
/// entry|), not to the entry itself: an entry that vanishes analytically has a finite difference of
/// the size of the round-off, which no entry-wise relative error could judge.
struct DerivativeComparison {
  std::string name;          ///< what was compared, e.g. "stiffness K"
  Eigen::Index row = -1;     ///< the worst entry, in the local order of the element's or
  Eigen::Index column = -1;  ///< constraint's blocks; −1 for an empty derivative
  double analytic = 0.0;           ///< the derivative's value there
  double finite_difference = 0.0;  ///< the central difference's value there
  double scale = 0.0;              ///< max(floor, max |FD entry|) over the derivative
  /// |analytic − finite_difference| / scale at the worst entry; +∞ when an entry of either is not
  /// finite (then that entry is the one reported).
  double error = 0.0;
  double tolerance = 0.0;

  bool passed() const { return error <= tolerance; }
};

/// Compares `analytic` with `finite_difference` entry by entry: the worst entry and its error
/// relative to max(scale_floor, max |FD entry|). Throws spar::InputError when the shapes differ.
DerivativeComparison compare_derivative(std::string name, const Eigen::Ref<const Eigen::MatrixXd>& analytic,
                                        const Eigen::Ref<const Eigen::MatrixXd>& finite_difference,
                                        double tolerance, double scale_floor);

/// Every comparison of one check.
struct DerivativeCheck {
  std::string subject;  ///< what was checked: "core::check_element, element 'spring'"
  std::vector<DerivativeComparison> comparisons;

  /// True when every comparison passed.
  bool passed() const;
  /// The comparison with the largest error relative to its tolerance. Throws spar::InputError
  /// when there is none.
  const DerivativeComparison& worst() const;
  /// The subject and the verdict, then one line per comparison: its worst entry (row, column),
  /// analytic and finite-difference values, error, scale and tolerance.
  std::string description() const;
};

}  // namespace spar::core
