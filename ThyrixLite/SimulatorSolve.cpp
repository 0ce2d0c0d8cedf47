/// @file SimulatorSolve.cpp
/// @brief Phase 6 of a step: the contact LCP island by island, then velocities and touch.
#include <ThyrixLite/BaraffSolver.h>
#include <ThyrixLite/GaussSeidelSolver.h>
#include <ThyrixLite/Simulator.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace thyrix {

void Simulator::solveContacts() {
  // Contacts are detected within a margin that covers the last step's motion, but under
  // F = m v the solve's velocities do not follow the last step's: a light lever pushed near its
  // pivot by a heavy body swings its far end many margins in one step. Where that carries an
  // end past a border unseen, the contacts are detected again with margins that cover the
  // motion (and listed again if they were), and solved again: the objects still hold their
  // free velocities.
  const bool listed = listedCount_ != 0 && !listsPending_;
  statistics_.redetections = 0;
  while (solveOnce(!hasMultiBodies_ && statistics_.redetections < maxRedetections)) {
    ++statistics_.redetections;
    redetect();
    if (listed) indexContacts();
  }
}

bool Simulator::solveOnce(bool mayRedetect) {
  // Rest: the contacts between two bodies at rest that hold at zero velocities build no row.
  // Each island of the rows left is then one of the whole problem, or a part of one through
  // bodies at rest: if such a part needs a force, those bodies wake and the pass runs again
  // with their rows (a pushed cluster is woken ring by ring); past a few passes, one with
  // every row. (Not within a divided step, whose substeps restore the free velocities.)
  const bool filtered = stepping_ && awakeValid_ && !hasMultiBodies_ && substep_ == 0;
  bool partial = false;
  bool redetect = solvePass(mayRedetect, filtered, partial);
  for (int pass = 1; partial && pass < maxRestPasses; ++pass)
    redetect = solvePass(mayRedetect, true, partial);
  if (partial) redetect = solvePass(mayRedetect, false, partial);
  return redetect;
}

bool Simulator::solvePass(bool mayRedetect, bool filtered, bool& partial) {
  partial = false;
  rowsFiltered_ = filtered;
  statistics_.restingContacts = 0;
  statistics_.islands = statistics_.solvedIslands = 0;
  statistics_.gaussSeidelSweeps = statistics_.baraffPivots = statistics_.baraffFallbacks = 0;
  statistics_.baraffOversizedIslands = 0;
  const real dt = solveStep();
  internal_.clear();
  internalOwner_.clear();
  if (hasMultiBodies_) {
    for (std::uint32_t i = 0; i < objects.size(); ++i) {
      if (multiBodies_[i] == nullptr) continue;
      multiBodies_[i]->collectInternalConstraints(dt, internal_);
      internalOwner_.resize(internal_.size(), i);
    }
  }
  // Whichever way this returns, the contacts' forces are this solve's (zero where none is
  // needed): the next step's warm start may read them.
  contactsSolved_ = true;
  if (contacts.empty() && internal_.empty()) {
    updateTactileSensors();
    ++stamp_;  // no body touched: every one moves at its free velocity (outranMargins())
    return mayRedetect && freeMotionOutranMargins();
  }

  // A row's lever arms and target, one formula for the judgment below and the rows. A circle
  // on its own turns about its centre, which the normal goes through: its lever arm is exactly
  // zero (the cross product would give round-off), and its contacts never turn it. Overlap:
  // separate at a fraction of the depth per step; gap: approach at most by the gap. The gap's
  // factor 1 changes no bit: one formula for both, its factor looked up, with no branch on the
  // sign of the depth (in a pile, as often one as the other: a branch was mispredicted half
  // the time; a conditional factor compiled to a branch too).
  const auto armA = [this](const GlobalContactInfo& c) {
    return centredCircle(c.shapeA, c.primitiveA, c.objectA)
               ? 0
               : cross(c.point - c.objectA->r, c.normal);
  };
  const auto armB = [this](const GlobalContactInfo& c) {
    return centredCircle(c.shapeB, c.primitiveB, c.objectB)
               ? 0
               : cross(c.point - c.objectB->r, c.normal);
  };
  const real depthFactor[2] = {1, settings_.penetrationCorrection};  // gap, overlap
  const auto target = [&depthFactor, dt](const GlobalContactInfo& c) {
    return depthFactor[c.depth > 0 ? 1 : 0] * c.depth / dt;
  };

  // In a sparse world most steps need no force at all: every contact (mostly speculative)
  // holds by itself at the free velocities, so no island needs solving and no velocity
  // changes. That is judged first, from the contacts and their objects (the velocities the
  // solver would copy, the same bits), so that such a step builds no row and copies no body (in
  // a small world, most of the solve); in a pile the first contacts mostly decide it. Only
  // rows between rigid bodies can be judged so (a multi-body row's velocity is its object's
  // business).
  const auto holds = [&](const GlobalContactInfo& c) {
    const PhysicalObject& a = *c.objectA;
    const PhysicalObject& b = *c.objectB;
    const ContactConstraint row{c.bodyA, c.bodyB, c.normal, armA(c), armB(c)};
    return row.normalVelocity({a.v, a.omega}, {b.v, b.omega}) >= target(c);
  };
  // Rest: a contact of two bodies at rest (v and omega +0, not pushed, not listed awake) that
  // holds at zero velocities, as it would at the free ones, is left out (its force stays 0,
  // as detection left it); the others, active, are listed. (A gap or a touch, depth <= 0, has
  // a target depth / dt <= 0, which a normal velocity of zero meets; a NaN depth does not.)
  std::size_t activeCount = 0;
  bool forceFree = false;
  if (filtered) {
    if (activeRows_.size() < contacts.size()) activeRows_.resize(contacts.size());
    std::uint32_t* const active = activeRows_.data();
    const std::uint64_t* const awakeStamp = awakeStamp_.data();
    const std::uint64_t now = awakeNow_;
    forceFree = true;
    for (std::size_t k = 0; k < contacts.size(); ++k) {
      const GlobalContactInfo& c = contacts.items_[k];
      if (awakeStamp[c.bodyA] != now && awakeStamp[c.bodyB] != now && c.depth <= 0) continue;
      active[activeCount++] = static_cast<std::uint32_t>(k);
      forceFree = forceFree && holds(c);
    }
    statistics_.restingContacts = contacts.size() - activeCount;
  } else {
    forceFree = !referenceMode && !hasMultiBodies_ &&
                std::all_of(contacts.items_.begin(), contacts.items_.end(), holds);
  }
  if (forceFree) {  // no force: contacts and object contact lists already say 0
    updateTactileSensors();
    ++stamp_;  // (as above)
    return mayRedetect && freeMotionOutranMargins();
  }
  const std::uint32_t* const active = activeRows_.data();

  // The rows, then their bodies, then the islands. Only the bodies that rows touch take part
  // (the others keep their velocities): a world of many bodies with few contacts pays for its
  // contacts, not for its size. The rows' pass lists each body at its first row without a
  // branch (whether a body is new is unpredictable: a branch on it was mispredicted about once
  // a contact in a pile); the bodies' pass then reads each object once.
  const std::size_t contactCount = filtered ? activeCount : contacts.size();  // (rows)
  const std::size_t rowCount = contactCount + internal_.size();
  rows_.resize(rowCount);
  // Each body once, and a slot past them for touch()'s store that is not taken. Sized by the
  // objects, not the rows: it grows only when objects are added.
  if (touched_.size() <= objects.size()) touched_.resize(objects.size() + 1);
  const std::uint64_t stamp = ++stamp_;
  std::uint64_t* const touchedStamp = touchedStamp_.data();
  std::uint32_t* const touched = touched_.data();
  std::size_t touchedCount = 0;
  const auto touch = [&](std::uint32_t i) {
    const bool first = touchedStamp[i] != stamp;
    touchedStamp[i] = stamp;
    touched[touchedCount] = i;
    touchedCount += first ? 1 : 0;
  };
  ContactConstraint* const rows = rows_.data();
  // Gauss-Seidel sweeps up and down the load's path (see ContactConstraint::order).
  const Vector2 up = settings_.gaussSeidelHeightOrder ? -gravity_ : Vector2{};
  // The warm start's forces, found here while the contact is at hand (a second pass over the
  // contacts, island by island, waited on the cache): the last step's contact after the one
  // found last is usually the one (detection keeps the order), tried without a call;
  // searchPreviousForce() looks further. A contact's force depends only on its identity, not
  // on the order of the search. Rows that no island solve starts from get theirs back to 0
  // (satisfied islands, solveIsland()); Baraff's islands ignore them.
  const bool warmStart = settings_.warmStart && previousSolved_ && !referenceMode;
  const GlobalContactInfo* const previous = previousContacts_.data();
  const std::size_t previousCount = previousContacts_.size();
  std::size_t hint = 0;
  for (std::size_t p = 0; p < contactCount; ++p) {
    const std::size_t k = filtered ? active[p] : p;  // row p is contact k
    const GlobalContactInfo& c = contacts.items_[k];
    touch(c.bodyA);
    touch(c.bodyB);
    ContactConstraint& row = rows[p];
    row.a = c.bodyA;
    row.b = c.bodyB;
    row.normal = c.normal;
    row.armA = armA(c);
    row.armB = armB(c);
    row.target = target(c);
    row.force = 0;
    row.order = dot(c.point, up);
    if (warmStart) {
      if (hint < previousCount && previous[hint].sameContactAs(c)) {
        row.force = previous[hint].force;
        ++hint;
      } else {
        std::size_t found = hint;
        row.force = searchPreviousForce(c, k, found);
        hint = found;
      }
    }
  }
  if (referenceMode && settings_.warmStart && previousSolved_)
    for (std::size_t k = 0; k < contactCount; ++k)
      rows[k].force = previousForcePlainly(contacts.items_[k]);
  // A joint limit is a row of its object alone; its Jacobian is the object's business.
  for (std::size_t j = 0; j < internal_.size(); ++j) {
    const std::uint32_t owner = internalOwner_[j];
    touch(owner);
    rows[contactCount + j] = {owner, owner, {}, 0, 0, internal_[j].target, 0};
  }

  // The bodies, each object read once. Only the velocities of movable rigid bodies go back to
  // their objects: they are kept at the front of touched_ (in place, without a branch), so
  // the write-back need not read the objects again.
  Islands::Adder islands = islands_.start(objects.size(), rowCount);
  SolverBody* const bodies = bodies_.data();
  std::uint8_t* const movableBody = movable_.data();
  std::size_t movedCount = 0;
  for (std::size_t t = 0; t < touchedCount; ++t) {
    const std::uint32_t i = touched[t];
    const PhysicalObject& object = objects[i];
    const bool multiBody = multiBodies_[i] != nullptr;
    // A multi-body object answers for itself (general islands): zero here, so the rigid
    // formulas ignore its sides.
    bodies[i] = multiBody ? SolverBody{}
                          : SolverBody{object.v, object.omega, object.inverseMass(),
                                       object.inverseInertia()};
    movableBody[i] = multiBody || !object.fixed ? 1 : 0;
    touched[movedCount] = i;
    movedCount += !multiBody && !object.fixed ? 1 : 0;
    islands.addBody(i);
  }

  // The islands, linked through plain pointers (the byte stores of movable would make the
  // compiler reload every member).
  for (std::size_t k = 0; k < rowCount; ++k) {
    const std::uint32_t a = rows[k].a;
    const std::uint32_t b = rows[k].b;
    islands.addRow(k, a, b, movableBody[a] != 0, movableBody[b] != 0);
  }
  islands_.finish();
  statistics_.islands = islands_.count();
  for (std::size_t i = 0; i < islands_.count(); ++i) {
    const auto island = islands_.island(i);
    const bool general =
        hasMultiBodies_ && std::any_of(island.begin(), island.end(), [this](std::uint32_t k) {
          return multiBodies_[rows_[k].a] != nullptr || multiBodies_[rows_[k].b] != nullptr;
        });
    if (general) {
      solveGeneralIsland(island);
      continue;
    }
    // An island whose contacts all hold without force needs no solve: its bodies keep u0.
    // (Tested here, not in a call: most islands of a small world are such.)
    const bool satisfied =
        std::all_of(island.begin(), island.end(), [rows, bodies](std::uint32_t k) {
          return rows[k].normalVelocity(bodies[rows[k].a], bodies[rows[k].b]) >= rows[k].target;
        });
    if (satisfied) {
      for (const std::uint32_t k : island) rows[k].force = 0;  // (the warm start's, unused)
      continue;
    }
    // Through a body at rest, the island may be a part of a larger one: such bodies wake, and
    // the pass is run again with their rows.
    if (filtered) {
      const std::size_t listed = awakeCount_;
      for (const std::uint32_t k : island) {
        if (movableBody[rows[k].a] != 0) listAwake(rows[k].a);
        if (movableBody[rows[k].b] != 0) listAwake(rows[k].b);
      }
      if (awakeCount_ != listed) partial = true;
      if (partial) continue;
    }
    solveIsland(island);
  }
  if (partial) return false;
  // No force anywhere: the step the judgment above returns early from (the reference mode comes
  // here): the velocities are the free ones, and neither divided nor checked against the walls.
  if (!hasMultiBodies_ && statistics_.solvedIslands == 0) {
    updateTactileSensors();
    return false;
  }
  parts_ = mayDivide_ ? partsNeeded({touched, movedCount}) : 1;
  // The rows' forces to their contacts (those left out keep 0).
  const auto storeForces = [&] {
    if (filtered)
      for (std::size_t p = 0; p < contactCount; ++p)
        contacts.items_[active[p]].force = rows[p].force;
    else
      for (std::size_t k = 0; k < contactCount; ++k) contacts.items_[k].force = rows[k].force;
  };
  if (parts_ > 1) {  // the objects keep their free velocities for the substeps
    storeForces();
    return false;
  }
  if (mayRedetect && outranMargins({touched, movedCount})) {
    // Detected again: the objects keep their free velocities, the contacts these forces (the
    // next solve's warm start).
    storeForces();
    return true;
  }
  for (std::size_t t = 0; t < movedCount; ++t) {
    const std::uint32_t i = touched[t];
    PhysicalObject& object = objects[i];
    object.v = bodies_[i].v;
    object.omega = bodies_[i].omega;
  }
  // A body at rest that a contact set moving wakes (for phase 8).
  if (awakeValid_)
    for (std::size_t t = 0; t < movedCount; ++t) {
      const std::uint32_t i = touched[t];
      const SolverBody& body = bodies_[i];
      if (body.v.x != 0 || body.v.y != 0 || body.omega != 0 || std::signbit(body.v.x) ||
          std::signbit(body.v.y) || std::signbit(body.omega))
        listAwake(i);
    }
  // The contacts keep their forces: next step's warm start reads them there.
  storeForces();
  // Lists made after the solve take the forces from the contacts; lists read before it (an
  // object's hook) are given them here.
  if (listedCount_ != 0 && !listsPending_ && filtered)
    for (ContactInfo& info : objectContacts_) info.force = contacts.items_[info.index].force;
  else if (listedCount_ != 0 && !listsPending_)
    for (ContactInfo& info : objectContacts_) info.force = rows_[info.index].force;
  updateTactileSensors();
  return false;
}

void Simulator::solveGeneralIsland(std::span<const std::uint32_t> island) {
  const std::size_t m = island.size();
  const std::size_t contactCount = contacts.size();
  // The multi-body sides of every row, as unit forces of their objects.
  sides_.clear();
  for (std::uint32_t p = 0; p < m; ++p) {
    const std::uint32_t k = island[p];
    if (k >= contactCount) {
      const std::size_t j = k - contactCount;
      sides_.push_back({internalOwner_[j], p, internal_[j].force});
      continue;
    }
    const GlobalContactInfo& c = contacts.items_[k];
    if (multiBodies_[c.bodyA] != nullptr)
      sides_.push_back({c.bodyA, p, {c.primitiveA, c.point, -c.normal, -1, 0}});
    if (multiBodies_[c.bodyB] != nullptr)
      sides_.push_back({c.bodyB, p, {c.primitiveB, c.point, c.normal, -1, 0}});
  }

  // The LCP: rigid couplings, then each multi-body object's response block.
  denseMatrix_.assign(m * m, 0);
  denseSlack_.resize(m);
  for (std::size_t p = 0; p < m; ++p) {
    const ContactConstraint& row = rows_[island[p]];
    denseSlack_[p] = row.normalVelocity(bodies_[row.a], bodies_[row.b]) - row.target;
    for (std::size_t q = 0; q < m; ++q)
      denseMatrix_[p * m + q] = rigidCoupling(row, rows_[island[q]], bodies_);
  }
  for (const Side& side : sides_)
    denseSlack_[side.row] += multiBodies_[side.owner]->velocityAlong(side.force);
  // The sides grouped by object (objects in index order, each one's sides in row order), to
  // visit each object once with all its sides.
  sideOrder_.resize(sides_.size());
  std::iota(sideOrder_.begin(), sideOrder_.end(), 0u);
  std::sort(sideOrder_.begin(), sideOrder_.end(), [this](std::uint32_t s, std::uint32_t t) {
    return sides_[s].owner != sides_[t].owner ? sides_[s].owner < sides_[t].owner : s < t;
  });
  const auto forEachOwner = [this](auto&& visit) {
    for (std::size_t begin = 0, end = 0; begin < sideOrder_.size(); begin = end) {
      const std::uint32_t owner = sides_[sideOrder_[begin]].owner;
      ownerForces_.clear();
      ownerRows_.clear();
      for (end = begin; end < sideOrder_.size() && sides_[sideOrder_[end]].owner == owner; ++end) {
        ownerForces_.push_back(sides_[sideOrder_[end]].force);
        ownerRows_.push_back(sides_[sideOrder_[end]].row);
      }
      visit(*multiBodies_[owner]);
    }
  };
  forEachOwner([&](MultiBodyObject& object) {
    const std::size_t n = ownerForces_.size();
    response_.resize(n * n);
    object.responseMatrix(ownerForces_, response_);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t j = 0; j < n; ++j)
        denseMatrix_[ownerRows_[i] * m + ownerRows_[j]] += response_[i * n + j];
  });

  denseForces_.assign(m, 0);
  if (std::any_of(denseSlack_.begin(), denseSlack_.end(), [](real s) { return s < 0; })) {
    ++statistics_.solvedIslands;
    bool solved = false;
    if (solverKind_ == ContactSolverKind::Baraff) {
      solved = baraff_.solveMatrix(denseMatrix_, denseSlack_, denseForces_);
      statistics_.baraffPivots += static_cast<std::size_t>(baraff_.lastPivotCount());
      if (!solved) {
        ++statistics_.baraffFallbacks;
        std::fill(denseForces_.begin(), denseForces_.end(), real(0));
      }
    }
    if (!solved)
      statistics_.gaussSeidelSweeps += static_cast<std::size_t>(
          GaussSeidelSolver::solveMatrix(denseMatrix_, denseSlack_, denseForces_, settings_));
  }

  // Forces to velocities: rigid bodies through their rows, multi-body objects by themselves.
  for (std::size_t p = 0; p < m; ++p) {
    ContactConstraint& row = rows_[island[p]];
    row.force = denseForces_[p];
    row.applyImpulse(row.force, bodies_[row.a], bodies_[row.b]);
  }
  forEachOwner([&](MultiBodyObject& object) {
    ownerMagnitudes_.resize(ownerForces_.size());
    for (std::size_t i = 0; i < ownerForces_.size(); ++i)
      ownerMagnitudes_[i] = denseForces_[ownerRows_[i]];
    object.applyConstraintForces(ownerForces_, ownerMagnitudes_);
  });
}

void Simulator::updateTactileSensors() {
  if (sensingPrimitives_.empty()) return;  // no tactile sensor in the world
  for (Primitive* primitive : sensingPrimitives_) primitive->tactile_.clear();
  for (const GlobalContactInfo& c : contacts.items_) {
    if (c.force <= 0) continue;
    if (c.primitiveA->sensing_) c.primitiveA->touch(c.point, c.force);
    if (c.primitiveB->sensing_) c.primitiveB->touch(c.point, c.force);
  }
  for (Primitive* primitive : sensingPrimitives_) primitive->tactile_.finish();
}

void Simulator::solveIsland(std::span<const std::uint32_t> island) {
  ++statistics_.solvedIslands;
  if (solverKind_ == ContactSolverKind::Baraff) {
    if (island.size() <= static_cast<std::size_t>(settings_.baraffMaxIslandContacts)) {
      const bool solved = baraff_.solve(island, rows_, bodies_);
      statistics_.baraffPivots += static_cast<std::size_t>(baraff_.lastPivotCount());
      if (solved) return;
      ++statistics_.baraffFallbacks;
    } else {
      ++statistics_.baraffOversizedIslands;  // Gauss-Seidel by choice: counted, so it shows
    }
  }
  // The rows hold the warm start's forces (solveContacts()), or 0: Gauss-Seidel adds their
  // velocities as it copies the island.
  const int sweeps = gaussSeidel_.solve(island, rows_, bodies_, settings_);
  statistics_.gaussSeidelSweeps += static_cast<std::size_t>(sweeps);
  // (Stopped by its cap: its error may be large. Converged, it is within the tolerance.)
  if (sweeps >=
      std::min(settings_.gaussSeidelMaxIterations, settings_.gaussSeidelMaxIterationsInHeightOrder))
    holdWalls(island);
}
}  // namespace thyrix
