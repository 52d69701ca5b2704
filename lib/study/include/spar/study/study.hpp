#pragma once
/// \file
/// spar::study — what a driver needs besides the model and the solvers: its command line
/// (options, checks of what a run may ask), the recording of a run (the results file, the CSV,
/// snapshots, the running reductions of the summary) and the static stability warning. Uses the
/// solvers, the joints and the output; names no element kind.

#include <spar/output/recording_csv.hpp>
#include <spar/output/recording_summary.hpp>
#include <spar/study/command_line.hpp>
#include <spar/study/energy_ledger.hpp>
#include <spar/study/integrator_options.hpp>
#include <spar/study/recorder.hpp>
#include <spar/study/run_limits.hpp>
#include <spar/study/schedule.hpp>
#include <spar/study/state.hpp>
#include <spar/study/static_stability.hpp>
#include <spar/study/statistics.hpp>
