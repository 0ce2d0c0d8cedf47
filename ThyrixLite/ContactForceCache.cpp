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
  table_.reserve(tableSize(count));
  stored_.reserve(count);
}

void ContactForceCache::reset(std::size_t count) {
  const std::size_t capacity = tableSize(count);
  table_.assign(capacity, Slot{empty, 0});
  stored_.clear();
  mask_ = capacity - 1;
}

void ContactForceCache::insert(std::uint64_t key, real force) {
  std::size_t i = slot(key);
  while (table_[i].key != empty) i = (i + 1) & mask_;
  table_[i] = {key, stored_.size()};
  stored_.push_back({key, force});
}

std::size_t ContactForceCache::position(std::uint64_t key) const {
  if (table_.empty()) return stored_.size();
  for (std::size_t i = slot(key);; i = (i + 1) & mask_) {
    if (table_[i].key == key) return table_[i].position;
    if (table_[i].key == empty) return stored_.size();
  }
}

real ContactForceCache::find(std::uint64_t key) const {
  const std::size_t p = position(key);
  return p < stored_.size() ? stored_[p].force : 0;
}

real ContactForceCache::find(std::uint64_t key, std::size_t& hint) const {
  std::size_t p = hint;
  if (p >= stored_.size() || stored_[p].key != key) {
    p = position(key);
    if (p == stored_.size()) return 0;
  }
  hint = p + 1;
  return stored_[p].force;
}

}  // namespace thyrix
