#pragma once
/// @file WorldState.h
/// @brief Everything that can change a simulator's next step, as one copyable value.

#include <ThyrixLite/StateRecord.h>

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

namespace thyrix {

/// A snapshot of a Simulator: everything its next step reads that a step can change (poses,
/// velocities, pending forces and torques, the mouse drag, the last step's contacts with their
/// forces, each shape's last detected place from which its speculative travel follows, link
/// lengths, joint state, sensor sums, controllers and their random streams, an agent
/// simulator's own bookkeeping). Everything else a simulator keeps is a cache rebuilt from
/// this. Settings (time step, gravity, solver and its tuning) are the world's configuration,
/// not its state: the world a state is restored into must be built the same way.
///
/// Made by Simulator::saveState(), used by Simulator::restoreState(); write() and read() keep
/// it in a versioned, checksummed binary form, exact to the bit.
class WorldState {
 public:
  /// The format version write() writes and read() accepts.
  static constexpr std::uint32_t formatVersion = 1;

  /// Writes the state to @p out: a magic word, the version, the precision of reals, the
  /// payload's length, the payload, and its FNV-1a checksum.
  /// @throws std::runtime_error if the stream fails
  void write(std::ostream& out) const;
  /// Reads a state written by write().
  /// @throws std::runtime_error saying what is wrong for a stream that is not a world state,
  ///         of another version or precision, truncated, or whose checksum does not match
  static WorldState read(std::istream& in);

  /// A 64-bit FNV-1a hash of the whole state: equal states have equal hashes.
  [[nodiscard]] std::uint64_t hash() const;

  /// The make-up the state was saved from (object types and shapes), one object a line.
  [[nodiscard]] const std::string& makeUp() const { return makeUp_; }

  /// Two states are equal when every value is, bit for bit.
  friend bool operator==(const WorldState&, const WorldState&) = default;

 private:
  friend class Simulator;
  /// The payload write() checksums: the make-up and the sections.
  [[nodiscard]] std::string payload() const;

  std::string makeUp_;
  // The simulator's own values, then one section per object in registration order, then the
  // values of the simulator's subclass (Simulator::saveOwnState()).
  std::vector<StateRecord> sections_;
};

}  // namespace thyrix
