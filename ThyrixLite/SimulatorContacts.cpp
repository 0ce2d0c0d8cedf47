/// @file SimulatorContacts.cpp
/// @brief Phases 2 and 3 of a step: broad and narrow phase, contact indexing (the shapes'
/// geometry is in SimulatorGeometry.cpp, the borders' reach in SimulatorBorderReach.cpp).
#include <ThyrixLite/NarrowPhase.h>
#include <ThyrixLite/Simulator.h>
#include <Tools/Inlining.h>

#include <algorithm>
#include <bit>
#include <cmath>

namespace thyrix {

namespace {

/// Whether shapes @p a and @p b of one body, whose shapes begin at @p first, may touch: only
/// a multi-body object's may, and only where its filter says (its neighbouring links never do).
bool ownShapesMayTouch(const MultiBodyObject* multi, std::uint32_t first, std::uint32_t a,
                       std::uint32_t b) {
  return multi != nullptr && multi->selfCollision().mayTouch(a - first, b - first);
}

}  // namespace

void Simulator::markNeverPaired(std::uint32_t body) {
  // Bit d - 1 of a grid shape's word: the grid shape d slots later is of the same body and
  // the pair is one detectContacts drops (ownShapesMayTouch), whatever the poses. A body's
  // shapes are consecutive, and so are their grid slots (borders have none).
  const BodyState& state = bodyStates_[body];
  if (state.shapeCount < 2) return;  // no pair of its own (its words, if any, stay 0)
  const std::uint32_t first = state.firstShape;
  const std::uint32_t end = first + state.shapeCount;
  neverPaired_.bits.resize(gridShapes_.size(), 0);
  const MultiBodyObject* const multi = multiBodies_[body];
  if (multi != nullptr && gridSlot_[first] != ~0u && gridSlot_[end - 1] != ~0u &&
      gridSlot_[end - 1] - gridSlot_[first] == end - 1 - first) {
    // Every shape in the grid, in slots as consecutive as the shapes: the filter's own words
    // (what ownShapesMayTouch reads for shapes up to 64 apart), one per shape.
    for (std::uint32_t a = first; a < end; ++a)
      neverPaired_.bits[gridSlot_[a]] = multi->selfCollision().apartAfter(a - first);
    return;
  }
  for (std::uint32_t a = first; a < end; ++a) {
    const std::uint32_t slot = gridSlot_[a];
    if (slot == ~0u) continue;
    std::uint64_t word = 0;
    for (std::uint32_t b = a + 1; b < end; ++b) {
      const std::uint32_t other = gridSlot_[b];
      if (other == ~0u) continue;
      if (other - slot > 64) break;
      if (!ownShapesMayTouch(multi, first, a, b)) word |= std::uint64_t{1} << (other - slot - 1);
    }
    neverPaired_.bits[slot] = word;
  }
}

void Simulator::updateNeverPaired() {
  // Registration only appends: the new objects' bits are added. A multi-body object's rules
  // may be set again (a new stamp): its bits are then marked again.
  NeverPaired& never = neverPaired_;
  for (std::size_t index = never.objects; index < bodyStates_.size(); ++index) {
    const auto body = static_cast<std::uint32_t>(index);
    if (multiBodies_[index] != nullptr)
      never.rules.emplace_back(body, multiBodies_[index]->selfCollision().stamp());
    markNeverPaired(body);
  }
  if (never.objects != bodyStates_.size() && !never.bits.empty())
    never.bits.resize(gridShapes_.size(), 0);  // the shapes added alone pair with any other
  never.objects = bodyStates_.size();
  for (auto& [body, stamp] : never.rules) {
    const std::uint64_t now = multiBodies_[body]->selfCollision().stamp();
    if (now == stamp) continue;
    stamp = now;
    markNeverPaired(body);
  }
}

// Inline: detectContacts() calls it once, for the default mode (a call cost small worlds' steps).
THYRIX_ALWAYS_INLINE void Simulator::detectPairs(bool reuse) {
  // The pairs of two circles in reach (most of a crowd's) are batched: their square roots and
  // divisions, in a short loop of their own, overlap from pair to pair (measured: one pair
  // at a time, each waited for the last). A batch is emptied before any other pair adds
  // contacts, so the order is the pairs'.
  CirclePair batch[circleBatch];
  std::size_t batched = 0;
  // (An empty batch is no call: most pairs of a small world at rest find it empty.)
  const auto flush = [&] {
    if (batched == 0) return;
    addCirclePairs(std::span<const CirclePair>(batch, batched));
    batched = 0;
  };
  for (const BoxPair& pair : pairs_) {
    const std::uint32_t a = gridShapes_[pair.first];
    const std::uint32_t b = gridShapes_[pair.second];
    // Pairs within one body are settled here, without a call: a chain's neighbouring links
    // overlap in every step and never touch (the sweep leaves such pairs out already, the
    // few-box test and the grid do not).
    const Shape& sa = shapes_[a];
    const Shape& sb = shapes_[b];
    if (sa.body == sb.body) {
      // Tested whether or not the shapes moved (so is a border's: whether it collides is its
      // object's call).
      if (ownShapesMayTouch(multiBodies_[sa.body], bodyStates_[sa.body].firstShape, a, b)) {
        flush();
        addContacts(a, b);
      }
      continue;
    }
    if (reuse && (shapeMoved_[a] | shapeMoved_[b]) == 0) {
      flush();
      // (Of two bodies: reusePair's shape A is the one addContacts would take first.)
      const bool swap = sb.type < sa.type;
      reusePair(swap ? b : a, swap ? a : b);
    } else if (sa.type == ShapeType::Circle && sb.type == ShapeType::Circle) {
      // Kept (the count advanced) without a branch: which candidates are in reach is random to
      // the predictor.
      batched += std::size_t{circlesInReach(a, b, batch[batched])};
      if (batched == circleBatch) flush();
    } else {
      flush();
      addContacts(a, b);
    }
  }
  flush();
  findBorderContacts(reuse);
}

void Simulator::detectContacts() {
  // Appending to contacts of another detection: this list is no basis for the next reuse.
  const bool fromEmpty = contacts.empty();
  const auto start = static_cast<std::uint32_t>(contacts.size());
  if (referenceMode) {
    updateGeometryPlainly();
    cachesForgotten_ = true;
  } else {
    if (cachesForgotten_) forgetCaches();  // (they did not follow the reference mode's steps)
    cachesForgotten_ = false;
    updateGeometry();
  }
  // Reuse needs the last detection's complete list (eraseContacts kept it aside).
  // (Only pairs of unmoved shapes are reused: none when every shape moved.)
  const bool reuse = restSkipping && !referenceMode && previousValid_ && fromEmpty;
  previousIndexed_ = false;  // indexed at most once a detection, for the shapes of now
  previousCursor_ = 0;
  previousCount_ = previousContacts_.size();
  reusedBegin_ = 0;  // no run of reused contacts yet
  reusedEnd_ = 0;
  if (pairChains_.size() != shapes_.size()) {  // new shapes: no pair in either list yet
    pairChains_.resize(shapes_.size());
    previousChains_.resize(shapes_.size());
  }
  nextListStamp();
  fitCountedObjects();
  contactsSolved_ = false;  // these contacts, until the solver gives them forces
  statistics_.reusedContacts = 0;
  if (referenceMode) {
    findPairsPlainly();
    for (const BoxPair& pair : pairs_)
      addContactsPlainly(gridShapes_[pair.first], gridShapes_[pair.second]);
    findBorderContactsPlainly();
  } else {
    // (Without new objects or objects with rules, there is nothing to look at.)
    if (neverPaired_.objects != bodyStates_.size() || !neverPaired_.rules.empty())
      updateNeverPaired();
    broadPhase_.setNeverPaired(neverPaired_.bits);
    broadPhase_.findPairs(gridBoxes_, gridMovedBits_, pairs_,
                          gridExtentsCount_ == gridShapes_.size() ? &gridExtents_ : nullptr);
    // Above its all-pairs limit the broad phase gives the pairs in the order of its grid, its
    // sweep or its memory of earlier calls; sorted, the contacts' order, which the solvers
    // follow, depends on the boxes alone (as a restored world's must).
    if (pairs_.size() > 1 && gridBoxes_.size() > BroadPhase::smallCount) sortPairs();
    detectPairs(reuse);
  }
  flushReused();
  if (contacts.size() > scannedListLength) chainFirstPairs(start);
  contactsComplete_ = fromEmpty;
  previousValid_ = false;  // used: the next detection compares against this one
  listsPending_ = true;    // (the objects' lists are made when first read)
  originsDetected_ = true;
  statistics_.contacts = contacts.size();
  if (referenceMode) {
    for (PhysicalObject& object : objects) object.updateSensors(*this);
  } else {
    for (const std::uint32_t index : customObjects_) objects[index].updateSensors(*this);
  }
}

void Simulator::sortPairs() {
  // A counting sort by first box, then an insertion sort by the whole pair, which only moves
  // pairs within their first box's few.
  const auto before = [](const BoxPair& a, const BoxPair& b) {
    return (std::uint64_t{a.first} << 32 | a.second) < (std::uint64_t{b.first} << 32 | b.second);
  };
  if (std::is_sorted(pairs_.begin(), pairs_.end(), before)) return;
  pairStart_.assign(gridBoxes_.size() + 1, 0);
  std::uint32_t* const start = pairStart_.data();
  for (const BoxPair& pair : pairs_) ++start[pair.first + 1];
  for (std::size_t i = 1; i < pairStart_.size(); ++i) start[i] += start[i - 1];
  sortedPairs_.resize(pairs_.size());
  BoxPair* const sorted = sortedPairs_.data();
  for (const BoxPair& pair : pairs_) sorted[start[pair.first]++] = pair;
  for (std::size_t k = 1; k < sortedPairs_.size(); ++k) {
    const BoxPair pair = sorted[k];
    std::size_t j = k;
    for (; j > 0 && before(pair, sorted[j - 1]); --j) sorted[j] = sorted[j - 1];
    sorted[j] = pair;
  }
  std::swap(pairs_, sortedPairs_);
}

void Simulator::findBorderContacts(bool reuse) {
  // Borders skip the broad phase: each meets every grid shape whose box reaches behind its
  // line. Which shapes do is kept as one bit per grid shape and border, retested only for
  // moved shapes; then the pairs are visited border by border, shape by shape.
  const std::size_t count = gridShapes_.size();
  const std::size_t words = (count + 63) / 64;
  const bool remembered = restSkipping && reachShapes_ == count;
  reachShapes_ = count;
  borderReach_.resize(borderShapes_.size() * words);
  if (!(remembered && findBorderReachTogether(words))) {
    for (std::size_t k = 0; k < borderShapes_.size(); ++k)
      findBorderReach(k, words, !remembered || shapeMoved_[borderShapes_[k]] != 0);
  }
  // (The words one after another, border by border. A word with no shape in reach, most of a
  // small world's, is passed over before anything is set up for its pairs.)
  const std::uint64_t* reach = borderReach_.data();
  for (const std::uint32_t border : borderShapes_) {
    for (std::size_t first = 0; first < count; first += 64, ++reach)
      if (*reach != 0) addBorderPairs(border, first, *reach, reuse && remembered);
  }
}

// Out of line: findBorderContacts' loop then keeps few values across its calls.
THYRIX_NO_INLINE void Simulator::addBorderPairs(std::uint32_t border, std::size_t first,
                                                std::uint64_t bits, bool reuse) {
  // A pair keeps its contacts if neither the border nor the shape moved.
  const bool reuseBorder = reuse && shapeMoved_[border] == 0;
  const std::uint32_t borderBody = shapes_[border].body;
  for (; bits != 0; bits &= bits - 1) {
    const std::uint32_t shape =
        gridShapes_[first + static_cast<std::size_t>(std::countr_zero(bits))];
    // (The border is shape A: a half-plane comes first. A pair within one body is always
    // tested: whether it collides is its object's call.)
    if (reuseBorder && shapeMoved_[shape] == 0 && shapes_[shape].body != borderBody)
      reusePair(border, shape);
    else
      addContacts(border, shape);
  }
}

// Inline: before each batch of contacts appended.
inline Simulator::ContactPair* Simulator::notesFor(std::size_t count) {
  if (count > contactPairs_.size())  // rare: the buffer doubles
    contactPairs_.resize(std::max({count, 2 * contactPairs_.size(), std::size_t{64}}));
  return contactPairs_.data();
}

// Inline: the first contact of every pair appended from position scannedListLength on is
// chained. (A short list, a small world's, is searched by a scan instead (findPreviousPair);
// its first pairs are chained if it grows longer, at the end of the detection:
// chainFirstPairs().)
inline void Simulator::chainPair(ContactPair* notes, std::uint32_t position, std::uint32_t shapeA) {
  // Without a branch (whether a circle's pair is its first as shape A is random; GCC made
  // the selects a branch): a mask of ones when the chain goes on. A shape's first pair writes
  // its own link (noPair, all ones, as it is).
  PairChain& chain = pairChains_[shapeA];
  const std::uint32_t on = 0u - std::uint32_t{chain.stamp == listStamp_};
  notes[(chain.last & on) | (position & ~on)].nextOfA = position | ~on;
  chain.first = (chain.first & on) | (position & ~on);
  chain.last = position;
  chain.pairsAndRun = (chain.pairsAndRun & on) + 1;
  chain.stamp = listStamp_;
}

// Inline: every contact appended is noted (SimulatorPreviousContacts.cpp reads the notes).
inline void Simulator::noteContactPair(ContactPair* notes, std::uint32_t position,
                                       std::uint32_t shapeA, std::uint32_t shapeB, bool first) {
  // A detection visits each pair once and appends its points one after another: the first
  // point's pair is chained to shape A's last one, or begins its chain.
  notes[position] = {pairKey(shapeA, shapeB), noPair};
  if (first && position >= scannedListLength) chainPair(notes, position, shapeA);
}

// Inline: every contact appended is counted.
inline void Simulator::countContact(std::uint32_t bodyA, std::uint32_t bodyB) {
  // Each body listed at its first contact without a branch (which contact is a body's first is
  // random to the predictor): written in the next place, which is kept if it was.
  std::uint32_t* const count = objectContactCursor_.data();
  std::uint32_t* const counted = countedObjects_.data();
  counted[countedCount_] = bodyA;
  countedCount_ += std::size_t{count[bodyA]++ == 0};
  counted[countedCount_] = bodyB;
  countedCount_ += std::size_t{count[bodyB]++ == 0};
}

void Simulator::chainFirstPairs(std::uint32_t start) {
  // The pairs chainPair() left out (positions start to scannedListLength - 1), put at the
  // heads of their chains last first: the chains are then as if each pair had been chained
  // in order.
  ContactPair* const notes = contactPairs_.data();
  const auto end = static_cast<std::uint32_t>(std::min(contacts.size(), scannedListLength));
  for (std::uint32_t position = end; position-- > start;) {
    if (position > start && notes[position - 1].key == notes[position].key)
      continue;  // not its pair's first contact
    PairChain& chain = pairChains_[notes[position].key >> 32];
    if (chain.stamp == listStamp_) {
      notes[position].nextOfA = chain.first;
      chain.first = position;
      ++chain.pairsAndRun;
    } else {
      chain = {position, position, 1, listStamp_};  // (its link is noPair, as noted)
    }
  }
}

// Out of line: objects registered since (rare); its callers then save no registers for it.
THYRIX_NO_INLINE void Simulator::growCountedObjects() {
  countedObjects_.resize(objects.size() + 1);
}

void Simulator::resetCounts() {
  for (std::size_t k = 0; k < countedCount_; ++k) objectContactCursor_[countedObjects_[k]] = 0;
  countedCount_ = 0;
  fitCountedObjects();
}

// Inline: the detection loop and the borders' loop call it for every pair at rest.
inline void Simulator::reusePair(std::uint32_t shapeA, std::uint32_t shapeB) {
  // Neither shape moved and its filters did not change: the contacts are last detection's.
  // Pairs at rest come in the last step's order, so their contacts follow one another there:
  // they are appended as a run, when another contact is to follow them (flushReused()).
  const PreviousRange range = previousContactsOf(shapeA, shapeB);
  if (range.begin == range.end) return;  // in reach, not touching
  if (range.begin != reusedEnd_) {
    flushReused();
    reusedBegin_ = range.begin;
  }
  reusedEnd_ = range.end;
}

// Inline: before every other batch of contacts appended (most find no run).
inline void Simulator::flushReused() {
  if (reusedBegin_ != reusedEnd_) appendReused();
}

void Simulator::appendReused() {
  // The run's contacts as they were but for the force (the solver's output, not detection's),
  // counted and noted as if appended one by one.
  const std::uint32_t begin = reusedBegin_;
  const std::uint32_t count = reusedEnd_ - begin;
  reusedBegin_ = reusedEnd_;
  std::vector<GlobalContactInfo>& items = contacts.items_;
  const auto position = static_cast<std::uint32_t>(items.size());
  ContactPair* const notes = notesFor(std::size_t{position} + count);
  const GlobalContactInfo* const from = previousContacts_.data() + begin;
  items.insert(items.end(), from, from + count);
  GlobalContactInfo* const to = items.data() + position;
  const ContactPair* const pairs = previousPairs_.data() + begin;
  for (std::uint32_t i = 0; i < count; ++i) {
    to[i].force = 0;
    countContact(to[i].bodyA, to[i].bodyB);
    const std::uint64_t key = pairs[i].key;
    notes[position + i] = {key, noPair};
    // (The run holds whole pairs: its first contact begins one.)
    if (position + i >= scannedListLength && (i == 0 || key != pairs[i - 1].key))
      chainPair(notes, position + i, static_cast<std::uint32_t>(key >> 32));
  }
  statistics_.reusedContacts += count;
}

// Inline: appendContacts and the circle batches store every contact through it.
inline void Simulator::appendContact(std::uint32_t shapeA, std::uint32_t shapeB,
                                     const ManifoldPoint& p, Vector2 normal) {
  const Shape& a = shapes_[shapeA];
  const Shape& b = shapes_[shapeB];
  contacts.items_.push_back({a.object, b.object, a.primitive, b.primitive, a.body, b.body, shapeA,
                             shapeB, p.feature, 0, p.point, normal, p.depth});
  countContact(a.body, b.body);
}

// Inline: the narrow phase calls it for every pair in reach.
inline void Simulator::appendContacts(std::uint32_t shapeA, std::uint32_t shapeB,
                                      const Manifold& manifold) {
  flushReused();  // (the reused contacts before it come first)
  const auto position = static_cast<std::uint32_t>(contacts.items_.size());
  const auto count = static_cast<std::uint32_t>(manifold.count);
  ContactPair* const notes = notesFor(std::size_t{position} + count);
  for (std::uint32_t i = 0; i < count; ++i) {
    appendContact(shapeA, shapeB, manifold.points[i], manifold.normal);
    noteContactPair(notes, position + i, shapeA, shapeB, i == 0);
  }
}

// Inline: the detection loop calls it for every pair of two circles.
inline bool Simulator::circlesInReach(std::uint32_t shapeA, std::uint32_t shapeB,
                                      CirclePair& pair) const {
  const Shape& a = shapes_[shapeA];
  const Shape& b = shapes_[shapeB];
  if (!a.movable && !b.movable) return false;
  if (a.group != 0 && a.group == b.group) return false;
  const ShapeGeometry& ga = geometry_[shapeA];
  const ShapeGeometry& gb = geometry_[shapeB];
  const real margin = std::min(ga.margin, gb.margin) + ga.travel + gb.travel;
  // Some candidate pairs of a crowd are out of reach: a conservative test on squared
  // distances (no square root, no call) drops them; the rest get the exact test.
  const Vector2 d = gb.p0 - ga.p0;
  // (The pair is written whether or not it is kept, so that the caller need not branch.)
  const real reach = (ga.radius + gb.radius + margin) * (1 + 64 * realEpsilon);
  pair = {ga.p0.x, ga.p0.y, gb.p0.x, gb.p0.y, ga.radius, gb.radius, margin, shapeA, shapeB};
  return !(d.lengthSquared() > reach * reach);
}

void Simulator::addCirclePairs(std::span<const CirclePair> pairs) {
  // collideCircles' one point, stored without a Manifold in between (zeroed, then read back
  // in a loop over its points).
  flushReused();  // (the reused contacts before them come first)
  auto position = static_cast<std::uint32_t>(contacts.items_.size());
  ContactPair* const notes = notesFor(position + pairs.size());
  const auto add = [&](auto longList) {
    for (const CirclePair& pair : pairs) {
      Vector2 normal;
      ManifoldPoint p;
      if (!narrow_phase::circlesPoint({pair.centreAx, pair.centreAy}, pair.radiusA,
                                      {pair.centreBx, pair.centreBy}, pair.radiusB, pair.margin,
                                      normal, p))
        continue;
      appendContact(pair.shapeA, pair.shapeB, p, normal);
      notes[position] = {pairKey(pair.shapeA, pair.shapeB), noPair};
      if (longList || position >= scannedListLength) chainPair(notes, position, pair.shapeA);
      ++position;
    }
  };
  // (A crowd's batches begin past the unchained contacts: they chain every pair untested.)
  if (position >= scannedListLength)
    add(std::true_type{});
  else
    add(std::false_type{});
}

bool Simulator::orderAndFilter(std::uint32_t& shapeA, std::uint32_t& shapeB) const {
  if (shapes_[shapeB].type < shapes_[shapeA].type) std::swap(shapeA, shapeB);
  const Shape& a = shapes_[shapeA];
  const Shape& b = shapes_[shapeB];
  if (!a.movable && !b.movable) return false;
  if (a.group != 0 && a.group == b.group) return false;
  return a.body != b.body ||
         ownShapesMayTouch(multiBodies_[a.body], bodyStates_[a.body].firstShape, shapeA, shapeB);
}

real Simulator::pairMargin(std::uint32_t shapeA, std::uint32_t shapeB) const {
  const ShapeGeometry& ga = geometry_[shapeA];
  const ShapeGeometry& gb = geometry_[shapeB];
  return (shapes_[shapeA].type == ShapeType::HalfPlane ? gb.margin
                                                       : std::min(ga.margin, gb.margin)) +
         ga.travel + gb.travel;
}

void Simulator::addContacts(std::uint32_t shapeA, std::uint32_t shapeB) {
  if (!orderAndFilter(shapeA, shapeB)) return;
  const Shape& a = shapes_[shapeA];
  const Shape& b = shapes_[shapeB];
  const ShapeGeometry& ga = geometry_[shapeA];
  const ShapeGeometry& gb = geometry_[shapeB];
  const real margin = pairMargin(shapeA, shapeB);
  const auto append = [&](const Manifold& manifold) { appendContacts(shapeA, shapeB, manifold); };
  switch (a.type) {
    case ShapeType::HalfPlane:
      append(b.type == ShapeType::Circle
                 ? collideHalfPlaneCircle(ga.p0, ga.p1, gb.p0, gb.radius, margin)
                 : collideHalfPlaneCapsule(ga.p0, ga.p1, gb.p0, gb.p1, gb.radius, margin));
      break;
    case ShapeType::Circle:
      if (b.type == ShapeType::Circle) {
        CirclePair pair;
        if (circlesInReach(shapeA, shapeB, pair)) addCirclePairs({&pair, 1});
      } else {
        append(collideCircleCapsule(ga.p0, ga.radius, gb.p0, gb.p1, gb.radius, margin));
      }
      break;
    case ShapeType::Capsule:
      append(collideCapsules(ga.p0, ga.p1, ga.radius, gb.p0, gb.p1, gb.radius, margin));
      break;
  }
}

void Simulator::addContactsPlainly(std::uint32_t shapeA, std::uint32_t shapeB) {
  if (!orderAndFilter(shapeA, shapeB)) return;
  const Shape& a = shapes_[shapeA];
  const Shape& b = shapes_[shapeB];
  const ShapeGeometry& ga = geometry_[shapeA];
  const ShapeGeometry& gb = geometry_[shapeB];
  const real margin = pairMargin(shapeA, shapeB);
  Manifold manifold;
  if (a.type == ShapeType::HalfPlane && b.type == ShapeType::Circle)
    manifold = collideHalfPlaneCircle(ga.p0, ga.p1, gb.p0, gb.radius, margin);
  else if (a.type == ShapeType::HalfPlane)
    manifold = collideHalfPlaneCapsule(ga.p0, ga.p1, gb.p0, gb.p1, gb.radius, margin);
  else if (a.type == ShapeType::Circle && b.type == ShapeType::Circle)
    manifold = collideCircles(ga.p0, ga.radius, gb.p0, gb.radius, margin);
  else if (a.type == ShapeType::Circle)
    manifold = collideCircleCapsule(ga.p0, ga.radius, gb.p0, gb.p1, gb.radius, margin);
  else
    manifold = collideCapsules(ga.p0, ga.p1, ga.radius, gb.p0, gb.p1, gb.radius, margin);
  appendContacts(shapeA, shapeB, manifold);
}

void Simulator::listContacts() {
  if (listsPending_) indexContacts();
}

void Simulator::indexContacts() {
  // Counting sort by object into one array; each object's `contacts` is its slice of it. Only
  // the objects with contacts are visited (listed in order of their first contact), so a
  // world of many objects with few contacts pays for its contacts, not for its size. The
  // counts are detection's (countContact()), unless this list was indexed already.
  clearContactLists();
  if (!countsComplete_) {
    resetCounts();
    for (const GlobalContactInfo& c : contacts.items_) countContact(c.bodyA, c.bodyB);
  }
  countsComplete_ = false;  // the counts become cursors (clearContactLists() zeroes them)
  objectContacts_.resize(2 * contacts.size());
  const std::span<const std::uint32_t> counted(countedObjects_.data(), countedCount_);
  // Each listed object's slice is known from the counts: it is given now, before it is filled.
  std::uint32_t offset = 0;
  for (const std::uint32_t i : counted) {
    const std::uint32_t n = objectContactCursor_[i];
    objectContactCursor_[i] = offset;
    objects[i].contacts_ = std::span(objectContacts_).subspan(offset, n);
    offset += n;
  }
  // The contacts' forces: 0 from detection until the solve gives them (lists first read
  // after the solve have them; the solve gives them to lists read before).
  // p is relative to the reference point the body was detected at (after phase 8 moved it:
  // the pose its detection recorded), or, for restored contacts, where it was restored.
  const auto origin = [&](std::uint32_t body, const PhysicalObject& object) {
    return originsDetected_ ? bodyStates_[body].r : object.r;
  };
  for (std::uint32_t k = 0; k < contacts.size(); ++k) {
    const GlobalContactInfo& c = contacts.items_[k];
    // The point relative to each body's reference point, and the side: A is pushed against n.
    objectContacts_[objectContactCursor_[c.bodyA]++] =
        ContactInfo{.index = k,
                    .other = c.objectB,
                    .primitive = c.primitiveA,
                    .otherPrimitive = c.primitiveB,
                    .p = c.point - origin(c.bodyA, *c.objectA),
                    .point = c.point,
                    .n = c.normal,
                    .sigma = -1,
                    .normal = -c.normal,
                    .depth = c.depth,
                    .force = c.force,
                    .type = ContactType::Force};
    objectContacts_[objectContactCursor_[c.bodyB]++] =
        ContactInfo{.index = k,
                    .other = c.objectA,
                    .primitive = c.primitiveB,
                    .otherPrimitive = c.primitiveA,
                    .p = c.point - origin(c.bodyB, *c.objectB),
                    .point = c.point,
                    .n = c.normal,
                    .sigma = 1,
                    .normal = c.normal,
                    .depth = c.depth,
                    .force = c.force,
                    .type = ContactType::Force};
  }
  // (Each cursor ends at its slice's end: clearContactLists() zeroes it with the list.)
  // The counted objects are the listed ones now (and none is counted).
  std::swap(listedObjects_, countedObjects_);
  listedCount_ = countedCount_;
  countedCount_ = 0;
  fitCountedObjects();
  listsPending_ = false;
}

void Simulator::clearContactLists() {
  // (Also the cursors indexContacts() left: each object's count starts from 0 again.)
  for (std::size_t k = 0; k < listedCount_; ++k) {
    const std::uint32_t i = listedObjects_[k];
    objects[i].contacts_ = {};
    objectContactCursor_[i] = 0;
  }
  listedCount_ = 0;
}

void Simulator::restoreContacts(std::vector<GlobalContactInfo> list, bool complete, bool solved) {
  clearContactLists();
  resetCounts();
  contacts.items_ = std::move(list);
  if (pairChains_.size() != shapes_.size()) {
    pairChains_.resize(shapes_.size());
    previousChains_.resize(shapes_.size());
  }
  // Noted as the detection that found them noted them: each pair's points are consecutive.
  nextListStamp();
  ContactPair* const notes = notesFor(contacts.size());
  for (std::uint32_t k = 0; k < contacts.size(); ++k) {
    const GlobalContactInfo& c = contacts.items_[k];
    const bool first = k == 0 || notes[k - 1].key != pairKey(c.shapeA, c.shapeB);
    noteContactPair(notes, k, c.shapeA, c.shapeB, first);
  }
  if (contacts.size() > scannedListLength) chainFirstPairs(0);
  contactsComplete_ = complete;
  contactsSolved_ = solved;
  previousValid_ = false;
  previousSolved_ = false;
  countsComplete_ = false;
  originsDetected_ = false;  // (the caches that kept the detected poses are forgotten)
  indexContacts();           // each object's list, as the step left it
}

}  // namespace thyrix
