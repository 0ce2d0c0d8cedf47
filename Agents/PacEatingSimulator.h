#pragma once
/// @file PacEatingSimulator.h
/// @brief The Pac arena with Pac 0 eating the food one circle after another, by a script that
/// runs in the step itself.

#include <Agents/PacEater.h>
#include <Agents/PacSimulator.h>

#include <memory>
#include <optional>
#include <vector>

namespace thyrix {

/// A PacSimulator whose Pac 0 has no controller: before each step, a PacEater script drives it
/// to the nearest food circle that no Pac holds, and on to the next once it has carried it for
/// a while (a target it cannot eat for too long, held against the other Pac say, is skipped).
/// With nothing left to eat, Pac 0 stands still, its mouth closed.
///
/// The script is this world's per-step logic, in advanceTime(): a console loop and GUIWx's
/// simulation thread, which both call advanceTime(), run it alike.
class PacEatingSimulator : public PacSimulator {
 public:
  /// The arena of @p options; Pac 1 is driven by @p second (null: driven by hand).
  /// @throws InvalidArgument as PacSimulator's constructor
  PacEatingSimulator(const Options& options, std::unique_ptr<Controller> second);

  /// Runs the script for Pac 0, then the step (Simulator::advanceTime()).
  void advanceTime() override;

  /// The script eating now, or null before the first step and when nothing is left to eat.
  [[nodiscard]] const PacEater* eater() const { return eater_ ? &*eater_ : nullptr; }

 protected:
  /// The script: its target, phase and stall count, the food skipped, the steps since the
  /// target was chosen.
  void saveOwnState(StateRecord& record) const override;
  /// Reads back what saveOwnState() appended.
  void restoreOwnState(StateRecord::Reader& reader) override;

 private:
  /// The food circle nearest to Pac 0 that no Pac holds, that is not skipped, and that lies
  /// far enough from the walls for Pac to get its mouth past it; or null.
  [[nodiscard]] const Circle* nearestFreeFood() const;
  /// The index of @p object in `objects` (objects.size() if it is not there).
  [[nodiscard]] std::uint64_t indexOf(const PhysicalObject& object) const;
  /// The object at @p index. @throws std::runtime_error if there is none
  [[nodiscard]] const PhysicalObject& objectAt(std::uint64_t index) const;

  std::optional<PacEater> eater_;
  std::vector<const PhysicalObject*> skipped_;
  long sinceTarget_ = 0;  // steps since the script last chose a target
};

}  // namespace thyrix
