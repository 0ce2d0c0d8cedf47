#include <Controller/RandomController.h>
#include <ThyrixLite/InvalidArgument.h>

#include <algorithm>

namespace thyrix {

RandomController::RandomController(std::uint32_t seed, int minHold, int maxHold)
    : seed_(seed), minHold_(minHold), maxHold_(maxHold), random_(seed) {
  if (minHold < 1) throw InvalidArgument("RandomController.minHold", "must be at least 1");
  if (maxHold < minHold)
    throw InvalidArgument("RandomController.maxHold", "must be at least minHold");
}

void RandomController::control(std::span<const real> /*sensors*/, std::span<real> effectors) {
  if (held_.size() != effectors.size()) {  // first call (or another agent): draw at once
    held_.assign(effectors.size(), 0);
    remaining_ = 0;
  }
  if (remaining_ <= 0) {
    for (real& value : held_) value = static_cast<real>(random_.uniform());
    remaining_ = random_.integer(minHold_, maxHold_);
  }
  --remaining_;
  std::copy(held_.begin(), held_.end(), effectors.begin());
}

void RandomController::reset() {
  random_.seed(seed_);
  held_.clear();
  remaining_ = 0;
}

}  // namespace thyrix
