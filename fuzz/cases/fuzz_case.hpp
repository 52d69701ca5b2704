#pragma once
/// \file
/// What the fuzz cases share (docs/errors.md, "Fuzzing"): a source of random decisions, which is
/// either a seeded generator (the Catch2 property test, label `fuzz`) or the bytes libFuzzer
/// mutates (the fuzz targets, label `libfuzzer`), and a log of the inputs drawn and the
/// properties broken. A case draws plausible inputs with rare hostile mutations (NaN, infinities,
/// huge and tiny values, wrong sizes, out-of-range counts), calls the public API, and checks that
/// every call ends in a spar::Error or in a result with its defining property.

#include <spar/error.hpp>

#include <Eigen/Core>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <span>
#include <sstream>
#include <string>
#include <typeinfo>
#include <vector>

namespace spar::fuzz {

/// Random decisions; value(), count() and vector() turn them into plausible or hostile inputs.
class FuzzSource {
public:
  virtual ~FuzzSource() = default;

  /// True with probability p.
  virtual bool chance(double p) = 0;
  /// An integer in [low, high].
  virtual int integer(int low, int high) = 0;
  /// A real in [low, high).
  virtual double uniform(double low, double high) = 0;

  /// `plausible` most of the time; else NaN, ±inf, 0, a negative, a huge or a tiny value.
  double value(double plausible, double hostility = 0.05) {
    if (!chance(hostility)) return plausible;
    constexpr double hostile[] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                                  -std::numeric_limits<double>::infinity(), 0.0, -1.0, 1e300, -1e300, 1e-300,
                                  std::numeric_limits<double>::denorm_min()};
    return hostile[integer(0, static_cast<int>(std::size(hostile)) - 1)];
  }
  /// `plausible` most of the time; else an out-of-range count.
  int count(int plausible, double hostility = 0.05) {
    if (!chance(hostility)) return plausible;
    constexpr int hostile[] = {-1, 0, 1, 100, std::numeric_limits<int>::max(), std::numeric_limits<int>::min()};
    return hostile[integer(0, static_cast<int>(std::size(hostile)) - 1)];
  }
  /// A vector of plausible components in [−scale, scale), each mutated with `hostility`.
  Eigen::Vector3d vector(double scale, double hostility = 0.05) {
    // A braced list evaluates left to right: the draws keep their order on every compiler.
    return Eigen::Vector3d{value(uniform(-scale, scale), hostility), value(uniform(-scale, scale), hostility),
                           value(uniform(-scale, scale), hostility)};
  }
};

/// Decisions from a seeded std::mt19937: a reproducible stream for the property test.
class SeededSource final : public FuzzSource {
public:
  explicit SeededSource(unsigned seed) : random_(seed) {}

  bool chance(double p) override { return std::bernoulli_distribution(p)(random_); }
  int integer(int low, int high) override { return std::uniform_int_distribution<int>(low, high)(random_); }
  double uniform(double low, double high) override {
    return std::uniform_real_distribution<double>(low, high)(random_);
  }

private:
  std::mt19937 random_;
};

/// Decisions read from libFuzzer's bytes, front to back: one byte for a chance, as few bytes as
/// the range needs for an integer, four for a real. Once the bytes are used up every decision
/// takes its low end (no chance, the lowest integer, `low`), so a short input is a plausible case.
class ByteSource final : public FuzzSource {
public:
  explicit ByteSource(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}

  bool chance(double p) override {
    if (next_ >= bytes_.size()) return false;
    return bytes_[next_++] < p * 256.0;
  }
  int integer(int low, int high) override {
    const auto range = static_cast<std::uint64_t>(static_cast<std::int64_t>(high) - low);
    std::uint64_t drawn = 0;
    for (std::uint64_t left = range; left != 0 && next_ < bytes_.size(); left >>= 8)
      drawn = (drawn << 8) | bytes_[next_++];
    return static_cast<int>(static_cast<std::int64_t>(low) + static_cast<std::int64_t>(drawn % (range + 1)));
  }
  double uniform(double low, double high) override {
    std::uint32_t drawn = 0;
    for (int k = 0; k < 4 && next_ < bytes_.size(); ++k) drawn = (drawn << 8) | bytes_[next_++];
    return low + (high - low) * (drawn / 4294967296.0);
  }

private:
  std::span<const std::uint8_t> bytes_;
  std::size_t next_ = 0;
};

/// The inputs a case drew (for the report of a failure) and the properties it found broken.
class CaseLog {
public:
  /// Records `value` under `name` and returns it: `note("E", source.value(…))`.
  template <class T>
  const T& note(const char* name, const T& value) {
    inputs_ << name << " = " << value << "\n";
    return value;
  }
  Eigen::Vector3d note(const char* name, const Eigen::Vector3d& v) {
    inputs_ << name << " = " << v.transpose() << "\n";
    return v;
  }
  /// Records a broken property unless `holds`.
  void check(bool holds, const std::string& property) {
    if (!holds) violations_.push_back(property);
  }

  const std::vector<std::string>& violations() const { return violations_; }
  /// The inputs and the broken properties, for a failure message.
  std::string report() const {
    std::string text = inputs_.str();
    for (const std::string& v : violations_) text += "VIOLATED: " + v + "\n";
    return text;
  }

private:
  std::ostringstream inputs_;
  std::vector<std::string> violations_;
};

/// Runs `call`: true when it returns, false when it ends in a spar::Error (an accepted outcome);
/// any other exception is logged as a broken property (and false).
template <class Call>
bool accepted(Call&& call, const char* what, CaseLog& log) {
  try {
    call();
    return true;
  } catch (const Error&) {
    return false;
  } catch (const std::exception& other) {
    log.check(false, std::string(what) + " threw a " + typeid(other).name() +
                         " instead of a spar::Error: " + other.what());
  }
  return false;
}

/// The body of a libFuzzer entry point: runs `fuzz_case` (spline_case, model_case) on the bytes;
/// a broken property prints the inputs drawn and aborts, which libFuzzer reports with the input.
template <class Case>
int fuzz_one_input(const std::uint8_t* data, std::size_t size, Case&& fuzz_case, const char* name) {
  ByteSource source({data, size});
  CaseLog log;
  fuzz_case(source, log);
  if (!log.violations().empty()) {
    std::fprintf(stderr, "%s case broke a property:\n%s", name, log.report().c_str());
    std::abort();
  }
  return 0;
}

}  // namespace spar::fuzz
