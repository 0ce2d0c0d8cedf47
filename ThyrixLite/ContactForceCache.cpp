#include <ThyrixLite/ContactForceCache.h>

#include <algorithm>

namespace thyrix {

std::size_t ContactForceCache::slot(std::uint64_t key) const {
  return static_cast<std::size_t>((key * 0x9E3779B97F4A7C15ull) >> 17) & mask_;
}

namespace {
std::size_t tableSize(std::size_t count) {
  std::size_t capacity = 16;
  while (capacity < 2 * count) capacity <<= 1;  // load factor at most one half
  return capacity;
}
}  // namespace

void ContactForceCache::reserve(std::size_t count) {
  keys_.reserve(tableSize(count));
  forces_.reserve(tableSize(count));
}

void ContactForceCache::reset(std::size_t count) {
  const std::size_t capacity = tableSize(count);
  keys_.assign(capacity, empty);
  forces_.resize(capacity);
  mask_ = capacity - 1;
  entries_ = 0;
}

void ContactForceCache::insert(std::uint64_t key, real force) {
  std::size_t i = slot(key);
  while (keys_[i] != empty) i = (i + 1) & mask_;
  keys_[i] = key;
  forces_[i] = force;
  ++entries_;
}

real ContactForceCache::find(std::uint64_t key) const {
  if (keys_.empty()) return 0;
  for (std::size_t i = slot(key);; i = (i + 1) & mask_) {
    if (keys_[i] == key) return forces_[i];
    if (keys_[i] == empty) return 0;
  }
}

}  // namespace thyrix
