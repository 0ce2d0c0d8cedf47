#pragma once
/// @file SameAgentMotion.h
/// @brief Expects two articulated agents to be in the same state, bit for bit.

#include "SolverCases.h"

#include <ThyrixPro/ArticulatedAgentBase.h>

#include <gtest/gtest.h>

namespace thyrix::test {

/// Expects every body of @p one and @p other (base first) to have the same bits in its centre
/// of mass, angle, velocity and angular velocity: two runs that must compute the same thing.
inline void expectSameAgentMotion(const ArticulatedAgentBase& one,
                                  const ArticulatedAgentBase& other) {
  ASSERT_EQ(one.linkCount(), other.linkCount());
  for (int b = ArticulatedAgentBase::base; b < one.linkCount(); ++b) {
    EXPECT_EQ(bitsOf(one.centerOfMass(b).x), bitsOf(other.centerOfMass(b).x)) << b;
    EXPECT_EQ(bitsOf(one.centerOfMass(b).y), bitsOf(other.centerOfMass(b).y)) << b;
    EXPECT_EQ(bitsOf(one.bodyAngle(b)), bitsOf(other.bodyAngle(b))) << b;
    EXPECT_EQ(bitsOf(one.bodyVelocity(b).x), bitsOf(other.bodyVelocity(b).x)) << b;
    EXPECT_EQ(bitsOf(one.bodyVelocity(b).y), bitsOf(other.bodyVelocity(b).y)) << b;
    EXPECT_EQ(bitsOf(one.bodyAngularVelocity(b)), bitsOf(other.bodyAngularVelocity(b))) << b;
  }
}

}  // namespace thyrix::test
