// libFuzzer target of model building and a short solve (docs/errors.md, "Fuzzing"): libFuzzer's
// bytes decide the beam, its loads, gravity, a rigid body and the solve (fuzz/cases/model_case.hpp);
// a broken property prints the inputs and aborts, which libFuzzer reports with the input that did it.
#include "cases/model_case.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return spar::fuzz::fuzz_one_input(data, size, spar::fuzz::model_case, "model");
}
