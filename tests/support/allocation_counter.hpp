#pragma once
// Counts heap allocations: a test suite that links allocation_counter.cpp replaces the global
// operator new (all forms) with a counting one, and a test compares the count before and after
// the code under test.

namespace spar::test {

/// The number of global operator new calls in this executable so far.
long allocation_count();

}  // namespace spar::test
