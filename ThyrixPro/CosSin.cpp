/// @file CosSin.cpp
/// @brief cosSinKernel(): the loop over many angles, with AVX-512 or AVX2 where the processor
/// has it.
#include <ThyrixPro/CosSin.h>
#include <Tools/ProcessorFeatures.h>

namespace thyrix {

namespace {

/// The loop, for the instructions the library is built for (SSE2 on x86-64: two at a time).
void kernelLoop(std::span<const real> angles, std::span<Vector2> out) {
  for (std::size_t k = 0; k < angles.size(); ++k) out[k] = detail::cosSinReduced(angles[k]);
}

#if defined(THYRIX_AVX_DISPATCH)
/// The same loop for AVX2: four angles at a time. The same operations in each lane, and AVX2
/// brings no fused multiply-add (that is FMA's), so the same bits.
[[gnu::target("avx2")]] void kernelLoopAvx2(std::span<const real> angles, std::span<Vector2> out) {
  for (std::size_t k = 0; k < angles.size(); ++k) out[k] = detail::cosSinReduced(angles[k]);
}

/// The same loop for AVX-512: eight angles at a time. The kernel waits on its chain of about
/// 20 dependent operations per angle more than on its arithmetic, and how many angles are in
/// flight at once is bound by how many instructions the processor holds: with twice the
/// lanes per instruction, twice the angles.
[[gnu::target("avx512f")]] void kernelLoopAvx512(std::span<const real> angles,
                                                 std::span<Vector2> out) {
  for (std::size_t k = 0; k < angles.size(); ++k) out[k] = detail::cosSinReduced(angles[k]);
}
#endif

}  // namespace

void cosSinKernel(std::span<const real> angles, std::span<Vector2> out) {
#if defined(THYRIX_AVX_DISPATCH)
  if (processorHasAvx512()) {
    kernelLoopAvx512(angles, out);
    return;
  }
  if (processorHasAvx2()) {
    kernelLoopAvx2(angles, out);
    return;
  }
#endif
  kernelLoop(angles, out);
}

}  // namespace thyrix
