// libFuzzer target of model building and a short solve (docs/errors.md, "Fuzzing"): libFuzzer's
// bytes decide the beam, its loads, gravity, a rigid body and the solve (fuzz/cases/model_case.hpp);
// a broken property prints the inputs and aborts, which libFuzzer reports with the input that did it.
#include "cases/model_case.hpp"

#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  spar::fuzz::ByteSource source({data, size});
  spar::fuzz::CaseLog log;
  spar::fuzz::model_case(source, log);
  if (!log.violations().empty()) {
    std::fprintf(stderr, "model case broke a property:\n%s", log.report().c_str());
    std::abort();
  }
  return 0;
}
