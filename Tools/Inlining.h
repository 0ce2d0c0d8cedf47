#pragma once
/// @file Inlining.h
/// @brief Inlining requests for the few hot functions where the compiler's own choice was
/// measured to cost (GCC and Clang take them; other compilers choose as they see fit).

/// @def THYRIX_ALWAYS_INLINE
/// Inline this function even where the compiler would keep a call.
/// @def THYRIX_NO_INLINE
/// Keep this function out of line (a loop that gets the registers to itself).
/// @def THYRIX_LAMBDA_ALWAYS_INLINE
/// THYRIX_ALWAYS_INLINE for a lambda, written after its parameter list.
#if defined(__GNUC__)
#define THYRIX_ALWAYS_INLINE [[gnu::always_inline]] inline
#define THYRIX_NO_INLINE [[gnu::noinline]]
#define THYRIX_LAMBDA_ALWAYS_INLINE __attribute__((always_inline))
#else
#define THYRIX_ALWAYS_INLINE inline
#define THYRIX_NO_INLINE
#define THYRIX_LAMBDA_ALWAYS_INLINE
#endif
