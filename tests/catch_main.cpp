// The single translation unit that defines Catch2's main() for every spar test suite. It prints
// doubles with 17 significant digits, so a failed tolerance check shows the numbers that failed.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

int main(int argc, char* argv[]) {
  Catch::StringMaker<double>::precision = 17;
  Catch::StringMaker<float>::precision = 9;
  return Catch::Session().run(argc, argv);
}
