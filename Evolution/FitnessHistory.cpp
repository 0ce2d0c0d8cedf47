#include "FitnessHistory.h"

#include <charconv>

namespace thyrix {

namespace {

void append(std::string& out, double x) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, x);
  out.append(buffer, result.ptr);
}

}  // namespace

std::string fitnessCsv(std::span<const GenerationRecord> records) {
  std::string out = "generation,best,mean,best_so_far\n";
  for (const GenerationRecord& r : records) {
    out += std::to_string(r.generation);
    out += ',';
    append(out, r.best);
    out += ',';
    append(out, r.mean);
    out += ',';
    append(out, r.bestSoFar);
    out += '\n';
  }
  return out;
}

}  // namespace thyrix
