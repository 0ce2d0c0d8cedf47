#pragma once
/// @file Elastoid.h
/// @brief The base of agents made of bodies joined by elastic links.

#include <ThyrixLite/ElasticLink.h>
#include <ThyrixLite/PhysicalObject.h>

#include <memory>
#include <vector>

namespace thyrix {

/// An agent made of rigid bodies joined by ElasticLinks (Spherus, Pac). Registering the
/// elastoid registers its bodies right after it. The elastoid itself has no shape and never
/// moves; each step, before the bodies' velocities are computed, it applies its links' forces.
/// Its bodies share a collision group, so they pass through each other; objects that are not
/// its bodies collide with them as usual.
///
/// Subclasses add bodies and links in their constructor and override control() to read their
/// sensors and set motor forces and commanded rest lengths for the next step.
class Elastoid : public PhysicalObject {
 public:
  Elastoid();

  /// Adds a body (registered with the world right after the elastoid) and returns it.
  template <class T>
  T& addBody(std::unique_ptr<T> body) {
    T& added = addSubBody(std::move(body));
    bodies_.push_back(&added);
    return added;
  }
  /// Adds a link between two of the bodies and returns it.
  ElasticLink& addLink(PhysicalObject& a, Vector2 anchorA, PhysicalObject& b, Vector2 anchorB,
                       real restLength, real stiffness);

  /// The bodies, in the order they were added.
  [[nodiscard]] std::span<PhysicalObject* const> bodies() const { return bodies_; }
  /// The links, in the order they were added.
  [[nodiscard]] const std::vector<std::unique_ptr<ElasticLink>>& links() const { return links_; }

  /// Applies the links' forces to the bodies (phase 5; the bodies come next in the same phase).
  void computeDerivativesWithoutContacts() override;
  /// Nothing: the elastoid has no mass of its own, and its bodies, registered as objects, are
  /// weighed in their own turn (once each).
  void applyWeight(Vector2 gravity) override;
  /// The elastoid has no pose of its own to integrate.
  void integrate(real dt) override;
  void validate() const override;
  /// PhysicalObject::saveState(), then each link's rest length and tension (its bodies are
  /// objects of their own, saved by the simulator).
  void saveState(StateRecord& record) const override;
  /// Reads back what saveState() appended.
  void restoreState(StateRecord::Reader& reader) override;
  /// Draws the links (the bodies draw themselves).
  void draw(GUI& gui) const override;
  [[nodiscard]] std::string typeName() const override { return "Elastoid"; }

 protected:
  void onRegistered(Simulator& simulator) noexcept override;

 private:
  std::vector<PhysicalObject*> bodies_;
  std::vector<std::unique_ptr<ElasticLink>> links_;
  const Simulator* simulator_ = nullptr;
};

}  // namespace thyrix
