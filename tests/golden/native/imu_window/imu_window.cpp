// generated from template kernel.cpp.jinja by fgc 0.1.0 — do not edit
// Problem: imu_window
// chain graph, two-ended ordering; solver: lm cholesky auto n_u=4 cpe=20
//
// A CPU program, not a hardware design (fgc_backends.native): built with the host compiler as a
// shared library, with SIMD lanes and host-only paths; g++ ignores the `#pragma HLS` lines, which
// stay only while the HLS backend renders this template too.
//
// Dataflow of one Levenberg-Marquardt iteration:
//   factor blocks (residual + Jacobian mode) -> whitened rows [A | b] per factor instance
//   -> elimination steps along the schedule (Cholesky process elements), level by level,
//      2 unit set(s) side by side -> conditionals (R | d) per step
//   -> back-substitution root first -> retraction x (+) delta -> factor blocks (cost mode) -> accept?
//   (a step that does not lower the cost is judged against the cost's rounding noise at x: the
//   factor blocks in noise mode, once per iteration that needs it)
#include "imu_window.h"

#include <cstring>

#include "fgc_lm.h"

// Inlined where it is called on the host (GCC keeps small fixed-size arrays in registers, and
// never splits a function returning a vector off as a call); HLS inlines by its own pragmas
#if defined(__GNUC__) && !defined(__SYNTHESIS__)
#define FGC_INLINE __attribute__((always_inline)) inline
#else
#define FGC_INLINE inline
#endif

namespace fgc {
namespace {

const int N_UPDATE_UNITS = 4;  // n_u: Update units per partial-QR block
const int N_CPE = 20;             // Cholesky process elements
const int UNIT_SETS = 2;
const int MAX_LEVEL_WIDTH = 2;
const int TILE = 4;  // Gram tiles are TILE x TILE; matrix rows are padded to whole TILEs
const int MAX_LD = 32;  // padded row length of the widest step
const int MAX_ITERATIONS = 100;
const int MAX_TRIES = 41;  // damping retries until mu passes its bound
const T LAMBDA_INITIAL = T(1e-05);
const T LAMBDA_FACTOR = T(10.0);
const T LAMBDA_UPPER_BOUND = T(10000000000.0);
const T MU_MIN = T(1e-30);
const T EPS_GRADIENT = T(1e-12);
const T EPS_STEP = T(1.1920928955078125e-06);  // at least 10 eps: the storage's resolution
const T REL_TOL = T(1e-12);
const T EPSILON = T(1.1920928955078125e-07);  // of the scalar type
const T RESOLUTION = T(1.9073486328125e-06);  // 16 eps: the cost's relative resolution
const T ABS_TOL = T(1e-14);
const T SINGULAR_EPS = T(1.1920928955078125e-06);
const int STATUS_CONVERGED = 0;
const int STATUS_MAX_ITERATIONS = 1;
const int STATUS_FAILED = 2;
const int REASON_GRADIENT = 0;
const int REASON_STEP = 1;
const int REASON_PREDICTED_DECREASE = 2;
const int REASON_ABSOLUTE_ERROR = 3;
const int REASON_RELATIVE_DECREASE = 4;
const int REASON_MAX_ITERATIONS = 5;
const int REASON_NON_FINITE = 6;
const int REASON_SINGULAR = 7;
const int REASON_COST_INCREASED = 8;
const int REASON_LAMBDA_LIMIT = 9;

// ---- the schedule and layout as constant tables (see fgc_backends/hls/tables.py)
const int VAR_T_OFF[25] = {
    0, 6, 9, 15, 21, 24, 30, 36, 39, 45, 51, 54, 60, 66, 69, 75,
    81, 84, 90, 96, 99, 105, 111, 114, 120,
};
const int FACTOR_BLOCK[10] = {
    0, 0, 0, 0, 0, 0, 0, 1, 2, 3,
};
const int FACTOR_A_OFF[11] = {
    0, 465, 930, 1395, 1860, 2325, 2790, 3255, 3297, 3309, 3351,
};
const int FACTOR_GRAM_OFF[11] = {
    0, 496, 992, 1488, 1984, 2480, 2976, 3472, 3500, 3510, 3538,
};
const int FACTOR_VAR_BEGIN[11] = {
    0, 6, 12, 18, 24, 30, 36, 42, 43, 44, 45,
};
const int FACTOR_VARS[45] = {
    0, 1, 3, 4, 2, 5, 3, 4, 6, 7, 5, 8, 6, 7, 9, 10,
    8, 11, 9, 10, 12, 13, 11, 14, 12, 13, 15, 16, 14, 17, 15, 16,
    18, 19, 17, 20, 18, 19, 21, 22, 20, 23, 0, 1, 2,
};
const int FACTOR_COLMAP_BEGIN[11] = {
    0, 30, 60, 90, 120, 150, 180, 210, 216, 219, 225,
};
const int FACTOR_COLMAP[225] = {
    0, 1, 2, 3, 4, 5, 6, 7, 8, 15, 16, 17, 18, 19, 20, 21,
    22, 23, 9, 10, 11, 12, 13, 14, 24, 25, 26, 27, 28, 29, 0, 1,
    2, 3, 4, 5, 6, 7, 8, 15, 16, 17, 18, 19, 20, 21, 22, 23,
    9, 10, 11, 12, 13, 14, 24, 25, 26, 27, 28, 29, 0, 1, 2, 3,
    4, 5, 6, 7, 8, 15, 16, 17, 18, 19, 20, 21, 22, 23, 9, 10,
    11, 12, 13, 14, 24, 25, 26, 27, 28, 29, 0, 1, 2, 3, 4, 5,
    6, 7, 8, 15, 16, 17, 18, 19, 20, 21, 22, 23, 9, 10, 11, 12,
    13, 14, 24, 25, 26, 27, 28, 29, 15, 16, 17, 18, 19, 20, 21, 22,
    23, 0, 1, 2, 3, 4, 5, 6, 7, 8, 24, 25, 26, 27, 28, 29,
    9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 0,
    1, 2, 3, 4, 5, 6, 7, 8, 24, 25, 26, 27, 28, 29, 9, 10,
    11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 0, 1, 2,
    3, 4, 5, 6, 7, 8, 24, 25, 26, 27, 28, 29, 9, 10, 11, 12,
    13, 14, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13,
    14,
};
const int STEP_F[7] = {
    15, 15, 15, 15, 15, 15, 30,
};
const int STEP_W[7] = {
    30, 30, 30, 30, 30, 30, 30,
};
const int STEP_ROWS[7] = {
    45, 30, 45, 45, 45, 45, 75,
};
const int STEP_NF_ROWS[7] = {
    15, 15, 15, 15, 15, 15, 0,
};
const int STEP_COND_OFF[7] = {
    0, 465, 930, 1395, 1860, 2325, 2790,
};
const int STEP_NF_OFF[7] = {
    0, 240, 480, 720, 960, 1200, 1440,
};
const int STEP_COL_BEGIN[8] = {
    0, 30, 60, 90, 120, 150, 180, 210,
};
const int STEP_COL[210] = {
    0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15,
    16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 105, 106,
    107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117, 118, 119, 90, 91, 92,
    93, 94, 95, 96, 97, 98, 99, 100, 101, 102, 103, 104, 15, 16, 17, 18,
    19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34,
    35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 90, 91, 92, 93, 94, 95,
    96, 97, 98, 99, 100, 101, 102, 103, 104, 75, 76, 77, 78, 79, 80, 81,
    82, 83, 84, 85, 86, 87, 88, 89, 30, 31, 32, 33, 34, 35, 36, 37,
    38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53,
    54, 55, 56, 57, 58, 59, 75, 76, 77, 78, 79, 80, 81, 82, 83, 84,
    85, 86, 87, 88, 89, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70,
    71, 72, 73, 74, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56,
    57, 58, 59, 60, 61, 62, 63, 64, 65, 66, 67, 68, 69, 70, 71, 72,
    73, 74,
};
const int STEP_FACTOR_BEGIN[8] = {
    0, 4, 5, 6, 7, 8, 9, 10,
};
const int STEP_FACTORS[10] = {
    0, 7, 8, 9, 6, 1, 5, 2, 4, 3,
};
const int STEP_CHILD_BEGIN[8] = {
    0, 0, 0, 1, 2, 3, 4, 6,
};
const int STEP_CHILDREN[6] = {
    0, 1, 2, 3, 4, 5,
};
const int STEP_SEPMAP_BEGIN[8] = {
    0, 15, 30, 45, 60, 75, 90, 90,
};
const int STEP_SEPMAP[90] = {
    0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 0,
    1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 0, 1,
    2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 0, 1, 2,
    3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 0, 1, 2, 3,
    4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19,
    20, 21, 22, 23, 24, 25, 26, 27, 28, 29,
};
const int LEVEL_BEGIN[5] = {
    0, 2, 4, 6, 7,
};
const int LEVEL_STEPS[7] = {
    0, 1, 2, 3, 4, 5, 6,
};
const int STEP_PATTERN[7] = {
    -1, -1, 0, 1, 0, 1, -1,
};
const int BLOCK0_INSTANCES[7] = {
    0, 1, 2, 3, 4, 5, 6,
};
const int BLOCK1_INSTANCES[1] = {
    7,
};
const int BLOCK2_INSTANCES[1] = {
    8,
};
const int BLOCK3_INSTANCES[1] = {
    9,
};
const int BLOCK0_TILES[100] = {  // (p0, q0, first row, rows, tiles wide) per Gram panel
    0, 0, 0, 9, 1, 4, 0, 9, 9, 2, 8, 0, 18, 9, 2, 8,
    8, 27, 9, 1, 12, 0, 36, 9, 2, 12, 8, 45, 9, 2, 16, 0,
    54, 9, 2, 16, 8, 63, 9, 2, 16, 16, 72, 11, 1, 20, 0, 83,
    9, 2, 20, 8, 92, 9, 2, 20, 16, 101, 15, 2, 24, 0, 116, 9,
    2, 24, 8, 125, 9, 2, 24, 16, 134, 13, 2, 24, 24, 147, 13, 1,
    28, 0, 160, 9, 2, 28, 8, 169, 9, 2, 28, 16, 178, 15, 2, 28,
    24, 193, 15, 2,
};
const int BLOCK0_TILE_ROWS[208] = {
    0, 1, 2, 3, 4, 5, 6, 7, 8, 0, 1, 2, 3, 4, 5, 6,
    7, 8, 0, 1, 2, 3, 4, 5, 6, 7, 8, 0, 1, 2, 3, 4,
    5, 6, 7, 8, 0, 1, 2, 3, 4, 5, 6, 7, 8, 0, 1, 2,
    3, 4, 5, 6, 7, 8, 0, 1, 2, 3, 4, 5, 6, 7, 8, 0,
    1, 2, 3, 4, 5, 6, 7, 8, 0, 1, 2, 3, 4, 5, 6, 7,
    8, 9, 10, 0, 1, 2, 3, 4, 5, 6, 7, 8, 0, 1, 2, 3,
    4, 5, 6, 7, 8, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10,
    11, 12, 13, 14, 0, 1, 2, 3, 4, 5, 6, 7, 8, 0, 1, 2,
    3, 4, 5, 6, 7, 8, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9,
    10, 11, 12, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12,
    0, 1, 2, 3, 4, 5, 6, 7, 8, 0, 1, 2, 3, 4, 5, 6,
    7, 8, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13,
    14, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14,
};
const int BLOCK1_TILES[10] = {  // (p0, q0, first row, rows, tiles wide) per Gram panel
    0, 0, 0, 6, 1, 4, 0, 6, 6, 2,
};
const int BLOCK1_TILE_ROWS[12] = {
    0, 1, 2, 3, 4, 5, 0, 1, 2, 3, 4, 5,
};
const int BLOCK2_TILES[5] = {  // (p0, q0, first row, rows, tiles wide) per Gram panel
    0, 0, 0, 3, 1,
};
const int BLOCK2_TILE_ROWS[3] = {
    0, 1, 2,
};
const int BLOCK3_TILES[10] = {  // (p0, q0, first row, rows, tiles wide) per Gram panel
    0, 0, 0, 4, 1, 4, 0, 4, 6, 2,
};
const int BLOCK3_TILE_ROWS[10] = {
    0, 1, 2, 3, 0, 1, 2, 3, 4, 5,
};
const int KIND0_VARIABLES[8] = {
    0, 3, 6, 9, 12, 15, 18, 21,
};
const int KIND1_VARIABLES[8] = {
    1, 4, 7, 10, 13, 16, 19, 22,
};
const int KIND2_VARIABLES[8] = {
    2, 5, 8, 11, 14, 17, 20, 23,
};

// ---- the accelerator's memories: static, sized at compile time; nothing is allocated
T X[N_X];          // current estimate (storage)
T X_TRIAL[N_X];    // x (+) delta
#ifdef __SYNTHESIS__
T DATA_BUF[N_DATA];
#else
const T* DATA_BUF = nullptr;  // on the host: the caller's data, read in place (never written)
#endif
T G[N_TANGENT];    // gradient A^T b
T VAR_SCALE[N_VARIABLES];
T DELTA[N_TANGENT];
L COND[N_COND];    // conditionals (R | d), one block per elimination step
L NF[N_NF];
L GRAM[N_GRAM];    // per factor instance: packed lower triangle of [A | b]^T [A | b]
        // update matrices passed to the parent step

// ---- the rest of the DSL's functions (fgc/frontend/functions.py), beside the header's wrappers
inline T fgc_asin(T x) { return std::asin(x); }
inline T fgc_acos(T x) { return std::acos(x); }
inline T fgc_tanh(T x) { return std::tanh(x); }
inline T fgc_sign(T x) { return x > T(0) ? T(1) : x < T(0) ? T(-1) : T(0); }
// a / b where g > t, else f: GTSAM's conventions at singular points (a norm's or a bearing's
// derivative at coincident points; fgc/frontend/geometry/special.py), no division where g <= t
inline T fgc_guarded_quotient(T a, T b, T g, T t, T f) { return g > t ? T(a / b) : f; }

// ---- lanes: a factor block evaluates LANES instances side by side, as values of type V
#ifdef __SYNTHESIS__
const int LANES = 1;  // in hardware: one datapath per block type, pipelined across instances
typedef T V;
inline T lane(T x, int) { return x; }
inline V load_lanes(const T* p) { return p[0]; }
#else
// V never crosses this file (everything here is internal), so GCC's note that passing it by
// value depends on -mavx is moot
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wpsabi"
#endif
// on the host: one SIMD lane each (a GCC / Clang vector type) of one register of the widest
// vectors the build has, 64 bytes with AVX-512 and 32 otherwise
#ifdef __AVX512F__
const int LANES = 64 / sizeof(T);
#else
const int LANES = 32 / sizeof(T);
#endif
typedef T V __attribute__((vector_size(LANES * sizeof(T))));
inline T lane(const V& v, int l) { return v[l]; }
inline T lane(T x, int) { return x; }
inline V load_lanes(const T* p) {  // p[0 ... LANES) as one V
    V v;
    std::memcpy(&v, p, sizeof v);
    return v;
}
#endif

// Functions of V, lane by lane: each lane makes exactly the scalar call of one instance.
template <T (*F)(T)>
inline V lanewise(const V& x) {
    T r[LANES];
    for (int l = 0; l < LANES; ++l) r[l] = F(lane(x, l));
    return load_lanes(r);
}
inline V v_fgc_sqrt(const V& x) { return lanewise<fgc_sqrt>(x); }
inline V v_fgc_sin(const V& x) { return lanewise<fgc_sin>(x); }
inline V v_fgc_cos(const V& x) { return lanewise<fgc_cos>(x); }
inline V v_fgc_tan(const V& x) { return lanewise<fgc_tan>(x); }
inline V v_fgc_atan(const V& x) { return lanewise<fgc_atan>(x); }
inline V v_fgc_exp(const V& x) { return lanewise<fgc_exp>(x); }
inline V v_fgc_log(const V& x) { return lanewise<fgc_log>(x); }
inline V v_fgc_asin(const V& x) { return lanewise<fgc_asin>(x); }
inline V v_fgc_acos(const V& x) { return lanewise<fgc_acos>(x); }
inline V v_fgc_tanh(const V& x) { return lanewise<fgc_tanh>(x); }
inline V v_fgc_abs(const V& x) { return lanewise<fgc_abs>(x); }
inline V v_fgc_sign(const V& x) { return lanewise<fgc_sign>(x); }
// The coefficients' series (every lane below the switch, the usual case) in whole vectors: the
// same operations lane by lane as the scalar lie_* make, so the same numbers. FGC_INLINE: GCC
// would otherwise split off the scalar fallback as a function returning V, which a build
// without AVX warns about (-Wpsabi, not silenced by the pragma above)
FGC_INLINE V v_lie_A(const V& t) {
    bool series = true;
    for (int l = 0; l < LANES; ++l) series = series && lane(t, l) < T(4.0);
    if (series) return T(1.0) + t*(T(-0.16666666666666666) + t*(T(0.008333333333333333) + t*(T(-0.0001984126984126984) + t*(T(2.7557319223985893e-06) + t*(T(-2.505210838544172e-08) + t*(T(1.6059043836821613e-10) + t*(T(-7.647163731819816e-13) + t*(T(2.8114572543455206e-15) + t*(T(-8.22063524662433e-18) + t*(T(1.9572941063391263e-20) + t*(T(-3.868170170630684e-23))))))))))));
    return lanewise<lie_A>(t);
}
FGC_INLINE V v_lie_B(const V& t) {
    bool series = true;
    for (int l = 0; l < LANES; ++l) series = series && lane(t, l) < T(4.0);
    if (series) return T(0.5) + t*(T(-0.041666666666666664) + t*(T(0.001388888888888889) + t*(T(-2.48015873015873e-05) + t*(T(2.755731922398589e-07) + t*(T(-2.08767569878681e-09) + t*(T(1.1470745597729725e-11) + t*(T(-4.779477332387385e-14) + t*(T(1.5619206968586225e-16) + t*(T(-4.110317623312165e-19) + t*(T(8.896791392450574e-22) + t*(T(-1.6117375710961184e-24))))))))))));
    return lanewise<lie_B>(t);
}
FGC_INLINE V v_lie_C(const V& t) {
    bool series = true;
    for (int l = 0; l < LANES; ++l) series = series && lane(t, l) < T(4.0);
    if (series) return T(0.16666666666666666) + t*(T(-0.008333333333333333) + t*(T(0.0001984126984126984) + t*(T(-2.7557319223985893e-06) + t*(T(2.505210838544172e-08) + t*(T(-1.6059043836821613e-10) + t*(T(7.647163731819816e-13) + t*(T(-2.8114572543455206e-15) + t*(T(8.22063524662433e-18) + t*(T(-1.9572941063391263e-20) + t*(T(3.868170170630684e-23) + t*(T(-6.446950284384474e-26))))))))))));
    return lanewise<lie_C>(t);
}
FGC_INLINE V v_lie_D(const V& t) {
    bool series = true;
    for (int l = 0; l < LANES; ++l) series = series && lane(t, l) < T(4.0);
    if (series) return T(0.08333333333333333) + t*(T(0.001388888888888889) + t*(T(3.306878306878307e-05) + t*(T(8.267195767195768e-07) + t*(T(2.08767569878681e-08) + t*(T(5.284190138687493e-10) + t*(T(1.3382536530684679e-11) + t*(T(3.3896802963225827e-13) + t*(T(8.586062056277845e-15) + t*(T(2.174868698558062e-16) + t*(T(5.5090028283602295e-18) + t*(T(1.3954464685812522e-19) + t*(T(3.534707039629467e-21) + t*(T(8.953517427037546e-23) + t*(T(2.267952452337683e-24) + t*(T(5.744790668872202e-26) + t*(T(1.455172475614865e-27) + t*(T(3.6859949406653103e-29) + t*(T(9.336734257095045e-31) + t*(T(2.36502241570063e-32) + t*(T(5.990671762482134e-34) + t*(T(1.5174548844682903e-35))))))))))))))))))))));
    return lanewise<lie_D>(t);
}
FGC_INLINE V v_lie_A1(const V& t) {
    bool series = true;
    for (int l = 0; l < LANES; ++l) series = series && lane(t, l) < T(4.0);
    if (series) return T(-0.16666666666666666) + t*(T(0.016666666666666666) + t*(T(-0.0005952380952380953) + t*(T(1.1022927689594357e-05) + t*(T(-1.252605419272086e-07) + t*(T(9.635426302092969e-10) + t*(T(-5.353014612273871e-12) + t*(T(2.2491658034764165e-14) + t*(T(-7.398571721961897e-17) + t*(T(1.9572941063391261e-19) + t*(T(-4.254987187693753e-22)))))))))));
    return lanewise<lie_A1>(t);
}
FGC_INLINE V v_lie_B1(const V& t) {
    bool series = true;
    for (int l = 0; l < LANES; ++l) series = series && lane(t, l) < T(4.0);
    if (series) return T(-0.041666666666666664) + t*(T(0.002777777777777778) + t*(T(-7.440476190476191e-05) + t*(T(1.1022927689594355e-06) + t*(T(-1.043837849393405e-08) + t*(T(6.882447358637835e-11) + t*(T(-3.3456341326711696e-13) + t*(T(1.249536557486898e-15) + t*(T(-3.6992858609809485e-18) + t*(T(8.896791392450573e-21) + t*(T(-1.77291132820573e-23)))))))))));
    return lanewise<lie_B1>(t);
}
FGC_INLINE V v_lie_C1(const V& t) {
    bool series = true;
    for (int l = 0; l < LANES; ++l) series = series && lane(t, l) < T(4.0);
    if (series) return T(-0.008333333333333333) + t*(T(0.0003968253968253968) + t*(T(-8.267195767195768e-06) + t*(T(1.0020843354176688e-07) + t*(T(-8.029521918410807e-10) + t*(T(4.58829823909189e-12) + t*(T(-1.9680200780418645e-14) + t*(T(6.576508197299464e-17) + t*(T(-1.7615646957052136e-19) + t*(T(3.868170170630684e-22) + t*(T(-7.091645312822921e-25)))))))))));
    return lanewise<lie_C1>(t);
}
FGC_INLINE V v_lie_D1(const V& t) {
    bool series = true;
    for (int l = 0; l < LANES; ++l) series = series && lane(t, l) < T(4.0);
    if (series) return T(0.001388888888888889) + t*(T(6.613756613756614e-05) + t*(T(2.48015873015873e-06) + t*(T(8.35070279514724e-08) + t*(T(2.6420950693437467e-09) + t*(T(8.029521918410807e-11) + t*(T(2.372776207425808e-12) + t*(T(6.868849645022276e-14) + t*(T(1.9573818287022555e-15) + t*(T(5.5090028283602297e-17) + t*(T(1.5349911154393775e-18) + t*(T(4.241648447555361e-20) + t*(T(1.163957265514881e-21) + t*(T(3.1751334332727565e-23) + t*(T(8.617186003308303e-25) + t*(T(2.328275960983784e-26) + t*(T(6.266191399131027e-28) + t*(T(1.6806121662771081e-29) + t*(T(4.4935425898311966e-31) + t*(T(1.1981343524964268e-32) + t*(T(3.1866552573834097e-34)))))))))))))))))))));
    return lanewise<lie_D1>(t);
}
template <class A, class B, class G>  // a constant argument is a T, a computed one a V
inline V v_fgc_guarded_quotient(const A& a, const B& b, const G& g, T t, T f) {
    T r[LANES];
    for (int l = 0; l < LANES; ++l)
        r[l] = fgc_guarded_quotient(lane(a, l), lane(b, l), lane(g, l), t, f);
    return load_lanes(r);
}
inline V v_fgc_atan2(const V& y, const V& x) {
    T r[LANES];
    for (int l = 0; l < LANES; ++l) r[l] = fgc_atan2(lane(y, l), lane(x, l));
    return load_lanes(r);
}
inline void v_so3_log(const V& r00, const V& r01, const V& r02, const V& r10, const V& r11,
                      const V& r12, const V& r20, const V& r21, const V& r22, V w[3]) {
    T o[3][LANES];
    for (int l = 0; l < LANES; ++l) {
        T one[3];
        so3_log(lane(r00, l), lane(r01, l), lane(r02, l), lane(r10, l), lane(r11, l),
                lane(r12, l), lane(r20, l), lane(r21, l), lane(r22, l), one);
        for (int i = 0; i < 3; ++i) o[i][l] = one[i];
    }
    for (int i = 0; i < 3; ++i) w[i] = load_lanes(o[i]);
}
inline V v_so3_log_x(const V& r00, const V& r01, const V& r02, const V& r10, const V& r11,
                        const V& r12, const V& r20, const V& r21, const V& r22) {
    V w[3];
    v_so3_log(r00, r01, r02, r10, r11, r12, r20, r21, r22, w);
    return w[0];
}
inline V v_so3_log_y(const V& r00, const V& r01, const V& r02, const V& r10, const V& r11,
                        const V& r12, const V& r20, const V& r21, const V& r22) {
    V w[3];
    v_so3_log(r00, r01, r02, r10, r11, r12, r20, r21, r22, w);
    return w[1];
}
inline V v_so3_log_z(const V& r00, const V& r01, const V& r02, const V& r10, const V& r11,
                        const V& r12, const V& r20, const V& r21, const V& r22) {
    V w[3];
    v_so3_log(r00, r01, r02, r10, r11, r12, r20, r21, r22, w);
    return w[2];
}

// ---- factor blocks (instance l of a call in lane l)
// block 0: CombinedImuFactor (15 rows, 30 columns, 7 instances)
void jacobian_0(const V* in, const V* dat, T ab[LANES][480]) {
#pragma HLS PIPELINE II=1
    const V t0 = in[30] - dat[63];
    const V t1 = in[31] - dat[64];
    const V t2 = in[32] - dat[65];
    const V t3 = in[33] - dat[66];
    const V t4 = in[34] - dat[67];
    const V t5 = in[35] - dat[68];
    const V t6 = t0*dat[9] + t1*dat[10] + t2*dat[11] + t3*dat[36] + t4*dat[37] + t5*dat[38] + dat[0];
    const V t7 = T(2)*t6;
    const V t8 = t0*dat[12] + t1*dat[13] + t2*dat[14] + t3*dat[39] + t4*dat[40] + t5*dat[41] + dat[1];
    const V t9 = T(2)*t8;
    const V t10 = t0*dat[15] + t1*dat[16] + t2*dat[17] + t3*dat[42] + t4*dat[43] + t5*dat[44] + dat[2];
    const V t11 = T(2)*t10;
    const V t12 = (t6*t6) + (t8*t8) + (t10*t10);
    const V t13 = v_lie_B1(t12);
    const V t14 = -t8;
    const V t15 = t8*t14;
    const V t16 = -t10;
    const V t17 = t16*t10;
    const V t18 = t17 + t15;
    const V t19 = -dat[15];
    const V t20 = t16*dat[15] + t10*t19;
    const V t21 = v_lie_B(t12);
    const V t22 = t21*t20;
    const V t23 = -dat[12];
    const V t24 = t8*t23 + t14*dat[12];
    const V t25 = t21*t24;
    const V t26 = -dat[16];
    const V t27 = t16*dat[16] + t10*t26;
    const V t28 = t21*t27;
    const V t29 = -dat[13];
    const V t30 = t8*t29 + t14*dat[13];
    const V t31 = t21*t30;
    const V t32 = -dat[17];
    const V t33 = t16*dat[17] + t10*t32;
    const V t34 = t21*t33;
    const V t35 = -dat[14];
    const V t36 = t8*t35 + t14*dat[14];
    const V t37 = t21*t36;
    const V t38 = -dat[42];
    const V t39 = t16*dat[42] + t10*t38;
    const V t40 = t21*t39;
    const V t41 = -dat[39];
    const V t42 = t8*t41 + t14*dat[39];
    const V t43 = t21*t42;
    const V t44 = -dat[40];
    const V t45 = t8*t44 + t14*dat[40];
    const V t46 = t21*t45;
    const V t47 = -dat[43];
    const V t48 = t16*dat[43] + t10*t47;
    const V t49 = t21*t48;
    const V t50 = -dat[41];
    const V t51 = t8*t50 + t14*dat[41];
    const V t52 = t21*t51;
    const V t53 = -dat[44];
    const V t54 = t16*dat[44] + t10*t53;
    const V t55 = t21*t54;
    const V t56 = in[0]*in[15] + in[3]*in[18] + in[6]*in[21];
    const V t57 = in[2]*in[15] + in[5]*in[18] + in[8]*in[21];
    const V t58 = -t57;
    const V t59 = in[1]*in[15] + in[4]*in[18] + in[7]*in[21];
    const V t60 = in[0]*in[17] + in[3]*in[20] + in[6]*in[23];
    const V t61 = -t60;
    const V t62 = in[0]*in[16] + in[3]*in[19] + in[6]*in[22];
    const V t63 = v_lie_A1(t12);
    const V t64 = -t56;
    const V t65 = in[1]*in[17] + in[4]*in[20] + in[7]*in[23];
    const V t66 = -t65;
    const V t67 = in[1]*in[16] + in[4]*in[19] + in[7]*in[22];
    const V t68 = -t59;
    const V t69 = in[2]*in[17] + in[5]*in[20] + in[8]*in[23];
    const V t70 = -t69;
    const V t71 = in[2]*in[16] + in[5]*in[19] + in[8]*in[22];
    const V t72 = -t6;
    const V t73 = t6*t72;
    const V t74 = t17 + t73;
    const V t75 = -dat[9];
    const V t76 = t6*t75 + t72*dat[9];
    const V t77 = t21*t76;
    const V t78 = -dat[10];
    const V t79 = t6*t78 + t72*dat[10];
    const V t80 = t21*t79;
    const V t81 = -dat[11];
    const V t82 = t6*t81 + t72*dat[11];
    const V t83 = t21*t82;
    const V t84 = -dat[36];
    const V t85 = t6*t84 + t72*dat[36];
    const V t86 = t21*t85;
    const V t87 = -dat[37];
    const V t88 = t6*t87 + t72*dat[37];
    const V t89 = t21*t88;
    const V t90 = -dat[38];
    const V t91 = t6*t90 + t72*dat[38];
    const V t92 = t21*t91;
    const V t93 = t73 + t15;
    const V t94 = t16*t21;
    const V t95 = t16*t72;
    const V t96 = t21*t72;
    const V t97 = t21*t10;
    const V t98 = t21*t8;
    const V t99 = t8*t10;
    const V t100 = -t71;
    const V t101 = -t62;
    const V t102 = -t67;
    const V t103 = t18*t21 + T(1);
    const V t104 = t56;
    const V t105 = v_lie_A(t12);
    const V t106 = t21*t14;
    const V t107 = t105*t10 + t72*t106;
    const V t108 = t59;
    const V t109 = t6*t21;
    const V t110 = t105*t14 + t109*t10;
    const V t111 = t57;
    const V t112 = t103*t104 + t107*t108 + t110*t111;
    const V t113 = t74*t21 + T(1);
    const V t114 = t16*t106 + t6*t105;
    const V t115 = t16*t105 + t109*t8;
    const V t116 = t104*t115 + t108*t113 + t111*t114;
    const V t117 = t93*t21 + T(1);
    const V t118 = t94*t72 + t105*t8;
    const V t119 = t97*t8 + t105*t72;
    const V t120 = t104*t118 + t108*t119 + t111*t117;
    const V t121 = t62;
    const V t122 = t67;
    const V t123 = t71;
    const V t124 = t103*t121 + t107*t122 + t110*t123;
    const V t125 = t113*t122 + t114*t123 + t115*t121;
    const V t126 = t117*t123 + t118*t121 + t119*t122;
    const V t127 = t60;
    const V t128 = t65;
    const V t129 = t69;
    const V t130 = t103*t127 + t107*t128 + t110*t129;
    const V t131 = t113*t128 + t114*t129 + t115*t127;
    const V t132 = t117*t129 + t118*t127 + t119*t128;
    V tlog0[3]; v_so3_log(t112, t116, t120, t124, t125, t126, t130, t131, t132, tlog0);
    const V t133 = tlog0[1];
    const V t134 = (T(0.5))*t133;
    const V t135 = tlog0[0];
    const V t136 = (t135*t135);
    const V t137 = (t133*t133);
    const V t138 = tlog0[2];
    const V t139 = (t138*t138);
    const V t140 = t137 + t139;
    const V t141 = v_lie_D(t136 + t140);
    const V t142 = t141*t135;
    const V t143 = t142*t138;
    const V t144 = t134 + t143;
    const V t145 = (T(0.5))*t112;
    const V t146 = -t140*t141 + T(1);
    const V t147 = -t144*t145 + (T(0.5))*t146*t120;
    const V t148 = (T(0.5))*t138;
    const V t149 = t142*t133;
    const V t150 = -t148 + t149;
    const V t151 = (T(0.5))*t146;
    const V t152 = t145*t150 - t151*t116;
    const V t153 = (T(0.5))*t144;
    const V t154 = (T(0.5))*t150;
    const V t155 = t153*t125 - t154*t126;
    const V t156 = (T(0.5))*t146*t126 - t153*t124;
    const V t157 = -t151*t125 + t154*t124;
    const V t158 = t153*t131 - t154*t132;
    const V t159 = (T(0.5))*t146*t132 - t153*t130;
    const V t160 = -t151*t131 + t154*t130;
    const V t161 = t153*t116 - t154*t120;
    const V t162 = (T(0.5))*t135;
    const V t163 = t141*t133*t138 - t162;
    const V t164 = t148 + t149;
    const V t165 = -t145*t163 + (T(0.5))*t164*t120;
    const V t166 = t141*(-t136 - t139) + T(1);
    const V t167 = (T(0.5))*t164;
    const V t168 = t145*t166 - t167*t116;
    const V t169 = (T(0.5))*t163;
    const V t170 = (T(0.5))*t166;
    const V t171 = t169*t125 - t170*t126;
    const V t172 = (T(0.5))*t164*t126 - t169*t124;
    const V t173 = -t167*t125 + t170*t124;
    const V t174 = t169*t131 - t170*t132;
    const V t175 = (T(0.5))*t164*t132 - t169*t130;
    const V t176 = -t167*t131 + t170*t130;
    const V t177 = t169*t116 - t170*t120;
    const V t178 = t141*(-t136 - t137) + T(1);
    const V t179 = -t134 + t143;
    const V t180 = -t145*t178 + (T(0.5))*t179*t120;
    const V t181 = t133*t138;
    const V t182 = t141*t181 + t162;
    const V t183 = (T(0.5))*t179;
    const V t184 = t145*t182 - t183*t116;
    const V t185 = (T(0.5))*t178;
    const V t186 = (T(0.5))*t182;
    const V t187 = -t186*t126 + t185*t125;
    const V t188 = (T(0.5))*t179*t126 - t185*t124;
    const V t189 = t186*t124 - t183*t125;
    const V t190 = -t186*t132 + t185*t131;
    const V t191 = (T(0.5))*t179*t132 - t185*t130;
    const V t192 = t186*t130 - t183*t131;
    const V t193 = -t186*t120 + t185*t116;
    const V t194 = T(2)*t133;
    const V t195 = T(2)*t138;
    const V t196 = T(2)*t135;
    const V t197 = t137;
    const V t198 = t139;
    const V t199 = t197 + t198;
    const V t200 = t136;
    const V t201 = t199 + t200;
    const V t202 = v_lie_D1(t201);
    const V t203 = -in[15];
    const V t204 = -in[16];
    const V t205 = -in[17];
    const V t206 = -in[18];
    const V t207 = -in[19];
    const V t208 = -in[20];
    const V t209 = -in[21];
    const V t210 = -in[22];
    const V t211 = -in[23];
    const V t212 = t0*dat[18] + t1*dat[19] + t2*dat[20] + t3*dat[45] + t4*dat[46] + t5*dat[47] + dat[3];
    const V t213 = t0*dat[21] + t1*dat[22] + t2*dat[23] + t3*dat[48] + t4*dat[49] + t5*dat[50] + dat[4];
    const V t214 = t0*dat[24] + t1*dat[25] + t2*dat[26] + t3*dat[51] + t4*dat[52] + t5*dat[53] + dat[5];
    const V t215 = (T(0.5))*(dat[69]*dat[69]);
    const V t216 = t212*in[0] + t213*in[1] + t214*in[2] + t215*dat[70] + dat[69]*in[12] + in[9] - in[24];
    const V t217 = t212*in[3] + t213*in[4] + t214*in[5] + t215*dat[71] + dat[69]*in[13] + in[10] - in[25];
    const V t218 = t212*in[6] + t213*in[7] + t214*in[8] + t215*dat[72] + dat[69]*in[14] + in[11] - in[26];
    const V t219 = t216*in[15] + t217*in[18] + t218*in[21];
    const V t220 = t216*in[17] + t217*in[20] + t218*in[23];
    const V t221 = t216*in[16] + t217*in[19] + t218*in[22];
    const V t222 = -t198 - t200;
    const V t223 = t57;
    const V t224 = t68;
    const V t225 = t107*t223 + t110*t224;
    const V t226 = t113*t223 + t114*t224;
    const V t227 = t117*t224 + t119*t223;
    const V t228 = t71;
    const V t229 = t102;
    const V t230 = t107*t228 + t110*t229;
    const V t231 = t113*t228 + t114*t229;
    const V t232 = t117*t229 + t119*t228;
    const V t233 = t69;
    const V t234 = t66;
    const V t235 = t107*t233 + t110*t234;
    const V t236 = t113*t233 + t114*t234;
    const V t237 = t117*t234 + t119*t233;
    const V t238 = t147*t226 + t152*t227 + t155*t230 + t156*t231 + t157*t232 + t158*t235 + t159*t236 + t160*t237 + t161*t225;
    const V t239 = t196*t238;
    const V t240 = v_lie_D(t201);
    const V t241 = t240*t239;
    const V t242 = t58;
    const V t243 = t56;
    const V t244 = t103*t242 + t110*t243;
    const V t245 = t114*t243 + t115*t242;
    const V t246 = t117*t243 + t118*t242;
    const V t247 = t100;
    const V t248 = t62;
    const V t249 = t103*t247 + t110*t248;
    const V t250 = t114*t248 + t115*t247;
    const V t251 = t117*t248 + t118*t247;
    const V t252 = t70;
    const V t253 = t60;
    const V t254 = t103*t252 + t110*t253;
    const V t255 = t114*t253 + t115*t252;
    const V t256 = t117*t253 + t118*t252;
    const V t257 = t147*t245 + t152*t246 + t155*t249 + t156*t250 + t157*t251 + t158*t254 + t159*t255 + t160*t256 + t161*t244;
    const V t258 = t196*t257;
    const V t259 = t240*t258;
    const V t260 = t59;
    const V t261 = t64;
    const V t262 = t103*t260 + t107*t261;
    const V t263 = t113*t261 + t115*t260;
    const V t264 = t118*t260 + t119*t261;
    const V t265 = t67;
    const V t266 = t101;
    const V t267 = t103*t265 + t107*t266;
    const V t268 = t113*t266 + t115*t265;
    const V t269 = t118*t265 + t119*t266;
    const V t270 = t65;
    const V t271 = t61;
    const V t272 = t103*t270 + t107*t271;
    const V t273 = t113*t271 + t115*t270;
    const V t274 = t118*t270 + t119*t271;
    const V t275 = t147*t263 + t152*t264 + t155*t267 + t156*t268 + t157*t269 + t158*t272 + t159*t273 + t160*t274 + t161*t262;
    const V t276 = t196*t275;
    const V t277 = t240*t276;
    const V t278 = t60;
    const V t279 = t65;
    const V t280 = t69;
    const V t281 = t103*t278 + t107*t279 + t110*t280;
    const V t282 = t113*t279 + t114*t280 + t115*t278;
    const V t283 = t117*t280 + t118*t278 + t119*t279;
    const V t284 = t101;
    const V t285 = t102;
    const V t286 = t100;
    const V t287 = t103*t284 + t107*t285 + t110*t286;
    const V t288 = t113*t285 + t114*t286 + t115*t284;
    const V t289 = t117*t286 + t118*t284 + t119*t285;
    const V t290 = t155*t281 + t156*t282 + t157*t283 + t158*t287 + t159*t288 + t160*t289;
    const V t291 = t196*t290;
    const V t292 = t240*t291;
    const V t293 = t61;
    const V t294 = t66;
    const V t295 = t70;
    const V t296 = t103*t293 + t107*t294 + t110*t295;
    const V t297 = t113*t294 + t114*t295 + t115*t293;
    const V t298 = t117*t295 + t118*t293 + t119*t294;
    const V t299 = t56;
    const V t300 = t59;
    const V t301 = t57;
    const V t302 = t103*t299 + t107*t300 + t110*t301;
    const V t303 = t113*t300 + t114*t301 + t115*t299;
    const V t304 = t117*t301 + t118*t299 + t119*t300;
    const V t305 = t147*t297 + t152*t298 + t158*t302 + t159*t303 + t160*t304 + t161*t296;
    const V t306 = t196*t305;
    const V t307 = t240*t306;
    const V t308 = t62;
    const V t309 = t67;
    const V t310 = t71;
    const V t311 = t103*t308 + t107*t309 + t110*t310;
    const V t312 = t113*t309 + t114*t310 + t115*t308;
    const V t313 = t117*t310 + t118*t308 + t119*t309;
    const V t314 = t64;
    const V t315 = t68;
    const V t316 = t58;
    const V t317 = t103*t314 + t107*t315 + t110*t316;
    const V t318 = t113*t315 + t114*t316 + t115*t314;
    const V t319 = t117*t316 + t118*t314 + t119*t315;
    const V t320 = t147*t312 + t152*t313 + t155*t317 + t156*t318 + t157*t319 + t161*t311;
    const V t321 = t196*t320;
    const V t322 = t240*t321;
    const V t323 = t7*dat[9] + t9*dat[12] + t11*dat[15];
    const V t324 = t13*t323;
    const V t325 = t18*t324 + t22 + t25;
    const V t326 = t63*t323;
    const V t327 = t21*t23 + t14*t324;
    const V t328 = t105*dat[15] + t72*t327 + t106*t75 + t10*t326;
    const V t329 = t6*t324 + t21*dat[9];
    const V t330 = t105*t23 + t109*dat[15] + t14*t326 + t10*t329;
    const V t331 = t104*t325 + t108*t328 + t111*t330;
    const V t332 = t74*t324 + t77 + t22;
    const V t333 = t16*t327 + t6*t326 + t105*dat[9] + t106*t19;
    const V t334 = t16*t326 + t105*t19 + t109*dat[12] + t8*t329;
    const V t335 = t104*t334 + t108*t332 + t111*t333;
    const V t336 = t77 + t93*t324 + t25;
    const V t337 = t94*t75 + t95*t324 + t96*t19 + t105*dat[12] + t8*t326;
    const V t338 = t97*dat[12] + t98*dat[15] + t99*t324 + t105*t75 + t72*t326;
    const V t339 = t104*t337 + t108*t338 + t111*t336;
    const V t340 = t121*t325 + t122*t328 + t123*t330;
    const V t341 = t121*t334 + t122*t332 + t123*t333;
    const V t342 = t121*t337 + t122*t338 + t123*t336;
    const V t343 = t127*t325 + t128*t328 + t129*t330;
    const V t344 = t127*t334 + t128*t332 + t129*t333;
    const V t345 = t127*t337 + t128*t338 + t129*t336;
    const V t346 = t147*t335 + t152*t339 + t155*t340 + t156*t341 + t157*t342 + t158*t343 + t159*t344 + t160*t345 + t161*t331;
    const V t347 = t196*t346;
    const V t348 = t240*t347;
    const V t349 = t7*dat[10] + t9*dat[13] + t11*dat[16];
    const V t350 = t13*t349;
    const V t351 = t18*t350 + t28 + t31;
    const V t352 = t63*t349;
    const V t353 = t21*t29 + t14*t350;
    const V t354 = t105*dat[16] + t72*t353 + t106*t78 + t10*t352;
    const V t355 = t6*t350 + t21*dat[10];
    const V t356 = t105*t29 + t109*dat[16] + t14*t352 + t10*t355;
    const V t357 = t104*t351 + t108*t354 + t111*t356;
    const V t358 = t74*t350 + t80 + t28;
    const V t359 = t16*t353 + t6*t352 + t105*dat[10] + t106*t26;
    const V t360 = t16*t352 + t105*t26 + t109*dat[13] + t8*t355;
    const V t361 = t104*t360 + t108*t358 + t111*t359;
    const V t362 = t80 + t93*t350 + t31;
    const V t363 = t94*t78 + t95*t350 + t96*t26 + t105*dat[13] + t8*t352;
    const V t364 = t97*dat[13] + t98*dat[16] + t99*t350 + t105*t78 + t72*t352;
    const V t365 = t104*t363 + t108*t364 + t111*t362;
    const V t366 = t121*t351 + t122*t354 + t123*t356;
    const V t367 = t121*t360 + t122*t358 + t123*t359;
    const V t368 = t121*t363 + t122*t364 + t123*t362;
    const V t369 = t127*t351 + t128*t354 + t129*t356;
    const V t370 = t127*t360 + t128*t358 + t129*t359;
    const V t371 = t127*t363 + t128*t364 + t129*t362;
    const V t372 = t147*t361 + t152*t365 + t155*t366 + t156*t367 + t157*t368 + t158*t369 + t159*t370 + t160*t371 + t161*t357;
    const V t373 = t196*t372;
    const V t374 = t240*t373;
    const V t375 = t7*dat[11] + t9*dat[14] + t11*dat[17];
    const V t376 = t13*t375;
    const V t377 = t37 + t18*t376 + t34;
    const V t378 = t63*t375;
    const V t379 = t21*t35 + t14*t376;
    const V t380 = t105*dat[17] + t72*t379 + t106*t81 + t10*t378;
    const V t381 = t6*t376 + t21*dat[11];
    const V t382 = t105*t35 + t109*dat[17] + t14*t378 + t10*t381;
    const V t383 = t104*t377 + t108*t380 + t111*t382;
    const V t384 = t74*t376 + t83 + t34;
    const V t385 = t16*t379 + t6*t378 + t105*dat[11] + t106*t32;
    const V t386 = t16*t378 + t105*t32 + t109*dat[14] + t8*t381;
    const V t387 = t104*t386 + t108*t384 + t111*t385;
    const V t388 = t37 + t83 + t93*t376;
    const V t389 = t94*t81 + t95*t376 + t96*t32 + t105*dat[14] + t8*t378;
    const V t390 = t97*dat[14] + t98*dat[17] + t99*t376 + t105*t81 + t72*t378;
    const V t391 = t104*t389 + t108*t390 + t111*t388;
    const V t392 = t121*t377 + t122*t380 + t123*t382;
    const V t393 = t121*t386 + t122*t384 + t123*t385;
    const V t394 = t121*t389 + t122*t390 + t123*t388;
    const V t395 = t127*t377 + t128*t380 + t129*t382;
    const V t396 = t127*t386 + t128*t384 + t129*t385;
    const V t397 = t127*t389 + t128*t390 + t129*t388;
    const V t398 = t147*t387 + t152*t391 + t155*t392 + t156*t393 + t157*t394 + t158*t395 + t159*t396 + t160*t397 + t161*t383;
    const V t399 = t196*t398;
    const V t400 = t240*t399;
    const V t401 = t7*dat[36] + t9*dat[39] + t11*dat[42];
    const V t402 = t13*t401;
    const V t403 = t40 + t43 + t18*t402;
    const V t404 = t63*t401;
    const V t405 = t21*t41 + t14*t402;
    const V t406 = t105*dat[42] + t72*t405 + t106*t84 + t10*t404;
    const V t407 = t6*t402 + t21*dat[36];
    const V t408 = t105*t41 + t109*dat[42] + t14*t404 + t10*t407;
    const V t409 = t104*t403 + t108*t406 + t111*t408;
    const V t410 = t40 + t74*t402 + t86;
    const V t411 = t16*t405 + t6*t404 + t105*dat[36] + t106*t38;
    const V t412 = t16*t404 + t105*t38 + t109*dat[39] + t8*t407;
    const V t413 = t104*t412 + t108*t410 + t111*t411;
    const V t414 = t43 + t86 + t93*t402;
    const V t415 = t94*t84 + t95*t402 + t96*t38 + t105*dat[39] + t8*t404;
    const V t416 = t97*dat[39] + t98*dat[42] + t99*t402 + t105*t84 + t72*t404;
    const V t417 = t104*t415 + t108*t416 + t111*t414;
    const V t418 = t121*t403 + t122*t406 + t123*t408;
    const V t419 = t121*t412 + t122*t410 + t123*t411;
    const V t420 = t121*t415 + t122*t416 + t123*t414;
    const V t421 = t127*t403 + t128*t406 + t129*t408;
    const V t422 = t127*t412 + t128*t410 + t129*t411;
    const V t423 = t127*t415 + t128*t416 + t129*t414;
    const V t424 = t147*t413 + t152*t417 + t155*t418 + t156*t419 + t157*t420 + t158*t421 + t159*t422 + t160*t423 + t161*t409;
    const V t425 = t196*t424;
    const V t426 = t240*t425;
    const V t427 = t7*dat[37] + t9*dat[40] + t11*dat[43];
    const V t428 = t13*t427;
    const V t429 = t46 + t49 + t18*t428;
    const V t430 = t63*t427;
    const V t431 = t21*t44 + t14*t428;
    const V t432 = t105*dat[43] + t72*t431 + t106*t87 + t10*t430;
    const V t433 = t6*t428 + t21*dat[37];
    const V t434 = t105*t44 + t109*dat[43] + t14*t430 + t10*t433;
    const V t435 = t104*t429 + t108*t432 + t111*t434;
    const V t436 = t49 + t74*t428 + t89;
    const V t437 = t16*t431 + t6*t430 + t105*dat[37] + t106*t47;
    const V t438 = t16*t430 + t105*t47 + t109*dat[40] + t8*t433;
    const V t439 = t104*t438 + t108*t436 + t111*t437;
    const V t440 = t46 + t89 + t93*t428;
    const V t441 = t94*t87 + t95*t428 + t96*t47 + t105*dat[40] + t8*t430;
    const V t442 = t97*dat[40] + t98*dat[43] + t99*t428 + t105*t87 + t72*t430;
    const V t443 = t104*t441 + t108*t442 + t111*t440;
    const V t444 = t121*t429 + t122*t432 + t123*t434;
    const V t445 = t121*t438 + t122*t436 + t123*t437;
    const V t446 = t121*t441 + t122*t442 + t123*t440;
    const V t447 = t127*t429 + t128*t432 + t129*t434;
    const V t448 = t127*t438 + t128*t436 + t129*t437;
    const V t449 = t127*t441 + t128*t442 + t129*t440;
    const V t450 = t147*t439 + t152*t443 + t155*t444 + t156*t445 + t157*t446 + t158*t447 + t159*t448 + t160*t449 + t161*t435;
    const V t451 = t196*t450;
    const V t452 = t240*t451;
    const V t453 = t7*dat[38] + t9*dat[41] + t11*dat[44];
    const V t454 = t13*t453;
    const V t455 = t52 + t55 + t18*t454;
    const V t456 = t63*t453;
    const V t457 = t21*t50 + t14*t454;
    const V t458 = t105*dat[44] + t72*t457 + t106*t90 + t10*t456;
    const V t459 = t6*t454 + t21*dat[38];
    const V t460 = t105*t50 + t109*dat[44] + t14*t456 + t10*t459;
    const V t461 = t104*t455 + t108*t458 + t111*t460;
    const V t462 = t55 + t74*t454 + t92;
    const V t463 = t16*t457 + t6*t456 + t105*dat[38] + t106*t53;
    const V t464 = t16*t456 + t105*t53 + t109*dat[41] + t8*t459;
    const V t465 = t104*t464 + t108*t462 + t111*t463;
    const V t466 = t52 + t92 + t93*t454;
    const V t467 = t94*t90 + t95*t454 + t96*t53 + t105*dat[41] + t8*t456;
    const V t468 = t97*dat[41] + t98*dat[44] + t99*t454 + t105*t90 + t72*t456;
    const V t469 = t104*t467 + t108*t468 + t111*t466;
    const V t470 = t121*t455 + t122*t458 + t123*t460;
    const V t471 = t121*t464 + t122*t462 + t123*t463;
    const V t472 = t121*t467 + t122*t468 + t123*t466;
    const V t473 = t127*t455 + t128*t458 + t129*t460;
    const V t474 = t127*t464 + t128*t462 + t129*t463;
    const V t475 = t127*t467 + t128*t468 + t129*t466;
    const V t476 = t147*t465 + t152*t469 + t155*t470 + t156*t471 + t157*t472 + t158*t473 + t159*t474 + t160*t475 + t161*t461;
    const V t477 = t196*t476;
    const V t478 = t240*t477;
    const V t479 = t133*t240;
    const V t480 = t138*t240;
    const V t481 = -t197 - t200;
    const V t482 = t0*dat[27] + t1*dat[28] + t2*dat[29] + t3*dat[54] + t4*dat[55] + t5*dat[56] + dat[6];
    const V t483 = t0*dat[30] + t1*dat[31] + t2*dat[32] + t3*dat[57] + t4*dat[58] + t5*dat[59] + dat[7];
    const V t484 = t0*dat[33] + t1*dat[34] + t2*dat[35] + t3*dat[60] + t4*dat[61] + t5*dat[62] + dat[8];
    const V t485 = t482*in[0] + t483*in[1] + t484*in[2] + dat[69]*dat[70] + in[12] - in[27];
    const V t486 = t482*in[3] + t483*in[4] + t484*in[5] + dat[69]*dat[71] + in[13] - in[28];
    const V t487 = t482*in[6] + t483*in[7] + t484*in[8] + dat[69]*dat[72] + in[14] - in[29];
    const V t488 = t485*in[15] + t486*in[18] + t487*in[21];
    const V t489 = t485*in[17] + t486*in[20] + t487*in[23];
    const V t490 = t485*in[16] + t486*in[19] + t487*in[22];
    const V t491 = t165*t226 + t168*t227 + t171*t230 + t172*t231 + t173*t232 + t174*t235 + t175*t236 + t176*t237 + t177*t225;
    const V t492 = t165*t245 + t168*t246 + t171*t249 + t172*t250 + t173*t251 + t174*t254 + t175*t255 + t176*t256 + t177*t244;
    const V t493 = t165*t263 + t168*t264 + t171*t267 + t172*t268 + t173*t269 + t174*t272 + t175*t273 + t176*t274 + t177*t262;
    const V t494 = t171*t281 + t172*t282 + t173*t283 + t174*t287 + t175*t288 + t176*t289;
    const V t495 = t165*t297 + t168*t298 + t174*t302 + t175*t303 + t176*t304 + t177*t296;
    const V t496 = t165*t312 + t168*t313 + t171*t317 + t172*t318 + t173*t319 + t177*t311;
    const V t497 = t165*t335 + t168*t339 + t171*t340 + t172*t341 + t173*t342 + t174*t343 + t175*t344 + t176*t345 + t177*t331;
    const V t498 = t165*t361 + t168*t365 + t171*t366 + t172*t367 + t173*t368 + t174*t369 + t175*t370 + t176*t371 + t177*t357;
    const V t499 = t165*t387 + t168*t391 + t171*t392 + t172*t393 + t173*t394 + t174*t395 + t175*t396 + t176*t397 + t177*t383;
    const V t500 = t165*t413 + t168*t417 + t171*t418 + t172*t419 + t173*t420 + t174*t421 + t175*t422 + t176*t423 + t177*t409;
    const V t501 = t165*t439 + t168*t443 + t171*t444 + t172*t445 + t173*t446 + t174*t447 + t175*t448 + t176*t449 + t177*t435;
    const V t502 = t165*t465 + t168*t469 + t171*t470 + t172*t471 + t173*t472 + t174*t473 + t175*t474 + t176*t475 + t177*t461;
    const V t503 = t187*t230 + t188*t231 + t189*t232 + t190*t235 + t191*t236 + t192*t237 + t193*t225 + t180*t226 + t184*t227;
    const V t504 = t187*t249 + t188*t250 + t189*t251 + t190*t254 + t191*t255 + t192*t256 + t193*t244 + t180*t245 + t184*t246;
    const V t505 = t187*t267 + t188*t268 + t189*t269 + t190*t272 + t191*t273 + t192*t274 + t193*t262 + t180*t263 + t184*t264;
    const V t506 = t187*t281 + t188*t282 + t189*t283 + t190*t287 + t191*t288 + t192*t289;
    const V t507 = t190*t302 + t191*t303 + t192*t304 + t193*t296 + t180*t297 + t184*t298;
    const V t508 = t187*t317 + t188*t318 + t189*t319 + t193*t311 + t180*t312 + t184*t313;
    const V t509 = t187*t340 + t188*t341 + t189*t342 + t190*t343 + t191*t344 + t192*t345 + t193*t331 + t180*t335 + t184*t339;
    const V t510 = t187*t366 + t188*t367 + t189*t368 + t190*t369 + t191*t370 + t192*t371 + t193*t357 + t180*t361 + t184*t365;
    const V t511 = t187*t392 + t188*t393 + t189*t394 + t190*t395 + t191*t396 + t192*t397 + t193*t383 + t180*t387 + t184*t391;
    const V t512 = t187*t418 + t188*t419 + t189*t420 + t190*t421 + t191*t422 + t192*t423 + t193*t409 + t180*t413 + t184*t417;
    const V t513 = t187*t444 + t188*t445 + t189*t446 + t190*t447 + t191*t448 + t192*t449 + t193*t435 + t180*t439 + t184*t443;
    const V t514 = t187*t470 + t188*t471 + t189*t472 + t190*t473 + t191*t474 + t192*t475 + t193*t461 + t180*t465 + t184*t469;
    const V t515 = t194*t491;
    const V t516 = t194*t492;
    const V t517 = t194*t493;
    const V t518 = t194*t494;
    const V t519 = t194*t495;
    const V t520 = t194*t496;
    const V t521 = t194*t497;
    const V t522 = t194*t498;
    const V t523 = t194*t499;
    const V t524 = t194*t500;
    const V t525 = t194*t501;
    const V t526 = t194*t502;
    const V t527 = t195*t503;
    const V t528 = t195*t504;
    const V t529 = t195*t505;
    const V t530 = t195*t506;
    const V t531 = t195*t507;
    const V t532 = t195*t508;
    const V t533 = t195*t509;
    const V t534 = t195*t510;
    const V t535 = t195*t511;
    const V t536 = t195*t512;
    const V t537 = t195*t513;
    const V t538 = t195*t514;
    const V t539 = t515 + t527;
    const V t540 = t516 + t528;
    const V t541 = t517 + t529;
    const V t542 = t518 + t530;
    const V t543 = t519 + t531;
    const V t544 = t520 + t532;
    const V t545 = t521 + t533;
    const V t546 = t522 + t534;
    const V t547 = t523 + t535;
    const V t548 = t524 + t536;
    const V t549 = t525 + t537;
    const V t550 = t526 + t538;
    const V t551 = t202*t539 + t202*t239;
    const V t552 = t202*t540 + t202*t258;
    const V t553 = t202*t541 + t202*t276;
    const V t554 = t202*t542 + t202*t291;
    const V t555 = t202*t543 + t202*t306;
    const V t556 = t202*t544 + t202*t321;
    const V t557 = t202*t545 + t202*t347;
    const V t558 = t202*t546 + t202*t373;
    const V t559 = t202*t547 + t202*t399;
    const V t560 = t202*t548 + t202*t425;
    const V t561 = t202*t549 + t202*t451;
    const V t562 = t202*t550 + t202*t477;
    const V t563 = -t199*t240 + T(1);
    const V t564 = -t199*t551 - t240*t539;
    const V t565 = -t199*t552 - t240*t540;
    const V t566 = -t199*t553 - t240*t541;
    const V t567 = -t199*t554 - t240*t542;
    const V t568 = -t199*t555 - t240*t543;
    const V t569 = -t199*t556 - t240*t544;
    const V t570 = -t199*t557 - t240*t545;
    const V t571 = -t199*t558 - t240*t546;
    const V t572 = -t199*t559 - t240*t547;
    const V t573 = -t199*t560 - t240*t548;
    const V t574 = -t199*t561 - t240*t549;
    const V t575 = -t199*t562 - t240*t550;
    const V t576 = t213*in[2] - t214*in[1];
    const V t577 = -t212*in[2] + t214*in[0];
    const V t578 = t212*in[1] - t213*in[0];
    const V t579 = t203;
    const V t580 = t204;
    const V t581 = t205;
    const V t582 = dat[18]*in[0] + dat[21]*in[1] + dat[24]*in[2];
    const V t583 = dat[19]*in[0] + dat[22]*in[1] + dat[25]*in[2];
    const V t584 = dat[20]*in[0] + dat[23]*in[1] + dat[26]*in[2];
    const V t585 = dat[45]*in[0] + dat[48]*in[1] + dat[51]*in[2];
    const V t586 = dat[46]*in[0] + dat[49]*in[1] + dat[52]*in[2];
    const V t587 = dat[47]*in[0] + dat[50]*in[1] + dat[53]*in[2];
    const V t588 = t213*in[5] - t214*in[4];
    const V t589 = -t212*in[5] + t214*in[3];
    const V t590 = t212*in[4] - t213*in[3];
    const V t591 = t206;
    const V t592 = t207;
    const V t593 = t208;
    const V t594 = dat[18]*in[3] + dat[21]*in[4] + dat[24]*in[5];
    const V t595 = dat[19]*in[3] + dat[22]*in[4] + dat[25]*in[5];
    const V t596 = dat[20]*in[3] + dat[23]*in[4] + dat[26]*in[5];
    const V t597 = dat[45]*in[3] + dat[48]*in[4] + dat[51]*in[5];
    const V t598 = dat[46]*in[3] + dat[49]*in[4] + dat[52]*in[5];
    const V t599 = dat[47]*in[3] + dat[50]*in[4] + dat[53]*in[5];
    const V t600 = t213*in[8] - t214*in[7];
    const V t601 = -t212*in[8] + t214*in[6];
    const V t602 = t212*in[7] - t213*in[6];
    const V t603 = t209;
    const V t604 = t210;
    const V t605 = t211;
    const V t606 = dat[18]*in[6] + dat[21]*in[7] + dat[24]*in[8];
    const V t607 = dat[19]*in[6] + dat[22]*in[7] + dat[25]*in[8];
    const V t608 = dat[20]*in[6] + dat[23]*in[7] + dat[26]*in[8];
    const V t609 = dat[45]*in[6] + dat[48]*in[7] + dat[51]*in[8];
    const V t610 = dat[46]*in[6] + dat[49]*in[7] + dat[52]*in[8];
    const V t611 = dat[47]*in[6] + dat[50]*in[7] + dat[53]*in[8];
    const V t612 = t219;
    const V t613 = t576*in[15] + t588*in[18] + t600*in[21];
    const V t614 = t577*in[15] + t589*in[18] + t601*in[21];
    const V t615 = t578*in[15] + t590*in[18] + t602*in[21];
    const V t616 = t56;
    const V t617 = t59;
    const V t618 = t57;
    const V t619 = dat[69]*in[15];
    const V t620 = dat[69]*in[18];
    const V t621 = dat[69]*in[21];
    const V t622 = -t220;
    const V t623 = t221;
    const V t624 = t579*in[15] + t591*in[18] + t603*in[21];
    const V t625 = t580*in[15] + t592*in[18] + t604*in[21];
    const V t626 = t581*in[15] + t593*in[18] + t605*in[21];
    const V t627 = t582*in[15] + t594*in[18] + t606*in[21];
    const V t628 = t583*in[15] + t595*in[18] + t607*in[21];
    const V t629 = t584*in[15] + t596*in[18] + t608*in[21];
    const V t630 = t585*in[15] + t597*in[18] + t609*in[21];
    const V t631 = t586*in[15] + t598*in[18] + t610*in[21];
    const V t632 = t587*in[15] + t599*in[18] + t611*in[21];
    const V t633 = t148;
    const V t634 = (T(0.5))*t503;
    const V t635 = (T(0.5))*t504;
    const V t636 = (T(0.5))*t505;
    const V t637 = (T(0.5))*t506;
    const V t638 = (T(0.5))*t507;
    const V t639 = (T(0.5))*t508;
    const V t640 = (T(0.5))*t509;
    const V t641 = (T(0.5))*t510;
    const V t642 = (T(0.5))*t511;
    const V t643 = (T(0.5))*t512;
    const V t644 = (T(0.5))*t513;
    const V t645 = (T(0.5))*t514;
    const V t646 = t135*t240;
    const V t647 = t135*t551 + t240*t238;
    const V t648 = t135*t552 + t240*t257;
    const V t649 = t135*t553 + t240*t275;
    const V t650 = t135*t554 + t240*t290;
    const V t651 = t135*t555 + t240*t305;
    const V t652 = t135*t556 + t240*t320;
    const V t653 = t135*t557 + t240*t346;
    const V t654 = t135*t558 + t240*t372;
    const V t655 = t135*t559 + t240*t398;
    const V t656 = t135*t560 + t240*t424;
    const V t657 = t135*t561 + t240*t450;
    const V t658 = t135*t562 + t240*t476;
    const V t659 = t133*t646;
    const V t660 = t133*t647 + t646*t491;
    const V t661 = t133*t648 + t646*t492;
    const V t662 = t133*t649 + t646*t493;
    const V t663 = t133*t650 + t646*t494;
    const V t664 = t133*t651 + t646*t495;
    const V t665 = t133*t652 + t646*t496;
    const V t666 = t133*t653 + t646*t497;
    const V t667 = t133*t654 + t646*t498;
    const V t668 = t133*t655 + t646*t499;
    const V t669 = t133*t656 + t646*t500;
    const V t670 = t133*t657 + t646*t501;
    const V t671 = t133*t658 + t646*t502;
    const V t672 = t633 + t659;
    const V t673 = t634 + t660;
    const V t674 = t635 + t661;
    const V t675 = t636 + t662;
    const V t676 = t637 + t663;
    const V t677 = t638 + t664;
    const V t678 = t639 + t665;
    const V t679 = t640 + t666;
    const V t680 = t641 + t667;
    const V t681 = t642 + t668;
    const V t682 = t643 + t669;
    const V t683 = t644 + t670;
    const V t684 = t645 + t671;
    const V t685 = t221;
    const V t686 = t576*in[16] + t588*in[19] + t600*in[22];
    const V t687 = t577*in[16] + t589*in[19] + t601*in[22];
    const V t688 = t578*in[16] + t590*in[19] + t602*in[22];
    const V t689 = t62;
    const V t690 = t67;
    const V t691 = t71;
    const V t692 = dat[69]*in[16];
    const V t693 = dat[69]*in[19];
    const V t694 = dat[69]*in[22];
    const V t695 = t220;
    const V t696 = -t219;
    const V t697 = t579*in[16] + t591*in[19] + t603*in[22];
    const V t698 = t580*in[16] + t592*in[19] + t604*in[22];
    const V t699 = t581*in[16] + t593*in[19] + t605*in[22];
    const V t700 = t582*in[16] + t594*in[19] + t606*in[22];
    const V t701 = t583*in[16] + t595*in[19] + t607*in[22];
    const V t702 = t584*in[16] + t596*in[19] + t608*in[22];
    const V t703 = t585*in[16] + t597*in[19] + t609*in[22];
    const V t704 = t586*in[16] + t598*in[19] + t610*in[22];
    const V t705 = t587*in[16] + t599*in[19] + t611*in[22];
    const V t706 = t134;
    const V t707 = (T(0.5))*t491;
    const V t708 = (T(0.5))*t492;
    const V t709 = (T(0.5))*t493;
    const V t710 = (T(0.5))*t494;
    const V t711 = (T(0.5))*t495;
    const V t712 = (T(0.5))*t496;
    const V t713 = (T(0.5))*t497;
    const V t714 = (T(0.5))*t498;
    const V t715 = (T(0.5))*t499;
    const V t716 = (T(0.5))*t500;
    const V t717 = (T(0.5))*t501;
    const V t718 = (T(0.5))*t502;
    const V t719 = t138*t646;
    const V t720 = t138*t647 + t646*t503;
    const V t721 = t138*t648 + t646*t504;
    const V t722 = t138*t649 + t646*t505;
    const V t723 = t138*t650 + t646*t506;
    const V t724 = t138*t651 + t646*t507;
    const V t725 = t138*t652 + t646*t508;
    const V t726 = t138*t653 + t646*t509;
    const V t727 = t138*t654 + t646*t510;
    const V t728 = t138*t655 + t646*t511;
    const V t729 = t138*t656 + t646*t512;
    const V t730 = t138*t657 + t646*t513;
    const V t731 = t138*t658 + t646*t514;
    const V t732 = -t706 + t719;
    const V t733 = -t707 + t720;
    const V t734 = -t708 + t721;
    const V t735 = -t709 + t722;
    const V t736 = -t710 + t723;
    const V t737 = -t711 + t724;
    const V t738 = -t712 + t725;
    const V t739 = -t713 + t726;
    const V t740 = -t714 + t727;
    const V t741 = -t715 + t728;
    const V t742 = -t716 + t729;
    const V t743 = -t717 + t730;
    const V t744 = -t718 + t731;
    const V t745 = t220;
    const V t746 = t576*in[17] + t588*in[20] + t600*in[23];
    const V t747 = t577*in[17] + t589*in[20] + t601*in[23];
    const V t748 = t578*in[17] + t590*in[20] + t602*in[23];
    const V t749 = t60;
    const V t750 = t65;
    const V t751 = t69;
    const V t752 = dat[69]*in[17];
    const V t753 = dat[69]*in[20];
    const V t754 = dat[69]*in[23];
    const V t755 = -t221;
    const V t756 = t219;
    const V t757 = t579*in[17] + t591*in[20] + t603*in[23];
    const V t758 = t580*in[17] + t592*in[20] + t604*in[23];
    const V t759 = t581*in[17] + t593*in[20] + t605*in[23];
    const V t760 = t582*in[17] + t594*in[20] + t606*in[23];
    const V t761 = t583*in[17] + t595*in[20] + t607*in[23];
    const V t762 = t584*in[17] + t596*in[20] + t608*in[23];
    const V t763 = t585*in[17] + t597*in[20] + t609*in[23];
    const V t764 = t586*in[17] + t598*in[20] + t610*in[23];
    const V t765 = t587*in[17] + t599*in[20] + t611*in[23];
    const V t766 = t222*t240 + T(1);
    const V t767 = t222*t551 - t241 - t240*t527;
    const V t768 = t222*t552 - t259 - t240*t528;
    const V t769 = t222*t553 - t277 - t240*t529;
    const V t770 = t222*t554 - t292 - t240*t530;
    const V t771 = t222*t555 - t307 - t240*t531;
    const V t772 = t222*t556 - t322 - t240*t532;
    const V t773 = t222*t557 - t348 - t240*t533;
    const V t774 = t222*t558 - t374 - t240*t534;
    const V t775 = t222*t559 - t400 - t240*t535;
    const V t776 = t222*t560 - t426 - t240*t536;
    const V t777 = t222*t561 - t452 - t240*t537;
    const V t778 = t222*t562 - t478 - t240*t538;
    const V t779 = t162;
    const V t780 = (T(0.5))*t238;
    const V t781 = (T(0.5))*t257;
    const V t782 = (T(0.5))*t275;
    const V t783 = (T(0.5))*t290;
    const V t784 = (T(0.5))*t305;
    const V t785 = (T(0.5))*t320;
    const V t786 = (T(0.5))*t346;
    const V t787 = (T(0.5))*t372;
    const V t788 = (T(0.5))*t398;
    const V t789 = (T(0.5))*t424;
    const V t790 = (T(0.5))*t450;
    const V t791 = (T(0.5))*t476;
    const V t792 = t181*t240;
    const V t793 = t479*t503 + t480*t491 + t181*t551;
    const V t794 = t479*t504 + t480*t492 + t181*t552;
    const V t795 = t479*t505 + t480*t493 + t181*t553;
    const V t796 = t479*t506 + t480*t494 + t181*t554;
    const V t797 = t479*t507 + t480*t495 + t181*t555;
    const V t798 = t479*t508 + t480*t496 + t181*t556;
    const V t799 = t479*t509 + t480*t497 + t181*t557;
    const V t800 = t479*t510 + t480*t498 + t181*t558;
    const V t801 = t479*t511 + t480*t499 + t181*t559;
    const V t802 = t479*t512 + t480*t500 + t181*t560;
    const V t803 = t479*t513 + t480*t501 + t181*t561;
    const V t804 = t479*t514 + t480*t502 + t181*t562;
    const V t805 = t779 + t792;
    const V t806 = t780 + t793;
    const V t807 = t781 + t794;
    const V t808 = t782 + t795;
    const V t809 = t783 + t796;
    const V t810 = t784 + t797;
    const V t811 = t785 + t798;
    const V t812 = t786 + t799;
    const V t813 = t787 + t800;
    const V t814 = t788 + t801;
    const V t815 = t789 + t802;
    const V t816 = t790 + t803;
    const V t817 = t791 + t804;
    const V t818 = -t633 + t659;
    const V t819 = -t634 + t660;
    const V t820 = -t635 + t661;
    const V t821 = -t636 + t662;
    const V t822 = -t637 + t663;
    const V t823 = -t638 + t664;
    const V t824 = -t639 + t665;
    const V t825 = -t640 + t666;
    const V t826 = -t641 + t667;
    const V t827 = -t642 + t668;
    const V t828 = -t643 + t669;
    const V t829 = -t644 + t670;
    const V t830 = -t645 + t671;
    const V t831 = t481*t240 + T(1);
    const V t832 = -t241 + t481*t551 - t240*t515;
    const V t833 = -t259 + t481*t552 - t240*t516;
    const V t834 = -t277 + t481*t553 - t240*t517;
    const V t835 = -t292 + t481*t554 - t240*t518;
    const V t836 = -t307 + t481*t555 - t240*t519;
    const V t837 = -t322 + t481*t556 - t240*t520;
    const V t838 = -t348 + t481*t557 - t240*t521;
    const V t839 = -t374 + t481*t558 - t240*t522;
    const V t840 = -t400 + t481*t559 - t240*t523;
    const V t841 = -t426 + t481*t560 - t240*t524;
    const V t842 = -t452 + t481*t561 - t240*t525;
    const V t843 = -t478 + t481*t562 - t240*t526;
    const V t844 = t706 + t719;
    const V t845 = t707 + t720;
    const V t846 = t708 + t721;
    const V t847 = t709 + t722;
    const V t848 = t710 + t723;
    const V t849 = t711 + t724;
    const V t850 = t712 + t725;
    const V t851 = t713 + t726;
    const V t852 = t714 + t727;
    const V t853 = t715 + t728;
    const V t854 = t716 + t729;
    const V t855 = t717 + t730;
    const V t856 = t718 + t731;
    const V t857 = -t779 + t792;
    const V t858 = -t780 + t793;
    const V t859 = -t781 + t794;
    const V t860 = -t782 + t795;
    const V t861 = -t783 + t796;
    const V t862 = -t784 + t797;
    const V t863 = -t785 + t798;
    const V t864 = -t786 + t799;
    const V t865 = -t787 + t800;
    const V t866 = -t788 + t801;
    const V t867 = -t789 + t802;
    const V t868 = -t790 + t803;
    const V t869 = -t791 + t804;
    const V t870 = t483*in[2] - t484*in[1];
    const V t871 = -t482*in[2] + t484*in[0];
    const V t872 = t482*in[1] - t483*in[0];
    const V t873 = dat[27]*in[0] + dat[30]*in[1] + dat[33]*in[2];
    const V t874 = dat[28]*in[0] + dat[31]*in[1] + dat[34]*in[2];
    const V t875 = dat[29]*in[0] + dat[32]*in[1] + dat[35]*in[2];
    const V t876 = dat[54]*in[0] + dat[57]*in[1] + dat[60]*in[2];
    const V t877 = dat[55]*in[0] + dat[58]*in[1] + dat[61]*in[2];
    const V t878 = dat[56]*in[0] + dat[59]*in[1] + dat[62]*in[2];
    const V t879 = t483*in[5] - t484*in[4];
    const V t880 = -t482*in[5] + t484*in[3];
    const V t881 = t482*in[4] - t483*in[3];
    const V t882 = dat[27]*in[3] + dat[30]*in[4] + dat[33]*in[5];
    const V t883 = dat[28]*in[3] + dat[31]*in[4] + dat[34]*in[5];
    const V t884 = dat[29]*in[3] + dat[32]*in[4] + dat[35]*in[5];
    const V t885 = dat[54]*in[3] + dat[57]*in[4] + dat[60]*in[5];
    const V t886 = dat[55]*in[3] + dat[58]*in[4] + dat[61]*in[5];
    const V t887 = dat[56]*in[3] + dat[59]*in[4] + dat[62]*in[5];
    const V t888 = t483*in[8] - t484*in[7];
    const V t889 = -t482*in[8] + t484*in[6];
    const V t890 = t482*in[7] - t483*in[6];
    const V t891 = dat[27]*in[6] + dat[30]*in[7] + dat[33]*in[8];
    const V t892 = dat[28]*in[6] + dat[31]*in[7] + dat[34]*in[8];
    const V t893 = dat[29]*in[6] + dat[32]*in[7] + dat[35]*in[8];
    const V t894 = dat[54]*in[6] + dat[57]*in[7] + dat[60]*in[8];
    const V t895 = dat[55]*in[6] + dat[58]*in[7] + dat[61]*in[8];
    const V t896 = dat[56]*in[6] + dat[59]*in[7] + dat[62]*in[8];
    const V t897 = t488;
    const V t898 = t870*in[15] + t879*in[18] + t888*in[21];
    const V t899 = t871*in[15] + t880*in[18] + t889*in[21];
    const V t900 = t872*in[15] + t881*in[18] + t890*in[21];
    const V t901 = -t489;
    const V t902 = t490;
    const V t903 = t203;
    const V t904 = t206;
    const V t905 = t209;
    const V t906 = t873*in[15] + t882*in[18] + t891*in[21];
    const V t907 = t874*in[15] + t883*in[18] + t892*in[21];
    const V t908 = t875*in[15] + t884*in[18] + t893*in[21];
    const V t909 = t876*in[15] + t885*in[18] + t894*in[21];
    const V t910 = t877*in[15] + t886*in[18] + t895*in[21];
    const V t911 = t878*in[15] + t887*in[18] + t896*in[21];
    const V t912 = t490;
    const V t913 = t870*in[16] + t879*in[19] + t888*in[22];
    const V t914 = t871*in[16] + t880*in[19] + t889*in[22];
    const V t915 = t872*in[16] + t881*in[19] + t890*in[22];
    const V t916 = t489;
    const V t917 = -t488;
    const V t918 = t204;
    const V t919 = t207;
    const V t920 = t210;
    const V t921 = t873*in[16] + t882*in[19] + t891*in[22];
    const V t922 = t874*in[16] + t883*in[19] + t892*in[22];
    const V t923 = t875*in[16] + t884*in[19] + t893*in[22];
    const V t924 = t876*in[16] + t885*in[19] + t894*in[22];
    const V t925 = t877*in[16] + t886*in[19] + t895*in[22];
    const V t926 = t878*in[16] + t887*in[19] + t896*in[22];
    const V t927 = t489;
    const V t928 = t870*in[17] + t879*in[20] + t888*in[23];
    const V t929 = t871*in[17] + t880*in[20] + t889*in[23];
    const V t930 = t872*in[17] + t881*in[20] + t890*in[23];
    const V t931 = -t490;
    const V t932 = t488;
    const V t933 = t205;
    const V t934 = t208;
    const V t935 = t211;
    const V t936 = t873*in[17] + t882*in[20] + t891*in[23];
    const V t937 = t874*in[17] + t883*in[20] + t892*in[23];
    const V t938 = t875*in[17] + t884*in[20] + t893*in[23];
    const V t939 = t876*in[17] + t885*in[20] + t894*in[23];
    const V t940 = t877*in[17] + t886*in[20] + t895*in[23];
    const V t941 = t878*in[17] + t887*in[20] + t896*in[23];
    // every output once, as a whole V, before it is taken apart lane by lane
    const V o0 = t238;
    const V o1 = t257;
    const V o2 = t275;
    const V o3 = t290;
    const V o4 = t305;
    const V o5 = t320;
    const V o6 = t346;
    const V o7 = t372;
    const V o8 = t398;
    const V o9 = t424;
    const V o10 = t450;
    const V o11 = t476;
    const V o12 = t135;
    const V o13 = t491;
    const V o14 = t492;
    const V o15 = t493;
    const V o16 = t494;
    const V o17 = t495;
    const V o18 = t496;
    const V o19 = t497;
    const V o20 = t498;
    const V o21 = t499;
    const V o22 = t500;
    const V o23 = t501;
    const V o24 = t502;
    const V o25 = t133;
    const V o26 = t503;
    const V o27 = t504;
    const V o28 = t505;
    const V o29 = t506;
    const V o30 = t507;
    const V o31 = t508;
    const V o32 = t509;
    const V o33 = t510;
    const V o34 = t511;
    const V o35 = t512;
    const V o36 = t513;
    const V o37 = t514;
    const V o38 = t138;
    const V o39 = t563*t613 + t612*t564 + t672*t686 + t685*t673 + t732*t746 + t745*t733;
    const V o40 = t563*t614 + t612*t565 + t672*t687 + t685*t674 + t732*t747 + t745*t734;
    const V o41 = t563*t615 + t612*t566 + t672*t688 + t685*t675 + t732*t748 + t745*t735;
    const V o42 = t563*t616 + t672*t689 + t732*t749;
    const V o43 = t563*t617 + t672*t690 + t732*t750;
    const V o44 = t563*t618 + t672*t691 + t732*t751;
    const V o45 = t563*t619 + t672*t692 + t732*t752;
    const V o46 = t563*t620 + t672*t693 + t732*t753;
    const V o47 = t563*t621 + t672*t694 + t732*t754;
    const V o48 = t612*t567 + t672*t695 + t685*t676 + t732*t755 + t745*t736;
    const V o49 = t563*t622 + t612*t568 + t685*t677 + t732*t756 + t745*t737;
    const V o50 = t563*t623 + t612*t569 + t672*t696 + t685*t678 + t745*t738;
    const V o51 = t563*t624 + t672*t697 + t732*t757;
    const V o52 = t563*t625 + t672*t698 + t732*t758;
    const V o53 = t563*t626 + t672*t699 + t732*t759;
    const V o54 = t563*t627 + t612*t570 + t672*t700 + t685*t679 + t732*t760 + t745*t739;
    const V o55 = t563*t628 + t612*t571 + t672*t701 + t685*t680 + t732*t761 + t745*t740;
    const V o56 = t563*t629 + t612*t572 + t672*t702 + t685*t681 + t732*t762 + t745*t741;
    const V o57 = t563*t630 + t612*t573 + t672*t703 + t685*t682 + t732*t763 + t745*t742;
    const V o58 = t563*t631 + t612*t574 + t672*t704 + t685*t683 + t732*t764 + t745*t743;
    const V o59 = t563*t632 + t612*t575 + t672*t705 + t685*t684 + t732*t765 + t745*t744;
    const V o60 = t563*t612 + t672*t685 + t732*t745;
    const V o61 = t612*t819 + t685*t767 + t745*t806 + t766*t686 + t805*t746 + t818*t613;
    const V o62 = t612*t820 + t685*t768 + t745*t807 + t766*t687 + t805*t747 + t818*t614;
    const V o63 = t612*t821 + t685*t769 + t745*t808 + t766*t688 + t805*t748 + t818*t615;
    const V o64 = t766*t689 + t805*t749 + t818*t616;
    const V o65 = t766*t690 + t805*t750 + t818*t617;
    const V o66 = t766*t691 + t805*t751 + t818*t618;
    const V o67 = t766*t692 + t805*t752 + t818*t619;
    const V o68 = t766*t693 + t805*t753 + t818*t620;
    const V o69 = t766*t694 + t805*t754 + t818*t621;
    const V o70 = t612*t822 + t685*t770 + t745*t809 + t766*t695 + t805*t755;
    const V o71 = t612*t823 + t685*t771 + t745*t810 + t805*t756 + t818*t622;
    const V o72 = t612*t824 + t685*t772 + t745*t811 + t766*t696 + t818*t623;
    const V o73 = t766*t697 + t805*t757 + t818*t624;
    const V o74 = t766*t698 + t805*t758 + t818*t625;
    const V o75 = t766*t699 + t805*t759 + t818*t626;
    const V o76 = t612*t825 + t685*t773 + t745*t812 + t766*t700 + t805*t760 + t818*t627;
    const V o77 = t612*t826 + t685*t774 + t745*t813 + t766*t701 + t805*t761 + t818*t628;
    const V o78 = t612*t827 + t685*t775 + t745*t814 + t766*t702 + t805*t762 + t818*t629;
    const V o79 = t612*t828 + t685*t776 + t745*t815 + t766*t703 + t805*t763 + t818*t630;
    const V o80 = t612*t829 + t685*t777 + t745*t816 + t766*t704 + t805*t764 + t818*t631;
    const V o81 = t612*t830 + t685*t778 + t745*t817 + t766*t705 + t805*t765 + t818*t632;
    const V o82 = t612*t818 + t685*t766 + t745*t805;
    const V o83 = t612*t845 + t685*t858 + t745*t832 + t831*t746 + t844*t613 + t857*t686;
    const V o84 = t612*t846 + t685*t859 + t745*t833 + t831*t747 + t844*t614 + t857*t687;
    const V o85 = t612*t847 + t685*t860 + t745*t834 + t831*t748 + t844*t615 + t857*t688;
    const V o86 = t831*t749 + t844*t616 + t857*t689;
    const V o87 = t831*t750 + t844*t617 + t857*t690;
    const V o88 = t831*t751 + t844*t618 + t857*t691;
    const V o89 = t831*t752 + t844*t619 + t857*t692;
    const V o90 = t831*t753 + t844*t620 + t857*t693;
    const V o91 = t831*t754 + t844*t621 + t857*t694;
    const V o92 = t612*t848 + t685*t861 + t745*t835 + t831*t755 + t857*t695;
    const V o93 = t612*t849 + t685*t862 + t745*t836 + t831*t756 + t844*t622;
    const V o94 = t612*t850 + t685*t863 + t745*t837 + t844*t623 + t857*t696;
    const V o95 = t831*t757 + t844*t624 + t857*t697;
    const V o96 = t831*t758 + t844*t625 + t857*t698;
    const V o97 = t831*t759 + t844*t626 + t857*t699;
    const V o98 = t612*t851 + t685*t864 + t745*t838 + t831*t760 + t844*t627 + t857*t700;
    const V o99 = t612*t852 + t685*t865 + t745*t839 + t831*t761 + t844*t628 + t857*t701;
    const V o100 = t612*t853 + t685*t866 + t745*t840 + t831*t762 + t844*t629 + t857*t702;
    const V o101 = t612*t854 + t685*t867 + t745*t841 + t831*t763 + t844*t630 + t857*t703;
    const V o102 = t612*t855 + t685*t868 + t745*t842 + t831*t764 + t844*t631 + t857*t704;
    const V o103 = t612*t856 + t685*t869 + t745*t843 + t831*t765 + t844*t632 + t857*t705;
    const V o104 = t612*t844 + t685*t857 + t745*t831;
    const V o105 = t563*t898 + t672*t913 + t732*t928 + t897*t564 + t912*t673 + t927*t733;
    const V o106 = t563*t899 + t672*t914 + t732*t929 + t897*t565 + t912*t674 + t927*t734;
    const V o107 = t563*t900 + t672*t915 + t732*t930 + t897*t566 + t912*t675 + t927*t735;
    const V o108 = t563*in[15] + t672*in[16] + t732*in[17];
    const V o109 = t563*in[18] + t672*in[19] + t732*in[20];
    const V o110 = t563*in[21] + t672*in[22] + t732*in[23];
    const V o111 = t672*t916 + t732*t931 + t897*t567 + t912*t676 + t927*t736;
    const V o112 = t563*t901 + t732*t932 + t897*t568 + t912*t677 + t927*t737;
    const V o113 = t563*t902 + t672*t917 + t897*t569 + t912*t678 + t927*t738;
    const V o114 = t563*t903 + t672*t918 + t732*t933;
    const V o115 = t563*t904 + t672*t919 + t732*t934;
    const V o116 = t563*t905 + t672*t920 + t732*t935;
    const V o117 = t563*t906 + t672*t921 + t732*t936 + t897*t570 + t912*t679 + t927*t739;
    const V o118 = t563*t907 + t672*t922 + t732*t937 + t897*t571 + t912*t680 + t927*t740;
    const V o119 = t563*t908 + t672*t923 + t732*t938 + t897*t572 + t912*t681 + t927*t741;
    const V o120 = t563*t909 + t672*t924 + t732*t939 + t897*t573 + t912*t682 + t927*t742;
    const V o121 = t563*t910 + t672*t925 + t732*t940 + t897*t574 + t912*t683 + t927*t743;
    const V o122 = t563*t911 + t672*t926 + t732*t941 + t897*t575 + t912*t684 + t927*t744;
    const V o123 = t563*t897 + t672*t912 + t732*t927;
    const V o124 = t766*t913 + t805*t928 + t818*t898 + t897*t819 + t912*t767 + t927*t806;
    const V o125 = t766*t914 + t805*t929 + t818*t899 + t897*t820 + t912*t768 + t927*t807;
    const V o126 = t766*t915 + t805*t930 + t818*t900 + t897*t821 + t912*t769 + t927*t808;
    const V o127 = t766*in[16] + t805*in[17] + t818*in[15];
    const V o128 = t766*in[19] + t805*in[20] + t818*in[18];
    const V o129 = t766*in[22] + t805*in[23] + t818*in[21];
    const V o130 = t766*t916 + t805*t931 + t897*t822 + t912*t770 + t927*t809;
    const V o131 = t805*t932 + t818*t901 + t897*t823 + t912*t771 + t927*t810;
    const V o132 = t766*t917 + t818*t902 + t897*t824 + t912*t772 + t927*t811;
    const V o133 = t766*t918 + t805*t933 + t818*t903;
    const V o134 = t766*t919 + t805*t934 + t818*t904;
    const V o135 = t766*t920 + t805*t935 + t818*t905;
    const V o136 = t766*t921 + t805*t936 + t818*t906 + t897*t825 + t912*t773 + t927*t812;
    const V o137 = t766*t922 + t805*t937 + t818*t907 + t897*t826 + t912*t774 + t927*t813;
    const V o138 = t766*t923 + t805*t938 + t818*t908 + t897*t827 + t912*t775 + t927*t814;
    const V o139 = t766*t924 + t805*t939 + t818*t909 + t897*t828 + t912*t776 + t927*t815;
    const V o140 = t766*t925 + t805*t940 + t818*t910 + t897*t829 + t912*t777 + t927*t816;
    const V o141 = t766*t926 + t805*t941 + t818*t911 + t897*t830 + t912*t778 + t927*t817;
    const V o142 = t766*t912 + t805*t927 + t818*t897;
    const V o143 = t831*t928 + t844*t898 + t857*t913 + t897*t845 + t912*t858 + t927*t832;
    const V o144 = t831*t929 + t844*t899 + t857*t914 + t897*t846 + t912*t859 + t927*t833;
    const V o145 = t831*t930 + t844*t900 + t857*t915 + t897*t847 + t912*t860 + t927*t834;
    const V o146 = t831*in[17] + t844*in[15] + t857*in[16];
    const V o147 = t831*in[20] + t844*in[18] + t857*in[19];
    const V o148 = t831*in[23] + t844*in[21] + t857*in[22];
    const V o149 = t831*t931 + t857*t916 + t897*t848 + t912*t861 + t927*t835;
    const V o150 = t831*t932 + t844*t901 + t897*t849 + t912*t862 + t927*t836;
    const V o151 = t844*t902 + t857*t917 + t897*t850 + t912*t863 + t927*t837;
    const V o152 = t831*t933 + t844*t903 + t857*t918;
    const V o153 = t831*t934 + t844*t904 + t857*t919;
    const V o154 = t831*t935 + t844*t905 + t857*t920;
    const V o155 = t831*t936 + t844*t906 + t857*t921 + t897*t851 + t912*t864 + t927*t838;
    const V o156 = t831*t937 + t844*t907 + t857*t922 + t897*t852 + t912*t865 + t927*t839;
    const V o157 = t831*t938 + t844*t908 + t857*t923 + t897*t853 + t912*t866 + t927*t840;
    const V o158 = t831*t939 + t844*t909 + t857*t924 + t897*t854 + t912*t867 + t927*t841;
    const V o159 = t831*t940 + t844*t910 + t857*t925 + t897*t855 + t912*t868 + t927*t842;
    const V o160 = t831*t941 + t844*t911 + t857*t926 + t897*t856 + t912*t869 + t927*t843;
    const V o161 = t831*t927 + t844*t897 + t857*t912;
    const V o164 = in[30] - in[36];
    const V o167 = in[31] - in[37];
    const V o170 = in[32] - in[38];
    const V o173 = in[33] - in[39];
    const V o176 = in[34] - in[40];
    const V o179 = in[35] - in[41];
    for (int l = 0; l < LANES; ++l) {
        ab[l][0] = lane(o0, l);
        ab[l][1] = lane(o1, l);
        ab[l][2] = lane(o2, l);
        ab[l][9] = lane(o3, l);
        ab[l][10] = lane(o4, l);
        ab[l][11] = lane(o5, l);
        ab[l][18] = lane(o6, l);
        ab[l][19] = lane(o7, l);
        ab[l][20] = lane(o8, l);
        ab[l][21] = lane(o9, l);
        ab[l][22] = lane(o10, l);
        ab[l][23] = lane(o11, l);
        ab[l][30] = lane(o12, l);
        ab[l][32] = lane(o13, l);
        ab[l][33] = lane(o14, l);
        ab[l][34] = lane(o15, l);
        ab[l][41] = lane(o16, l);
        ab[l][42] = lane(o17, l);
        ab[l][43] = lane(o18, l);
        ab[l][50] = lane(o19, l);
        ab[l][51] = lane(o20, l);
        ab[l][52] = lane(o21, l);
        ab[l][53] = lane(o22, l);
        ab[l][54] = lane(o23, l);
        ab[l][55] = lane(o24, l);
        ab[l][62] = lane(o25, l);
        ab[l][64] = lane(o26, l);
        ab[l][65] = lane(o27, l);
        ab[l][66] = lane(o28, l);
        ab[l][73] = lane(o29, l);
        ab[l][74] = lane(o30, l);
        ab[l][75] = lane(o31, l);
        ab[l][82] = lane(o32, l);
        ab[l][83] = lane(o33, l);
        ab[l][84] = lane(o34, l);
        ab[l][85] = lane(o35, l);
        ab[l][86] = lane(o36, l);
        ab[l][87] = lane(o37, l);
        ab[l][94] = lane(o38, l);
        ab[l][96] = lane(o39, l);
        ab[l][97] = lane(o40, l);
        ab[l][98] = lane(o41, l);
        ab[l][99] = lane(o42, l);
        ab[l][100] = lane(o43, l);
        ab[l][101] = lane(o44, l);
        ab[l][102] = lane(o45, l);
        ab[l][103] = lane(o46, l);
        ab[l][104] = lane(o47, l);
        ab[l][105] = lane(o48, l);
        ab[l][106] = lane(o49, l);
        ab[l][107] = lane(o50, l);
        ab[l][108] = lane(o51, l);
        ab[l][109] = lane(o52, l);
        ab[l][110] = lane(o53, l);
        ab[l][114] = lane(o54, l);
        ab[l][115] = lane(o55, l);
        ab[l][116] = lane(o56, l);
        ab[l][117] = lane(o57, l);
        ab[l][118] = lane(o58, l);
        ab[l][119] = lane(o59, l);
        ab[l][126] = lane(o60, l);
        ab[l][128] = lane(o61, l);
        ab[l][129] = lane(o62, l);
        ab[l][130] = lane(o63, l);
        ab[l][131] = lane(o64, l);
        ab[l][132] = lane(o65, l);
        ab[l][133] = lane(o66, l);
        ab[l][134] = lane(o67, l);
        ab[l][135] = lane(o68, l);
        ab[l][136] = lane(o69, l);
        ab[l][137] = lane(o70, l);
        ab[l][138] = lane(o71, l);
        ab[l][139] = lane(o72, l);
        ab[l][140] = lane(o73, l);
        ab[l][141] = lane(o74, l);
        ab[l][142] = lane(o75, l);
        ab[l][146] = lane(o76, l);
        ab[l][147] = lane(o77, l);
        ab[l][148] = lane(o78, l);
        ab[l][149] = lane(o79, l);
        ab[l][150] = lane(o80, l);
        ab[l][151] = lane(o81, l);
        ab[l][158] = lane(o82, l);
        ab[l][160] = lane(o83, l);
        ab[l][161] = lane(o84, l);
        ab[l][162] = lane(o85, l);
        ab[l][163] = lane(o86, l);
        ab[l][164] = lane(o87, l);
        ab[l][165] = lane(o88, l);
        ab[l][166] = lane(o89, l);
        ab[l][167] = lane(o90, l);
        ab[l][168] = lane(o91, l);
        ab[l][169] = lane(o92, l);
        ab[l][170] = lane(o93, l);
        ab[l][171] = lane(o94, l);
        ab[l][172] = lane(o95, l);
        ab[l][173] = lane(o96, l);
        ab[l][174] = lane(o97, l);
        ab[l][178] = lane(o98, l);
        ab[l][179] = lane(o99, l);
        ab[l][180] = lane(o100, l);
        ab[l][181] = lane(o101, l);
        ab[l][182] = lane(o102, l);
        ab[l][183] = lane(o103, l);
        ab[l][190] = lane(o104, l);
        ab[l][192] = lane(o105, l);
        ab[l][193] = lane(o106, l);
        ab[l][194] = lane(o107, l);
        ab[l][198] = lane(o108, l);
        ab[l][199] = lane(o109, l);
        ab[l][200] = lane(o110, l);
        ab[l][201] = lane(o111, l);
        ab[l][202] = lane(o112, l);
        ab[l][203] = lane(o113, l);
        ab[l][207] = lane(o114, l);
        ab[l][208] = lane(o115, l);
        ab[l][209] = lane(o116, l);
        ab[l][210] = lane(o117, l);
        ab[l][211] = lane(o118, l);
        ab[l][212] = lane(o119, l);
        ab[l][213] = lane(o120, l);
        ab[l][214] = lane(o121, l);
        ab[l][215] = lane(o122, l);
        ab[l][222] = lane(o123, l);
        ab[l][224] = lane(o124, l);
        ab[l][225] = lane(o125, l);
        ab[l][226] = lane(o126, l);
        ab[l][230] = lane(o127, l);
        ab[l][231] = lane(o128, l);
        ab[l][232] = lane(o129, l);
        ab[l][233] = lane(o130, l);
        ab[l][234] = lane(o131, l);
        ab[l][235] = lane(o132, l);
        ab[l][239] = lane(o133, l);
        ab[l][240] = lane(o134, l);
        ab[l][241] = lane(o135, l);
        ab[l][242] = lane(o136, l);
        ab[l][243] = lane(o137, l);
        ab[l][244] = lane(o138, l);
        ab[l][245] = lane(o139, l);
        ab[l][246] = lane(o140, l);
        ab[l][247] = lane(o141, l);
        ab[l][254] = lane(o142, l);
        ab[l][256] = lane(o143, l);
        ab[l][257] = lane(o144, l);
        ab[l][258] = lane(o145, l);
        ab[l][262] = lane(o146, l);
        ab[l][263] = lane(o147, l);
        ab[l][264] = lane(o148, l);
        ab[l][265] = lane(o149, l);
        ab[l][266] = lane(o150, l);
        ab[l][267] = lane(o151, l);
        ab[l][271] = lane(o152, l);
        ab[l][272] = lane(o153, l);
        ab[l][273] = lane(o154, l);
        ab[l][274] = lane(o155, l);
        ab[l][275] = lane(o156, l);
        ab[l][276] = lane(o157, l);
        ab[l][277] = lane(o158, l);
        ab[l][278] = lane(o159, l);
        ab[l][279] = lane(o160, l);
        ab[l][286] = lane(o161, l);
        ab[l][306] = T(1);
        ab[l][312] = (-T(1));
        ab[l][318] = lane(o164, l);
        ab[l][339] = T(1);
        ab[l][345] = (-T(1));
        ab[l][350] = lane(o167, l);
        ab[l][372] = T(1);
        ab[l][378] = (-T(1));
        ab[l][382] = lane(o170, l);
        ab[l][405] = T(1);
        ab[l][411] = (-T(1));
        ab[l][414] = lane(o173, l);
        ab[l][438] = T(1);
        ab[l][444] = (-T(1));
        ab[l][446] = lane(o176, l);
        ab[l][471] = T(1);
        ab[l][477] = (-T(1));
        ab[l][478] = lane(o179, l);
    }
}

void cost_0(const V* in, const V* dat, T half[LANES][1]) {
#pragma HLS PIPELINE II=1
    const V t0 = in[30] - dat[63];
    const V t1 = in[31] - dat[64];
    const V t2 = in[32] - dat[65];
    const V t3 = in[33] - dat[66];
    const V t4 = in[34] - dat[67];
    const V t5 = in[35] - dat[68];
    const V t6 = t0*dat[12] + t1*dat[13] + t2*dat[14] + t3*dat[39] + t4*dat[40] + t5*dat[41] + dat[1];
    const V t7 = -t6;
    const V t8 = t6*t7;
    const V t9 = t0*dat[15] + t1*dat[16] + t2*dat[17] + t3*dat[42] + t4*dat[43] + t5*dat[44] + dat[2];
    const V t10 = -t9;
    const V t11 = t10*t9;
    const V t12 = t11 + t8;
    const V t13 = t0*dat[9] + t1*dat[10] + t2*dat[11] + t3*dat[36] + t4*dat[37] + t5*dat[38] + dat[0];
    const V t14 = (t13*t13) + (t6*t6) + (t9*t9);
    const V t15 = v_lie_B(t14);
    const V t16 = t12*t15 + T(1);
    const V t17 = in[0]*in[15] + in[3]*in[18] + in[6]*in[21];
    const V t18 = t17;
    const V t19 = -t13;
    const V t20 = v_lie_A(t14);
    const V t21 = t15*t7;
    const V t22 = t20*t9 + t19*t21;
    const V t23 = in[1]*in[15] + in[4]*in[18] + in[7]*in[21];
    const V t24 = t23;
    const V t25 = t13*t15;
    const V t26 = t20*t7 + t25*t9;
    const V t27 = in[2]*in[15] + in[5]*in[18] + in[8]*in[21];
    const V t28 = t27;
    const V t29 = t16*t18 + t22*t24 + t26*t28;
    const V t30 = t13*t19;
    const V t31 = t11 + t30;
    const V t32 = t31*t15 + T(1);
    const V t33 = t10*t21 + t13*t20;
    const V t34 = t10*t20 + t25*t6;
    const V t35 = t18*t34 + t24*t32 + t28*t33;
    const V t36 = t30 + t8;
    const V t37 = t36*t15 + T(1);
    const V t38 = t10*t15;
    const V t39 = t38*t19 + t20*t6;
    const V t40 = t15*t9;
    const V t41 = t40*t6 + t20*t19;
    const V t42 = t18*t39 + t24*t41 + t28*t37;
    const V t43 = in[0]*in[16] + in[3]*in[19] + in[6]*in[22];
    const V t44 = t43;
    const V t45 = in[1]*in[16] + in[4]*in[19] + in[7]*in[22];
    const V t46 = t45;
    const V t47 = in[2]*in[16] + in[5]*in[19] + in[8]*in[22];
    const V t48 = t47;
    const V t49 = t16*t44 + t22*t46 + t26*t48;
    const V t50 = t32*t46 + t33*t48 + t34*t44;
    const V t51 = t37*t48 + t39*t44 + t41*t46;
    const V t52 = in[0]*in[17] + in[3]*in[20] + in[6]*in[23];
    const V t53 = t52;
    const V t54 = in[1]*in[17] + in[4]*in[20] + in[7]*in[23];
    const V t55 = t54;
    const V t56 = in[2]*in[17] + in[5]*in[20] + in[8]*in[23];
    const V t57 = t56;
    const V t58 = t16*t53 + t22*t55 + t26*t57;
    const V t59 = t32*t55 + t33*t57 + t34*t53;
    const V t60 = t37*t57 + t39*t53 + t41*t55;
    V tlog0[3]; v_so3_log(t29, t35, t42, t49, t50, t51, t58, t59, t60, tlog0);
    const V t61 = tlog0[1];
    const V t62 = (t61*t61);
    const V t63 = t62;
    const V t64 = tlog0[2];
    const V t65 = (t64*t64);
    const V t66 = t65;
    const V t67 = t63 + t66;
    const V t68 = tlog0[0];
    const V t69 = (t68*t68);
    const V t70 = t69;
    const V t71 = t67 + t70;
    const V t72 = v_lie_D(t71);
    const V t73 = -t67*t72 + T(1);
    const V t74 = t0*dat[18] + t1*dat[19] + t2*dat[20] + t3*dat[45] + t4*dat[46] + t5*dat[47] + dat[3];
    const V t75 = t0*dat[21] + t1*dat[22] + t2*dat[23] + t3*dat[48] + t4*dat[49] + t5*dat[50] + dat[4];
    const V t76 = t0*dat[24] + t1*dat[25] + t2*dat[26] + t3*dat[51] + t4*dat[52] + t5*dat[53] + dat[5];
    const V t77 = (T(0.5))*(dat[69]*dat[69]);
    const V t78 = t74*in[0] + t75*in[1] + t76*in[2] + t77*dat[70] + dat[69]*in[12] + in[9] - in[24];
    const V t79 = t74*in[3] + t75*in[4] + t76*in[5] + t77*dat[71] + dat[69]*in[13] + in[10] - in[25];
    const V t80 = t74*in[6] + t75*in[7] + t76*in[8] + t77*dat[72] + dat[69]*in[14] + in[11] - in[26];
    const V t81 = t78*in[15] + t79*in[18] + t80*in[21];
    const V t82 = t81;
    const V t83 = (T(0.5))*t64;
    const V t84 = t83;
    const V t85 = t68*t72;
    const V t86 = t61*t85;
    const V t87 = t84 + t86;
    const V t88 = t78*in[16] + t79*in[19] + t80*in[22];
    const V t89 = t88;
    const V t90 = (T(0.5))*t61;
    const V t91 = t90;
    const V t92 = t64*t85;
    const V t93 = -t91 + t92;
    const V t94 = t78*in[17] + t79*in[20] + t80*in[23];
    const V t95 = t94;
    const V t96 = t73*t82 + t87*t89 + t93*t95;
    const V t97 = -t66 - t70;
    const V t98 = t97*t72 + T(1);
    const V t99 = (T(0.5))*t68;
    const V t100 = t99;
    const V t101 = t61*t64;
    const V t102 = t101*t72;
    const V t103 = t100 + t102;
    const V t104 = -t84 + t86;
    const V t105 = t82*t104 + t89*t98 + t95*t103;
    const V t106 = -t63 - t70;
    const V t107 = t106*t72 + T(1);
    const V t108 = t91 + t92;
    const V t109 = -t100 + t102;
    const V t110 = t82*t108 + t89*t109 + t95*t107;
    const V t111 = t0*dat[27] + t1*dat[28] + t2*dat[29] + t3*dat[54] + t4*dat[55] + t5*dat[56] + dat[6];
    const V t112 = t0*dat[30] + t1*dat[31] + t2*dat[32] + t3*dat[57] + t4*dat[58] + t5*dat[59] + dat[7];
    const V t113 = t0*dat[33] + t1*dat[34] + t2*dat[35] + t3*dat[60] + t4*dat[61] + t5*dat[62] + dat[8];
    const V t114 = t111*in[0] + t112*in[1] + t113*in[2] + dat[69]*dat[70] + in[12] - in[27];
    const V t115 = t111*in[3] + t112*in[4] + t113*in[5] + dat[69]*dat[71] + in[13] - in[28];
    const V t116 = t111*in[6] + t112*in[7] + t113*in[8] + dat[69]*dat[72] + in[14] - in[29];
    const V t117 = t114*in[15] + t115*in[18] + t116*in[21];
    const V t118 = t117;
    const V t119 = t114*in[16] + t115*in[19] + t116*in[22];
    const V t120 = t119;
    const V t121 = t114*in[17] + t115*in[20] + t116*in[23];
    const V t122 = t121;
    const V t123 = t73*t118 + t87*t120 + t93*t122;
    const V t124 = t98*t120 + t103*t122 + t104*t118;
    const V t125 = t107*t122 + t108*t118 + t109*t120;
    const V t126 = in[30] - in[36];
    const V t127 = in[31] - in[37];
    const V t128 = in[32] - in[38];
    const V t129 = in[33] - in[39];
    const V t130 = in[34] - in[40];
    const V t131 = in[35] - in[41];
    const V t132 = (T(0.5))*(t131*t131)*(dat[192]*dat[192]) + (T(0.5))*((t130*dat[190] + t131*dat[191])*(t130*dat[190] + t131*dat[191])) + (T(0.5))*((t129*dat[187] + t130*dat[188] + t131*dat[189])*(t129*dat[187] + t130*dat[188] + t131*dat[189])) + (T(0.5))*((t129*dat[184] + t130*dat[185] + t131*dat[186] + t128*dat[183])*(t129*dat[184] + t130*dat[185] + t131*dat[186] + t128*dat[183])) + (T(0.5))*((t129*dat[180] + t130*dat[181] + t131*dat[182] + t127*dat[178] + t128*dat[179])*(t129*dat[180] + t130*dat[181] + t131*dat[182] + t127*dat[178] + t128*dat[179])) + (T(0.5))*((t129*dat[175] + t130*dat[176] + t131*dat[177] + t126*dat[172] + t127*dat[173] + t128*dat[174])*(t129*dat[175] + t130*dat[176] + t131*dat[177] + t126*dat[172] + t127*dat[173] + t128*dat[174])) + (T(0.5))*((t129*dat[169] + t130*dat[170] + t131*dat[171] + t125*dat[165] + t126*dat[166] + t127*dat[167] + t128*dat[168])*(t129*dat[169] + t130*dat[170] + t131*dat[171] + t125*dat[165] + t126*dat[166] + t127*dat[167] + t128*dat[168])) + (T(0.5))*((t129*dat[162] + t130*dat[163] + t131*dat[164] + t124*dat[157] + t125*dat[158] + t126*dat[159] + t127*dat[160] + t128*dat[161])*(t129*dat[162] + t130*dat[163] + t131*dat[164] + t124*dat[157] + t125*dat[158] + t126*dat[159] + t127*dat[160] + t128*dat[161])) + (T(0.5))*((t129*dat[154] + t130*dat[155] + t131*dat[156] + t123*dat[148] + t124*dat[149] + t125*dat[150] + t126*dat[151] + t127*dat[152] + t128*dat[153])*(t129*dat[154] + t130*dat[155] + t131*dat[156] + t123*dat[148] + t124*dat[149] + t125*dat[150] + t126*dat[151] + t127*dat[152] + t128*dat[153])) + (T(0.5))*((t129*dat[145] + t130*dat[146] + t131*dat[147] + t110*dat[138] + t123*dat[139] + t124*dat[140] + t125*dat[141] + t126*dat[142] + t127*dat[143] + t128*dat[144])*(t129*dat[145] + t130*dat[146] + t131*dat[147] + t110*dat[138] + t123*dat[139] + t124*dat[140] + t125*dat[141] + t126*dat[142] + t127*dat[143] + t128*dat[144])) + (T(0.5))*((t105*dat[127] + t129*dat[135] + t130*dat[136] + t131*dat[137] + t110*dat[128] + t123*dat[129] + t124*dat[130] + t125*dat[131] + t126*dat[132] + t127*dat[133] + t128*dat[134])*(t105*dat[127] + t129*dat[135] + t130*dat[136] + t131*dat[137] + t110*dat[128] + t123*dat[129] + t124*dat[130] + t125*dat[131] + t126*dat[132] + t127*dat[133] + t128*dat[134])) + (T(0.5))*((t96*dat[115] + t105*dat[116] + t129*dat[124] + t130*dat[125] + t131*dat[126] + t110*dat[117] + t123*dat[118] + t124*dat[119] + t125*dat[120] + t126*dat[121] + t127*dat[122] + t128*dat[123])*(t96*dat[115] + t105*dat[116] + t129*dat[124] + t130*dat[125] + t131*dat[126] + t110*dat[117] + t123*dat[118] + t124*dat[119] + t125*dat[120] + t126*dat[121] + t127*dat[122] + t128*dat[123])) + (T(0.5))*((t96*dat[103] + t105*dat[104] + t129*dat[112] + t130*dat[113] + t131*dat[114] + t110*dat[105] + t123*dat[106] + t124*dat[107] + t125*dat[108] + t126*dat[109] + t127*dat[110] + t128*dat[111] + t64*dat[102])*(t96*dat[103] + t105*dat[104] + t129*dat[112] + t130*dat[113] + t131*dat[114] + t110*dat[105] + t123*dat[106] + t124*dat[107] + t125*dat[108] + t126*dat[109] + t127*dat[110] + t128*dat[111] + t64*dat[102])) + (T(0.5))*((t96*dat[90] + t105*dat[91] + t129*dat[99] + t130*dat[100] + t131*dat[101] + t110*dat[92] + t123*dat[93] + t124*dat[94] + t125*dat[95] + t126*dat[96] + t127*dat[97] + t128*dat[98] + t61*dat[88] + t64*dat[89])*(t96*dat[90] + t105*dat[91] + t129*dat[99] + t130*dat[100] + t131*dat[101] + t110*dat[92] + t123*dat[93] + t124*dat[94] + t125*dat[95] + t126*dat[96] + t127*dat[97] + t128*dat[98] + t61*dat[88] + t64*dat[89])) + (T(0.5))*((t96*dat[76] + t105*dat[77] + t129*dat[85] + t130*dat[86] + t131*dat[87] + t110*dat[78] + t123*dat[79] + t124*dat[80] + t125*dat[81] + t126*dat[82] + t127*dat[83] + t128*dat[84] + t68*dat[73] + t61*dat[74] + t64*dat[75])*(t96*dat[76] + t105*dat[77] + t129*dat[85] + t130*dat[86] + t131*dat[87] + t110*dat[78] + t123*dat[79] + t124*dat[80] + t125*dat[81] + t126*dat[82] + t127*dat[83] + t128*dat[84] + t68*dat[73] + t61*dat[74] + t64*dat[75]));
    const V o0 = t132;
    for (int l = 0; l < LANES; ++l) {
        half[l][0] = lane(o0, l);
    }
}

// block 1: PriorFactorPose3 (6 rows, 6 columns, 1 instances)
void jacobian_1(const V* in, const V* dat, T ab[LANES][48]) {
#pragma HLS PIPELINE II=1
    const V t0 = dat[0]*in[0] + dat[3]*in[3] + dat[6]*in[6];
    const V t1 = dat[0]*in[2] + dat[3]*in[5] + dat[6]*in[8];
    const V t2 = dat[0]*in[1] + dat[3]*in[4] + dat[6]*in[7];
    const V t3 = dat[1]*in[0] + dat[4]*in[3] + dat[7]*in[6];
    const V t4 = dat[1]*in[2] + dat[4]*in[5] + dat[7]*in[8];
    const V t5 = dat[1]*in[1] + dat[4]*in[4] + dat[7]*in[7];
    const V t6 = dat[2]*in[0] + dat[5]*in[3] + dat[8]*in[6];
    const V t7 = dat[2]*in[2] + dat[5]*in[5] + dat[8]*in[8];
    const V t8 = dat[2]*in[1] + dat[5]*in[4] + dat[8]*in[7];
    const V t9 = t0;
    const V t10 = t2;
    const V t11 = t1;
    const V t12 = t3;
    const V t13 = t5;
    const V t14 = t4;
    const V t15 = t6;
    const V t16 = t8;
    const V t17 = t7;
    V tlog0[3]; v_so3_log(t9, t10, t11, t12, t13, t14, t15, t16, t17, tlog0);
    const V t18 = tlog0[2];
    const V t19 = (T(0.5))*t18;
    const V t20 = tlog0[0];
    const V t21 = (t20*t20);
    const V t22 = tlog0[1];
    const V t23 = (t22*t22);
    const V t24 = (t18*t18);
    const V t25 = t23 + t24;
    const V t26 = v_lie_D(t21 + t25);
    const V t27 = t26*t20;
    const V t28 = t27*t22;
    const V t29 = (T(0.5))*t28 - T(0.5)*t19;
    const V t30 = -t25*t26 + T(1);
    const V t31 = (T(0.5))*t30;
    const V t32 = t29*t12 - t31*t13;
    const V t33 = (T(0.5))*t22;
    const V t34 = (T(0.5))*t27*t18 + (T(0.5))*t33;
    const V t35 = (T(0.5))*t30*t17 - t34*t15;
    const V t36 = t29*t15 - t31*t16;
    const V t37 = (T(0.5))*t30*t11 - t34*t9;
    const V t38 = t29*t9 - t31*t10;
    const V t39 = (T(0.5))*t30*t14 - t34*t12;
    const V t40 = -t29*t11 + t34*t10;
    const V t41 = -t29*t17 + t34*t16;
    const V t42 = -t29*t14 + t34*t13;
    const V t43 = (T(0.5))*t26*(-t21 - t24) + T(0.5);
    const V t44 = t28 + t19;
    const V t45 = (T(0.5))*t44;
    const V t46 = t43*t12 - t45*t13;
    const V t47 = (T(0.5))*t20;
    const V t48 = t22*t18;
    const V t49 = t26*t48;
    const V t50 = -T(0.5)*t47 + (T(0.5))*t49;
    const V t51 = (T(0.5))*t44*t17 - t50*t15;
    const V t52 = t43*t15 - t45*t16;
    const V t53 = (T(0.5))*t44*t11 - t50*t9;
    const V t54 = t43*t9 - t45*t10;
    const V t55 = (T(0.5))*t44*t14 - t50*t12;
    const V t56 = -t43*t11 + t50*t10;
    const V t57 = -t43*t17 + t50*t16;
    const V t58 = -t43*t14 + t50*t13;
    const V t59 = (T(0.5))*t47 + (T(0.5))*t49;
    const V t60 = t26*t18*t20 - t33;
    const V t61 = (T(0.5))*t60;
    const V t62 = t59*t12 - t61*t13;
    const V t63 = (T(0.5))*t26*(-t21 - t23) + T(0.5);
    const V t64 = (T(0.5))*t60*t17 - t63*t15;
    const V t65 = t59*t15 - t61*t16;
    const V t66 = (T(0.5))*t60*t11 - t63*t9;
    const V t67 = t59*t9 - t61*t10;
    const V t68 = (T(0.5))*t60*t14 - t63*t12;
    const V t69 = -t59*t11 + t63*t10;
    const V t70 = -t59*t17 + t63*t16;
    const V t71 = -t59*t14 + t63*t13;
    const V t72 = T(2)*t22;
    const V t73 = T(2)*t18;
    const V t74 = T(2)*t20;
    const V t75 = t23;
    const V t76 = t24;
    const V t77 = t75 + t76;
    const V t78 = t21;
    const V t79 = t77 + t78;
    const V t80 = v_lie_D1(t79);
    const V t81 = v_lie_D(t79);
    const V t82 = t22*t81;
    const V t83 = t18*t81;
    const V t84 = -t77*t81 + T(1);
    const V t85 = t19;
    const V t86 = t81*t20;
    const V t87 = t22*t86;
    const V t88 = t85 + t87;
    const V t89 = t33;
    const V t90 = t18*t86;
    const V t91 = -t89 + t90;
    const V t92 = -t85 + t87;
    const V t93 = -t76 - t78;
    const V t94 = t93*t81 + T(1);
    const V t95 = t47;
    const V t96 = t48*t81;
    const V t97 = t95 + t96;
    const V t98 = t89 + t90;
    const V t99 = -t95 + t96;
    const V t100 = -t75 - t78;
    const V t101 = t100*t81 + T(1);
    const V t102 = -dat[0]*dat[9] + dat[0]*in[9] - dat[3]*dat[10] + dat[3]*in[10] - dat[6]*dat[11] + dat[6]*in[11];
    const V t103 = t77*t102;
    const V t104 = t81*t102;
    const V t105 = -dat[1]*dat[9] + dat[1]*in[9] - dat[4]*dat[10] + dat[4]*in[10] - dat[7]*dat[11] + dat[7]*in[11];
    const V t106 = t93*t105;
    const V t107 = t81*t105;
    const V t108 = -dat[2]*dat[9] + dat[2]*in[9] - dat[5]*dat[10] + dat[5]*in[10] - dat[8]*dat[11] + dat[8]*in[11];
    const V t109 = t100*t108;
    const V t110 = t81*t108;
    const V t111 = -t1;
    const V t112 = t2;
    const V t113 = t1;
    const V t114 = -t0;
    const V t115 = -t2;
    const V t116 = t0;
    const V t117 = -t4;
    const V t118 = t5;
    const V t119 = t4;
    const V t120 = -t3;
    const V t121 = -t5;
    const V t122 = t3;
    const V t123 = -t7;
    const V t124 = t8;
    const V t125 = t7;
    const V t126 = -t6;
    const V t127 = -t8;
    const V t128 = t6;
    const V t129 = t32*t121 + t35*t125 + t36*t127 + t37*t113 + t38*t115 + t39*t119;
    const V t130 = t32*t122 + t36*t128 + t38*t116 + t40*t111 + t41*t123 + t42*t117;
    const V t131 = t35*t126 + t37*t114 + t39*t120 + t40*t112 + t41*t124 + t42*t118;
    const V t132 = t46*t121 + t51*t125 + t52*t127 + t53*t113 + t54*t115 + t55*t119;
    const V t133 = t46*t122 + t52*t128 + t54*t116 + t56*t111 + t57*t123 + t58*t117;
    const V t134 = t51*t126 + t53*t114 + t55*t120 + t56*t112 + t57*t124 + t58*t118;
    const V t135 = t62*t121 + t64*t125 + t65*t127 + t66*t113 + t67*t115 + t68*t119;
    const V t136 = t62*t122 + t65*t128 + t67*t116 + t69*t111 + t70*t123 + t71*t117;
    const V t137 = t64*t126 + t66*t114 + t68*t120 + t69*t112 + t70*t124 + t71*t118;
    const V t138 = t72*t132;
    const V t139 = t72*t133;
    const V t140 = t72*t134;
    const V t141 = t73*t135;
    const V t142 = t73*t136;
    const V t143 = t73*t137;
    const V t144 = t138 + t141;
    const V t145 = t139 + t142;
    const V t146 = t140 + t143;
    const V t147 = t74*t129;
    const V t148 = t74*t130;
    const V t149 = t74*t131;
    const V t150 = t80*t144 + t80*t147;
    const V t151 = t80*t145 + t80*t148;
    const V t152 = t80*t146 + t80*t149;
    const V t153 = t0;
    const V t154 = t2;
    const V t155 = t1;
    const V t156 = (T(0.5))*t135;
    const V t157 = (T(0.5))*t136;
    const V t158 = (T(0.5))*t137;
    const V t159 = t81*t129 + t20*t150;
    const V t160 = t81*t130 + t20*t151;
    const V t161 = t81*t131 + t20*t152;
    const V t162 = t22*t159 + t86*t132;
    const V t163 = t22*t160 + t86*t133;
    const V t164 = t22*t161 + t86*t134;
    const V t165 = t3;
    const V t166 = t5;
    const V t167 = t4;
    const V t168 = (T(0.5))*t132;
    const V t169 = (T(0.5))*t133;
    const V t170 = (T(0.5))*t134;
    const V t171 = t18*t159 + t86*t135;
    const V t172 = t18*t160 + t86*t136;
    const V t173 = t18*t161 + t86*t137;
    const V t174 = t6;
    const V t175 = t8;
    const V t176 = t7;
    const V t177 = (T(0.5))*t129;
    const V t178 = (T(0.5))*t130;
    const V t179 = (T(0.5))*t131;
    const V t180 = t48*t150 + t82*t135 + t83*t132;
    const V t181 = t48*t151 + t82*t136 + t83*t133;
    const V t182 = t48*t152 + t82*t137 + t83*t134;
    // every output once, as a whole V, before it is taken apart lane by lane
    const V o0 = t129;
    const V o1 = t130;
    const V o2 = t131;
    const V o3 = t20;
    const V o4 = t132;
    const V o5 = t133;
    const V o6 = t134;
    const V o7 = t22;
    const V o8 = t135;
    const V o9 = t136;
    const V o10 = t137;
    const V o11 = t18;
    const V o12 = -t103*t150 - t104*t144 + t105*t156 + t105*t162 - t108*t168 + t108*t171;
    const V o13 = -t103*t151 - t104*t145 + t105*t157 + t105*t163 - t108*t169 + t108*t172;
    const V o14 = -t103*t152 - t104*t146 + t105*t158 + t105*t164 - t108*t170 + t108*t173;
    const V o15 = t84*t153 + t88*t165 + t91*t174;
    const V o16 = t84*t154 + t88*t166 + t91*t175;
    const V o17 = t84*t155 + t88*t167 + t91*t176;
    const V o18 = t84*t102 + t88*t105 + t91*t108;
    const V o19 = t106*t150 - t107*t141 - t107*t147 - t102*t156 + t102*t162 + t108*t177 + t108*t180;
    const V o20 = t106*t151 - t107*t142 - t107*t148 - t102*t157 + t102*t163 + t108*t178 + t108*t181;
    const V o21 = t106*t152 - t107*t143 - t107*t149 - t102*t158 + t102*t164 + t108*t179 + t108*t182;
    const V o22 = t92*t153 + t94*t165 + t97*t174;
    const V o23 = t92*t154 + t94*t166 + t97*t175;
    const V o24 = t92*t155 + t94*t167 + t97*t176;
    const V o25 = t92*t102 + t94*t105 + t97*t108;
    const V o26 = t109*t150 - t110*t138 - t110*t147 + t102*t168 + t102*t171 - t105*t177 + t105*t180;
    const V o27 = t109*t151 - t110*t139 - t110*t148 + t102*t169 + t102*t172 - t105*t178 + t105*t181;
    const V o28 = t109*t152 - t110*t140 - t110*t149 + t102*t170 + t102*t173 - t105*t179 + t105*t182;
    const V o29 = t98*t153 + t99*t165 + t101*t174;
    const V o30 = t98*t154 + t99*t166 + t101*t175;
    const V o31 = t98*t155 + t99*t167 + t101*t176;
    const V o32 = t98*t102 + t99*t105 + t101*t108;
    for (int l = 0; l < LANES; ++l) {
        ab[l][0] = lane(o0, l);
        ab[l][1] = lane(o1, l);
        ab[l][2] = lane(o2, l);
        ab[l][6] = lane(o3, l);
        ab[l][8] = lane(o4, l);
        ab[l][9] = lane(o5, l);
        ab[l][10] = lane(o6, l);
        ab[l][14] = lane(o7, l);
        ab[l][16] = lane(o8, l);
        ab[l][17] = lane(o9, l);
        ab[l][18] = lane(o10, l);
        ab[l][22] = lane(o11, l);
        ab[l][24] = lane(o12, l);
        ab[l][25] = lane(o13, l);
        ab[l][26] = lane(o14, l);
        ab[l][27] = lane(o15, l);
        ab[l][28] = lane(o16, l);
        ab[l][29] = lane(o17, l);
        ab[l][30] = lane(o18, l);
        ab[l][32] = lane(o19, l);
        ab[l][33] = lane(o20, l);
        ab[l][34] = lane(o21, l);
        ab[l][35] = lane(o22, l);
        ab[l][36] = lane(o23, l);
        ab[l][37] = lane(o24, l);
        ab[l][38] = lane(o25, l);
        ab[l][40] = lane(o26, l);
        ab[l][41] = lane(o27, l);
        ab[l][42] = lane(o28, l);
        ab[l][43] = lane(o29, l);
        ab[l][44] = lane(o30, l);
        ab[l][45] = lane(o31, l);
        ab[l][46] = lane(o32, l);
    }
}

void cost_1(const V* in, const V* dat, T half[LANES][1]) {
#pragma HLS PIPELINE II=1
    const V t0 = dat[0]*in[0] + dat[3]*in[3] + dat[6]*in[6];
    const V t1 = t0;
    const V t2 = dat[0]*in[1] + dat[3]*in[4] + dat[6]*in[7];
    const V t3 = t2;
    const V t4 = dat[0]*in[2] + dat[3]*in[5] + dat[6]*in[8];
    const V t5 = t4;
    const V t6 = dat[1]*in[0] + dat[4]*in[3] + dat[7]*in[6];
    const V t7 = t6;
    const V t8 = dat[1]*in[1] + dat[4]*in[4] + dat[7]*in[7];
    const V t9 = t8;
    const V t10 = dat[1]*in[2] + dat[4]*in[5] + dat[7]*in[8];
    const V t11 = t10;
    const V t12 = dat[2]*in[0] + dat[5]*in[3] + dat[8]*in[6];
    const V t13 = t12;
    const V t14 = dat[2]*in[1] + dat[5]*in[4] + dat[8]*in[7];
    const V t15 = t14;
    const V t16 = dat[2]*in[2] + dat[5]*in[5] + dat[8]*in[8];
    const V t17 = t16;
    V tlog0[3]; v_so3_log(t1, t3, t5, t7, t9, t11, t13, t15, t17, tlog0);
    const V t18 = tlog0[0];
    const V t19 = (t18*t18);
    const V t20 = tlog0[1];
    const V t21 = (t20*t20);
    const V t22 = tlog0[2];
    const V t23 = (t22*t22);
    const V t24 = t21;
    const V t25 = t24;
    const V t26 = t23;
    const V t27 = t26;
    const V t28 = t25 + t27;
    const V t29 = t19;
    const V t30 = t29;
    const V t31 = t28 + t30;
    const V t32 = v_lie_D(t31);
    const V t33 = -t28*t32 + T(1);
    const V t34 = (T(0.5))*t22;
    const V t35 = t34;
    const V t36 = t32*t18;
    const V t37 = t20*t36;
    const V t38 = t35 + t37;
    const V t39 = (T(0.5))*t20;
    const V t40 = t39;
    const V t41 = t22*t36;
    const V t42 = -t40 + t41;
    const V t43 = -dat[0]*dat[9] + dat[0]*in[9] - dat[3]*dat[10] + dat[3]*in[10] - dat[6]*dat[11] + dat[6]*in[11];
    const V t44 = -dat[1]*dat[9] + dat[1]*in[9] - dat[4]*dat[10] + dat[4]*in[10] - dat[7]*dat[11] + dat[7]*in[11];
    const V t45 = -dat[2]*dat[9] + dat[2]*in[9] - dat[5]*dat[10] + dat[5]*in[10] - dat[8]*dat[11] + dat[8]*in[11];
    const V t46 = t33*t43 + t38*t44 + t42*t45;
    const V t47 = -t35 + t37;
    const V t48 = -t27 - t30;
    const V t49 = t48*t32 + T(1);
    const V t50 = (T(0.5))*t18;
    const V t51 = t50;
    const V t52 = t20*t22;
    const V t53 = t52*t32;
    const V t54 = t51 + t53;
    const V t55 = t47*t43 + t49*t44 + t54*t45;
    const V t56 = t40 + t41;
    const V t57 = -t51 + t53;
    const V t58 = -t25 - t30;
    const V t59 = t58*t32 + T(1);
    const V t60 = t56*t43 + t57*t44 + t59*t45;
    const V t61 = (T(0.5))*(dat[12]*dat[12]);
    const V t62 = t19*t61 + t21*t61 + t23*t61 + (t46*t46)*t61 + (t55*t55)*t61 + (t60*t60)*t61;
    const V o0 = t62;
    for (int l = 0; l < LANES; ++l) {
        half[l][0] = lane(o0, l);
    }
}

// block 2: PriorFactorVector3 (3 rows, 3 columns, 1 instances)
void jacobian_2(const V* in, const V* dat, T ab[LANES][12]) {
#pragma HLS PIPELINE II=1
    // every output once, as a whole V, before it is taken apart lane by lane
    const V o1 = -dat[0] + in[0];
    const V o3 = -dat[1] + in[1];
    const V o5 = -dat[2] + in[2];
    for (int l = 0; l < LANES; ++l) {
        ab[l][0] = T(1);
        ab[l][3] = lane(o1, l);
        ab[l][5] = T(1);
        ab[l][7] = lane(o3, l);
        ab[l][10] = T(1);
        ab[l][11] = lane(o5, l);
    }
}

void cost_2(const V* in, const V* dat, T half[LANES][1]) {
#pragma HLS PIPELINE II=1
    const V t0 = -dat[0] + in[0];
    const V t1 = -dat[1] + in[1];
    const V t2 = -dat[2] + in[2];
    const V t3 = (T(0.5))*(dat[3]*dat[3]);
    const V t4 = (t0*t0)*t3 + (t1*t1)*t3 + (t2*t2)*t3;
    const V o0 = t4;
    for (int l = 0; l < LANES; ++l) {
        half[l][0] = lane(o0, l);
    }
}

// block 3: PriorFactorImuBias (6 rows, 6 columns, 1 instances)
void jacobian_3(const V* in, const V* dat, T ab[LANES][48]) {
#pragma HLS PIPELINE II=1
    // every output once, as a whole V, before it is taken apart lane by lane
    const V o1 = -dat[0] + in[0];
    const V o3 = -dat[1] + in[1];
    const V o5 = -dat[2] + in[2];
    const V o7 = -dat[3] + in[3];
    const V o9 = -dat[4] + in[4];
    const V o11 = -dat[5] + in[5];
    for (int l = 0; l < LANES; ++l) {
        ab[l][0] = T(1);
        ab[l][6] = lane(o1, l);
        ab[l][9] = T(1);
        ab[l][14] = lane(o3, l);
        ab[l][18] = T(1);
        ab[l][22] = lane(o5, l);
        ab[l][27] = T(1);
        ab[l][30] = lane(o7, l);
        ab[l][36] = T(1);
        ab[l][38] = lane(o9, l);
        ab[l][45] = T(1);
        ab[l][46] = lane(o11, l);
    }
}

void cost_3(const V* in, const V* dat, T half[LANES][1]) {
#pragma HLS PIPELINE II=1
    const V t0 = -dat[0] + in[0];
    const V t1 = -dat[1] + in[1];
    const V t2 = -dat[2] + in[2];
    const V t3 = -dat[3] + in[3];
    const V t4 = -dat[4] + in[4];
    const V t5 = -dat[5] + in[5];
    const V t6 = (T(0.5))*(dat[6]*dat[6]);
    const V t7 = (t0*t0)*t6 + (t1*t1)*t6 + (t2*t2)*t6 + (t3*t3)*t6 + (t4*t4)*t6 + (t5*t5)*t6;
    const V o0 = t7;
    for (int l = 0; l < LANES; ++l) {
        half[l][0] = lane(o0, l);
    }
}

// Rows [J | r] of one member (row stride STRIDE, right-hand side in column COLS - 1) ->
// W * [J | -r] in `ab`: W is 1/sigma (KIND 0), 1/sigma_i (1) or the upper-triangular
// square-root information R (2, parameters row-major). Every entry of `ab` is written (so it
// needs no zeroing) and `raw` keeps its structural zeros; rows are whitened whole: a short
// fixed-length vector loop per row. KIND 2 sums only rows j < DENSE so: the rows after hold
// just 0 and ±1 left of the right-hand side, and the member's whiten_tail adds their share
// (R_ij itself at their constant entries, then R_ij b_j), after this and in the same row order,
// so every entry is the same sum as over whole rows.
template <int STRIDE, int COLS, int ROWS, int KIND, int DENSE>
void whiten(T* raw, T* ab, const T* p) {
    for (int i = 0; i < ROWS; ++i) raw[i * STRIDE + COLS - 1] = -raw[i * STRIDE + COLS - 1];
    for (int i = 0; i < ROWS; ++i) {
        const T* row = raw + i * STRIDE;
        T* out = ab + i * STRIDE;
        if (KIND == 2) {  // row i = sum over j >= i of R_ij row j
            const int base = i * ROWS - (i * (i - 1)) / 2 - i;
            T acc[STRIDE];
            if (i < DENSE) {
                for (int c = 0; c < STRIDE; ++c) acc[c] = row[c] * p[base + i];
            } else {
                for (int c = 0; c < STRIDE; ++c) acc[c] = T(0);
            }
            for (int j = i + 1; j < DENSE; ++j) {
                const T rij = p[base + j];
                const T* other = raw + j * STRIDE;
                for (int c = 0; c < STRIDE; ++c) acc[c] += rij * other[c];
            }
            for (int c = 0; c < STRIDE; ++c) out[c] = acc[c];
        } else {
            const T s = KIND == 1 ? p[i] : p[0];
            for (int c = 0; c < STRIDE; ++c) out[c] = row[c] * s;
        }
    }
}

// sqrt(w) * the whitened rows of one member: w reweights a robust loss (CODE 1 Huber, 2 Cauchy)
// at the whitened residual norm, as GTSAM does.
template <int STRIDE, int COLS, int ROWS>
void reweight(T ab[], T code, T k) {
    if (code == T(0)) return;
    T e2 = T(0);
    for (int i = 0; i < ROWS; ++i) e2 += ab[i * STRIDE + COLS - 1] * ab[i * STRIDE + COLS - 1];
    const T e = fgc_sqrt(e2);
    const T w = code == T(1) ? (e <= k ? T(1) : T(k / e)) : T(k * k / (k * k + e * e));
    const T s = fgc_sqrt(w);
    for (int i = 0; i < ROWS * STRIDE; ++i) ab[i] *= s;
}

// The cost's rounding noise: row r of whitened [A | b] (ROWS of STRIDE, b in column COLS - 1)
// moves by up to m_r = eps * sum_c |A_rc| scale_c when x is rounded to T, so the cost by
// |b_r| m_r + m_r^2 / 2. Each row's sum in TILE partial sums, then the rows' terms in TILE
// partial sums: a fixed order, and no chain from row to row.
template <int STRIDE, int COLS, int ROWS>
T rounding_noise(const T* ab, const T scale[STRIDE]) {
    T moved[ROWS], b_abs[ROWS];
    for (int r = 0; r < ROWS; ++r) {
        const T* row = ab + r * STRIDE;
        T part[TILE];
        for (int t = 0; t < TILE; ++t) part[t] = T(0);
        for (int c0 = 0; c0 < STRIDE; c0 += TILE) {
            for (int t = 0; t < TILE; ++t) part[t] += fgc_abs(row[c0 + t]) * scale[c0 + t];
        }
        moved[r] = EPSILON * ((part[0] + part[1]) + (part[2] + part[3]));  // scale 0: b, padding
        b_abs[r] = fgc_abs(row[COLS - 1]);
    }
    T sum[TILE];
    for (int t = 0; t < TILE; ++t) sum[t] = T(0);
    for (int r0 = 0; r0 < ROWS; r0 += TILE) {
        for (int t = 0; t < TILE; ++t) {
            if (r0 + t < ROWS) {
                const T m = moved[r0 + t];
                sum[t] += b_abs[r0 + t] * m + T(0.5) * m * m;
            }
        }
    }
    return (sum[0] + sum[1]) + (sum[2] + sum[3]);
}


// One panel of WIDE tiles side by side: rows p0 ... p0 + TILE - 1, columns q0 ... q0 + WIDE TILE - 1
// of the square buffer, summed over the n rows rows[0 ... n) in order. A function of constant
// width, left to GCC to inline or not: faster than one loop body per width inside gram (5-7 %
// at LIO N=30 and N=200; forced inline, 5 % at N=30 but 8 % slower at N=200)
template <int STRIDE, int ROWS, int WIDE>
inline void gram_panel(const T* ab, const int* rows, int n, int p0, int q0, L* sq) {
    L acc[TILE][WIDE * TILE];  // the linear solver's scalar: the HGC accumulates in it
#pragma HLS ARRAY_PARTITION variable=acc complete dim=0
    for (int i = 0; i < TILE; ++i) {
        for (int j = 0; j < WIDE * TILE; ++j) acc[i][j] = L(0);
    }
    for (int k = 0; k < n; ++k) {
#pragma HLS LOOP_TRIPCOUNT max=ROWS
#pragma HLS PIPELINE
        const T* row = ab + rows[k] * STRIDE;
        for (int i = 0; i < TILE; ++i) {
            const L ap = row[p0 + i];
            for (int j = 0; j < WIDE * TILE; ++j) acc[i][j] += ap * L(row[q0 + j]);
        }
    }
    for (int i = 0; i < TILE; ++i) {
        for (int j = 0; j < WIDE * TILE; ++j) sq[(p0 + i) * STRIDE + q0 + j] = acc[i][j];
    }
}

// HGC (paper B): the packed lower triangle of [A | b]^T [A | b] (entry (p, q), q <= p < COLS, at
// p (p + 1) / 2 + q) of rows of STRIDE. The block's non-zero TILE x TILE tiles come in panels
// (p0, q0, first, n, tiles in `tiles`) of one tile or two side by side; each panel is summed over
// just the n rows that touch it (`rows[first ...]`), one row streamed through TILE x 2 TILE
// accumulators per cycle, into a square buffer (zeroed first unless every lower tile is summed);
// the lower triangle is then copied out row by row (tiles left out are structural zeros).
template <int STRIDE, int COLS, int ROWS, int PANELS, int TILES>
void gram(const T* ab, const int* tiles, const int* rows, L* out) {
    L sq[STRIDE * STRIDE];
    if (TILES < (STRIDE / TILE) * (STRIDE / TILE + 1) / 2) {  // else every lower tile is written
        for (int i = 0; i < STRIDE * STRIDE; ++i) sq[i] = L(0);
    }
    for (int t = 0; t < PANELS; ++t) {
        const int p0 = tiles[5 * t], q0 = tiles[5 * t + 1], first = tiles[5 * t + 2];
        const int n = tiles[5 * t + 3];
        if (tiles[5 * t + 4] == 2) {
            gram_panel<STRIDE, ROWS, 2>(ab, rows + first, n, p0, q0, sq);
        } else {
            gram_panel<STRIDE, ROWS, 1>(ab, rows + first, n, p0, q0, sq);
        }
    }
    // whole tiles per row: up to TILE - 1 entries past row p land in row p + 1, which is
    // written next (the last row, entry by entry, stays inside this instance's Gram)
    for (int p = 0; p < COLS - 1; ++p) {
        for (int q0 = 0; q0 <= p; q0 += TILE) {
#pragma HLS LOOP_TRIPCOUNT max=COLS
            for (int t = 0; t < TILE; ++t) out[p * (p + 1) / 2 + q0 + t] = sq[p * STRIDE + q0 + t];
        }
    }
    for (int q = 0; q < COLS; ++q) {
#pragma HLS LOOP_TRIPCOUNT max=COLS
        out[(COLS - 1) * COLS / 2 + q] = sq[(COLS - 1) * STRIDE + q];
    }
}

// From one instance's packed Gram of [A | b] (row COLS - 1 is b^T A, then b^T b): the local
// gradient A^T b (column c into G[col[c]]). False if the Gram is not finite: a NaN or infinity
// anywhere in [A | b] makes its column's diagonal entry one.
template <int COLS>
bool gradient_from_gram(const L* h, const int col[COLS - 1]) {
    const L* brow = h + (COLS - 1) * COLS / 2;
    for (int c = 0; c < COLS - 1; ++c) G[col[c]] += T(brow[c]);
    L check = L(0);
    for (int c = 0; c < COLS; ++c) check += h[c * (c + 1) / 2 + c];
    return fgc_isfinite(T(check));
}

// rho(e) at e = sqrt(2 half): the cost of one member (plain half when not robust).
T robust_loss(T half, T code, T k) {
    if (code == T(0)) return half;
    const T e = fgc_sqrt(T(2) * half);
    if (code == T(1)) return e <= k ? half : T(k * e - T(0.5) * k * k);
    return T(0.5) * k * k * fgc_log1p(e * e / (k * k));
}

#ifndef __SYNTHESIS__
// The data inputs (measurements, then noise parameters) of every LANES instances, laned once per
// call by lane_data(): they are the same in every iteration, so a gather only lanes x and the
// kernels read the data in place.
V BLOCK0_LANED[(7 + LANES - 1) / LANES][193];

void lane_data_0() {
    for (int first = 0; first < 7; first += LANES) {
        T laned[193][LANES];
        for (int l = 0; l < LANES; ++l) {
            const int f = BLOCK0_INSTANCES[first + l < 7 ? first + l : 6];
            const T* line = DATA_BUF + FACTOR_DATA_OFF[f];
            for (int i = 0; i < 73; ++i) laned[0 + i][l] = line[0 + i];
            for (int i = 0; i < 120; ++i) laned[73 + i][l] = line[73 + i];
        }
        for (int i = 0; i < 193; ++i) BLOCK0_LANED[first / LANES][i] = load_lanes(laned[i]);
    }
}
#endif

// The inputs of instances BLOCK0_INSTANCES[first ...] into the lanes (lanes past the last
// instance repeat it; their results are not used): x's storage into `in`; returns where the data
// inputs are (on the host the laned data, in hardware the rest of `in`).
const V* gather_0(const T* x, int first, bool cost, V in[235]) {
#ifndef __SYNTHESIS__
    T buf[42][LANES];
    for (int l = 0; l < LANES; ++l) {
        const int f = BLOCK0_INSTANCES[first + l < 7 ? first + l : 6];
        const int vb = FACTOR_VAR_BEGIN[f];
        for (int i = 0; i < 12; ++i) buf[0 + i][l] = x[VAR_X_OFF[FACTOR_VARS[vb + 0]] + i];
        for (int i = 0; i < 3; ++i) buf[12 + i][l] = x[VAR_X_OFF[FACTOR_VARS[vb + 1]] + i];
        for (int i = 0; i < 12; ++i) buf[15 + i][l] = x[VAR_X_OFF[FACTOR_VARS[vb + 2]] + i];
        for (int i = 0; i < 3; ++i) buf[27 + i][l] = x[VAR_X_OFF[FACTOR_VARS[vb + 3]] + i];
        for (int i = 0; i < 6; ++i) buf[30 + i][l] = x[VAR_X_OFF[FACTOR_VARS[vb + 4]] + i];
        for (int i = 0; i < 6; ++i) buf[36 + i][l] = x[VAR_X_OFF[FACTOR_VARS[vb + 5]] + i];
    }
    for (int i = 0; i < 42; ++i) in[i] = load_lanes(buf[i]);
    (void)cost;
    return BLOCK0_LANED[first / LANES];
#else
    T buf[235][LANES];
    for (int l = 0; l < LANES; ++l) {
        const int f = BLOCK0_INSTANCES[first + l < 7 ? first + l : 6];
        const int vb = FACTOR_VAR_BEGIN[f];
        for (int i = 0; i < 12; ++i) buf[0 + i][l] = x[VAR_X_OFF[FACTOR_VARS[vb + 0]] + i];
        for (int i = 0; i < 3; ++i) buf[12 + i][l] = x[VAR_X_OFF[FACTOR_VARS[vb + 1]] + i];
        for (int i = 0; i < 12; ++i) buf[15 + i][l] = x[VAR_X_OFF[FACTOR_VARS[vb + 2]] + i];
        for (int i = 0; i < 3; ++i) buf[27 + i][l] = x[VAR_X_OFF[FACTOR_VARS[vb + 3]] + i];
        for (int i = 0; i < 6; ++i) buf[30 + i][l] = x[VAR_X_OFF[FACTOR_VARS[vb + 4]] + i];
        for (int i = 0; i < 6; ++i) buf[36 + i][l] = x[VAR_X_OFF[FACTOR_VARS[vb + 5]] + i];
        const T* line = DATA_BUF + FACTOR_DATA_OFF[f];
        for (int i = 0; i < 73; ++i) buf[42 + i][l] = line[0 + i];
        if (!cost) continue;
        for (int i = 0; i < 120; ++i) buf[115 + i][l] = line[73 + i];
    }
    for (int i = 0; i < (cost ? 235 : 115); ++i) {
#pragma HLS LOOP_TRIPCOUNT max=235
        in[i] = load_lanes(buf[i]);
    }
    return in + 42;
#endif
}

// block 0, member 0: its rows 9 ... 14 of 15 hold only 0 and +-1 left of the right-hand side;
// their share of the whitened rows, row by row in order: +-R_ij at j's constant entries, R_ij b_j
void whiten_tail_0_0(const T raw[], T ab[], const T p[]) {
    ab[18] += p[9];
    ab[24] -= p[9];
    ab[30] += p[9] * raw[318];
    ab[19] += p[10];
    ab[25] -= p[10];
    ab[30] += p[10] * raw[350];
    ab[20] += p[11];
    ab[26] -= p[11];
    ab[30] += p[11] * raw[382];
    ab[21] += p[12];
    ab[27] -= p[12];
    ab[30] += p[12] * raw[414];
    ab[22] += p[13];
    ab[28] -= p[13];
    ab[30] += p[13] * raw[446];
    ab[23] += p[14];
    ab[29] -= p[14];
    ab[30] += p[14] * raw[478];
    ab[50] += p[23];
    ab[56] -= p[23];
    ab[62] += p[23] * raw[318];
    ab[51] += p[24];
    ab[57] -= p[24];
    ab[62] += p[24] * raw[350];
    ab[52] += p[25];
    ab[58] -= p[25];
    ab[62] += p[25] * raw[382];
    ab[53] += p[26];
    ab[59] -= p[26];
    ab[62] += p[26] * raw[414];
    ab[54] += p[27];
    ab[60] -= p[27];
    ab[62] += p[27] * raw[446];
    ab[55] += p[28];
    ab[61] -= p[28];
    ab[62] += p[28] * raw[478];
    ab[82] += p[36];
    ab[88] -= p[36];
    ab[94] += p[36] * raw[318];
    ab[83] += p[37];
    ab[89] -= p[37];
    ab[94] += p[37] * raw[350];
    ab[84] += p[38];
    ab[90] -= p[38];
    ab[94] += p[38] * raw[382];
    ab[85] += p[39];
    ab[91] -= p[39];
    ab[94] += p[39] * raw[414];
    ab[86] += p[40];
    ab[92] -= p[40];
    ab[94] += p[40] * raw[446];
    ab[87] += p[41];
    ab[93] -= p[41];
    ab[94] += p[41] * raw[478];
    ab[114] += p[48];
    ab[120] -= p[48];
    ab[126] += p[48] * raw[318];
    ab[115] += p[49];
    ab[121] -= p[49];
    ab[126] += p[49] * raw[350];
    ab[116] += p[50];
    ab[122] -= p[50];
    ab[126] += p[50] * raw[382];
    ab[117] += p[51];
    ab[123] -= p[51];
    ab[126] += p[51] * raw[414];
    ab[118] += p[52];
    ab[124] -= p[52];
    ab[126] += p[52] * raw[446];
    ab[119] += p[53];
    ab[125] -= p[53];
    ab[126] += p[53] * raw[478];
    ab[146] += p[59];
    ab[152] -= p[59];
    ab[158] += p[59] * raw[318];
    ab[147] += p[60];
    ab[153] -= p[60];
    ab[158] += p[60] * raw[350];
    ab[148] += p[61];
    ab[154] -= p[61];
    ab[158] += p[61] * raw[382];
    ab[149] += p[62];
    ab[155] -= p[62];
    ab[158] += p[62] * raw[414];
    ab[150] += p[63];
    ab[156] -= p[63];
    ab[158] += p[63] * raw[446];
    ab[151] += p[64];
    ab[157] -= p[64];
    ab[158] += p[64] * raw[478];
    ab[178] += p[69];
    ab[184] -= p[69];
    ab[190] += p[69] * raw[318];
    ab[179] += p[70];
    ab[185] -= p[70];
    ab[190] += p[70] * raw[350];
    ab[180] += p[71];
    ab[186] -= p[71];
    ab[190] += p[71] * raw[382];
    ab[181] += p[72];
    ab[187] -= p[72];
    ab[190] += p[72] * raw[414];
    ab[182] += p[73];
    ab[188] -= p[73];
    ab[190] += p[73] * raw[446];
    ab[183] += p[74];
    ab[189] -= p[74];
    ab[190] += p[74] * raw[478];
    ab[210] += p[78];
    ab[216] -= p[78];
    ab[222] += p[78] * raw[318];
    ab[211] += p[79];
    ab[217] -= p[79];
    ab[222] += p[79] * raw[350];
    ab[212] += p[80];
    ab[218] -= p[80];
    ab[222] += p[80] * raw[382];
    ab[213] += p[81];
    ab[219] -= p[81];
    ab[222] += p[81] * raw[414];
    ab[214] += p[82];
    ab[220] -= p[82];
    ab[222] += p[82] * raw[446];
    ab[215] += p[83];
    ab[221] -= p[83];
    ab[222] += p[83] * raw[478];
    ab[242] += p[86];
    ab[248] -= p[86];
    ab[254] += p[86] * raw[318];
    ab[243] += p[87];
    ab[249] -= p[87];
    ab[254] += p[87] * raw[350];
    ab[244] += p[88];
    ab[250] -= p[88];
    ab[254] += p[88] * raw[382];
    ab[245] += p[89];
    ab[251] -= p[89];
    ab[254] += p[89] * raw[414];
    ab[246] += p[90];
    ab[252] -= p[90];
    ab[254] += p[90] * raw[446];
    ab[247] += p[91];
    ab[253] -= p[91];
    ab[254] += p[91] * raw[478];
    ab[274] += p[93];
    ab[280] -= p[93];
    ab[286] += p[93] * raw[318];
    ab[275] += p[94];
    ab[281] -= p[94];
    ab[286] += p[94] * raw[350];
    ab[276] += p[95];
    ab[282] -= p[95];
    ab[286] += p[95] * raw[382];
    ab[277] += p[96];
    ab[283] -= p[96];
    ab[286] += p[96] * raw[414];
    ab[278] += p[97];
    ab[284] -= p[97];
    ab[286] += p[97] * raw[446];
    ab[279] += p[98];
    ab[285] -= p[98];
    ab[286] += p[98] * raw[478];
    ab[306] += p[99];
    ab[312] -= p[99];
    ab[318] += p[99] * raw[318];
    ab[307] += p[100];
    ab[313] -= p[100];
    ab[318] += p[100] * raw[350];
    ab[308] += p[101];
    ab[314] -= p[101];
    ab[318] += p[101] * raw[382];
    ab[309] += p[102];
    ab[315] -= p[102];
    ab[318] += p[102] * raw[414];
    ab[310] += p[103];
    ab[316] -= p[103];
    ab[318] += p[103] * raw[446];
    ab[311] += p[104];
    ab[317] -= p[104];
    ab[318] += p[104] * raw[478];
    ab[339] += p[105];
    ab[345] -= p[105];
    ab[350] += p[105] * raw[350];
    ab[340] += p[106];
    ab[346] -= p[106];
    ab[350] += p[106] * raw[382];
    ab[341] += p[107];
    ab[347] -= p[107];
    ab[350] += p[107] * raw[414];
    ab[342] += p[108];
    ab[348] -= p[108];
    ab[350] += p[108] * raw[446];
    ab[343] += p[109];
    ab[349] -= p[109];
    ab[350] += p[109] * raw[478];
    ab[372] += p[110];
    ab[378] -= p[110];
    ab[382] += p[110] * raw[382];
    ab[373] += p[111];
    ab[379] -= p[111];
    ab[382] += p[111] * raw[414];
    ab[374] += p[112];
    ab[380] -= p[112];
    ab[382] += p[112] * raw[446];
    ab[375] += p[113];
    ab[381] -= p[113];
    ab[382] += p[113] * raw[478];
    ab[405] += p[114];
    ab[411] -= p[114];
    ab[414] += p[114] * raw[414];
    ab[406] += p[115];
    ab[412] -= p[115];
    ab[414] += p[115] * raw[446];
    ab[407] += p[116];
    ab[413] -= p[116];
    ab[414] += p[116] * raw[478];
    ab[438] += p[117];
    ab[444] -= p[117];
    ab[446] += p[117] * raw[446];
    ab[439] += p[118];
    ab[445] -= p[118];
    ab[446] += p[118] * raw[478];
    ab[471] += p[119];
    ab[477] -= p[119];
    ab[478] += p[119] * raw[478];
}

// block 0, instances first ... first + LANES - 1: residual + Jacobian (its 180
// structural non-zeros of 15 x 31), whiten. Mode 1 (noise_mode false): accumulate the gradient
// and the Gram from its 36 non-zero tiles; false if not finite. Mode 3 (true): only add
// the cost's rounding noise (how far the cost moves when x is rounded to T) to *noise. Mode 4
// (rows_out given, host only): copy each instance's whitened rows [A | b] (15 x 31, row-major)
// to rows_out + instance * 465, nothing else.
bool linearize_0(const T* x, int first, bool noise_mode, T* noise,
                   double* rows_out = nullptr) {
    V in[235];
    const V* dat = gather_0(x, first, false, in);
    // rows [J | r] padded to 32 (whole tiles): the Jacobian writes only its structural
    // non-zeros, so the zeros this buffer starts with are never overwritten
    static T raw[LANES][480];
    static T ab[LANES][480];  // the whitened rows, every entry written
    jacobian_0(in, dat, raw);
    bool finite = true;
    for (int l = 0; l < LANES; ++l) {
        if (first + l >= 7) continue;
        const int f = BLOCK0_INSTANCES[first + l];
        const int vb = FACTOR_VAR_BEGIN[f];
        const T* line = DATA_BUF + FACTOR_DATA_OFF[f];
        whiten<32, 31, 15, 2, 9>(raw[l] + 0, ab[l] + 0, line + 73);
        whiten_tail_0_0(raw[l] + 0, ab[l] + 0, line + 73);
        reweight<32, 31, 15>(ab[l] + 0, line[193], line[194]);
#ifndef __SYNTHESIS__
        if (rows_out != nullptr) {
            double* out = rows_out + (first + l) * 465;
            for (int r = 0; r < 15; ++r) {
                for (int c = 0; c < 31; ++c) out[r * 31 + c] = static_cast<double>(ab[l][r * 32 + c]);
            }
            continue;
        }
#endif
        if (noise_mode) {
            T scale[32];  // per column: largest storage entry of its variable (0: b, padding)
            for (int c = 0; c < 32; ++c) scale[c] = T(0);
            for (int j = 0; j < 6; ++j) scale[0 + j] = VAR_SCALE[FACTOR_VARS[vb + 0]];
            for (int j = 0; j < 3; ++j) scale[6 + j] = VAR_SCALE[FACTOR_VARS[vb + 1]];
            for (int j = 0; j < 6; ++j) scale[9 + j] = VAR_SCALE[FACTOR_VARS[vb + 2]];
            for (int j = 0; j < 3; ++j) scale[15 + j] = VAR_SCALE[FACTOR_VARS[vb + 3]];
            for (int j = 0; j < 6; ++j) scale[18 + j] = VAR_SCALE[FACTOR_VARS[vb + 4]];
            for (int j = 0; j < 6; ++j) scale[24 + j] = VAR_SCALE[FACTOR_VARS[vb + 5]];
            *noise += rounding_noise<32, 31, 15>(ab[l], scale);
            continue;
        }
        int col[30];  // per column: its tangent entry
        for (int j = 0; j < 6; ++j) col[0 + j] = VAR_T_OFF[FACTOR_VARS[vb + 0]] + j;
        for (int j = 0; j < 3; ++j) col[6 + j] = VAR_T_OFF[FACTOR_VARS[vb + 1]] + j;
        for (int j = 0; j < 6; ++j) col[9 + j] = VAR_T_OFF[FACTOR_VARS[vb + 2]] + j;
        for (int j = 0; j < 3; ++j) col[15 + j] = VAR_T_OFF[FACTOR_VARS[vb + 3]] + j;
        for (int j = 0; j < 6; ++j) col[18 + j] = VAR_T_OFF[FACTOR_VARS[vb + 4]] + j;
        for (int j = 0; j < 6; ++j) col[24 + j] = VAR_T_OFF[FACTOR_VARS[vb + 5]] + j;
        L* h = GRAM + FACTOR_GRAM_OFF[f];
        gram<32, 31, 15, 20, 36>(ab[l], BLOCK0_TILES, BLOCK0_TILE_ROWS, h);
        finite = gradient_from_gram<31>(h, col) && finite;
    }
    return finite;
}

// block 0, mode 2: add the cost of instances first ... first + LANES - 1 to *total, in order
void cost_of_0(const T* x, int first, T* total) {
    V in[235];
    const V* dat = gather_0(x, first, true, in);
    T half[LANES][1];
    cost_0(in, dat, half);
    for (int l = 0; l < LANES; ++l) {
        if (first + l >= 7) continue;
        const T* line = DATA_BUF + FACTOR_DATA_OFF[BLOCK0_INSTANCES[first + l]];
        T cost = T(0);
        cost += robust_loss(half[l][0], line[193], line[194]);
        *total += cost;
    }
}

#ifndef __SYNTHESIS__
// The data inputs (measurements, then noise parameters) of every LANES instances, laned once per
// call by lane_data(): they are the same in every iteration, so a gather only lanes x and the
// kernels read the data in place.
V BLOCK1_LANED[(1 + LANES - 1) / LANES][13];

void lane_data_1() {
    for (int first = 0; first < 1; first += LANES) {
        T laned[13][LANES];
        for (int l = 0; l < LANES; ++l) {
            const int f = BLOCK1_INSTANCES[first + l < 1 ? first + l : 0];
            const T* line = DATA_BUF + FACTOR_DATA_OFF[f];
            for (int i = 0; i < 12; ++i) laned[0 + i][l] = line[0 + i];
            for (int i = 0; i < 1; ++i) laned[12 + i][l] = line[12 + i];
        }
        for (int i = 0; i < 13; ++i) BLOCK1_LANED[first / LANES][i] = load_lanes(laned[i]);
    }
}
#endif

// The inputs of instances BLOCK1_INSTANCES[first ...] into the lanes (lanes past the last
// instance repeat it; their results are not used): x's storage into `in`; returns where the data
// inputs are (on the host the laned data, in hardware the rest of `in`).
const V* gather_1(const T* x, int first, bool cost, V in[25]) {
#ifndef __SYNTHESIS__
    T buf[12][LANES];
    for (int l = 0; l < LANES; ++l) {
        const int f = BLOCK1_INSTANCES[first + l < 1 ? first + l : 0];
        const int vb = FACTOR_VAR_BEGIN[f];
        for (int i = 0; i < 12; ++i) buf[0 + i][l] = x[VAR_X_OFF[FACTOR_VARS[vb + 0]] + i];
    }
    for (int i = 0; i < 12; ++i) in[i] = load_lanes(buf[i]);
    (void)cost;
    return BLOCK1_LANED[first / LANES];
#else
    T buf[25][LANES];
    for (int l = 0; l < LANES; ++l) {
        const int f = BLOCK1_INSTANCES[first + l < 1 ? first + l : 0];
        const int vb = FACTOR_VAR_BEGIN[f];
        for (int i = 0; i < 12; ++i) buf[0 + i][l] = x[VAR_X_OFF[FACTOR_VARS[vb + 0]] + i];
        const T* line = DATA_BUF + FACTOR_DATA_OFF[f];
        for (int i = 0; i < 12; ++i) buf[12 + i][l] = line[0 + i];
        if (!cost) continue;
        for (int i = 0; i < 1; ++i) buf[24 + i][l] = line[12 + i];
    }
    for (int i = 0; i < (cost ? 25 : 24); ++i) {
#pragma HLS LOOP_TRIPCOUNT max=25
        in[i] = load_lanes(buf[i]);
    }
    return in + 12;
#endif
}

// block 1, instances first ... first + LANES - 1: residual + Jacobian (its 33
// structural non-zeros of 6 x 7), whiten. Mode 1 (noise_mode false): accumulate the gradient
// and the Gram from its 3 non-zero tiles; false if not finite. Mode 3 (true): only add
// the cost's rounding noise (how far the cost moves when x is rounded to T) to *noise. Mode 4
// (rows_out given, host only): copy each instance's whitened rows [A | b] (6 x 7, row-major)
// to rows_out + instance * 42, nothing else.
bool linearize_1(const T* x, int first, bool noise_mode, T* noise,
                   double* rows_out = nullptr) {
    V in[25];
    const V* dat = gather_1(x, first, false, in);
    // rows [J | r] padded to 8 (whole tiles): the Jacobian writes only its structural
    // non-zeros, so the zeros this buffer starts with are never overwritten
    static T raw[LANES][48];
    static T ab[LANES][48];  // the whitened rows, every entry written
    jacobian_1(in, dat, raw);
    bool finite = true;
    for (int l = 0; l < LANES; ++l) {
        if (first + l >= 1) continue;
        const int f = BLOCK1_INSTANCES[first + l];
        const int vb = FACTOR_VAR_BEGIN[f];
        const T* line = DATA_BUF + FACTOR_DATA_OFF[f];
        whiten<8, 7, 6, 0, 6>(raw[l] + 0, ab[l] + 0, line + 12);
        reweight<8, 7, 6>(ab[l] + 0, line[13], line[14]);
#ifndef __SYNTHESIS__
        if (rows_out != nullptr) {
            double* out = rows_out + (first + l) * 42;
            for (int r = 0; r < 6; ++r) {
                for (int c = 0; c < 7; ++c) out[r * 7 + c] = static_cast<double>(ab[l][r * 8 + c]);
            }
            continue;
        }
#endif
        if (noise_mode) {
            T scale[8];  // per column: largest storage entry of its variable (0: b, padding)
            for (int c = 0; c < 8; ++c) scale[c] = T(0);
            for (int j = 0; j < 6; ++j) scale[0 + j] = VAR_SCALE[FACTOR_VARS[vb + 0]];
            *noise += rounding_noise<8, 7, 6>(ab[l], scale);
            continue;
        }
        int col[6];  // per column: its tangent entry
        for (int j = 0; j < 6; ++j) col[0 + j] = VAR_T_OFF[FACTOR_VARS[vb + 0]] + j;
        L* h = GRAM + FACTOR_GRAM_OFF[f];
        gram<8, 7, 6, 2, 3>(ab[l], BLOCK1_TILES, BLOCK1_TILE_ROWS, h);
        finite = gradient_from_gram<7>(h, col) && finite;
    }
    return finite;
}

// block 1, mode 2: add the cost of instances first ... first + LANES - 1 to *total, in order
void cost_of_1(const T* x, int first, T* total) {
    V in[25];
    const V* dat = gather_1(x, first, true, in);
    T half[LANES][1];
    cost_1(in, dat, half);
    for (int l = 0; l < LANES; ++l) {
        if (first + l >= 1) continue;
        const T* line = DATA_BUF + FACTOR_DATA_OFF[BLOCK1_INSTANCES[first + l]];
        T cost = T(0);
        cost += robust_loss(half[l][0], line[13], line[14]);
        *total += cost;
    }
}

#ifndef __SYNTHESIS__
// The data inputs (measurements, then noise parameters) of every LANES instances, laned once per
// call by lane_data(): they are the same in every iteration, so a gather only lanes x and the
// kernels read the data in place.
V BLOCK2_LANED[(1 + LANES - 1) / LANES][4];

void lane_data_2() {
    for (int first = 0; first < 1; first += LANES) {
        T laned[4][LANES];
        for (int l = 0; l < LANES; ++l) {
            const int f = BLOCK2_INSTANCES[first + l < 1 ? first + l : 0];
            const T* line = DATA_BUF + FACTOR_DATA_OFF[f];
            for (int i = 0; i < 3; ++i) laned[0 + i][l] = line[0 + i];
            for (int i = 0; i < 1; ++i) laned[3 + i][l] = line[3 + i];
        }
        for (int i = 0; i < 4; ++i) BLOCK2_LANED[first / LANES][i] = load_lanes(laned[i]);
    }
}
#endif

// The inputs of instances BLOCK2_INSTANCES[first ...] into the lanes (lanes past the last
// instance repeat it; their results are not used): x's storage into `in`; returns where the data
// inputs are (on the host the laned data, in hardware the rest of `in`).
const V* gather_2(const T* x, int first, bool cost, V in[7]) {
#ifndef __SYNTHESIS__
    T buf[3][LANES];
    for (int l = 0; l < LANES; ++l) {
        const int f = BLOCK2_INSTANCES[first + l < 1 ? first + l : 0];
        const int vb = FACTOR_VAR_BEGIN[f];
        for (int i = 0; i < 3; ++i) buf[0 + i][l] = x[VAR_X_OFF[FACTOR_VARS[vb + 0]] + i];
    }
    for (int i = 0; i < 3; ++i) in[i] = load_lanes(buf[i]);
    (void)cost;
    return BLOCK2_LANED[first / LANES];
#else
    T buf[7][LANES];
    for (int l = 0; l < LANES; ++l) {
        const int f = BLOCK2_INSTANCES[first + l < 1 ? first + l : 0];
        const int vb = FACTOR_VAR_BEGIN[f];
        for (int i = 0; i < 3; ++i) buf[0 + i][l] = x[VAR_X_OFF[FACTOR_VARS[vb + 0]] + i];
        const T* line = DATA_BUF + FACTOR_DATA_OFF[f];
        for (int i = 0; i < 3; ++i) buf[3 + i][l] = line[0 + i];
        if (!cost) continue;
        for (int i = 0; i < 1; ++i) buf[6 + i][l] = line[3 + i];
    }
    for (int i = 0; i < (cost ? 7 : 6); ++i) {
#pragma HLS LOOP_TRIPCOUNT max=7
        in[i] = load_lanes(buf[i]);
    }
    return in + 3;
#endif
}

// block 2, instances first ... first + LANES - 1: residual + Jacobian (its 6
// structural non-zeros of 3 x 4), whiten. Mode 1 (noise_mode false): accumulate the gradient
// and the Gram from its 1 non-zero tiles; false if not finite. Mode 3 (true): only add
// the cost's rounding noise (how far the cost moves when x is rounded to T) to *noise. Mode 4
// (rows_out given, host only): copy each instance's whitened rows [A | b] (3 x 4, row-major)
// to rows_out + instance * 12, nothing else.
bool linearize_2(const T* x, int first, bool noise_mode, T* noise,
                   double* rows_out = nullptr) {
    V in[7];
    const V* dat = gather_2(x, first, false, in);
    // rows [J | r] padded to 4 (whole tiles): the Jacobian writes only its structural
    // non-zeros, so the zeros this buffer starts with are never overwritten
    static T raw[LANES][12];
    static T ab[LANES][12];  // the whitened rows, every entry written
    jacobian_2(in, dat, raw);
    bool finite = true;
    for (int l = 0; l < LANES; ++l) {
        if (first + l >= 1) continue;
        const int f = BLOCK2_INSTANCES[first + l];
        const int vb = FACTOR_VAR_BEGIN[f];
        const T* line = DATA_BUF + FACTOR_DATA_OFF[f];
        whiten<4, 4, 3, 0, 3>(raw[l] + 0, ab[l] + 0, line + 3);
        reweight<4, 4, 3>(ab[l] + 0, line[4], line[5]);
#ifndef __SYNTHESIS__
        if (rows_out != nullptr) {
            double* out = rows_out + (first + l) * 12;
            for (int r = 0; r < 3; ++r) {
                for (int c = 0; c < 4; ++c) out[r * 4 + c] = static_cast<double>(ab[l][r * 4 + c]);
            }
            continue;
        }
#endif
        if (noise_mode) {
            T scale[4];  // per column: largest storage entry of its variable (0: b, padding)
            for (int c = 0; c < 4; ++c) scale[c] = T(0);
            for (int j = 0; j < 3; ++j) scale[0 + j] = VAR_SCALE[FACTOR_VARS[vb + 0]];
            *noise += rounding_noise<4, 4, 3>(ab[l], scale);
            continue;
        }
        int col[3];  // per column: its tangent entry
        for (int j = 0; j < 3; ++j) col[0 + j] = VAR_T_OFF[FACTOR_VARS[vb + 0]] + j;
        L* h = GRAM + FACTOR_GRAM_OFF[f];
        gram<4, 4, 3, 1, 1>(ab[l], BLOCK2_TILES, BLOCK2_TILE_ROWS, h);
        finite = gradient_from_gram<4>(h, col) && finite;
    }
    return finite;
}

// block 2, mode 2: add the cost of instances first ... first + LANES - 1 to *total, in order
void cost_of_2(const T* x, int first, T* total) {
    V in[7];
    const V* dat = gather_2(x, first, true, in);
    T half[LANES][1];
    cost_2(in, dat, half);
    for (int l = 0; l < LANES; ++l) {
        if (first + l >= 1) continue;
        const T* line = DATA_BUF + FACTOR_DATA_OFF[BLOCK2_INSTANCES[first + l]];
        T cost = T(0);
        cost += robust_loss(half[l][0], line[4], line[5]);
        *total += cost;
    }
}

#ifndef __SYNTHESIS__
// The data inputs (measurements, then noise parameters) of every LANES instances, laned once per
// call by lane_data(): they are the same in every iteration, so a gather only lanes x and the
// kernels read the data in place.
V BLOCK3_LANED[(1 + LANES - 1) / LANES][7];

void lane_data_3() {
    for (int first = 0; first < 1; first += LANES) {
        T laned[7][LANES];
        for (int l = 0; l < LANES; ++l) {
            const int f = BLOCK3_INSTANCES[first + l < 1 ? first + l : 0];
            const T* line = DATA_BUF + FACTOR_DATA_OFF[f];
            for (int i = 0; i < 6; ++i) laned[0 + i][l] = line[0 + i];
            for (int i = 0; i < 1; ++i) laned[6 + i][l] = line[6 + i];
        }
        for (int i = 0; i < 7; ++i) BLOCK3_LANED[first / LANES][i] = load_lanes(laned[i]);
    }
}
#endif

// The inputs of instances BLOCK3_INSTANCES[first ...] into the lanes (lanes past the last
// instance repeat it; their results are not used): x's storage into `in`; returns where the data
// inputs are (on the host the laned data, in hardware the rest of `in`).
const V* gather_3(const T* x, int first, bool cost, V in[13]) {
#ifndef __SYNTHESIS__
    T buf[6][LANES];
    for (int l = 0; l < LANES; ++l) {
        const int f = BLOCK3_INSTANCES[first + l < 1 ? first + l : 0];
        const int vb = FACTOR_VAR_BEGIN[f];
        for (int i = 0; i < 6; ++i) buf[0 + i][l] = x[VAR_X_OFF[FACTOR_VARS[vb + 0]] + i];
    }
    for (int i = 0; i < 6; ++i) in[i] = load_lanes(buf[i]);
    (void)cost;
    return BLOCK3_LANED[first / LANES];
#else
    T buf[13][LANES];
    for (int l = 0; l < LANES; ++l) {
        const int f = BLOCK3_INSTANCES[first + l < 1 ? first + l : 0];
        const int vb = FACTOR_VAR_BEGIN[f];
        for (int i = 0; i < 6; ++i) buf[0 + i][l] = x[VAR_X_OFF[FACTOR_VARS[vb + 0]] + i];
        const T* line = DATA_BUF + FACTOR_DATA_OFF[f];
        for (int i = 0; i < 6; ++i) buf[6 + i][l] = line[0 + i];
        if (!cost) continue;
        for (int i = 0; i < 1; ++i) buf[12 + i][l] = line[6 + i];
    }
    for (int i = 0; i < (cost ? 13 : 12); ++i) {
#pragma HLS LOOP_TRIPCOUNT max=13
        in[i] = load_lanes(buf[i]);
    }
    return in + 6;
#endif
}

// block 3, instances first ... first + LANES - 1: residual + Jacobian (its 12
// structural non-zeros of 6 x 7), whiten. Mode 1 (noise_mode false): accumulate the gradient
// and the Gram from its 3 non-zero tiles; false if not finite. Mode 3 (true): only add
// the cost's rounding noise (how far the cost moves when x is rounded to T) to *noise. Mode 4
// (rows_out given, host only): copy each instance's whitened rows [A | b] (6 x 7, row-major)
// to rows_out + instance * 42, nothing else.
bool linearize_3(const T* x, int first, bool noise_mode, T* noise,
                   double* rows_out = nullptr) {
    V in[13];
    const V* dat = gather_3(x, first, false, in);
    // rows [J | r] padded to 8 (whole tiles): the Jacobian writes only its structural
    // non-zeros, so the zeros this buffer starts with are never overwritten
    static T raw[LANES][48];
    static T ab[LANES][48];  // the whitened rows, every entry written
    jacobian_3(in, dat, raw);
    bool finite = true;
    for (int l = 0; l < LANES; ++l) {
        if (first + l >= 1) continue;
        const int f = BLOCK3_INSTANCES[first + l];
        const int vb = FACTOR_VAR_BEGIN[f];
        const T* line = DATA_BUF + FACTOR_DATA_OFF[f];
        whiten<8, 7, 6, 0, 6>(raw[l] + 0, ab[l] + 0, line + 6);
        reweight<8, 7, 6>(ab[l] + 0, line[7], line[8]);
#ifndef __SYNTHESIS__
        if (rows_out != nullptr) {
            double* out = rows_out + (first + l) * 42;
            for (int r = 0; r < 6; ++r) {
                for (int c = 0; c < 7; ++c) out[r * 7 + c] = static_cast<double>(ab[l][r * 8 + c]);
            }
            continue;
        }
#endif
        if (noise_mode) {
            T scale[8];  // per column: largest storage entry of its variable (0: b, padding)
            for (int c = 0; c < 8; ++c) scale[c] = T(0);
            for (int j = 0; j < 6; ++j) scale[0 + j] = VAR_SCALE[FACTOR_VARS[vb + 0]];
            *noise += rounding_noise<8, 7, 6>(ab[l], scale);
            continue;
        }
        int col[6];  // per column: its tangent entry
        for (int j = 0; j < 6; ++j) col[0 + j] = VAR_T_OFF[FACTOR_VARS[vb + 0]] + j;
        L* h = GRAM + FACTOR_GRAM_OFF[f];
        gram<8, 7, 6, 2, 3>(ab[l], BLOCK3_TILES, BLOCK3_TILE_ROWS, h);
        finite = gradient_from_gram<7>(h, col) && finite;
    }
    return finite;
}

// block 3, mode 2: add the cost of instances first ... first + LANES - 1 to *total, in order
void cost_of_3(const T* x, int first, T* total) {
    V in[13];
    const V* dat = gather_3(x, first, true, in);
    T half[LANES][1];
    cost_3(in, dat, half);
    for (int l = 0; l < LANES; ++l) {
        if (first + l >= 1) continue;
        const T* line = DATA_BUF + FACTOR_DATA_OFF[BLOCK3_INSTANCES[first + l]];
        T cost = T(0);
        cost += robust_loss(half[l][0], line[7], line[8]);
        *total += cost;
    }
}

// Linearise every factor (each block type is its own pipelined unit); false if not finite.
bool linearize_all(const T* x) {
    for (int i = 0; i < N_TANGENT; ++i) G[i] = T(0);
    bool finite = true;
    T unused = T(0);  // mode 1 adds no noise
    for (int i = 0; i < 7; i += LANES) finite = linearize_0(x, i, false, &unused) && finite;
    for (int i = 0; i < 1; i += LANES) finite = linearize_1(x, i, false, &unused) && finite;
    for (int i = 0; i < 1; i += LANES) finite = linearize_2(x, i, false, &unused) && finite;
    for (int i = 0; i < 1; i += LANES) finite = linearize_3(x, i, false, &unused) && finite;
    return finite;
}

// The cost's rounding noise at x: every block in mode 3, in linearize_all's order. Only a step
// that does not lower the cost needs it, so it is computed then, not in every linearisation.
T rounding_noise_all(const T* x) {
    for (int v = 0; v < N_VARIABLES; ++v) {  // largest storage entry of each variable, at least 1
        T scale = T(1);
        for (int i = VAR_X_OFF[v]; i < VAR_X_OFF[v + 1]; ++i) {
#pragma HLS LOOP_TRIPCOUNT max=12
            scale = fgc_abs(x[i]) > scale ? fgc_abs(x[i]) : scale;
        }
        VAR_SCALE[v] = scale;
    }
    T noise = T(0);
    for (int i = 0; i < 7; i += LANES) linearize_0(x, i, true, &noise);
    for (int i = 0; i < 1; i += LANES) linearize_1(x, i, true, &noise);
    for (int i = 0; i < 1; i += LANES) linearize_2(x, i, true, &noise);
    for (int i = 0; i < 1; i += LANES) linearize_3(x, i, true, &noise);
    return noise;
}

#ifndef __SYNTHESIS__
// The whitened rows [A | b] of every factor instance at x (mode 4), block by block, each block's
// instances in order: what a caller eliminating part of the graph itself (the fixed-lag
// stream's marginalisation) needs.
void linearized_rows(const T* x, double* out) {
    T unused = T(0);
    for (int i = 0; i < 7; i += LANES) linearize_0(x, i, false, &unused, out + 0);
    for (int i = 0; i < 1; i += LANES) linearize_1(x, i, false, &unused, out + 3255);
    for (int i = 0; i < 1; i += LANES) linearize_2(x, i, false, &unused, out + 3297);
    for (int i = 0; i < 1; i += LANES) linearize_3(x, i, false, &unused, out + 3309);
}
#endif

// The graph's cost (GTSAM's error) at x: every block in cost mode.
T total_cost(const T* x) {
    T total = T(0);
    for (int i = 0; i < 7; i += LANES) cost_of_0(x, i, &total);
    for (int i = 0; i < 1; i += LANES) cost_of_1(x, i, &total);
    for (int i = 0; i < 1; i += LANES) cost_of_2(x, i, &total);
    for (int i = 0; i < 1; i += LANES) cost_of_3(x, i, &total);
    return total;
}

// ---- retraction x (+) delta, one unit per variable type
// kind 0: Pose3
void retract_0(const T x[12], const T d[6], T out[12]) {
    const T r0 = (d[1]*d[1]);
    const T r1 = (d[2]*d[2]);
    const T r2 = r0 + r1;
    const T r3 = -r2;
    const T r4 = (d[0]*d[0]);
    const T r5 = r2 + r4;
    const T r6 = lie_B(r5);
    const T r7 = r3*r6 + T(1);
    const T r8 = lie_A(r5);
    const T r9 = r8*d[2];
    const T r10 = r6*d[1];
    const T r11 = r10*d[0];
    const T r12 = r11 + r9;
    const T r13 = r8*d[1];
    const T r14 = r6*d[2];
    const T r15 = r14*d[0];
    const T r16 = -r13 + r15;
    const T r17 = r11 - r9;
    const T r18 = -r1 - r4;
    const T r19 = r18*r6 + T(1);
    const T r20 = r8*d[0];
    const T r21 = r14*d[1] + r20;
    const T r22 = r13 + r15;
    const T r23 = -r20 + r6*d[1]*d[2];
    const T r24 = -r0 - r4;
    const T r25 = r24*r6 + T(1);
    const T r26 = lie_C(r5);
    const T r27 = r26*d[0];
    const T r28 = r27*d[1];
    const T r29 = r27*d[2];
    const T r30 = d[3]*(r26*r3 + T(1)) + d[4]*(-r14 + r28) + d[5]*(r10 + r29);
    const T r31 = r6*d[0];
    const T r32 = d[3]*(r14 + r28) + d[4]*(r18*r26 + T(1)) + d[5]*(r26*d[1]*d[2] - r31);
    const T r33 = d[3]*(-r10 + r29) + d[4]*(r26*d[1]*d[2] + r31) + d[5]*(r24*r26 + T(1));
    out[0] = r12*x[1] + r16*x[2] + r7*x[0];
    out[1] = r17*x[0] + r19*x[1] + r21*x[2];
    out[2] = r22*x[0] + r23*x[1] + r25*x[2];
    out[3] = r12*x[4] + r16*x[5] + r7*x[3];
    out[4] = r17*x[3] + r19*x[4] + r21*x[5];
    out[5] = r22*x[3] + r23*x[4] + r25*x[5];
    out[6] = r12*x[7] + r16*x[8] + r7*x[6];
    out[7] = r17*x[6] + r19*x[7] + r21*x[8];
    out[8] = r22*x[6] + r23*x[7] + r25*x[8];
    out[9] = r30*x[0] + r32*x[1] + r33*x[2] + x[9];
    out[10] = r30*x[3] + r32*x[4] + r33*x[5] + x[10];
    out[11] = r30*x[6] + r32*x[7] + r33*x[8] + x[11];
}

// kind 1: Vector3
void retract_1(const T x[3], const T d[3], T out[3]) {
    out[0] = d[0] + x[0];
    out[1] = d[1] + x[1];
    out[2] = d[2] + x[2];
}

// kind 2: ImuBias
void retract_2(const T x[6], const T d[6], T out[6]) {
    out[0] = d[0] + x[0];
    out[1] = d[1] + x[1];
    out[2] = d[2] + x[2];
    out[3] = d[3] + x[3];
    out[4] = d[4] + x[4];
    out[5] = d[5] + x[5];
}

void retract_all(const T* x, const T* delta, T* out) {
    for (int i = 0; i < 8; ++i) {
        const int v = KIND0_VARIABLES[i];
        retract_0(x + VAR_X_OFF[v], delta + VAR_T_OFF[v], out + VAR_X_OFF[v]);
    }
    for (int i = 0; i < 8; ++i) {
        const int v = KIND1_VARIABLES[i];
        retract_1(x + VAR_X_OFF[v], delta + VAR_T_OFF[v], out + VAR_X_OFF[v]);
    }
    for (int i = 0; i < 8; ++i) {
        const int v = KIND2_VARIABLES[i];
        retract_2(x + VAR_X_OFF[v], delta + VAR_T_OFF[v], out + VAR_X_OFF[v]);
    }
}

// g++ -O3 inlines the factorisation into LM's loop and then warns about register-block rows
// past the end of a small front's H on paths its loop bounds never take (fronts narrower than
// a TILE block: a 4-pose graph's 3 x 4 H); -Warray-bounds is off for this part alone (the
// float64 simulator checks its numbers, tests/native)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Warray-bounds"
// The factored frontal matrix out: rows 0 ... f - 1 as the step's conditional (R | S | d), after
// checking each pivot against the block's largest entry, and the separator's rows as the update
// matrix for the parent. Rows go as they are: left of the diagonal they may hold leftovers that no
// reader looks at (back-substitution reads a conditional's row from its diagonal on, the parent
// an update matrix's upper triangle). False if a pivot is below SINGULAR_EPS * scale.
template <int LD>
FGC_INLINE bool store_step(T (*H)[LD], int w, int f, int s, T scale) {
    // never taken (the tables' widths), but it bounds the copies for g++, which otherwise merges
    // the rows of a one-tile H into one memcpy it cannot prove inside H (-Werror=array-bounds)
    if (w > MAX_W || f > MAX_F || w + 1 > LD) return false;
    T* cond = COND + STEP_COND_OFF[s];
    for (int i = 0; i < f; ++i) {
#pragma HLS LOOP_TRIPCOUNT max=30
        if (!(fgc_abs(H[i][i]) > SINGULAR_EPS * scale)) return false;
        // from the diagonal on: back-substitution reads nothing left of it (the copy of a wide
        // front's square block, half of it leftovers, was a tenth of its solve)
        for (int c = i; c <= w; ++c) {
#pragma HLS LOOP_TRIPCOUNT max=30
            cond[i * (w + 1) + c] = H[i][c];
        }
    }
    const int sw = w - f;
    T* u = NF + STEP_NF_OFF[s];
    for (int a = 0; a < sw; ++a) {
#pragma HLS LOOP_TRIPCOUNT max=30
        // the upper triangle and the reduced gradient only: the parent reads nothing else (half
        // the copy, which was a sixth of a wide-stepped solve's time)
        for (int b = a; b <= sw; ++b) {
#pragma HLS LOOP_TRIPCOUNT max=30
            u[a * (sw + 1) + b] = H[f + a][f + b];
        }
    }
    return true;
}

// ---- multifrontal Cholesky (paper B's LES): per step the frontal matrix [H | g] (upper
// triangle, row-major: U = L^T row by row keeps every inner loop contiguous) of its factors'
// Grams, its children's update matrices and mu on the frontal diagonal; #CPE process elements
// each Evaluate one row of U and Update the rows after it, streaming to the next. Then the
// conditional (R | S | d) = rows of U (L^T, L^-1 H_fs, L^-1 g_f) and the update matrix (Schur
// complement, upper, and reduced gradient) for the parent. False if not positive definite.
// One later row i of a frontal matrix through the Updates of n rows of U (P[0 ... n), a panel
// or every frontal row): from the row's tile boundary to the end of the padded row.
template <int LD>
FGC_INLINE void later_row_update(T (*H)[LD], const T (*P)[LD], int n, int i, int end) {
    for (int c0 = i - i % TILE; c0 < end; c0 += TILE) {
#pragma HLS LOOP_TRIPCOUNT max=8
#pragma HLS PIPELINE
        T h[TILE];
        for (int t = 0; t < TILE; ++t) h[t] = H[i][c0 + t];
        for (int k = 0; k < n; ++k) {
#pragma HLS LOOP_TRIPCOUNT max=30
            const T u = P[k][i];
            for (int t = 0; t < TILE; ++t) h[t] -= u * P[k][c0 + t];
        }
        for (int t = 0; t < TILE; ++t) H[i][c0 + t] = h[t];
    }
}

// TILE rows i ... i + TILE - 1 from column c0 to c1 (whole tiles) through the Updates of n rows
// of U (P), TILE x TILE at a time: the rows share a start column, so TILE independent
// accumulator chains instead of one.
template <int LD>
FGC_INLINE void tile_rows_update(T (*H)[LD], const T (*P)[LD], int n, int i, int c0, int c1) {
    for (; c0 < c1; c0 += TILE) {
#pragma HLS LOOP_TRIPCOUNT max=8
        T h[TILE][TILE];
        for (int r = 0; r < TILE; ++r) {
            for (int t = 0; t < TILE; ++t) h[r][t] = H[i + r][c0 + t];
        }
        for (int k = 0; k < n; ++k) {
#pragma HLS LOOP_TRIPCOUNT max=30
            for (int r = 0; r < TILE; ++r) {
                const T u = P[k][i + r];
                for (int t = 0; t < TILE; ++t) h[r][t] -= u * P[k][c0 + t];
            }
        }
        for (int r = 0; r < TILE; ++r) {
            for (int t = 0; t < TILE; ++t) H[i + r][c0 + t] = h[r][t];
        }
    }
}

#if !defined(__SYNTHESIS__) && (defined(__AVX512F__) || defined(__AVX__))
// On the host, the wide steps' Updates in register blocks of whole SIMD registers: rows in
// blocks of WR, columns WN vectors (WL entries each) at a time, WR x WN accumulators: with
// AVX-512 8 rows x 16 doubles in 16 of its 32 registers, with AVX TILE rows x 8 doubles in 8 of
// its 16 (a vector wider than the build's registers is split by g++ into slow code: 64-byte
// vectors in an AVX2 build made sphere2500's solve 4x slower); other hosts keep the TILE x TILE
// blocks. Each accumulator entry takes the Updates k = 0 ... n - 1 in order, a product and then
// a difference (no fused multiply-add), exactly as the TILE x TILE blocks do, so the same bits;
// per k a block loads WN vectors of P's row k and WR of its entries, against 4 and 4 per 16
// products in a TILE x TILE block.
#define FGC_WIDE_UPDATES 1
#ifdef __AVX512F__
typedef T WV __attribute__((vector_size(64)));
const int WR = 2 * TILE, WN = 2;
#else
typedef T WV __attribute__((vector_size(32)));
const int WR = TILE, WN = 2;
#endif
const int WL = sizeof(WV) / sizeof(T);

FGC_INLINE WV wv_load(const T* p) {
    WV v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

FGC_INLINE void wv_store(T* p, const WV& v) { std::memcpy(p, &v, sizeof v); }

// Rows i ... i + R - 1 from column c0 on, NV vectors at a time while whole ones fit before end;
// returns where it stopped.
template <int LD, int R, int NV>
FGC_INLINE int wide_rows_update(T (*H)[LD], const T (*P)[LD], int n, int i, int c0, int end) {
    // a row narrower than NV vectors never takes this path (end <= LD): not instantiated, so
    // g++ does not see accesses past a small H (-Werror=array-bounds)
    if constexpr (NV * WL <= LD) {
        if (end > LD) end = LD;  // never (end is a row's width), but it bounds the loads for g++
        for (; c0 + NV * WL <= end; c0 += NV * WL) {
            WV h[R][NV];
            for (int r = 0; r < R; ++r) {
                for (int v = 0; v < NV; ++v) h[r][v] = wv_load(&H[i + r][c0 + v * WL]);
            }
            for (int k = 0; k < n; ++k) {
                WV p[NV];
                for (int v = 0; v < NV; ++v) p[v] = wv_load(&P[k][c0 + v * WL]);
                for (int r = 0; r < R; ++r) {
                    const T u = P[k][i + r];
                    for (int v = 0; v < NV; ++v) h[r][v] -= u * p[v];
                }
            }
            for (int r = 0; r < R; ++r) {
                for (int v = 0; v < NV; ++v) wv_store(&H[i + r][c0 + v * WL], h[r][v]);
            }
        }
    }
    return c0;
}
#endif

// Rows i0 ... i1 - 1 through the Updates of n rows of U (P): one row at a time up to a tile
// boundary, then TILE rows at a time (each row from its tile boundary: the block's start column),
// then the rest. Every entry takes the Updates k = 0 ... n - 1 in order, exactly as one row at a
// time would (bit for bit). On the host (floating point) blocks of WR rows go first, in whole
// SIMD registers: the top TILE rows' first tile as a TILE x TILE block, then every row of the
// block from the next tile on (where the lower rows' tiles start), the same entries as TILE
// rows at a time would update.
template <int LD>
FGC_INLINE void later_rows_update(T (*H)[LD], const T (*P)[LD], int n, int i0, int i1,
                                  int end) {
    int i = i0;
    for (; i < i1 && i % TILE != 0; ++i) later_row_update<LD>(H, P, n, i, end);
#ifdef FGC_WIDE_UPDATES
    for (; i + WR <= i1; i += WR) {
        int c0 = i;
        for (; c0 + TILE < i + WR; c0 += TILE) {  // rows i + b ... start at tile i + b
            for (int b = 0; b <= c0 - i; b += TILE) tile_rows_update<LD>(H, P, n, i + b, c0, c0 + TILE);
        }
        c0 = wide_rows_update<LD, WR, WN>(H, P, n, i, c0, end);
        if (WN > 1) c0 = wide_rows_update<LD, WR, 1>(H, P, n, i, c0, end);
        for (int b = 0; b < WR; b += TILE) tile_rows_update<LD>(H, P, n, i + b, c0, end);
    }
    for (; i + TILE <= i1; i += TILE) {
        const int c0 = wide_rows_update<LD, TILE, 1>(H, P, n, i, i, end);
        tile_rows_update<LD>(H, P, n, i, c0, end);
    }
#endif
    for (; i + TILE <= i1; i += TILE) {
#pragma HLS LOOP_TRIPCOUNT max=7
        tile_rows_update<LD>(H, P, n, i, i, end);
    }
    for (; i < i1; ++i) later_row_update<LD>(H, P, n, i, end);
}

template <int LD>
bool cholesky_frontal(T (*H)[LD], int w, int f, int s, T mu) {
    // Rows are updated from the tile boundary at or left of the diagonal to the end of the
    // padded row (w < end <= LD, a multiple of TILE): whole vectors, no remainders. Right of
    // the gradient the padding stays zero; left of the diagonal, where only the lower triangle
    // is, leftovers accumulate that nothing reads (a pivot row is read from its diagonal on).
    const int end = (w + TILE) / TILE * TILE;
    T pivot[TILE][LD];  // rows j ... of U, read by the Updates of their panel (zero left of the diagonal)
    for (int j = 0; j < f; ++j) {
#pragma HLS LOOP_TRIPCOUNT max=30
        H[j][j] += mu;
    }
    // CPE rounds in panels of TILE rows of U: each row of the panel is Evaluated and Updates
    // the panel's rows after it; then every later row of the block of NB frontal rows streams
    // through the panel's TILE Updates in turn (read once, written once); once the block is
    // factored, the frontal rows after it take its NB Updates in one pass (read and written once
    // per block instead of once per panel: on a wide front the passes of TILE Updates each were
    // its time). Each entry is updated by rows j = 0, 1, ... in order, exactly as one round per
    // row would.
    const int NB = 8 * TILE;
    for (int jb = 0; jb < f; jb += NB) {
#pragma HLS LOOP_TRIPCOUNT max=1
        const int jb1 = f - jb < NB ? f : jb + NB;
        for (int j = jb; j < jb1; j += TILE) {
#pragma HLS LOOP_TRIPCOUNT max=8
#pragma HLS UNROLL factor=5
            const int pn = f - j < TILE ? f - j : TILE;
            for (int k = 0; k < pn; ++k) {  // Evaluate row jj, Update the panel's rows after it
#pragma HLS LOOP_TRIPCOUNT max=4
                const int jj = j + k;
                if (!(H[jj][jj] > T(0))) return false;
                const int j0 = jj - jj % TILE;
                // inside the diagonal tile the later rows are updated by the unscaled row times
                // its 1 / pivot, so the pivot chain from row to row is a division, not a square
                // root and a division (cholesky_frontal_fixed's frontal_pivot, bit for bit)
                T row[TILE];
                for (int t = 0; t < TILE; ++t) row[t] = H[jj][j0 + t];
                const T r = T(1) / H[jj][jj];
                const T inv = T(1) / fgc_sqrt(H[jj][jj]);
                for (int c0 = j0; c0 < end; c0 += TILE) {
#pragma HLS LOOP_TRIPCOUNT max=8
                    for (int t = 0; t < TILE; ++t) pivot[k][c0 + t] = H[jj][c0 + t] * inv;
                }
                for (int c = j0; c < jj; ++c) {
#pragma HLS LOOP_TRIPCOUNT max=4
                    pivot[k][c] = T(0);
                }
                for (int c0 = j0; c0 < end; c0 += TILE) {
#pragma HLS LOOP_TRIPCOUNT max=8
                    for (int t = 0; t < TILE; ++t) H[jj][c0 + t] = pivot[k][c0 + t];
                }
                for (int i = jj + 1; i < j + pn; ++i) {
#pragma HLS LOOP_TRIPCOUNT max=4
                    const T uji = pivot[k][i];
                    const T a = row[i - j0] * r;
                    for (int t = 0; t < TILE; ++t) H[i][j0 + t] -= a * row[t];
                    // (only if a row is wider than one tile: g++ -Werror proves the dead loop would
                    // index past H[i][LD] otherwise)
                    for (int c0 = j0 + TILE; c0 < end; c0 += TILE) {
#pragma HLS LOOP_TRIPCOUNT max=8
                        for (int t = 0; t < TILE; ++t) H[i][c0 + t] -= uji * pivot[k][c0 + t];
                    }
                }
            }
            // the block's rows after the panel through its Updates (they are the next panels)
            later_rows_update<LD>(H, pivot, pn, j + pn, jb1, end);
        }
        // the frontal rows after the block through its Updates (rows jb ... jb1 - 1 of H are U)
        later_rows_update<LD>(H, H + jb, jb1 - jb, jb1, f, end);
    }
    // the separator rows through every frontal row's Updates in one pass (rows 0 ... f - 1 of H
    // are U now): each entry takes the Updates k = 0 ... f - 1 in the order the panels would
    // have applied them, bit for bit, but is read and written once instead of once per panel
    // (on a wide step with few frontal columns the passes over the separator rows were the
    // factorisation's time)
    later_rows_update<LD>(H, H, f, f, w, end);
    // the largest |U_ic| of the frontal block, in TILE running maxima (a maximum does not depend
    // on the order it is taken in)
    T largest[TILE];
    for (int t = 0; t < TILE; ++t) largest[t] = T(0);
    for (int i = 0; i < f; ++i) {
#pragma HLS LOOP_TRIPCOUNT max=30
        for (int c0 = i - i % TILE; c0 < f; c0 += TILE) {
#pragma HLS LOOP_TRIPCOUNT max=8
            for (int t = 0; t < TILE; ++t) {
                const T a = c0 + t >= i && c0 + t < f ? fgc_abs(H[i][c0 + t]) : T(0);
                largest[t] = a > largest[t] ? a : largest[t];
            }
        }
    }
    T scale = T(0);
    for (int t = 0; t < TILE; ++t) scale = largest[t] > scale ? largest[t] : scale;
    return store_step<LD>(H, w, f, s, scale);
}

// ---- the same factorisation for a step pattern, W, F and LD known at compile time: every entry
// takes the same operations in the same order as in cholesky_frontal (bit for bit), but the CPU
// build gets fixed trip counts, the pivot rows are scaled in place (no copy round trip) and the
// pivot chain (1 / sqrt per row of U) is interleaved with independent Updates. Measured on LIO
// (W = 30, F = 15): 0.7x the time of cholesky_frontal<32>, 0.8x the instructions.
// Evaluate row K of a panel's diagonal tile d (PN rows of U, TILE columns; the upper part):
// its pivot, its inverse, its row of U, and its Update of the tile's rows after it.
template <int K, int PN>
FGC_INLINE bool frontal_pivot(T (&d)[TILE][TILE], T (&inv)[TILE]) {
#pragma HLS INLINE
    if (K >= PN) return true;
    if (!(d[K][K] > T(0))) return false;
    const T r = T(1) / d[K][K];
    for (int i = K + 1; i < PN; ++i) {
        const T a = d[K][i] * r;
        for (int t = i; t < TILE; ++t) d[i][t] -= a * d[K][t];
    }
    inv[K] = T(1) / fgc_sqrt(d[K][K]);
    for (int t = K; t < TILE; ++t) d[K][t] = d[K][t] * inv[K];
    return true;
}

// The Updates of rows i0 ... i1 - 1 by the panel of PN rows of U from row j on (as in
// cholesky_frontal: from each row's tile boundary to the end of the padded row).
template <int W, int LD, int PN>
FGC_INLINE void frontal_update(T (*H)[LD], int j, int i0, int i1) {
#pragma HLS INLINE
    const int END = (W + TILE) / TILE * TILE;
    for (int i = i0; i < i1; ++i) {
#pragma HLS LOOP_TRIPCOUNT max=30
        T u[PN];
        for (int k = 0; k < PN; ++k) u[k] = H[j + k][i];
        int c0 = i - i % TILE;
        if ((END - c0) / TILE % 2 == 1) {  // an odd tile first, then two tiles at a time
            T h[TILE];
            for (int t = 0; t < TILE; ++t) h[t] = H[i][c0 + t];
            for (int k = 0; k < PN; ++k) {
                for (int t = 0; t < TILE; ++t) h[t] -= u[k] * H[j + k][c0 + t];
            }
            for (int t = 0; t < TILE; ++t) H[i][c0 + t] = h[t];
            c0 += TILE;
        }
        for (; c0 < END; c0 += 2 * TILE) {
#pragma HLS LOOP_TRIPCOUNT max=4
#pragma HLS PIPELINE
            T h[2 * TILE];
            for (int t = 0; t < 2 * TILE; ++t) h[t] = H[i][c0 + t];
            for (int k = 0; k < PN; ++k) {
                for (int t = 0; t < 2 * TILE; ++t) h[t] -= u[k] * H[j + k][c0 + t];
            }
            for (int t = 0; t < 2 * TILE; ++t) H[i][c0 + t] = h[t];
        }
    }
}

// Factor the panel of PN rows from row jn on (Updated by every earlier panel already), while
// the panel of PC rows from row j on (PC = 0: none) Updates rows jn + PN ... i1 - 1: one share
// after each pivot, so the pivot chain runs next to them. The diagonal tile is Evaluated in d,
// then the panel's rows are finished TILE columns at a time; the largest |U_ic| of the frontal
// block (c < F; left of the diagonal U is zero) is kept in TILE running maxima.
template <int W, int F, int LD, int PC, int PN>
FGC_INLINE bool frontal_panel(T (*H)[LD], int j, int jn, int i1) {
#pragma HLS INLINE
    const int END = (W + TILE) / TILE * TILE;
    T d[TILE][TILE], inv[TILE];
    for (int k = 0; k < PN; ++k) {
        for (int t = 0; t < TILE; ++t) d[k][t] = H[jn + k][jn + t];
    }
    const int i0 = jn + PN, n = i1 - i0;
    if (!frontal_pivot<0, PN>(d, inv)) return false;
    if (PC > 0) frontal_update<W, LD, (PC > 0 ? PC : 1)>(H, j, i0 + 0 * n / 4, i0 + 1 * n / 4);
    if (!frontal_pivot<1, PN>(d, inv)) return false;
    if (PC > 0) frontal_update<W, LD, (PC > 0 ? PC : 1)>(H, j, i0 + 1 * n / 4, i0 + 2 * n / 4);
    if (!frontal_pivot<2, PN>(d, inv)) return false;
    if (PC > 0) frontal_update<W, LD, (PC > 0 ? PC : 1)>(H, j, i0 + 2 * n / 4, i0 + 3 * n / 4);
    if (!frontal_pivot<3, PN>(d, inv)) return false;
    if (PC > 0) frontal_update<W, LD, (PC > 0 ? PC : 1)>(H, j, i0 + 3 * n / 4, i0 + 4 * n / 4);
    for (int k = 0; k < PN; ++k) {
        for (int t = 0; t < TILE; ++t) H[jn + k][jn + t] = t < k ? T(0) : d[k][t];
    }
    for (int c0 = jn + TILE; c0 < END; c0 += TILE) {
#pragma HLS LOOP_TRIPCOUNT max=8
#pragma HLS PIPELINE
        T h[PN][TILE];
        for (int k = 0; k < PN; ++k) {
            for (int t = 0; t < TILE; ++t) h[k][t] = H[jn + k][c0 + t];
        }
        for (int k = 0; k < PN; ++k) {
            for (int q = 0; q < PN; ++q) {
                if (q < k) {
                    for (int t = 0; t < TILE; ++t) h[k][t] -= d[q][k] * h[q][t];
                }
            }
            for (int t = 0; t < TILE; ++t) h[k][t] = h[k][t] * inv[k];
        }
        for (int k = 0; k < PN; ++k) {
            for (int t = 0; t < TILE; ++t) H[jn + k][c0 + t] = h[k][t];
        }
    }
    return true;
}

template <int W, int F, int LD>
bool cholesky_frontal_fixed(T (*H)[LD], int s, T mu) {
    for (int j = 0; j < F; ++j) H[j][j] += mu;
    // panels of TILE rows of U and a last one of TAIL rows; each panel's Updates of the rows
    // after the next panel run inside the next panel's factorisation (the same Updates, in the
    // same order for every entry: panel by panel)
    const int NFULL = F / TILE, TAIL = F % TILE;
    const int P0 = NFULL > 0 ? TILE : TAIL;
    const int PT = TAIL > 0 ? TAIL : 1;
    if (!frontal_panel<W, F, LD, 0, P0>(H, 0, 0, 0)) return false;
    int j = 0;
    for (int p = 0; p < NFULL - 1; ++p, j += TILE) {
#pragma HLS UNROLL factor=5
        frontal_update<W, LD, TILE>(H, j, j + TILE, j + 2 * TILE);
        if (!frontal_panel<W, F, LD, TILE, TILE>(H, j, j + TILE, W)) return false;
    }
    if (NFULL > 0 && TAIL > 0) {
        frontal_update<W, LD, TILE>(H, j, j + TILE, j + TILE + TAIL);
        if (!frontal_panel<W, F, LD, TILE, PT>(H, j, j + TILE, W)) return false;
        j += TILE;
        frontal_update<W, LD, PT>(H, j, j + PT, W);
    } else {
        frontal_update<W, LD, P0>(H, j, j + P0, W);
    }
    // the largest |U_ic| of the frontal block (i <= c < F), from row i's tile on: left of the
    // diagonal in that tile U is zero (the diagonal tiles are written with zeros), so only c < F
    // is masked, a fixed mask the loop vectorises with (the maximum does not depend on the order
    // it is taken in); left of the tile the generic step's assembly leaves H as it was
    T largest[TILE];
    for (int t = 0; t < TILE; ++t) largest[t] = T(0);
    for (int i = 0; i < F; ++i) {
        for (int c0 = i - i % TILE; c0 < F; c0 += TILE) {
            for (int t = 0; t < TILE; ++t) {
                const T a = c0 + t < F ? fgc_abs(H[i][c0 + t]) : T(0);
                largest[t] = a > largest[t] ? a : largest[t];
            }
        }
    }
    T scale = T(0);
    for (int t = 0; t < TILE; ++t) scale = largest[t] > scale ? largest[t] : scale;
    return store_step<LD>(H, W, F, s, scale);
}

// Any step: assemble [H | g] through the step tables, then factor.
template <int U>
bool eliminate_step(int s, T mu) {
    static T H[MAX_W][MAX_LD];  // upper triangle of H, gradient in column w, zero padding
#pragma HLS ARRAY_PARTITION variable=H cyclic factor=20 dim=2
    const int w = STEP_W[s];
    // zero the step's padded rows only, each from its tile boundary on: nothing reads a row past
    // its padded end or left of its tile (the Updates start there, the assembly writes the upper
    // triangle), and a zeroing of MAX_LD columns per row cost more than the factorisation of a
    // graph's many narrow steps when one step is wide (sphere2500: 594 columns)
    const int end = (w + TILE) / TILE * TILE;
    // never taken (the tables' widths), but it bounds the zeroing for g++, which otherwise turns
    // it into memsets it cannot prove inside a small H (-Werror=array-bounds)
    if (w > MAX_W || end > MAX_LD) return false;
    for (int i = 0; i < w; ++i) {
#pragma HLS LOOP_TRIPCOUNT max=30
        for (int c = i - i % TILE; c < end; ++c) H[i][c] = T(0);
    }
    for (int e = STEP_FACTOR_BEGIN[s]; e < STEP_FACTOR_BEGIN[s + 1]; ++e) {
#pragma HLS LOOP_TRIPCOUNT max=4
        const int fac = STEP_FACTORS[e];
        const int* cm = FACTOR_COLMAP + FACTOR_COLMAP_BEGIN[fac];
        const int d = FACTOR_COLMAP_BEGIN[fac + 1] - FACTOR_COLMAP_BEGIN[fac];
        const T* gram = GRAM + FACTOR_GRAM_OFF[fac];
        for (int p = 0, base = 0; p < d; base += ++p) {
#pragma HLS LOOP_TRIPCOUNT max=30
            for (int q = 0; q <= p; ++q) {
#pragma HLS LOOP_TRIPCOUNT max=30
                const int lo = cm[q] < cm[p] ? cm[q] : cm[p], hi = cm[q] < cm[p] ? cm[p] : cm[q];
                H[lo][hi] += gram[base + q];
            }
        }
        const int gbase = d * (d + 1) / 2;
        for (int p = 0; p < d; ++p) {
#pragma HLS LOOP_TRIPCOUNT max=30
            H[cm[p]][w] += gram[gbase + p];
        }
    }
    for (int e = STEP_CHILD_BEGIN[s]; e < STEP_CHILD_BEGIN[s + 1]; ++e) {
#pragma HLS LOOP_TRIPCOUNT max=2
        const int c = STEP_CHILDREN[e];
        const int sc = STEP_W[c] - STEP_F[c];
        const int* map = STEP_SEPMAP + STEP_SEPMAP_BEGIN[c];
        const T* u = NF + STEP_NF_OFF[c];
        bool ascending = true;  // the child's separator in the parent's column order
        for (int a = 1; a < sc; ++a) ascending = ascending && map[a - 1] < map[a];
        if (ascending) {  // the upper triangle lands in the upper triangle: no min / max per entry
            // and the separator falls into runs of consecutive parent columns (a variable's
            // at least): each run of a row is one contiguous, vectorised add
            static int run_end[MAX_W];
            for (int b = sc - 1; b >= 0; --b) {
                run_end[b] = b + 1 < sc && map[b + 1] == map[b] + 1 ? run_end[b + 1] : b + 1;
            }
            for (int a = 0; a < sc; ++a) {
                T* row = H[map[a]];
                const T* ua = u + a * (sc + 1);
                for (int b = a; b < sc; b = run_end[b]) {
                    T* dst = row + map[b];
                    const T* src = ua + b;
                    const int n = run_end[b] - b;
                    for (int t = 0; t < n; ++t) dst[t] += src[t];
                }
                row[w] += ua[sc];
            }
            continue;
        }
        for (int a = 0; a < sc; ++a) {
#pragma HLS LOOP_TRIPCOUNT max=30
            for (int b = a; b < sc; ++b) {
#pragma HLS LOOP_TRIPCOUNT max=30
                const int lo = map[a] < map[b] ? map[a] : map[b], hi = map[a] < map[b] ? map[b] : map[a];
                H[lo][hi] += u[a * (sc + 1) + b];
            }
            H[map[a]][w] += u[a * (sc + 1) + sc];
        }
    }
    if (w == 30 && STEP_F[s] == 15) return cholesky_frontal_fixed<30, 15, MAX_LD>(H, s, mu);
    return cholesky_frontal<MAX_LD>(H, w, STEP_F[s], s, mu);
}

// Step pattern 0 (2 steps): W = 30, F = 15, 1 factor(s) and 1 child(ren)
// entering; 630 moves of their structural non-zeros into [H | g].
template <int U>
bool eliminate_pattern_0(int s, T mu) {
    static T H[30][32];
#pragma HLS ARRAY_PARTITION variable=H cyclic factor=20 dim=2
    for (int i = 0; i < 30; ++i) {
        for (int c = 0; c < 32; ++c) H[i][c] = T(0);
    }
    const T* op0 = GRAM + FACTOR_GRAM_OFF[STEP_FACTORS[STEP_FACTOR_BEGIN[s] + 0]];
    const T* op1 = NF + STEP_NF_OFF[STEP_CHILDREN[STEP_CHILD_BEGIN[s] + 0]];
    H[0][0] += op0[0];
    H[0][1] += op0[1];
    H[1][1] += op0[2];
    H[0][2] += op0[3];
    H[1][2] += op0[4];
    H[2][2] += op0[5];
    H[0][3] += op0[6];
    H[1][3] += op0[7];
    H[2][3] += op0[8];
    H[3][3] += op0[9];
    H[0][4] += op0[10];
    H[1][4] += op0[11];
    H[2][4] += op0[12];
    H[3][4] += op0[13];
    H[4][4] += op0[14];
    H[0][5] += op0[15];
    H[1][5] += op0[16];
    H[2][5] += op0[17];
    H[3][5] += op0[18];
    H[4][5] += op0[19];
    H[5][5] += op0[20];
    H[0][6] += op0[21];
    H[1][6] += op0[22];
    H[2][6] += op0[23];
    H[3][6] += op0[24];
    H[4][6] += op0[25];
    H[5][6] += op0[26];
    H[6][6] += op0[27];
    H[0][7] += op0[28];
    H[1][7] += op0[29];
    H[2][7] += op0[30];
    H[3][7] += op0[31];
    H[4][7] += op0[32];
    H[5][7] += op0[33];
    H[6][7] += op0[34];
    H[7][7] += op0[35];
    H[0][8] += op0[36];
    H[1][8] += op0[37];
    H[2][8] += op0[38];
    H[3][8] += op0[39];
    H[4][8] += op0[40];
    H[5][8] += op0[41];
    H[6][8] += op0[42];
    H[7][8] += op0[43];
    H[8][8] += op0[44];
    H[0][15] += op0[45];
    H[1][15] += op0[46];
    H[2][15] += op0[47];
    H[3][15] += op0[48];
    H[4][15] += op0[49];
    H[5][15] += op0[50];
    H[6][15] += op0[51];
    H[7][15] += op0[52];
    H[8][15] += op0[53];
    H[15][15] += op0[54];
    H[0][16] += op0[55];
    H[1][16] += op0[56];
    H[2][16] += op0[57];
    H[3][16] += op0[58];
    H[4][16] += op0[59];
    H[5][16] += op0[60];
    H[6][16] += op0[61];
    H[7][16] += op0[62];
    H[8][16] += op0[63];
    H[15][16] += op0[64];
    H[16][16] += op0[65];
    H[0][17] += op0[66];
    H[1][17] += op0[67];
    H[2][17] += op0[68];
    H[3][17] += op0[69];
    H[4][17] += op0[70];
    H[5][17] += op0[71];
    H[6][17] += op0[72];
    H[7][17] += op0[73];
    H[8][17] += op0[74];
    H[15][17] += op0[75];
    H[16][17] += op0[76];
    H[17][17] += op0[77];
    H[0][18] += op0[78];
    H[1][18] += op0[79];
    H[2][18] += op0[80];
    H[3][18] += op0[81];
    H[4][18] += op0[82];
    H[5][18] += op0[83];
    H[6][18] += op0[84];
    H[7][18] += op0[85];
    H[8][18] += op0[86];
    H[15][18] += op0[87];
    H[16][18] += op0[88];
    H[17][18] += op0[89];
    H[18][18] += op0[90];
    H[0][19] += op0[91];
    H[1][19] += op0[92];
    H[2][19] += op0[93];
    H[3][19] += op0[94];
    H[4][19] += op0[95];
    H[5][19] += op0[96];
    H[6][19] += op0[97];
    H[7][19] += op0[98];
    H[8][19] += op0[99];
    H[15][19] += op0[100];
    H[16][19] += op0[101];
    H[17][19] += op0[102];
    H[18][19] += op0[103];
    H[19][19] += op0[104];
    H[0][20] += op0[105];
    H[1][20] += op0[106];
    H[2][20] += op0[107];
    H[3][20] += op0[108];
    H[4][20] += op0[109];
    H[5][20] += op0[110];
    H[6][20] += op0[111];
    H[7][20] += op0[112];
    H[8][20] += op0[113];
    H[15][20] += op0[114];
    H[16][20] += op0[115];
    H[17][20] += op0[116];
    H[18][20] += op0[117];
    H[19][20] += op0[118];
    H[20][20] += op0[119];
    H[0][21] += op0[120];
    H[1][21] += op0[121];
    H[2][21] += op0[122];
    H[3][21] += op0[123];
    H[4][21] += op0[124];
    H[5][21] += op0[125];
    H[6][21] += op0[126];
    H[7][21] += op0[127];
    H[8][21] += op0[128];
    H[15][21] += op0[129];
    H[16][21] += op0[130];
    H[17][21] += op0[131];
    H[18][21] += op0[132];
    H[19][21] += op0[133];
    H[20][21] += op0[134];
    H[21][21] += op0[135];
    H[0][22] += op0[136];
    H[1][22] += op0[137];
    H[2][22] += op0[138];
    H[3][22] += op0[139];
    H[4][22] += op0[140];
    H[5][22] += op0[141];
    H[6][22] += op0[142];
    H[7][22] += op0[143];
    H[8][22] += op0[144];
    H[15][22] += op0[145];
    H[16][22] += op0[146];
    H[17][22] += op0[147];
    H[18][22] += op0[148];
    H[19][22] += op0[149];
    H[20][22] += op0[150];
    H[21][22] += op0[151];
    H[22][22] += op0[152];
    H[0][23] += op0[153];
    H[1][23] += op0[154];
    H[2][23] += op0[155];
    H[3][23] += op0[156];
    H[4][23] += op0[157];
    H[5][23] += op0[158];
    H[6][23] += op0[159];
    H[7][23] += op0[160];
    H[8][23] += op0[161];
    H[15][23] += op0[162];
    H[16][23] += op0[163];
    H[17][23] += op0[164];
    H[18][23] += op0[165];
    H[19][23] += op0[166];
    H[20][23] += op0[167];
    H[21][23] += op0[168];
    H[22][23] += op0[169];
    H[23][23] += op0[170];
    H[0][9] += op0[171];
    H[1][9] += op0[172];
    H[2][9] += op0[173];
    H[3][9] += op0[174];
    H[4][9] += op0[175];
    H[5][9] += op0[176];
    H[6][9] += op0[177];
    H[7][9] += op0[178];
    H[8][9] += op0[179];
    H[9][15] += op0[180];
    H[9][16] += op0[181];
    H[9][17] += op0[182];
    H[9][18] += op0[183];
    H[9][19] += op0[184];
    H[9][20] += op0[185];
    H[9][21] += op0[186];
    H[9][22] += op0[187];
    H[9][23] += op0[188];
    H[9][9] += op0[189];
    H[0][10] += op0[190];
    H[1][10] += op0[191];
    H[2][10] += op0[192];
    H[3][10] += op0[193];
    H[4][10] += op0[194];
    H[5][10] += op0[195];
    H[6][10] += op0[196];
    H[7][10] += op0[197];
    H[8][10] += op0[198];
    H[10][15] += op0[199];
    H[10][16] += op0[200];
    H[10][17] += op0[201];
    H[10][18] += op0[202];
    H[10][19] += op0[203];
    H[10][20] += op0[204];
    H[10][21] += op0[205];
    H[10][22] += op0[206];
    H[10][23] += op0[207];
    H[9][10] += op0[208];
    H[10][10] += op0[209];
    H[0][11] += op0[210];
    H[1][11] += op0[211];
    H[2][11] += op0[212];
    H[3][11] += op0[213];
    H[4][11] += op0[214];
    H[5][11] += op0[215];
    H[6][11] += op0[216];
    H[7][11] += op0[217];
    H[8][11] += op0[218];
    H[11][15] += op0[219];
    H[11][16] += op0[220];
    H[11][17] += op0[221];
    H[11][18] += op0[222];
    H[11][19] += op0[223];
    H[11][20] += op0[224];
    H[11][21] += op0[225];
    H[11][22] += op0[226];
    H[11][23] += op0[227];
    H[9][11] += op0[228];
    H[10][11] += op0[229];
    H[11][11] += op0[230];
    H[0][12] += op0[231];
    H[1][12] += op0[232];
    H[2][12] += op0[233];
    H[3][12] += op0[234];
    H[4][12] += op0[235];
    H[5][12] += op0[236];
    H[6][12] += op0[237];
    H[7][12] += op0[238];
    H[8][12] += op0[239];
    H[12][15] += op0[240];
    H[12][16] += op0[241];
    H[12][17] += op0[242];
    H[12][18] += op0[243];
    H[12][19] += op0[244];
    H[12][20] += op0[245];
    H[12][21] += op0[246];
    H[12][22] += op0[247];
    H[12][23] += op0[248];
    H[9][12] += op0[249];
    H[10][12] += op0[250];
    H[11][12] += op0[251];
    H[12][12] += op0[252];
    H[0][13] += op0[253];
    H[1][13] += op0[254];
    H[2][13] += op0[255];
    H[3][13] += op0[256];
    H[4][13] += op0[257];
    H[5][13] += op0[258];
    H[6][13] += op0[259];
    H[7][13] += op0[260];
    H[8][13] += op0[261];
    H[13][15] += op0[262];
    H[13][16] += op0[263];
    H[13][17] += op0[264];
    H[13][18] += op0[265];
    H[13][19] += op0[266];
    H[13][20] += op0[267];
    H[13][21] += op0[268];
    H[13][22] += op0[269];
    H[13][23] += op0[270];
    H[9][13] += op0[271];
    H[10][13] += op0[272];
    H[11][13] += op0[273];
    H[12][13] += op0[274];
    H[13][13] += op0[275];
    H[0][14] += op0[276];
    H[1][14] += op0[277];
    H[2][14] += op0[278];
    H[3][14] += op0[279];
    H[4][14] += op0[280];
    H[5][14] += op0[281];
    H[6][14] += op0[282];
    H[7][14] += op0[283];
    H[8][14] += op0[284];
    H[14][15] += op0[285];
    H[14][16] += op0[286];
    H[14][17] += op0[287];
    H[14][18] += op0[288];
    H[14][19] += op0[289];
    H[14][20] += op0[290];
    H[14][21] += op0[291];
    H[14][22] += op0[292];
    H[14][23] += op0[293];
    H[9][14] += op0[294];
    H[10][14] += op0[295];
    H[11][14] += op0[296];
    H[12][14] += op0[297];
    H[13][14] += op0[298];
    H[14][14] += op0[299];
    H[0][24] += op0[300];
    H[1][24] += op0[301];
    H[2][24] += op0[302];
    H[3][24] += op0[303];
    H[4][24] += op0[304];
    H[5][24] += op0[305];
    H[6][24] += op0[306];
    H[7][24] += op0[307];
    H[8][24] += op0[308];
    H[15][24] += op0[309];
    H[16][24] += op0[310];
    H[17][24] += op0[311];
    H[18][24] += op0[312];
    H[19][24] += op0[313];
    H[20][24] += op0[314];
    H[21][24] += op0[315];
    H[22][24] += op0[316];
    H[23][24] += op0[317];
    H[9][24] += op0[318];
    H[10][24] += op0[319];
    H[11][24] += op0[320];
    H[12][24] += op0[321];
    H[13][24] += op0[322];
    H[14][24] += op0[323];
    H[24][24] += op0[324];
    H[0][25] += op0[325];
    H[1][25] += op0[326];
    H[2][25] += op0[327];
    H[3][25] += op0[328];
    H[4][25] += op0[329];
    H[5][25] += op0[330];
    H[6][25] += op0[331];
    H[7][25] += op0[332];
    H[8][25] += op0[333];
    H[15][25] += op0[334];
    H[16][25] += op0[335];
    H[17][25] += op0[336];
    H[18][25] += op0[337];
    H[19][25] += op0[338];
    H[20][25] += op0[339];
    H[21][25] += op0[340];
    H[22][25] += op0[341];
    H[23][25] += op0[342];
    H[9][25] += op0[343];
    H[10][25] += op0[344];
    H[11][25] += op0[345];
    H[12][25] += op0[346];
    H[13][25] += op0[347];
    H[14][25] += op0[348];
    H[24][25] += op0[349];
    H[25][25] += op0[350];
    H[0][26] += op0[351];
    H[1][26] += op0[352];
    H[2][26] += op0[353];
    H[3][26] += op0[354];
    H[4][26] += op0[355];
    H[5][26] += op0[356];
    H[6][26] += op0[357];
    H[7][26] += op0[358];
    H[8][26] += op0[359];
    H[15][26] += op0[360];
    H[16][26] += op0[361];
    H[17][26] += op0[362];
    H[18][26] += op0[363];
    H[19][26] += op0[364];
    H[20][26] += op0[365];
    H[21][26] += op0[366];
    H[22][26] += op0[367];
    H[23][26] += op0[368];
    H[9][26] += op0[369];
    H[10][26] += op0[370];
    H[11][26] += op0[371];
    H[12][26] += op0[372];
    H[13][26] += op0[373];
    H[14][26] += op0[374];
    H[24][26] += op0[375];
    H[25][26] += op0[376];
    H[26][26] += op0[377];
    H[0][27] += op0[378];
    H[1][27] += op0[379];
    H[2][27] += op0[380];
    H[3][27] += op0[381];
    H[4][27] += op0[382];
    H[5][27] += op0[383];
    H[6][27] += op0[384];
    H[7][27] += op0[385];
    H[8][27] += op0[386];
    H[15][27] += op0[387];
    H[16][27] += op0[388];
    H[17][27] += op0[389];
    H[18][27] += op0[390];
    H[19][27] += op0[391];
    H[20][27] += op0[392];
    H[21][27] += op0[393];
    H[22][27] += op0[394];
    H[23][27] += op0[395];
    H[9][27] += op0[396];
    H[10][27] += op0[397];
    H[11][27] += op0[398];
    H[12][27] += op0[399];
    H[13][27] += op0[400];
    H[14][27] += op0[401];
    H[24][27] += op0[402];
    H[25][27] += op0[403];
    H[26][27] += op0[404];
    H[27][27] += op0[405];
    H[0][28] += op0[406];
    H[1][28] += op0[407];
    H[2][28] += op0[408];
    H[3][28] += op0[409];
    H[4][28] += op0[410];
    H[5][28] += op0[411];
    H[6][28] += op0[412];
    H[7][28] += op0[413];
    H[8][28] += op0[414];
    H[15][28] += op0[415];
    H[16][28] += op0[416];
    H[17][28] += op0[417];
    H[18][28] += op0[418];
    H[19][28] += op0[419];
    H[20][28] += op0[420];
    H[21][28] += op0[421];
    H[22][28] += op0[422];
    H[23][28] += op0[423];
    H[9][28] += op0[424];
    H[10][28] += op0[425];
    H[11][28] += op0[426];
    H[12][28] += op0[427];
    H[13][28] += op0[428];
    H[14][28] += op0[429];
    H[24][28] += op0[430];
    H[25][28] += op0[431];
    H[26][28] += op0[432];
    H[27][28] += op0[433];
    H[28][28] += op0[434];
    H[0][29] += op0[435];
    H[1][29] += op0[436];
    H[2][29] += op0[437];
    H[3][29] += op0[438];
    H[4][29] += op0[439];
    H[5][29] += op0[440];
    H[6][29] += op0[441];
    H[7][29] += op0[442];
    H[8][29] += op0[443];
    H[15][29] += op0[444];
    H[16][29] += op0[445];
    H[17][29] += op0[446];
    H[18][29] += op0[447];
    H[19][29] += op0[448];
    H[20][29] += op0[449];
    H[21][29] += op0[450];
    H[22][29] += op0[451];
    H[23][29] += op0[452];
    H[9][29] += op0[453];
    H[10][29] += op0[454];
    H[11][29] += op0[455];
    H[12][29] += op0[456];
    H[13][29] += op0[457];
    H[14][29] += op0[458];
    H[24][29] += op0[459];
    H[25][29] += op0[460];
    H[26][29] += op0[461];
    H[27][29] += op0[462];
    H[28][29] += op0[463];
    H[29][29] += op0[464];
    H[0][30] += op0[465];
    H[1][30] += op0[466];
    H[2][30] += op0[467];
    H[3][30] += op0[468];
    H[4][30] += op0[469];
    H[5][30] += op0[470];
    H[6][30] += op0[471];
    H[7][30] += op0[472];
    H[8][30] += op0[473];
    H[15][30] += op0[474];
    H[16][30] += op0[475];
    H[17][30] += op0[476];
    H[18][30] += op0[477];
    H[19][30] += op0[478];
    H[20][30] += op0[479];
    H[21][30] += op0[480];
    H[22][30] += op0[481];
    H[23][30] += op0[482];
    H[9][30] += op0[483];
    H[10][30] += op0[484];
    H[11][30] += op0[485];
    H[12][30] += op0[486];
    H[13][30] += op0[487];
    H[14][30] += op0[488];
    H[24][30] += op0[489];
    H[25][30] += op0[490];
    H[26][30] += op0[491];
    H[27][30] += op0[492];
    H[28][30] += op0[493];
    H[29][30] += op0[494];
    H[0][0] += op1[0];
    H[0][1] += op1[1];
    H[0][2] += op1[2];
    H[0][3] += op1[3];
    H[0][4] += op1[4];
    H[0][5] += op1[5];
    H[0][6] += op1[6];
    H[0][7] += op1[7];
    H[0][8] += op1[8];
    H[0][9] += op1[9];
    H[0][10] += op1[10];
    H[0][11] += op1[11];
    H[0][12] += op1[12];
    H[0][13] += op1[13];
    H[0][14] += op1[14];
    H[0][30] += op1[15];
    H[1][1] += op1[17];
    H[1][2] += op1[18];
    H[1][3] += op1[19];
    H[1][4] += op1[20];
    H[1][5] += op1[21];
    H[1][6] += op1[22];
    H[1][7] += op1[23];
    H[1][8] += op1[24];
    H[1][9] += op1[25];
    H[1][10] += op1[26];
    H[1][11] += op1[27];
    H[1][12] += op1[28];
    H[1][13] += op1[29];
    H[1][14] += op1[30];
    H[1][30] += op1[31];
    H[2][2] += op1[34];
    H[2][3] += op1[35];
    H[2][4] += op1[36];
    H[2][5] += op1[37];
    H[2][6] += op1[38];
    H[2][7] += op1[39];
    H[2][8] += op1[40];
    H[2][9] += op1[41];
    H[2][10] += op1[42];
    H[2][11] += op1[43];
    H[2][12] += op1[44];
    H[2][13] += op1[45];
    H[2][14] += op1[46];
    H[2][30] += op1[47];
    H[3][3] += op1[51];
    H[3][4] += op1[52];
    H[3][5] += op1[53];
    H[3][6] += op1[54];
    H[3][7] += op1[55];
    H[3][8] += op1[56];
    H[3][9] += op1[57];
    H[3][10] += op1[58];
    H[3][11] += op1[59];
    H[3][12] += op1[60];
    H[3][13] += op1[61];
    H[3][14] += op1[62];
    H[3][30] += op1[63];
    H[4][4] += op1[68];
    H[4][5] += op1[69];
    H[4][6] += op1[70];
    H[4][7] += op1[71];
    H[4][8] += op1[72];
    H[4][9] += op1[73];
    H[4][10] += op1[74];
    H[4][11] += op1[75];
    H[4][12] += op1[76];
    H[4][13] += op1[77];
    H[4][14] += op1[78];
    H[4][30] += op1[79];
    H[5][5] += op1[85];
    H[5][6] += op1[86];
    H[5][7] += op1[87];
    H[5][8] += op1[88];
    H[5][9] += op1[89];
    H[5][10] += op1[90];
    H[5][11] += op1[91];
    H[5][12] += op1[92];
    H[5][13] += op1[93];
    H[5][14] += op1[94];
    H[5][30] += op1[95];
    H[6][6] += op1[102];
    H[6][7] += op1[103];
    H[6][8] += op1[104];
    H[6][9] += op1[105];
    H[6][10] += op1[106];
    H[6][11] += op1[107];
    H[6][12] += op1[108];
    H[6][13] += op1[109];
    H[6][14] += op1[110];
    H[6][30] += op1[111];
    H[7][7] += op1[119];
    H[7][8] += op1[120];
    H[7][9] += op1[121];
    H[7][10] += op1[122];
    H[7][11] += op1[123];
    H[7][12] += op1[124];
    H[7][13] += op1[125];
    H[7][14] += op1[126];
    H[7][30] += op1[127];
    H[8][8] += op1[136];
    H[8][9] += op1[137];
    H[8][10] += op1[138];
    H[8][11] += op1[139];
    H[8][12] += op1[140];
    H[8][13] += op1[141];
    H[8][14] += op1[142];
    H[8][30] += op1[143];
    H[9][9] += op1[153];
    H[9][10] += op1[154];
    H[9][11] += op1[155];
    H[9][12] += op1[156];
    H[9][13] += op1[157];
    H[9][14] += op1[158];
    H[9][30] += op1[159];
    H[10][10] += op1[170];
    H[10][11] += op1[171];
    H[10][12] += op1[172];
    H[10][13] += op1[173];
    H[10][14] += op1[174];
    H[10][30] += op1[175];
    H[11][11] += op1[187];
    H[11][12] += op1[188];
    H[11][13] += op1[189];
    H[11][14] += op1[190];
    H[11][30] += op1[191];
    H[12][12] += op1[204];
    H[12][13] += op1[205];
    H[12][14] += op1[206];
    H[12][30] += op1[207];
    H[13][13] += op1[221];
    H[13][14] += op1[222];
    H[13][30] += op1[223];
    H[14][14] += op1[238];
    H[14][30] += op1[239];
    return cholesky_frontal_fixed<30, 15, 32>(H, s, mu);
}

// Step pattern 1 (2 steps): W = 30, F = 15, 1 factor(s) and 1 child(ren)
// entering; 630 moves of their structural non-zeros into [H | g].
template <int U>
bool eliminate_pattern_1(int s, T mu) {
    static T H[30][32];
#pragma HLS ARRAY_PARTITION variable=H cyclic factor=20 dim=2
    for (int i = 0; i < 30; ++i) {
        for (int c = 0; c < 32; ++c) H[i][c] = T(0);
    }
    const T* op0 = GRAM + FACTOR_GRAM_OFF[STEP_FACTORS[STEP_FACTOR_BEGIN[s] + 0]];
    const T* op1 = NF + STEP_NF_OFF[STEP_CHILDREN[STEP_CHILD_BEGIN[s] + 0]];
    H[15][15] += op0[0];
    H[15][16] += op0[1];
    H[16][16] += op0[2];
    H[15][17] += op0[3];
    H[16][17] += op0[4];
    H[17][17] += op0[5];
    H[15][18] += op0[6];
    H[16][18] += op0[7];
    H[17][18] += op0[8];
    H[18][18] += op0[9];
    H[15][19] += op0[10];
    H[16][19] += op0[11];
    H[17][19] += op0[12];
    H[18][19] += op0[13];
    H[19][19] += op0[14];
    H[15][20] += op0[15];
    H[16][20] += op0[16];
    H[17][20] += op0[17];
    H[18][20] += op0[18];
    H[19][20] += op0[19];
    H[20][20] += op0[20];
    H[15][21] += op0[21];
    H[16][21] += op0[22];
    H[17][21] += op0[23];
    H[18][21] += op0[24];
    H[19][21] += op0[25];
    H[20][21] += op0[26];
    H[21][21] += op0[27];
    H[15][22] += op0[28];
    H[16][22] += op0[29];
    H[17][22] += op0[30];
    H[18][22] += op0[31];
    H[19][22] += op0[32];
    H[20][22] += op0[33];
    H[21][22] += op0[34];
    H[22][22] += op0[35];
    H[15][23] += op0[36];
    H[16][23] += op0[37];
    H[17][23] += op0[38];
    H[18][23] += op0[39];
    H[19][23] += op0[40];
    H[20][23] += op0[41];
    H[21][23] += op0[42];
    H[22][23] += op0[43];
    H[23][23] += op0[44];
    H[0][15] += op0[45];
    H[0][16] += op0[46];
    H[0][17] += op0[47];
    H[0][18] += op0[48];
    H[0][19] += op0[49];
    H[0][20] += op0[50];
    H[0][21] += op0[51];
    H[0][22] += op0[52];
    H[0][23] += op0[53];
    H[0][0] += op0[54];
    H[1][15] += op0[55];
    H[1][16] += op0[56];
    H[1][17] += op0[57];
    H[1][18] += op0[58];
    H[1][19] += op0[59];
    H[1][20] += op0[60];
    H[1][21] += op0[61];
    H[1][22] += op0[62];
    H[1][23] += op0[63];
    H[0][1] += op0[64];
    H[1][1] += op0[65];
    H[2][15] += op0[66];
    H[2][16] += op0[67];
    H[2][17] += op0[68];
    H[2][18] += op0[69];
    H[2][19] += op0[70];
    H[2][20] += op0[71];
    H[2][21] += op0[72];
    H[2][22] += op0[73];
    H[2][23] += op0[74];
    H[0][2] += op0[75];
    H[1][2] += op0[76];
    H[2][2] += op0[77];
    H[3][15] += op0[78];
    H[3][16] += op0[79];
    H[3][17] += op0[80];
    H[3][18] += op0[81];
    H[3][19] += op0[82];
    H[3][20] += op0[83];
    H[3][21] += op0[84];
    H[3][22] += op0[85];
    H[3][23] += op0[86];
    H[0][3] += op0[87];
    H[1][3] += op0[88];
    H[2][3] += op0[89];
    H[3][3] += op0[90];
    H[4][15] += op0[91];
    H[4][16] += op0[92];
    H[4][17] += op0[93];
    H[4][18] += op0[94];
    H[4][19] += op0[95];
    H[4][20] += op0[96];
    H[4][21] += op0[97];
    H[4][22] += op0[98];
    H[4][23] += op0[99];
    H[0][4] += op0[100];
    H[1][4] += op0[101];
    H[2][4] += op0[102];
    H[3][4] += op0[103];
    H[4][4] += op0[104];
    H[5][15] += op0[105];
    H[5][16] += op0[106];
    H[5][17] += op0[107];
    H[5][18] += op0[108];
    H[5][19] += op0[109];
    H[5][20] += op0[110];
    H[5][21] += op0[111];
    H[5][22] += op0[112];
    H[5][23] += op0[113];
    H[0][5] += op0[114];
    H[1][5] += op0[115];
    H[2][5] += op0[116];
    H[3][5] += op0[117];
    H[4][5] += op0[118];
    H[5][5] += op0[119];
    H[6][15] += op0[120];
    H[6][16] += op0[121];
    H[6][17] += op0[122];
    H[6][18] += op0[123];
    H[6][19] += op0[124];
    H[6][20] += op0[125];
    H[6][21] += op0[126];
    H[6][22] += op0[127];
    H[6][23] += op0[128];
    H[0][6] += op0[129];
    H[1][6] += op0[130];
    H[2][6] += op0[131];
    H[3][6] += op0[132];
    H[4][6] += op0[133];
    H[5][6] += op0[134];
    H[6][6] += op0[135];
    H[7][15] += op0[136];
    H[7][16] += op0[137];
    H[7][17] += op0[138];
    H[7][18] += op0[139];
    H[7][19] += op0[140];
    H[7][20] += op0[141];
    H[7][21] += op0[142];
    H[7][22] += op0[143];
    H[7][23] += op0[144];
    H[0][7] += op0[145];
    H[1][7] += op0[146];
    H[2][7] += op0[147];
    H[3][7] += op0[148];
    H[4][7] += op0[149];
    H[5][7] += op0[150];
    H[6][7] += op0[151];
    H[7][7] += op0[152];
    H[8][15] += op0[153];
    H[8][16] += op0[154];
    H[8][17] += op0[155];
    H[8][18] += op0[156];
    H[8][19] += op0[157];
    H[8][20] += op0[158];
    H[8][21] += op0[159];
    H[8][22] += op0[160];
    H[8][23] += op0[161];
    H[0][8] += op0[162];
    H[1][8] += op0[163];
    H[2][8] += op0[164];
    H[3][8] += op0[165];
    H[4][8] += op0[166];
    H[5][8] += op0[167];
    H[6][8] += op0[168];
    H[7][8] += op0[169];
    H[8][8] += op0[170];
    H[15][24] += op0[171];
    H[16][24] += op0[172];
    H[17][24] += op0[173];
    H[18][24] += op0[174];
    H[19][24] += op0[175];
    H[20][24] += op0[176];
    H[21][24] += op0[177];
    H[22][24] += op0[178];
    H[23][24] += op0[179];
    H[0][24] += op0[180];
    H[1][24] += op0[181];
    H[2][24] += op0[182];
    H[3][24] += op0[183];
    H[4][24] += op0[184];
    H[5][24] += op0[185];
    H[6][24] += op0[186];
    H[7][24] += op0[187];
    H[8][24] += op0[188];
    H[24][24] += op0[189];
    H[15][25] += op0[190];
    H[16][25] += op0[191];
    H[17][25] += op0[192];
    H[18][25] += op0[193];
    H[19][25] += op0[194];
    H[20][25] += op0[195];
    H[21][25] += op0[196];
    H[22][25] += op0[197];
    H[23][25] += op0[198];
    H[0][25] += op0[199];
    H[1][25] += op0[200];
    H[2][25] += op0[201];
    H[3][25] += op0[202];
    H[4][25] += op0[203];
    H[5][25] += op0[204];
    H[6][25] += op0[205];
    H[7][25] += op0[206];
    H[8][25] += op0[207];
    H[24][25] += op0[208];
    H[25][25] += op0[209];
    H[15][26] += op0[210];
    H[16][26] += op0[211];
    H[17][26] += op0[212];
    H[18][26] += op0[213];
    H[19][26] += op0[214];
    H[20][26] += op0[215];
    H[21][26] += op0[216];
    H[22][26] += op0[217];
    H[23][26] += op0[218];
    H[0][26] += op0[219];
    H[1][26] += op0[220];
    H[2][26] += op0[221];
    H[3][26] += op0[222];
    H[4][26] += op0[223];
    H[5][26] += op0[224];
    H[6][26] += op0[225];
    H[7][26] += op0[226];
    H[8][26] += op0[227];
    H[24][26] += op0[228];
    H[25][26] += op0[229];
    H[26][26] += op0[230];
    H[15][27] += op0[231];
    H[16][27] += op0[232];
    H[17][27] += op0[233];
    H[18][27] += op0[234];
    H[19][27] += op0[235];
    H[20][27] += op0[236];
    H[21][27] += op0[237];
    H[22][27] += op0[238];
    H[23][27] += op0[239];
    H[0][27] += op0[240];
    H[1][27] += op0[241];
    H[2][27] += op0[242];
    H[3][27] += op0[243];
    H[4][27] += op0[244];
    H[5][27] += op0[245];
    H[6][27] += op0[246];
    H[7][27] += op0[247];
    H[8][27] += op0[248];
    H[24][27] += op0[249];
    H[25][27] += op0[250];
    H[26][27] += op0[251];
    H[27][27] += op0[252];
    H[15][28] += op0[253];
    H[16][28] += op0[254];
    H[17][28] += op0[255];
    H[18][28] += op0[256];
    H[19][28] += op0[257];
    H[20][28] += op0[258];
    H[21][28] += op0[259];
    H[22][28] += op0[260];
    H[23][28] += op0[261];
    H[0][28] += op0[262];
    H[1][28] += op0[263];
    H[2][28] += op0[264];
    H[3][28] += op0[265];
    H[4][28] += op0[266];
    H[5][28] += op0[267];
    H[6][28] += op0[268];
    H[7][28] += op0[269];
    H[8][28] += op0[270];
    H[24][28] += op0[271];
    H[25][28] += op0[272];
    H[26][28] += op0[273];
    H[27][28] += op0[274];
    H[28][28] += op0[275];
    H[15][29] += op0[276];
    H[16][29] += op0[277];
    H[17][29] += op0[278];
    H[18][29] += op0[279];
    H[19][29] += op0[280];
    H[20][29] += op0[281];
    H[21][29] += op0[282];
    H[22][29] += op0[283];
    H[23][29] += op0[284];
    H[0][29] += op0[285];
    H[1][29] += op0[286];
    H[2][29] += op0[287];
    H[3][29] += op0[288];
    H[4][29] += op0[289];
    H[5][29] += op0[290];
    H[6][29] += op0[291];
    H[7][29] += op0[292];
    H[8][29] += op0[293];
    H[24][29] += op0[294];
    H[25][29] += op0[295];
    H[26][29] += op0[296];
    H[27][29] += op0[297];
    H[28][29] += op0[298];
    H[29][29] += op0[299];
    H[9][15] += op0[300];
    H[9][16] += op0[301];
    H[9][17] += op0[302];
    H[9][18] += op0[303];
    H[9][19] += op0[304];
    H[9][20] += op0[305];
    H[9][21] += op0[306];
    H[9][22] += op0[307];
    H[9][23] += op0[308];
    H[0][9] += op0[309];
    H[1][9] += op0[310];
    H[2][9] += op0[311];
    H[3][9] += op0[312];
    H[4][9] += op0[313];
    H[5][9] += op0[314];
    H[6][9] += op0[315];
    H[7][9] += op0[316];
    H[8][9] += op0[317];
    H[9][24] += op0[318];
    H[9][25] += op0[319];
    H[9][26] += op0[320];
    H[9][27] += op0[321];
    H[9][28] += op0[322];
    H[9][29] += op0[323];
    H[9][9] += op0[324];
    H[10][15] += op0[325];
    H[10][16] += op0[326];
    H[10][17] += op0[327];
    H[10][18] += op0[328];
    H[10][19] += op0[329];
    H[10][20] += op0[330];
    H[10][21] += op0[331];
    H[10][22] += op0[332];
    H[10][23] += op0[333];
    H[0][10] += op0[334];
    H[1][10] += op0[335];
    H[2][10] += op0[336];
    H[3][10] += op0[337];
    H[4][10] += op0[338];
    H[5][10] += op0[339];
    H[6][10] += op0[340];
    H[7][10] += op0[341];
    H[8][10] += op0[342];
    H[10][24] += op0[343];
    H[10][25] += op0[344];
    H[10][26] += op0[345];
    H[10][27] += op0[346];
    H[10][28] += op0[347];
    H[10][29] += op0[348];
    H[9][10] += op0[349];
    H[10][10] += op0[350];
    H[11][15] += op0[351];
    H[11][16] += op0[352];
    H[11][17] += op0[353];
    H[11][18] += op0[354];
    H[11][19] += op0[355];
    H[11][20] += op0[356];
    H[11][21] += op0[357];
    H[11][22] += op0[358];
    H[11][23] += op0[359];
    H[0][11] += op0[360];
    H[1][11] += op0[361];
    H[2][11] += op0[362];
    H[3][11] += op0[363];
    H[4][11] += op0[364];
    H[5][11] += op0[365];
    H[6][11] += op0[366];
    H[7][11] += op0[367];
    H[8][11] += op0[368];
    H[11][24] += op0[369];
    H[11][25] += op0[370];
    H[11][26] += op0[371];
    H[11][27] += op0[372];
    H[11][28] += op0[373];
    H[11][29] += op0[374];
    H[9][11] += op0[375];
    H[10][11] += op0[376];
    H[11][11] += op0[377];
    H[12][15] += op0[378];
    H[12][16] += op0[379];
    H[12][17] += op0[380];
    H[12][18] += op0[381];
    H[12][19] += op0[382];
    H[12][20] += op0[383];
    H[12][21] += op0[384];
    H[12][22] += op0[385];
    H[12][23] += op0[386];
    H[0][12] += op0[387];
    H[1][12] += op0[388];
    H[2][12] += op0[389];
    H[3][12] += op0[390];
    H[4][12] += op0[391];
    H[5][12] += op0[392];
    H[6][12] += op0[393];
    H[7][12] += op0[394];
    H[8][12] += op0[395];
    H[12][24] += op0[396];
    H[12][25] += op0[397];
    H[12][26] += op0[398];
    H[12][27] += op0[399];
    H[12][28] += op0[400];
    H[12][29] += op0[401];
    H[9][12] += op0[402];
    H[10][12] += op0[403];
    H[11][12] += op0[404];
    H[12][12] += op0[405];
    H[13][15] += op0[406];
    H[13][16] += op0[407];
    H[13][17] += op0[408];
    H[13][18] += op0[409];
    H[13][19] += op0[410];
    H[13][20] += op0[411];
    H[13][21] += op0[412];
    H[13][22] += op0[413];
    H[13][23] += op0[414];
    H[0][13] += op0[415];
    H[1][13] += op0[416];
    H[2][13] += op0[417];
    H[3][13] += op0[418];
    H[4][13] += op0[419];
    H[5][13] += op0[420];
    H[6][13] += op0[421];
    H[7][13] += op0[422];
    H[8][13] += op0[423];
    H[13][24] += op0[424];
    H[13][25] += op0[425];
    H[13][26] += op0[426];
    H[13][27] += op0[427];
    H[13][28] += op0[428];
    H[13][29] += op0[429];
    H[9][13] += op0[430];
    H[10][13] += op0[431];
    H[11][13] += op0[432];
    H[12][13] += op0[433];
    H[13][13] += op0[434];
    H[14][15] += op0[435];
    H[14][16] += op0[436];
    H[14][17] += op0[437];
    H[14][18] += op0[438];
    H[14][19] += op0[439];
    H[14][20] += op0[440];
    H[14][21] += op0[441];
    H[14][22] += op0[442];
    H[14][23] += op0[443];
    H[0][14] += op0[444];
    H[1][14] += op0[445];
    H[2][14] += op0[446];
    H[3][14] += op0[447];
    H[4][14] += op0[448];
    H[5][14] += op0[449];
    H[6][14] += op0[450];
    H[7][14] += op0[451];
    H[8][14] += op0[452];
    H[14][24] += op0[453];
    H[14][25] += op0[454];
    H[14][26] += op0[455];
    H[14][27] += op0[456];
    H[14][28] += op0[457];
    H[14][29] += op0[458];
    H[9][14] += op0[459];
    H[10][14] += op0[460];
    H[11][14] += op0[461];
    H[12][14] += op0[462];
    H[13][14] += op0[463];
    H[14][14] += op0[464];
    H[15][30] += op0[465];
    H[16][30] += op0[466];
    H[17][30] += op0[467];
    H[18][30] += op0[468];
    H[19][30] += op0[469];
    H[20][30] += op0[470];
    H[21][30] += op0[471];
    H[22][30] += op0[472];
    H[23][30] += op0[473];
    H[0][30] += op0[474];
    H[1][30] += op0[475];
    H[2][30] += op0[476];
    H[3][30] += op0[477];
    H[4][30] += op0[478];
    H[5][30] += op0[479];
    H[6][30] += op0[480];
    H[7][30] += op0[481];
    H[8][30] += op0[482];
    H[24][30] += op0[483];
    H[25][30] += op0[484];
    H[26][30] += op0[485];
    H[27][30] += op0[486];
    H[28][30] += op0[487];
    H[29][30] += op0[488];
    H[9][30] += op0[489];
    H[10][30] += op0[490];
    H[11][30] += op0[491];
    H[12][30] += op0[492];
    H[13][30] += op0[493];
    H[14][30] += op0[494];
    H[0][0] += op1[0];
    H[0][1] += op1[1];
    H[0][2] += op1[2];
    H[0][3] += op1[3];
    H[0][4] += op1[4];
    H[0][5] += op1[5];
    H[0][6] += op1[6];
    H[0][7] += op1[7];
    H[0][8] += op1[8];
    H[0][9] += op1[9];
    H[0][10] += op1[10];
    H[0][11] += op1[11];
    H[0][12] += op1[12];
    H[0][13] += op1[13];
    H[0][14] += op1[14];
    H[0][30] += op1[15];
    H[1][1] += op1[17];
    H[1][2] += op1[18];
    H[1][3] += op1[19];
    H[1][4] += op1[20];
    H[1][5] += op1[21];
    H[1][6] += op1[22];
    H[1][7] += op1[23];
    H[1][8] += op1[24];
    H[1][9] += op1[25];
    H[1][10] += op1[26];
    H[1][11] += op1[27];
    H[1][12] += op1[28];
    H[1][13] += op1[29];
    H[1][14] += op1[30];
    H[1][30] += op1[31];
    H[2][2] += op1[34];
    H[2][3] += op1[35];
    H[2][4] += op1[36];
    H[2][5] += op1[37];
    H[2][6] += op1[38];
    H[2][7] += op1[39];
    H[2][8] += op1[40];
    H[2][9] += op1[41];
    H[2][10] += op1[42];
    H[2][11] += op1[43];
    H[2][12] += op1[44];
    H[2][13] += op1[45];
    H[2][14] += op1[46];
    H[2][30] += op1[47];
    H[3][3] += op1[51];
    H[3][4] += op1[52];
    H[3][5] += op1[53];
    H[3][6] += op1[54];
    H[3][7] += op1[55];
    H[3][8] += op1[56];
    H[3][9] += op1[57];
    H[3][10] += op1[58];
    H[3][11] += op1[59];
    H[3][12] += op1[60];
    H[3][13] += op1[61];
    H[3][14] += op1[62];
    H[3][30] += op1[63];
    H[4][4] += op1[68];
    H[4][5] += op1[69];
    H[4][6] += op1[70];
    H[4][7] += op1[71];
    H[4][8] += op1[72];
    H[4][9] += op1[73];
    H[4][10] += op1[74];
    H[4][11] += op1[75];
    H[4][12] += op1[76];
    H[4][13] += op1[77];
    H[4][14] += op1[78];
    H[4][30] += op1[79];
    H[5][5] += op1[85];
    H[5][6] += op1[86];
    H[5][7] += op1[87];
    H[5][8] += op1[88];
    H[5][9] += op1[89];
    H[5][10] += op1[90];
    H[5][11] += op1[91];
    H[5][12] += op1[92];
    H[5][13] += op1[93];
    H[5][14] += op1[94];
    H[5][30] += op1[95];
    H[6][6] += op1[102];
    H[6][7] += op1[103];
    H[6][8] += op1[104];
    H[6][9] += op1[105];
    H[6][10] += op1[106];
    H[6][11] += op1[107];
    H[6][12] += op1[108];
    H[6][13] += op1[109];
    H[6][14] += op1[110];
    H[6][30] += op1[111];
    H[7][7] += op1[119];
    H[7][8] += op1[120];
    H[7][9] += op1[121];
    H[7][10] += op1[122];
    H[7][11] += op1[123];
    H[7][12] += op1[124];
    H[7][13] += op1[125];
    H[7][14] += op1[126];
    H[7][30] += op1[127];
    H[8][8] += op1[136];
    H[8][9] += op1[137];
    H[8][10] += op1[138];
    H[8][11] += op1[139];
    H[8][12] += op1[140];
    H[8][13] += op1[141];
    H[8][14] += op1[142];
    H[8][30] += op1[143];
    H[9][9] += op1[153];
    H[9][10] += op1[154];
    H[9][11] += op1[155];
    H[9][12] += op1[156];
    H[9][13] += op1[157];
    H[9][14] += op1[158];
    H[9][30] += op1[159];
    H[10][10] += op1[170];
    H[10][11] += op1[171];
    H[10][12] += op1[172];
    H[10][13] += op1[173];
    H[10][14] += op1[174];
    H[10][30] += op1[175];
    H[11][11] += op1[187];
    H[11][12] += op1[188];
    H[11][13] += op1[189];
    H[11][14] += op1[190];
    H[11][30] += op1[191];
    H[12][12] += op1[204];
    H[12][13] += op1[205];
    H[12][14] += op1[206];
    H[12][30] += op1[207];
    H[13][13] += op1[221];
    H[13][14] += op1[222];
    H[13][30] += op1[223];
    H[14][14] += op1[238];
    H[14][30] += op1[239];
    return cholesky_frontal_fixed<30, 15, 32>(H, s, mu);
}
#pragma GCC diagnostic pop

// One step through its specialised routine, or the generic one.
template <int U>
bool eliminate(int s, T mu) {
    switch (STEP_PATTERN[s]) {
    case 0:
        return eliminate_pattern_0<U>(s, mu);
    case 1:
        return eliminate_pattern_1<U>(s, mu);
    default:
        return eliminate_step<U>(s, mu);
    }
}

// Eliminate every step, level by level (a level's steps are independent: the unit sets take
// them 2 at a time), then back-substitute root first. False if singular.
bool solve(T mu) {
    bool ok = true;
    for (int l = 0; l < N_LEVELS; ++l) {
        for (int i = LEVEL_BEGIN[l]; i < LEVEL_BEGIN[l + 1]; i += UNIT_SETS) {
#pragma HLS LOOP_TRIPCOUNT max=2
#pragma HLS DATAFLOW
            if (i + 0 < LEVEL_BEGIN[l + 1]) ok = eliminate<0>(LEVEL_STEPS[i + 0], mu) && ok;
            if (i + 1 < LEVEL_BEGIN[l + 1]) ok = eliminate<1>(LEVEL_STEPS[i + 1], mu) && ok;
        }
    }
    if (!ok) return false;
    for (int l = N_LEVELS - 1; l >= 0; --l) {
        for (int i = LEVEL_BEGIN[l]; i < LEVEL_BEGIN[l + 1]; ++i) {
#pragma HLS LOOP_TRIPCOUNT max=2
            const int s = LEVEL_STEPS[i];
            const int w = STEP_W[s], f = STEP_F[s];
            const int* cols = STEP_COL + STEP_COL_BEGIN[s];
            const T* cond = COND + STEP_COND_OFF[s];
            T xs[MAX_W];
            for (int c = f; c < w; ++c) {
#pragma HLS LOOP_TRIPCOUNT max=30
                xs[c] = DELTA[cols[c]];
            }
            // the separator's share of every row first: the rows do not wait for each other
            T rhs[MAX_F];
            for (int r = 0; r < f; ++r) {
#pragma HLS LOOP_TRIPCOUNT max=30
                const T* row = cond + r * (w + 1);
                T part[TILE];  // TILE interleaved partial sums: a fixed order, short chains
                for (int t = 0; t < TILE; ++t) part[t] = T(0);
                int c = f;
                for (; c + TILE <= w; c += TILE) {
#pragma HLS LOOP_TRIPCOUNT max=8
                    for (int t = 0; t < TILE; ++t) part[t] += row[c + t] * xs[c + t];
                }
                for (; c < w; ++c) {
#pragma HLS LOOP_TRIPCOUNT max=4
                    part[0] += row[c] * xs[c];
                }
                T acc = T(0);
                for (int t = 0; t < TILE; ++t) acc += part[t];
                rhs[r] = row[w] - acc;
            }
            // then the frontal triangle column by column: x_r, and its column out of the rows
            // above (short dependency chains: one product per row and step; the divisions by
            // the diagonal, independent of each other, are taken out of the chain first)
            T inv[MAX_F];
            for (int r = 0; r < f; ++r) {
#pragma HLS LOOP_TRIPCOUNT max=30
                inv[r] = T(1) / cond[r * (w + 1) + r];
            }
            for (int r = f - 1; r >= 0; --r) {
#pragma HLS LOOP_TRIPCOUNT max=30
                const T xr = rhs[r] * inv[r];
                xs[r] = xr;
                for (int i = 0; i < r; ++i) {
#pragma HLS LOOP_TRIPCOUNT max=30
                    rhs[i] -= cond[i * (w + 1) + r] * xr;
                }
            }
            for (int c = 0; c < f; ++c) {
#pragma HLS LOOP_TRIPCOUNT max=30
                DELTA[cols[c]] = xs[c];
            }
        }
    }
    return true;
}

// ---- trust-region control (paper B): the rules in fgc_lm.h (shared with the HLS kernel); here
// the kernel's constants and hooks, its sums plain loops. fgc_lm::optimize<LmConfig>: GN/LM
// iterations from X.
struct LmConfig {
    typedef ::fgc::T T;
    static const int MAX_ITERATIONS = ::fgc::MAX_ITERATIONS, MAX_TRIES = ::fgc::MAX_TRIES;
    static const bool LM = true;  // false: Gauss-Newton, mu stays 0
    static const int STATUS_CONVERGED = ::fgc::STATUS_CONVERGED;
    static const int STATUS_MAX_ITERATIONS = ::fgc::STATUS_MAX_ITERATIONS;
    static const int STATUS_FAILED = ::fgc::STATUS_FAILED;
    static const int REASON_GRADIENT = ::fgc::REASON_GRADIENT;
    static const int REASON_STEP = ::fgc::REASON_STEP;
    static const int REASON_PREDICTED_DECREASE = ::fgc::REASON_PREDICTED_DECREASE;
    static const int REASON_ABSOLUTE_ERROR = ::fgc::REASON_ABSOLUTE_ERROR;
    static const int REASON_RELATIVE_DECREASE = ::fgc::REASON_RELATIVE_DECREASE;
    static const int REASON_MAX_ITERATIONS = ::fgc::REASON_MAX_ITERATIONS;
    static const int REASON_NON_FINITE = ::fgc::REASON_NON_FINITE;
    static const int REASON_SINGULAR = ::fgc::REASON_SINGULAR;
    static const int REASON_COST_INCREASED = ::fgc::REASON_COST_INCREASED;
    static const int REASON_LAMBDA_LIMIT = ::fgc::REASON_LAMBDA_LIMIT;
    static T lambda_initial() { return LAMBDA_INITIAL; }
    static T lambda_factor() { return LAMBDA_FACTOR; }
    static T lambda_upper_bound() { return LAMBDA_UPPER_BOUND; }
    static T mu_min() { return MU_MIN; }
    static T eps_gradient() { return EPS_GRADIENT; }
    static T eps_step() { return EPS_STEP; }
    static T rel_tol() { return REL_TOL; }
    static T resolution() { return RESOLUTION; }
    static T abs_tol() { return ABS_TOL; }
    static T root(T x) { return fgc_sqrt(x); }
    static T magnitude(T x) { return fgc_abs(x); }
    static bool finite(T x) { return fgc_isfinite(x); }
    static T cost_x() { return total_cost(X); }
    static bool linearize_x(T) { return linearize_all(X); }  // (mu: the HLS Cholesky kernel's)
    static bool solve_at(T mu) { return solve(mu); }
    static void retract_trial() { retract_all(X, DELTA, X_TRIAL); }
    static T cost_trial() { return total_cost(X_TRIAL); }
    static T noise_x() { return rounding_noise_all(X); }
    static T x_norm() {
        T x_norm2 = T(0);
        for (int i = 0; i < N_X; ++i) x_norm2 += X[i] * X[i];
        return fgc_sqrt(x_norm2);
    }
    static bool step_test(bool solved, T mu, T out[2]) {
        bool ok = solved;
        T d2 = T(0), predicted = T(0);
        for (int i = 0; i < N_TANGENT; ++i) {
            ok = ok && fgc_isfinite(DELTA[i]);
            d2 += DELTA[i] * DELTA[i];
            predicted += DELTA[i] * (G[i] + mu * DELTA[i]);
        }
        out[0] = d2;
        out[1] = T(0.5) * predicted;
        return ok;
    }
    static T gradient_max() {
        T g_max = T(0);
        for (int i = 0; i < N_TANGENT; ++i) g_max = fgc_abs(G[i]) > g_max ? fgc_abs(G[i]) : g_max;
        return g_max;
    }
    static void accept_trial() {
        for (int i = 0; i < N_X; ++i) X[i] = X_TRIAL[i];
    }
    // after each accepted step: the host's progress display, when one is set (fgc_set_progress)
    static void accepted(int it, T cost, T mu, T change) {
        if (progress_hook != nullptr) {
            progress_hook(it, static_cast<double>(cost), static_cast<double>(mu),
                          static_cast<double>(change));
        }
    }
};

#ifndef __SYNTHESIS__
// The host's inputs: x into X, the caller's data read where it is, laned once per call.
void host_inputs(const T* x_in, const T* data) {
    for (int i = 0; i < N_X; ++i) X[i] = x_in[i];
    DATA_BUF = data;
    lane_data_0();
    lane_data_1();
    lane_data_2();
    lane_data_3();
}
#endif

}  // namespace

void (*progress_hook)(int, double, double, double) = nullptr;

}  // namespace fgc

void imu_window_top(const fgc::T x_in[fgc::N_X], const fgc::T data[fgc::N_DATA],
                    fgc::T x_out[fgc::N_X], fgc::T errors[2], int info[3]) {
#pragma HLS INTERFACE m_axi port=x_in offset=slave bundle=gmem0 depth=168
#pragma HLS INTERFACE m_axi port=data offset=slave bundle=gmem1 depth=1395
#pragma HLS INTERFACE m_axi port=x_out offset=slave bundle=gmem0 depth=168
#pragma HLS INTERFACE s_axilite port=errors
#pragma HLS INTERFACE s_axilite port=info
#pragma HLS INTERFACE s_axilite port=return
#ifdef __SYNTHESIS__
    for (int i = 0; i < fgc::N_X; ++i) fgc::X[i] = x_in[i];
    for (int i = 0; i < fgc::N_DATA; ++i) fgc::DATA_BUF[i] = data[i];
#else
    fgc::host_inputs(x_in, data);
#endif
    fgc_lm::optimize<fgc::LmConfig>(errors, info);
    for (int i = 0; i < fgc::N_X; ++i) x_out[i] = fgc::X[i];
}

#ifndef __SYNTHESIS__
void imu_window_probe(const fgc::T x_in[fgc::N_X], const fgc::T data[fgc::N_DATA], fgc::T out[2]) {
    fgc::host_inputs(x_in, data);
    out[0] = fgc::total_cost(fgc::X);
    out[1] = fgc::rounding_noise_all(fgc::X);
}

void imu_window_rows(const fgc::T x_in[fgc::N_X], const fgc::T data[fgc::N_DATA], double* out) {
    fgc::host_inputs(x_in, data);
    fgc::linearized_rows(fgc::X, out);
}
#endif
