#pragma once
/// @file StateRecord.h
/// @brief A sequence of exact values: one part of a WorldState (an object's, a controller's).

#include <ThyrixLite/ThyrixParameters.h>
#include <ThyrixLite/Vector2.h>

#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace thyrix {

/// The values an object, a controller or a simulator saves of its state, in the order it saves
/// them, each kept as the bits of a 64-bit word (a real exactly, whatever its precision).
///
/// A part of the world appends its values with add() in PhysicalObject::saveState() (or
/// Controller::saveState(), Simulator::saveOwnState()) and reads them back, in the same order,
/// through a StateRecord::Reader in the matching restoreState().
class StateRecord {
 public:
  /// Appends a real, bit for bit.
  void add(real value) {
    using Bits = std::conditional_t<sizeof(real) == 8, std::uint64_t, std::uint32_t>;
    words_.push_back(std::bit_cast<Bits>(value));
  }
  /// Appends both coordinates of a vector.
  void add(Vector2 value) {
    add(value.x);
    add(value.y);
  }
  /// Appends a flag.
  void add(bool value) { words_.push_back(value ? 1 : 0); }
  /// Appends an unsigned integer.
  void addWord(std::uint64_t value) { words_.push_back(value); }
  /// Appends a signed integer.
  void addInteger(std::int64_t value) { words_.push_back(static_cast<std::uint64_t>(value)); }
  /// Appends a double (a step's time, a random stream's spare draw), bit for bit.
  void addDouble(double value) { words_.push_back(std::bit_cast<std::uint64_t>(value)); }
  /// Appends every real of @p values, after their count.
  void add(std::span<const real> values) {
    addWord(values.size());
    for (const real value : values) add(value);
  }

  /// The words, in the order added.
  [[nodiscard]] std::span<const std::uint64_t> words() const { return words_; }
  /// The record of @p words, as words() gave them (WorldState::read()).
  static StateRecord fromWords(std::vector<std::uint64_t> words) {
    StateRecord record;
    record.words_ = std::move(words);
    return record;
  }

  /// Two records are equal when they hold the same words.
  friend bool operator==(const StateRecord&, const StateRecord&) = default;

  /// Reads a record's values back in the order they were added.
  class Reader {
   public:
    /// A reader of @p record from its first value; @p owner names the record in errors.
    Reader(const StateRecord& record, std::string owner)
        : words_(record.words_), owner_(std::move(owner)) {}

    /// The next value as a real.
    real value() {
      using Bits = std::conditional_t<sizeof(real) == 8, std::uint64_t, std::uint32_t>;
      return std::bit_cast<real>(static_cast<Bits>(next()));
    }
    /// The next two values as a vector.
    Vector2 vector() {
      const real x = value();
      return {x, value()};
    }
    /// The next value as a flag.
    bool flag() { return next() != 0; }
    /// The next value as an unsigned integer.
    std::uint64_t word() { return next(); }
    /// The next value as a signed integer.
    std::int64_t integer() { return static_cast<std::int64_t>(next()); }
    /// The next value as a double.
    double number() { return std::bit_cast<double>(next()); }
    /// Reads reals saved by StateRecord::add(std::span) into @p values, which must be as long.
    /// @throws std::runtime_error naming the record if the saved count differs
    void reals(std::span<real> values) {
      if (next() != values.size())
        throw std::runtime_error("WorldState: " + owner_ + " saved another number of values");
      for (real& value : values) value = this->value();
    }
    /// Reads reals saved by StateRecord::add(std::span) whatever their count.
    /// @throws std::runtime_error naming the record if it ends before them
    std::vector<real> realVector() {
      const std::uint64_t count = next();
      if (count > words_.size() - position_)
        throw std::runtime_error("WorldState: " + owner_ + "'s record ends early");
      std::vector<real> values(static_cast<std::size_t>(count));
      for (real& value : values) value = this->value();
      return values;
    }
    /// Whether every value was read.
    [[nodiscard]] bool atEnd() const { return position_ == words_.size(); }

   private:
    std::uint64_t next() {
      if (position_ == words_.size())
        throw std::runtime_error("WorldState: " + owner_ + "'s record ends early");
      return words_[position_++];
    }
    std::span<const std::uint64_t> words_;
    std::size_t position_ = 0;
    std::string owner_;
  };

 private:
  std::vector<std::uint64_t> words_;
};

}  // namespace thyrix
