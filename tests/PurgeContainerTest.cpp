// Tests of Tools/PurgeContainer.h: the objects a container owns are deleted, and it is emptied
// with its memory given back.

#include <Tools/PurgeContainer.h>
#include <gtest/gtest.h>

#include <list>
#include <memory>
#include <vector>

namespace thyrix {
namespace {

// Counts its live instances, so that a leak or a double deletion shows as a wrong count.
class Counted {
 public:
  explicit Counted(int* live) : live_(live) { ++*live_; }
  Counted(const Counted& other) : live_(other.live_) { ++*live_; }
  Counted& operator=(const Counted&) = delete;
  ~Counted() { --*live_; }

 private:
  int* live_;
};

TEST(PurgeContainerTest, DeletesTheObjectsOfRawOwningPointers) {
  int live = 0;
  std::vector<Counted*> owned;
  for (int i = 0; i < 10; ++i) owned.push_back(new Counted(&live));
  ASSERT_EQ(live, 10);
  purgeContainer(owned);
  EXPECT_EQ(live, 0) << "every object the container pointed to is deleted";
  EXPECT_TRUE(owned.empty());
  EXPECT_EQ(owned.capacity(), 0u);
}

TEST(PurgeContainerTest, SkipsNullPointersAndWorksOnLists) {
  int live = 0;
  std::list<Counted*> owned{new Counted(&live), nullptr, new Counted(&live), nullptr};
  ASSERT_EQ(live, 2);
  purgeContainer(owned);
  EXPECT_EQ(live, 0);
  EXPECT_TRUE(owned.empty());
}

TEST(PurgeContainerTest, DeletesThroughAPointerToConst) {
  int live = 0;
  std::vector<const Counted*> owned{new Counted(&live), new Counted(&live)};
  purgeContainer(owned);
  EXPECT_EQ(live, 0);
  EXPECT_TRUE(owned.empty());
}

TEST(PurgeContainerTest, EmptiesUniquePointers) {
  int live = 0;
  std::vector<std::unique_ptr<Counted>> owned;
  for (int i = 0; i < 5; ++i) owned.push_back(std::make_unique<Counted>(&live));
  ASSERT_EQ(live, 5);
  purgeContainer(owned);
  EXPECT_EQ(live, 0);
  EXPECT_TRUE(owned.empty());
  EXPECT_EQ(owned.capacity(), 0u);
}

TEST(PurgeContainerTest, SharedPointersLetTheirOtherOwnersKeepTheObject) {
  int live = 0;
  std::vector<std::shared_ptr<Counted>> owned;
  for (int i = 0; i < 4; ++i) owned.push_back(std::make_shared<Counted>(&live));
  const std::shared_ptr<Counted> kept = owned[2];
  purgeContainer(owned);
  EXPECT_EQ(live, 1) << "only the object with an owner outside the container survives";
  EXPECT_TRUE(owned.empty());
}

TEST(PurgeContainerTest, DestroysValuesAndReleasesCapacity) {
  int live = 0;
  {
    std::vector<Counted> items;
    items.reserve(10);
    for (int i = 0; i < 10; ++i) items.emplace_back(&live);
    EXPECT_EQ(live, 10);
    purgeContainer(items);
    EXPECT_EQ(live, 0);
    EXPECT_EQ(items.capacity(), 0u);
  }
  EXPECT_EQ(live, 0);
}

TEST(PurgeContainerTest, ContainerIsUsableAfterwards) {
  std::vector<int> values(1000, 7);
  values.reserve(5000);
  purgeContainer(values);
  EXPECT_TRUE(values.empty());
  EXPECT_EQ(values.capacity(), 0u);
  values.push_back(3);
  ASSERT_EQ(values.size(), 1u);
  EXPECT_EQ(values[0], 3);
}

}  // namespace
}  // namespace thyrix
