// generated from template kernel.h.jinja by fgc 0.1.0 — do not edit
// Problem: imu_window
// chain graph, two-ended ordering; solver: lm cholesky auto n_u=4 cpe=20
//
// A CPU program, not a hardware design (fgc_backends.native): built with the host compiler as a
// shared library, with SIMD lanes and host-only paths; g++ ignores the `#pragma HLS` lines, which
// stay only while the HLS backend renders this template too.
//
// The accelerator is specialised to this structure: sizes and tables below are compile-time
// constants; measurements, noise and initial values arrive at run time (fgc data file).
#ifndef FGC_IMU_WINDOW_H
#define FGC_IMU_WINDOW_H

#include <cmath>

namespace fgc {

typedef float T;  // the accelerator's scalar type
typedef T L;  // the linear solver's scalar type

const int N_VARIABLES = 24;
const int N_FACTORS = 10;
const int N_STEPS = 7;
const int N_LEVELS = 4;
const int N_X = 168;
const int N_TANGENT = 120;
const int N_DATA = 1395;
const int N_A = 3351;
const int N_GRAM = 3538;
const int N_COND = 3720;
const int N_NF = 1440;
const int MAX_W = 30;
const int MAX_F = 30;
const int MAX_ROWS = 75;
const int MAX_STEP_FACTORS = 4;
const int MAX_CHILDREN = 2;
const int MAX_VARIABLES = 24;  // the compiled window (Program.max_variables)
const int MAX_LINE_CHARS = 6304;  // longest data-file line the testbench reads
const int N_STATUSES = 3;
const int N_REASONS = 10;
static const int VAR_X_OFF[25] = {
    0, 12, 15, 21, 33, 36, 42, 54, 57, 63, 75, 78, 84, 96, 99, 105,
    117, 120, 126, 138, 141, 147, 159, 162, 168,
};
static const int FACTOR_DATA_OFF[11] = {
    0, 195, 390, 585, 780, 975, 1170, 1365, 1380, 1386, 1395,
};

// ---- scalar math: one wrapper per function, so the scalar type decides the implementation
inline T fgc_sqrt(T x) { return std::sqrt(x); }
inline T fgc_sin(T x) { return std::sin(x); }
inline T fgc_cos(T x) { return std::cos(x); }
inline T fgc_tan(T x) { return std::tan(x); }
inline T fgc_atan(T x) { return std::atan(x); }
inline T fgc_atan2(T y, T x) { return std::atan2(y, x); }
inline T fgc_exp(T x) { return std::exp(x); }
inline T fgc_log(T x) { return std::log(x); }
inline T fgc_log1p(T x) { return std::log1p(x); }
inline T fgc_abs(T x) { return std::fabs(x); }
inline bool fgc_isfinite(T x) { return std::isfinite(x); }

// ---- robust Lie coefficients of t = θ² (fgc/frontend/geometry/special.py): series below t < 4,
// closed form above
inline T lie_A(T t) {
    if (t < T(4.0)) {
        return T(1.0) + t*(T(-0.16666666666666666) + t*(T(0.008333333333333333) + t*(T(-0.0001984126984126984) + t*(T(2.7557319223985893e-06) + t*(T(-2.505210838544172e-08) + t*(T(1.6059043836821613e-10) + t*(T(-7.647163731819816e-13) + t*(T(2.8114572543455206e-15) + t*(T(-8.22063524662433e-18) + t*(T(1.9572941063391263e-20) + t*(T(-3.868170170630684e-23))))))))))));
    }
    const T c0 = fgc_sqrt(t);
    const T c1 = fgc_sin(c0);
    const T c2 = c1/c0;
    return c2;
}

inline T lie_B(T t) {
    if (t < T(4.0)) {
        return T(0.5) + t*(T(-0.041666666666666664) + t*(T(0.001388888888888889) + t*(T(-2.48015873015873e-05) + t*(T(2.755731922398589e-07) + t*(T(-2.08767569878681e-09) + t*(T(1.1470745597729725e-11) + t*(T(-4.779477332387385e-14) + t*(T(1.5619206968586225e-16) + t*(T(-4.110317623312165e-19) + t*(T(8.896791392450574e-22) + t*(T(-1.6117375710961184e-24))))))))))));
    }
    const T c0 = fgc_sqrt(t);
    const T c1 = T(2)*((fgc_sin((T(0.5))*c0))*(fgc_sin((T(0.5))*c0)))/t;
    return c1;
}

inline T lie_C(T t) {
    if (t < T(4.0)) {
        return T(0.16666666666666666) + t*(T(-0.008333333333333333) + t*(T(0.0001984126984126984) + t*(T(-2.7557319223985893e-06) + t*(T(2.505210838544172e-08) + t*(T(-1.6059043836821613e-10) + t*(T(7.647163731819816e-13) + t*(T(-2.8114572543455206e-15) + t*(T(8.22063524662433e-18) + t*(T(-1.9572941063391263e-20) + t*(T(3.868170170630684e-23) + t*(T(-6.446950284384474e-26))))))))))));
    }
    const T c0 = fgc_sqrt(t);
    const T c1 = fgc_sin(c0);
    const T c2 = (-c1 + c0)/(t*c0);
    return c2;
}

inline T lie_D(T t) {
    if (t < T(4.0)) {
        return T(0.08333333333333333) + t*(T(0.001388888888888889) + t*(T(3.306878306878307e-05) + t*(T(8.267195767195768e-07) + t*(T(2.08767569878681e-08) + t*(T(5.284190138687493e-10) + t*(T(1.3382536530684679e-11) + t*(T(3.3896802963225827e-13) + t*(T(8.586062056277845e-15) + t*(T(2.174868698558062e-16) + t*(T(5.5090028283602295e-18) + t*(T(1.3954464685812522e-19) + t*(T(3.534707039629467e-21) + t*(T(8.953517427037546e-23) + t*(T(2.267952452337683e-24) + t*(T(5.744790668872202e-26) + t*(T(1.455172475614865e-27) + t*(T(3.6859949406653103e-29) + t*(T(9.336734257095045e-31) + t*(T(2.36502241570063e-32) + t*(T(5.990671762482134e-34) + t*(T(1.5174548844682903e-35))))))))))))))))))))));
    }
    const T c0 = fgc_sqrt(t);
    const T c1 = fgc_cos((T(0.5))*c0)/fgc_sin((T(0.5))*c0);
    return -T(0.5)*c1/c0 + (T(1)/(t));
}

inline T lie_A1(T t) {
    if (t < T(4.0)) {
        return T(-0.16666666666666666) + t*(T(0.016666666666666666) + t*(T(-0.0005952380952380953) + t*(T(1.1022927689594357e-05) + t*(T(-1.252605419272086e-07) + t*(T(9.635426302092969e-10) + t*(T(-5.353014612273871e-12) + t*(T(2.2491658034764165e-14) + t*(T(-7.398571721961897e-17) + t*(T(1.9572941063391261e-19) + t*(T(-4.254987187693753e-22)))))))))));
    }
    const T c0 = fgc_sqrt(t);
    const T c1 = fgc_sin(c0);
    const T c2 = fgc_cos(c0);
    const T c3 = c1/c0;
    return (T(0.5))*(-c3 + c2)/t;
}

inline T lie_B1(T t) {
    if (t < T(4.0)) {
        return T(-0.041666666666666664) + t*(T(0.002777777777777778) + t*(T(-7.440476190476191e-05) + t*(T(1.1022927689594355e-06) + t*(T(-1.043837849393405e-08) + t*(T(6.882447358637835e-11) + t*(T(-3.3456341326711696e-13) + t*(T(1.249536557486898e-15) + t*(T(-3.6992858609809485e-18) + t*(T(8.896791392450573e-21) + t*(T(-1.77291132820573e-23)))))))))));
    }
    const T c0 = fgc_sqrt(t);
    const T c1 = fgc_sin(c0);
    const T c2 = c1/c0;
    const T c3 = T(2)*((fgc_sin((T(0.5))*c0))*(fgc_sin((T(0.5))*c0)))/t;
    return ((T(0.5))*c2 - c3)/t;
}

inline T lie_C1(T t) {
    if (t < T(4.0)) {
        return T(-0.008333333333333333) + t*(T(0.0003968253968253968) + t*(T(-8.267195767195768e-06) + t*(T(1.0020843354176688e-07) + t*(T(-8.029521918410807e-10) + t*(T(4.58829823909189e-12) + t*(T(-1.9680200780418645e-14) + t*(T(6.576508197299464e-17) + t*(T(-1.7615646957052136e-19) + t*(T(3.868170170630684e-22) + t*(T(-7.091645312822921e-25)))))))))));
    }
    const T c0 = fgc_sqrt(t);
    const T c1 = fgc_sin(c0);
    const T c2 = T(2)*((fgc_sin((T(0.5))*c0))*(fgc_sin((T(0.5))*c0)))/t;
    const T c3 = (-c1 + c0)/(t*c0);
    return (T(0.5))*(c2 - T(3)*c3)/t;
}

inline T lie_D1(T t) {
    if (t < T(4.0)) {
        return T(0.001388888888888889) + t*(T(6.613756613756614e-05) + t*(T(2.48015873015873e-06) + t*(T(8.35070279514724e-08) + t*(T(2.6420950693437467e-09) + t*(T(8.029521918410807e-11) + t*(T(2.372776207425808e-12) + t*(T(6.868849645022276e-14) + t*(T(1.9573818287022555e-15) + t*(T(5.5090028283602297e-17) + t*(T(1.5349911154393775e-18) + t*(T(4.241648447555361e-20) + t*(T(1.163957265514881e-21) + t*(T(3.1751334332727565e-23) + t*(T(8.617186003308303e-25) + t*(T(2.328275960983784e-26) + t*(T(6.266191399131027e-28) + t*(T(1.6806121662771081e-29) + t*(T(4.4935425898311966e-31) + t*(T(1.1981343524964268e-32) + t*(T(3.1866552573834097e-34)))))))))))))))))))));
    }
    const T c0 = fgc_sqrt(t);
    const T c1 = fgc_cos((T(0.5))*c0)/fgc_sin((T(0.5))*c0);
    return (T(0.5))*((T(0.5))*c1/t + (T(0.25))/(c0*((fgc_sin((T(0.5))*c0))*(fgc_sin((T(0.5))*c0)))) - T(2)/(t*c0))/c0;
}

// Rotation vector ω with Exp(ω) = R (R row-major). θ = atan2(sin θ, cos θ); the axis comes
// from the skew part when cos θ ≥ 0 and from the symmetric part otherwise, so θ → π keeps
// its digits (special.so3_log_numeric).
inline void so3_log(T r00, T r01, T r02, T r10, T r11, T r12, T r20, T r21, T r22, T w[3]) {
    const T sk[3] = {r21 - r12, r02 - r20, r10 - r01};
    const T cos_t = T(0.5) * (r00 + r11 + r22 - T(1));
    const T sin_t = T(0.5) * fgc_sqrt(sk[0] * sk[0] + sk[1] * sk[1] + sk[2] * sk[2]);
    const T theta = fgc_atan2(sin_t, cos_t);
    if (cos_t >= T(0)) {
        const T scale = T(0.5) * (sin_t > T(0) ? T(theta / sin_t) : T(1));  // θ / (2 sin θ)
        for (int i = 0; i < 3; ++i) w[i] = scale * sk[i];
        return;
    }
    const T sym[3][3] = {{r00 - cos_t, T(0.5) * (r01 + r10), T(0.5) * (r02 + r20)},
                         {T(0.5) * (r10 + r01), r11 - cos_t, T(0.5) * (r12 + r21)},
                         {T(0.5) * (r20 + r02), T(0.5) * (r21 + r12), r22 - cos_t}};
    int k = 0;
    for (int i = 1; i < 3; ++i) {
        if (sym[i][i] > sym[k][k]) k = i;
    }
    const T first = fgc_sqrt(sym[k][k] * (T(1) - cos_t));
    T axis[3];
    for (int i = 0; i < 3; ++i) axis[i] = sym[i][k] / first;
    const T norm = fgc_sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
    const T dot = axis[0] * sk[0] + axis[1] * sk[1] + axis[2] * sk[2];
    const T sign = dot < T(0) ? T(-1) : T(1);
    for (int i = 0; i < 3; ++i) w[i] = sign * theta * (axis[i] / norm);
}

inline T so3_log_x(T r00, T r01, T r02, T r10, T r11, T r12, T r20, T r21, T r22) {
    T w[3];
    so3_log(r00, r01, r02, r10, r11, r12, r20, r21, r22, w);
    return w[0];
}

inline T so3_log_y(T r00, T r01, T r02, T r10, T r11, T r12, T r20, T r21, T r22) {
    T w[3];
    so3_log(r00, r01, r02, r10, r11, r12, r20, r21, r22, w);
    return w[1];
}

inline T so3_log_z(T r00, T r01, T r02, T r10, T r11, T r12, T r20, T r21, T r22) {
    T w[3];
    so3_log(r00, r01, r02, r10, r11, r12, r20, r21, r22, w);
    return w[2];
}

#ifndef __SYNTHESIS__
// Host only: called after each accepted iteration of the top function with (iteration, cost,
// LM's damping for the next iteration, the relative decrease) when set; null (the default)
// costs one test per iteration. fgc's progress display sets it through fgc_set_progress.
extern void (*progress_hook)(int, double, double, double);
#endif

}  // namespace fgc

// The accelerator: optimise the variables x_in (storage, VAR_X_OFF layout) given the factor data
// (FACTOR_DATA_OFF layout) into x_out; errors = {initial, final}, info = {iterations, status,
// reason} (status/reason: indices into the result file's names).
void imu_window_top(const fgc::T x_in[fgc::N_X], const fgc::T data[fgc::N_DATA],
                    fgc::T x_out[fgc::N_X], fgc::T errors[2], int info[3]);

#ifndef __SYNTHESIS__
// Host only: the cost at x_in and its rounding noise (how far the cost moves when x is rounded
// to the scalar type, the tolerance the step test in try_steps grants a step that is not below
// the cost), computed as the accelerator computes them: out = {cost, noise}.
void imu_window_probe(const fgc::T x_in[fgc::N_X], const fgc::T data[fgc::N_DATA], fgc::T out[2]);
// the whitened rows [A | b] of every factor instance at x_in (3351 numbers: per block, per instance,
// residual rows x (tangent columns + 1), row-major)
void imu_window_rows(const fgc::T x_in[fgc::N_X], const fgc::T data[fgc::N_DATA], double* out);
#endif

#endif  // FGC_IMU_WINDOW_H
