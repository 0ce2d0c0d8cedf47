#pragma once
/// @file FitnessPlot.h
/// @brief A plot of a run's best and mean fitness per generation, as an SVG document.

#include <Evolution/FitnessHistory.h>

#include <span>
#include <string>
#include <string_view>

namespace thyrix {

/// An SVG 1.1 document of 640 x 400 pixels that any browser opens: the best (blue) and mean
/// (orange) fitness of each generation as lines, axes with rounded ticks and their values,
/// the labels "generation" and "fitness", a legend and @p title (escaped). Numbers are written
/// locale-independently. With no record, the axes alone.
[[nodiscard]] std::string fitnessPlotSvg(std::span<const GenerationRecord> records,
                                         std::string_view title);

}  // namespace thyrix
