#include <ThyrixLite/InvalidArgument.h>
#include <ThyrixPro/ArticulatedLimb.h>

#include <string>

namespace thyrix {

ArticulatedLimb::ArticulatedLimb(Vector2 attachment) : attachment_(attachment) {
  requireFinite(attachment, "ArticulatedLimb.attachment");
}

ArticulatedLimb ArticulatedLimb::chain(Vector2 attachment, int count, real length, real radius,
                                       real mass, real angle) {
  if (count <= 0)
    throw InvalidArgument("ArticulatedLimb.count",
                          "must be positive (got " + std::to_string(count) + ")");
  ArticulatedLimb limb(attachment);
  limb.parts_.reserve(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) limb.addLink(i - 1, length, radius, mass, i == 0 ? angle : 0);
  return limb;
}

int ArticulatedLimb::addLink(int parent, real length, real radius, real mass, real angle) {
  const int index = linkCount();
  // The parent is checked first: its tip is needed to place the joint. A parent that is not an
  // earlier link is the only way to describe a loop (or a forward reference), so it is refused
  // with the same message as any link (ArticulatedLink::validate()).
  if (parent < ArticulatedLink::base || parent >= index) {
    ArticulatedLink probe;
    probe.parent = parent;
    probe.validate(index);  // throws "ArticulatedLink.parent"
  }
  const Vector2 joint = parent == ArticulatedLink::base
                            ? Vector2{}
                            : parts_[static_cast<std::size_t>(parent)].link.tip();
  // capsule() names "ArticulatedLink.length", ".radius" and ".mass": a zero-length link is
  // refused there, since a capsule needs a segment.
  const ArticulatedLink link = ArticulatedLink::capsule(parent, joint, length / 2, radius, mass);
  requireFinite(angle, "ArticulatedLimb.angle");
  parts_.push_back({link, radius, angle});
  return index;
}

int ArticulatedLimb::addLink(const ArticulatedLink& link, real radius, real angle) {
  const int index = linkCount();
  link.validate(index);
  requirePositive(radius, "ArticulatedLimb.radius");
  requireFinite(angle, "ArticulatedLimb.angle");
  parts_.push_back({link, radius, angle});
  return index;
}

ArticulatedLimb& ArticulatedLimb::setLimits(int link, real qMin, real qMax) {
  if (link < 0 || link >= linkCount())
    throw InvalidArgument("ArticulatedLimb.link", "must be in [0, " + std::to_string(linkCount()) +
                                                      ") (got " + std::to_string(link) + ")");
  ArticulatedLink limited = parts_[static_cast<std::size_t>(link)].link;
  limited.hasLimits = true;
  limited.qMin = qMin;
  limited.qMax = qMax;
  limited.validate(link);  // names "ArticulatedLink.qMin" or ".qMax"
  parts_[static_cast<std::size_t>(link)].link = limited;
  return *this;
}

}  // namespace thyrix
