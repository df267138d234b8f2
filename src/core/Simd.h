#pragma once
// Lanes of doubles for the contact kernel: `double` itself (one lane, the reference), `Double4`
// (four lanes in a 256-bit register) where the compiler targets AVX, and `Double8` (eight lanes in
// a 512-bit register) where it targets AVX-512 (F and DQ). All offer the same operations under the
// same names, so one template of the kernel serves every width, and since every operation here is
// an IEEE operation rounded the same way in a lane as in a scalar (no FMA contraction: the project
// builds with -ffp-contract=off), every vector path gives the scalar path's bits exactly.
//
// Why by hand: GCC 12 if-converts the branch-free kernel for some targets (AVX-512 machines) and
// not for others (znver3: "control flow in loop"), and a kernel left scalar is 5 to 10 times slower.
//
// The instruction set is a property of the translation unit: the step's pair loops are compiled
// once per instruction set and chosen at run time (physics/ForceKernels.h). So that the copies of
// these inline functions compiled for AVX-512 can never stand in for the baseline's at link time,
// everything here and in the kernel headers built on it (ContactLaw.h, PairKernel.h) lives in an
// inline namespace named after the instruction set of the translation unit (WIGGLE_ISA_NAMESPACE):
// the names differ, so the linker cannot merge them. Plain data types shared across instruction
// sets (ContactParams, Kinematics, PairSlots) stay outside it.
#include <cmath>
#include <type_traits>

#if defined(__AVX__)
// GCC 12 warns that the AVX-512 intrinsics' own placeholder operand (_mm512_undefined_pd) "may be
// used uninitialized" wherever they are inlined (GCC bug 105593, fixed in GCC 13): silenced for the
// header's lines only.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
#endif
#include <immintrin.h>
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif
#define WIGGLE_SIMD_DOUBLE4 1
#endif
#if defined(__AVX512F__) && defined(__AVX512DQ__)
#define WIGGLE_SIMD_DOUBLE8 1
#endif

#if WIGGLE_SIMD_DOUBLE8
#define WIGGLE_ISA_NAMESPACE isa_avx512
#elif WIGGLE_SIMD_DOUBLE4
#define WIGGLE_ISA_NAMESPACE isa_avx
#else
#define WIGGLE_ISA_NAMESPACE isa_baseline
#endif

namespace wiggle {
inline namespace WIGGLE_ISA_NAMESPACE {
namespace simd {

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

#if WIGGLE_SIMD_DOUBLE8
// Eight lanes in one 512-bit register, with AVX-512's mask registers for comparisons. Every
// operation is the lane-wise IEEE operation of Double4 and of double (max and min included: like
// the 256-bit forms, they return the second operand when either is NaN).
struct Mask8 {
  __mmask8 v;
  friend Mask8 operator&(Mask8 a, Mask8 b) { return {static_cast<__mmask8>(a.v & b.v)}; }
};

struct Double8 {
  static constexpr int kLanes = 8;
  __m512d v;
  Double8() = default;
  Double8(double x) : v(_mm512_set1_pd(x)) {}
  Double8(__m512d x) : v(x) {}
  // Four lanes below, four above.
  Double8(Double4 low, Double4 high) : v(_mm512_insertf64x4(_mm512_castpd256_pd512(low.v[0]), high.v[0], 1)) {}
  static Double8 load(const double* p) { return _mm512_loadu_pd(p); }
  void store(double* p) const { _mm512_storeu_pd(p, v); }
  friend Double8 operator+(Double8 a, Double8 b) { return _mm512_add_pd(a.v, b.v); }
  friend Double8 operator-(Double8 a, Double8 b) { return _mm512_sub_pd(a.v, b.v); }
  friend Double8 operator*(Double8 a, Double8 b) { return _mm512_mul_pd(a.v, b.v); }
  friend Double8 operator/(Double8 a, Double8 b) { return _mm512_div_pd(a.v, b.v); }
  friend Double8 operator-(Double8 a) { return _mm512_xor_pd(a.v, _mm512_set1_pd(-0.0)); }
  friend Mask8 operator<(Double8 a, Double8 b) { return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_LT_OQ)}; }
  friend Mask8 operator>(Double8 a, Double8 b) { return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_GT_OQ)}; }
  friend Mask8 operator!=(Double8 a, Double8 b) { return {_mm512_cmp_pd_mask(a.v, b.v, _CMP_NEQ_UQ)}; }
  // a where the mask is set, b elsewhere (the blend takes its second operand where the bit is set).
  friend Double8 select(Mask8 m, Double8 a, Double8 b) { return _mm512_mask_blend_pd(m.v, b.v, a.v); }
  friend Double8 sqrt(Double8 a) { return _mm512_sqrt_pd(a.v); }
  friend Double8 abs(Double8 a) { return _mm512_andnot_pd(_mm512_set1_pd(-0.0), a.v); }
  friend Double8 max(Double8 a, Double8 b) { return _mm512_max_pd(a.v, b.v); }
  friend Double8 min(Double8 a, Double8 b) { return _mm512_min_pd(a.v, b.v); }
};

inline double horizontalMax(Double8 a) {
  alignas(64) double lane[8];
  a.store(lane);
  double m = lane[0];
  for (int k = 1; k < 8; ++k) m = max(m, lane[k]);
  return m;
}
#endif

// The widest lanes this translation unit's instruction set offers.
#if WIGGLE_SIMD_DOUBLE8
using WidestLanes = Double8;
#elif WIGGLE_SIMD_DOUBLE4
using WidestLanes = Double4;
#else
using WidestLanes = double;
#endif

}  // namespace simd
}  // inline namespace WIGGLE_ISA_NAMESPACE
}  // namespace wiggle
