#pragma once
/// @file ArticulatedLimb.h
/// @brief A tree of capsule links (a chain, or branches) attached to an articulated agent's base
/// at one point: the building block of an agent's description.

#include <ThyrixLite/ThyrixParameters.h>
#include <ThyrixLite/Vector2.h>
#include <ThyrixPro/ArticulatedLink.h>

#include <span>
#include <vector>

namespace thyrix {

/// A limb: links on revolute joints forming a tree whose root joint(s) sit at one point of the
/// base, its attachment. Each link is a capsule (a CappedRectangle of radius `radius` whose
/// segment runs from its joint to its tip) and is added after its parent, so a loop cannot be
/// built: a parent that is not an earlier link of the limb is refused.
///
/// **Numbering.** Links are numbered in the limb from 0 in the order they are added; the parent
/// -1 means the attachment on the base. ArticulatedAgentBase renumbers them into the agent's
/// link indices (limb after limb, in order).
///
/// **Angles.** A joint angle q is the angle of the link's axis from its parent's axis (the base's
/// x axis for a root link), counter-clockwise; the `angle` given when adding a link is its
/// initial q. Joint limits are on the same q.
///
/// A plain value: build it, then pass it to an agent's constructor.
class ArticulatedLimb {
 public:
  /// One link of the limb and what the agent needs to build its shape.
  struct Part {
    /// The link; `parent` in limb numbering. For a root link `jointPosition` is an offset from
    /// the attachment (in the base's axes), zero for links added with the first addLink().
    ArticulatedLink link;
    real radius = 0;  ///< capsule radius (m)
    real angle = 0;   ///< initial joint angle q (rad)
  };

  /// An empty limb attached at @p attachment, a point of the base given in the frame the
  /// base's parts are described in (ArticulatedBasePart::position).
  /// @throws InvalidArgument naming "ArticulatedLimb.attachment" unless finite
  explicit ArticulatedLimb(Vector2 attachment);

  /// A chain of @p count equal capsule links of length @p length (joint to tip, m), radius
  /// @p radius and mass @p mass, each on the previous one's tip, the first at @p attachment
  /// turned by @p angle from the base's x axis (the others straight, q = 0).
  /// @throws InvalidArgument as addLink(), or naming "ArticulatedLimb.count" unless positive
  static ArticulatedLimb chain(Vector2 attachment, int count, real length, real radius, real mass,
                               real angle = 0);

  /// Adds a uniform capsule link of length @p length (joint to tip), radius @p radius and mass
  /// @p mass, whose joint is at the tip of link @p parent, or at the attachment for -1; its
  /// initial joint angle is @p angle. Returns its index in the limb.
  /// @throws InvalidArgument naming "ArticulatedLink.parent" unless @p parent is -1 or an
  /// earlier link of this limb (a loop or a forward reference), "ArticulatedLink.length" (for
  /// example a zero-length link), ".radius" or ".mass" unless positive and finite, or
  /// "ArticulatedLimb.angle" unless finite; the limb is then unchanged
  int addLink(int parent, real length, real radius, real mass, real angle = 0);

  /// Adds the link @p link as described (its own joint position, centre of mass, mass, inertia
  /// and limits; `link.parent` in limb numbering; for a root link `link.jointPosition` is an
  /// offset from the attachment), drawn and colliding as a capsule of radius @p radius from its
  /// joint to its tip, with initial joint angle @p angle. Returns its index in the limb.
  /// @throws InvalidArgument naming the first bad field of @p link (ArticulatedLink::validate(),
  /// e.g. "ArticulatedLink.parent" for a loop, "ArticulatedLink.length" for a zero length),
  /// "ArticulatedLimb.radius" unless positive and finite, or "ArticulatedLimb.angle" unless
  /// finite; the limb is then unchanged
  int addLink(const ArticulatedLink& link, real radius, real angle = 0);

  /// Limits the joint of link @p link to [@p qMin, @p qMax] (rad). Returns this limb.
  /// @throws InvalidArgument naming "ArticulatedLimb.link" unless it is a link of this limb,
  /// "ArticulatedLink.qMin" unless finite, or "ArticulatedLink.qMax" unless finite and at least
  /// @p qMin; the limb is then unchanged
  ArticulatedLimb& setLimits(int link, real qMin, real qMax);

  /// The attachment on the base, in the base parts' frame (m).
  [[nodiscard]] Vector2 attachment() const { return attachment_; }
  /// The number of links.
  [[nodiscard]] int linkCount() const { return static_cast<int>(parts_.size()); }
  /// The links, in limb numbering.
  [[nodiscard]] std::span<const Part> parts() const { return parts_; }

 private:
  Vector2 attachment_;
  std::vector<Part> parts_;
};

}  // namespace thyrix
