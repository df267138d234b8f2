#pragma once
// Lanes of doubles for the contact kernel: `double` itself (one lane, the reference) and, where the
// compiler targets AVX, `Double4` (four lanes in a 256-bit register). Both offer the same
// operations under the same names, so one template of the kernel serves both, and since every
// operation here is an IEEE operation rounded the same way in a lane as in a scalar (no FMA
// contraction: the project builds with -ffp-contract=off), the vector path gives the scalar path's
// bits exactly.
//
// Why by hand: GCC 12 if-converts the branch-free kernel for some targets (AVX-512 machines) and
// not for others (znver3: "control flow in loop"), and a kernel left scalar is 5 to 10 times slower.
#include <cmath>
#include <type_traits>

#if defined(__AVX__)
#include <immintrin.h>
#define WIGGLE_SIMD_DOUBLE4 1
#endif

namespace wiggle::simd {

// Lanes in a V: 1 for double.
template <class V>
inline constexpr int kLaneCount = V::kLanes;
template <>
inline constexpr int kLaneCount<double> = 1;

// Lanes from and to consecutive doubles.
template <class V>
inline V load(const double* p) {
  if constexpr (std::is_same_v<V, double>) return *p;
  else return V::load(p);
}
template <class V>
inline void store(double* p, V value) {
  if constexpr (std::is_same_v<V, double>) *p = value;
  else value.store(p);
}

// --- one lane: the scalar reference ---
inline double select(bool m, double a, double b) { return m ? a : b; }
inline double sqrt(double a) { return std::sqrt(a); }
inline double abs(double a) { return std::fabs(a); }
inline double max(double a, double b) { return a > b ? a : b; }  // as _mm256_max_pd: b when unordered
inline double min(double a, double b) { return a < b ? a : b; }  // as _mm256_min_pd

#if WIGGLE_SIMD_DOUBLE4
// N registers of four doubles, operated on in lockstep. The kernel uses N = 1: two interleaved
// chains (N = 2) were measured 10 % slower on znver3, the doubled body spilling the 16 ymm
// registers (docs/PERFORMANCE.md).
#define WIGGLE_SIMD_LANEWISE(Result, op) \
  Result r;                              \
  for (int k = 0; k < N; ++k) r.v[k] = op; \
  return r

template <int N>
struct MaskN {
  __m256d v[N];
  friend MaskN operator&(MaskN a, MaskN b) { WIGGLE_SIMD_LANEWISE(MaskN, _mm256_and_pd(a.v[k], b.v[k])); }
};

// The operators are hidden friends, so that a double converts to lanes where one meets them.
template <int N>
struct DoubleN {
  static constexpr int kLanes = 4 * N;
  __m256d v[N];
  DoubleN() = default;
  DoubleN(double x) {
    for (int k = 0; k < N; ++k) v[k] = _mm256_set1_pd(x);
  }
  static DoubleN load(const double* p) {
    DoubleN r;
    for (int k = 0; k < N; ++k) r.v[k] = _mm256_loadu_pd(p + 4 * k);
    return r;
  }
  void store(double* p) const {
    for (int k = 0; k < N; ++k) _mm256_storeu_pd(p + 4 * k, v[k]);
  }
  friend DoubleN operator+(DoubleN a, DoubleN b) { WIGGLE_SIMD_LANEWISE(DoubleN, _mm256_add_pd(a.v[k], b.v[k])); }
  friend DoubleN operator-(DoubleN a, DoubleN b) { WIGGLE_SIMD_LANEWISE(DoubleN, _mm256_sub_pd(a.v[k], b.v[k])); }
  friend DoubleN operator*(DoubleN a, DoubleN b) { WIGGLE_SIMD_LANEWISE(DoubleN, _mm256_mul_pd(a.v[k], b.v[k])); }
  friend DoubleN operator/(DoubleN a, DoubleN b) { WIGGLE_SIMD_LANEWISE(DoubleN, _mm256_div_pd(a.v[k], b.v[k])); }
  friend DoubleN operator-(DoubleN a) { WIGGLE_SIMD_LANEWISE(DoubleN, _mm256_xor_pd(a.v[k], _mm256_set1_pd(-0.0))); }
  friend MaskN<N> operator<(DoubleN a, DoubleN b) { WIGGLE_SIMD_LANEWISE(MaskN<N>, _mm256_cmp_pd(a.v[k], b.v[k], _CMP_LT_OQ)); }
  friend MaskN<N> operator>(DoubleN a, DoubleN b) { WIGGLE_SIMD_LANEWISE(MaskN<N>, _mm256_cmp_pd(a.v[k], b.v[k], _CMP_GT_OQ)); }
  friend MaskN<N> operator!=(DoubleN a, DoubleN b) {
    WIGGLE_SIMD_LANEWISE(MaskN<N>, _mm256_cmp_pd(a.v[k], b.v[k], _CMP_NEQ_UQ));
  }
  friend DoubleN select(MaskN<N> m, DoubleN a, DoubleN b) {
    WIGGLE_SIMD_LANEWISE(DoubleN, _mm256_blendv_pd(b.v[k], a.v[k], m.v[k]));
  }
  friend DoubleN sqrt(DoubleN a) { WIGGLE_SIMD_LANEWISE(DoubleN, _mm256_sqrt_pd(a.v[k])); }
  friend DoubleN abs(DoubleN a) { WIGGLE_SIMD_LANEWISE(DoubleN, _mm256_andnot_pd(_mm256_set1_pd(-0.0), a.v[k])); }
  friend DoubleN max(DoubleN a, DoubleN b) { WIGGLE_SIMD_LANEWISE(DoubleN, _mm256_max_pd(a.v[k], b.v[k])); }
  friend DoubleN min(DoubleN a, DoubleN b) { WIGGLE_SIMD_LANEWISE(DoubleN, _mm256_min_pd(a.v[k], b.v[k])); }
  DoubleN(__m256d x) requires(N == 1) : v{x} {}
};
#undef WIGGLE_SIMD_LANEWISE

template <int N>
inline double horizontalMax(DoubleN<N> a) {
  alignas(32) double lane[4 * N];
  a.store(lane);
  double m = lane[0];
  for (int k = 1; k < 4 * N; ++k) m = max(m, lane[k]);
  return m;
}
using Double4 = DoubleN<1>;
#endif

}  // namespace wiggle::simd
