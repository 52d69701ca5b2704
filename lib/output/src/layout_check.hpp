#pragma once
/// \file
/// What ResultsWriter's constructor refuses in a layout (docs/output.md, "Time histories"): counts
/// that are negative, names that cannot be dataset names or are given twice, quantities without
/// a unit or a description, shapes at nodes that do not exist or of sizes a shape cannot have.

#include <spar/output/results_writer.hpp>

#include <string>

namespace spar::output::detail {

/// Checks the layout's counts and names and `flush_every` (≥ 1); throws spar::Error naming the
/// field, `where` and the fix.
void check_layout(const ResultsLayout& layout, int flush_every, const std::string& where);

}  // namespace spar::output::detail
