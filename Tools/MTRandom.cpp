#include <Tools/MTRandom.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <istream>
#include <ostream>
#include <stdexcept>
#include <string>

namespace thyrix {

namespace {

constexpr std::uint32_t wordCount = 624;  // MT19937's n
constexpr std::uint32_t shift = 397;      // MT19937's m
constexpr const char* stateHeader = "mt19937-state";
constexpr int stateVersion = 1;

// ln(x) for a positive finite x from frexp, +, * and / only: IEEE arithmetic gives these bits
// on every platform, where the C library's log may differ in the last bit.
double portableLog(double x) {
  int exponent = 0;
  double m = std::frexp(x, &exponent);  // x = m 2^exponent, m in [1/2, 1)
  if (m < 0x1.6a09e667f3bcdp-1) {       // below sqrt(1/2): m in [sqrt(1/2), sqrt(2)) instead
    m *= 2;
    --exponent;
  }
  // ln(m) = 2 atanh(s) = 2 (s + s^3/3 + s^5/5 + ...) with |s| < 0.172: the terms past s^23 are
  // below 1e-19 of the sum.
  const double s = (m - 1) / (m + 1);
  const double s2 = s * s;
  double series = 1.0 / 23;
  for (int k = 21; k >= 1; k -= 2) series = series * s2 + 1.0 / k;
  // ln 2 split as in fdlibm: the high part has zero low bits, so exponent * high is exact.
  constexpr double ln2High = 0x1.62e42feep-1;
  constexpr double ln2Low = 0x1.a39ef35793c76p-33;
  const double e = exponent;
  return e * ln2High + (e * ln2Low + 2 * s * series);
}

[[noreturn]] void failRead(const std::string& problem) {
  throw std::runtime_error("MTRandom state: " + problem);
}

}  // namespace

MTRandom::MTRandom(std::uint32_t seed) { this->seed(seed); }

void MTRandom::seed(std::uint32_t seed) {
  std::array<std::uint32_t, wordCount>& x = state_.words;
  x[0] = seed;
  for (std::uint32_t i = 1; i < wordCount; ++i)
    x[i] = 1812433253u * (x[i - 1] ^ (x[i - 1] >> 30)) + i;
  state_.index = wordCount;
  state_.hasSpare = false;
  state_.spare = 0;
}

void MTRandom::twist() {
  std::array<std::uint32_t, wordCount>& x = state_.words;
  for (std::uint32_t i = 0; i < wordCount; ++i) {
    const std::uint32_t y = (x[i] & 0x80000000u) | (x[(i + 1) % wordCount] & 0x7fffffffu);
    x[i] = x[(i + shift) % wordCount] ^ (y >> 1) ^ ((y & 1u) ? 0x9908b0dfu : 0u);
  }
  state_.index = 0;
}

std::uint32_t MTRandom::nextUint32() {
  if (state_.index >= wordCount) twist();
  std::uint32_t y = state_.words[state_.index++];
  y ^= y >> 11;
  y ^= (y << 7) & 0x9d2c5680u;
  y ^= (y << 15) & 0xefc60000u;
  y ^= y >> 18;
  return y;
}

double MTRandom::normal() {
  if (state_.hasSpare) {
    state_.hasSpare = false;
    const double result = state_.spare;
    state_.spare = 0;
    return result;
  }
  double u = 0;
  double v = 0;
  double s = 0;
  do {
    u = 2 * uniform() - 1;
    v = 2 * uniform() - 1;
    s = u * u + v * v;
  } while (s >= 1 || s == 0);
  const double factor = std::sqrt(-2 * portableLog(s) / s);
  state_.spare = v * factor;
  state_.hasSpare = true;
  return u * factor;
}

double MTRandom::normal(double mean, double sd) {
  if (!(sd >= 0) || !std::isfinite(sd))
    throw std::invalid_argument("MTRandom.normal sd must be non-negative and finite (got " +
                                std::to_string(sd) + ")");
  return mean + sd * normal();
}

void MTRandom::restoreState(const State& state) {
  if (state.index > wordCount)
    throw std::invalid_argument("MTRandom.State.index must be at most 624 (got " +
                                std::to_string(state.index) + ")");
  if (state.hasSpare && !std::isfinite(state.spare))
    throw std::invalid_argument("MTRandom.State.spare must be finite");
  state_ = state;
  if (!state_.hasSpare) state_.spare = 0;
}

void MTRandom::State::write(std::ostream& out) const {
  char spareText[64];
  std::snprintf(spareText, sizeof spareText, "%a", hasSpare ? spare : 0.0);
  out << stateHeader << ' ' << stateVersion << '\n' << index;
  for (const std::uint32_t word : words) out << ' ' << word;
  out << '\n' << "spare " << (hasSpare ? 1 : 0) << ' ' << spareText << '\n';
}

namespace {

// A whole word as a number up to @p max, or nothing.
bool parseUnsigned(const std::string& word, std::uint64_t max, std::uint32_t& value) {
  if (word.empty() || word.size() > 10 || word.find_first_not_of("0123456789") != std::string::npos)
    return false;
  const unsigned long long parsed = std::stoull(word);
  if (parsed > max) return false;
  value = static_cast<std::uint32_t>(parsed);
  return true;
}

}  // namespace

MTRandom::State MTRandom::State::read(std::istream& in) {
  std::string word;
  if (!(in >> word) || word != stateHeader)
    failRead(std::string("expected '") + stateHeader + "' (got '" + word + "')");
  if (!(in >> word) || word != std::to_string(stateVersion))
    failRead("version '" + word + "' is not supported (this reader knows " +
             std::to_string(stateVersion) + ")");
  State state;
  if (!(in >> word)) failRead("missing index");
  if (!parseUnsigned(word, wordCount, state.index))
    failRead("index '" + word + "' is not a number from 0 to 624");
  for (std::uint32_t i = 0; i < wordCount; ++i) {
    if (!(in >> word)) failRead("missing word " + std::to_string(i) + " of 624");
    if (!parseUnsigned(word, 0xffffffffu, state.words[i]))
      failRead("word " + std::to_string(i) + " ('" + word + "') is not a 32-bit unsigned number");
  }
  std::string flag;
  std::string value;
  if (!(in >> word >> flag >> value) || word != "spare" || (flag != "0" && flag != "1"))
    failRead("expected 'spare 0|1 VALUE' after the words");
  const char* begin = value.c_str();
  char* end = nullptr;
  const double parsed = std::strtod(begin, &end);
  if (end == begin || *end != '\0' || !std::isfinite(parsed))
    failRead("the spare '" + value + "' is not a finite number");
  state.hasSpare = flag == "1";
  state.spare = state.hasSpare ? parsed : 0;
  return state;
}

}  // namespace thyrix
