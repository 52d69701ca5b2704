// libFuzzer target of the spline inputs (docs/errors.md, "Fuzzing"): libFuzzer's bytes decide a
// knot vector, control points and weights and the operations on them (fuzz/cases/spline_case.hpp);
// a broken property prints the inputs and aborts, which libFuzzer reports with the input that did it.
#include "cases/spline_case.hpp"

#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  spar::fuzz::ByteSource source({data, size});
  spar::fuzz::CaseLog log;
  spar::fuzz::spline_case(source, log);
  if (!log.violations().empty()) {
    std::fprintf(stderr, "spline case broke a property:\n%s", log.report().c_str());
    std::abort();
  }
  return 0;
}
