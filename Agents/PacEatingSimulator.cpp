#include <Agents/PacEatingSimulator.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace thyrix {

PacEatingSimulator::PacEatingSimulator(const Options& options, std::unique_ptr<Controller> second)
    : PacSimulator(options, nullptr, std::move(second)) {}

const Circle* PacEatingSimulator::nearestFreeFood() const {
  const Circle* nearest = nullptr;
  real best = 0;
  const PacParameters& parameters = options().pac;
  const real margin = parameters.ringRadius + 2 * parameters.radius;
  const real size = options().size;
  for (const Circle* food : food()) {
    if (pac(0).contains(food->r) || pac(1).contains(food->r)) continue;
    if (std::find(skipped_.begin(), skipped_.end(), food) != skipped_.end()) continue;
    if (std::min({food->r.x, food->r.y, size - food->r.x, size - food->r.y}) < margin) continue;
    const real d = distance(food->r, pac(0).centre());
    if (nearest == nullptr || d < best) {
      nearest = food;
      best = d;
    }
  }
  return nearest;
}

void PacEatingSimulator::advanceTime() {
  // A new target once the last one is carried for a while, or when it could not be eaten for
  // too long.
  const bool givenUp = eater_ && !eater_->done() && sinceTarget_ > 2000;
  if (givenUp) skipped_.push_back(&eater_->target());
  if (!eater_ || givenUp || (eater_->done() && sinceTarget_ > 300)) {
    const Circle* target = nearestFreeFood();
    if (target == nullptr)
      eater_.reset();
    else if (eater_)
      eater_->setTarget(*target);
    else
      eater_.emplace(pac(0), *target);
    sinceTarget_ = 0;
  }
  if (eater_)
    eater_->step();
  else
    std::fill(pac(0).effectors().begin(), pac(0).effectors().end(), real(0));
  ++sinceTarget_;
  PacSimulator::advanceTime();
}

std::uint64_t PacEatingSimulator::indexOf(const PhysicalObject& object) const {
  for (std::size_t i = 0; i < objects.size(); ++i)
    if (&objects[i] == &object) return i;
  return objects.size();
}

const PhysicalObject& PacEatingSimulator::objectAt(std::uint64_t index) const {
  if (index >= objects.size())
    throw std::runtime_error("WorldState: the script's object " + std::to_string(index) +
                             " is not in the world");
  return objects[static_cast<std::size_t>(index)];
}

void PacEatingSimulator::saveOwnState(StateRecord& record) const {
  record.add(eater_.has_value());
  if (eater_) {
    record.addWord(indexOf(eater_->target()));
    eater_->saveState(record);
  }
  record.addWord(skipped_.size());
  for (const PhysicalObject* object : skipped_) record.addWord(indexOf(*object));
  record.addInteger(sinceTarget_);
}

void PacEatingSimulator::restoreOwnState(StateRecord::Reader& reader) {
  std::optional<PacEater> eater;
  if (reader.flag()) {
    eater.emplace(pac(0), objectAt(reader.word()));
    eater->restoreState(reader);
  }
  const std::uint64_t count = reader.word();
  if (count > objects.size()) throw std::runtime_error("WorldState: too many skipped objects");
  std::vector<const PhysicalObject*> skipped;
  for (std::uint64_t k = 0; k < count; ++k) skipped.push_back(&objectAt(reader.word()));
  sinceTarget_ = static_cast<long>(reader.integer());
  eater_ = std::move(eater);
  skipped_ = std::move(skipped);
}

}  // namespace thyrix
