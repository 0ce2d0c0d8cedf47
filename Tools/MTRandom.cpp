#include <Tools/MTRandom.h>

namespace thyrix {

MTRandom::MTRandom(std::uint32_t seed) : engine_(seed) {}

void MTRandom::seed(std::uint32_t seed) { engine_.seed(seed); }

std::uint32_t MTRandom::nextUint32() { return static_cast<std::uint32_t>(engine_()); }

}  // namespace thyrix
