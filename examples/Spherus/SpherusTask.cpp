#include "SpherusTask.h"

#include <Controller/NeuralController.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string>

namespace thyrix {

SpherusGoal parseSpherusGoal(std::string_view text) {
  if (text == "distance") return SpherusGoal::Distance;
  if (text == "clear") return SpherusGoal::Clear;
  throw std::invalid_argument("--task must be distance or clear, not '" + std::string(text) + "'");
}

std::string_view toString(SpherusGoal goal) {
  return goal == SpherusGoal::Distance ? "distance" : "clear";
}

SpherusEpisode::SpherusEpisode(const Options& options, std::unique_ptr<Controller> controller)
    : SpherusSimulator(options, std::move(controller)), start_(spherus().centre()) {
  ballStarts_.reserve(obstacles().size());
  for (const Circle* ball : obstacles()) ballStarts_.push_back(ball->r);
}

std::unique_ptr<SpherusEpisode> SpherusTask::makeWorld(const std::vector<double>& parameters,
                                                       std::uint64_t seed) const {
  auto controller = std::make_unique<NeuralController>(network, arena.timestep);
  std::vector<real> values(parameters.begin(), parameters.end());
  controller->setParameters(values);
  SpherusSimulator::Options options = arena;
  // The layout from the seed's low half, the pose from its high half: two streams.
  options.seed = static_cast<std::uint32_t>(seed);
  if (randomPose) options.poseSeed = static_cast<std::uint32_t>(seed >> 32);
  return std::make_unique<SpherusEpisode>(options, std::move(controller));
}

double SpherusTask::fitness(const SpherusEpisode& episode) const {
  if (goal == SpherusGoal::Distance) {
    const Vector2 d = episode.spherus().centre() - episode.start();
    return std::sqrt(static_cast<double>(d.x) * d.x + static_cast<double>(d.y) * d.y);
  }
  const double size = static_cast<double>(arena.size);
  const auto gap = [&](Vector2 p, real radius) {
    const double x = static_cast<double>(p.x), y = static_cast<double>(p.y);
    return std::min({x, size - x, y, size - y}) - static_cast<double>(radius);
  };
  double pushed = 0;
  for (std::size_t i = 0; i < episode.obstacles().size(); ++i) {
    const Circle& ball = *episode.obstacles()[i];
    pushed += gap(episode.ballStarts()[i], ball.radius()) - gap(ball.r, ball.radius());
  }
  return pushed;
}

NetworkSpec parseSpherusNetwork(std::string_view text) {
  const auto bad = [&](const std::string& why) {
    return std::invalid_argument("--network " + why + " (e.g. ff:8, ff:8,4 or ctrnn:8), not '" +
                                 std::string(text) + "'");
  };
  NetworkSpec spec;
  std::string_view sizes;
  if (text == "ff") {
    spec.kind = NetworkKind::FeedForward;
  } else if (text.starts_with("ff:")) {
    spec.kind = NetworkKind::FeedForward;
    sizes = text.substr(3);
  } else if (text.starts_with("ctrnn:")) {
    spec.kind = NetworkKind::Ctrnn;
    sizes = text.substr(6);
  } else {
    throw bad("must be ff[:H1,H2...] or ctrnn:N");
  }
  spec.layers.push_back(Spherus::sensorCount);
  while (!sizes.empty()) {
    const std::size_t comma = std::min(sizes.find(','), sizes.size());
    std::size_t size = 0;
    const std::string_view part = sizes.substr(0, comma);
    const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), size);
    if (error != std::errc() || end != part.data() + part.size() || size == 0 || size > 4096)
      throw bad("needs layer sizes from 1 to 4096");
    spec.layers.push_back(size);
    sizes.remove_prefix(comma == sizes.size() ? comma : comma + 1);
  }
  spec.layers.push_back(Spherus::effectorCount);
  if (spec.kind == NetworkKind::Ctrnn && spec.layers.size() != 3)
    throw bad("ctrnn needs one size, its neurons");
  return spec;
}

}  // namespace thyrix
