#pragma once
/// @file Wide.h
/// @brief The one SIMD layer: a few lanes of a floating-point type as one value, with the
/// operations the core's vector kernels use. Every kernel is written once against it, and the
/// intrinsics live here alone.
///
/// The definitions: scalar (plain C++, always there, and the only one in a build configured
/// with `THYRIX_SIMD=scalar`, which defines THYRIX_SIMD_SCALAR), SSE2 (every x86-64 build) and
/// AVX2 (4 doubles or 8 floats; the native width of a build for a processor that has it, e.g.
/// `-march=native`, and otherwise compiled into the kernels that a THYRIX_SIMD_AVX2_KERNEL
/// entry chooses at run time, by processorHasAvx2()). Each operation does in every lane what
/// its scalar definition does, in the same order, so every definition gives the same bits
/// (multiply-adds are never fused: the build has `-ffp-contract=off`).
///
/// THYRIX_SIMD_AVX2_DISPATCH is defined where a kernel can also be compiled for AVX2 and chosen at
/// run time (an optimized build with GCC or Clang on x86-64). THYRIX_SIMD_AVX512_KERNEL is as
/// THYRIX_SIMD_AVX2_KERNEL, for AVX-512 (its foundation, AVX512F): Wide<double, 8> has only the
/// comparisons of the one kernel that earns it (the broad phase's rows of overlaps).
/// THYRIX_SIMD_AVX2_KERNEL holds the attributes of a kernel's AVX2 entry: compiled for AVX2 with
/// everything it calls inlined into it (so that the kernel, a template compiled for the default
/// target, and the AVX2 operations meet in one function compiled for AVX2).
#include <Tools/ProcessorFeatures.h>

#include <bit>
#include <cstdint>
#include <type_traits>

#if !defined(THYRIX_SIMD_SCALAR) && (defined(__SSE2__) || defined(_M_X64))
#define THYRIX_SIMD_SSE2 1
#include <emmintrin.h>
#if defined(__AVX2__) || (defined(THYRIX_AVX_DISPATCH) && defined(__OPTIMIZE__))
#define THYRIX_SIMD_AVX2 1
#include <immintrin.h>
#endif
#endif
// (Not without optimization: nothing is then inlined into the entry, and a 256-bit value would
// cross a call between code compiled for two targets, which pass it differently.)
#if defined(THYRIX_SIMD_AVX2) && defined(THYRIX_AVX_DISPATCH) && defined(__OPTIMIZE__)
#define THYRIX_SIMD_AVX2_DISPATCH 1
#define THYRIX_SIMD_AVX2_KERNEL [[gnu::target("avx2"), gnu::flatten]]
#define THYRIX_SIMD_AVX2_FUNCTION [[gnu::target("avx2")]]
#define THYRIX_SIMD_AVX512_KERNEL [[gnu::target("avx512f"), gnu::flatten]]
#define THYRIX_SIMD_AVX512_FUNCTION [[gnu::target("avx512f")]]
#elif defined(THYRIX_SIMD_AVX2)
#define THYRIX_SIMD_AVX2_FUNCTION
#endif

namespace thyrix::simd {

/// The name of the definitions this build uses natively: "scalar", "sse2" or "avx2".
#if defined(THYRIX_SIMD_AVX2) && defined(__AVX2__)
inline constexpr const char* kind = "avx2";
#elif defined(THYRIX_SIMD_SSE2)
inline constexpr const char* kind = "sse2";
#else
inline constexpr const char* kind = "scalar";
#endif

/// An unsigned integer of the size of @p T, to handle a real's bits.
template <class T>
using BitsOf = std::conditional_t<sizeof(T) == 8, std::uint64_t, std::uint32_t>;

/// The lanes of a comparison of two Wide values: each true or false. The scalar definition.
template <class T, int N>
struct Mask {
  bool lane[N];  ///< the lanes, lane 0 first
  /// Lane i's truth as bit i.
  [[nodiscard]] std::uint32_t bits() const {
    std::uint32_t b = 0;
    for (int i = 0; i < N; ++i) b |= std::uint32_t{lane[i]} << i;
    return b;
  }
  /// Both masks' lanes true.
  friend Mask operator&(Mask a, Mask b) {
    for (int i = 0; i < N; ++i) a.lane[i] = a.lane[i] & b.lane[i];
    return a;
  }
};

/// @p N lanes of @p T (float or double) as one value. The scalar definition: an array, each
/// operation a loop over the lanes; the SSE2 and AVX2 definitions specialise it.
template <class T, int N>
struct Wide {
  static_assert(std::is_floating_point_v<T> && N >= 1);
  /// The number of lanes.
  static constexpr int lanes = N;
  T lane[N];  ///< the lanes, lane 0 first (at the lowest address when stored)

  /// The lanes @p p[0] to @p p[N - 1] (no alignment needed).
  static Wide load(const T* p) {
    Wide w;
    for (int i = 0; i < N; ++i) w.lane[i] = p[i];
    return w;
  }
  /// @p x in every lane.
  static Wide broadcast(T x) {
    Wide w;
    for (int i = 0; i < N; ++i) w.lane[i] = x;
    return w;
  }
  /// Stores the lanes at @p p[0] to @p p[N - 1] (no alignment needed).
  void store(T* p) const {
    for (int i = 0; i < N; ++i) p[i] = lane[i];
  }
  /// Lane 0.
  [[nodiscard]] T first() const { return lane[0]; }
  /// Lane @p i.
  [[nodiscard]] T at(int i) const { return lane[i]; }

/// Defines `a op b` lane by lane, for the scalar definition's arithmetic operators.
#define THYRIX_WIDE_LANEWISE(op)                                    \
  /** `a op b` in every lane. */                                    \
  friend Wide operator op(Wide a, Wide b) {                         \
    for (int i = 0; i < N; ++i) a.lane[i] = a.lane[i] op b.lane[i]; \
    return a;                                                       \
  }
  THYRIX_WIDE_LANEWISE(+)
  THYRIX_WIDE_LANEWISE(-)
  THYRIX_WIDE_LANEWISE(*)
  THYRIX_WIDE_LANEWISE(/)
#undef THYRIX_WIDE_LANEWISE

  /// `a < b ? a : b` in every lane (so @p b where either is NaN, and b for -0 against +0).
  friend Wide min(Wide a, Wide b) {
    for (int i = 0; i < N; ++i) a.lane[i] = a.lane[i] < b.lane[i] ? a.lane[i] : b.lane[i];
    return a;
  }
  /// `a > b ? a : b` in every lane (so @p b where either is NaN, and b for -0 against +0).
  friend Wide max(Wide a, Wide b) {
    for (int i = 0; i < N; ++i) a.lane[i] = a.lane[i] > b.lane[i] ? a.lane[i] : b.lane[i];
    return a;
  }
  /// @p a with its sign bit cleared in every lane (also for NaN).
  friend Wide abs(Wide a) {
    for (int i = 0; i < N; ++i)
      a.lane[i] = std::bit_cast<T>(std::bit_cast<BitsOf<T>>(a.lane[i]) & ~signBit);
    return a;
  }
  /// @p a with its sign bit flipped in each lane where @p signs is -0 (an exact negation of
  /// those lanes, NaN included); @p signs holds only +0 and -0.
  friend Wide flipSigns(Wide a, Wide signs) {
    for (int i = 0; i < N; ++i)
      a.lane[i] = std::bit_cast<T>(std::bit_cast<BitsOf<T>>(a.lane[i]) ^
                                   std::bit_cast<BitsOf<T>>(signs.lane[i]));
    return a;
  }
  /// `a <= b` in every lane (false where either is NaN).
  friend Mask<T, N> lessOrEqual(Wide a, Wide b) {
    Mask<T, N> m;
    for (int i = 0; i < N; ++i) m.lane[i] = a.lane[i] <= b.lane[i];
    return m;
  }
  /// `a >= b` in every lane (false where either is NaN).
  friend Mask<T, N> greaterOrEqual(Wide a, Wide b) {
    Mask<T, N> m;
    for (int i = 0; i < N; ++i) m.lane[i] = a.lane[i] >= b.lane[i];
    return m;
  }

 private:
  static constexpr BitsOf<T> signBit = BitsOf<T>{1} << (8 * sizeof(T) - 1);
};

/// One 64-bit word per lane of a Wide<T, N> (bit sets, one per lane). The scalar definition.
template <class T, int N>
struct Words {
  std::uint64_t lane[N];  ///< the lanes, lane 0 first
  /// @p x in every lane.
  static Words broadcast(std::uint64_t x) {
    Words w;
    for (int i = 0; i < N; ++i) w.lane[i] = x;
    return w;
  }
  /// Stores the lanes at @p p[0] to @p p[N - 1].
  void store(std::uint64_t* p) const {
    for (int i = 0; i < N; ++i) p[i] = lane[i];
  }
  /// `a | b` in every lane.
  friend Words operator|(Words a, Words b) {
    for (int i = 0; i < N; ++i) a.lane[i] |= b.lane[i];
    return a;
  }
  /// `a + b` in every lane (modulo 2^64).
  friend Words operator+(Words a, Words b) {
    for (int i = 0; i < N; ++i) a.lane[i] += b.lane[i];
    return a;
  }
  /// @p w where @p m is true, 0 elsewhere.
  friend Words select(Mask<T, N> m, Words w) {
    const std::uint32_t bits = m.bits();
    for (int i = 0; i < N; ++i) w.lane[i] = ((bits >> i) & 1) != 0 ? w.lane[i] : 0;
    return w;
  }
};

/// Two lanes (a 2D vector's x and y): (@p x, @p y).
template <class T>
Wide<T, 2> pair(T x, T y) {
  Wide<T, 2> w;
  w.lane[0] = x;
  w.lane[1] = y;
  return w;
}
/// (a[1], a[0]).
template <class T>
Wide<T, 2> swapped(Wide<T, 2> a) {
  return pair(a.lane[1], a.lane[0]);
}
/// (a[0], b[0]).
template <class T>
Wide<T, 2> lows(Wide<T, 2> a, Wide<T, 2> b) {
  return pair(a.lane[0], b.lane[0]);
}
/// (a[1], b[1]).
template <class T>
Wide<T, 2> highs(Wide<T, 2> a, Wide<T, 2> b) {
  return pair(a.lane[1], b.lane[1]);
}

/// `q` truncated toward zero, as an integer; for `q` NaN or out of std::int64_t's range, the
/// least std::int64_t (the x86-64 conversion's result, without undefined behaviour).
template <class T>
std::int64_t truncateToInt64(T q) {
#if defined(THYRIX_SIMD_SSE2) && (defined(__x86_64__) || defined(_M_X64))
  if constexpr (std::is_same_v<T, double>)
    return _mm_cvttsd_si64(_mm_set_sd(q));
  else
    return _mm_cvttss_si64(_mm_set_ss(q));
#else
  constexpr T bound = 0x1p63;  // (exact in float and double)
  if (!(q >= -bound && q < bound)) return INT64_MIN;
  return static_cast<std::int64_t>(q);
#endif
}

#if defined(THYRIX_SIMD_SSE2)
/// The SSE2 definition of Mask<double, 2>.
template <>
struct Mask<double, 2> {
  __m128d m;  ///< all ones in a true lane
  /// Lane i's truth as bit i.
  [[nodiscard]] std::uint32_t bits() const {
    return static_cast<std::uint32_t>(_mm_movemask_pd(m));
  }
  /// Both masks' lanes true.
  friend Mask operator&(Mask a, Mask b) { return {_mm_and_pd(a.m, b.m)}; }
};

/// The SSE2 definition of Wide<double, 2>.
template <>
struct Wide<double, 2> {
  /// The number of lanes.
  static constexpr int lanes = 2;
  __m128d v;  ///< the register
  /// See the scalar definition.
  static Wide load(const double* p) { return {_mm_loadu_pd(p)}; }
  /// See the scalar definition.
  static Wide broadcast(double x) { return {_mm_set1_pd(x)}; }
  /// See the scalar definition.
  void store(double* p) const { _mm_storeu_pd(p, v); }
  /// See the scalar definition.
  [[nodiscard]] double first() const { return _mm_cvtsd_f64(v); }
  /// See the scalar definition.
  [[nodiscard]] double at(int i) const {
    return i == 0 ? first() : _mm_cvtsd_f64(_mm_unpackhi_pd(v, v));
  }
  /// See the scalar definition.
  friend Wide operator+(Wide a, Wide b) { return {_mm_add_pd(a.v, b.v)}; }
  /// See the scalar definition.
  friend Wide operator-(Wide a, Wide b) { return {_mm_sub_pd(a.v, b.v)}; }
  /// See the scalar definition.
  friend Wide operator*(Wide a, Wide b) { return {_mm_mul_pd(a.v, b.v)}; }
  /// See the scalar definition.
  friend Wide operator/(Wide a, Wide b) { return {_mm_div_pd(a.v, b.v)}; }
  /// See the scalar definition.
  friend Wide min(Wide a, Wide b) { return {_mm_min_pd(a.v, b.v)}; }
  /// See the scalar definition.
  friend Wide max(Wide a, Wide b) { return {_mm_max_pd(a.v, b.v)}; }
  /// See the scalar definition.
  friend Wide abs(Wide a) { return {_mm_andnot_pd(_mm_set1_pd(-0.0), a.v)}; }
  /// See the scalar definition.
  friend Wide flipSigns(Wide a, Wide signs) { return {_mm_xor_pd(a.v, signs.v)}; }
  /// See the scalar definition.
  friend Mask<double, 2> lessOrEqual(Wide a, Wide b) { return {_mm_cmple_pd(a.v, b.v)}; }
  /// See the scalar definition.
  friend Mask<double, 2> greaterOrEqual(Wide a, Wide b) { return {_mm_cmpge_pd(a.v, b.v)}; }
};

/// See the scalar definition.
template <>
inline Wide<double, 2> pair(double x, double y) {
  return {_mm_set_pd(y, x)};
}
/// See the scalar definition.
template <>
inline Wide<double, 2> swapped(Wide<double, 2> a) {
  return {_mm_shuffle_pd(a.v, a.v, 1)};
}
/// See the scalar definition.
template <>
inline Wide<double, 2> lows(Wide<double, 2> a, Wide<double, 2> b) {
  return {_mm_unpacklo_pd(a.v, b.v)};
}
/// See the scalar definition.
template <>
inline Wide<double, 2> highs(Wide<double, 2> a, Wide<double, 2> b) {
  return {_mm_unpackhi_pd(a.v, b.v)};
}

/// The SSE2 definition of Words<double, 2>.
template <>
struct Words<double, 2> {
  __m128i v;  ///< the register
  /// See the scalar definition.
  static Words broadcast(std::uint64_t x) { return {_mm_set1_epi64x(static_cast<long long>(x))}; }
  /// See the scalar definition.
  void store(std::uint64_t* p) const { _mm_storeu_si128(reinterpret_cast<__m128i*>(p), v); }
  /// See the scalar definition.
  friend Words operator|(Words a, Words b) { return {_mm_or_si128(a.v, b.v)}; }
  /// See the scalar definition.
  friend Words operator+(Words a, Words b) { return {_mm_add_epi64(a.v, b.v)}; }
  /// See the scalar definition.
  friend Words select(Mask<double, 2> m, Words w) {
    return {_mm_and_si128(_mm_castpd_si128(m.m), w.v)};
  }
};

/// The SSE2 definition of Mask<float, 4>.
template <>
struct Mask<float, 4> {
  __m128 m;  ///< all ones in a true lane
  /// Lane i's truth as bit i.
  [[nodiscard]] std::uint32_t bits() const {
    return static_cast<std::uint32_t>(_mm_movemask_ps(m));
  }
  /// Both masks' lanes true.
  friend Mask operator&(Mask a, Mask b) { return {_mm_and_ps(a.m, b.m)}; }
};

/// The SSE2 definition of Wide<float, 4>.
template <>
struct Wide<float, 4> {
  /// The number of lanes.
  static constexpr int lanes = 4;
  __m128 v;  ///< the register
  /// See the scalar definition.
  static Wide load(const float* p) { return {_mm_loadu_ps(p)}; }
  /// See the scalar definition.
  static Wide broadcast(float x) { return {_mm_set1_ps(x)}; }
  /// See the scalar definition.
  void store(float* p) const { _mm_storeu_ps(p, v); }
  /// See the scalar definition.
  [[nodiscard]] float first() const { return _mm_cvtss_f32(v); }
  /// See the scalar definition.
  friend Wide operator+(Wide a, Wide b) { return {_mm_add_ps(a.v, b.v)}; }
  /// See the scalar definition.
  friend Wide operator-(Wide a, Wide b) { return {_mm_sub_ps(a.v, b.v)}; }
  /// See the scalar definition.
  friend Wide operator*(Wide a, Wide b) { return {_mm_mul_ps(a.v, b.v)}; }
  /// See the scalar definition.
  friend Wide operator/(Wide a, Wide b) { return {_mm_div_ps(a.v, b.v)}; }
  /// See the scalar definition.
  friend Wide min(Wide a, Wide b) { return {_mm_min_ps(a.v, b.v)}; }
  /// See the scalar definition.
  friend Wide max(Wide a, Wide b) { return {_mm_max_ps(a.v, b.v)}; }
  /// See the scalar definition.
  friend Wide abs(Wide a) { return {_mm_andnot_ps(_mm_set1_ps(-0.0f), a.v)}; }
  /// See the scalar definition.
  friend Wide flipSigns(Wide a, Wide signs) { return {_mm_xor_ps(a.v, signs.v)}; }
  /// See the scalar definition.
  friend Mask<float, 4> lessOrEqual(Wide a, Wide b) { return {_mm_cmple_ps(a.v, b.v)}; }
  /// See the scalar definition.
  friend Mask<float, 4> greaterOrEqual(Wide a, Wide b) { return {_mm_cmpge_ps(a.v, b.v)}; }
};
#endif

#if defined(THYRIX_SIMD_AVX2)
/// The AVX2 definition of Mask<double, 4>.
template <>
struct Mask<double, 4> {
  __m256d m;  ///< all ones in a true lane
  /// Lane i's truth as bit i.
  THYRIX_SIMD_AVX2_FUNCTION [[nodiscard]] std::uint32_t bits() const {
    return static_cast<std::uint32_t>(_mm256_movemask_pd(m));
  }
  /// Both masks' lanes true.
  THYRIX_SIMD_AVX2_FUNCTION friend Mask operator&(Mask a, Mask b) {
    return {_mm256_and_pd(a.m, b.m)};
  }
};

/// The AVX2 definition of Wide<double, 4>.
template <>
struct Wide<double, 4> {
  /// The number of lanes.
  static constexpr int lanes = 4;
  __m256d v;  ///< the register
  /// See the scalar definition.
  THYRIX_SIMD_AVX2_FUNCTION static Wide load(const double* p) { return {_mm256_loadu_pd(p)}; }
  /// See the scalar definition.
  THYRIX_SIMD_AVX2_FUNCTION static Wide broadcast(double x) { return {_mm256_set1_pd(x)}; }
  /// See the scalar definition.
  THYRIX_SIMD_AVX2_FUNCTION void store(double* p) const { _mm256_storeu_pd(p, v); }
  /// See the scalar definition.
  THYRIX_SIMD_AVX2_FUNCTION [[nodiscard]] double first() const { return _mm256_cvtsd_f64(v); }
  /// See the scalar definition.
  THYRIX_SIMD_AVX2_FUNCTION friend Wide operator+(Wide a, Wide b) {
    return {_mm256_add_pd(a.v, b.v)};
  }
  /// See the scalar definition.
  THYRIX_SIMD_AVX2_FUNCTION friend Wide operator-(Wide a, Wide b) {
    return {_mm256_sub_pd(a.v, b.v)};
  }
  /// See the scalar definition.
  THYRIX_SIMD_AVX2_FUNCTION friend Wide operator*(Wide a, Wide b) {
    return {_mm256_mul_pd(a.v, b.v)};
  }
  /// See the scalar definition.
  THYRIX_SIMD_AVX2_FUNCTION friend Wide operator/(Wide a, Wide b) {
    return {_mm256_div_pd(a.v, b.v)};
  }
  /// See the scalar definition.
  THYRIX_SIMD_AVX2_FUNCTION friend Wide min(Wide a, Wide b) { return {_mm256_min_pd(a.v, b.v)}; }
  /// See the scalar definition.
  THYRIX_SIMD_AVX2_FUNCTION friend Wide max(Wide a, Wide b) { return {_mm256_max_pd(a.v, b.v)}; }
  /// See the scalar definition.
  THYRIX_SIMD_AVX2_FUNCTION friend Wide abs(Wide a) {
    return {_mm256_andnot_pd(_mm256_set1_pd(-0.0), a.v)};
  }
  /// See the scalar definition.
  THYRIX_SIMD_AVX2_FUNCTION friend Wide flipSigns(Wide a, Wide signs) {
    return {_mm256_xor_pd(a.v, signs.v)};
  }
  /// See the scalar definition.
  THYRIX_SIMD_AVX2_FUNCTION friend Mask<double, 4> lessOrEqual(Wide a, Wide b) {
    return {_mm256_cmp_pd(a.v, b.v, _CMP_LE_OQ)};
  }
  /// See the scalar definition.
  THYRIX_SIMD_AVX2_FUNCTION friend Mask<double, 4> greaterOrEqual(Wide a, Wide b) {
    return {_mm256_cmp_pd(a.v, b.v, _CMP_GE_OQ)};
  }
};

/// The AVX2 definition of Words<double, 4>.
template <>
struct Words<double, 4> {
  __m256i v;  ///< the register
  /// See the scalar definition.
  THYRIX_SIMD_AVX2_FUNCTION static Words broadcast(std::uint64_t x) {
    return {_mm256_set1_epi64x(static_cast<long long>(x))};
  }
  /// See the scalar definition.
  THYRIX_SIMD_AVX2_FUNCTION void store(std::uint64_t* p) const {
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(p), v);
  }
  /// See the scalar definition.
  THYRIX_SIMD_AVX2_FUNCTION friend Words operator|(Words a, Words b) {
    return {_mm256_or_si256(a.v, b.v)};
  }
  /// See the scalar definition.
  THYRIX_SIMD_AVX2_FUNCTION friend Words operator+(Words a, Words b) {
    return {_mm256_add_epi64(a.v, b.v)};
  }
  /// See the scalar definition.
  THYRIX_SIMD_AVX2_FUNCTION friend Words select(Mask<double, 4> m, Words w) {
    return {_mm256_and_si256(_mm256_castpd_si256(m.m), w.v)};
  }
};

/// The AVX2 definition of Mask<float, 8>.
template <>
struct Mask<float, 8> {
  __m256 m;  ///< all ones in a true lane
  /// Lane i's truth as bit i.
  THYRIX_SIMD_AVX2_FUNCTION [[nodiscard]] std::uint32_t bits() const {
    return static_cast<std::uint32_t>(_mm256_movemask_ps(m));
  }
  /// Both masks' lanes true.
  THYRIX_SIMD_AVX2_FUNCTION friend Mask operator&(Mask a, Mask b) {
    return {_mm256_and_ps(a.m, b.m)};
  }
};

/// The AVX2 definition of Wide<float, 8>.
template <>
struct Wide<float, 8> {
  /// The number of lanes.
  static constexpr int lanes = 8;
  __m256 v;  ///< the register
  /// See the scalar definition.
  THYRIX_SIMD_AVX2_FUNCTION static Wide load(const float* p) { return {_mm256_loadu_ps(p)}; }
  /// See the scalar definition.
  THYRIX_SIMD_AVX2_FUNCTION static Wide broadcast(float x) { return {_mm256_set1_ps(x)}; }
  /// See the scalar definition.
  THYRIX_SIMD_AVX2_FUNCTION void store(float* p) const { _mm256_storeu_ps(p, v); }
  /// See the scalar definition.
  THYRIX_SIMD_AVX2_FUNCTION [[nodiscard]] float first() const { return _mm256_cvtss_f32(v); }
  /// See the scalar definition.
  THYRIX_SIMD_AVX2_FUNCTION friend Wide operator+(Wide a, Wide b) {
    return {_mm256_add_ps(a.v, b.v)};
  }
  /// See the scalar definition.
  THYRIX_SIMD_AVX2_FUNCTION friend Wide operator-(Wide a, Wide b) {
    return {_mm256_sub_ps(a.v, b.v)};
  }
  /// See the scalar definition.
  THYRIX_SIMD_AVX2_FUNCTION friend Wide operator*(Wide a, Wide b) {
    return {_mm256_mul_ps(a.v, b.v)};
  }
  /// See the scalar definition.
  THYRIX_SIMD_AVX2_FUNCTION friend Wide operator/(Wide a, Wide b) {
    return {_mm256_div_ps(a.v, b.v)};
  }
  /// See the scalar definition.
  THYRIX_SIMD_AVX2_FUNCTION friend Wide min(Wide a, Wide b) { return {_mm256_min_ps(a.v, b.v)}; }
  /// See the scalar definition.
  THYRIX_SIMD_AVX2_FUNCTION friend Wide max(Wide a, Wide b) { return {_mm256_max_ps(a.v, b.v)}; }
  /// See the scalar definition.
  THYRIX_SIMD_AVX2_FUNCTION friend Wide abs(Wide a) {
    return {_mm256_andnot_ps(_mm256_set1_ps(-0.0f), a.v)};
  }
  /// See the scalar definition.
  THYRIX_SIMD_AVX2_FUNCTION friend Wide flipSigns(Wide a, Wide signs) {
    return {_mm256_xor_ps(a.v, signs.v)};
  }
  /// See the scalar definition.
  THYRIX_SIMD_AVX2_FUNCTION friend Mask<float, 8> lessOrEqual(Wide a, Wide b) {
    return {_mm256_cmp_ps(a.v, b.v, _CMP_LE_OQ)};
  }
  /// See the scalar definition.
  THYRIX_SIMD_AVX2_FUNCTION friend Mask<float, 8> greaterOrEqual(Wide a, Wide b) {
    return {_mm256_cmp_ps(a.v, b.v, _CMP_GE_OQ)};
  }
};
#endif

#if defined(THYRIX_SIMD_AVX2_DISPATCH)
/// The AVX-512 definition of Mask<double, 8>.
template <>
struct Mask<double, 8> {
  __mmask8 m;  ///< bit i for lane i
  /// Lane i's truth as bit i.
  THYRIX_SIMD_AVX512_FUNCTION [[nodiscard]] std::uint32_t bits() const { return m; }
  /// Both masks' lanes true.
  THYRIX_SIMD_AVX512_FUNCTION friend Mask operator&(Mask a, Mask b) {
    return {static_cast<__mmask8>(a.m & b.m)};
  }
};

/// The AVX-512 definition of Wide<double, 8>: loads and comparisons only.
template <>
struct Wide<double, 8> {
  /// The number of lanes.
  static constexpr int lanes = 8;
  __m512d v;  ///< the register
  /// See the scalar definition.
  THYRIX_SIMD_AVX512_FUNCTION static Wide load(const double* p) { return {_mm512_loadu_pd(p)}; }
  /// See the scalar definition.
  THYRIX_SIMD_AVX512_FUNCTION static Wide broadcast(double x) { return {_mm512_set1_pd(x)}; }
  /// See the scalar definition.
  THYRIX_SIMD_AVX512_FUNCTION friend Mask<double, 8> lessOrEqual(Wide a, Wide b) {
    return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_LE_OQ)};
  }
  /// See the scalar definition.
  THYRIX_SIMD_AVX512_FUNCTION friend Mask<double, 8> greaterOrEqual(Wide a, Wide b) {
    return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_GE_OQ)};
  }
};
#endif

/// The widest lane count of @p T this build has a register for (1 in a scalar build).
template <class T>
inline constexpr int nativeLanes =
#if defined(THYRIX_SIMD_AVX2) && defined(__AVX2__)
    32 / static_cast<int>(sizeof(T));
#elif defined(THYRIX_SIMD_SSE2)
    16 / static_cast<int>(sizeof(T));
#else
    1;
#endif

/// As many lanes of @p T as a register of the build's target holds.
template <class T>
using Native = Wide<T, nativeLanes<T>>;

/// As many lanes of @p T as an AVX2 register holds (the kernels' entries for AVX2 use it).
template <class T>
using Avx2 = Wide<T, 32 / static_cast<int>(sizeof(T))>;

}  // namespace thyrix::simd
