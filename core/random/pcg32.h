// Seeded PCG32 random generator: the only source of randomness in the core (no std distributions).
#pragma once

#include <cstdint>

namespace niwa {

// PCG-XSH-RR 64/32 (O'Neill 2014). Same sequence on every platform for a given seed and stream.
class Pcg32 {
 public:
  explicit Pcg32(uint64_t seed = 0x853c49e6748fea9bULL, uint64_t stream = 0xda3e39cb94b95bdbULL) {
    state_ = 0u;
    increment_ = (stream << 1u) | 1u;
    NextU32();
    state_ += seed;
    NextU32();
  }

  uint32_t NextU32() {
    uint64_t old = state_;
    state_ = old * 6364136223846793005ULL + increment_;
    uint32_t xorshifted = static_cast<uint32_t>(((old >> 18u) ^ old) >> 27u);
    uint32_t rot = static_cast<uint32_t>(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
  }

  // Uniform in [0, 1) with 32 bits of resolution, exactly representable as double.
  double Uniform() { return static_cast<double>(NextU32()) * (1.0 / 4294967296.0); }

  // Uniform in [lo, hi).
  double Uniform(double lo, double hi) { return lo + (hi - lo) * Uniform(); }

  // True with probability p (p <= 0 never, p >= 1 always).
  bool Bernoulli(double p) { return Uniform() < p; }

 private:
  uint64_t state_;
  uint64_t increment_;
};

}  // namespace niwa
