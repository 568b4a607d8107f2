// generated from template kernel.cpp.jinja by fgc 0.1.0 — do not edit
// Problem: pose_graph
// general graph, min-degree ordering; solver: lm qr auto n_u=4 cpe=20
//
// A CPU program, not a hardware design (fgc_backends.native): built with the host compiler as a
// shared library, with SIMD lanes and host-only paths; g++ ignores the `#pragma HLS` lines, which
// stay only while the HLS backend renders this template too.
//
// Dataflow of one Levenberg-Marquardt iteration:
//   factor blocks (residual + Jacobian mode) -> whitened rows [A | b] per factor instance
//   -> elimination steps along the schedule (partial QR: Evaluate + Update units), level by level,
//      1 unit set(s) side by side -> conditionals (R | d) per step
//   -> back-substitution root first -> retraction x (+) delta -> factor blocks (cost mode) -> accept?
//   (a step that does not lower the cost is judged against the cost's rounding noise at x: the
//   factor blocks in noise mode, once per iteration that needs it)
#include "pose_graph.h"

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
const int UNIT_SETS = 1;
const int MAX_LEVEL_WIDTH = 2;
const int TILE = 4;  // Gram tiles are TILE x TILE; matrix rows are padded to whole TILEs
const int MAX_LD = 20;  // padded row length of the widest step
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
const int VAR_T_OFF[6] = {
    0, 6, 12, 18, 24, 30,
};
const int FACTOR_BLOCK[7] = {
    0, 0, 0, 0, 0, 0, 1,
};
const int FACTOR_A_OFF[8] = {
    0, 78, 156, 234, 312, 390, 468, 510,
};
const int FACTOR_GRAM_OFF[8] = {
    0, 91, 182, 273, 364, 455, 546, 574,
};
const int FACTOR_VAR_BEGIN[8] = {
    0, 2, 4, 6, 8, 10, 12, 13,
};
const int FACTOR_VARS[13] = {
    0, 1, 1, 2, 2, 3, 3, 4, 1, 4, 3, 0, 0,
};
const int FACTOR_COLMAP_BEGIN[8] = {
    0, 12, 24, 36, 48, 60, 72, 78,
};
const int FACTOR_COLMAP[78] = {
    0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 6, 7, 8, 9,
    10, 11, 0, 1, 2, 3, 4, 5, 0, 1, 2, 3, 4, 5, 12, 13,
    14, 15, 16, 17, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17,
    0, 1, 2, 3, 4, 5, 12, 13, 14, 15, 16, 17, 12, 13, 14, 15,
    16, 17, 0, 1, 2, 3, 4, 5, 0, 1, 2, 3, 4, 5,
};
const int STEP_F[3] = {
    6, 6, 18,
};
const int STEP_W[3] = {
    18, 18, 18,
};
const int STEP_ROWS[3] = {
    24, 18, 54,
};
const int STEP_NF_ROWS[3] = {
    12, 12, 0,
};
const int STEP_COND_OFF[3] = {
    0, 114, 228,
};
const int STEP_NF_OFF[3] = {
    0, 156, 312,
};
const int STEP_COL_BEGIN[4] = {
    0, 18, 36, 54,
};
const int STEP_COL[54] = {
    0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 18, 19, 20, 21,
    22, 23, 12, 13, 14, 15, 16, 17, 6, 7, 8, 9, 10, 11, 18, 19,
    20, 21, 22, 23, 6, 7, 8, 9, 10, 11, 18, 19, 20, 21, 22, 23,
    24, 25, 26, 27, 28, 29,
};
const int STEP_FACTOR_BEGIN[4] = {
    0, 3, 5, 7,
};
const int STEP_FACTORS[7] = {
    0, 5, 6, 1, 2, 3, 4,
};
const int STEP_CHILD_BEGIN[4] = {
    0, 0, 0, 2,
};
const int STEP_CHILDREN[2] = {
    0, 1,
};
const int STEP_SEPMAP_BEGIN[4] = {
    0, 12, 24, 24,
};
const int STEP_SEPMAP[24] = {
    0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 0, 1, 2, 3,
    4, 5, 6, 7, 8, 9, 10, 11,
};
const int LEVEL_BEGIN[3] = {
    0, 2, 3,
};
const int LEVEL_STEPS[3] = {
    0, 1, 2,
};
const int BLOCK0_INSTANCES[6] = {
    0, 1, 2, 3, 4, 5,
};
const int BLOCK1_INSTANCES[1] = {
    6,
};
const int KIND0_VARIABLES[5] = {
    0, 1, 2, 3, 4,
};

// ---- the accelerator's memories: static, sized at compile time; nothing is allocated
T X[N_X];          // current estimate (storage)
T X_TRIAL[N_X];    // x (+) delta
#ifdef __SYNTHESIS__
T DATA_BUF[N_DATA];
#else
const T* DATA_BUF = nullptr;  // on the host: the caller's data, read in place (never written)
#endif
L AB[N_A];         // whitened rows [A | b] of every factor instance (row-major, d + 1 columns)
T G[N_TANGENT];    // gradient A^T b
T VAR_SCALE[N_VARIABLES];
T DELTA[N_TANGENT];
L COND[N_COND];    // conditionals (R | d), one block per elimination step
L NF[N_NF];
        // new factors passed to the parent step

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
// block 0: BetweenFactorPose3 (6 rows, 12 columns, 6 instances)
void jacobian_0(const V* in, const V* dat, T ab[LANES][96]) {
#pragma HLS PIPELINE II=1
    const V t0 = in[0]*in[12] + in[3]*in[15] + in[6]*in[18];
    const V t1 = in[2]*in[12] + in[5]*in[15] + in[8]*in[18];
    const V t2 = -t1;
    const V t3 = in[1]*in[12] + in[4]*in[15] + in[7]*in[18];
    const V t4 = in[0]*in[14] + in[3]*in[17] + in[6]*in[20];
    const V t5 = -t4;
    const V t6 = in[0]*in[13] + in[3]*in[16] + in[6]*in[19];
    const V t7 = -t0;
    const V t8 = in[1]*in[14] + in[4]*in[17] + in[7]*in[20];
    const V t9 = -t8;
    const V t10 = in[1]*in[13] + in[4]*in[16] + in[7]*in[19];
    const V t11 = -t3;
    const V t12 = in[2]*in[14] + in[5]*in[17] + in[8]*in[20];
    const V t13 = -t12;
    const V t14 = in[2]*in[13] + in[5]*in[16] + in[8]*in[19];
    const V t15 = -t14;
    const V t16 = -t6;
    const V t17 = -t10;
    const V t18 = t0;
    const V t19 = t3;
    const V t20 = t1;
    const V t21 = t18*dat[0] + t19*dat[3] + t20*dat[6];
    const V t22 = t6;
    const V t23 = t10;
    const V t24 = t14;
    const V t25 = t22*dat[0] + t23*dat[3] + t24*dat[6];
    const V t26 = t4;
    const V t27 = t8;
    const V t28 = t12;
    const V t29 = t28*dat[6] + t26*dat[0] + t27*dat[3];
    const V t30 = t18*dat[1] + t19*dat[4] + t20*dat[7];
    const V t31 = t22*dat[1] + t23*dat[4] + t24*dat[7];
    const V t32 = t28*dat[7] + t26*dat[1] + t27*dat[4];
    const V t33 = t18*dat[2] + t19*dat[5] + t20*dat[8];
    const V t34 = t22*dat[2] + t23*dat[5] + t24*dat[8];
    const V t35 = t28*dat[8] + t26*dat[2] + t27*dat[5];
    V tlog0[3]; v_so3_log(t21, t25, t29, t30, t31, t32, t33, t34, t35, tlog0);
    const V t36 = tlog0[2];
    const V t37 = (T(0.5))*t36;
    const V t38 = tlog0[0];
    const V t39 = (t38*t38);
    const V t40 = tlog0[1];
    const V t41 = (t40*t40);
    const V t42 = (t36*t36);
    const V t43 = t41 + t42;
    const V t44 = v_lie_D(t39 + t43);
    const V t45 = t44*t38;
    const V t46 = t45*t40;
    const V t47 = -t37 + t46;
    const V t48 = (T(0.5))*t29;
    const V t49 = (T(0.5))*t40;
    const V t50 = t45*t36;
    const V t51 = t49 + t50;
    const V t52 = -t47*t48 + (T(0.5))*t51*t25;
    const V t53 = -t43*t44 + T(1);
    const V t54 = (T(0.5))*t51;
    const V t55 = t48*t53 - t54*t21;
    const V t56 = (T(0.5))*t47;
    const V t57 = (T(0.5))*t53;
    const V t58 = t56*t21 - t57*t25;
    const V t59 = t54*t31 - t56*t32;
    const V t60 = (T(0.5))*t53*t32 - t54*t30;
    const V t61 = t56*t30 - t57*t31;
    const V t62 = t54*t34 - t56*t35;
    const V t63 = (T(0.5))*t53*t35 - t54*t33;
    const V t64 = t56*t33 - t57*t34;
    const V t65 = t44*(-t39 - t42) + T(1);
    const V t66 = (T(0.5))*t38;
    const V t67 = t44*t40*t36 - t66;
    const V t68 = -t48*t65 + (T(0.5))*t67*t25;
    const V t69 = t37 + t46;
    const V t70 = (T(0.5))*t67;
    const V t71 = t48*t69 - t70*t21;
    const V t72 = (T(0.5))*t65;
    const V t73 = (T(0.5))*t69;
    const V t74 = t72*t21 - t73*t25;
    const V t75 = t70*t31 - t72*t32;
    const V t76 = (T(0.5))*t69*t32 - t70*t30;
    const V t77 = t72*t30 - t73*t31;
    const V t78 = t70*t34 - t72*t35;
    const V t79 = (T(0.5))*t69*t35 - t70*t33;
    const V t80 = t72*t33 - t73*t34;
    const V t81 = t40*t36;
    const V t82 = t44*t81 + t66;
    const V t83 = t44*(-t39 - t41) + T(1);
    const V t84 = -t48*t82 + (T(0.5))*t83*t25;
    const V t85 = -t49 + t50;
    const V t86 = (T(0.5))*t83;
    const V t87 = t48*t85 - t86*t21;
    const V t88 = (T(0.5))*t82;
    const V t89 = (T(0.5))*t85;
    const V t90 = t88*t21 - t89*t25;
    const V t91 = t86*t31 - t88*t32;
    const V t92 = (T(0.5))*t85*t32 - t86*t30;
    const V t93 = t88*t30 - t89*t31;
    const V t94 = t86*t34 - t88*t35;
    const V t95 = (T(0.5))*t85*t35 - t86*t33;
    const V t96 = t88*t33 - t89*t34;
    const V t97 = T(2)*t40;
    const V t98 = T(2)*t36;
    const V t99 = T(2)*t38;
    const V t100 = t41;
    const V t101 = t42;
    const V t102 = t100 + t101;
    const V t103 = t39;
    const V t104 = t102 + t103;
    const V t105 = v_lie_D1(t104);
    const V t106 = -in[9] + in[21];
    const V t107 = -in[10] + in[22];
    const V t108 = -in[11] + in[23];
    const V t109 = t106*in[2] + t107*in[5] + t108*in[8];
    const V t110 = t106*in[1] + t107*in[4] + t108*in[7];
    const V t111 = -in[0]*in[1] - in[3]*in[4] - in[6]*in[7];
    const V t112 = -in[0]*in[2] - in[3]*in[5] - in[6]*in[8];
    const V t113 = t106*in[0] + t107*in[3] + t108*in[6];
    const V t114 = -in[1]*in[2] - in[4]*in[5] - in[7]*in[8];
    const V t115 = v_lie_D(t104);
    const V t116 = t40*t115;
    const V t117 = t36*t115;
    const V t118 = -t102*t115 + T(1);
    const V t119 = t37;
    const V t120 = t38*t115;
    const V t121 = t40*t120;
    const V t122 = t119 + t121;
    const V t123 = t49;
    const V t124 = t36*t120;
    const V t125 = -t123 + t124;
    const V t126 = -t119 + t121;
    const V t127 = -t101 - t103;
    const V t128 = t127*t115 + T(1);
    const V t129 = t66;
    const V t130 = t81*t115;
    const V t131 = t129 + t130;
    const V t132 = t123 + t124;
    const V t133 = -t129 + t130;
    const V t134 = -t100 - t103;
    const V t135 = t134*t115 + T(1);
    const V t136 = -in[0]*in[9] + in[0]*in[21] - in[3]*in[10] + in[3]*in[22] - in[6]*in[11] + in[6]*in[23];
    const V t137 = -in[1]*in[9] + in[1]*in[21] - in[4]*in[10] + in[4]*in[22] - in[7]*in[11] + in[7]*in[23];
    const V t138 = -in[2]*in[9] + in[2]*in[21] - in[5]*in[10] + in[5]*in[22] - in[8]*in[11] + in[8]*in[23];
    const V t139 = t136*dat[0] + t137*dat[3] + t138*dat[6] - dat[0]*dat[9] - dat[3]*dat[10] - dat[6]*dat[11];
    const V t140 = t102*t139;
    const V t141 = t115*t139;
    const V t142 = t136*dat[1] + t137*dat[4] + t138*dat[7] - dat[1]*dat[9] - dat[4]*dat[10] - dat[7]*dat[11];
    const V t143 = t127*t142;
    const V t144 = t115*t142;
    const V t145 = t136*dat[2] + t137*dat[5] + t138*dat[8] - dat[2]*dat[9] - dat[5]*dat[10] - dat[8]*dat[11];
    const V t146 = t134*t145;
    const V t147 = t115*t145;
    const V t148 = t2;
    const V t149 = t3;
    const V t150 = t5;
    const V t151 = t6;
    const V t152 = t1;
    const V t153 = t7;
    const V t154 = t9;
    const V t155 = t10;
    const V t156 = t11;
    const V t157 = t0;
    const V t158 = t13;
    const V t159 = t14;
    const V t160 = t152*dat[3] + t156*dat[6];
    const V t161 = t148*dat[0] + t157*dat[6];
    const V t162 = t149*dat[0] + t153*dat[3];
    const V t163 = t158*dat[6] + t150*dat[0] + t154*dat[3];
    const V t164 = t159*dat[6] + t151*dat[0] + t155*dat[3];
    const V t165 = t15;
    const V t166 = t10;
    const V t167 = t4;
    const V t168 = t7;
    const V t169 = t14;
    const V t170 = t16;
    const V t171 = t8;
    const V t172 = t11;
    const V t173 = t17;
    const V t174 = t6;
    const V t175 = t12;
    const V t176 = t2;
    const V t177 = t169*dat[3] + t173*dat[6];
    const V t178 = t165*dat[0] + t174*dat[6];
    const V t179 = t166*dat[0] + t170*dat[3];
    const V t180 = t167*dat[0] + t171*dat[3] + t175*dat[6];
    const V t181 = t168*dat[0] + t172*dat[3] + t176*dat[6];
    const V t182 = t13;
    const V t183 = t8;
    const V t184 = t16;
    const V t185 = t0;
    const V t186 = t12;
    const V t187 = t5;
    const V t188 = t17;
    const V t189 = t3;
    const V t190 = t9;
    const V t191 = t4;
    const V t192 = t15;
    const V t193 = t1;
    const V t194 = t186*dat[3] + t190*dat[6];
    const V t195 = t182*dat[0] + t191*dat[6];
    const V t196 = t183*dat[0] + t187*dat[3];
    const V t197 = t184*dat[0] + t188*dat[3] + t192*dat[6];
    const V t198 = t185*dat[0] + t189*dat[3] + t193*dat[6];
    const V t199 = t152*dat[4] + t156*dat[7];
    const V t200 = t148*dat[1] + t157*dat[7];
    const V t201 = t149*dat[1] + t153*dat[4];
    const V t202 = t158*dat[7] + t150*dat[1] + t154*dat[4];
    const V t203 = t159*dat[7] + t151*dat[1] + t155*dat[4];
    const V t204 = t169*dat[4] + t173*dat[7];
    const V t205 = t165*dat[1] + t174*dat[7];
    const V t206 = t166*dat[1] + t170*dat[4];
    const V t207 = t167*dat[1] + t171*dat[4] + t175*dat[7];
    const V t208 = t168*dat[1] + t172*dat[4] + t176*dat[7];
    const V t209 = t186*dat[4] + t190*dat[7];
    const V t210 = t182*dat[1] + t191*dat[7];
    const V t211 = t183*dat[1] + t187*dat[4];
    const V t212 = t184*dat[1] + t188*dat[4] + t192*dat[7];
    const V t213 = t185*dat[1] + t189*dat[4] + t193*dat[7];
    const V t214 = t152*dat[5] + t156*dat[8];
    const V t215 = t148*dat[2] + t157*dat[8];
    const V t216 = t149*dat[2] + t153*dat[5];
    const V t217 = t158*dat[8] + t150*dat[2] + t154*dat[5];
    const V t218 = t159*dat[8] + t151*dat[2] + t155*dat[5];
    const V t219 = t169*dat[5] + t173*dat[8];
    const V t220 = t165*dat[2] + t174*dat[8];
    const V t221 = t166*dat[2] + t170*dat[5];
    const V t222 = t167*dat[2] + t171*dat[5] + t175*dat[8];
    const V t223 = t168*dat[2] + t172*dat[5] + t176*dat[8];
    const V t224 = t186*dat[5] + t190*dat[8];
    const V t225 = t182*dat[2] + t191*dat[8];
    const V t226 = t183*dat[2] + t187*dat[5];
    const V t227 = t184*dat[2] + t188*dat[5] + t192*dat[8];
    const V t228 = t185*dat[2] + t189*dat[5] + t193*dat[8];
    const V t229 = t52*t160 + t55*t177 + t58*t194 + t59*t199 + t60*t204 + t61*t209 + t62*t214 + t63*t219 + t64*t224;
    const V t230 = t52*t161 + t55*t178 + t58*t195 + t59*t200 + t60*t205 + t61*t210 + t62*t215 + t63*t220 + t64*t225;
    const V t231 = t52*t162 + t55*t179 + t58*t196 + t59*t201 + t60*t206 + t61*t211 + t62*t216 + t63*t221 + t64*t226;
    const V t232 = t55*t180 + t58*t197 + t60*t207 + t61*t212 + t63*t222 + t64*t227;
    const V t233 = t52*t163 + t58*t198 + t59*t202 + t61*t213 + t62*t217 + t64*t228;
    const V t234 = t52*t164 + t55*t181 + t59*t203 + t60*t208 + t62*t218 + t63*t223;
    const V t235 = t68*t160 + t71*t177 + t74*t194 + t75*t199 + t76*t204 + t77*t209 + t78*t214 + t79*t219 + t80*t224;
    const V t236 = t68*t161 + t71*t178 + t74*t195 + t75*t200 + t76*t205 + t77*t210 + t78*t215 + t79*t220 + t80*t225;
    const V t237 = t68*t162 + t71*t179 + t74*t196 + t75*t201 + t76*t206 + t77*t211 + t78*t216 + t79*t221 + t80*t226;
    const V t238 = t71*t180 + t74*t197 + t76*t207 + t77*t212 + t79*t222 + t80*t227;
    const V t239 = t68*t163 + t74*t198 + t75*t202 + t77*t213 + t78*t217 + t80*t228;
    const V t240 = t68*t164 + t71*t181 + t75*t203 + t76*t208 + t78*t218 + t79*t223;
    const V t241 = t84*t160 + t87*t177 + t90*t194 + t91*t199 + t92*t204 + t93*t209 + t94*t214 + t95*t219 + t96*t224;
    const V t242 = t84*t161 + t87*t178 + t90*t195 + t91*t200 + t92*t205 + t93*t210 + t94*t215 + t95*t220 + t96*t225;
    const V t243 = t84*t162 + t87*t179 + t90*t196 + t91*t201 + t92*t206 + t93*t211 + t94*t216 + t95*t221 + t96*t226;
    const V t244 = t87*t180 + t90*t197 + t92*t207 + t93*t212 + t95*t222 + t96*t227;
    const V t245 = t84*t163 + t90*t198 + t91*t202 + t93*t213 + t94*t217 + t96*t228;
    const V t246 = t84*t164 + t87*t181 + t91*t203 + t92*t208 + t94*t218 + t95*t223;
    const V t247 = t97*t235;
    const V t248 = t97*t236;
    const V t249 = t97*t237;
    const V t250 = t97*t238;
    const V t251 = t97*t239;
    const V t252 = t97*t240;
    const V t253 = t98*t241;
    const V t254 = t98*t242;
    const V t255 = t98*t243;
    const V t256 = t98*t244;
    const V t257 = t98*t245;
    const V t258 = t98*t246;
    const V t259 = t253 + t247;
    const V t260 = t248 + t254;
    const V t261 = t249 + t255;
    const V t262 = t250 + t256;
    const V t263 = t251 + t257;
    const V t264 = t252 + t258;
    const V t265 = t99*t229;
    const V t266 = t99*t230;
    const V t267 = t99*t231;
    const V t268 = t99*t232;
    const V t269 = t99*t233;
    const V t270 = t99*t234;
    const V t271 = t105*t259 + t105*t265;
    const V t272 = t105*t260 + t105*t266;
    const V t273 = t105*t261 + t105*t267;
    const V t274 = t105*t262 + t105*t268;
    const V t275 = t105*t263 + t105*t269;
    const V t276 = t105*t264 + t105*t270;
    const V t277 = -t109;
    const V t278 = t110;
    const V t279 = -(in[0]*in[0]) - (in[3]*in[3]) - (in[6]*in[6]);
    const V t280 = t111;
    const V t281 = t112;
    const V t282 = t0;
    const V t283 = t6;
    const V t284 = t4;
    const V t285 = t109;
    const V t286 = -t113;
    const V t287 = t111;
    const V t288 = -(in[1]*in[1]) - (in[4]*in[4]) - (in[7]*in[7]);
    const V t289 = t114;
    const V t290 = t3;
    const V t291 = t10;
    const V t292 = t8;
    const V t293 = -t110;
    const V t294 = t113;
    const V t295 = t112;
    const V t296 = t114;
    const V t297 = -(in[2]*in[2]) - (in[5]*in[5]) - (in[8]*in[8]);
    const V t298 = t1;
    const V t299 = t14;
    const V t300 = t12;
    const V t301 = t285*dat[3] + t293*dat[6];
    const V t302 = t277*dat[0] + t294*dat[6];
    const V t303 = t278*dat[0] + t286*dat[3];
    const V t304 = t279*dat[0] + t287*dat[3] + t295*dat[6];
    const V t305 = t280*dat[0] + t288*dat[3] + t296*dat[6];
    const V t306 = t281*dat[0] + t289*dat[3] + t297*dat[6];
    const V t307 = t282*dat[0] + t290*dat[3] + t298*dat[6];
    const V t308 = t283*dat[0] + t291*dat[3] + t299*dat[6];
    const V t309 = t284*dat[0] + t292*dat[3] + t300*dat[6];
    const V t310 = (T(0.5))*t241;
    const V t311 = (T(0.5))*t242;
    const V t312 = (T(0.5))*t243;
    const V t313 = (T(0.5))*t244;
    const V t314 = (T(0.5))*t245;
    const V t315 = (T(0.5))*t246;
    const V t316 = t38*t271 + t115*t229;
    const V t317 = t38*t272 + t115*t230;
    const V t318 = t38*t273 + t115*t231;
    const V t319 = t38*t274 + t115*t232;
    const V t320 = t38*t275 + t115*t233;
    const V t321 = t38*t276 + t115*t234;
    const V t322 = t40*t316 + t120*t235;
    const V t323 = t40*t317 + t120*t236;
    const V t324 = t40*t318 + t120*t237;
    const V t325 = t40*t319 + t120*t238;
    const V t326 = t40*t320 + t120*t239;
    const V t327 = t40*t321 + t120*t240;
    const V t328 = t285*dat[4] + t293*dat[7];
    const V t329 = t277*dat[1] + t294*dat[7];
    const V t330 = t278*dat[1] + t286*dat[4];
    const V t331 = t279*dat[1] + t287*dat[4] + t295*dat[7];
    const V t332 = t280*dat[1] + t288*dat[4] + t296*dat[7];
    const V t333 = t281*dat[1] + t289*dat[4] + t297*dat[7];
    const V t334 = t282*dat[1] + t290*dat[4] + t298*dat[7];
    const V t335 = t283*dat[1] + t291*dat[4] + t299*dat[7];
    const V t336 = t284*dat[1] + t292*dat[4] + t300*dat[7];
    const V t337 = (T(0.5))*t235;
    const V t338 = (T(0.5))*t236;
    const V t339 = (T(0.5))*t237;
    const V t340 = (T(0.5))*t238;
    const V t341 = (T(0.5))*t239;
    const V t342 = (T(0.5))*t240;
    const V t343 = t36*t316 + t120*t241;
    const V t344 = t36*t317 + t120*t242;
    const V t345 = t36*t318 + t120*t243;
    const V t346 = t36*t319 + t120*t244;
    const V t347 = t36*t320 + t120*t245;
    const V t348 = t36*t321 + t120*t246;
    const V t349 = t285*dat[5] + t293*dat[8];
    const V t350 = t277*dat[2] + t294*dat[8];
    const V t351 = t278*dat[2] + t286*dat[5];
    const V t352 = t279*dat[2] + t287*dat[5] + t295*dat[8];
    const V t353 = t280*dat[2] + t288*dat[5] + t296*dat[8];
    const V t354 = t281*dat[2] + t289*dat[5] + t297*dat[8];
    const V t355 = t282*dat[2] + t290*dat[5] + t298*dat[8];
    const V t356 = t283*dat[2] + t291*dat[5] + t299*dat[8];
    const V t357 = t284*dat[2] + t292*dat[5] + t300*dat[8];
    const V t358 = (T(0.5))*t229;
    const V t359 = (T(0.5))*t230;
    const V t360 = (T(0.5))*t231;
    const V t361 = (T(0.5))*t232;
    const V t362 = (T(0.5))*t233;
    const V t363 = (T(0.5))*t234;
    const V t364 = t81*t271 + t116*t241 + t117*t235;
    const V t365 = t81*t272 + t116*t242 + t117*t236;
    const V t366 = t81*t273 + t116*t243 + t117*t237;
    const V t367 = t81*t274 + t116*t244 + t117*t238;
    const V t368 = t81*t275 + t116*t245 + t117*t239;
    const V t369 = t81*t276 + t116*t246 + t117*t240;
    // every output once, as a whole V, before it is taken apart lane by lane
    const V o0 = t229;
    const V o1 = t230;
    const V o2 = t231;
    const V o3 = t232;
    const V o4 = t233;
    const V o5 = t234;
    const V o6 = t38;
    const V o7 = t235;
    const V o8 = t236;
    const V o9 = t237;
    const V o10 = t238;
    const V o11 = t239;
    const V o12 = t240;
    const V o13 = t40;
    const V o14 = t241;
    const V o15 = t242;
    const V o16 = t243;
    const V o17 = t244;
    const V o18 = t245;
    const V o19 = t246;
    const V o20 = t36;
    const V o21 = -t140*t271 - t141*t259 + t118*t301 + t122*t328 + t125*t349 + t142*t310 + t142*t322 - t145*t337 + t145*t343;
    const V o22 = -t140*t272 - t141*t260 + t118*t302 + t122*t329 + t125*t350 + t142*t311 + t142*t323 - t145*t338 + t145*t344;
    const V o23 = -t140*t273 - t141*t261 + t118*t303 + t122*t330 + t125*t351 + t142*t312 + t142*t324 - t145*t339 + t145*t345;
    const V o24 = t118*t304 + t122*t331 + t125*t352;
    const V o25 = t118*t305 + t122*t332 + t125*t353;
    const V o26 = t118*t306 + t122*t333 + t125*t354;
    const V o27 = -t140*t274 - t141*t262 + t142*t313 + t142*t325 - t145*t340 + t145*t346;
    const V o28 = -t140*t275 - t141*t263 + t142*t314 + t142*t326 - t145*t341 + t145*t347;
    const V o29 = -t140*t276 - t141*t264 + t142*t315 + t142*t327 - t145*t342 + t145*t348;
    const V o30 = t118*t307 + t122*t334 + t125*t355;
    const V o31 = t118*t308 + t122*t335 + t125*t356;
    const V o32 = t118*t309 + t122*t336 + t125*t357;
    const V o33 = t118*t139 + t122*t142 + t125*t145;
    const V o34 = t143*t271 - t144*t253 - t144*t265 + t126*t301 + t128*t328 + t131*t349 - t139*t310 + t139*t322 + t145*t358 + t145*t364;
    const V o35 = t143*t272 - t144*t254 - t144*t266 + t126*t302 + t128*t329 + t131*t350 - t139*t311 + t139*t323 + t145*t359 + t145*t365;
    const V o36 = t143*t273 - t144*t255 - t144*t267 + t126*t303 + t128*t330 + t131*t351 - t139*t312 + t139*t324 + t145*t360 + t145*t366;
    const V o37 = t126*t304 + t128*t331 + t131*t352;
    const V o38 = t126*t305 + t128*t332 + t131*t353;
    const V o39 = t126*t306 + t128*t333 + t131*t354;
    const V o40 = t143*t274 - t144*t256 - t144*t268 - t139*t313 + t139*t325 + t145*t361 + t145*t367;
    const V o41 = t143*t275 - t144*t257 - t144*t269 - t139*t314 + t139*t326 + t145*t362 + t145*t368;
    const V o42 = t143*t276 - t144*t258 - t144*t270 - t139*t315 + t139*t327 + t145*t363 + t145*t369;
    const V o43 = t126*t307 + t128*t334 + t131*t355;
    const V o44 = t126*t308 + t128*t335 + t131*t356;
    const V o45 = t126*t309 + t128*t336 + t131*t357;
    const V o46 = t126*t139 + t128*t142 + t131*t145;
    const V o47 = t133*t328 + t135*t349 + t146*t271 - t147*t265 - t147*t247 + t132*t301 + t139*t337 + t139*t343 - t142*t358 + t142*t364;
    const V o48 = t133*t329 + t135*t350 + t146*t272 - t147*t248 - t147*t266 + t132*t302 + t139*t338 + t139*t344 - t142*t359 + t142*t365;
    const V o49 = t133*t330 + t135*t351 + t146*t273 - t147*t249 - t147*t267 + t132*t303 + t139*t339 + t139*t345 - t142*t360 + t142*t366;
    const V o50 = t133*t331 + t135*t352 + t132*t304;
    const V o51 = t133*t332 + t135*t353 + t132*t305;
    const V o52 = t133*t333 + t135*t354 + t132*t306;
    const V o53 = t146*t274 - t147*t250 - t147*t268 + t139*t340 + t139*t346 - t142*t361 + t142*t367;
    const V o54 = t146*t275 - t147*t251 - t147*t269 + t139*t341 + t139*t347 - t142*t362 + t142*t368;
    const V o55 = t146*t276 - t147*t252 - t147*t270 + t139*t342 + t139*t348 - t142*t363 + t142*t369;
    const V o56 = t133*t334 + t135*t355 + t132*t307;
    const V o57 = t133*t335 + t135*t356 + t132*t308;
    const V o58 = t133*t336 + t135*t357 + t132*t309;
    const V o59 = t133*t142 + t135*t145 + t132*t139;
    for (int l = 0; l < LANES; ++l) {
        ab[l][0] = lane(o0, l);
        ab[l][1] = lane(o1, l);
        ab[l][2] = lane(o2, l);
        ab[l][6] = lane(o3, l);
        ab[l][7] = lane(o4, l);
        ab[l][8] = lane(o5, l);
        ab[l][12] = lane(o6, l);
        ab[l][16] = lane(o7, l);
        ab[l][17] = lane(o8, l);
        ab[l][18] = lane(o9, l);
        ab[l][22] = lane(o10, l);
        ab[l][23] = lane(o11, l);
        ab[l][24] = lane(o12, l);
        ab[l][28] = lane(o13, l);
        ab[l][32] = lane(o14, l);
        ab[l][33] = lane(o15, l);
        ab[l][34] = lane(o16, l);
        ab[l][38] = lane(o17, l);
        ab[l][39] = lane(o18, l);
        ab[l][40] = lane(o19, l);
        ab[l][44] = lane(o20, l);
        ab[l][48] = lane(o21, l);
        ab[l][49] = lane(o22, l);
        ab[l][50] = lane(o23, l);
        ab[l][51] = lane(o24, l);
        ab[l][52] = lane(o25, l);
        ab[l][53] = lane(o26, l);
        ab[l][54] = lane(o27, l);
        ab[l][55] = lane(o28, l);
        ab[l][56] = lane(o29, l);
        ab[l][57] = lane(o30, l);
        ab[l][58] = lane(o31, l);
        ab[l][59] = lane(o32, l);
        ab[l][60] = lane(o33, l);
        ab[l][64] = lane(o34, l);
        ab[l][65] = lane(o35, l);
        ab[l][66] = lane(o36, l);
        ab[l][67] = lane(o37, l);
        ab[l][68] = lane(o38, l);
        ab[l][69] = lane(o39, l);
        ab[l][70] = lane(o40, l);
        ab[l][71] = lane(o41, l);
        ab[l][72] = lane(o42, l);
        ab[l][73] = lane(o43, l);
        ab[l][74] = lane(o44, l);
        ab[l][75] = lane(o45, l);
        ab[l][76] = lane(o46, l);
        ab[l][80] = lane(o47, l);
        ab[l][81] = lane(o48, l);
        ab[l][82] = lane(o49, l);
        ab[l][83] = lane(o50, l);
        ab[l][84] = lane(o51, l);
        ab[l][85] = lane(o52, l);
        ab[l][86] = lane(o53, l);
        ab[l][87] = lane(o54, l);
        ab[l][88] = lane(o55, l);
        ab[l][89] = lane(o56, l);
        ab[l][90] = lane(o57, l);
        ab[l][91] = lane(o58, l);
        ab[l][92] = lane(o59, l);
    }
}

void cost_0(const V* in, const V* dat, T half[LANES][1]) {
#pragma HLS PIPELINE II=1
    const V t0 = in[0]*in[12] + in[3]*in[15] + in[6]*in[18];
    const V t1 = t0;
    const V t2 = in[1]*in[12] + in[4]*in[15] + in[7]*in[18];
    const V t3 = t2;
    const V t4 = in[2]*in[12] + in[5]*in[15] + in[8]*in[18];
    const V t5 = t4;
    const V t6 = t1*dat[0] + t3*dat[3] + t5*dat[6];
    const V t7 = in[0]*in[13] + in[3]*in[16] + in[6]*in[19];
    const V t8 = t7;
    const V t9 = in[1]*in[13] + in[4]*in[16] + in[7]*in[19];
    const V t10 = t9;
    const V t11 = in[2]*in[13] + in[5]*in[16] + in[8]*in[19];
    const V t12 = t11;
    const V t13 = t8*dat[0] + t10*dat[3] + t12*dat[6];
    const V t14 = in[0]*in[14] + in[3]*in[17] + in[6]*in[20];
    const V t15 = t14;
    const V t16 = in[1]*in[14] + in[4]*in[17] + in[7]*in[20];
    const V t17 = t16;
    const V t18 = in[2]*in[14] + in[5]*in[17] + in[8]*in[20];
    const V t19 = t18;
    const V t20 = t19*dat[6] + t15*dat[0] + t17*dat[3];
    const V t21 = t1*dat[1] + t3*dat[4] + t5*dat[7];
    const V t22 = t8*dat[1] + t10*dat[4] + t12*dat[7];
    const V t23 = t19*dat[7] + t15*dat[1] + t17*dat[4];
    const V t24 = t1*dat[2] + t3*dat[5] + t5*dat[8];
    const V t25 = t8*dat[2] + t10*dat[5] + t12*dat[8];
    const V t26 = t19*dat[8] + t15*dat[2] + t17*dat[5];
    V tlog0[3]; v_so3_log(t6, t13, t20, t21, t22, t23, t24, t25, t26, tlog0);
    const V t27 = tlog0[0];
    const V t28 = (t27*t27);
    const V t29 = tlog0[1];
    const V t30 = (t29*t29);
    const V t31 = tlog0[2];
    const V t32 = (t31*t31);
    const V t33 = t30;
    const V t34 = t33;
    const V t35 = t32;
    const V t36 = t35;
    const V t37 = t34 + t36;
    const V t38 = t28;
    const V t39 = t38;
    const V t40 = t37 + t39;
    const V t41 = v_lie_D(t40);
    const V t42 = -t37*t41 + T(1);
    const V t43 = (T(0.5))*t31;
    const V t44 = t43;
    const V t45 = t27*t41;
    const V t46 = t29*t45;
    const V t47 = t44 + t46;
    const V t48 = (T(0.5))*t29;
    const V t49 = t48;
    const V t50 = t31*t45;
    const V t51 = -t49 + t50;
    const V t52 = -in[0]*in[9] + in[0]*in[21] - in[3]*in[10] + in[3]*in[22] - in[6]*in[11] + in[6]*in[23];
    const V t53 = -in[1]*in[9] + in[1]*in[21] - in[4]*in[10] + in[4]*in[22] - in[7]*in[11] + in[7]*in[23];
    const V t54 = -in[2]*in[9] + in[2]*in[21] - in[5]*in[10] + in[5]*in[22] - in[8]*in[11] + in[8]*in[23];
    const V t55 = t52*dat[0] + t53*dat[3] + t54*dat[6] - dat[0]*dat[9] - dat[3]*dat[10] - dat[6]*dat[11];
    const V t56 = t52*dat[1] + t53*dat[4] + t54*dat[7] - dat[1]*dat[9] - dat[4]*dat[10] - dat[7]*dat[11];
    const V t57 = t52*dat[2] + t53*dat[5] + t54*dat[8] - dat[2]*dat[9] - dat[5]*dat[10] - dat[8]*dat[11];
    const V t58 = t42*t55 + t47*t56 + t51*t57;
    const V t59 = -t44 + t46;
    const V t60 = -t36 - t39;
    const V t61 = t60*t41 + T(1);
    const V t62 = (T(0.5))*t27;
    const V t63 = t62;
    const V t64 = t29*t31;
    const V t65 = t64*t41;
    const V t66 = t63 + t65;
    const V t67 = t59*t55 + t61*t56 + t66*t57;
    const V t68 = t49 + t50;
    const V t69 = -t63 + t65;
    const V t70 = -t34 - t39;
    const V t71 = t70*t41 + T(1);
    const V t72 = t69*t56 + t71*t57 + t68*t55;
    const V t73 = (T(0.5))*(dat[12]*dat[12]);
    const V t74 = (t67*t67)*t73 + (t72*t72)*t73 + t73*t28 + t73*t30 + t73*t32 + t73*(t58*t58);
    const V o0 = t74;
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

// Whitened rows [A | b] -> the local gradient A^T b (column c into G[col[c]], summed down the
// columns: one row per step, whole vectors). False if an entry is infinite or NaN.
template <int STRIDE, int COLS, int ROWS>
bool accumulate(const T* ab, const int col[COLS - 1]) {
    T g[STRIDE], check[STRIDE];
    for (int c = 0; c < STRIDE; ++c) {
        g[c] = T(0);
        check[c] = T(0);
    }
    for (int r = 0; r < ROWS; ++r) {
        const T* row = ab + r * STRIDE;
        const T b = row[COLS - 1];
        for (int c = 0; c < STRIDE; ++c) {
            g[c] += row[c] * b;
            check[c] += row[c] - row[c];  // 0, or NaN for inf / NaN
        }
    }
    T bad[TILE];
    for (int t = 0; t < TILE; ++t) bad[t] = T(0);
    for (int c0 = 0; c0 < STRIDE; c0 += TILE) {
        for (int t = 0; t < TILE; ++t) bad[t] += check[c0 + t];
    }
    for (int c = 0; c < COLS - 1; ++c) G[col[c]] += g[c];
    return fgc_isfinite((bad[0] + bad[1]) + (bad[2] + bad[3]));
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
V BLOCK0_LANED[(6 + LANES - 1) / LANES][13];

void lane_data_0() {
    for (int first = 0; first < 6; first += LANES) {
        T laned[13][LANES];
        for (int l = 0; l < LANES; ++l) {
            const int f = BLOCK0_INSTANCES[first + l < 6 ? first + l : 5];
            const T* line = DATA_BUF + FACTOR_DATA_OFF[f];
            for (int i = 0; i < 12; ++i) laned[0 + i][l] = line[0 + i];
            for (int i = 0; i < 1; ++i) laned[12 + i][l] = line[12 + i];
        }
        for (int i = 0; i < 13; ++i) BLOCK0_LANED[first / LANES][i] = load_lanes(laned[i]);
    }
}
#endif

// The inputs of instances BLOCK0_INSTANCES[first ...] into the lanes (lanes past the last
// instance repeat it; their results are not used): x's storage into `in`; returns where the data
// inputs are (on the host the laned data, in hardware the rest of `in`).
const V* gather_0(const T* x, int first, bool cost, V in[37]) {
#ifndef __SYNTHESIS__
    T buf[24][LANES];
    for (int l = 0; l < LANES; ++l) {
        const int f = BLOCK0_INSTANCES[first + l < 6 ? first + l : 5];
        const int vb = FACTOR_VAR_BEGIN[f];
        for (int i = 0; i < 12; ++i) buf[0 + i][l] = x[VAR_X_OFF[FACTOR_VARS[vb + 0]] + i];
        for (int i = 0; i < 12; ++i) buf[12 + i][l] = x[VAR_X_OFF[FACTOR_VARS[vb + 1]] + i];
    }
    for (int i = 0; i < 24; ++i) in[i] = load_lanes(buf[i]);
    (void)cost;
    return BLOCK0_LANED[first / LANES];
#else
    T buf[37][LANES];
    for (int l = 0; l < LANES; ++l) {
        const int f = BLOCK0_INSTANCES[first + l < 6 ? first + l : 5];
        const int vb = FACTOR_VAR_BEGIN[f];
        for (int i = 0; i < 12; ++i) buf[0 + i][l] = x[VAR_X_OFF[FACTOR_VARS[vb + 0]] + i];
        for (int i = 0; i < 12; ++i) buf[12 + i][l] = x[VAR_X_OFF[FACTOR_VARS[vb + 1]] + i];
        const T* line = DATA_BUF + FACTOR_DATA_OFF[f];
        for (int i = 0; i < 12; ++i) buf[24 + i][l] = line[0 + i];
        if (!cost) continue;
        for (int i = 0; i < 1; ++i) buf[36 + i][l] = line[12 + i];
    }
    for (int i = 0; i < (cost ? 37 : 36); ++i) {
#pragma HLS LOOP_TRIPCOUNT max=37
        in[i] = load_lanes(buf[i]);
    }
    return in + 24;
#endif
}

// block 0, instances first ... first + LANES - 1: residual + Jacobian (its 60
// structural non-zeros of 6 x 13), whiten. Mode 1 (noise_mode false): accumulate the gradient
// and the whitened rows into the A buffer; false if not finite. Mode 3 (true): only add
// the cost's rounding noise (how far the cost moves when x is rounded to T) to *noise. Mode 4
// (rows_out given, host only): copy each instance's whitened rows [A | b] (6 x 13, row-major)
// to rows_out + instance * 78, nothing else.
bool linearize_0(const T* x, int first, bool noise_mode, T* noise,
                   double* rows_out = nullptr) {
    V in[37];
    const V* dat = gather_0(x, first, false, in);
    // rows [J | r] padded to 16 (whole tiles): the Jacobian writes only its structural
    // non-zeros, so the zeros this buffer starts with are never overwritten
    static T raw[LANES][96];
    static T ab[LANES][96];  // the whitened rows, every entry written
    jacobian_0(in, dat, raw);
    bool finite = true;
    for (int l = 0; l < LANES; ++l) {
        if (first + l >= 6) continue;
        const int f = BLOCK0_INSTANCES[first + l];
        const int vb = FACTOR_VAR_BEGIN[f];
        const T* line = DATA_BUF + FACTOR_DATA_OFF[f];
        whiten<16, 13, 6, 0, 6>(raw[l] + 0, ab[l] + 0, line + 12);
        reweight<16, 13, 6>(ab[l] + 0, line[13], line[14]);
#ifndef __SYNTHESIS__
        if (rows_out != nullptr) {
            double* out = rows_out + (first + l) * 78;
            for (int r = 0; r < 6; ++r) {
                for (int c = 0; c < 13; ++c) out[r * 13 + c] = static_cast<double>(ab[l][r * 16 + c]);
            }
            continue;
        }
#endif
        if (noise_mode) {
            T scale[16];  // per column: largest storage entry of its variable (0: b, padding)
            for (int c = 0; c < 16; ++c) scale[c] = T(0);
            for (int j = 0; j < 6; ++j) scale[0 + j] = VAR_SCALE[FACTOR_VARS[vb + 0]];
            for (int j = 0; j < 6; ++j) scale[6 + j] = VAR_SCALE[FACTOR_VARS[vb + 1]];
            *noise += rounding_noise<16, 13, 6>(ab[l], scale);
            continue;
        }
        int col[12];  // per column: its tangent entry
        for (int j = 0; j < 6; ++j) col[0 + j] = VAR_T_OFF[FACTOR_VARS[vb + 0]] + j;
        for (int j = 0; j < 6; ++j) col[6 + j] = VAR_T_OFF[FACTOR_VARS[vb + 1]] + j;
        finite = accumulate<16, 13, 6>(ab[l], col) && finite;
        L* rows = AB + FACTOR_A_OFF[f];
        for (int r = 0; r < 6; ++r) {
            for (int c = 0; c < 13; ++c) rows[r * 13 + c] = ab[l][r * 16 + c];
        }
    }
    return finite;
}

// block 0, mode 2: add the cost of instances first ... first + LANES - 1 to *total, in order
void cost_of_0(const T* x, int first, T* total) {
    V in[37];
    const V* dat = gather_0(x, first, true, in);
    T half[LANES][1];
    cost_0(in, dat, half);
    for (int l = 0; l < LANES; ++l) {
        if (first + l >= 6) continue;
        const T* line = DATA_BUF + FACTOR_DATA_OFF[BLOCK0_INSTANCES[first + l]];
        T cost = T(0);
        cost += robust_loss(half[l][0], line[13], line[14]);
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
// and the whitened rows into the A buffer; false if not finite. Mode 3 (true): only add
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
        finite = accumulate<8, 7, 6>(ab[l], col) && finite;
        L* rows = AB + FACTOR_A_OFF[f];
        for (int r = 0; r < 6; ++r) {
            for (int c = 0; c < 7; ++c) rows[r * 7 + c] = ab[l][r * 8 + c];
        }
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

// Linearise every factor (each block type is its own pipelined unit); false if not finite.
bool linearize_all(const T* x) {
    for (int i = 0; i < N_TANGENT; ++i) G[i] = T(0);
    bool finite = true;
    T unused = T(0);  // mode 1 adds no noise
    for (int i = 0; i < 6; i += LANES) finite = linearize_0(x, i, false, &unused) && finite;
    for (int i = 0; i < 1; i += LANES) finite = linearize_1(x, i, false, &unused) && finite;
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
    for (int i = 0; i < 6; i += LANES) linearize_0(x, i, true, &noise);
    for (int i = 0; i < 1; i += LANES) linearize_1(x, i, true, &noise);
    return noise;
}

#ifndef __SYNTHESIS__
// The whitened rows [A | b] of every factor instance at x (mode 4), block by block, each block's
// instances in order: what a caller eliminating part of the graph itself (the fixed-lag
// stream's marginalisation) needs.
void linearized_rows(const T* x, double* out) {
    T unused = T(0);
    for (int i = 0; i < 6; i += LANES) linearize_0(x, i, false, &unused, out + 0);
    for (int i = 0; i < 1; i += LANES) linearize_1(x, i, false, &unused, out + 468);
}
#endif

// The graph's cost (GTSAM's error) at x: every block in cost mode.
T total_cost(const T* x) {
    T total = T(0);
    for (int i = 0; i < 6; i += LANES) cost_of_0(x, i, &total);
    for (int i = 0; i < 1; i += LANES) cost_of_1(x, i, &total);
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

void retract_all(const T* x, const T* delta, T* out) {
    for (int i = 0; i < 5; ++i) {
        const int v = KIND0_VARIABLES[i];
        retract_0(x + VAR_X_OFF[v], delta + VAR_T_OFF[v], out + VAR_X_OFF[v]);
    }
}

// ---- partial QR (paper A): per step the stacked rows [A | b] of its factors, its children's new
// factors and the damping rows sqrt(mu) I; the Evaluate unit builds the Householder vector of one
// column, n_u Update units apply it to the columns after it. Then the conditional (the first f
// rows) and the new factor for the parent. False if rank deficient.
template <int LD, int MR>
bool householder(T (*W)[LD], int m, int w, int f, int s, const int* plan) {
    int scanned[MR];
    T v[MR];
    T dots[LD + TILE];
    const int k = m < w + 1 ? m : w + 1;
    const int end = (w + TILE) / TILE * TILE;  // padded row length (<= LD)
    for (int j = 0; j < k; ++j) {  // Evaluate: Householder vector of column j
#pragma HLS LOOP_TRIPCOUNT max=18
        // rows with a zero in column j have v_i = 0: the reflection leaves them unchanged, so
        // only the pivot row and the non-zero rows are touched (zeros are never computed).
        // A step pattern's plan lists them (structurally: "n, rows" per column); else a scan.
        int n = 0;
        const int* active = scanned;
        if (plan != nullptr) {
            n = plan[0];
            active = plan + 1;
            plan += n + 1;
        } else {
            for (int i = j; i < m; ++i) {
#pragma HLS LOOP_TRIPCOUNT max=54
                if (i == j || W[i][j] != T(0)) scanned[n++] = i;
            }
        }
        // the column scaled by its largest magnitude: |v| <= 1, so v.v neither underflows on a
        // tiny non-zero column (float32: 1e-20 squared is 0, and tau would be inf) nor
        // overflows; the reflection I - tau v v^T does not depend on v's scale.
        T big = T(0);
        for (int a = 0; a < n; ++a) {
#pragma HLS LOOP_TRIPCOUNT max=54
            const T e = fgc_abs(W[active[a]][j]);
            big = e > big ? e : big;
        }
        if (big == T(0)) continue;
        for (int a = 0; a < n; ++a) {
#pragma HLS LOOP_TRIPCOUNT max=54
            v[a] = W[active[a]][j] / big;
        }
        T part[TILE];  // TILE interleaved partial sums of the squares: short chains, fixed order
        for (int t = 0; t < TILE; ++t) part[t] = T(0);
        int a = 0;
        for (; a + TILE <= n; a += TILE) {
#pragma HLS LOOP_TRIPCOUNT max=13
            for (int t = 0; t < TILE; ++t) part[t] += v[a + t] * v[a + t];
        }
        for (; a < n; ++a) {
#pragma HLS LOOP_TRIPCOUNT max=4
            part[0] += v[a] * v[a];
        }
        T norm2 = T(0);
        for (int t = 0; t < TILE; ++t) norm2 += part[t];
        const T norm = fgc_sqrt(norm2);  // of the scaled column: >= 1
        const T pivot = v[0];  // active[0] is the pivot row j
        const T alpha = pivot >= T(0) ? T(-norm) : norm;
        v[0] = pivot - alpha;
        const T tau = T(1) / (norm2 - alpha * pivot);  // 2 / |v|^2, without a second sum
        // columns from the tile boundary at or left of j + 1 to the end of the padded row:
        // whole vectors; left of j + 1 the active rows are zero (and column j is set below)
        const int c0 = (j + 1) - (j + 1) % TILE;
        // Update: dots = v^T W, 2 TILE columns (two independent accumulator chains) at a time
        for (int c = c0; c < end; c += 2 * TILE) {
#pragma HLS LOOP_TRIPCOUNT max=3
            const int width = end - c < 2 * TILE ? TILE : 2 * TILE;
            T acc[2 * TILE];
            for (int t = 0; t < 2 * TILE; ++t) acc[t] = T(0);
            if (width == 2 * TILE) {
                for (int a = 0; a < n; ++a) {
#pragma HLS LOOP_TRIPCOUNT max=54
#pragma HLS PIPELINE
                    const T va = v[a];
                    const T* row = W[active[a]] + c;
                    for (int t = 0; t < 2 * TILE; ++t) acc[t] += va * row[t];
                }
            } else {
                for (int a = 0; a < n; ++a) {
#pragma HLS LOOP_TRIPCOUNT max=54
#pragma HLS PIPELINE
                    const T va = v[a];
                    const T* row = W[active[a]] + c;
                    for (int t = 0; t < TILE; ++t) acc[t] += va * row[t];
                }
            }
            for (int t = 0; t < 2 * TILE; ++t) dots[c + t] = acc[t];  // past end: unused
        }
        for (int a = 0; a < n; ++a) {
#pragma HLS LOOP_TRIPCOUNT max=54
            const T tv = tau * v[a];
            T* row = W[active[a]];
            for (int c = c0; c < end; ++c) {
#pragma HLS LOOP_TRIPCOUNT max=20
#pragma HLS UNROLL factor=4
                row[c] -= tv * dots[c];
            }
            row[j] = T(0);
        }
        W[j][j] = alpha * big;
    }
    T scale = T(0);
    for (int i = 0; i < k; ++i) {
#pragma HLS LOOP_TRIPCOUNT max=18
        for (int c = i; c <= w; ++c) {
#pragma HLS LOOP_TRIPCOUNT max=18
            scale = fgc_abs(W[i][c]) > scale ? fgc_abs(W[i][c]) : scale;
        }
    }
    if (k < f) return false;
    T* cond = COND + STEP_COND_OFF[s];
    for (int i = 0; i < f; ++i) {
#pragma HLS LOOP_TRIPCOUNT max=18
        if (!(fgc_abs(W[i][i]) > SINGULAR_EPS * scale)) return false;
        for (int c = 0; c <= w; ++c) {
#pragma HLS LOOP_TRIPCOUNT max=18
            cond[i * (w + 1) + c] = W[i][c];
        }
    }
    const int sw = w - f;
    T* nf = NF + STEP_NF_OFF[s];
    for (int r = 0; r < STEP_NF_ROWS[s]; ++r) {
#pragma HLS LOOP_TRIPCOUNT max=18
        for (int c = 0; c <= sw; ++c) {
#pragma HLS LOOP_TRIPCOUNT max=18
            nf[r * (sw + 1) + c] = W[f + r][f + c];
        }
    }
    return true;
}

// Any step: stack its rows through the step tables, then triangularise.
template <int U>
bool eliminate_step(int s, T root_mu) {
    static T W[MAX_ROWS][MAX_LD];
#pragma HLS ARRAY_PARTITION variable=W cyclic factor=4 dim=2
    const int w = STEP_W[s], f = STEP_F[s], m = STEP_ROWS[s];
    const int end = (w + TILE) / TILE * TILE;  // the padded row: nothing reads past it
    for (int i = 0; i < m; ++i) {
#pragma HLS LOOP_TRIPCOUNT max=54
        for (int c = 0; c < end; ++c) W[i][c] = T(0);
    }
    int row = 0;
    for (int e = STEP_FACTOR_BEGIN[s]; e < STEP_FACTOR_BEGIN[s + 1]; ++e) {
#pragma HLS LOOP_TRIPCOUNT max=3
        const int fac = STEP_FACTORS[e];
        const int* cm = FACTOR_COLMAP + FACTOR_COLMAP_BEGIN[fac];
        const int d = FACTOR_COLMAP_BEGIN[fac + 1] - FACTOR_COLMAP_BEGIN[fac];
        const int rows = (FACTOR_A_OFF[fac + 1] - FACTOR_A_OFF[fac]) / (d + 1);
        const T* ab = AB + FACTOR_A_OFF[fac];
        for (int r = 0; r < rows; ++r, ++row) {
#pragma HLS LOOP_TRIPCOUNT max=54
            for (int c = 0; c < d; ++c) {
#pragma HLS LOOP_TRIPCOUNT max=18
                W[row][cm[c]] = ab[r * (d + 1) + c];
            }
            W[row][w] = ab[r * (d + 1) + d];
        }
    }
    for (int e = STEP_CHILD_BEGIN[s]; e < STEP_CHILD_BEGIN[s + 1]; ++e) {
#pragma HLS LOOP_TRIPCOUNT max=2
        const int c = STEP_CHILDREN[e];
        const int sc = STEP_W[c] - STEP_F[c];
        const int* map = STEP_SEPMAP + STEP_SEPMAP_BEGIN[c];
        const T* nf = NF + STEP_NF_OFF[c];
        for (int r = 0; r < STEP_NF_ROWS[c]; ++r, ++row) {
#pragma HLS LOOP_TRIPCOUNT max=18
            for (int k = 0; k < sc; ++k) {
#pragma HLS LOOP_TRIPCOUNT max=18
                W[row][map[k]] = nf[r * (sc + 1) + k];
            }
            W[row][w] = nf[r * (sc + 1) + sc];
        }
    }
    for (int j = 0; j < f; ++j, ++row) {
#pragma HLS LOOP_TRIPCOUNT max=18
        W[row][j] = root_mu;
    }
    return householder<MAX_LD, (MAX_ROWS > TILE ? MAX_ROWS : TILE)>(W, m, w, f, s, nullptr);
}

// One step through its specialised routine, or the generic one.
template <int U>
bool eliminate(int s, T mu) {
    return eliminate_step<U>(s, mu);
}

// Eliminate every step, level by level (a level's steps are independent: the unit sets take
// them 1 at a time), then back-substitute root first. False if singular.
bool solve(T mu) {
    const T root_mu = fgc_sqrt(mu);
    bool ok = true;
    for (int l = 0; l < N_LEVELS; ++l) {
        for (int i = LEVEL_BEGIN[l]; i < LEVEL_BEGIN[l + 1]; i += UNIT_SETS) {
#pragma HLS LOOP_TRIPCOUNT max=2
#pragma HLS DATAFLOW
            if (i + 0 < LEVEL_BEGIN[l + 1]) ok = eliminate<0>(LEVEL_STEPS[i + 0], root_mu) && ok;
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
#pragma HLS LOOP_TRIPCOUNT max=18
                xs[c] = DELTA[cols[c]];
            }
            // the separator's share of every row first: the rows do not wait for each other
            T rhs[MAX_F];
            for (int r = 0; r < f; ++r) {
#pragma HLS LOOP_TRIPCOUNT max=18
                const T* row = cond + r * (w + 1);
                T part[TILE];  // TILE interleaved partial sums: a fixed order, short chains
                for (int t = 0; t < TILE; ++t) part[t] = T(0);
                int c = f;
                for (; c + TILE <= w; c += TILE) {
#pragma HLS LOOP_TRIPCOUNT max=5
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
#pragma HLS LOOP_TRIPCOUNT max=18
                inv[r] = T(1) / cond[r * (w + 1) + r];
            }
            for (int r = f - 1; r >= 0; --r) {
#pragma HLS LOOP_TRIPCOUNT max=18
                const T xr = rhs[r] * inv[r];
                xs[r] = xr;
                for (int i = 0; i < r; ++i) {
#pragma HLS LOOP_TRIPCOUNT max=18
                    rhs[i] -= cond[i * (w + 1) + r] * xr;
                }
            }
            for (int c = 0; c < f; ++c) {
#pragma HLS LOOP_TRIPCOUNT max=18
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
}
#endif

}  // namespace

void (*progress_hook)(int, double, double, double) = nullptr;

}  // namespace fgc

void pose_graph_top(const fgc::T x_in[fgc::N_X], const fgc::T data[fgc::N_DATA],
                    fgc::T x_out[fgc::N_X], fgc::T errors[2], int info[3]) {
#pragma HLS INTERFACE m_axi port=x_in offset=slave bundle=gmem0 depth=60
#pragma HLS INTERFACE m_axi port=data offset=slave bundle=gmem1 depth=105
#pragma HLS INTERFACE m_axi port=x_out offset=slave bundle=gmem0 depth=60
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
void pose_graph_probe(const fgc::T x_in[fgc::N_X], const fgc::T data[fgc::N_DATA], fgc::T out[2]) {
    fgc::host_inputs(x_in, data);
    out[0] = fgc::total_cost(fgc::X);
    out[1] = fgc::rounding_noise_all(fgc::X);
}

void pose_graph_rows(const fgc::T x_in[fgc::N_X], const fgc::T data[fgc::N_DATA], double* out) {
    fgc::host_inputs(x_in, data);
    fgc::linearized_rows(fgc::X, out);
}
#endif
