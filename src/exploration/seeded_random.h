#pragma once
// Random draws that give the same numbers for the same seed with every standard library: std::mt19937
// is fixed by the standard, but its distributions (uniform_int, uniform_real, normal) are not, so
// the draws are made here from the engine's raw 32-bit words.
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace topocut {

class SeededRandom {
 public:
  // One stream per (seed, stream): the stages of a simulation draw from their own streams, so that
  // switching one realism off does not change what the others draw.
  SeededRandom(std::uint32_t seed, std::uint32_t stream) {
    std::seed_seq sequence{seed, stream, 0x746f706fu};
    engine_.seed(sequence);
  }

  // Uniform in [0, 1), 53 random bits.
  double uniform() {
    const std::uint64_t a = engine_() >> 5, b = engine_() >> 6;
    return static_cast<double>((a << 26) | b) * 0x1.0p-53;
  }
  double uniform(double low, double high) { return low + (high - low) * uniform(); }
  // Uniform integer in [0, n), n >= 1 (64-bit draw; the bias of the modulo is below 2^-32 for n < 2^32).
  std::uint64_t below(std::uint64_t n) {
    const std::uint64_t draw = (static_cast<std::uint64_t>(engine_()) << 32) | engine_();
    return draw % n;
  }
  bool chance(double probability) { return uniform() < probability; }
  // Standard normal (Box-Muller; the second value is dropped so that every call costs the same).
  double normal() {
    const double u = 1.0 - uniform();  // (0, 1]
    const double v = uniform();
    return std::sqrt(-2.0 * std::log(u)) * std::cos(2.0 * std::numbers::pi * v);
  }

 private:
  std::mt19937 engine_;
};

}  // namespace topocut
