#pragma once
/// \file
/// spar::output — results files (HDF5 with an XDMF sidecar for ParaView, CSV), the JSON summary
/// line and the progress bar.

#include <spar/output/hdf5_file.hpp>
#include <spar/output/progress_bar.hpp>
#include <spar/output/provenance.hpp>
#include <spar/output/recording_csv.hpp>
#include <spar/output/recording_summary.hpp>
#include <spar/output/results_writer.hpp>
