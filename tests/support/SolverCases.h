#pragma once
// What the tests that run once per contact solver, or compare results bit for bit, share.

#include <ThyrixLite/ContactSolver.h>
#include <ThyrixLite/ThyrixParameters.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>

namespace thyrix::test {

/// The name of a parameterized test's solver: "Baraff" or "GaussSeidel".
inline const char* solverName(const ::testing::TestParamInfo<ContactSolverKind>& solver) {
  return solver.param == ContactSolverKind::Baraff ? "Baraff" : "GaussSeidel";
}

/// The bits of @p value: results that must be identical are compared so (== would take -0 for
/// 0).
inline std::uint64_t bitsOf(real value) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &value, sizeof value);
  return bits;
}

}  // namespace thyrix::test
