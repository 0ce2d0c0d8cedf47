#pragma once
/// @file FitnessHistory.h
/// @brief The per-generation record of a run and its CSV form.

#include <cstdint>
#include <span>
#include <string>

namespace thyrix {

/// One generation of a run: its population's fitnesses summarized.
struct GenerationRecord {
  std::uint64_t generation = 0;  ///< 1 for the first generation evaluated
  double best = 0;               ///< the best fitness of the generation
  double mean = 0;               ///< the mean fitness of the generation
  double bestSoFar = 0;          ///< the best fitness of this and every earlier generation
};

/// The records as CSV: the header `generation,best,mean,best_so_far`, then one row per
/// record. Numbers are written in their shortest exact form (std::to_chars), independent of
/// the locale, so equal records give equal files.
[[nodiscard]] std::string fitnessCsv(std::span<const GenerationRecord> records);

}  // namespace thyrix
