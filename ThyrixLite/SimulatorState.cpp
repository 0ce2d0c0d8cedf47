/// @file SimulatorState.cpp
/// @brief Saving and restoring a simulator's state (WorldState).
#include <ThyrixLite/InvalidArgument.h>
#include <ThyrixLite/Primitive.h>
#include <ThyrixLite/Simulator.h>

#include <cstdio>
#include <sstream>

namespace thyrix {
namespace {

const char* shapeName(ShapeType type) {
  switch (type) {
    case ShapeType::Circle:
      return "circle";
    case ShapeType::Capsule:
      return "capsule";
    case ShapeType::HalfPlane:
      return "half-plane";
  }
  return "shape";
}

/// @p value exactly, as a hexadecimal float.
std::string exact(real value) {
  char text[64];
  std::snprintf(text, sizeof text, "%a", static_cast<double>(value));
  return text;
}

/// The first line where @p saved and @p here differ, for an error message.
std::string firstDifference(const std::string& saved, const std::string& here) {
  std::istringstream a(saved);
  std::istringstream b(here);
  std::string lineA;
  std::string lineB;
  while (true) {
    const bool moreA = static_cast<bool>(std::getline(a, lineA));
    const bool moreB = static_cast<bool>(std::getline(b, lineB));
    if (!moreA && !moreB) return "the sections differ";
    if (!moreA) return "this world has more: \"" + lineB + "\"";
    if (!moreB) return "the saved world has more: \"" + lineA + "\"";
    if (lineA != lineB) return "saved \"" + lineA + "\", this world \"" + lineB + "\"";
  }
}

/// What a world state keeps of a contact: its identity and its detection's and solve's values.
constexpr std::size_t contactWords = 3 + 1 + 2 + 2 + 1;

}  // namespace

std::string Simulator::makeUp() const {
  std::string text = "reals of " + std::to_string(8 * sizeof(real)) + " bits, " +
                     std::to_string(objects.size()) + " objects\n";
  for (std::size_t i = 0; i < objects.size(); ++i) {
    const PhysicalObject& object = objects[i];
    text += "object " + std::to_string(i) + ": " + object.typeName();
    for (const Primitive* primitive : object.primitives()) {
      text += std::string(", ") + shapeName(primitive->shapeType()) + " r " +
              exact(primitive->radius());
      if (primitive->shapeType() == ShapeType::Capsule)
        text += " l " + exact(primitive->halfLength());
    }
    text += '\n';
  }
  return text;
}

WorldState Simulator::saveState() const {
  WorldState state;
  state.makeUp_ = makeUp();
  state.sections_.resize(objects.size() + 2);
  StateRecord& core = state.sections_.front();
  core.addWord(stepCount());
  core.addDouble(time());
  std::uint64_t dragged = 0;  // the dragged object's index + 1, 0 for none
  for (std::size_t i = 0; i < objects.size(); ++i)
    if (&objects[i] == dragged_) dragged = i + 1;
  core.addWord(dragged);
  core.add(dragLocalPoint_);
  core.add(dragTarget_);
  core.add(dragMaxStep_);
  // Which bodies were detected before, and each shape's last detected place: the next
  // detection's speculative travel is the distance from there.
  core.addWord(bodyStates_.size());
  for (const BodyState& body : bodyStates_) core.add(body.fixed != BodyState::unknown);
  core.addWord(geometry_.size());
  for (const ShapeGeometry& geometry : geometry_) {
    core.add(geometry.p0);
    core.add(geometry.p1);
    core.add(geometry.travel);
  }
  // The last step's contacts: what rest skipping reuses and the warm start starts from.
  core.add(contactsComplete_);
  core.add(contactsSolved_);
  core.addWord(contacts.size());
  for (const GlobalContactInfo& contact : contacts) {
    core.addWord(contact.shapeA);
    core.addWord(contact.shapeB);
    core.addWord(contact.feature);
    core.add(contact.force);
    core.add(contact.point);
    core.add(contact.normal);
    core.add(contact.depth);
  }
  for (std::size_t i = 0; i < objects.size(); ++i) objects[i].saveState(state.sections_[i + 1]);
  saveOwnState(state.sections_.back());
  return state;
}

void Simulator::restoreState(const WorldState& state) {
  const std::string here = makeUp();
  if (state.makeUp_ != here)
    throw InvalidArgument("WorldState", "was saved from a world of another make-up: " +
                                            firstDifference(state.makeUp_, here));
  if (state.sections_.size() != objects.size() + 2)
    throw InvalidArgument("WorldState", "has " + std::to_string(state.sections_.size()) +
                                            " sections, this world needs " +
                                            std::to_string(objects.size() + 2));
  // A part may find it does not fit only once read (an agent with another controller): the
  // world is then put back as it was.
  const WorldState before = saveState();
  try {
    applyState(state);
  } catch (const std::exception& error) {
    applyState(before);
    throw InvalidArgument("WorldState", std::string("does not fit this world: ") + error.what());
  }
}

void Simulator::applyState(const WorldState& state) {
  StateRecord::Reader core(state.sections_.front(), "the simulator");
  const std::uint64_t steps = core.word();
  const double now = core.number();
  const std::uint64_t dragged = core.word();
  if (dragged > objects.size()) throw std::runtime_error("the dragged object is not in the world");
  const Vector2 dragLocalPoint = core.vector();
  const Vector2 dragTarget = core.vector();
  const real dragMaxStep = core.value();
  if (core.word() != bodyStates_.size())
    throw std::runtime_error("the simulator's record has another number of bodies");
  std::vector<bool> known(bodyStates_.size());
  for (std::size_t i = 0; i < known.size(); ++i) known[i] = core.flag();
  if (core.word() != geometry_.size())
    throw std::runtime_error("the simulator's record has another number of shapes");
  std::vector<ShapeGeometry> places(geometry_.size());
  for (ShapeGeometry& place : places) {
    place.p0 = core.vector();
    place.p1 = core.vector();
    place.travel = core.value();
  }
  const bool complete = core.flag();
  const bool solved = core.flag();
  const std::uint64_t count = core.word();
  if (count > state.sections_.front().words().size() / contactWords)
    throw std::runtime_error("the simulator's record ends in its contacts");
  std::vector<GlobalContactInfo> list(static_cast<std::size_t>(count));
  for (GlobalContactInfo& contact : list) {
    const std::uint64_t a = core.word();
    const std::uint64_t b = core.word();
    if (a >= shapes_.size() || b >= shapes_.size())
      throw std::runtime_error("a contact's shape is not in the world");
    contact.shapeA = static_cast<std::uint32_t>(a);
    contact.shapeB = static_cast<std::uint32_t>(b);
    contact.feature = static_cast<std::uint32_t>(core.word());
    contact.force = core.value();
    contact.point = core.vector();
    contact.normal = core.vector();
    contact.depth = core.value();
    contact.primitiveA = shapes_[a].primitive;
    contact.primitiveB = shapes_[b].primitive;
    contact.objectA = shapes_[a].object;
    contact.objectB = shapes_[b].object;
    contact.bodyA = shapes_[a].body;
    contact.bodyB = shapes_[b].body;
  }
  if (!core.atEnd()) throw std::runtime_error("the simulator's record is longer than it reads");

  for (std::size_t i = 0; i < objects.size(); ++i) {
    StateRecord::Reader reader(state.sections_[i + 1],
                               "object " + std::to_string(i) + " (" + objects[i].typeName() + ")");
    objects[i].restoreState(reader);
    if (!reader.atEnd())
      throw std::runtime_error("object " + std::to_string(i) + " (" + objects[i].typeName() +
                               ") saved more values than it reads");
  }
  StateRecord::Reader own(state.sections_.back(), "the simulator's subclass");
  restoreOwnState(own);
  if (!own.atEnd()) throw std::runtime_error("the simulator's subclass saved more than it reads");

  setClock(steps, now);
  dragged_ = dragged == 0 ? nullptr : &objects[static_cast<std::size_t>(dragged - 1)];
  draggedIndex_ = dragged == 0 ? 0 : static_cast<std::uint32_t>(dragged - 1);
  dragLocalPoint_ = dragLocalPoint;
  dragTarget_ = dragTarget;
  dragMaxStep_ = dragMaxStep;
  // Each shape's last place, its body known or not as saved, so that the travels come out as
  // they would; the caches are then rebuilt by the next detection.
  for (std::size_t i = 0; i < bodyStates_.size(); ++i)
    bodyStates_[i].fixed = !known[i] ? BodyState::unknown : objects[i].fixed ? 1 : 0;
  for (std::size_t s = 0; s < geometry_.size(); ++s) {
    geometry_[s].p0 = places[s].p0;
    geometry_[s].p1 = places[s].p1;
    geometry_[s].travel = places[s].travel;
  }
  forgetCaches();
  cachesForgotten_ = false;
  restoreContacts(std::move(list), complete, solved);
}

}  // namespace thyrix
