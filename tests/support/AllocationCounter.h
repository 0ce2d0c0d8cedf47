#pragma once
// Counting of heap allocations for tests. Linking support/AllocationCounter.cpp into a test
// program replaces the global operator new and delete (C++ allows one replacement per
// program) with versions that count calls and live bytes.

namespace thyrix::test {

/// Calls to the global operator new so far.
long allocationCount();
/// Bytes allocated through operator new and not yet freed.
long liveHeapBytes();

}  // namespace thyrix::test
