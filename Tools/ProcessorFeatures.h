#pragma once
/// @file ProcessorFeatures.h
/// @brief Which optional instruction sets the processor runs, for the few loops that have a
/// copy compiled for them and choose it at run time.

/// Defined where a function can be compiled for AVX, AVX2 or AVX-512 (`[[gnu::target("avx")]]`,
/// `[[gnu::target("avx2")]]`, `[[gnu::target("avx512f")]]`) and chosen at run time by
/// processorHasAvx(), processorHasAvx2() or processorHasAvx512(): GCC or Clang on x86-64,
/// except in the scalar build (THYRIX_SIMD_SCALAR). Elsewhere the portable loops run.
#if defined(__GNUC__) && defined(__x86_64__) && !defined(THYRIX_SIMD_SCALAR)
#define THYRIX_AVX_DISPATCH 1
#endif

#include <cstdlib>
#include <string_view>

namespace thyrix {

#if defined(THYRIX_AVX_DISPATCH)
namespace detail {

/// The most the dispatched loops may use, from the environment variable `THYRIX_ISA`, read
/// once: `sse2` (the portable loops only), `avx` (no AVX2), `avx2` (no AVX-512); unset or any
/// other value, what the processor runs. Every copy of a loop gives the same bits, so this
/// only chooses which copy runs: the tests run each copy on one machine this way.
inline int instructionSetCap() {
  static const int cap = [] {
    const char* value = std::getenv("THYRIX_ISA");  // NOLINT(concurrency-mt-unsafe): read once
    const std::string_view isa = value != nullptr ? value : "";
    if (isa == "sse2") return 0;
    if (isa == "avx") return 1;
    if (isa == "avx2") return 2;
    return 3;
  }();
  return cap;
}

}  // namespace detail

/// Whether the processor runs AVX, asked once (a thread-safe local static). As for
/// processorHasAvx2(): an AVX copy of a loop does what the portable loop does, so the same bits.
inline bool processorHasAvx() {
  static const bool has = detail::instructionSetCap() >= 1 && __builtin_cpu_supports("avx") != 0;
  return has;
}

/// Whether the processor runs AVX2, asked once (a thread-safe local static). A loop's AVX2
/// copy must do the same operations in each lane as its portable loop, and AVX2 brings no
/// fused multiply-add (that is FMA's): which copy runs then never changes a result.
inline bool processorHasAvx2() {
  static const bool has = detail::instructionSetCap() >= 2 && __builtin_cpu_supports("avx2") != 0;
  return has;
}

/// Whether the processor runs AVX-512 (its foundation, AVX512F), asked once. As for
/// processorHasAvx2(): the same operations in each lane as the portable loop, without fused
/// multiply-adds, so the same bits.
inline bool processorHasAvx512() {
  static const bool has =
      detail::instructionSetCap() >= 3 && __builtin_cpu_supports("avx512f") != 0;
  return has;
}
#endif

}  // namespace thyrix
