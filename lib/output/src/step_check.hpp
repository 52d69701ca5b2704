#pragma once
/// \file
/// What ResultsWriter::append refuses in a step (docs/output.md, "Time histories"): a time that is
/// not after the previous step's, an entry count that does not match the layout, a value that is
/// not finite (NaN only in a scalar or probe declared may_be_undefined), a counter that is not a
/// whole number of 32 bits.

#include <spar/output/results_writer.hpp>

#include <string>

namespace spar::output::detail {

/// The place of a step in its run, for the check and its messages.
struct StepPosition {
  const std::string& where;  ///< the call, e.g. "output::ResultsWriter::append(run.h5)"
  int index = 0;             ///< the step's number, 0 for the first
  double last_time = 0;      ///< the previous step's time, if index > 0
};

/// Checks `step` against `layout`; throws spar::Error naming the field, the expected size or the
/// bad value, `position.where` and the step's number.
void check_step(const ResultsLayout& layout, const ResultsStep& step, const StepPosition& position);

}  // namespace spar::output::detail
