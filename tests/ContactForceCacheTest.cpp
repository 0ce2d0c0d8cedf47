// The warm-start cache: what is stored is found again, whatever hint the lookup is given.

#include <ThyrixLite/ContactForceCache.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace thyrix {
namespace {

struct Stored {
  std::uint64_t key;
  real force;
};

/// 300 contacts of a crowd: shape pairs with one or two features, forces all different.
std::vector<Stored> someContacts() {
  std::vector<Stored> stored;
  for (std::uint32_t a = 0; a < 100; ++a)
    for (std::uint32_t feature = 0; feature < (a % 3 == 0 ? 2u : 1u); ++feature)
      for (const std::uint32_t b : {a + 1, a + 7})
        stored.push_back(
            {ContactForceCache::key(a, b, feature), real(1) + static_cast<real>(stored.size())});
  return stored;
}

TEST(ContactForceCache, FindsWhatWasStoredAndZeroForTheRest) {
  ContactForceCache cache;
  const std::vector<Stored> stored = someContacts();
  cache.reset(stored.size());
  for (const Stored& s : stored) cache.insert(s.key, s.force);
  for (const Stored& s : stored) EXPECT_EQ(cache.find(s.key), s.force);
  EXPECT_EQ(cache.find(ContactForceCache::key(5, 6, 1)), 0);  // shape 5 has one feature
  EXPECT_EQ(cache.find(ContactForceCache::key(200, 201, 0)), 0);
}

TEST(ContactForceCache, AHintChangesNothingButWhereTheSearchStarts) {
  ContactForceCache cache;
  const std::vector<Stored> stored = someContacts();
  cache.reset(stored.size());
  for (const Stored& s : stored) cache.insert(s.key, s.force);
  // The same order as stored (every hint right), reversed (every hint wrong), and absent keys
  // in between: the forces are those found without a hint.
  std::size_t hint = 0;
  for (const Stored& s : stored) {
    EXPECT_EQ(cache.find(s.key, hint), s.force);
    EXPECT_EQ(cache.find(s.key ^ (std::uint64_t{1} << 40), hint), 0);  // absent: hint kept
  }
  EXPECT_EQ(hint, stored.size());
  hint = 0;
  for (auto s = stored.rbegin(); s != stored.rend(); ++s)
    EXPECT_EQ(cache.find(s->key, hint), s->force);
  hint = stored.size() + 5;  // past the end
  EXPECT_EQ(cache.find(stored[3].key, hint), stored[3].force);
  EXPECT_EQ(hint, 4u);
}

TEST(ContactForceCache, ResetForgetsAndClearEmpties) {
  ContactForceCache cache;
  cache.reset(4);
  cache.insert(ContactForceCache::key(1, 2, 0), real(3));
  cache.reset(4);
  EXPECT_EQ(cache.find(ContactForceCache::key(1, 2, 0)), 0);
  cache.insert(ContactForceCache::key(1, 2, 0), real(3));
  cache.clear();
  std::size_t hint = 0;
  EXPECT_EQ(cache.find(ContactForceCache::key(1, 2, 0), hint), 0);
  EXPECT_EQ(hint, 0u);
}

}  // namespace
}  // namespace thyrix
