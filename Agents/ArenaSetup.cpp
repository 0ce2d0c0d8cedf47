#include <Agents/ArenaSetup.h>

#include <ThyrixLite/Border.h>

#include <memory>

namespace thyrix {

void addArenaWalls(Simulator& simulator, real size) {
  simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
  simulator.registerObject(std::make_unique<Border>(Vector2{0, size}, Vector2{0, -1}));
  simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{1, 0}));
  simulator.registerObject(std::make_unique<Border>(Vector2{size, 0}, Vector2{-1, 0}));
}

}  // namespace thyrix
