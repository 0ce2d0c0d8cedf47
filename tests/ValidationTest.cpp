// Bad input is refused with an InvalidArgument naming the field, and the world is left as it
// was (docs/Design.md section 6).

#include <ThyrixLite/Border.h>
#include <ThyrixLite/CappedRectangle.h>
#include <ThyrixLite/Circle.h>
#include <ThyrixLite/ComposedPhysicalObject.h>
#include <ThyrixLite/Elastoid.h>
#include <ThyrixLite/InvalidArgument.h>
#include <ThyrixLite/Simulator.h>
#include <gtest/gtest.h>
#include <scenes/Scenes.h>

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace thyrix {
namespace {

constexpr real kNaN = std::numeric_limits<real>::quiet_NaN();
constexpr real kInf = std::numeric_limits<real>::infinity();

/// Runs @p action and returns the field named by the InvalidArgument it throws, after checking
/// that the message names the field too; "<no exception>" or "<other exception>" otherwise.
template <class Action>
std::string thrownField(Action&& action) {
  try {
    action();
  } catch (const InvalidArgument& e) {
    EXPECT_NE(std::string(e.what()).find(e.field()), std::string::npos)
        << "message \"" << e.what() << "\" does not name the field " << e.field();
    EXPECT_FALSE(e.field().empty());
    return e.field();
  } catch (...) {
    return "<other exception>";
  }
  return "<no exception>";
}

// ---------------------------------------------------------------------------------------------
// Construction

TEST(ValidationTest, CircleRadius) {
  for (const real radius : {real(-1), real(0), kNaN, kInf, -kInf}) {
    SCOPED_TRACE(radius);
    EXPECT_EQ(thrownField([&] { Circle circle(radius, 1); }), "Circle.radius");
  }
  EXPECT_EQ(thrownField([] { Circle circle(real(0.5), 1); }), "<no exception>");
}

TEST(ValidationTest, CircleMass) {
  for (const real mass : {real(-1), real(0), kNaN, kInf, -kInf}) {
    SCOPED_TRACE(mass);
    EXPECT_EQ(thrownField([&] { Circle circle(1, mass); }), "Circle.mass");
  }
}

TEST(ValidationTest, CappedRectangleFields) {
  for (const real bad : {real(-1), real(0), kNaN, kInf}) {
    SCOPED_TRACE(bad);
    EXPECT_EQ(thrownField([&] { CappedRectangle c(bad, 1, 1); }), "CappedRectangle.l");
    EXPECT_EQ(thrownField([&] { CappedRectangle c(1, bad, 1); }), "CappedRectangle.R");
    EXPECT_EQ(thrownField([&] { CappedRectangle c(1, 1, bad); }), "CappedRectangle.mass");
  }
  EXPECT_EQ(thrownField([] { CappedRectangle c(2, real(0.5), 3); }), "<no exception>");
}

TEST(ValidationTest, MassWhoseInverseOverflows) {
  // The smallest subnormal: positive and finite, but 1 / m is infinite (in double and float).
  const real tiny = std::numeric_limits<real>::denorm_min();
  ASSERT_FALSE(std::isfinite(1 / tiny));
  EXPECT_EQ(thrownField([&] { Circle c(1, tiny); }), "Circle.mass");
  EXPECT_EQ(thrownField([&] { CappedRectangle c(1, 1, tiny); }), "CappedRectangle.mass");
  // A mass set after construction, and a moment of inertia, are refused at registration.
  Simulator simulator;
  auto circle = std::make_unique<Circle>(1, 1);
  circle->m = tiny;
  EXPECT_EQ(thrownField([&] { simulator.registerObject(std::move(circle)); }), "Circle.m");
  auto capsule = std::make_unique<CappedRectangle>(1, 1, 1);
  capsule->I = tiny;
  EXPECT_EQ(thrownField([&] { simulator.registerObject(std::move(capsule)); }),
            "CappedRectangle.I");
  EXPECT_EQ(simulator.objects.size(), 0u);
}

TEST(ValidationTest, BorderFields) {
  // A normal of subnormal length (1e-310 in double, 1e-40 in float) is too short to normalize.
  const real subnormal = std::numeric_limits<real>::min() / 4;
  ASSERT_GT(subnormal, 0);
  EXPECT_EQ(thrownField([&] { Border b({0, 0}, {subnormal, 0}); }), "Border.normal");
  EXPECT_EQ(thrownField([&] { Border b({0, 0}, {0, -subnormal}); }), "Border.normal");
  EXPECT_EQ(thrownField([&] { Border b({0, 0}, {subnormal, subnormal}); }), "Border.normal");
  // The smallest normal length is accepted and gives a unit normal.
  const Border smallest({0, 0}, {0, std::numeric_limits<real>::min()});
  EXPECT_EQ(smallest.normal().x, 0);
  EXPECT_EQ(smallest.normal().y, 1);
  EXPECT_EQ(thrownField([] { Border b({0, 0}, {0, 0}); }), "Border.normal");
  EXPECT_EQ(thrownField([] { Border b({0, 0}, {kNaN, 1}); }), "Border.normal");
  EXPECT_EQ(thrownField([] { Border b({0, 0}, {1, kNaN}); }), "Border.normal");
  EXPECT_EQ(thrownField([] { Border b({0, 0}, {kInf, 0}); }), "Border.normal");
  EXPECT_EQ(thrownField([] { Border b({kNaN, 0}, {0, 1}); }), "Border.point");
  EXPECT_EQ(thrownField([] { Border b({0, kInf}, {0, 1}); }), "Border.point");
  EXPECT_EQ(thrownField([] { Border b({1, 2}, {0, 3}); }), "<no exception>");
}

TEST(ValidationTest, SimulatorTimestepConstructor) {
  for (const real dt : {real(0), real(-0.01), kNaN, kInf}) {
    SCOPED_TRACE(dt);
    EXPECT_EQ(thrownField([&] { Simulator simulator(dt); }), "World.timestep");
  }
  EXPECT_EQ(thrownField([] { Simulator simulator(real(0.02)); }), "<no exception>");
}

TEST(ValidationTest, SetTimestepKeepsTheOldOne) {
  Simulator simulator(real(0.02));
  for (const real dt : {real(0), real(-0.01), kNaN, kInf}) {
    SCOPED_TRACE(dt);
    EXPECT_EQ(thrownField([&] { simulator.setTimestep(dt); }), "World.timestep");
    EXPECT_EQ(simulator.timestep(), real(0.02));
  }
  simulator.setTimestep(real(0.05));
  EXPECT_EQ(simulator.timestep(), real(0.05));
}

// ---------------------------------------------------------------------------------------------
// Registration and drag, with the world left unchanged

/// A small world: a floor, a wall, two circles and a capsule touching or slightly overlapping,
/// all pushed down and sideways each step so that contacts and solving happen.
struct TestWorld {
  Simulator simulator{real(0.01)};
  std::vector<PhysicalObject*> bodies;

  TestWorld() {
    simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{0, 1}));
    simulator.registerObject(std::make_unique<Border>(Vector2{0, 0}, Vector2{1, 0}));
    auto& a = simulator.registerObject(std::make_unique<Circle>(real(0.5), 1));
    a.r = {1, real(0.49)};
    auto& b = simulator.registerObject(std::make_unique<Circle>(real(0.5), 2));
    b.r = {real(1.95), real(0.52)};
    auto& c = simulator.registerObject(std::make_unique<CappedRectangle>(1, real(0.25), 1));
    c.r = {real(1.5), real(1.2)};
    c.alpha = real(0.1);
    bodies = {&a, &b, &c};
  }

  void step() {
    scenes::push(bodies, Vector2{real(-0.5), -1});
    simulator.advanceTime();
  }
};

/// A refused action on a world, and the field it must name.
struct BadInput {
  const char* name;   // test name
  const char* field;  // expected InvalidArgument::field()
  std::function<void(TestWorld&)> action;
};

std::unique_ptr<Circle> circleAt(Vector2 r) {
  auto circle = std::make_unique<Circle>(real(0.3), 1);
  circle->r = r;
  return circle;
}

const std::vector<BadInput>& badInputs() {
  static const std::vector<BadInput> cases = {
      {"CircleRadiusNegative", "Circle.radius",
       [](TestWorld& w) { w.simulator.registerObject(std::make_unique<Circle>(real(-1), 1)); }},
      {"CircleMassNaN", "Circle.mass",
       [](TestWorld& w) { w.simulator.registerObject(std::make_unique<Circle>(1, kNaN)); }},
      {"CappedRectangleLZero", "CappedRectangle.l",
       [](TestWorld& w) {
         w.simulator.registerObject(std::make_unique<CappedRectangle>(0, 1, 1));
       }},
      {"BorderZeroNormal", "Border.normal",
       [](TestWorld& w) {
         w.simulator.registerObject(std::make_unique<Border>(Vector2{0, 5}, Vector2{0, 0}));
       }},
      {"CirclePositionNaN", "Circle.r",
       [](TestWorld& w) {
         w.simulator.registerObject(circleAt({kNaN, 3}));
       }},
      {"CirclePositionYNaN", "Circle.r",
       [](TestWorld& w) {
         w.simulator.registerObject(circleAt({3, kNaN}));
       }},
      {"CirclePositionInfinite", "Circle.r",
       [](TestWorld& w) {
         w.simulator.registerObject(circleAt({kInf, 3}));
       }},
      {"CircleAngleNaN", "Circle.alpha",
       [](TestWorld& w) {
         auto circle = circleAt({3, 3});
         circle->alpha = kNaN;
         w.simulator.registerObject(std::move(circle));
       }},
      {"CircleMassNegativeAfterConstruction", "Circle.m",
       [](TestWorld& w) {
         auto circle = circleAt({3, 3});
         circle->m = -1;
         w.simulator.registerObject(std::move(circle));
       }},
      {"CappedRectanglePositionNaN", "CappedRectangle.r",
       [](TestWorld& w) {
         auto capsule = std::make_unique<CappedRectangle>(1, real(0.2), 1);
         capsule->r = {kNaN, kNaN};
         w.simulator.registerObject(std::move(capsule));
       }},
      {"NullObject", "World.registerObject.object",
       [](TestWorld& w) { w.simulator.registerObject(std::unique_ptr<Circle>()); }},
      {"SetTimestepZero", "World.timestep", [](TestWorld& w) { w.simulator.setTimestep(0); }},
      {"SetTimestepNegative", "World.timestep",
       [](TestWorld& w) { w.simulator.setTimestep(real(-0.01)); }},
      {"SetTimestepNaN", "World.timestep", [](TestWorld& w) { w.simulator.setTimestep(kNaN); }},
      {"StartDragUnregisteredObject", "Simulator.startDrag.object",
       [](TestWorld& w) {
         Circle stranger(real(0.5), 1);
         w.simulator.startDrag(stranger, {0, 0});
       }},
      {"StartDragObjectOfAnotherSimulator", "Simulator.startDrag.object",
       [](TestWorld& w) {
         TestWorld other;
         w.simulator.startDrag(*other.bodies[0], other.bodies[0]->r);
       }},
      {"StartDragObjectWithoutShape", "Simulator.startDrag.object",
       [](TestWorld& w) {
         // An elastoid has no shape of its own (its bodies have), so there is nothing to grab:
         // registered in a world of its own, so that this one stays unchanged.
         Simulator other;
         auto elastoid = std::make_unique<Elastoid>();
         elastoid->addBody(circleAt({3, 3}));
         auto& registered = other.registerObject(std::move(elastoid));
         other.startDrag(registered, {3, 3});
         (void)w;
       }},
      {"StartDragGrabPointNaN", "Simulator.startDrag.grabPoint",
       [](TestWorld& w) {
         w.simulator.startDrag(*w.bodies[0], {kNaN, 0});
       }},
      // An object owned elsewhere, handed over in a second unique_ptr: refused and not
      // destroyed (the world still holds it, or its body or carrier does).
      {"SameObjectTwice", "World.registerObject.object",
       [](TestWorld& w) {
         w.simulator.registerObject(std::unique_ptr<PhysicalObject>(w.bodies[0]));
       }},
      {"ObjectOfAnotherSimulator", "World.registerObject.object",
       [](TestWorld& w) {
         TestWorld other;
         w.simulator.registerObject(std::unique_ptr<PhysicalObject>(other.bodies[0]));
       }},
      {"PartOfAComposedBody", "World.registerObject.object",
       [](TestWorld& w) {
         ComposedPhysicalObject body;
         auto& part = body.add(circleAt({3, 3}), {0, 0});
         w.simulator.registerObject(std::unique_ptr<Circle>(&part));
       }},
      {"SubBodyOfAnotherObject", "World.registerObject.object",
       [](TestWorld& w) {
         Elastoid carrier;
         auto& body = carrier.addBody(circleAt({3, 3}));
         w.simulator.registerObject(std::unique_ptr<Circle>(&body));
       }},
      {"RegisteredObjectAsPart", "ComposedPhysicalObject.part",
       [](TestWorld& w) {
         ComposedPhysicalObject body;
         body.add(std::unique_ptr<Circle>(static_cast<Circle*>(w.bodies[0])), {0, 0});
       }},
      {"RegisteredObjectAsSubBody", "PhysicalObject.addSubBody.body",
       [](TestWorld& w) {
         Elastoid carrier;
         carrier.addBody(std::unique_ptr<Circle>(static_cast<Circle*>(w.bodies[0])));
       }},
      {"DragToNaN", "Simulator.dragTo.target",
       [](TestWorld& w) {
         w.simulator.dragTo({0, kNaN});
       }},
  };
  return cases;
}

class RefusedInputTest : public ::testing::TestWithParam<BadInput> {};

TEST_P(RefusedInputTest, NamesTheFieldAndLeavesTheWorldUnchanged) {
  const BadInput& bad = GetParam();
  TestWorld world;
  TestWorld reference;
  const std::size_t size = world.simulator.objects.size();
  const std::uint64_t hash = scenes::stateHash(world.simulator);
  const real timestep = world.simulator.timestep();
  ASSERT_EQ(hash, scenes::stateHash(reference.simulator));

  EXPECT_EQ(thrownField([&] { bad.action(world); }), bad.field);

  EXPECT_EQ(world.simulator.objects.size(), size);
  EXPECT_EQ(scenes::stateHash(world.simulator), hash);
  EXPECT_EQ(world.simulator.timestep(), timestep);
  EXPECT_EQ(world.simulator.draggedObject(), nullptr);

  // The world moves on exactly as one that never saw the bad input.
  for (int i = 0; i < 50; ++i) {
    world.step();
    reference.step();
  }
  EXPECT_NE(scenes::stateHash(reference.simulator), hash) << "the test world should move";
  EXPECT_EQ(scenes::stateHash(world.simulator), scenes::stateHash(reference.simulator));

  // And it still accepts objects, which then behave as in the reference world.
  for (TestWorld* w : {&world, &reference}) {
    auto& circle = w->simulator.registerObject(circleAt({real(3.5), real(0.25)}));
    w->bodies.push_back(&circle);
  }
  for (int i = 0; i < 50; ++i) {
    world.step();
    reference.step();
  }
  EXPECT_EQ(world.simulator.objects.size(), size + 1);
  EXPECT_EQ(scenes::stateHash(world.simulator), scenes::stateHash(reference.simulator));
}

INSTANTIATE_TEST_SUITE_P(ValidationTest, RefusedInputTest, ::testing::ValuesIn(badInputs()),
                         [](const ::testing::TestParamInfo<BadInput>& testInfo) {
                           return std::string(testInfo.param.name);
                         });

TEST(ValidationTest, RefusedPartOfARegisteredBodyKeepsTheBodyWhole) {
  // A composed body in the world, whose part is then handed to registerObject: the refusal must
  // not destroy the part the body still steps with.
  TestWorld world;
  TestWorld reference;
  Circle* part = nullptr;
  for (TestWorld* w : {&world, &reference}) {
    auto body = std::make_unique<ComposedPhysicalObject>();
    auto& tip = body->add(std::make_unique<Circle>(real(0.25), 1), {0, 0});
    body->add(std::make_unique<CappedRectangle>(real(0.5), real(0.2), 1), {real(0.6), 0});
    body->r = {3, real(0.3)};
    w->bodies.push_back(&w->simulator.registerObject(std::move(body)));
    if (w == &world) part = &tip;
  }
  const std::uint64_t hash = scenes::stateHash(world.simulator);
  part = static_cast<Circle*>(
      world.simulator.objects[world.simulator.objects.size() - 1].primitives()[0]);
  EXPECT_EQ(thrownField([&] { world.simulator.registerObject(std::unique_ptr<Circle>(part)); }),
            "World.registerObject.object");
  EXPECT_EQ(scenes::stateHash(world.simulator), hash);
  EXPECT_EQ(part->radius(), real(0.25)) << "the part must still be alive";
  for (int i = 0; i < 50; ++i) {
    world.step();
    reference.step();
  }
  EXPECT_NE(scenes::stateHash(reference.simulator), hash);
  EXPECT_EQ(scenes::stateHash(world.simulator), scenes::stateHash(reference.simulator));
}

TEST(ValidationTest, RegisteredObjectsKnowTheirWorld) {
  TestWorld world;
  TestWorld other;
  for (const PhysicalObject* body : world.bodies)
    EXPECT_EQ(body->registeredWith(), &world.simulator);
  EXPECT_EQ(other.bodies[0]->registeredWith(), &other.simulator);
  const Circle unregistered(1, 1);
  EXPECT_EQ(unregistered.registeredWith(), nullptr);
  EXPECT_EQ(unregistered.ownedElsewhere(), nullptr);
  EXPECT_NE(world.bodies[0]->ownedElsewhere(), nullptr);
}

TEST(ValidationTest, NonFiniteValuesWrittenBetweenStepsAreRefusedBeforeTheStep) {
  // Each field of each body, NaN or infinite, written between steps: the next step throws
  // naming the field and the object's index, and leaves the world as it was; once the value
  // is repaired, the world goes on exactly as one that never saw it.
  struct Field {
    const char* name;
    real* (*at)(PhysicalObject&);
  };
  const Field fields[] = {
      {"r", [](PhysicalObject& o) { return &o.r.x; }},
      {"r", [](PhysicalObject& o) { return &o.r.y; }},
      {"alpha", [](PhysicalObject& o) { return &o.alpha; }},
      {"externalForce", [](PhysicalObject& o) { return &o.externalForce.x; }},
      {"externalForce", [](PhysicalObject& o) { return &o.externalForce.y; }},
      {"externalTorque", [](PhysicalObject& o) { return &o.externalTorque; }},
  };
  for (const Field& field : fields) {
    for (std::size_t body = 0; body < 3; ++body) {
      for (const real bad : {kNaN, kInf, -kInf}) {
        SCOPED_TRACE(std::string(field.name) + " of body " + std::to_string(body) + " = " +
                     std::to_string(bad));
        TestWorld world;
        TestWorld reference;
        world.simulator.checkInputs = true;
        for (int i = 0; i < 5; ++i) {
          world.step();
          reference.step();
        }
        PhysicalObject& object = *world.bodies[body];
        const std::size_t index = 2 + body;  // after the two borders
        ASSERT_EQ(&world.simulator.objects[index], &object);
        const std::uint64_t hash = scenes::stateHash(world.simulator);
        const std::size_t contacts = world.simulator.contacts.size();
        real* value = field.at(object);
        const real good = *value;
        *value = bad;
        try {
          world.simulator.advanceTime();
          ADD_FAILURE() << "no exception";
        } catch (const InvalidArgument& error) {
          EXPECT_EQ(error.field(), object.typeName() + "." + field.name);
          EXPECT_NE(std::string(error.what()).find("objects[" + std::to_string(index) + "]"),
                    std::string::npos)
              << error.what();
        }
        EXPECT_EQ(world.simulator.stepCount(), reference.simulator.stepCount());
        EXPECT_EQ(world.simulator.contacts.size(), contacts);
        *value = good;
        EXPECT_EQ(scenes::stateHash(world.simulator), hash);
        for (int i = 0; i < 20; ++i) {
          world.step();
          reference.step();
        }
        EXPECT_EQ(scenes::stateHash(world.simulator), scenes::stateHash(reference.simulator));
      }
    }
  }
}

TEST(ValidationTest, InputCheckIsOnByDefaultInDebugBuilds) {
  const Simulator simulator;
#ifdef NDEBUG
  EXPECT_FALSE(simulator.checkInputs);
#else
  EXPECT_TRUE(simulator.checkInputs);
#endif
}

TEST(ValidationTest, RefusedDragKeepsTheCurrentDrag) {
  // Two identical worlds dragging the same body; one is also sent bad drag requests.
  TestWorld world;
  TestWorld reference;
  for (TestWorld* w : {&world, &reference}) {
    w->simulator.startDrag(*w->bodies[2], w->bodies[2]->r + Vector2{real(0.5), 0});
    w->simulator.dragTo({3, 2});
  }
  const std::uint64_t hash = scenes::stateHash(world.simulator);

  EXPECT_EQ(thrownField([&] { world.simulator.dragTo({kNaN, 1}); }), "Simulator.dragTo.target");
  EXPECT_EQ(thrownField([&] { world.simulator.dragTo({1, kInf}); }), "Simulator.dragTo.target");
  EXPECT_EQ(thrownField([&] {
              world.simulator.startDrag(*world.bodies[0], {kNaN, kNaN});
            }),
            "Simulator.startDrag.grabPoint");
  Circle stranger(1, 1);
  EXPECT_EQ(thrownField([&] {
              world.simulator.startDrag(stranger, {0, 0});
            }),
            "Simulator.startDrag.object");
  EXPECT_EQ(
      thrownField([&] { world.simulator.startDrag(*reference.bodies[0], reference.bodies[0]->r); }),
      "Simulator.startDrag.object");

  EXPECT_EQ(world.simulator.draggedObject(), world.bodies[2]);
  EXPECT_EQ(scenes::stateHash(world.simulator), hash);
  for (int i = 0; i < 50; ++i) {
    world.step();
    reference.step();
  }
  EXPECT_NE(scenes::stateHash(reference.simulator), hash);
  EXPECT_EQ(scenes::stateHash(world.simulator), scenes::stateHash(reference.simulator));
}

TEST(ValidationTest, ValidInputIsAccepted) {
  // The counterpart of the refusals: sound values go through.
  TestWorld world;
  const std::size_t size = world.simulator.objects.size();
  EXPECT_EQ(thrownField([&] {
              world.simulator.registerObject(circleAt({3, 3}));
            }),
            "<no exception>");
  EXPECT_EQ(world.simulator.objects.size(), size + 1);
  EXPECT_EQ(thrownField([&] { world.simulator.setTimestep(real(0.005)); }), "<no exception>");
  EXPECT_EQ(world.simulator.timestep(), real(0.005));
  EXPECT_EQ(thrownField([&] {
              world.simulator.startDrag(*world.bodies[1], {2, real(0.5)});
            }),
            "<no exception>");
  EXPECT_EQ(world.simulator.draggedObject(), world.bodies[1]);
  EXPECT_EQ(thrownField([&] { world.simulator.dragTo({4, 4}); }), "<no exception>");
}

}  // namespace
}  // namespace thyrix
