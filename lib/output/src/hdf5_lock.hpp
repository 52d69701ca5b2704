#pragma once
/// \file
/// The lock around the library's HDF5 calls. A ResultsWriter writes its blocks on a thread of
/// its own (docs/output.md, "Storage and flushing"), and HDF5 is not assumed thread-safe: a build
/// without `--enable-threadsafe` allows one caller at a time in the whole process, whichever file
/// each works on. Every HDF5 call of spar_output (Hdf5File, ResultsWriter and its writer threads)
/// holds this lock, so two writers, or a writer and an Hdf5File, may run side by side. Code that
/// waits for a writer thread must not hold it (the writer thread takes it to write a block).

#include <mutex>

namespace spar::output::detail {

/// The process-wide lock of the library's HDF5 calls.
std::mutex& hdf5_mutex();

}  // namespace spar::output::detail
