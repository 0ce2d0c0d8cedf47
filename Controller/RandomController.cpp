#include <Controller/RandomController.h>
#include <ThyrixLite/InvalidArgument.h>

#include <algorithm>
#include <stdexcept>
#include <string>

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

void RandomController::saveState(StateRecord& record) const {
  const MTRandom::State stream = random_.saveState();
  for (const std::uint32_t word : stream.words) record.addWord(word);
  record.addWord(stream.index);
  record.add(stream.hasSpare);
  record.addDouble(stream.spare);
  record.add(std::span<const real>(held_));
  record.addInteger(remaining_);
}

void RandomController::restoreState(StateRecord::Reader& reader) {
  MTRandom::State stream;
  for (std::uint32_t& word : stream.words) word = static_cast<std::uint32_t>(reader.word());
  stream.index = static_cast<std::uint32_t>(reader.word());
  stream.hasSpare = reader.flag();
  stream.spare = reader.number();
  std::vector<real> held = reader.realVector();
  const auto remaining = static_cast<int>(reader.integer());
  try {
    random_.restoreState(stream);  // (checks the stream first: nothing is changed if it throws)
  } catch (const std::invalid_argument& error) {
    throw std::runtime_error(std::string("WorldState: RandomController's random stream: ") +
                             error.what());
  }
  held_ = std::move(held);
  remaining_ = remaining;
}

}  // namespace thyrix
