#pragma once
/// @file SvgAnimation.h
/// @brief An episode as an animated SVG document, which a browser plays with no display server
/// or GUI library.

#include <ThyrixLite/SvgGUI.h>
#include <ThyrixLite/WorldDrawing.h>

#include <string>
#include <string_view>
#include <vector>

namespace thyrix {

class World;

/// Frames of a world drawn by drawWorld() into SvgGUI, played in a loop by SMIL: each frame is a
/// group `<g class="frame">` shown for frameSeconds() by a discrete `<animate>` of its
/// `visibility` (SVG 1.1; Firefox, Chrome and Safari play it). A viewer without SMIL shows the
/// first frame.
class SvgAnimation {
 public:
  /// @param lower lower-left corner of the world rectangle shown (m)
  /// @param upper upper-right corner of the world rectangle shown (m)
  /// @param widthPixels width of the picture (pixels)
  /// @param frameSeconds how long each frame is shown (s)
  /// @throws InvalidArgument as SvgGUI's constructor, or naming "SvgAnimation.frameSeconds"
  ///         unless it is positive and finite
  SvgAnimation(Vector2 lower, Vector2 upper, int widthPixels, double frameSeconds);

  /// Appends a frame: @p world drawn with @p options, and @p caption (if not empty) in the
  /// top-left corner.
  void addFrame(const World& world, const DrawOptions& options = {}, std::string_view caption = {});
  /// The frames added so far.
  [[nodiscard]] std::size_t frameCount() const { return frames_.size(); }
  /// How long each frame is shown (s).
  [[nodiscard]] double frameSeconds() const { return frameSeconds_; }

  /// The whole document: SvgGUI's header and background, then one group per frame.
  [[nodiscard]] std::string svg() const;
  /// Writes svg() to the file @p path (created or truncated).
  /// @throws std::runtime_error naming the path if the file cannot be opened or written
  void save(const std::string& path) const;

 private:
  SvgGUI gui_;
  Vector2 lower_;
  Vector2 upper_;
  double frameSeconds_;
  std::vector<std::string> frames_;  // each frame's elements
};

}  // namespace thyrix
