// libFuzzer target of the spline inputs (docs/errors.md, "Fuzzing"): libFuzzer's bytes decide a
// knot vector, control points and weights and the operations on them (fuzz/cases/spline_case.hpp);
// a broken property prints the inputs and aborts, which libFuzzer reports with the input that did it.
#include "cases/spline_case.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return spar::fuzz::fuzz_one_input(data, size, spar::fuzz::spline_case, "spline");
}
