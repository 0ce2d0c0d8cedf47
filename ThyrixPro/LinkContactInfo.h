#pragma once
/// @file LinkContactInfo.h
/// @brief One contact of an articulated agent, seen from the body (base or link) it touches.

#include <ThyrixLite/ContactInfo.h>

namespace thyrix {

/// A contact of an articulated agent, as ArticulatedAgentBase::linkContact() and
/// ArticulatedAgentBase::linkContacts() report it: a ContactInfo seen from the agent's body it
/// touches, whose `p` is relative to that body's centre of mass (the base's is the agent's
/// `r`). A contact between two of the agent's own links (self-collision) appears twice in
/// `contacts`, once from each side, with `other` the agent itself.
///
/// A joint at its limit is a torque contact (`type` ContactType::Torque) between the joint's
/// link and its parent: `force` is the limit's torque magnitude (N m), `sigma` the sign of the
/// torque on this body (+1 counter-clockwise), `point` the joint, `n` and `normal` zero,
/// `depth` how far the joint is past the limit (rad; negative: short of it), `index`
/// ContactInfo::noIndex.
struct LinkContactInfo : ContactInfo {
  int body = -1;  ///< the agent's body touched: -1 the base, else a link
};

}  // namespace thyrix
