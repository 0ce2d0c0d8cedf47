/// @file Integrator.cpp
/// @brief Explicit Euler, the default integrator, and its fast loop.
#include <ThyrixLite/Integrator.h>
#include <ThyrixLite/Simulator.h>
#include <Tools/Inlining.h>
#include <Tools/ProcessorFeatures.h>

namespace thyrix {
namespace {

// integrateExcept's loop, inlined whole (forEachInRuns, the core shapes' hook), so that the AVX
// copy below compiles all of it (a call it made would run SSE2 code).
THYRIX_ALWAYS_INLINE void integrateInRuns(const ObjectList& objects,
                                          std::span<const std::uint32_t> customObjects, real dt) {
  forEachInRuns(
      objects, customObjects,
      [dt](PhysicalObject& object)
          THYRIX_LAMBDA_ALWAYS_INLINE { object.PhysicalObject::integrate(dt); },
      [dt](PhysicalObject& object) { object.integrate(dt); });
}

#if defined(THYRIX_AVX_DISPATCH)
// The same loop in VEX form: the same operations, so the same bits, but its three-operand
// instructions read their unaligned operands from memory, where SSE2 loaded them into
// registers first (a core shape 12 instructions, not 15).
[[gnu::target("avx")]] void integrateInRunsAvx(const ObjectList& objects,
                                               std::span<const std::uint32_t> customObjects,
                                               real dt) {
  integrateInRuns(objects, customObjects, dt);
}
#endif

}  // namespace

void Integrator::integrate(Simulator& simulator, real dt) {
  for (PhysicalObject& object : simulator.objects) integrateObject(object, dt);
}

void Integrator::integrateObject(PhysicalObject& object, real dt) { object.integrate(dt); }

void Integrator::integrateExcept(const ObjectList& objects,
                                 std::span<const std::uint32_t> customObjects, real dt) {
#if defined(THYRIX_AVX_DISPATCH)
  if (processorHasAvx()) {
    integrateInRunsAvx(objects, customObjects, dt);
    return;
  }
#endif
  integrateInRuns(objects, customObjects, dt);
}

}  // namespace thyrix
