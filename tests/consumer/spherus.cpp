// Runs the installed Spherus as docs/Agents.md shows ("The installed agents"): a random
// controller, then a network read from a genome, each in its own arena.
#include <Agents/SpherusSimulator.h>
#include <Controller/Genome.h>
#include <Controller/RandomController.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <sstream>

int main() {
  // --- the docs' example ---
  thyrix::SpherusSimulator::Options options;
  options.objects = 20;  // circles to push
  options.seed = 7;      // their layout
  options.poseSeed = 3;  // the agent's random start (unset: the centre, facing +y)
  thyrix::SpherusSimulator simulator(options, std::make_unique<thyrix::RandomController>(7));
  const thyrix::Vector2 start = simulator.spherus().centre();
  for (int step = 0; step < 1000; ++step) simulator.advanceTime();
  const thyrix::Vector2 where = simulator.spherus().centre();
  // --- end of the docs' example ---

  // A 35-8-5 network whose output biases are +4 on the forward rockets (effectors 0 and 2)
  // and -4 on the rest: the agent drives straight ahead, away from its start.
  thyrix::Genome genome;
  genome.spec = {thyrix::NetworkKind::FeedForward, {35, 8, 5}, thyrix::Activation::Tanh};
  genome.parameters.assign(genome.spec.parameterCount(), 0);
  const std::size_t outputBiases = 8 + 35 * 8;
  const double biases[5] = {4, -4, 4, -4, -4};
  for (std::size_t o = 0; o < 5; ++o)
    genome.parameters[outputBiases + o] = static_cast<thyrix::real>(biases[o]);
  std::stringstream file;
  genome.write(file);
  const thyrix::Genome read = thyrix::Genome::read(file);
  read.requireShape(thyrix::Spherus::sensorCount, thyrix::Spherus::effectorCount);
  thyrix::SpherusSimulator::Options empty;
  empty.objects = 0;
  thyrix::SpherusSimulator driven(empty, read.makeController(empty.timestep));
  for (int step = 0; step < 100; ++step) driven.advanceTime();
  const thyrix::Vector2 ahead = driven.spherus().centre();

  const bool inside =
      where.x > 0 && where.x < options.size && where.y > 0 && where.y < options.size;
  const bool moved = distance(where, start) > 0.01;
  // Facing +y from the centre, the agent goes up and not sideways.
  const bool straight = ahead.y - empty.size / 2 > 0.1 && std::abs(ahead.x - empty.size / 2) < 1e-3;
  std::printf("spherus: from (%g, %g) to (%g, %g); the network drove it to (%g, %g) %s\n",
              static_cast<double>(start.x), static_cast<double>(start.y),
              static_cast<double>(where.x), static_cast<double>(where.y),
              static_cast<double>(ahead.x), static_cast<double>(ahead.y),
              inside && moved && straight ? "ok" : "WRONG");
  return inside && moved && straight ? 0 : 1;
}
