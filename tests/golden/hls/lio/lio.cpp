// generated from template accel.cpp.jinja by fgc 0.1.0 — do not edit
// Problem: lio
// chain graph, two-ended ordering; solver: lm qr auto n_u=4 cpe=20
//
// The dataflow accelerator of the accelerator plan (fgc_backends.hls.plan, docs/hls.md). One
// Levenberg-Marquardt iteration: the factor datapaths (Jacobian mode) -> whitened rows [A | b] (AB)
// -> per schedule level the QR unit set(s): Evaluate + n_u Update units over streams
// -> back-substitution -> state update (retract) -> the factor datapaths (cost mode) -> LM control.
//
// The linear solver's process network (from the plan): the units' DATAFLOW regions, then
// back_substitute's by columns (the loader streaming COND to a process per end of the chain,
// the state update fed by both):
//   21 processes, 55 streams (n_u=4, 2 unit set(s))
//   process qr0_broadcast
//   process qr0_finish
//   process qr0_update0
//   process qr0_update1
//   process qr0_update2
//   process qr0_update3
//   process qr0_evaluate
//   process qr0_collect
//   process qr1_broadcast
//   process qr1_finish
//   process qr1_update0
//   process qr1_update1
//   process qr1_update2
//   process qr1_update3
//   process qr1_evaluate
//   process qr1_collect
//   process backsub_loader
//   process backsub_end0
//   process backsub_end1
//   process backsub_retire
//   process trial_cost
//   stream qr0_v0 depth=8: qr0_broadcast -> qr0_update0
//   stream qr0_v1 depth=8: qr0_broadcast -> qr0_update1
//   stream qr0_v2 depth=8: qr0_broadcast -> qr0_update2
//   stream qr0_v3 depth=8: qr0_broadcast -> qr0_update3
//   stream qr0_t0 depth=2: qr0_finish -> qr0_update0
//   stream qr0_t1 depth=2: qr0_finish -> qr0_update1
//   stream qr0_t2 depth=2: qr0_finish -> qr0_update2
//   stream qr0_t3 depth=2: qr0_finish -> qr0_update3
//   stream qr0_r depth=1: qr0_finish -> qr0_collect
//   stream qr0_col0_even depth=44: qr0_update0 -> qr0_evaluate
//   stream qr0_col0_odd depth=44: qr0_update0 -> qr0_evaluate
//   stream qr0_row0 depth=2: qr0_update0 -> qr0_collect
//   stream qr0_col1_even depth=44: qr0_update1 -> qr0_evaluate
//   stream qr0_col1_odd depth=44: qr0_update1 -> qr0_evaluate
//   stream qr0_row1 depth=2: qr0_update1 -> qr0_collect
//   stream qr0_col2_even depth=44: qr0_update2 -> qr0_evaluate
//   stream qr0_col2_odd depth=44: qr0_update2 -> qr0_evaluate
//   stream qr0_row2 depth=2: qr0_update2 -> qr0_collect
//   stream qr0_col3_even depth=44: qr0_update3 -> qr0_evaluate
//   stream qr0_col3_odd depth=44: qr0_update3 -> qr0_evaluate
//   stream qr0_row3 depth=2: qr0_update3 -> qr0_collect
//   stream qr0_ve depth=2: qr0_broadcast -> qr0_evaluate
//   stream qr0_te depth=3: qr0_finish -> qr0_evaluate
//   stream qr0_e depth=2: qr0_evaluate -> qr0_collect
//   stream qr1_v0 depth=8: qr1_broadcast -> qr1_update0
//   stream qr1_v1 depth=8: qr1_broadcast -> qr1_update1
//   stream qr1_v2 depth=8: qr1_broadcast -> qr1_update2
//   stream qr1_v3 depth=8: qr1_broadcast -> qr1_update3
//   stream qr1_t0 depth=2: qr1_finish -> qr1_update0
//   stream qr1_t1 depth=2: qr1_finish -> qr1_update1
//   stream qr1_t2 depth=2: qr1_finish -> qr1_update2
//   stream qr1_t3 depth=2: qr1_finish -> qr1_update3
//   stream qr1_r depth=1: qr1_finish -> qr1_collect
//   stream qr1_col0_even depth=44: qr1_update0 -> qr1_evaluate
//   stream qr1_col0_odd depth=44: qr1_update0 -> qr1_evaluate
//   stream qr1_row0 depth=2: qr1_update0 -> qr1_collect
//   stream qr1_col1_even depth=44: qr1_update1 -> qr1_evaluate
//   stream qr1_col1_odd depth=44: qr1_update1 -> qr1_evaluate
//   stream qr1_row1 depth=2: qr1_update1 -> qr1_collect
//   stream qr1_col2_even depth=44: qr1_update2 -> qr1_evaluate
//   stream qr1_col2_odd depth=44: qr1_update2 -> qr1_evaluate
//   stream qr1_row2 depth=2: qr1_update2 -> qr1_collect
//   stream qr1_col3_even depth=44: qr1_update3 -> qr1_evaluate
//   stream qr1_col3_odd depth=44: qr1_update3 -> qr1_evaluate
//   stream qr1_row3 depth=2: qr1_update3 -> qr1_collect
//   stream qr1_ve depth=2: qr1_broadcast -> qr1_evaluate
//   stream qr1_te depth=3: qr1_finish -> qr1_evaluate
//   stream qr1_e depth=2: qr1_evaluate -> qr1_collect
//   stream backsub_groups0 depth=97: backsub_loader -> backsub_end0
//   stream backsub_dx0 depth=39: backsub_end0 -> backsub_retire
//   stream backsub_groups1 depth=100: backsub_loader -> backsub_end1
//   stream backsub_dx1 depth=24: backsub_end1 -> backsub_retire
//   stream backsub_xroot depth=30: backsub_end0 -> backsub_end1
//   stream trial_tx depth=24: backsub_retire -> trial_cost
//   stream trial_tx2 depth=24: backsub_retire -> trial_cost
#include "lio.h"

#include "hls_stream.h"
#include "fgc_qr.h"
#include "fgc_backsub.h"
#define FGC_LM_COST_IN_LINEARIZE  // fgc_lm.h: the first linearisation gives the cost at X (linearized_cost)
#include "fgc_lm.h"
#include "fgc_lm_units.h"

namespace fgc {
namespace {

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
const int TILE = 4;  // partial sums interleaved TILE ways; rows padded to whole TILEs
const int MAX_LD = 32;  // padded row length of the widest step
// the plan's operator latencies of T and L; the kernel's dot products and Grams interleave
// ADD_LAT partial sums (a sum comes back to the adder after it is done: II 1)
const int PORTS = 2;  // words a cycle through a memory's two ports (true dual-port RAM): the copies
const int T_ADD_LAT = 4, T_MUL_LAT = 3, T_PARTIALS = T_ADD_LAT;
const int L_ADD_LAT = 4, L_MUL_LAT = 3, L_PARTIALS = L_ADD_LAT;
// LM control's running maximum: the compare's latency, |.| ahead of it; T_MAXIMA partial maxima
const int T_CMP_LAT = 1, T_ABS_LAT = 2, T_MAXIMA = T_CMP_LAT;
const int N_UNITS = 4;  // --units: Update units per unit set
const int LOCAL_COLS = (MAX_W + 1 + N_UNITS - 1) / N_UNITS;  // columns of [W | b] per bank

// ---- the schedule and layout as constant tables (ROMs; see fgc_backends/hls/tables.py)
const int VAR_T_OFF[25] = {
    0, 6, 9, 15, 21, 24, 30, 36, 39, 45, 51, 54, 60, 66, 69, 75,
    81, 84, 90, 96, 99, 105, 111, 114, 120,
};
const int FACTOR_BLOCK[18] = {
    0, 1, 2, 3, 3, 3, 3, 3, 3, 3, 4, 4, 4, 4, 4, 4,
    4, 4,
};
const int FACTOR_A_OFF[19] = {
    0, 42, 54, 96, 747, 1398, 2049, 2700, 3351, 4002, 4653, 4674, 4695, 4716, 4737, 4758,
    4779, 4800, 4821,
};
const int FACTOR_GRAM_OFF[19] = {
    0, 28, 38, 66, 562, 1058, 1554, 2050, 2546, 3042, 3538, 3566, 3594, 3622, 3650, 3678,
    3706, 3734, 3762,
};
const int FACTOR_VAR_BEGIN[19] = {
    0, 1, 2, 3, 9, 15, 21, 27, 33, 39, 45, 46, 47, 48, 49, 50,
    51, 52, 53,
};
const int FACTOR_VARS[53] = {
    0, 1, 2, 0, 1, 3, 4, 2, 5, 3, 4, 6, 7, 5, 8, 6,
    7, 9, 10, 8, 11, 9, 10, 12, 13, 11, 14, 12, 13, 15, 16, 14,
    17, 15, 16, 18, 19, 17, 20, 18, 19, 21, 22, 20, 23, 0, 3, 6,
    9, 12, 15, 18, 21,
};
const int FACTOR_COLMAP_BEGIN[19] = {
    0, 6, 9, 15, 45, 75, 105, 135, 165, 195, 225, 231, 237, 243, 249, 255,
    261, 267, 273,
};
const int FACTOR_COLMAP[273] = {
    0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 0,
    1, 2, 3, 4, 5, 6, 7, 8, 15, 16, 17, 18, 19, 20, 21, 22,
    23, 9, 10, 11, 12, 13, 14, 24, 25, 26, 27, 28, 29, 0, 1, 2,
    3, 4, 5, 6, 7, 8, 15, 16, 17, 18, 19, 20, 21, 22, 23, 9,
    10, 11, 12, 13, 14, 24, 25, 26, 27, 28, 29, 0, 1, 2, 3, 4,
    5, 6, 7, 8, 15, 16, 17, 18, 19, 20, 21, 22, 23, 9, 10, 11,
    12, 13, 14, 24, 25, 26, 27, 28, 29, 0, 1, 2, 3, 4, 5, 6,
    7, 8, 15, 16, 17, 18, 19, 20, 21, 22, 23, 9, 10, 11, 12, 13,
    14, 24, 25, 26, 27, 28, 29, 15, 16, 17, 18, 19, 20, 21, 22, 23,
    0, 1, 2, 3, 4, 5, 6, 7, 8, 24, 25, 26, 27, 28, 29, 9,
    10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 0, 1,
    2, 3, 4, 5, 6, 7, 8, 24, 25, 26, 27, 28, 29, 9, 10, 11,
    12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 0, 1, 2, 3,
    4, 5, 6, 7, 8, 24, 25, 26, 27, 28, 29, 9, 10, 11, 12, 13,
    14, 0, 1, 2, 3, 4, 5, 0, 1, 2, 3, 4, 5, 0, 1, 2,
    3, 4, 5, 0, 1, 2, 3, 4, 5, 15, 16, 17, 18, 19, 20, 0,
    1, 2, 3, 4, 5, 0, 1, 2, 3, 4, 5, 0, 1, 2, 3, 4,
    5,
};
const int STEP_F[7] = {
    15, 15, 15, 15, 15, 15, 30,
};
const int STEP_W[7] = {
    30, 30, 30, 30, 30, 30, 30,
};
const int STEP_ROWS[7] = {
    54, 39, 54, 54, 54, 54, 87,
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
    0, 5, 7, 9, 11, 13, 15, 18,
};
const int STEP_FACTORS[18] = {
    0, 1, 2, 3, 10, 9, 17, 4, 11, 8, 16, 5, 12, 7, 15, 6,
    13, 14,
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
const int BLOCK0_INSTANCES[1] = {
    0,
};
const int BLOCK1_INSTANCES[1] = {
    1,
};
const int BLOCK2_INSTANCES[1] = {
    2,
};
const int BLOCK3_INSTANCES[7] = {
    3, 4, 5, 6, 7, 8, 9,
};
const int BLOCK4_INSTANCES[8] = {
    10, 11, 12, 13, 14, 15, 16, 17,
};

// ---- the accelerator's memories: static, sized at compile time; nothing is allocated
T X[N_X];          // current estimate (storage)
T X_TRIAL[N_X];    // x (+) delta
T DATA_BUF[N_DATA];  // the factor data, copied in once per call
L AB[N_A];         // whitened rows [A | b] of every factor instance (row-major, d + 1 columns)
T G[N_TANGENT];    // gradient A^T b
T LIN_COST = T(0);  // the cost at the last linearisation point, 1/2 sum |W r|^2 (linearize_all)
T VAR_SCALE[N_VARIABLES];
T DELTA[N_TANGENT];
L COND[N_COND];    // conditionals (R | d), one block per elimination step
L NF[N_NF];        // new factors passed to the parent step

// ---- the rest of the DSL's functions (fgc/frontend/functions.py), beside the header's wrappers
inline T fgc_asin(T x) { return std::asin(x); }
inline T fgc_acos(T x) { return std::acos(x); }
inline T fgc_tanh(T x) { return std::tanh(x); }
inline T fgc_sign(T x) { return x > T(0) ? T(1) : x < T(0) ? T(-1) : T(0); }
// a / b where g > t, else f: GTSAM's conventions at singular points (a norm's or a bearing's
// derivative at coincident points; fgc/frontend/geometry/special.py), no division where g <= t
inline T fgc_guarded_quotient(T a, T b, T g, T t, T f) { return g > t ? T(a / b) : f; }

// ---- factor datapaths, per block type: factor_<b> (the Jacobian mode: residual and Jacobian
// into `raw`), called by evaluate_<b>, and factor_cost_<b> (the members' 1/2 |W r|^2 into
// `half`), called by cost_of_<b>. Each call site is its own RTL instance, so each mode is its
// own function under its own ALLOCATION (the plan's limits for that mode).
// block 0: PriorFactorPose3 (6 rows, 6 columns, 1 instances)
void factor_0(const T in[12], const T dat[18],
              T raw[48]) {
#pragma HLS INLINE off
#pragma HLS ALLOCATION operation instances=fadd limit=3
#pragma HLS ALLOCATION operation instances=fmul limit=4
#pragma HLS ALLOCATION operation instances=fdiv limit=1
#pragma HLS ALLOCATION operation instances=fsqrt limit=1
    const T t0 = dat[6]*in[6] + (dat[0]*in[0] + dat[3]*in[3]);
    const T t1 = dat[6]*in[8] + (dat[0]*in[2] + dat[3]*in[5]);
    const T t2 = dat[6]*in[7] + (dat[0]*in[1] + dat[3]*in[4]);
    const T t3 = dat[7]*in[6] + (dat[1]*in[0] + dat[4]*in[3]);
    const T t4 = dat[7]*in[8] + (dat[1]*in[2] + dat[4]*in[5]);
    const T t5 = dat[7]*in[7] + (dat[1]*in[1] + dat[4]*in[4]);
    const T t6 = dat[8]*in[6] + (dat[2]*in[0] + dat[5]*in[3]);
    const T t7 = dat[8]*in[8] + (dat[2]*in[2] + dat[5]*in[5]);
    const T t8 = dat[8]*in[7] + (dat[2]*in[1] + dat[5]*in[4]);
    const T t9 = t0;
    const T t10 = t2;
    const T t11 = t1;
    const T t12 = t3;
    const T t13 = t5;
    const T t14 = t4;
    const T t15 = t6;
    const T t16 = t8;
    const T t17 = t7;
    T tlog0[3]; so3_log(t9, t10, t11, t12, t13, t14, t15, t16, t17, tlog0);
    const T t18 = tlog0[2];
    const T t19 = (T(0.5))*t18;
    const T t20 = tlog0[0];
    const T t21 = (t20*t20);
    const T t22 = tlog0[1];
    const T t23 = (t22*t22);
    const T t24 = (t18*t18);
    const T t25 = t23 + t24;
    const T t26 = lie_D(t21 + t25);
    const T t27 = t20*t26;
    const T t28 = t22*t27;
    const T t29 = (T(0.5))*t28 - T(0.5)*t19;
    const T t30 = T(1) - t25*t26;
    const T t31 = (T(0.5))*t30;
    const T t32 = t12*t29 - t13*t31;
    const T t33 = (T(0.5))*t22;
    const T t34 = (T(0.5))*t33 + ((T(0.5))*t18)*t27;
    const T t35 = ((T(0.5))*t17)*t30 - t15*t34;
    const T t36 = t15*t29 - t16*t31;
    const T t37 = ((T(0.5))*t11)*t30 - t9*t34;
    const T t38 = t9*t29 - t10*t31;
    const T t39 = ((T(0.5))*t14)*t30 - t12*t34;
    const T t40 = t10*t34 - t11*t29;
    const T t41 = t16*t34 - t17*t29;
    const T t42 = t13*t34 - t14*t29;
    const T t43 = T(0.5) + ((T(0.5))*(-(t21 + t24)))*t26;
    const T t44 = t19 + t28;
    const T t45 = (T(0.5))*t44;
    const T t46 = t12*t43 - t13*t45;
    const T t47 = (T(0.5))*t20;
    const T t48 = t22*t18;
    const T t49 = t48*t26;
    const T t50 = (T(0.5))*t49 - T(0.5)*t47;
    const T t51 = ((T(0.5))*t17)*t44 - t15*t50;
    const T t52 = t15*t43 - t16*t45;
    const T t53 = ((T(0.5))*t11)*t44 - t9*t50;
    const T t54 = t9*t43 - t10*t45;
    const T t55 = ((T(0.5))*t14)*t44 - t12*t50;
    const T t56 = t10*t50 - t11*t43;
    const T t57 = t16*t50 - t17*t43;
    const T t58 = t13*t50 - t14*t43;
    const T t59 = (T(0.5))*t47 + (T(0.5))*t49;
    const T t60 = (t18*t20)*t26 - t33;
    const T t61 = (T(0.5))*t60;
    const T t62 = t12*t59 - t13*t61;
    const T t63 = T(0.5) + ((T(0.5))*(-(t21 + t23)))*t26;
    const T t64 = ((T(0.5))*t17)*t60 - t15*t63;
    const T t65 = t15*t59 - t16*t61;
    const T t66 = ((T(0.5))*t11)*t60 - t9*t63;
    const T t67 = t9*t59 - t10*t61;
    const T t68 = ((T(0.5))*t14)*t60 - t12*t63;
    const T t69 = t10*t63 - t11*t59;
    const T t70 = t16*t63 - t17*t59;
    const T t71 = t13*t63 - t14*t59;
    const T t72 = T(2)*t22;
    const T t73 = T(2)*t18;
    const T t74 = T(2)*t20;
    const T t75 = t23;
    const T t76 = t24;
    const T t77 = t75 + t76;
    const T t78 = t21;
    const T t79 = t78 + t77;
    const T t80 = lie_D1(t79);
    const T t81 = lie_D(t79);
    const T t82 = t22*t81;
    const T t83 = t18*t81;
    const T t84 = T(1) - t77*t81;
    const T t85 = t19;
    const T t86 = t20*t81;
    const T t87 = t22*t86;
    const T t88 = t85 + t87;
    const T t89 = t33;
    const T t90 = t18*t86;
    const T t91 = t90 - t89;
    const T t92 = t87 - t85;
    const T t93 = -(t76 + t78);
    const T t94 = T(1) + t93*t81;
    const T t95 = t47;
    const T t96 = t48*t81;
    const T t97 = t95 + t96;
    const T t98 = t89 + t90;
    const T t99 = t96 - t95;
    const T t100 = -(t75 + t78);
    const T t101 = T(1) + t100*t81;
    const T t102 = (dat[6]*in[11] - dat[6]*dat[11]) + ((dat[0]*in[9] - dat[0]*dat[9]) + (dat[3]*in[10] - dat[3]*dat[10]));
    const T t103 = t102*t77;
    const T t104 = t102*t81;
    const T t105 = (dat[7]*in[11] - dat[7]*dat[11]) + ((dat[1]*in[9] - dat[1]*dat[9]) + (dat[4]*in[10] - dat[4]*dat[10]));
    const T t106 = t105*t93;
    const T t107 = t105*t81;
    const T t108 = (dat[8]*in[11] - dat[8]*dat[11]) + ((dat[2]*in[9] - dat[2]*dat[9]) + (dat[5]*in[10] - dat[5]*dat[10]));
    const T t109 = t108*t100;
    const T t110 = t108*t81;
    const T t111 = -t1;
    const T t112 = t2;
    const T t113 = t1;
    const T t114 = -t0;
    const T t115 = -t2;
    const T t116 = t0;
    const T t117 = -t4;
    const T t118 = t5;
    const T t119 = t4;
    const T t120 = -t3;
    const T t121 = -t5;
    const T t122 = t3;
    const T t123 = -t7;
    const T t124 = t8;
    const T t125 = t7;
    const T t126 = -t6;
    const T t127 = -t8;
    const T t128 = t6;
    const T t129 = (t127*t36 + t115*t38) + ((t125*t35 + t113*t37) + (t119*t39 + t121*t32));
    const T t130 = (t123*t41 + t117*t42) + ((t122*t32 + t128*t36) + (t116*t38 + t111*t40));
    const T t131 = (t124*t41 + t118*t42) + ((t126*t35 + t114*t37) + (t120*t39 + t112*t40));
    const T t132 = (t127*t52 + t115*t54) + ((t125*t51 + t113*t53) + (t119*t55 + t121*t46));
    const T t133 = (t128*t52 + t116*t54) + ((t111*t56 + t123*t57) + (t117*t58 + t122*t46));
    const T t134 = (t124*t57 + t118*t58) + ((t126*t51 + t114*t53) + (t120*t55 + t112*t56));
    const T t135 = (t127*t65 + t115*t67) + ((t125*t64 + t113*t66) + (t119*t68 + t121*t62));
    const T t136 = (t123*t70 + t117*t71) + ((t122*t62 + t128*t65) + (t116*t67 + t111*t69));
    const T t137 = (t124*t70 + t118*t71) + ((t126*t64 + t114*t66) + (t120*t68 + t112*t69));
    const T t138 = t72*t132;
    const T t139 = t72*t133;
    const T t140 = t72*t134;
    const T t141 = t73*t135;
    const T t142 = t73*t136;
    const T t143 = t73*t137;
    const T t144 = t141 + t138;
    const T t145 = t142 + t139;
    const T t146 = t140 + t143;
    const T t147 = t74*t129;
    const T t148 = t74*t130;
    const T t149 = t74*t131;
    const T t150 = t80*t147 + t80*t144;
    const T t151 = t80*t148 + t80*t145;
    const T t152 = t80*t149 + t80*t146;
    const T t153 = t0;
    const T t154 = t2;
    const T t155 = t1;
    const T t156 = (T(0.5))*t135;
    const T t157 = (T(0.5))*t136;
    const T t158 = (T(0.5))*t137;
    const T t159 = t81*t129 + t20*t150;
    const T t160 = t81*t130 + t20*t151;
    const T t161 = t81*t131 + t20*t152;
    const T t162 = t86*t132 + t22*t159;
    const T t163 = t86*t133 + t22*t160;
    const T t164 = t86*t134 + t22*t161;
    const T t165 = t3;
    const T t166 = t5;
    const T t167 = t4;
    const T t168 = (T(0.5))*t132;
    const T t169 = (T(0.5))*t133;
    const T t170 = (T(0.5))*t134;
    const T t171 = t86*t135 + t18*t159;
    const T t172 = t86*t136 + t18*t160;
    const T t173 = t86*t137 + t18*t161;
    const T t174 = t6;
    const T t175 = t8;
    const T t176 = t7;
    const T t177 = (T(0.5))*t129;
    const T t178 = (T(0.5))*t130;
    const T t179 = (T(0.5))*t131;
    const T t180 = (t82*t135 + t83*t132) + t48*t150;
    const T t181 = (t82*t136 + t83*t133) + t48*t151;
    const T t182 = (t82*t137 + t83*t134) + t48*t152;
    raw[0] = t129;
    raw[1] = t130;
    raw[2] = t131;
    raw[6] = t20;
    raw[8] = t132;
    raw[9] = t133;
    raw[10] = t134;
    raw[14] = t22;
    raw[16] = t135;
    raw[17] = t136;
    raw[18] = t137;
    raw[22] = t18;
    raw[24] = t108*t171 + ((((t105*t156 - t108*t168) - t104*t144) - t103*t150) + t105*t162);
    raw[25] = t108*t172 + ((((t105*t157 - t108*t169) - t104*t145) - t103*t151) + t105*t163);
    raw[26] = t108*t173 + ((((t105*t158 - t108*t170) - t104*t146) - t103*t152) + t105*t164);
    raw[27] = t174*t91 + (t153*t84 + t165*t88);
    raw[28] = t175*t91 + (t154*t84 + t166*t88);
    raw[29] = t176*t91 + (t155*t84 + t167*t88);
    raw[30] = t108*t91 + (t102*t84 + t105*t88);
    raw[32] = ((((t108*t177 - t107*t147) - (t107*t141 + t102*t156)) + t106*t150) + t108*t180) + t102*t162;
    raw[33] = ((((t108*t178 - t107*t148) - (t107*t142 + t102*t157)) + t106*t151) + t108*t181) + t102*t163;
    raw[34] = ((t106*t152 + ((t108*t179 - t107*t149) - (t107*t143 + t102*t158))) + t108*t182) + t102*t164;
    raw[35] = t153*t92 + (t165*t94 + t174*t97);
    raw[36] = t154*t92 + (t166*t94 + t175*t97);
    raw[37] = t155*t92 + (t167*t94 + t176*t97);
    raw[38] = t102*t92 + (t105*t94 + t108*t97);
    raw[40] = ((((t102*t168 - t105*t177) - (t110*t138 + t110*t147)) + t109*t150) + t105*t180) + t102*t171;
    raw[41] = ((((t102*t169 - t105*t178) - (t110*t139 + t110*t148)) + t109*t151) + t105*t181) + t102*t172;
    raw[42] = ((t109*t152 + ((t102*t170 - t110*t140) - (t110*t149 + t105*t179))) + t105*t182) + t102*t173;
    raw[43] = t153*t98 + (t165*t99 + t174*t101);
    raw[44] = t154*t98 + (t166*t99 + t175*t101);
    raw[45] = t155*t98 + (t167*t99 + t176*t101);
    raw[46] = t102*t98 + (t105*t99 + t108*t101);
}

void factor_cost_0(const T in[12], const T dat[18],
                   T half[1]) {
#pragma HLS INLINE off
#pragma HLS ALLOCATION operation instances=fadd limit=3
#pragma HLS ALLOCATION operation instances=fmul limit=3
#pragma HLS ALLOCATION operation instances=fdiv limit=1
#pragma HLS ALLOCATION operation instances=fsqrt limit=1
    const T t0 = dat[6]*in[6] + (dat[0]*in[0] + dat[3]*in[3]);
    const T t1 = t0;
    const T t2 = dat[6]*in[7] + (dat[0]*in[1] + dat[3]*in[4]);
    const T t3 = t2;
    const T t4 = dat[6]*in[8] + (dat[0]*in[2] + dat[3]*in[5]);
    const T t5 = t4;
    const T t6 = dat[7]*in[6] + (dat[1]*in[0] + dat[4]*in[3]);
    const T t7 = t6;
    const T t8 = dat[7]*in[7] + (dat[1]*in[1] + dat[4]*in[4]);
    const T t9 = t8;
    const T t10 = dat[7]*in[8] + (dat[1]*in[2] + dat[4]*in[5]);
    const T t11 = t10;
    const T t12 = dat[8]*in[6] + (dat[2]*in[0] + dat[5]*in[3]);
    const T t13 = t12;
    const T t14 = dat[8]*in[7] + (dat[2]*in[1] + dat[5]*in[4]);
    const T t15 = t14;
    const T t16 = dat[8]*in[8] + (dat[2]*in[2] + dat[5]*in[5]);
    const T t17 = t16;
    T tlog0[3]; so3_log(t1, t3, t5, t7, t9, t11, t13, t15, t17, tlog0);
    const T t18 = tlog0[0];
    const T t19 = (t18*t18);
    const T t20 = tlog0[1];
    const T t21 = (t20*t20);
    const T t22 = tlog0[2];
    const T t23 = (t22*t22);
    const T t24 = t21;
    const T t25 = t24;
    const T t26 = t23;
    const T t27 = t26;
    const T t28 = t25 + t27;
    const T t29 = t19;
    const T t30 = t29;
    const T t31 = t30 + t28;
    const T t32 = lie_D(t31);
    const T t33 = T(1) - t28*t32;
    const T t34 = (T(0.5))*t22;
    const T t35 = t34;
    const T t36 = t18*t32;
    const T t37 = t20*t36;
    const T t38 = t35 + t37;
    const T t39 = (T(0.5))*t20;
    const T t40 = t39;
    const T t41 = t22*t36;
    const T t42 = t41 - t40;
    const T t43 = (dat[6]*in[11] - dat[6]*dat[11]) + ((dat[0]*in[9] - dat[0]*dat[9]) + (dat[3]*in[10] - dat[3]*dat[10]));
    const T t44 = (dat[7]*in[11] - dat[7]*dat[11]) + ((dat[1]*in[9] - dat[1]*dat[9]) + (dat[4]*in[10] - dat[4]*dat[10]));
    const T t45 = (dat[8]*in[11] - dat[8]*dat[11]) + ((dat[2]*in[9] - dat[2]*dat[9]) + (dat[5]*in[10] - dat[5]*dat[10]));
    const T t46 = t45*t42 + (t43*t33 + t44*t38);
    const T t47 = t37 - t35;
    const T t48 = -(t27 + t30);
    const T t49 = T(1) + t48*t32;
    const T t50 = (T(0.5))*t18;
    const T t51 = t50;
    const T t52 = t20*t22;
    const T t53 = t52*t32;
    const T t54 = t51 + t53;
    const T t55 = t43*t47 + (t44*t49 + t45*t54);
    const T t56 = t40 + t41;
    const T t57 = t53 - t51;
    const T t58 = -(t25 + t30);
    const T t59 = T(1) + t58*t32;
    const T t60 = t43*t56 + (t44*t57 + t45*t59);
    const T t61 = ((((T(0.5))*(dat[14]*dat[14]))*t23 + (((T(0.5))*(dat[12]*dat[12]))*t19 + ((T(0.5))*(dat[13]*dat[13]))*t21)) + ((T(0.5))*(dat[16]*dat[16]))*(t55*t55)) + (((T(0.5))*(dat[17]*dat[17]))*(t60*t60) + ((T(0.5))*(dat[15]*dat[15]))*(t46*t46));
    half[0] = t61;
}

// block 1: PriorFactorVector3 (3 rows, 3 columns, 1 instances)
void factor_1(const T in[3], const T dat[4],
              T raw[12]) {
#pragma HLS INLINE
    raw[0] = T(1);
    raw[3] = in[0] - dat[0];
    raw[5] = T(1);
    raw[7] = in[1] - dat[1];
    raw[10] = T(1);
    raw[11] = in[2] - dat[2];
}

void factor_cost_1(const T in[3], const T dat[4],
                   T half[1]) {
#pragma HLS INLINE
    const T t0 = in[0] - dat[0];
    const T t1 = in[1] - dat[1];
    const T t2 = in[2] - dat[2];
    const T t3 = (T(0.5))*(dat[3]*dat[3]);
    const T t4 = t3*(t2*t2) + (t3*(t0*t0) + t3*(t1*t1));
    half[0] = t4;
}

// block 2: PriorFactorImuBias (6 rows, 6 columns, 1 instances)
void factor_2(const T in[6], const T dat[7],
              T raw[48]) {
#pragma HLS INLINE
    raw[0] = T(1);
    raw[6] = in[0] - dat[0];
    raw[9] = T(1);
    raw[14] = in[1] - dat[1];
    raw[18] = T(1);
    raw[22] = in[2] - dat[2];
    raw[27] = T(1);
    raw[30] = in[3] - dat[3];
    raw[36] = T(1);
    raw[38] = in[4] - dat[4];
    raw[45] = T(1);
    raw[46] = in[5] - dat[5];
}

void factor_cost_2(const T in[6], const T dat[7],
                   T half[1]) {
#pragma HLS INLINE
    const T t0 = in[0] - dat[0];
    const T t1 = in[1] - dat[1];
    const T t2 = in[2] - dat[2];
    const T t3 = in[3] - dat[3];
    const T t4 = in[4] - dat[4];
    const T t5 = in[5] - dat[5];
    const T t6 = (T(0.5))*(dat[6]*dat[6]);
    const T t7 = (t6*(t4*t4) + t6*(t5*t5)) + ((t6*(t0*t0) + t6*(t1*t1)) + (t6*(t2*t2) + t6*(t3*t3)));
    half[0] = t7;
}

// block 3: CombinedImuFactor+LidarOdometryFactor (21 rows, 30 columns, 7 instances)
void factor_3(const T in[42], const T dat[211],
              T raw[672]) {
#pragma HLS INLINE off
#pragma HLS ALLOCATION operation instances=fadd limit=8
#pragma HLS ALLOCATION operation instances=fmul limit=11
#pragma HLS ALLOCATION operation instances=fdiv limit=1
#pragma HLS ALLOCATION operation instances=fsqrt limit=1
    const T t0 = in[30] - dat[63];
    const T t1 = in[31] - dat[64];
    const T t2 = in[32] - dat[65];
    const T t3 = in[33] - dat[66];
    const T t4 = in[34] - dat[67];
    const T t5 = in[35] - dat[68];
    const T t6 = (dat[38]*t5 + (dat[0] + dat[9]*t0)) + ((dat[10]*t1 + dat[11]*t2) + (dat[36]*t3 + dat[37]*t4));
    const T t7 = T(2)*t6;
    const T t8 = (dat[41]*t5 + (dat[1] + dat[12]*t0)) + ((dat[13]*t1 + dat[14]*t2) + (dat[39]*t3 + dat[40]*t4));
    const T t9 = T(2)*t8;
    const T t10 = (dat[44]*t5 + (dat[2] + dat[15]*t0)) + ((dat[16]*t1 + dat[17]*t2) + (dat[42]*t3 + dat[43]*t4));
    const T t11 = T(2)*t10;
    const T t12 = (t10*t10) + ((t6*t6) + (t8*t8));
    const T t13 = lie_B1(t12);
    const T t14 = -t8;
    const T t15 = t8*t14;
    const T t16 = -t10;
    const T t17 = t16*t10;
    const T t18 = t17 + t15;
    const T t19 = -dat[15];
    const T t20 = dat[15]*t16 + t19*t10;
    const T t21 = lie_B(t12);
    const T t22 = t20*t21;
    const T t23 = -dat[12];
    const T t24 = t23*t8 + dat[12]*t14;
    const T t25 = t24*t21;
    const T t26 = -dat[16];
    const T t27 = dat[16]*t16 + t26*t10;
    const T t28 = t27*t21;
    const T t29 = -dat[13];
    const T t30 = t29*t8 + dat[13]*t14;
    const T t31 = t30*t21;
    const T t32 = -dat[17];
    const T t33 = dat[17]*t16 + t32*t10;
    const T t34 = t33*t21;
    const T t35 = -dat[14];
    const T t36 = t35*t8 + dat[14]*t14;
    const T t37 = t36*t21;
    const T t38 = -dat[42];
    const T t39 = dat[42]*t16 + t38*t10;
    const T t40 = t39*t21;
    const T t41 = -dat[39];
    const T t42 = t41*t8 + dat[39]*t14;
    const T t43 = t42*t21;
    const T t44 = -dat[40];
    const T t45 = t44*t8 + dat[40]*t14;
    const T t46 = t45*t21;
    const T t47 = -dat[43];
    const T t48 = dat[43]*t16 + t47*t10;
    const T t49 = t48*t21;
    const T t50 = -dat[41];
    const T t51 = t50*t8 + dat[41]*t14;
    const T t52 = t51*t21;
    const T t53 = -dat[44];
    const T t54 = dat[44]*t16 + t53*t10;
    const T t55 = t54*t21;
    const T t56 = in[6]*in[21] + (in[0]*in[15] + in[3]*in[18]);
    const T t57 = in[8]*in[21] + (in[2]*in[15] + in[5]*in[18]);
    const T t58 = -t57;
    const T t59 = in[7]*in[21] + (in[1]*in[15] + in[4]*in[18]);
    const T t60 = in[6]*in[23] + (in[0]*in[17] + in[3]*in[20]);
    const T t61 = -t60;
    const T t62 = in[6]*in[22] + (in[0]*in[16] + in[3]*in[19]);
    const T t63 = lie_A1(t12);
    const T t64 = -t56;
    const T t65 = in[7]*in[23] + (in[1]*in[17] + in[4]*in[20]);
    const T t66 = -t65;
    const T t67 = in[7]*in[22] + (in[1]*in[16] + in[4]*in[19]);
    const T t68 = -t59;
    const T t69 = in[8]*in[23] + (in[2]*in[17] + in[5]*in[20]);
    const T t70 = -t69;
    const T t71 = in[8]*in[22] + (in[2]*in[16] + in[5]*in[19]);
    const T t72 = -t6;
    const T t73 = t6*t72;
    const T t74 = t17 + t73;
    const T t75 = -dat[9];
    const T t76 = t75*t6 + dat[9]*t72;
    const T t77 = t76*t21;
    const T t78 = -dat[10];
    const T t79 = t78*t6 + dat[10]*t72;
    const T t80 = t79*t21;
    const T t81 = -dat[11];
    const T t82 = t81*t6 + dat[11]*t72;
    const T t83 = t82*t21;
    const T t84 = -dat[36];
    const T t85 = t84*t6 + dat[36]*t72;
    const T t86 = t85*t21;
    const T t87 = -dat[37];
    const T t88 = t87*t6 + dat[37]*t72;
    const T t89 = t88*t21;
    const T t90 = -dat[38];
    const T t91 = t90*t6 + dat[38]*t72;
    const T t92 = t91*t21;
    const T t93 = t73 + t15;
    const T t94 = t16*t21;
    const T t95 = t16*t72;
    const T t96 = t72*t21;
    const T t97 = t8*t21;
    const T t98 = t10*t21;
    const T t99 = t8*t10;
    const T t100 = -t71;
    const T t101 = -t62;
    const T t102 = -t67;
    const T t103 = T(1) + t18*t21;
    const T t104 = t56;
    const T t105 = lie_A(t12);
    const T t106 = t14*t21;
    const T t107 = t10*t105 + t72*t106;
    const T t108 = t59;
    const T t109 = t6*t21;
    const T t110 = t14*t105 + t10*t109;
    const T t111 = t57;
    const T t112 = t111*t110 + (t104*t103 + t108*t107);
    const T t113 = T(1) + t74*t21;
    const T t114 = t6*t105 + t16*t106;
    const T t115 = t16*t105 + t8*t109;
    const T t116 = t111*t114 + (t108*t113 + t104*t115);
    const T t117 = T(1) + t93*t21;
    const T t118 = t8*t105 + t72*t94;
    const T t119 = t72*t105 + t10*t97;
    const T t120 = t108*t119 + (t111*t117 + t104*t118);
    const T t121 = t62;
    const T t122 = t67;
    const T t123 = t71;
    const T t124 = t123*t110 + (t121*t103 + t122*t107);
    const T t125 = t121*t115 + (t122*t113 + t123*t114);
    const T t126 = t122*t119 + (t123*t117 + t121*t118);
    const T t127 = t60;
    const T t128 = t65;
    const T t129 = t69;
    const T t130 = t129*t110 + (t127*t103 + t128*t107);
    const T t131 = t127*t115 + (t128*t113 + t129*t114);
    const T t132 = t128*t119 + (t129*t117 + t127*t118);
    T tlog0[3]; so3_log(t112, t116, t120, t124, t125, t126, t130, t131, t132, tlog0);
    const T t133 = tlog0[1];
    const T t134 = (T(0.5))*t133;
    const T t135 = tlog0[0];
    const T t136 = (t135*t135);
    const T t137 = (t133*t133);
    const T t138 = tlog0[2];
    const T t139 = (t138*t138);
    const T t140 = t137 + t139;
    const T t141 = lie_D(t136 + t140);
    const T t142 = t135*t141;
    const T t143 = t138*t142;
    const T t144 = t134 + t143;
    const T t145 = (T(0.5))*t112;
    const T t146 = T(1) - t140*t141;
    const T t147 = ((T(0.5))*t120)*t146 - t145*t144;
    const T t148 = (T(0.5))*t138;
    const T t149 = t133*t142;
    const T t150 = t149 - t148;
    const T t151 = (T(0.5))*t146;
    const T t152 = t145*t150 - t116*t151;
    const T t153 = (T(0.5))*t144;
    const T t154 = (T(0.5))*t150;
    const T t155 = t125*t153 - t126*t154;
    const T t156 = ((T(0.5))*t126)*t146 - t124*t153;
    const T t157 = t124*t154 - t125*t151;
    const T t158 = t131*t153 - t132*t154;
    const T t159 = ((T(0.5))*t132)*t146 - t130*t153;
    const T t160 = t130*t154 - t131*t151;
    const T t161 = t116*t153 - t120*t154;
    const T t162 = (T(0.5))*t135;
    const T t163 = (t133*t138)*t141 - t162;
    const T t164 = t148 + t149;
    const T t165 = ((T(0.5))*t120)*t164 - t145*t163;
    const T t166 = T(1) + (-(t136 + t139))*t141;
    const T t167 = (T(0.5))*t164;
    const T t168 = t145*t166 - t116*t167;
    const T t169 = (T(0.5))*t163;
    const T t170 = (T(0.5))*t166;
    const T t171 = t125*t169 - t126*t170;
    const T t172 = ((T(0.5))*t126)*t164 - t124*t169;
    const T t173 = t124*t170 - t125*t167;
    const T t174 = t131*t169 - t132*t170;
    const T t175 = ((T(0.5))*t132)*t164 - t130*t169;
    const T t176 = t130*t170 - t131*t167;
    const T t177 = t116*t169 - t120*t170;
    const T t178 = T(1) + (-(t136 + t137))*t141;
    const T t179 = t143 - t134;
    const T t180 = ((T(0.5))*t120)*t179 - t145*t178;
    const T t181 = t133*t138;
    const T t182 = t162 + t181*t141;
    const T t183 = (T(0.5))*t179;
    const T t184 = t145*t182 - t116*t183;
    const T t185 = (T(0.5))*t178;
    const T t186 = (T(0.5))*t182;
    const T t187 = t125*t185 - t126*t186;
    const T t188 = ((T(0.5))*t126)*t179 - t124*t185;
    const T t189 = t124*t186 - t125*t183;
    const T t190 = t131*t185 - t132*t186;
    const T t191 = ((T(0.5))*t132)*t179 - t130*t185;
    const T t192 = t130*t186 - t131*t183;
    const T t193 = t116*t185 - t120*t186;
    const T t194 = T(2)*t133;
    const T t195 = T(2)*t138;
    const T t196 = T(2)*t135;
    const T t197 = t137;
    const T t198 = t139;
    const T t199 = t197 + t198;
    const T t200 = t136;
    const T t201 = t200 + t199;
    const T t202 = lie_D1(t201);
    const T t203 = in[9] - in[24];
    const T t204 = -in[15];
    const T t205 = -in[16];
    const T t206 = -in[17];
    const T t207 = in[10] - in[25];
    const T t208 = -in[18];
    const T t209 = -in[19];
    const T t210 = -in[20];
    const T t211 = in[11] - in[26];
    const T t212 = -in[21];
    const T t213 = -in[22];
    const T t214 = -in[23];
    const T t215 = (dat[47]*t5 + (dat[3] + dat[18]*t0)) + ((dat[19]*t1 + dat[20]*t2) + (dat[45]*t3 + dat[46]*t4));
    const T t216 = (dat[50]*t5 + (dat[4] + dat[21]*t0)) + ((dat[22]*t1 + dat[23]*t2) + (dat[48]*t3 + dat[49]*t4));
    const T t217 = (dat[53]*t5 + (dat[5] + dat[24]*t0)) + ((dat[25]*t1 + dat[26]*t2) + (dat[51]*t3 + dat[52]*t4));
    const T t218 = (T(0.5))*(dat[69]*dat[69]);
    const T t219 = (((dat[69]*in[12] + t203) + dat[70]*t218) + in[0]*t215) + (in[1]*t216 + in[2]*t217);
    const T t220 = (((dat[69]*in[13] + t207) + dat[71]*t218) + in[3]*t215) + (in[4]*t216 + in[5]*t217);
    const T t221 = (((dat[69]*in[14] + t211) + dat[72]*t218) + in[6]*t215) + (in[7]*t216 + in[8]*t217);
    const T t222 = in[21]*t221 + (in[15]*t219 + in[18]*t220);
    const T t223 = in[23]*t221 + (in[17]*t219 + in[20]*t220);
    const T t224 = in[22]*t221 + (in[16]*t219 + in[19]*t220);
    const T t225 = -(t198 + t200);
    const T t226 = t57;
    const T t227 = t68;
    const T t228 = t226*t107 + t227*t110;
    const T t229 = t226*t113 + t227*t114;
    const T t230 = t227*t117 + t226*t119;
    const T t231 = t71;
    const T t232 = t102;
    const T t233 = t231*t107 + t232*t110;
    const T t234 = t231*t113 + t232*t114;
    const T t235 = t232*t117 + t231*t119;
    const T t236 = t69;
    const T t237 = t66;
    const T t238 = t236*t107 + t237*t110;
    const T t239 = t236*t113 + t237*t114;
    const T t240 = t237*t117 + t236*t119;
    const T t241 = ((t233*t155 + t234*t156) + (t235*t157 + t238*t158)) + ((t239*t159 + t240*t160) + (t228*t161 + (t229*t147 + t230*t152)));
    const T t242 = t196*t241;
    const T t243 = lie_D(t201);
    const T t244 = t243*t242;
    const T t245 = t58;
    const T t246 = t56;
    const T t247 = t245*t103 + t246*t110;
    const T t248 = t246*t114 + t245*t115;
    const T t249 = t246*t117 + t245*t118;
    const T t250 = t100;
    const T t251 = t62;
    const T t252 = t250*t103 + t251*t110;
    const T t253 = t251*t114 + t250*t115;
    const T t254 = t251*t117 + t250*t118;
    const T t255 = t70;
    const T t256 = t60;
    const T t257 = t255*t103 + t256*t110;
    const T t258 = t256*t114 + t255*t115;
    const T t259 = t256*t117 + t255*t118;
    const T t260 = ((t252*t155 + t253*t156) + (t254*t157 + t257*t158)) + ((t258*t159 + t259*t160) + (t247*t161 + (t248*t147 + t249*t152)));
    const T t261 = t196*t260;
    const T t262 = t243*t261;
    const T t263 = t59;
    const T t264 = t64;
    const T t265 = t263*t103 + t264*t107;
    const T t266 = t264*t113 + t263*t115;
    const T t267 = t263*t118 + t264*t119;
    const T t268 = t67;
    const T t269 = t101;
    const T t270 = t268*t103 + t269*t107;
    const T t271 = t269*t113 + t268*t115;
    const T t272 = t268*t118 + t269*t119;
    const T t273 = t65;
    const T t274 = t61;
    const T t275 = t273*t103 + t274*t107;
    const T t276 = t274*t113 + t273*t115;
    const T t277 = t273*t118 + t274*t119;
    const T t278 = ((t270*t155 + t271*t156) + (t272*t157 + t275*t158)) + ((t276*t159 + t277*t160) + (t265*t161 + (t266*t147 + t267*t152)));
    const T t279 = t196*t278;
    const T t280 = t243*t279;
    const T t281 = t60;
    const T t282 = t65;
    const T t283 = t69;
    const T t284 = t283*t110 + (t281*t103 + t282*t107);
    const T t285 = t281*t115 + (t282*t113 + t283*t114);
    const T t286 = t282*t119 + (t283*t117 + t281*t118);
    const T t287 = t101;
    const T t288 = t102;
    const T t289 = t100;
    const T t290 = t289*t110 + (t287*t103 + t288*t107);
    const T t291 = t287*t115 + (t288*t113 + t289*t114);
    const T t292 = t288*t119 + (t289*t117 + t287*t118);
    const T t293 = (t291*t159 + t292*t160) + ((t284*t155 + t285*t156) + (t286*t157 + t290*t158));
    const T t294 = t196*t293;
    const T t295 = t243*t294;
    const T t296 = t61;
    const T t297 = t66;
    const T t298 = t70;
    const T t299 = t298*t110 + (t296*t103 + t297*t107);
    const T t300 = t296*t115 + (t297*t113 + t298*t114);
    const T t301 = t297*t119 + (t298*t117 + t296*t118);
    const T t302 = t56;
    const T t303 = t59;
    const T t304 = t57;
    const T t305 = t304*t110 + (t302*t103 + t303*t107);
    const T t306 = t302*t115 + (t303*t113 + t304*t114);
    const T t307 = t303*t119 + (t304*t117 + t302*t118);
    const T t308 = (t307*t160 + t299*t161) + ((t300*t147 + t301*t152) + (t305*t158 + t306*t159));
    const T t309 = t196*t308;
    const T t310 = t243*t309;
    const T t311 = t62;
    const T t312 = t67;
    const T t313 = t71;
    const T t314 = t313*t110 + (t311*t103 + t312*t107);
    const T t315 = t311*t115 + (t312*t113 + t313*t114);
    const T t316 = t312*t119 + (t313*t117 + t311*t118);
    const T t317 = t64;
    const T t318 = t68;
    const T t319 = t58;
    const T t320 = t319*t110 + (t317*t103 + t318*t107);
    const T t321 = t317*t115 + (t318*t113 + t319*t114);
    const T t322 = t318*t119 + (t319*t117 + t317*t118);
    const T t323 = (t322*t157 + t314*t161) + ((t315*t147 + t316*t152) + (t320*t155 + t321*t156));
    const T t324 = t196*t323;
    const T t325 = t243*t324;
    const T t326 = dat[15]*t11 + (dat[9]*t7 + dat[12]*t9);
    const T t327 = t326*t13;
    const T t328 = t18*t327 + (t22 + t25);
    const T t329 = t326*t63;
    const T t330 = t23*t21 + t14*t327;
    const T t331 = t72*t330 + (t10*t329 + (dat[15]*t105 + t75*t106));
    const T t332 = dat[9]*t21 + t6*t327;
    const T t333 = t10*t332 + (t14*t329 + (t23*t105 + dat[15]*t109));
    const T t334 = t111*t333 + (t104*t328 + t108*t331);
    const T t335 = t74*t327 + (t77 + t22);
    const T t336 = t16*t330 + (t19*t106 + (dat[9]*t105 + t6*t329));
    const T t337 = t8*t332 + (dat[12]*t109 + (t19*t105 + t16*t329));
    const T t338 = t111*t336 + (t108*t335 + t104*t337);
    const T t339 = t93*t327 + (t77 + t25);
    const T t340 = (t95*t327 + t19*t96) + (t8*t329 + (dat[12]*t105 + t75*t94));
    const T t341 = (dat[12]*t98 + t99*t327) + (t72*t329 + (t75*t105 + dat[15]*t97));
    const T t342 = t108*t341 + (t111*t339 + t104*t340);
    const T t343 = t123*t333 + (t121*t328 + t122*t331);
    const T t344 = t123*t336 + (t122*t335 + t121*t337);
    const T t345 = t122*t341 + (t123*t339 + t121*t340);
    const T t346 = t129*t333 + (t127*t328 + t128*t331);
    const T t347 = t129*t336 + (t128*t335 + t127*t337);
    const T t348 = t128*t341 + (t129*t339 + t127*t340);
    const T t349 = ((t343*t155 + t344*t156) + (t345*t157 + t346*t158)) + ((t347*t159 + t348*t160) + (t334*t161 + (t338*t147 + t342*t152)));
    const T t350 = t196*t349;
    const T t351 = t243*t350;
    const T t352 = dat[16]*t11 + (dat[10]*t7 + dat[13]*t9);
    const T t353 = t352*t13;
    const T t354 = t18*t353 + (t28 + t31);
    const T t355 = t352*t63;
    const T t356 = t29*t21 + t14*t353;
    const T t357 = t72*t356 + (t10*t355 + (dat[16]*t105 + t78*t106));
    const T t358 = dat[10]*t21 + t6*t353;
    const T t359 = t10*t358 + (t14*t355 + (t29*t105 + dat[16]*t109));
    const T t360 = t111*t359 + (t104*t354 + t108*t357);
    const T t361 = t74*t353 + (t80 + t28);
    const T t362 = t16*t356 + (t26*t106 + (dat[10]*t105 + t6*t355));
    const T t363 = t8*t358 + (dat[13]*t109 + (t26*t105 + t16*t355));
    const T t364 = t111*t362 + (t108*t361 + t104*t363);
    const T t365 = t93*t353 + (t80 + t31);
    const T t366 = (t95*t353 + t26*t96) + (t8*t355 + (dat[13]*t105 + t78*t94));
    const T t367 = (dat[13]*t98 + t99*t353) + (t72*t355 + (t78*t105 + dat[16]*t97));
    const T t368 = t108*t367 + (t111*t365 + t104*t366);
    const T t369 = t123*t359 + (t121*t354 + t122*t357);
    const T t370 = t123*t362 + (t122*t361 + t121*t363);
    const T t371 = t122*t367 + (t123*t365 + t121*t366);
    const T t372 = t129*t359 + (t127*t354 + t128*t357);
    const T t373 = t129*t362 + (t128*t361 + t127*t363);
    const T t374 = t128*t367 + (t129*t365 + t127*t366);
    const T t375 = ((t369*t155 + t370*t156) + (t371*t157 + t372*t158)) + ((t373*t159 + t374*t160) + (t360*t161 + (t364*t147 + t368*t152)));
    const T t376 = t196*t375;
    const T t377 = t243*t376;
    const T t378 = dat[17]*t11 + (dat[11]*t7 + dat[14]*t9);
    const T t379 = t378*t13;
    const T t380 = t18*t379 + (t37 + t34);
    const T t381 = t378*t63;
    const T t382 = t35*t21 + t14*t379;
    const T t383 = t72*t382 + (t10*t381 + (dat[17]*t105 + t81*t106));
    const T t384 = dat[11]*t21 + t6*t379;
    const T t385 = t10*t384 + (t14*t381 + (t35*t105 + dat[17]*t109));
    const T t386 = t111*t385 + (t104*t380 + t108*t383);
    const T t387 = t74*t379 + (t83 + t34);
    const T t388 = t16*t382 + (t32*t106 + (dat[11]*t105 + t6*t381));
    const T t389 = t8*t384 + (dat[14]*t109 + (t32*t105 + t16*t381));
    const T t390 = t111*t388 + (t108*t387 + t104*t389);
    const T t391 = t93*t379 + (t37 + t83);
    const T t392 = (t95*t379 + t32*t96) + (t8*t381 + (dat[14]*t105 + t81*t94));
    const T t393 = (dat[14]*t98 + t99*t379) + (t72*t381 + (t81*t105 + dat[17]*t97));
    const T t394 = t108*t393 + (t111*t391 + t104*t392);
    const T t395 = t123*t385 + (t121*t380 + t122*t383);
    const T t396 = t123*t388 + (t122*t387 + t121*t389);
    const T t397 = t122*t393 + (t123*t391 + t121*t392);
    const T t398 = t129*t385 + (t127*t380 + t128*t383);
    const T t399 = t129*t388 + (t128*t387 + t127*t389);
    const T t400 = t128*t393 + (t129*t391 + t127*t392);
    const T t401 = ((t395*t155 + t396*t156) + (t397*t157 + t398*t158)) + ((t399*t159 + t400*t160) + (t386*t161 + (t390*t147 + t394*t152)));
    const T t402 = t196*t401;
    const T t403 = t243*t402;
    const T t404 = dat[42]*t11 + (dat[36]*t7 + dat[39]*t9);
    const T t405 = t404*t13;
    const T t406 = t18*t405 + (t40 + t43);
    const T t407 = t404*t63;
    const T t408 = t41*t21 + t14*t405;
    const T t409 = t72*t408 + (t10*t407 + (dat[42]*t105 + t84*t106));
    const T t410 = dat[36]*t21 + t6*t405;
    const T t411 = t10*t410 + (t14*t407 + (t41*t105 + dat[42]*t109));
    const T t412 = t111*t411 + (t104*t406 + t108*t409);
    const T t413 = t74*t405 + (t40 + t86);
    const T t414 = t16*t408 + (t38*t106 + (dat[36]*t105 + t6*t407));
    const T t415 = t8*t410 + (dat[39]*t109 + (t38*t105 + t16*t407));
    const T t416 = t111*t414 + (t108*t413 + t104*t415);
    const T t417 = t93*t405 + (t43 + t86);
    const T t418 = (t95*t405 + t38*t96) + (t8*t407 + (dat[39]*t105 + t84*t94));
    const T t419 = (dat[39]*t98 + t99*t405) + (t72*t407 + (t84*t105 + dat[42]*t97));
    const T t420 = t108*t419 + (t111*t417 + t104*t418);
    const T t421 = t123*t411 + (t121*t406 + t122*t409);
    const T t422 = t123*t414 + (t122*t413 + t121*t415);
    const T t423 = t122*t419 + (t123*t417 + t121*t418);
    const T t424 = t129*t411 + (t127*t406 + t128*t409);
    const T t425 = t129*t414 + (t128*t413 + t127*t415);
    const T t426 = t128*t419 + (t129*t417 + t127*t418);
    const T t427 = ((t421*t155 + t422*t156) + (t423*t157 + t424*t158)) + ((t425*t159 + t426*t160) + (t412*t161 + (t416*t147 + t420*t152)));
    const T t428 = t196*t427;
    const T t429 = t243*t428;
    const T t430 = dat[43]*t11 + (dat[37]*t7 + dat[40]*t9);
    const T t431 = t430*t13;
    const T t432 = t18*t431 + (t46 + t49);
    const T t433 = t430*t63;
    const T t434 = t44*t21 + t14*t431;
    const T t435 = t72*t434 + (t10*t433 + (dat[43]*t105 + t87*t106));
    const T t436 = dat[37]*t21 + t6*t431;
    const T t437 = t10*t436 + (t14*t433 + (t44*t105 + dat[43]*t109));
    const T t438 = t111*t437 + (t104*t432 + t108*t435);
    const T t439 = t74*t431 + (t49 + t89);
    const T t440 = t16*t434 + (t47*t106 + (dat[37]*t105 + t6*t433));
    const T t441 = t8*t436 + (dat[40]*t109 + (t47*t105 + t16*t433));
    const T t442 = t111*t440 + (t108*t439 + t104*t441);
    const T t443 = t93*t431 + (t46 + t89);
    const T t444 = (t95*t431 + t47*t96) + (t8*t433 + (dat[40]*t105 + t87*t94));
    const T t445 = (dat[40]*t98 + t99*t431) + (t72*t433 + (t87*t105 + dat[43]*t97));
    const T t446 = t108*t445 + (t111*t443 + t104*t444);
    const T t447 = t123*t437 + (t121*t432 + t122*t435);
    const T t448 = t123*t440 + (t122*t439 + t121*t441);
    const T t449 = t122*t445 + (t123*t443 + t121*t444);
    const T t450 = t129*t437 + (t127*t432 + t128*t435);
    const T t451 = t129*t440 + (t128*t439 + t127*t441);
    const T t452 = t128*t445 + (t129*t443 + t127*t444);
    const T t453 = ((t447*t155 + t448*t156) + (t449*t157 + t450*t158)) + ((t451*t159 + t452*t160) + (t438*t161 + (t442*t147 + t446*t152)));
    const T t454 = t196*t453;
    const T t455 = t243*t454;
    const T t456 = dat[44]*t11 + (dat[38]*t7 + dat[41]*t9);
    const T t457 = t456*t13;
    const T t458 = t18*t457 + (t52 + t55);
    const T t459 = t456*t63;
    const T t460 = t50*t21 + t14*t457;
    const T t461 = t72*t460 + (t10*t459 + (dat[44]*t105 + t90*t106));
    const T t462 = dat[38]*t21 + t6*t457;
    const T t463 = t10*t462 + (t14*t459 + (t50*t105 + dat[44]*t109));
    const T t464 = t111*t463 + (t104*t458 + t108*t461);
    const T t465 = t74*t457 + (t55 + t92);
    const T t466 = t16*t460 + (t53*t106 + (dat[38]*t105 + t6*t459));
    const T t467 = t8*t462 + (dat[41]*t109 + (t53*t105 + t16*t459));
    const T t468 = t111*t466 + (t108*t465 + t104*t467);
    const T t469 = t93*t457 + (t52 + t92);
    const T t470 = (t95*t457 + t53*t96) + (t8*t459 + (dat[41]*t105 + t90*t94));
    const T t471 = (dat[41]*t98 + t99*t457) + (t72*t459 + (t90*t105 + dat[44]*t97));
    const T t472 = t108*t471 + (t111*t469 + t104*t470);
    const T t473 = t123*t463 + (t121*t458 + t122*t461);
    const T t474 = t123*t466 + (t122*t465 + t121*t467);
    const T t475 = t122*t471 + (t123*t469 + t121*t470);
    const T t476 = t129*t463 + (t127*t458 + t128*t461);
    const T t477 = t129*t466 + (t128*t465 + t127*t467);
    const T t478 = t128*t471 + (t129*t469 + t127*t470);
    const T t479 = ((t473*t155 + t474*t156) + (t475*t157 + t476*t158)) + ((t477*t159 + t478*t160) + (t464*t161 + (t468*t147 + t472*t152)));
    const T t480 = t196*t479;
    const T t481 = t243*t480;
    const T t482 = t133*t243;
    const T t483 = t138*t243;
    const T t484 = -(t197 + t200);
    const T t485 = (dat[56]*t5 + (dat[6] + dat[27]*t0)) + ((dat[28]*t1 + dat[29]*t2) + (dat[54]*t3 + dat[55]*t4));
    const T t486 = (dat[59]*t5 + (dat[7] + dat[30]*t0)) + ((dat[31]*t1 + dat[32]*t2) + (dat[57]*t3 + dat[58]*t4));
    const T t487 = (dat[62]*t5 + (dat[8] + dat[33]*t0)) + ((dat[34]*t1 + dat[35]*t2) + (dat[60]*t3 + dat[61]*t4));
    const T t488 = ((dat[69]*dat[70] + (in[12] - in[27])) + in[0]*t485) + (in[1]*t486 + in[2]*t487);
    const T t489 = ((dat[69]*dat[71] + (in[13] - in[28])) + in[3]*t485) + (in[4]*t486 + in[5]*t487);
    const T t490 = ((dat[69]*dat[72] + (in[14] - in[29])) + in[6]*t485) + (in[7]*t486 + in[8]*t487);
    const T t491 = in[21]*t490 + (in[15]*t488 + in[18]*t489);
    const T t492 = in[23]*t490 + (in[17]*t488 + in[20]*t489);
    const T t493 = in[22]*t490 + (in[16]*t488 + in[19]*t489);
    const T t494 = dat[79]*t111 + (dat[73]*t104 + dat[76]*t108);
    const T t495 = dat[79]*t123 + (dat[73]*t121 + dat[76]*t122);
    const T t496 = dat[79]*t129 + (dat[73]*t127 + dat[76]*t128);
    const T t497 = dat[80]*t111 + (dat[74]*t104 + dat[77]*t108);
    const T t498 = dat[80]*t123 + (dat[74]*t121 + dat[77]*t122);
    const T t499 = dat[80]*t129 + (dat[74]*t127 + dat[77]*t128);
    const T t500 = dat[81]*t111 + (dat[75]*t104 + dat[78]*t108);
    const T t501 = dat[81]*t123 + (dat[75]*t121 + dat[78]*t122);
    const T t502 = dat[81]*t129 + (dat[75]*t127 + dat[78]*t128);
    T tlog1[3]; so3_log(t494, t495, t496, t497, t498, t499, t500, t501, t502, tlog1);
    const T t503 = tlog1[1];
    const T t504 = (T(0.5))*t503;
    const T t505 = tlog1[0];
    const T t506 = (t505*t505);
    const T t507 = (t503*t503);
    const T t508 = tlog1[2];
    const T t509 = (t508*t508);
    const T t510 = t507 + t509;
    const T t511 = lie_D(t506 + t510);
    const T t512 = t505*t511;
    const T t513 = (T(0.5))*t504 + ((T(0.5))*t508)*t512;
    const T t514 = (T(0.5))*t508;
    const T t515 = t503*t512;
    const T t516 = t515 - t514;
    const T t517 = (T(0.5))*t496;
    const T t518 = t495*t513 - t517*t516;
    const T t519 = T(1) - t510*t511;
    const T t520 = ((T(0.5))*t496)*t519 - t494*t513;
    const T t521 = (T(0.5))*t516;
    const T t522 = (T(0.5))*t519;
    const T t523 = t494*t521 - t495*t522;
    const T t524 = t498*t513 - t499*t521;
    const T t525 = ((T(0.5))*t499)*t519 - t497*t513;
    const T t526 = t497*t521 - t498*t522;
    const T t527 = t501*t513 - t502*t521;
    const T t528 = ((T(0.5))*t502)*t519 - t500*t513;
    const T t529 = t500*t521 - t501*t522;
    const T t530 = (T(0.5))*t505;
    const T t531 = t503*t508;
    const T t532 = t531*t511;
    const T t533 = (T(0.5))*t532 - T(0.5)*t530;
    const T t534 = T(1) + (-(t506 + t509))*t511;
    const T t535 = t495*t533 - t517*t534;
    const T t536 = t514 + t515;
    const T t537 = ((T(0.5))*t496)*t536 - t494*t533;
    const T t538 = (T(0.5))*t534;
    const T t539 = (T(0.5))*t536;
    const T t540 = t494*t538 - t495*t539;
    const T t541 = t498*t533 - t499*t538;
    const T t542 = ((T(0.5))*t499)*t536 - t497*t533;
    const T t543 = t497*t538 - t498*t539;
    const T t544 = t501*t533 - t502*t538;
    const T t545 = ((T(0.5))*t502)*t536 - t500*t533;
    const T t546 = t500*t538 - t501*t539;
    const T t547 = T(0.5) + ((T(0.5))*(-(t506 + t507)))*t511;
    const T t548 = t530 + t532;
    const T t549 = t495*t547 - t517*t548;
    const T t550 = (t508*t505)*t511 - t504;
    const T t551 = ((T(0.5))*t496)*t550 - t494*t547;
    const T t552 = (T(0.5))*t548;
    const T t553 = (T(0.5))*t550;
    const T t554 = t494*t552 - t495*t553;
    const T t555 = t498*t547 - t499*t552;
    const T t556 = ((T(0.5))*t499)*t550 - t497*t547;
    const T t557 = t497*t552 - t498*t553;
    const T t558 = t501*t547 - t502*t552;
    const T t559 = ((T(0.5))*t502)*t550 - t500*t547;
    const T t560 = t500*t552 - t501*t553;
    const T t561 = T(2)*t503;
    const T t562 = T(2)*t508;
    const T t563 = T(2)*t505;
    const T t564 = t507;
    const T t565 = t509;
    const T t566 = t564 + t565;
    const T t567 = t506;
    const T t568 = t567 + t566;
    const T t569 = lie_D1(t568);
    const T t570 = -t203;
    const T t571 = -t207;
    const T t572 = -t211;
    const T t573 = in[8]*t572 + (in[2]*t570 + in[5]*t571);
    const T t574 = in[7]*t572 + (in[1]*t570 + in[4]*t571);
    const T t575 = -(in[6]*in[7] + (in[0]*in[1] + in[3]*in[4]));
    const T t576 = -(in[6]*in[8] + (in[0]*in[2] + in[3]*in[5]));
    const T t577 = in[6]*t572 + (in[0]*t570 + in[3]*t571);
    const T t578 = -(in[7]*in[8] + (in[1]*in[2] + in[4]*in[5]));
    const T t579 = lie_D(t568);
    const T t580 = t503*t579;
    const T t581 = t508*t579;
    const T t582 = T(1) - t566*t579;
    const T t583 = t514;
    const T t584 = t505*t579;
    const T t585 = t503*t584;
    const T t586 = t583 + t585;
    const T t587 = t504;
    const T t588 = t508*t584;
    const T t589 = t588 - t587;
    const T t590 = t585 - t583;
    const T t591 = -(t565 + t567);
    const T t592 = T(1) + t591*t579;
    const T t593 = t530;
    const T t594 = t531*t579;
    const T t595 = t593 + t594;
    const T t596 = t587 + t588;
    const T t597 = t594 - t593;
    const T t598 = -(t564 + t567);
    const T t599 = T(1) + t598*t579;
    const T t600 = (in[6]*in[26] - in[6]*in[11]) + ((in[0]*in[24] - in[0]*in[9]) + (in[3]*in[25] - in[3]*in[10]));
    const T t601 = (in[7]*in[26] - in[7]*in[11]) + ((in[1]*in[24] - in[1]*in[9]) + (in[4]*in[25] - in[4]*in[10]));
    const T t602 = (in[8]*in[26] - in[8]*in[11]) + ((in[2]*in[24] - in[2]*in[9]) + (in[5]*in[25] - in[5]*in[10]));
    const T t603 = (dat[73]*t600 - (dat[79]*dat[84] + (dat[73]*dat[82] + dat[76]*dat[83]))) + (dat[76]*t601 + dat[79]*t602);
    const T t604 = t603*t566;
    const T t605 = t603*t579;
    const T t606 = (dat[74]*t600 - (dat[80]*dat[84] + (dat[74]*dat[82] + dat[77]*dat[83]))) + (dat[77]*t601 + dat[80]*t602);
    const T t607 = t606*t591;
    const T t608 = t606*t579;
    const T t609 = (dat[75]*t600 - (dat[81]*dat[84] + (dat[75]*dat[82] + dat[78]*dat[83]))) + (dat[78]*t601 + dat[81]*t602);
    const T t610 = t609*t598;
    const T t611 = t609*t579;
    const T t612 = ((t234*t172 + t238*t174) + (t239*t175 + t228*t177)) + ((t230*t168 + t235*t173) + (t240*t176 + (t229*t165 + t233*t171)));
    const T t613 = ((t253*t172 + t257*t174) + (t258*t175 + t247*t177)) + ((t249*t168 + t254*t173) + (t259*t176 + (t248*t165 + t252*t171)));
    const T t614 = ((t271*t172 + t275*t174) + (t276*t175 + t265*t177)) + ((t267*t168 + t272*t173) + (t277*t176 + (t266*t165 + t270*t171)));
    const T t615 = (t286*t173 + t292*t176) + ((t284*t171 + t285*t172) + (t290*t174 + t291*t175));
    const T t616 = (t301*t168 + t307*t176) + ((t300*t165 + t305*t174) + (t306*t175 + t299*t177));
    const T t617 = (t316*t168 + t322*t173) + ((t315*t165 + t320*t171) + (t321*t172 + t314*t177));
    const T t618 = ((t344*t172 + t346*t174) + (t347*t175 + t334*t177)) + ((t342*t168 + t345*t173) + (t348*t176 + (t338*t165 + t343*t171)));
    const T t619 = ((t370*t172 + t372*t174) + (t373*t175 + t360*t177)) + ((t368*t168 + t371*t173) + (t374*t176 + (t364*t165 + t369*t171)));
    const T t620 = ((t396*t172 + t398*t174) + (t399*t175 + t386*t177)) + ((t394*t168 + t397*t173) + (t400*t176 + (t390*t165 + t395*t171)));
    const T t621 = ((t422*t172 + t424*t174) + (t425*t175 + t412*t177)) + ((t420*t168 + t423*t173) + (t426*t176 + (t416*t165 + t421*t171)));
    const T t622 = ((t448*t172 + t450*t174) + (t451*t175 + t438*t177)) + ((t446*t168 + t449*t173) + (t452*t176 + (t442*t165 + t447*t171)));
    const T t623 = ((t474*t172 + t476*t174) + (t477*t175 + t464*t177)) + ((t472*t168 + t475*t173) + (t478*t176 + (t468*t165 + t473*t171)));
    const T t624 = ((t238*t190 + t239*t191) + (t228*t193 + t229*t180)) + ((t235*t189 + t240*t192) + (t230*t184 + (t233*t187 + t234*t188)));
    const T t625 = ((t257*t190 + t258*t191) + (t247*t193 + t248*t180)) + ((t254*t189 + t259*t192) + (t249*t184 + (t252*t187 + t253*t188)));
    const T t626 = ((t275*t190 + t276*t191) + (t265*t193 + t266*t180)) + ((t272*t189 + t277*t192) + (t267*t184 + (t270*t187 + t271*t188)));
    const T t627 = (t286*t189 + t292*t192) + ((t284*t187 + t285*t188) + (t290*t190 + t291*t191));
    const T t628 = (t307*t192 + t301*t184) + ((t305*t190 + t306*t191) + (t299*t193 + t300*t180));
    const T t629 = (t322*t189 + t316*t184) + ((t320*t187 + t321*t188) + (t314*t193 + t315*t180));
    const T t630 = ((t346*t190 + t347*t191) + (t334*t193 + t338*t180)) + ((t345*t189 + t348*t192) + (t342*t184 + (t343*t187 + t344*t188)));
    const T t631 = ((t372*t190 + t373*t191) + (t360*t193 + t364*t180)) + ((t371*t189 + t374*t192) + (t368*t184 + (t369*t187 + t370*t188)));
    const T t632 = ((t398*t190 + t399*t191) + (t386*t193 + t390*t180)) + ((t397*t189 + t400*t192) + (t394*t184 + (t395*t187 + t396*t188)));
    const T t633 = ((t424*t190 + t425*t191) + (t412*t193 + t416*t180)) + ((t423*t189 + t426*t192) + (t420*t184 + (t421*t187 + t422*t188)));
    const T t634 = ((t450*t190 + t451*t191) + (t438*t193 + t442*t180)) + ((t449*t189 + t452*t192) + (t446*t184 + (t447*t187 + t448*t188)));
    const T t635 = ((t476*t190 + t477*t191) + (t464*t193 + t468*t180)) + ((t475*t189 + t478*t192) + (t472*t184 + (t473*t187 + t474*t188)));
    const T t636 = t194*t612;
    const T t637 = t194*t613;
    const T t638 = t194*t614;
    const T t639 = t194*t615;
    const T t640 = t194*t616;
    const T t641 = t194*t617;
    const T t642 = t194*t618;
    const T t643 = t194*t619;
    const T t644 = t194*t620;
    const T t645 = t194*t621;
    const T t646 = t194*t622;
    const T t647 = t194*t623;
    const T t648 = t195*t624;
    const T t649 = t195*t625;
    const T t650 = t195*t626;
    const T t651 = t195*t627;
    const T t652 = t195*t628;
    const T t653 = t195*t629;
    const T t654 = t195*t630;
    const T t655 = t195*t631;
    const T t656 = t195*t632;
    const T t657 = t195*t633;
    const T t658 = t195*t634;
    const T t659 = t195*t635;
    const T t660 = t636 + t648;
    const T t661 = t637 + t649;
    const T t662 = t638 + t650;
    const T t663 = t639 + t651;
    const T t664 = t640 + t652;
    const T t665 = t641 + t653;
    const T t666 = t642 + t654;
    const T t667 = t643 + t655;
    const T t668 = t644 + t656;
    const T t669 = t645 + t657;
    const T t670 = t646 + t658;
    const T t671 = t647 + t659;
    const T t672 = t202*t242 + t202*t660;
    const T t673 = t202*t261 + t202*t661;
    const T t674 = t202*t279 + t202*t662;
    const T t675 = t202*t294 + t202*t663;
    const T t676 = t202*t309 + t202*t664;
    const T t677 = t202*t324 + t202*t665;
    const T t678 = t202*t350 + t202*t666;
    const T t679 = t202*t376 + t202*t667;
    const T t680 = t202*t402 + t202*t668;
    const T t681 = t202*t428 + t202*t669;
    const T t682 = t202*t454 + t202*t670;
    const T t683 = t202*t480 + t202*t671;
    const T t684 = T(1) - t199*t243;
    const T t685 = -(t243*t660 + t199*t672);
    const T t686 = -(t243*t661 + t199*t673);
    const T t687 = -(t243*t662 + t199*t674);
    const T t688 = -(t243*t663 + t199*t675);
    const T t689 = -(t243*t664 + t199*t676);
    const T t690 = -(t243*t665 + t199*t677);
    const T t691 = -(t243*t666 + t199*t678);
    const T t692 = -(t243*t667 + t199*t679);
    const T t693 = -(t243*t668 + t199*t680);
    const T t694 = -(t243*t669 + t199*t681);
    const T t695 = -(t243*t670 + t199*t682);
    const T t696 = -(t243*t671 + t199*t683);
    const T t697 = in[2]*t216 - in[1]*t217;
    const T t698 = in[0]*t217 - in[2]*t215;
    const T t699 = in[1]*t215 - in[0]*t216;
    const T t700 = t204;
    const T t701 = t205;
    const T t702 = t206;
    const T t703 = dat[24]*in[2] + (dat[18]*in[0] + dat[21]*in[1]);
    const T t704 = dat[25]*in[2] + (dat[19]*in[0] + dat[22]*in[1]);
    const T t705 = dat[26]*in[2] + (dat[20]*in[0] + dat[23]*in[1]);
    const T t706 = dat[51]*in[2] + (dat[45]*in[0] + dat[48]*in[1]);
    const T t707 = dat[52]*in[2] + (dat[46]*in[0] + dat[49]*in[1]);
    const T t708 = dat[53]*in[2] + (dat[47]*in[0] + dat[50]*in[1]);
    const T t709 = in[5]*t216 - in[4]*t217;
    const T t710 = in[3]*t217 - in[5]*t215;
    const T t711 = in[4]*t215 - in[3]*t216;
    const T t712 = t208;
    const T t713 = t209;
    const T t714 = t210;
    const T t715 = dat[24]*in[5] + (dat[18]*in[3] + dat[21]*in[4]);
    const T t716 = dat[25]*in[5] + (dat[19]*in[3] + dat[22]*in[4]);
    const T t717 = dat[26]*in[5] + (dat[20]*in[3] + dat[23]*in[4]);
    const T t718 = dat[51]*in[5] + (dat[45]*in[3] + dat[48]*in[4]);
    const T t719 = dat[52]*in[5] + (dat[46]*in[3] + dat[49]*in[4]);
    const T t720 = dat[53]*in[5] + (dat[47]*in[3] + dat[50]*in[4]);
    const T t721 = in[8]*t216 - in[7]*t217;
    const T t722 = in[6]*t217 - in[8]*t215;
    const T t723 = in[7]*t215 - in[6]*t216;
    const T t724 = t212;
    const T t725 = t213;
    const T t726 = t214;
    const T t727 = dat[24]*in[8] + (dat[18]*in[6] + dat[21]*in[7]);
    const T t728 = dat[25]*in[8] + (dat[19]*in[6] + dat[22]*in[7]);
    const T t729 = dat[26]*in[8] + (dat[20]*in[6] + dat[23]*in[7]);
    const T t730 = dat[51]*in[8] + (dat[45]*in[6] + dat[48]*in[7]);
    const T t731 = dat[52]*in[8] + (dat[46]*in[6] + dat[49]*in[7]);
    const T t732 = dat[53]*in[8] + (dat[47]*in[6] + dat[50]*in[7]);
    const T t733 = t222;
    const T t734 = in[21]*t721 + (in[15]*t697 + in[18]*t709);
    const T t735 = in[21]*t722 + (in[15]*t698 + in[18]*t710);
    const T t736 = in[21]*t723 + (in[15]*t699 + in[18]*t711);
    const T t737 = t56;
    const T t738 = t59;
    const T t739 = t57;
    const T t740 = dat[69]*in[15];
    const T t741 = dat[69]*in[18];
    const T t742 = dat[69]*in[21];
    const T t743 = -t223;
    const T t744 = t224;
    const T t745 = t724*in[21] + (t700*in[15] + t712*in[18]);
    const T t746 = t725*in[21] + (t701*in[15] + t713*in[18]);
    const T t747 = t726*in[21] + (t702*in[15] + t714*in[18]);
    const T t748 = in[21]*t727 + (in[15]*t703 + in[18]*t715);
    const T t749 = in[21]*t728 + (in[15]*t704 + in[18]*t716);
    const T t750 = in[21]*t729 + (in[15]*t705 + in[18]*t717);
    const T t751 = in[21]*t730 + (in[15]*t706 + in[18]*t718);
    const T t752 = in[21]*t731 + (in[15]*t707 + in[18]*t719);
    const T t753 = in[21]*t732 + (in[15]*t708 + in[18]*t720);
    const T t754 = t148;
    const T t755 = (T(0.5))*t624;
    const T t756 = (T(0.5))*t625;
    const T t757 = (T(0.5))*t626;
    const T t758 = (T(0.5))*t627;
    const T t759 = (T(0.5))*t628;
    const T t760 = (T(0.5))*t629;
    const T t761 = (T(0.5))*t630;
    const T t762 = (T(0.5))*t631;
    const T t763 = (T(0.5))*t632;
    const T t764 = (T(0.5))*t633;
    const T t765 = (T(0.5))*t634;
    const T t766 = (T(0.5))*t635;
    const T t767 = t135*t243;
    const T t768 = t243*t241 + t135*t672;
    const T t769 = t243*t260 + t135*t673;
    const T t770 = t243*t278 + t135*t674;
    const T t771 = t243*t293 + t135*t675;
    const T t772 = t243*t308 + t135*t676;
    const T t773 = t243*t323 + t135*t677;
    const T t774 = t243*t349 + t135*t678;
    const T t775 = t243*t375 + t135*t679;
    const T t776 = t243*t401 + t135*t680;
    const T t777 = t243*t427 + t135*t681;
    const T t778 = t243*t453 + t135*t682;
    const T t779 = t243*t479 + t135*t683;
    const T t780 = t133*t767;
    const T t781 = t767*t612 + t133*t768;
    const T t782 = t767*t613 + t133*t769;
    const T t783 = t767*t614 + t133*t770;
    const T t784 = t767*t615 + t133*t771;
    const T t785 = t767*t616 + t133*t772;
    const T t786 = t767*t617 + t133*t773;
    const T t787 = t767*t618 + t133*t774;
    const T t788 = t767*t619 + t133*t775;
    const T t789 = t767*t620 + t133*t776;
    const T t790 = t767*t621 + t133*t777;
    const T t791 = t767*t622 + t133*t778;
    const T t792 = t767*t623 + t133*t779;
    const T t793 = t754 + t780;
    const T t794 = t755 + t781;
    const T t795 = t756 + t782;
    const T t796 = t757 + t783;
    const T t797 = t758 + t784;
    const T t798 = t759 + t785;
    const T t799 = t760 + t786;
    const T t800 = t761 + t787;
    const T t801 = t762 + t788;
    const T t802 = t763 + t789;
    const T t803 = t764 + t790;
    const T t804 = t765 + t791;
    const T t805 = t766 + t792;
    const T t806 = t224;
    const T t807 = in[22]*t721 + (in[16]*t697 + in[19]*t709);
    const T t808 = in[22]*t722 + (in[16]*t698 + in[19]*t710);
    const T t809 = in[22]*t723 + (in[16]*t699 + in[19]*t711);
    const T t810 = t62;
    const T t811 = t67;
    const T t812 = t71;
    const T t813 = dat[69]*in[16];
    const T t814 = dat[69]*in[19];
    const T t815 = dat[69]*in[22];
    const T t816 = t223;
    const T t817 = -t222;
    const T t818 = t724*in[22] + (t700*in[16] + t712*in[19]);
    const T t819 = t725*in[22] + (t701*in[16] + t713*in[19]);
    const T t820 = t726*in[22] + (t702*in[16] + t714*in[19]);
    const T t821 = in[22]*t727 + (in[16]*t703 + in[19]*t715);
    const T t822 = in[22]*t728 + (in[16]*t704 + in[19]*t716);
    const T t823 = in[22]*t729 + (in[16]*t705 + in[19]*t717);
    const T t824 = in[22]*t730 + (in[16]*t706 + in[19]*t718);
    const T t825 = in[22]*t731 + (in[16]*t707 + in[19]*t719);
    const T t826 = in[22]*t732 + (in[16]*t708 + in[19]*t720);
    const T t827 = t134;
    const T t828 = (T(0.5))*t612;
    const T t829 = (T(0.5))*t613;
    const T t830 = (T(0.5))*t614;
    const T t831 = (T(0.5))*t615;
    const T t832 = (T(0.5))*t616;
    const T t833 = (T(0.5))*t617;
    const T t834 = (T(0.5))*t618;
    const T t835 = (T(0.5))*t619;
    const T t836 = (T(0.5))*t620;
    const T t837 = (T(0.5))*t621;
    const T t838 = (T(0.5))*t622;
    const T t839 = (T(0.5))*t623;
    const T t840 = t138*t767;
    const T t841 = t767*t624 + t138*t768;
    const T t842 = t767*t625 + t138*t769;
    const T t843 = t767*t626 + t138*t770;
    const T t844 = t767*t627 + t138*t771;
    const T t845 = t767*t628 + t138*t772;
    const T t846 = t767*t629 + t138*t773;
    const T t847 = t767*t630 + t138*t774;
    const T t848 = t767*t631 + t138*t775;
    const T t849 = t767*t632 + t138*t776;
    const T t850 = t767*t633 + t138*t777;
    const T t851 = t767*t634 + t138*t778;
    const T t852 = t767*t635 + t138*t779;
    const T t853 = t840 - t827;
    const T t854 = t841 - t828;
    const T t855 = t842 - t829;
    const T t856 = t843 - t830;
    const T t857 = t844 - t831;
    const T t858 = t845 - t832;
    const T t859 = t846 - t833;
    const T t860 = t847 - t834;
    const T t861 = t848 - t835;
    const T t862 = t849 - t836;
    const T t863 = t850 - t837;
    const T t864 = t851 - t838;
    const T t865 = t852 - t839;
    const T t866 = t223;
    const T t867 = in[23]*t721 + (in[17]*t697 + in[20]*t709);
    const T t868 = in[23]*t722 + (in[17]*t698 + in[20]*t710);
    const T t869 = in[23]*t723 + (in[17]*t699 + in[20]*t711);
    const T t870 = t60;
    const T t871 = t65;
    const T t872 = t69;
    const T t873 = dat[69]*in[17];
    const T t874 = dat[69]*in[20];
    const T t875 = dat[69]*in[23];
    const T t876 = -t224;
    const T t877 = t222;
    const T t878 = t724*in[23] + (t700*in[17] + t712*in[20]);
    const T t879 = t725*in[23] + (t701*in[17] + t713*in[20]);
    const T t880 = t726*in[23] + (t702*in[17] + t714*in[20]);
    const T t881 = in[23]*t727 + (in[17]*t703 + in[20]*t715);
    const T t882 = in[23]*t728 + (in[17]*t704 + in[20]*t716);
    const T t883 = in[23]*t729 + (in[17]*t705 + in[20]*t717);
    const T t884 = in[23]*t730 + (in[17]*t706 + in[20]*t718);
    const T t885 = in[23]*t731 + (in[17]*t707 + in[20]*t719);
    const T t886 = in[23]*t732 + (in[17]*t708 + in[20]*t720);
    const T t887 = T(1) + t225*t243;
    const T t888 = t225*t672 - (t244 + t243*t648);
    const T t889 = t225*t673 - (t262 + t243*t649);
    const T t890 = t225*t674 - (t280 + t243*t650);
    const T t891 = t225*t675 - (t243*t651 + t295);
    const T t892 = t225*t676 - (t243*t652 + t310);
    const T t893 = t225*t677 - (t243*t653 + t325);
    const T t894 = t225*t678 - (t351 + t243*t654);
    const T t895 = t225*t679 - (t377 + t243*t655);
    const T t896 = t225*t680 - (t403 + t243*t656);
    const T t897 = t225*t681 - (t429 + t243*t657);
    const T t898 = t225*t682 - (t455 + t243*t658);
    const T t899 = t225*t683 - (t481 + t243*t659);
    const T t900 = t162;
    const T t901 = (T(0.5))*t241;
    const T t902 = (T(0.5))*t260;
    const T t903 = (T(0.5))*t278;
    const T t904 = (T(0.5))*t293;
    const T t905 = (T(0.5))*t308;
    const T t906 = (T(0.5))*t323;
    const T t907 = (T(0.5))*t349;
    const T t908 = (T(0.5))*t375;
    const T t909 = (T(0.5))*t401;
    const T t910 = (T(0.5))*t427;
    const T t911 = (T(0.5))*t453;
    const T t912 = (T(0.5))*t479;
    const T t913 = t181*t243;
    const T t914 = (t482*t624 + t483*t612) + t181*t672;
    const T t915 = (t482*t625 + t483*t613) + t181*t673;
    const T t916 = (t482*t626 + t483*t614) + t181*t674;
    const T t917 = (t482*t627 + t483*t615) + t181*t675;
    const T t918 = (t482*t628 + t483*t616) + t181*t676;
    const T t919 = (t482*t629 + t483*t617) + t181*t677;
    const T t920 = (t482*t630 + t483*t618) + t181*t678;
    const T t921 = (t482*t631 + t483*t619) + t181*t679;
    const T t922 = (t482*t632 + t483*t620) + t181*t680;
    const T t923 = (t482*t633 + t483*t621) + t181*t681;
    const T t924 = (t482*t634 + t483*t622) + t181*t682;
    const T t925 = (t482*t635 + t483*t623) + t181*t683;
    const T t926 = t900 + t913;
    const T t927 = t901 + t914;
    const T t928 = t902 + t915;
    const T t929 = t903 + t916;
    const T t930 = t904 + t917;
    const T t931 = t905 + t918;
    const T t932 = t906 + t919;
    const T t933 = t907 + t920;
    const T t934 = t908 + t921;
    const T t935 = t909 + t922;
    const T t936 = t910 + t923;
    const T t937 = t911 + t924;
    const T t938 = t912 + t925;
    const T t939 = t780 - t754;
    const T t940 = t781 - t755;
    const T t941 = t782 - t756;
    const T t942 = t783 - t757;
    const T t943 = t784 - t758;
    const T t944 = t785 - t759;
    const T t945 = t786 - t760;
    const T t946 = t787 - t761;
    const T t947 = t788 - t762;
    const T t948 = t789 - t763;
    const T t949 = t790 - t764;
    const T t950 = t791 - t765;
    const T t951 = t792 - t766;
    const T t952 = T(1) + t484*t243;
    const T t953 = t484*t672 - (t244 + t243*t636);
    const T t954 = t484*t673 - (t262 + t243*t637);
    const T t955 = t484*t674 - (t280 + t243*t638);
    const T t956 = t484*t675 - (t243*t639 + t295);
    const T t957 = t484*t676 - (t243*t640 + t310);
    const T t958 = t484*t677 - (t243*t641 + t325);
    const T t959 = t484*t678 - (t351 + t243*t642);
    const T t960 = t484*t679 - (t377 + t243*t643);
    const T t961 = t484*t680 - (t403 + t243*t644);
    const T t962 = t484*t681 - (t429 + t243*t645);
    const T t963 = t484*t682 - (t455 + t243*t646);
    const T t964 = t484*t683 - (t481 + t243*t647);
    const T t965 = t827 + t840;
    const T t966 = t828 + t841;
    const T t967 = t829 + t842;
    const T t968 = t830 + t843;
    const T t969 = t831 + t844;
    const T t970 = t832 + t845;
    const T t971 = t833 + t846;
    const T t972 = t834 + t847;
    const T t973 = t835 + t848;
    const T t974 = t836 + t849;
    const T t975 = t837 + t850;
    const T t976 = t838 + t851;
    const T t977 = t839 + t852;
    const T t978 = t913 - t900;
    const T t979 = t914 - t901;
    const T t980 = t915 - t902;
    const T t981 = t916 - t903;
    const T t982 = t917 - t904;
    const T t983 = t918 - t905;
    const T t984 = t919 - t906;
    const T t985 = t920 - t907;
    const T t986 = t921 - t908;
    const T t987 = t922 - t909;
    const T t988 = t923 - t910;
    const T t989 = t924 - t911;
    const T t990 = t925 - t912;
    const T t991 = in[2]*t486 - in[1]*t487;
    const T t992 = in[0]*t487 - in[2]*t485;
    const T t993 = in[1]*t485 - in[0]*t486;
    const T t994 = dat[33]*in[2] + (dat[27]*in[0] + dat[30]*in[1]);
    const T t995 = dat[34]*in[2] + (dat[28]*in[0] + dat[31]*in[1]);
    const T t996 = dat[35]*in[2] + (dat[29]*in[0] + dat[32]*in[1]);
    const T t997 = dat[60]*in[2] + (dat[54]*in[0] + dat[57]*in[1]);
    const T t998 = dat[61]*in[2] + (dat[55]*in[0] + dat[58]*in[1]);
    const T t999 = dat[62]*in[2] + (dat[56]*in[0] + dat[59]*in[1]);
    const T t1000 = in[5]*t486 - in[4]*t487;
    const T t1001 = in[3]*t487 - in[5]*t485;
    const T t1002 = in[4]*t485 - in[3]*t486;
    const T t1003 = dat[33]*in[5] + (dat[27]*in[3] + dat[30]*in[4]);
    const T t1004 = dat[34]*in[5] + (dat[28]*in[3] + dat[31]*in[4]);
    const T t1005 = dat[35]*in[5] + (dat[29]*in[3] + dat[32]*in[4]);
    const T t1006 = dat[60]*in[5] + (dat[54]*in[3] + dat[57]*in[4]);
    const T t1007 = dat[61]*in[5] + (dat[55]*in[3] + dat[58]*in[4]);
    const T t1008 = dat[62]*in[5] + (dat[56]*in[3] + dat[59]*in[4]);
    const T t1009 = in[8]*t486 - in[7]*t487;
    const T t1010 = in[6]*t487 - in[8]*t485;
    const T t1011 = in[7]*t485 - in[6]*t486;
    const T t1012 = dat[33]*in[8] + (dat[27]*in[6] + dat[30]*in[7]);
    const T t1013 = dat[34]*in[8] + (dat[28]*in[6] + dat[31]*in[7]);
    const T t1014 = dat[35]*in[8] + (dat[29]*in[6] + dat[32]*in[7]);
    const T t1015 = dat[60]*in[8] + (dat[54]*in[6] + dat[57]*in[7]);
    const T t1016 = dat[61]*in[8] + (dat[55]*in[6] + dat[58]*in[7]);
    const T t1017 = dat[62]*in[8] + (dat[56]*in[6] + dat[59]*in[7]);
    const T t1018 = t491;
    const T t1019 = in[21]*t1009 + (in[15]*t991 + in[18]*t1000);
    const T t1020 = in[21]*t1010 + (in[15]*t992 + in[18]*t1001);
    const T t1021 = in[21]*t1011 + (in[15]*t993 + in[18]*t1002);
    const T t1022 = -t492;
    const T t1023 = t493;
    const T t1024 = t204;
    const T t1025 = t208;
    const T t1026 = t212;
    const T t1027 = in[21]*t1012 + (in[15]*t994 + in[18]*t1003);
    const T t1028 = in[21]*t1013 + (in[15]*t995 + in[18]*t1004);
    const T t1029 = in[21]*t1014 + (in[15]*t996 + in[18]*t1005);
    const T t1030 = in[21]*t1015 + (in[15]*t997 + in[18]*t1006);
    const T t1031 = in[21]*t1016 + (in[15]*t998 + in[18]*t1007);
    const T t1032 = in[21]*t1017 + (in[15]*t999 + in[18]*t1008);
    const T t1033 = t493;
    const T t1034 = in[22]*t1009 + (in[16]*t991 + in[19]*t1000);
    const T t1035 = in[22]*t1010 + (in[16]*t992 + in[19]*t1001);
    const T t1036 = in[22]*t1011 + (in[16]*t993 + in[19]*t1002);
    const T t1037 = t492;
    const T t1038 = -t491;
    const T t1039 = t205;
    const T t1040 = t209;
    const T t1041 = t213;
    const T t1042 = in[22]*t1012 + (in[16]*t994 + in[19]*t1003);
    const T t1043 = in[22]*t1013 + (in[16]*t995 + in[19]*t1004);
    const T t1044 = in[22]*t1014 + (in[16]*t996 + in[19]*t1005);
    const T t1045 = in[22]*t1015 + (in[16]*t997 + in[19]*t1006);
    const T t1046 = in[22]*t1016 + (in[16]*t998 + in[19]*t1007);
    const T t1047 = in[22]*t1017 + (in[16]*t999 + in[19]*t1008);
    const T t1048 = t492;
    const T t1049 = in[23]*t1009 + (in[17]*t991 + in[20]*t1000);
    const T t1050 = in[23]*t1010 + (in[17]*t992 + in[20]*t1001);
    const T t1051 = in[23]*t1011 + (in[17]*t993 + in[20]*t1002);
    const T t1052 = -t493;
    const T t1053 = t491;
    const T t1054 = t206;
    const T t1055 = t210;
    const T t1056 = t214;
    const T t1057 = in[23]*t1012 + (in[17]*t994 + in[20]*t1003);
    const T t1058 = in[23]*t1013 + (in[17]*t995 + in[20]*t1004);
    const T t1059 = in[23]*t1014 + (in[17]*t996 + in[20]*t1005);
    const T t1060 = in[23]*t1015 + (in[17]*t997 + in[20]*t1006);
    const T t1061 = in[23]*t1016 + (in[17]*t998 + in[20]*t1007);
    const T t1062 = in[23]*t1017 + (in[17]*t999 + in[20]*t1008);
    const T t1063 = dat[76]*t226 + dat[79]*t227;
    const T t1064 = dat[73]*t245 + dat[79]*t246;
    const T t1065 = dat[73]*t263 + dat[76]*t264;
    const T t1066 = dat[79]*t298 + (dat[73]*t296 + dat[76]*t297);
    const T t1067 = dat[79]*t313 + (dat[73]*t311 + dat[76]*t312);
    const T t1068 = dat[76]*t231 + dat[79]*t232;
    const T t1069 = dat[73]*t250 + dat[79]*t251;
    const T t1070 = dat[73]*t268 + dat[76]*t269;
    const T t1071 = dat[79]*t283 + (dat[73]*t281 + dat[76]*t282);
    const T t1072 = dat[79]*t319 + (dat[73]*t317 + dat[76]*t318);
    const T t1073 = dat[76]*t236 + dat[79]*t237;
    const T t1074 = dat[73]*t255 + dat[79]*t256;
    const T t1075 = dat[73]*t273 + dat[76]*t274;
    const T t1076 = dat[79]*t289 + (dat[73]*t287 + dat[76]*t288);
    const T t1077 = dat[79]*t304 + (dat[73]*t302 + dat[76]*t303);
    const T t1078 = dat[77]*t226 + dat[80]*t227;
    const T t1079 = dat[74]*t245 + dat[80]*t246;
    const T t1080 = dat[74]*t263 + dat[77]*t264;
    const T t1081 = dat[80]*t298 + (dat[74]*t296 + dat[77]*t297);
    const T t1082 = dat[80]*t313 + (dat[74]*t311 + dat[77]*t312);
    const T t1083 = dat[77]*t231 + dat[80]*t232;
    const T t1084 = dat[74]*t250 + dat[80]*t251;
    const T t1085 = dat[74]*t268 + dat[77]*t269;
    const T t1086 = dat[80]*t283 + (dat[74]*t281 + dat[77]*t282);
    const T t1087 = dat[80]*t319 + (dat[74]*t317 + dat[77]*t318);
    const T t1088 = dat[77]*t236 + dat[80]*t237;
    const T t1089 = dat[74]*t255 + dat[80]*t256;
    const T t1090 = dat[74]*t273 + dat[77]*t274;
    const T t1091 = dat[80]*t289 + (dat[74]*t287 + dat[77]*t288);
    const T t1092 = dat[80]*t304 + (dat[74]*t302 + dat[77]*t303);
    const T t1093 = dat[78]*t226 + dat[81]*t227;
    const T t1094 = dat[75]*t245 + dat[81]*t246;
    const T t1095 = dat[75]*t263 + dat[78]*t264;
    const T t1096 = dat[81]*t298 + (dat[75]*t296 + dat[78]*t297);
    const T t1097 = dat[81]*t313 + (dat[75]*t311 + dat[78]*t312);
    const T t1098 = dat[78]*t231 + dat[81]*t232;
    const T t1099 = dat[75]*t250 + dat[81]*t251;
    const T t1100 = dat[75]*t268 + dat[78]*t269;
    const T t1101 = dat[81]*t283 + (dat[75]*t281 + dat[78]*t282);
    const T t1102 = dat[81]*t319 + (dat[75]*t317 + dat[78]*t318);
    const T t1103 = dat[78]*t236 + dat[81]*t237;
    const T t1104 = dat[75]*t255 + dat[81]*t256;
    const T t1105 = dat[75]*t273 + dat[78]*t274;
    const T t1106 = dat[81]*t289 + (dat[75]*t287 + dat[78]*t288);
    const T t1107 = dat[81]*t304 + (dat[75]*t302 + dat[78]*t303);
    const T t1108 = ((t1083*t525 + t1098*t528) + (t1073*t523 + t1078*t524)) + ((t1088*t526 + t1093*t527) + (t1103*t529 + (t1063*t518 + t1068*t520)));
    const T t1109 = ((t1084*t525 + t1099*t528) + (t1074*t523 + t1079*t524)) + ((t1089*t526 + t1094*t527) + (t1104*t529 + (t1064*t518 + t1069*t520)));
    const T t1110 = ((t1085*t525 + t1100*t528) + (t1075*t523 + t1080*t524)) + ((t1090*t526 + t1095*t527) + (t1105*t529 + (t1065*t518 + t1070*t520)));
    const T t1111 = (t1091*t526 + t1106*t529) + ((t1071*t520 + t1086*t525) + (t1101*t528 + t1076*t523));
    const T t1112 = (t1096*t527 + t1107*t529) + ((t1066*t518 + t1077*t523) + (t1081*t524 + t1092*t526));
    const T t1113 = (t1082*t524 + t1097*t527) + ((t1067*t518 + t1072*t520) + (t1087*t525 + t1102*t528));
    const T t1114 = ((t1078*t541 + t1083*t542) + (t1093*t544 + t1098*t545)) + ((t1073*t540 + t1088*t543) + (t1103*t546 + (t1063*t535 + t1068*t537)));
    const T t1115 = ((t1079*t541 + t1084*t542) + (t1094*t544 + t1099*t545)) + ((t1074*t540 + t1089*t543) + (t1104*t546 + (t1064*t535 + t1069*t537)));
    const T t1116 = ((t1080*t541 + t1085*t542) + (t1095*t544 + t1100*t545)) + ((t1075*t540 + t1090*t543) + (t1105*t546 + (t1065*t535 + t1070*t537)));
    const T t1117 = (t1091*t543 + t1106*t546) + ((t1071*t537 + t1086*t542) + (t1101*t545 + t1076*t540));
    const T t1118 = (t1092*t543 + t1107*t546) + ((t1066*t535 + t1081*t541) + (t1096*t544 + t1077*t540));
    const T t1119 = (t1097*t544 + t1102*t545) + ((t1067*t535 + t1072*t537) + (t1082*t541 + t1087*t542));
    const T t1120 = ((t1083*t556 + t1098*t559) + (t1073*t554 + t1078*t555)) + ((t1088*t557 + t1093*t558) + (t1103*t560 + (t1063*t549 + t1068*t551)));
    const T t1121 = ((t1084*t556 + t1099*t559) + (t1074*t554 + t1079*t555)) + ((t1089*t557 + t1094*t558) + (t1104*t560 + (t1064*t549 + t1069*t551)));
    const T t1122 = ((t1085*t556 + t1100*t559) + (t1075*t554 + t1080*t555)) + ((t1090*t557 + t1095*t558) + (t1105*t560 + (t1065*t549 + t1070*t551)));
    const T t1123 = (t1091*t557 + t1106*t560) + ((t1071*t551 + t1086*t556) + (t1101*t559 + t1076*t554));
    const T t1124 = (t1096*t558 + t1107*t560) + ((t1066*t549 + t1077*t554) + (t1081*t555 + t1092*t557));
    const T t1125 = (t1082*t555 + t1097*t558) + ((t1067*t549 + t1072*t551) + (t1087*t556 + t1102*t559));
    const T t1126 = t561*t1114;
    const T t1127 = t561*t1115;
    const T t1128 = t561*t1116;
    const T t1129 = t561*t1117;
    const T t1130 = t561*t1118;
    const T t1131 = t561*t1119;
    const T t1132 = t562*t1120;
    const T t1133 = t562*t1121;
    const T t1134 = t562*t1122;
    const T t1135 = t562*t1123;
    const T t1136 = t562*t1124;
    const T t1137 = t562*t1125;
    const T t1138 = t1132 + t1126;
    const T t1139 = t1133 + t1127;
    const T t1140 = t1134 + t1128;
    const T t1141 = t1135 + t1129;
    const T t1142 = t1136 + t1130;
    const T t1143 = t1137 + t1131;
    const T t1144 = t563*t1108;
    const T t1145 = t563*t1109;
    const T t1146 = t563*t1110;
    const T t1147 = t563*t1111;
    const T t1148 = t563*t1112;
    const T t1149 = t563*t1113;
    const T t1150 = t569*t1144 + t569*t1138;
    const T t1151 = t569*t1145 + t569*t1139;
    const T t1152 = t569*t1146 + t569*t1140;
    const T t1153 = t569*t1147 + t569*t1141;
    const T t1154 = t569*t1148 + t569*t1142;
    const T t1155 = t569*t1149 + t569*t1143;
    const T t1156 = -t573;
    const T t1157 = t574;
    const T t1158 = -((in[6]*in[6]) + ((in[0]*in[0]) + (in[3]*in[3])));
    const T t1159 = t575;
    const T t1160 = t576;
    const T t1161 = t56;
    const T t1162 = t62;
    const T t1163 = t60;
    const T t1164 = t573;
    const T t1165 = -t577;
    const T t1166 = t575;
    const T t1167 = -((in[7]*in[7]) + ((in[1]*in[1]) + (in[4]*in[4])));
    const T t1168 = t578;
    const T t1169 = t59;
    const T t1170 = t67;
    const T t1171 = t65;
    const T t1172 = -t574;
    const T t1173 = t577;
    const T t1174 = t576;
    const T t1175 = t578;
    const T t1176 = -((in[8]*in[8]) + ((in[2]*in[2]) + (in[5]*in[5])));
    const T t1177 = t57;
    const T t1178 = t71;
    const T t1179 = t69;
    const T t1180 = dat[76]*t1164 + dat[79]*t1172;
    const T t1181 = dat[73]*t1156 + dat[79]*t1173;
    const T t1182 = dat[73]*t1157 + dat[76]*t1165;
    const T t1183 = dat[79]*t1174 + (dat[73]*t1158 + dat[76]*t1166);
    const T t1184 = dat[79]*t1175 + (dat[73]*t1159 + dat[76]*t1167);
    const T t1185 = dat[79]*t1176 + (dat[73]*t1160 + dat[76]*t1168);
    const T t1186 = dat[79]*t1177 + (dat[73]*t1161 + dat[76]*t1169);
    const T t1187 = dat[79]*t1178 + (dat[73]*t1162 + dat[76]*t1170);
    const T t1188 = dat[79]*t1179 + (dat[73]*t1163 + dat[76]*t1171);
    const T t1189 = (T(0.5))*t1120;
    const T t1190 = (T(0.5))*t1121;
    const T t1191 = (T(0.5))*t1122;
    const T t1192 = (T(0.5))*t1123;
    const T t1193 = (T(0.5))*t1124;
    const T t1194 = (T(0.5))*t1125;
    const T t1195 = t579*t1108 + t505*t1150;
    const T t1196 = t579*t1109 + t505*t1151;
    const T t1197 = t579*t1110 + t505*t1152;
    const T t1198 = t579*t1111 + t505*t1153;
    const T t1199 = t579*t1112 + t505*t1154;
    const T t1200 = t579*t1113 + t505*t1155;
    const T t1201 = t584*t1114 + t503*t1195;
    const T t1202 = t584*t1115 + t503*t1196;
    const T t1203 = t584*t1116 + t503*t1197;
    const T t1204 = t584*t1117 + t503*t1198;
    const T t1205 = t584*t1118 + t503*t1199;
    const T t1206 = t584*t1119 + t503*t1200;
    const T t1207 = dat[77]*t1164 + dat[80]*t1172;
    const T t1208 = dat[74]*t1156 + dat[80]*t1173;
    const T t1209 = dat[74]*t1157 + dat[77]*t1165;
    const T t1210 = dat[80]*t1174 + (dat[74]*t1158 + dat[77]*t1166);
    const T t1211 = dat[80]*t1175 + (dat[74]*t1159 + dat[77]*t1167);
    const T t1212 = dat[80]*t1176 + (dat[74]*t1160 + dat[77]*t1168);
    const T t1213 = dat[80]*t1177 + (dat[74]*t1161 + dat[77]*t1169);
    const T t1214 = dat[80]*t1178 + (dat[74]*t1162 + dat[77]*t1170);
    const T t1215 = dat[80]*t1179 + (dat[74]*t1163 + dat[77]*t1171);
    const T t1216 = (T(0.5))*t1114;
    const T t1217 = (T(0.5))*t1115;
    const T t1218 = (T(0.5))*t1116;
    const T t1219 = (T(0.5))*t1117;
    const T t1220 = (T(0.5))*t1118;
    const T t1221 = (T(0.5))*t1119;
    const T t1222 = t584*t1120 + t508*t1195;
    const T t1223 = t584*t1121 + t508*t1196;
    const T t1224 = t584*t1122 + t508*t1197;
    const T t1225 = t584*t1123 + t508*t1198;
    const T t1226 = t584*t1124 + t508*t1199;
    const T t1227 = t584*t1125 + t508*t1200;
    const T t1228 = dat[78]*t1164 + dat[81]*t1172;
    const T t1229 = dat[75]*t1156 + dat[81]*t1173;
    const T t1230 = dat[75]*t1157 + dat[78]*t1165;
    const T t1231 = dat[81]*t1174 + (dat[75]*t1158 + dat[78]*t1166);
    const T t1232 = dat[81]*t1175 + (dat[75]*t1159 + dat[78]*t1167);
    const T t1233 = dat[81]*t1176 + (dat[75]*t1160 + dat[78]*t1168);
    const T t1234 = dat[81]*t1177 + (dat[75]*t1161 + dat[78]*t1169);
    const T t1235 = dat[81]*t1178 + (dat[75]*t1162 + dat[78]*t1170);
    const T t1236 = dat[81]*t1179 + (dat[75]*t1163 + dat[78]*t1171);
    const T t1237 = (T(0.5))*t1108;
    const T t1238 = (T(0.5))*t1109;
    const T t1239 = (T(0.5))*t1110;
    const T t1240 = (T(0.5))*t1111;
    const T t1241 = (T(0.5))*t1112;
    const T t1242 = (T(0.5))*t1113;
    const T t1243 = (t580*t1120 + t581*t1114) + t531*t1150;
    const T t1244 = (t580*t1121 + t581*t1115) + t531*t1151;
    const T t1245 = (t580*t1122 + t581*t1116) + t531*t1152;
    const T t1246 = (t580*t1123 + t581*t1117) + t531*t1153;
    const T t1247 = (t580*t1124 + t581*t1118) + t531*t1154;
    const T t1248 = (t580*t1125 + t581*t1119) + t531*t1155;
    raw[0] = t241;
    raw[1] = t260;
    raw[2] = t278;
    raw[9] = t293;
    raw[10] = t308;
    raw[11] = t323;
    raw[18] = t349;
    raw[19] = t375;
    raw[20] = t401;
    raw[21] = t427;
    raw[22] = t453;
    raw[23] = t479;
    raw[30] = t135;
    raw[32] = t612;
    raw[33] = t613;
    raw[34] = t614;
    raw[41] = t615;
    raw[42] = t616;
    raw[43] = t617;
    raw[50] = t618;
    raw[51] = t619;
    raw[52] = t620;
    raw[53] = t621;
    raw[54] = t622;
    raw[55] = t623;
    raw[62] = t133;
    raw[64] = t624;
    raw[65] = t625;
    raw[66] = t626;
    raw[73] = t627;
    raw[74] = t628;
    raw[75] = t629;
    raw[82] = t630;
    raw[83] = t631;
    raw[84] = t632;
    raw[85] = t633;
    raw[86] = t634;
    raw[87] = t635;
    raw[94] = t138;
    raw[96] = t866*t854 + (((t867*t853 + (t734*t684 + t807*t793)) + t733*t685) + t806*t794);
    raw[97] = t866*t855 + (((t868*t853 + (t735*t684 + t808*t793)) + t733*t686) + t806*t795);
    raw[98] = t866*t856 + (((t869*t853 + (t736*t684 + t809*t793)) + t733*t687) + t806*t796);
    raw[99] = t870*t853 + (t737*t684 + t810*t793);
    raw[100] = t871*t853 + (t738*t684 + t811*t793);
    raw[101] = t872*t853 + (t739*t684 + t812*t793);
    raw[102] = t873*t853 + (t740*t684 + t813*t793);
    raw[103] = t874*t853 + (t741*t684 + t814*t793);
    raw[104] = t875*t853 + (t742*t684 + t815*t793);
    raw[105] = t866*t857 + (((t816*t793 + t876*t853) + t733*t688) + t806*t797);
    raw[106] = t866*t858 + (((t743*t684 + t877*t853) + t733*t689) + t806*t798);
    raw[107] = t866*t859 + (((t744*t684 + t817*t793) + t733*t690) + t806*t799);
    raw[108] = t878*t853 + (t745*t684 + t818*t793);
    raw[109] = t879*t853 + (t746*t684 + t819*t793);
    raw[110] = t880*t853 + (t747*t684 + t820*t793);
    raw[114] = t866*t860 + (((t881*t853 + (t748*t684 + t821*t793)) + t733*t691) + t806*t800);
    raw[115] = t866*t861 + (((t882*t853 + (t749*t684 + t822*t793)) + t733*t692) + t806*t801);
    raw[116] = t866*t862 + (((t883*t853 + (t750*t684 + t823*t793)) + t733*t693) + t806*t802);
    raw[117] = t866*t863 + (((t884*t853 + (t751*t684 + t824*t793)) + t733*t694) + t806*t803);
    raw[118] = t866*t864 + (((t885*t853 + (t752*t684 + t825*t793)) + t733*t695) + t806*t804);
    raw[119] = t866*t865 + (((t886*t853 + (t753*t684 + t826*t793)) + t733*t696) + t806*t805);
    raw[126] = t866*t853 + (t733*t684 + t806*t793);
    raw[128] = (t866*t927 + ((t734*t939 + (t807*t887 + t867*t926)) + t806*t888)) + t733*t940;
    raw[129] = (t866*t928 + ((t735*t939 + (t808*t887 + t868*t926)) + t806*t889)) + t733*t941;
    raw[130] = (t866*t929 + ((t736*t939 + (t809*t887 + t869*t926)) + t806*t890)) + t733*t942;
    raw[131] = t737*t939 + (t810*t887 + t870*t926);
    raw[132] = t738*t939 + (t811*t887 + t871*t926);
    raw[133] = t739*t939 + (t812*t887 + t872*t926);
    raw[134] = t740*t939 + (t813*t887 + t873*t926);
    raw[135] = t741*t939 + (t814*t887 + t874*t926);
    raw[136] = t742*t939 + (t815*t887 + t875*t926);
    raw[137] = (t866*t930 + ((t816*t887 + t876*t926) + t806*t891)) + t733*t943;
    raw[138] = (t866*t931 + ((t877*t926 + t743*t939) + t806*t892)) + t733*t944;
    raw[139] = (t866*t932 + ((t817*t887 + t744*t939) + t806*t893)) + t733*t945;
    raw[140] = t745*t939 + (t818*t887 + t878*t926);
    raw[141] = t746*t939 + (t819*t887 + t879*t926);
    raw[142] = t747*t939 + (t820*t887 + t880*t926);
    raw[146] = (t866*t933 + ((t748*t939 + (t821*t887 + t881*t926)) + t806*t894)) + t733*t946;
    raw[147] = (t866*t934 + ((t749*t939 + (t822*t887 + t882*t926)) + t806*t895)) + t733*t947;
    raw[148] = (t866*t935 + ((t750*t939 + (t823*t887 + t883*t926)) + t806*t896)) + t733*t948;
    raw[149] = (t866*t936 + ((t751*t939 + (t824*t887 + t884*t926)) + t806*t897)) + t733*t949;
    raw[150] = (t866*t937 + ((t752*t939 + (t825*t887 + t885*t926)) + t806*t898)) + t733*t950;
    raw[151] = (t866*t938 + ((t753*t939 + (t826*t887 + t886*t926)) + t806*t899)) + t733*t951;
    raw[158] = t733*t939 + (t806*t887 + t866*t926);
    raw[160] = (t806*t979 + ((t734*t965 + (t867*t952 + t807*t978)) + t866*t953)) + t733*t966;
    raw[161] = (t806*t980 + ((t735*t965 + (t868*t952 + t808*t978)) + t866*t954)) + t733*t967;
    raw[162] = (t806*t981 + ((t736*t965 + (t869*t952 + t809*t978)) + t866*t955)) + t733*t968;
    raw[163] = t737*t965 + (t870*t952 + t810*t978);
    raw[164] = t738*t965 + (t871*t952 + t811*t978);
    raw[165] = t739*t965 + (t872*t952 + t812*t978);
    raw[166] = t740*t965 + (t873*t952 + t813*t978);
    raw[167] = t741*t965 + (t874*t952 + t814*t978);
    raw[168] = t742*t965 + (t875*t952 + t815*t978);
    raw[169] = (t806*t982 + ((t876*t952 + t816*t978) + t866*t956)) + t733*t969;
    raw[170] = (t806*t983 + ((t877*t952 + t743*t965) + t866*t957)) + t733*t970;
    raw[171] = (t806*t984 + ((t817*t978 + t744*t965) + t866*t958)) + t733*t971;
    raw[172] = t745*t965 + (t878*t952 + t818*t978);
    raw[173] = t746*t965 + (t879*t952 + t819*t978);
    raw[174] = t747*t965 + (t880*t952 + t820*t978);
    raw[178] = (t806*t985 + ((t748*t965 + (t881*t952 + t821*t978)) + t866*t959)) + t733*t972;
    raw[179] = (t806*t986 + ((t749*t965 + (t882*t952 + t822*t978)) + t866*t960)) + t733*t973;
    raw[180] = (t806*t987 + ((t750*t965 + (t883*t952 + t823*t978)) + t866*t961)) + t733*t974;
    raw[181] = (t806*t988 + ((t751*t965 + (t884*t952 + t824*t978)) + t866*t962)) + t733*t975;
    raw[182] = (t806*t989 + ((t752*t965 + (t885*t952 + t825*t978)) + t866*t963)) + t733*t976;
    raw[183] = (t806*t990 + ((t753*t965 + (t886*t952 + t826*t978)) + t866*t964)) + t733*t977;
    raw[190] = t733*t965 + (t806*t978 + t866*t952);
    raw[192] = t1048*t854 + (((t1049*t853 + (t1019*t684 + t1034*t793)) + t1018*t685) + t1033*t794);
    raw[193] = t1048*t855 + (((t1050*t853 + (t1020*t684 + t1035*t793)) + t1018*t686) + t1033*t795);
    raw[194] = t1048*t856 + (((t1051*t853 + (t1021*t684 + t1036*t793)) + t1018*t687) + t1033*t796);
    raw[198] = in[17]*t853 + (in[15]*t684 + in[16]*t793);
    raw[199] = in[20]*t853 + (in[18]*t684 + in[19]*t793);
    raw[200] = in[23]*t853 + (in[21]*t684 + in[22]*t793);
    raw[201] = t1048*t857 + (((t1037*t793 + t1052*t853) + t1018*t688) + t1033*t797);
    raw[202] = t1048*t858 + (((t1022*t684 + t1053*t853) + t1018*t689) + t1033*t798);
    raw[203] = t1048*t859 + (((t1023*t684 + t1038*t793) + t1018*t690) + t1033*t799);
    raw[207] = t1054*t853 + (t1024*t684 + t1039*t793);
    raw[208] = t1055*t853 + (t1025*t684 + t1040*t793);
    raw[209] = t1056*t853 + (t1026*t684 + t1041*t793);
    raw[210] = t1048*t860 + (((t1057*t853 + (t1027*t684 + t1042*t793)) + t1018*t691) + t1033*t800);
    raw[211] = t1048*t861 + (((t1058*t853 + (t1028*t684 + t1043*t793)) + t1018*t692) + t1033*t801);
    raw[212] = t1048*t862 + (((t1059*t853 + (t1029*t684 + t1044*t793)) + t1018*t693) + t1033*t802);
    raw[213] = t1048*t863 + (((t1060*t853 + (t1030*t684 + t1045*t793)) + t1018*t694) + t1033*t803);
    raw[214] = t1048*t864 + (((t1061*t853 + (t1031*t684 + t1046*t793)) + t1018*t695) + t1033*t804);
    raw[215] = t1048*t865 + (((t1062*t853 + (t1032*t684 + t1047*t793)) + t1018*t696) + t1033*t805);
    raw[222] = t1048*t853 + (t1018*t684 + t1033*t793);
    raw[224] = (t1048*t927 + ((t1019*t939 + (t1034*t887 + t1049*t926)) + t1033*t888)) + t1018*t940;
    raw[225] = (t1048*t928 + ((t1020*t939 + (t1035*t887 + t1050*t926)) + t1033*t889)) + t1018*t941;
    raw[226] = (t1048*t929 + ((t1021*t939 + (t1036*t887 + t1051*t926)) + t1033*t890)) + t1018*t942;
    raw[230] = in[15]*t939 + (in[16]*t887 + in[17]*t926);
    raw[231] = in[18]*t939 + (in[19]*t887 + in[20]*t926);
    raw[232] = in[21]*t939 + (in[22]*t887 + in[23]*t926);
    raw[233] = (t1048*t930 + ((t1037*t887 + t1052*t926) + t1033*t891)) + t1018*t943;
    raw[234] = (t1048*t931 + ((t1053*t926 + t1022*t939) + t1033*t892)) + t1018*t944;
    raw[235] = (t1048*t932 + ((t1038*t887 + t1023*t939) + t1033*t893)) + t1018*t945;
    raw[239] = t1024*t939 + (t1039*t887 + t1054*t926);
    raw[240] = t1025*t939 + (t1040*t887 + t1055*t926);
    raw[241] = t1026*t939 + (t1041*t887 + t1056*t926);
    raw[242] = (t1048*t933 + ((t1027*t939 + (t1042*t887 + t1057*t926)) + t1033*t894)) + t1018*t946;
    raw[243] = (t1048*t934 + ((t1028*t939 + (t1043*t887 + t1058*t926)) + t1033*t895)) + t1018*t947;
    raw[244] = (t1048*t935 + ((t1029*t939 + (t1044*t887 + t1059*t926)) + t1033*t896)) + t1018*t948;
    raw[245] = (t1048*t936 + ((t1030*t939 + (t1045*t887 + t1060*t926)) + t1033*t897)) + t1018*t949;
    raw[246] = (t1048*t937 + ((t1031*t939 + (t1046*t887 + t1061*t926)) + t1033*t898)) + t1018*t950;
    raw[247] = (t1048*t938 + ((t1032*t939 + (t1047*t887 + t1062*t926)) + t1033*t899)) + t1018*t951;
    raw[254] = t1018*t939 + (t1033*t887 + t1048*t926);
    raw[256] = (t1033*t979 + ((t1019*t965 + (t1049*t952 + t1034*t978)) + t1048*t953)) + t1018*t966;
    raw[257] = (t1033*t980 + ((t1020*t965 + (t1050*t952 + t1035*t978)) + t1048*t954)) + t1018*t967;
    raw[258] = (t1033*t981 + ((t1021*t965 + (t1051*t952 + t1036*t978)) + t1048*t955)) + t1018*t968;
    raw[262] = in[15]*t965 + (in[17]*t952 + in[16]*t978);
    raw[263] = in[18]*t965 + (in[20]*t952 + in[19]*t978);
    raw[264] = in[21]*t965 + (in[23]*t952 + in[22]*t978);
    raw[265] = (t1033*t982 + ((t1052*t952 + t1037*t978) + t1048*t956)) + t1018*t969;
    raw[266] = (t1033*t983 + ((t1053*t952 + t1022*t965) + t1048*t957)) + t1018*t970;
    raw[267] = (t1033*t984 + ((t1038*t978 + t1023*t965) + t1048*t958)) + t1018*t971;
    raw[271] = t1024*t965 + (t1054*t952 + t1039*t978);
    raw[272] = t1025*t965 + (t1055*t952 + t1040*t978);
    raw[273] = t1026*t965 + (t1056*t952 + t1041*t978);
    raw[274] = (t1033*t985 + ((t1027*t965 + (t1057*t952 + t1042*t978)) + t1048*t959)) + t1018*t972;
    raw[275] = (t1033*t986 + ((t1028*t965 + (t1058*t952 + t1043*t978)) + t1048*t960)) + t1018*t973;
    raw[276] = (t1033*t987 + ((t1029*t965 + (t1059*t952 + t1044*t978)) + t1048*t961)) + t1018*t974;
    raw[277] = (t1033*t988 + ((t1030*t965 + (t1060*t952 + t1045*t978)) + t1048*t962)) + t1018*t975;
    raw[278] = (t1033*t989 + ((t1031*t965 + (t1061*t952 + t1046*t978)) + t1048*t963)) + t1018*t976;
    raw[279] = (t1033*t990 + ((t1032*t965 + (t1062*t952 + t1047*t978)) + t1048*t964)) + t1018*t977;
    raw[286] = t1018*t965 + (t1048*t952 + t1033*t978);
    raw[306] = T(1);
    raw[312] = (-T(1));
    raw[318] = in[30] - in[36];
    raw[339] = T(1);
    raw[345] = (-T(1));
    raw[350] = in[31] - in[37];
    raw[372] = T(1);
    raw[378] = (-T(1));
    raw[382] = in[32] - in[38];
    raw[405] = T(1);
    raw[411] = (-T(1));
    raw[414] = in[33] - in[39];
    raw[438] = T(1);
    raw[444] = (-T(1));
    raw[446] = in[34] - in[40];
    raw[471] = T(1);
    raw[477] = (-T(1));
    raw[478] = in[35] - in[41];
    raw[480] = t1108;
    raw[481] = t1109;
    raw[482] = t1110;
    raw[489] = t1111;
    raw[490] = t1112;
    raw[491] = t1113;
    raw[510] = t505;
    raw[512] = t1114;
    raw[513] = t1115;
    raw[514] = t1116;
    raw[521] = t1117;
    raw[522] = t1118;
    raw[523] = t1119;
    raw[542] = t503;
    raw[544] = t1120;
    raw[545] = t1121;
    raw[546] = t1122;
    raw[553] = t1123;
    raw[554] = t1124;
    raw[555] = t1125;
    raw[574] = t508;
    raw[576] = t609*t1222 + ((((((t1228*t589 + (t1180*t582 + t1207*t586)) + t606*t1189) - t609*t1216) - t605*t1138) - t604*t1150) + t606*t1201);
    raw[577] = t609*t1223 + ((((((t1229*t589 + (t1181*t582 + t1208*t586)) + t606*t1190) - t609*t1217) - t605*t1139) - t604*t1151) + t606*t1202);
    raw[578] = t609*t1224 + ((((((t1230*t589 + (t1182*t582 + t1209*t586)) + t606*t1191) - t609*t1218) - t605*t1140) - t604*t1152) + t606*t1203);
    raw[579] = t1231*t589 + (t1183*t582 + t1210*t586);
    raw[580] = t1232*t589 + (t1184*t582 + t1211*t586);
    raw[581] = t1233*t589 + (t1185*t582 + t1212*t586);
    raw[585] = t609*t1225 + ((((t606*t1192 - t609*t1219) - t605*t1141) - t604*t1153) + t606*t1204);
    raw[586] = t609*t1226 + ((((t606*t1193 - t609*t1220) - t605*t1142) - t604*t1154) + t606*t1205);
    raw[587] = t609*t1227 + ((((t606*t1194 - t609*t1221) - t605*t1143) - t604*t1155) + t606*t1206);
    raw[588] = t1234*t589 + (t1186*t582 + t1213*t586);
    raw[589] = t1235*t589 + (t1187*t582 + t1214*t586);
    raw[590] = t1236*t589 + (t1188*t582 + t1215*t586);
    raw[606] = t609*t589 + (t603*t582 + t606*t586);
    raw[608] = ((((t609*t1237 + ((t1180*t590 + (t1207*t592 + t1228*t595)) - t608*t1132)) - (t603*t1189 + t608*t1144)) + t607*t1150) + t609*t1243) + t603*t1201;
    raw[609] = ((((t609*t1238 + ((t1181*t590 + (t1208*t592 + t1229*t595)) - t608*t1133)) - (t603*t1190 + t608*t1145)) + t607*t1151) + t609*t1244) + t603*t1202;
    raw[610] = ((((t609*t1239 + ((t1182*t590 + (t1209*t592 + t1230*t595)) - t608*t1134)) - (t603*t1191 + t608*t1146)) + t607*t1152) + t609*t1245) + t603*t1203;
    raw[611] = t1183*t590 + (t1210*t592 + t1231*t595);
    raw[612] = t1184*t590 + (t1211*t592 + t1232*t595);
    raw[613] = t1185*t590 + (t1212*t592 + t1233*t595);
    raw[617] = ((((t609*t1240 - t608*t1147) - (t608*t1135 + t603*t1192)) + t607*t1153) + t609*t1246) + t603*t1204;
    raw[618] = ((((t609*t1241 - t608*t1148) - (t608*t1136 + t603*t1193)) + t607*t1154) + t609*t1247) + t603*t1205;
    raw[619] = ((((t609*t1242 - t608*t1149) - (t608*t1137 + t603*t1194)) + t607*t1155) + t609*t1248) + t603*t1206;
    raw[620] = t1186*t590 + (t1213*t592 + t1234*t595);
    raw[621] = t1187*t590 + (t1214*t592 + t1235*t595);
    raw[622] = t1188*t590 + (t1215*t592 + t1236*t595);
    raw[638] = t603*t590 + (t606*t592 + t609*t595);
    raw[640] = ((t610*t1150 + ((t603*t1216 - t611*t1144) + (((t1180*t596 + (t1207*t597 + t1228*t599)) - t611*t1126) - t606*t1237))) + t606*t1243) + t603*t1222;
    raw[641] = ((t610*t1151 + ((t603*t1217 - t611*t1145) + (((t1181*t596 + (t1208*t597 + t1229*t599)) - t611*t1127) - t606*t1238))) + t606*t1244) + t603*t1223;
    raw[642] = ((t610*t1152 + ((t603*t1218 - t611*t1146) + (((t1182*t596 + (t1209*t597 + t1230*t599)) - t611*t1128) - t606*t1239))) + t606*t1245) + t603*t1224;
    raw[643] = t1183*t596 + (t1210*t597 + t1231*t599);
    raw[644] = t1184*t596 + (t1211*t597 + t1232*t599);
    raw[645] = t1185*t596 + (t1212*t597 + t1233*t599);
    raw[649] = ((((t603*t1219 - t606*t1240) - (t611*t1129 + t611*t1147)) + t610*t1153) + t606*t1246) + t603*t1225;
    raw[650] = ((((t603*t1220 - t606*t1241) - (t611*t1130 + t611*t1148)) + t610*t1154) + t606*t1247) + t603*t1226;
    raw[651] = ((((t603*t1221 - t606*t1242) - (t611*t1131 + t611*t1149)) + t610*t1155) + t606*t1248) + t603*t1227;
    raw[652] = t1186*t596 + (t1213*t597 + t1234*t599);
    raw[653] = t1187*t596 + (t1214*t597 + t1235*t599);
    raw[654] = t1188*t596 + (t1215*t597 + t1236*t599);
    raw[670] = t603*t596 + (t606*t597 + t609*t599);
}

void factor_cost_3(const T in[42], const T dat[211],
                   T half[2]) {
#pragma HLS INLINE off
#pragma HLS ALLOCATION operation instances=fadd limit=8
#pragma HLS ALLOCATION operation instances=fmul limit=10
#pragma HLS ALLOCATION operation instances=fdiv limit=1
#pragma HLS ALLOCATION operation instances=fsqrt limit=1
    const T t0 = in[6]*in[21] + (in[0]*in[15] + in[3]*in[18]);
    const T t1 = t0;
    const T t2 = in[7]*in[21] + (in[1]*in[15] + in[4]*in[18]);
    const T t3 = t2;
    const T t4 = in[8]*in[21] + (in[2]*in[15] + in[5]*in[18]);
    const T t5 = t4;
    const T t6 = dat[79]*t5 + (dat[73]*t1 + dat[76]*t3);
    const T t7 = in[6]*in[22] + (in[0]*in[16] + in[3]*in[19]);
    const T t8 = t7;
    const T t9 = in[7]*in[22] + (in[1]*in[16] + in[4]*in[19]);
    const T t10 = t9;
    const T t11 = in[8]*in[22] + (in[2]*in[16] + in[5]*in[19]);
    const T t12 = t11;
    const T t13 = dat[79]*t12 + (dat[73]*t8 + dat[76]*t10);
    const T t14 = in[6]*in[23] + (in[0]*in[17] + in[3]*in[20]);
    const T t15 = t14;
    const T t16 = in[7]*in[23] + (in[1]*in[17] + in[4]*in[20]);
    const T t17 = t16;
    const T t18 = in[8]*in[23] + (in[2]*in[17] + in[5]*in[20]);
    const T t19 = t18;
    const T t20 = dat[79]*t19 + (dat[73]*t15 + dat[76]*t17);
    const T t21 = dat[80]*t5 + (dat[74]*t1 + dat[77]*t3);
    const T t22 = dat[80]*t12 + (dat[74]*t8 + dat[77]*t10);
    const T t23 = dat[80]*t19 + (dat[74]*t15 + dat[77]*t17);
    const T t24 = dat[81]*t5 + (dat[75]*t1 + dat[78]*t3);
    const T t25 = dat[81]*t12 + (dat[75]*t8 + dat[78]*t10);
    const T t26 = dat[81]*t19 + (dat[75]*t15 + dat[78]*t17);
    T tlog0[3]; so3_log(t6, t13, t20, t21, t22, t23, t24, t25, t26, tlog0);
    const T t27 = tlog0[0];
    const T t28 = (t27*t27);
    const T t29 = tlog0[1];
    const T t30 = (t29*t29);
    const T t31 = tlog0[2];
    const T t32 = (t31*t31);
    const T t33 = in[30] - dat[63];
    const T t34 = in[31] - dat[64];
    const T t35 = in[32] - dat[65];
    const T t36 = in[33] - dat[66];
    const T t37 = in[34] - dat[67];
    const T t38 = in[35] - dat[68];
    const T t39 = (dat[41]*t38 + (dat[1] + dat[12]*t33)) + ((dat[13]*t34 + dat[14]*t35) + (dat[39]*t36 + dat[40]*t37));
    const T t40 = -t39;
    const T t41 = t39*t40;
    const T t42 = (dat[44]*t38 + (dat[2] + dat[15]*t33)) + ((dat[16]*t34 + dat[17]*t35) + (dat[42]*t36 + dat[43]*t37));
    const T t43 = -t42;
    const T t44 = t43*t42;
    const T t45 = t44 + t41;
    const T t46 = (dat[38]*t38 + (dat[0] + dat[9]*t33)) + ((dat[10]*t34 + dat[11]*t35) + (dat[36]*t36 + dat[37]*t37));
    const T t47 = (t42*t42) + ((t46*t46) + (t39*t39));
    const T t48 = lie_B(t47);
    const T t49 = T(1) + t45*t48;
    const T t50 = -t46;
    const T t51 = lie_A(t47);
    const T t52 = t40*t48;
    const T t53 = t42*t51 + t50*t52;
    const T t54 = t46*t48;
    const T t55 = t40*t51 + t42*t54;
    const T t56 = t5*t55 + (t1*t49 + t3*t53);
    const T t57 = t46*t50;
    const T t58 = t44 + t57;
    const T t59 = T(1) + t58*t48;
    const T t60 = t46*t51 + t43*t52;
    const T t61 = t43*t51 + t39*t54;
    const T t62 = t5*t60 + (t3*t59 + t1*t61);
    const T t63 = t57 + t41;
    const T t64 = T(1) + t63*t48;
    const T t65 = t43*t48;
    const T t66 = t39*t51 + t50*t65;
    const T t67 = t39*t48;
    const T t68 = t50*t51 + t42*t67;
    const T t69 = t3*t68 + (t5*t64 + t1*t66);
    const T t70 = t12*t55 + (t8*t49 + t10*t53);
    const T t71 = t8*t61 + (t10*t59 + t12*t60);
    const T t72 = t10*t68 + (t12*t64 + t8*t66);
    const T t73 = t19*t55 + (t15*t49 + t17*t53);
    const T t74 = t15*t61 + (t17*t59 + t19*t60);
    const T t75 = t17*t68 + (t19*t64 + t15*t66);
    T tlog1[3]; so3_log(t56, t62, t69, t70, t71, t72, t73, t74, t75, tlog1);
    const T t76 = tlog1[1];
    const T t77 = (t76*t76);
    const T t78 = t77;
    const T t79 = tlog1[2];
    const T t80 = (t79*t79);
    const T t81 = t80;
    const T t82 = t78 + t81;
    const T t83 = tlog1[0];
    const T t84 = (t83*t83);
    const T t85 = t84;
    const T t86 = t85 + t82;
    const T t87 = lie_D(t86);
    const T t88 = T(1) - t82*t87;
    const T t89 = in[9] - in[24];
    const T t90 = (dat[47]*t38 + (dat[3] + dat[18]*t33)) + ((dat[19]*t34 + dat[20]*t35) + (dat[45]*t36 + dat[46]*t37));
    const T t91 = (dat[50]*t38 + (dat[4] + dat[21]*t33)) + ((dat[22]*t34 + dat[23]*t35) + (dat[48]*t36 + dat[49]*t37));
    const T t92 = (dat[53]*t38 + (dat[5] + dat[24]*t33)) + ((dat[25]*t34 + dat[26]*t35) + (dat[51]*t36 + dat[52]*t37));
    const T t93 = (T(0.5))*(dat[69]*dat[69]);
    const T t94 = (((dat[69]*in[12] + t89) + dat[70]*t93) + in[0]*t90) + (in[1]*t91 + in[2]*t92);
    const T t95 = in[10] - in[25];
    const T t96 = (((dat[69]*in[13] + t95) + dat[71]*t93) + in[3]*t90) + (in[4]*t91 + in[5]*t92);
    const T t97 = in[11] - in[26];
    const T t98 = (((dat[69]*in[14] + t97) + dat[72]*t93) + in[6]*t90) + (in[7]*t91 + in[8]*t92);
    const T t99 = in[21]*t98 + (in[15]*t94 + in[18]*t96);
    const T t100 = t99;
    const T t101 = (T(0.5))*t79;
    const T t102 = t101;
    const T t103 = t83*t87;
    const T t104 = t76*t103;
    const T t105 = t102 + t104;
    const T t106 = in[22]*t98 + (in[16]*t94 + in[19]*t96);
    const T t107 = t106;
    const T t108 = (T(0.5))*t76;
    const T t109 = t108;
    const T t110 = t79*t103;
    const T t111 = t110 - t109;
    const T t112 = in[23]*t98 + (in[17]*t94 + in[20]*t96);
    const T t113 = t112;
    const T t114 = t113*t111 + (t100*t88 + t107*t105);
    const T t115 = -(t81 + t85);
    const T t116 = T(1) + t115*t87;
    const T t117 = (T(0.5))*t83;
    const T t118 = t117;
    const T t119 = t76*t79;
    const T t120 = t119*t87;
    const T t121 = t118 + t120;
    const T t122 = t104 - t102;
    const T t123 = t100*t122 + (t107*t116 + t113*t121);
    const T t124 = -(t78 + t85);
    const T t125 = T(1) + t124*t87;
    const T t126 = t109 + t110;
    const T t127 = t120 - t118;
    const T t128 = t100*t126 + (t107*t127 + t113*t125);
    const T t129 = (dat[56]*t38 + (dat[6] + dat[27]*t33)) + ((dat[28]*t34 + dat[29]*t35) + (dat[54]*t36 + dat[55]*t37));
    const T t130 = (dat[59]*t38 + (dat[7] + dat[30]*t33)) + ((dat[31]*t34 + dat[32]*t35) + (dat[57]*t36 + dat[58]*t37));
    const T t131 = (dat[62]*t38 + (dat[8] + dat[33]*t33)) + ((dat[34]*t34 + dat[35]*t35) + (dat[60]*t36 + dat[61]*t37));
    const T t132 = ((dat[69]*dat[70] + (in[12] - in[27])) + in[0]*t129) + (in[1]*t130 + in[2]*t131);
    const T t133 = ((dat[69]*dat[71] + (in[13] - in[28])) + in[3]*t129) + (in[4]*t130 + in[5]*t131);
    const T t134 = ((dat[69]*dat[72] + (in[14] - in[29])) + in[6]*t129) + (in[7]*t130 + in[8]*t131);
    const T t135 = in[21]*t134 + (in[15]*t132 + in[18]*t133);
    const T t136 = t135;
    const T t137 = in[22]*t134 + (in[16]*t132 + in[19]*t133);
    const T t138 = t137;
    const T t139 = in[23]*t134 + (in[17]*t132 + in[20]*t133);
    const T t140 = t139;
    const T t141 = t140*t111 + (t136*t88 + t138*t105);
    const T t142 = t136*t122 + (t138*t116 + t140*t121);
    const T t143 = t136*t126 + (t140*t125 + t138*t127);
    const T t144 = in[30] - in[36];
    const T t145 = in[31] - in[37];
    const T t146 = in[32] - in[38];
    const T t147 = in[33] - in[39];
    const T t148 = in[34] - in[40];
    const T t149 = in[35] - in[41];
    const T t150 = t30;
    const T t151 = t150;
    const T t152 = t32;
    const T t153 = t152;
    const T t154 = t151 + t153;
    const T t155 = t28;
    const T t156 = t155;
    const T t157 = t156 + t154;
    const T t158 = lie_D(t157);
    const T t159 = T(1) - t154*t158;
    const T t160 = (T(0.5))*t31;
    const T t161 = t160;
    const T t162 = t27*t158;
    const T t163 = t29*t162;
    const T t164 = t161 + t163;
    const T t165 = (T(0.5))*t29;
    const T t166 = t165;
    const T t167 = t31*t162;
    const T t168 = t167 - t166;
    const T t169 = (in[6]*in[26] - in[6]*in[11]) + ((in[0]*in[24] - in[0]*in[9]) + (in[3]*in[25] - in[3]*in[10]));
    const T t170 = (in[7]*in[26] - in[7]*in[11]) + ((in[1]*in[24] - in[1]*in[9]) + (in[4]*in[25] - in[4]*in[10]));
    const T t171 = (in[8]*in[26] - in[8]*in[11]) + ((in[2]*in[24] - in[2]*in[9]) + (in[5]*in[25] - in[5]*in[10]));
    const T t172 = (dat[73]*t169 - (dat[79]*dat[84] + (dat[73]*dat[82] + dat[76]*dat[83]))) + (dat[76]*t170 + dat[79]*t171);
    const T t173 = (dat[74]*t169 - (dat[80]*dat[84] + (dat[74]*dat[82] + dat[77]*dat[83]))) + (dat[77]*t170 + dat[80]*t171);
    const T t174 = (dat[75]*t169 - (dat[81]*dat[84] + (dat[75]*dat[82] + dat[78]*dat[83]))) + (dat[78]*t170 + dat[81]*t171);
    const T t175 = t174*t168 + (t172*t159 + t173*t164);
    const T t176 = t163 - t161;
    const T t177 = -(t153 + t156);
    const T t178 = T(1) + t177*t158;
    const T t179 = (T(0.5))*t27;
    const T t180 = t179;
    const T t181 = t29*t31;
    const T t182 = t181*t158;
    const T t183 = t180 + t182;
    const T t184 = t172*t176 + (t173*t178 + t174*t183);
    const T t185 = t166 + t167;
    const T t186 = t182 - t180;
    const T t187 = -(t151 + t156);
    const T t188 = T(1) + t187*t158;
    const T t189 = t172*t185 + (t173*t186 + t174*t188);
    const T t190 = (((T(0.5))*(((((dat[167]*t148 + dat[168]*t149) + ((dat[163]*t144 + dat[164]*t145) + (dat[165]*t146 + dat[166]*t147))) + dat[161]*t142) + (dat[162]*t143 + dat[160]*t141))*((((dat[167]*t148 + dat[168]*t149) + ((dat[163]*t144 + dat[164]*t145) + (dat[165]*t146 + dat[166]*t147))) + dat[161]*t142) + (dat[162]*t143 + dat[160]*t141))) + (T(0.5))*(((dat[152]*t142 + dat[153]*t143) + (dat[151]*t141 + (((dat[158]*t148 + dat[159]*t149) + ((dat[154]*t144 + dat[155]*t145) + (dat[156]*t146 + dat[157]*t147))) + dat[150]*t128)))*((dat[152]*t142 + dat[153]*t143) + (dat[151]*t141 + (((dat[158]*t148 + dat[159]*t149) + ((dat[154]*t144 + dat[155]*t145) + (dat[156]*t146 + dat[157]*t147))) + dat[150]*t128))))) + ((T(0.5))*(((dat[143]*t143 + dat[141]*t141) + ((((dat[148]*t148 + dat[149]*t149) + ((dat[144]*t144 + dat[145]*t145) + (dat[146]*t146 + dat[147]*t147))) + dat[139]*t123) + (dat[140]*t128 + dat[142]*t142)))*((dat[143]*t143 + dat[141]*t141) + ((((dat[148]*t148 + dat[149]*t149) + ((dat[144]*t144 + dat[145]*t145) + (dat[146]*t146 + dat[147]*t147))) + dat[139]*t123) + (dat[140]*t128 + dat[142]*t142)))) + ((T(0.5))*((dat[170]*t143 + (((dat[175]*t148 + dat[176]*t149) + ((dat[171]*t144 + dat[172]*t145) + (dat[173]*t146 + dat[174]*t147))) + dat[169]*t142))*(dat[170]*t143 + (((dat[175]*t148 + dat[176]*t149) + ((dat[171]*t144 + dat[172]*t145) + (dat[173]*t146 + dat[174]*t147))) + dat[169]*t142))) + ((((((T(0.5))*(dat[204]*dat[204]))*(t149*t149) + (T(0.5))*((dat[202]*t148 + dat[203]*t149)*(dat[202]*t148 + dat[203]*t149))) + (T(0.5))*(((dat[192]*t147 + dat[193]*t148) + (dat[194]*t149 + (dat[190]*t145 + dat[191]*t146)))*((dat[192]*t147 + dat[193]*t148) + (dat[194]*t149 + (dat[190]*t145 + dat[191]*t146))))) + ((T(0.5))*(((dat[188]*t148 + dat[189]*t149) + ((dat[184]*t144 + dat[185]*t145) + (dat[186]*t146 + dat[187]*t147)))*((dat[188]*t148 + dat[189]*t149) + ((dat[184]*t144 + dat[185]*t145) + (dat[186]*t146 + dat[187]*t147)))) + ((T(0.5))*((dat[201]*t149 + (dat[199]*t147 + dat[200]*t148))*(dat[201]*t149 + (dat[199]*t147 + dat[200]*t148))) + (T(0.5))*(((dat[195]*t146 + dat[196]*t147) + (dat[197]*t148 + dat[198]*t149))*((dat[195]*t146 + dat[196]*t147) + (dat[197]*t148 + dat[198]*t149)))))) + (T(0.5))*((((dat[182]*t148 + dat[183]*t149) + ((dat[178]*t144 + dat[179]*t145) + (dat[180]*t146 + dat[181]*t147))) + dat[177]*t143)*(((dat[182]*t148 + dat[183]*t149) + ((dat[178]*t144 + dat[179]*t145) + (dat[180]*t146 + dat[181]*t147))) + dat[177]*t143)))))) + (((T(0.5))*(((dat[130]*t141 + (((dat[137]*t148 + dat[138]*t149) + ((dat[133]*t144 + dat[134]*t145) + (dat[135]*t146 + dat[136]*t147))) + dat[128]*t123)) + ((dat[129]*t128 + dat[131]*t142) + (dat[132]*t143 + dat[127]*t114)))*((dat[130]*t141 + (((dat[137]*t148 + dat[138]*t149) + ((dat[133]*t144 + dat[134]*t145) + (dat[135]*t146 + dat[136]*t147))) + dat[128]*t123)) + ((dat[129]*t128 + dat[131]*t142) + (dat[132]*t143 + dat[127]*t114)))) + (T(0.5))*(((dat[118]*t141 + ((((dat[125]*t148 + dat[126]*t149) + ((dat[121]*t144 + dat[122]*t145) + (dat[123]*t146 + dat[124]*t147))) + dat[114]*t79) + dat[116]*t123)) + ((dat[117]*t128 + dat[119]*t142) + (dat[120]*t143 + dat[115]*t114)))*((dat[118]*t141 + ((((dat[125]*t148 + dat[126]*t149) + ((dat[121]*t144 + dat[122]*t145) + (dat[123]*t146 + dat[124]*t147))) + dat[114]*t79) + dat[116]*t123)) + ((dat[117]*t128 + dat[119]*t142) + (dat[120]*t143 + dat[115]*t114))))) + ((T(0.5))*(((dat[105]*t141 + ((dat[101]*t79 + (((dat[112]*t148 + dat[113]*t149) + ((dat[108]*t144 + dat[109]*t145) + (dat[110]*t146 + dat[111]*t147))) + dat[100]*t76)) + dat[103]*t123)) + ((dat[104]*t128 + dat[106]*t142) + (dat[107]*t143 + dat[102]*t114)))*((dat[105]*t141 + ((dat[101]*t79 + (((dat[112]*t148 + dat[113]*t149) + ((dat[108]*t144 + dat[109]*t145) + (dat[110]*t146 + dat[111]*t147))) + dat[100]*t76)) + dat[103]*t123)) + ((dat[104]*t128 + dat[106]*t142) + (dat[107]*t143 + dat[102]*t114)))) + (T(0.5))*(((dat[91]*t141 + (((((dat[98]*t148 + dat[99]*t149) + ((dat[94]*t144 + dat[95]*t145) + (dat[96]*t146 + dat[97]*t147))) + dat[85]*t83) + (dat[86]*t76 + dat[87]*t79)) + dat[89]*t123)) + ((dat[90]*t128 + dat[92]*t142) + (dat[93]*t143 + dat[88]*t114)))*((dat[91]*t141 + (((((dat[98]*t148 + dat[99]*t149) + ((dat[94]*t144 + dat[95]*t145) + (dat[96]*t146 + dat[97]*t147))) + dat[85]*t83) + (dat[86]*t76 + dat[87]*t79)) + dat[89]*t123)) + ((dat[90]*t128 + dat[92]*t142) + (dat[93]*t143 + dat[88]*t114))))));
    const T t191 = ((((T(0.5))*(dat[207]*dat[207]))*t32 + (((T(0.5))*(dat[205]*dat[205]))*t28 + ((T(0.5))*(dat[206]*dat[206]))*t30)) + ((T(0.5))*(dat[209]*dat[209]))*(t184*t184)) + (((T(0.5))*(dat[210]*dat[210]))*(t189*t189) + ((T(0.5))*(dat[208]*dat[208]))*(t175*t175));
    half[0] = t190;
    half[1] = t191;
}

// block 4: GPSFactor (3 rows, 6 columns, 8 instances)
void factor_4(const T in[12], const T dat[4],
              T raw[24]) {
#pragma HLS INLINE
    raw[3] = in[0];
    raw[4] = in[1];
    raw[5] = in[2];
    raw[6] = in[9] - dat[0];
    raw[11] = in[3];
    raw[12] = in[4];
    raw[13] = in[5];
    raw[14] = in[10] - dat[1];
    raw[19] = in[6];
    raw[20] = in[7];
    raw[21] = in[8];
    raw[22] = in[11] - dat[2];
}

void factor_cost_4(const T in[12], const T dat[4],
                   T half[1]) {
#pragma HLS INLINE
    const T t0 = in[9] - dat[0];
    const T t1 = in[10] - dat[1];
    const T t2 = in[11] - dat[2];
    const T t3 = (T(0.5))*(dat[3]*dat[3]);
    const T t4 = t3*(t2*t2) + (t3*(t0*t0) + t3*(t1*t1));
    half[0] = t4;
}

// Rows [J | r] of one member (row stride STRIDE, right-hand side in column COLS - 1) ->
// W * [J | -r] in `ab`: W is 1/sigma (KIND 0), 1/sigma_i (1) or the upper-triangular
// square-root information R (2, parameters row-major). KIND 2 sums only rows j < DENSE: the rows
// after hold just 0 and +-1 left of the right-hand side, and the member's whiten_tail adds their
// share after this, in the same row order. Constant trip counts: unrolled in the pipelined
// instance loop.
template <int STRIDE, int COLS, int ROWS, int KIND, int DENSE>
void whiten(T raw[], T ab[], const T p[]) {
    for (int i = 0; i < ROWS; ++i) raw[i * STRIDE + COLS - 1] = -raw[i * STRIDE + COLS - 1];
    for (int i = 0; i < ROWS; ++i) {
        if (KIND == 2) {  // row i = sum over j >= i of R_ij row j
            const int base = i * ROWS - (i * (i - 1)) / 2 - i;
            T acc[STRIDE];
            for (int c = 0; c < STRIDE; ++c) acc[c] = i < DENSE ? T(raw[i * STRIDE + c] * p[base + i]) : T(0);
            for (int j = i + 1; j < DENSE; ++j) {
                const T rij = p[base + j];
                for (int c = 0; c < STRIDE; ++c) acc[c] += rij * raw[j * STRIDE + c];
            }
            for (int c = 0; c < STRIDE; ++c) ab[i * STRIDE + c] = acc[c];
        } else {
            const T s = KIND == 1 ? p[i] : p[0];
            for (int c = 0; c < STRIDE; ++c) ab[i * STRIDE + c] = raw[i * STRIDE + c] * s;
        }
    }
}

// The cost's rounding noise: row r of whitened [A | b] (rows of stride, b in column cols - 1)
// moves by up to m_r = eps * sum_c |A_rc| scale_c when x is rounded to T, so the cost by
// |b_r| m_r + m_r^2 / 2. Each row's sum in TILE partial sums, then the rows' terms in TILE
// partial sums: a fixed order, and no chain from row to row. One module for every block type
// (rounding_noise_all's ALLOCATION; each noise_<b> INLINE there): the block's sizes are
// run-time arguments, the widest block type's at compile time (NOISE_*), so a row takes
// NOISE_ROW_II = NOISE_STRIDE + 3 cycles whatever its width: the widest row's NOISE_STRIDE + 1
// products share one multiplier and its NOISE_STRIDE + 3 adds one adder, a narrower row's
// columns past its stride add zero (the rejected step's pass is rare: parallelism there does
// not pay).
const int NOISE_STRIDE = 32;  // the widest block type's padded row
const int NOISE_AB = 672;  // the largest block type's padded rows
const int NOISE_ROWS = 21;  // the most rows of a block type
const int NOISE_ROW_II = NOISE_STRIDE + 3;
T rounding_noise(const T ab[NOISE_AB], const T scale[NOISE_STRIDE], int stride, int cols, int rows) {
    T moved[NOISE_ROWS], b_abs[NOISE_ROWS];
    for (int r = 0; r < rows; ++r) {
#pragma HLS LOOP_TRIPCOUNT max=NOISE_ROWS
#pragma HLS PIPELINE II=NOISE_ROW_II
        T part[TILE];
        for (int t = 0; t < TILE; ++t) part[t] = T(0);
        for (int c0 = 0; c0 < NOISE_STRIDE; c0 += TILE) {
            for (int t = 0; t < TILE; ++t) {
                if (c0 + t < stride) part[t] += fgc_abs(ab[r * stride + c0 + t]) * scale[c0 + t];
            }
        }
        moved[r] = EPSILON * ((part[0] + part[1]) + (part[2] + part[3]));  // scale 0: b, padding
        b_abs[r] = fgc_abs(ab[r * stride + cols - 1]);
    }
    T sum[TILE];
    for (int t = 0; t < TILE; ++t) sum[t] = T(0);
    for (int r0 = 0; r0 < rows; r0 += TILE) {  // TILE rows a step: the sums' recurrence sets the II
#pragma HLS LOOP_TRIPCOUNT max=6
#pragma HLS PIPELINE II=12
        for (int t = 0; t < TILE; ++t) {
            if (r0 + t < rows) {
                const T m = moved[r0 + t];
                sum[t] += b_abs[r0 + t] * m + T(0.5) * m * m;
            }
        }
    }
    return (sum[0] + sum[1]) + (sum[2] + sum[3]);
}

// Whitened rows [A | b] of one instance, as its datapath streams them (`grad`, PORTS words a
// stream word: evaluate_<b> writes them beside its rows into AB) -> the local gradient A^T b
// (column c into G[col[c]]). One module for every block type (reduce_all's ALLOCATION; each
// reduce_<b> INLINE there): the block's sizes are run-time arguments, the largest block type's
// at compile time (GRAD_*). A row comes as stride / PORTS words, the group holding b (column
// cols - 1) first and the others after it in turn, so b is in a register before its row's first
// product: PORTS columns of a row a cycle (PORTS multipliers and adders; columns past the row's
// `cols` are zero), rows x stride / PORTS iterations of one flattened loop reading a word each;
// row r goes into partial sum r % T_PARTIALS of its columns, so an accumulator comes back
// T_PARTIALS * stride / PORTS iterations later, at least GRAD_DIST (the narrowest block type's;
// the DEPENDENCE's distance, at least the adder's latency). Then a column a cycle: its partial
// sums folded and added into G (the columns' entries are distinct: II 1). False if an entry is
// infinite or NaN. (AB is not read again: the rows pass once, from the datapath.)
// The right-hand side's own column (b^T b, its ||W r||^2) comes out of the same scatter, one
// iteration more, into `sq` through the same adder (LM's cost at X from the linearisation:
// fgc_lm.h's FGC_LM_COST_IN_LINEARIZE).
struct GradWord { T v[PORTS]; };
const int GRAD_STRIDE = 32;  // the widest block type's padded row
const int GRAD_ROWS = 21;  // the most rows of a block type
const int GRAD_COLS = 30;  // the most columns of a block type (its tangent entries)
const int GRAD_GROUPS = 336;  // the most PORTS groups of a block type's padded rows
const int GRAD_DIST = 8;  // T_PARTIALS x the narrowest padded row / PORTS
const int GRAD_DEPTH = GRAD_GROUPS;  // the rows stream: one instance's words of the largest block type

// one whitened row (ab: padded to STRIDE columns, COLS of them [A | b]) to the gradient's
// stream, b's group first (accumulate's order); unrolled in the datapath's pipelined loop
template <int STRIDE, int COLS>
void grad_row(const T* ab, hls::stream<GradWord>& grad) {
#pragma HLS INLINE
    for (int j = 0; j < STRIDE / PORTS; ++j) {
        const int g = (COLS - 1) / PORTS + j < STRIDE / PORTS ? (COLS - 1) / PORTS + j
                                                               : (COLS - 1) / PORTS + j - STRIDE / PORTS;
        GradWord w;
        for (int t = 0; t < PORTS; ++t) w.v[t] = g * PORTS + t < COLS ? ab[g * PORTS + t] : T(0);
        grad.write(w);
    }
}

bool accumulate(hls::stream<GradWord>& grad, const int col[GRAD_COLS], int stride, int cols, int rows, T& sq) {
    T g[T_PARTIALS][GRAD_STRIDE];
#pragma HLS ARRAY_PARTITION variable=g complete dim=0
    for (int t = 0; t < T_PARTIALS; ++t) {
#pragma HLS UNROLL
        for (int c = 0; c < GRAD_STRIDE; ++c) {
#pragma HLS UNROLL
            g[t][c] = T(0);
        }
    }
    const int groups = stride / PORTS, gb = (cols - 1) / PORTS, hb = (cols - 1) % PORTS;
    bool finite = true;
    T b = T(0);  // the row's right-hand side (its first word's)
    int j = 0, p = 0;  // the word of the row, the row's partial sum (r % T_PARTIALS)
    for (int i = 0; i < rows * groups; ++i) {
#pragma HLS LOOP_TRIPCOUNT max=GRAD_GROUPS
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=g inter true distance=GRAD_DIST
        const GradWord w = grad.read();
        const int grp = gb + j < groups ? gb + j : gb + j - groups;
        const T bj = j == 0 ? w.v[hb] : b;
        for (int t = 0; t < PORTS; ++t) {
            const int c = grp * PORTS + t;
            const T a = c < cols ? w.v[t] : T(0);
            g[p][c] += a * bj;
            finite = finite && fgc_isfinite(a);
        }
        b = bj;
        if (j + 1 == groups) {
            j = 0;
            p = p + 1 == T_PARTIALS ? 0 : p + 1;
        } else {
            ++j;
        }
    }
    for (int c = 0; c < cols; ++c) {  // a column a cycle: its partial sums folded, into G (b's: into sq)
#pragma HLS LOOP_TRIPCOUNT max=GRAD_COLS+1
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=G inter false
        T pg[T_PARTIALS];
        for (int t = 0; t < T_PARTIALS; ++t) pg[t] = g[t][c];
        const bool rhs = c == cols - 1;
        const T v = (rhs ? sq : G[col[c]]) + fgc_units::fold_partials<T, T_PARTIALS>(pg);
        if (rhs) {
            sq = v;
        } else {
            G[col[c]] = v;
        }
    }
    return finite;
}

// gather_<b>: block b's inputs of instance f (x's storage, then its measurements and noise)
// gather_trial_<b>: the same for trial_cost (DATA_BUF cyclic 2 there): the line's words read
// from the even address below it, 2 h + lo + i (h the line's half, lo the block's first data
// word), so each read's bank is known and an instance's reads (w's words) take the two banks'
// four ports; into registers (w), its data picked from them by the line's parity (2:1 muxes;
// units/datapath.py's trial_data_ii)
void gather_0(const T x[N_X], int f, T in[12], T dat[18]) {
    const int vb = FACTOR_VAR_BEGIN[f];
    const int line = FACTOR_DATA_OFF[f];
    for (int i = 0; i < 12; ++i) in[0 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 0]] + i];
    for (int i = 0; i < 12; ++i) dat[0 + i] = DATA_BUF[line + 0 + i];
    for (int i = 0; i < 6; ++i) dat[12 + i] = DATA_BUF[line + 12 + i];
}

void gather_trial_0(const T x[N_X], int f, T in[12], T dat[18]) {
    const int vb = FACTOR_VAR_BEGIN[f];
    const int line = FACTOR_DATA_OFF[f], h = line >> 1, p = line & 1;
    for (int i = 0; i < 12; ++i) in[0 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 0]] + i];
    T w[19];  // DATA_BUF[2 h + 0 ...]: the line's words from 0 at w[p ...]
#pragma HLS ARRAY_PARTITION variable=w complete
    for (int i = 0; i < 18; ++i) w[i] = DATA_BUF[2 * h + 0 + i];
    w[18] = p ? DATA_BUF[2 * h + 18] : T(0);  // an odd line's last word
    for (int i = 0; i < 12; ++i) dat[0 + i] = p ? w[1 + i] : w[0 + i];
    for (int i = 0; i < 6; ++i) dat[12 + i] = p ? w[13 + i] : w[12 + i];
}

// block 0, Jacobian mode: per instance residual + Jacobian (its 33 structural non-zeros of
// 6 x 7), whitening, into AB; one instance every II=111 cycles (the plan's)
void evaluate_0(const T x[N_X], hls::stream<GradWord>& grad) {
    for (int i = 0; i < 1; ++i) {
#pragma HLS PIPELINE II=111
        const int f = BLOCK0_INSTANCES[i];
        T in[12], dat[18];
        gather_0(x, f, in, dat);
        T raw[48];  // the Jacobian writes only its structural non-zeros
        T ab[48];
        for (int c = 0; c < 48; ++c) raw[c] = T(0);
        factor_0(in, dat, raw);
        whiten<8, 7, 6, 1, 6>(raw + 0, ab + 0, dat + 12);
        const int a0 = FACTOR_A_OFF[f];
        for (int r = 0; r < 6; ++r) {
            for (int c = 0; c < 7; ++c) AB[a0 + r * 7 + c] = ab[r * 8 + c];
        }
        // and beside AB, to the gradient (reduce_all, the same DATAFLOW region): 24 stream words
        for (int r = 0; r < 6; ++r) grad_row<8, 7>(ab + r * 8, grad);
    }
    // (one process of linearize_rows' region: the datapaths one after another)
    FGC_CYCLES("datapaths", 0, "factor_0_jacobian", 1, 111, 416);
}

// block 0's whitened rows of instance f from AB, padded to 8 columns (a multiple of PORTS)
void load_rows_0(int f, T ab[48]) {
    const int a0 = FACTOR_A_OFF[f];
    for (int e = 0; e < 48; e += PORTS) {  // PORTS words a cycle
#pragma HLS PIPELINE II=1
        for (int h = 0; h < PORTS; ++h) {
            const int r = (e + h) / 8, c = (e + h) % 8;
            ab[e + h] = c < 7 ? T(AB[a0 + r * 7 + c]) : T(0);
        }
    }
}

// block 0: the gradient of each instance from the datapath's stream; false if not
// finite. INLINE into reduce_all, whose ALLOCATION makes every block type's accumulate one module
bool reduce_0(hls::stream<GradWord>& grad, T& sq) {
#pragma HLS INLINE
    bool finite = true;
    for (int i = 0; i < 1; ++i) {
        const int f = BLOCK0_INSTANCES[i];
        const int vb = FACTOR_VAR_BEGIN[f];
        int col[GRAD_COLS];  // per column: its tangent entry
        for (int j = 0; j < 6; ++j) col[0 + j] = VAR_T_OFF[FACTOR_VARS[vb + 0]] + j;
        finite = accumulate(grad, col, 8, 7, 6, sq) && finite;
        // column map, A^T b PORTS columns a cycle from the stream (a dot product of m rows x
        // STRIDE / PORTS groups: the plan's rule), the scatter into G
        FGC_CYCLES("gradient", 0, "reduce_0_columns", 6, 1, 1);
        if (i == 0) FGC_WAIT("gradient", 0, "datapaths", 0, "factor_0_jacobian");
        FGC_CYCLES("gradient", 0, "reduce_0_rows", 24, fgc_units::dot_ii(24, T_PARTIALS, T_ADD_LAT),
                   fgc_units::dot_depth(24, T_PARTIALS, T_ADD_LAT, T_MUL_LAT));
        FGC_CYCLES("gradient", 0, "reduce_0_scatter", 7, 1, 6 + T_ADD_LAT * fgc_units::ceil_log2(T_PARTIALS));
    }
    return finite;
}

// block 0: `noise` plus the cost's rounding noise of its instances at the linearisation point (from AB);
// INLINE: the block types' running sums land in rounding_noise_all's body, one after another, so
// they share its one adder, and its ALLOCATION makes their rounding_noise calls one module
T noise_0(T noise, T ab[NOISE_AB]) {
#pragma HLS INLINE
    for (int i = 0; i < 1; ++i) {
        const int f = BLOCK0_INSTANCES[i];
        const int vb = FACTOR_VAR_BEGIN[f];
        load_rows_0(f, ab);  // into rounding_noise_all's one row buffer
        T scale[NOISE_STRIDE];  // per column: largest storage entry of its variable (0: b, padding)
        for (int c = 0; c < 8; ++c) scale[c] = T(0);
        for (int j = 0; j < 6; ++j) scale[0 + j] = VAR_SCALE[FACTOR_VARS[vb + 0]];
        noise += rounding_noise(ab, scale, 8, 7, 6);
        FGC_CYCLES("noise_0", 0, "load", 24, 1, 2);
        FGC_CYCLES("noise_0", 0, "scales", 8, 1, 1);
        FGC_CYCLES("noise_0", 0, "rows", 6, 35, 49);
        FGC_CYCLES("noise_0", 0, "terms", 2, 12, 25);
    }
    return noise;
}

void gather_1(const T x[N_X], int f, T in[3], T dat[4]) {
    const int vb = FACTOR_VAR_BEGIN[f];
    const int line = FACTOR_DATA_OFF[f];
    for (int i = 0; i < 3; ++i) in[0 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 0]] + i];
    for (int i = 0; i < 3; ++i) dat[0 + i] = DATA_BUF[line + 0 + i];
    for (int i = 0; i < 1; ++i) dat[3 + i] = DATA_BUF[line + 3 + i];
}


// block 1's whitened rows of instance f from AB, padded to 4 columns (a multiple of PORTS)
void load_rows_1(int f, T ab[12]) {
    const int a0 = FACTOR_A_OFF[f];
    for (int e = 0; e < 12; e += PORTS) {  // PORTS words a cycle
#pragma HLS PIPELINE II=1
        for (int h = 0; h < PORTS; ++h) {
            const int r = (e + h) / 4, c = (e + h) % 4;
            ab[e + h] = c < 4 ? T(AB[a0 + r * 4 + c]) : T(0);
        }
    }
}

// block 1: the gradient of each instance from the datapath's stream; false if not
// finite. INLINE into reduce_all, whose ALLOCATION makes every block type's accumulate one module
// block 1: `noise` plus the cost's rounding noise of its instances at the linearisation point (from AB);
// INLINE: the block types' running sums land in rounding_noise_all's body, one after another, so
// they share its one adder, and its ALLOCATION makes their rounding_noise calls one module
T noise_1(T noise, T ab[NOISE_AB]) {
#pragma HLS INLINE
    for (int i = 0; i < 1; ++i) {
        const int f = BLOCK1_INSTANCES[i];
        const int vb = FACTOR_VAR_BEGIN[f];
        load_rows_1(f, ab);  // into rounding_noise_all's one row buffer
        T scale[NOISE_STRIDE];  // per column: largest storage entry of its variable (0: b, padding)
        for (int c = 0; c < 4; ++c) scale[c] = T(0);
        for (int j = 0; j < 3; ++j) scale[0 + j] = VAR_SCALE[FACTOR_VARS[vb + 0]];
        noise += rounding_noise(ab, scale, 4, 4, 3);
        FGC_CYCLES("noise_1", 0, "load", 6, 1, 2);
        FGC_CYCLES("noise_1", 0, "scales", 4, 1, 1);
        FGC_CYCLES("noise_1", 0, "rows", 3, 35, 49);
        FGC_CYCLES("noise_1", 0, "terms", 1, 12, 25);
    }
    return noise;
}

void gather_2(const T x[N_X], int f, T in[6], T dat[7]) {
    const int vb = FACTOR_VAR_BEGIN[f];
    const int line = FACTOR_DATA_OFF[f];
    for (int i = 0; i < 6; ++i) in[0 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 0]] + i];
    for (int i = 0; i < 6; ++i) dat[0 + i] = DATA_BUF[line + 0 + i];
    for (int i = 0; i < 1; ++i) dat[6 + i] = DATA_BUF[line + 6 + i];
}


// block 2's whitened rows of instance f from AB, padded to 8 columns (a multiple of PORTS)
void load_rows_2(int f, T ab[48]) {
    const int a0 = FACTOR_A_OFF[f];
    for (int e = 0; e < 48; e += PORTS) {  // PORTS words a cycle
#pragma HLS PIPELINE II=1
        for (int h = 0; h < PORTS; ++h) {
            const int r = (e + h) / 8, c = (e + h) % 8;
            ab[e + h] = c < 7 ? T(AB[a0 + r * 7 + c]) : T(0);
        }
    }
}

// block 2: the gradient of each instance from the datapath's stream; false if not
// finite. INLINE into reduce_all, whose ALLOCATION makes every block type's accumulate one module
// block 2: `noise` plus the cost's rounding noise of its instances at the linearisation point (from AB);
// INLINE: the block types' running sums land in rounding_noise_all's body, one after another, so
// they share its one adder, and its ALLOCATION makes their rounding_noise calls one module
T noise_2(T noise, T ab[NOISE_AB]) {
#pragma HLS INLINE
    for (int i = 0; i < 1; ++i) {
        const int f = BLOCK2_INSTANCES[i];
        const int vb = FACTOR_VAR_BEGIN[f];
        load_rows_2(f, ab);  // into rounding_noise_all's one row buffer
        T scale[NOISE_STRIDE];  // per column: largest storage entry of its variable (0: b, padding)
        for (int c = 0; c < 8; ++c) scale[c] = T(0);
        for (int j = 0; j < 6; ++j) scale[0 + j] = VAR_SCALE[FACTOR_VARS[vb + 0]];
        noise += rounding_noise(ab, scale, 8, 7, 6);
        FGC_CYCLES("noise_2", 0, "load", 24, 1, 2);
        FGC_CYCLES("noise_2", 0, "scales", 8, 1, 1);
        FGC_CYCLES("noise_2", 0, "rows", 6, 35, 49);
        FGC_CYCLES("noise_2", 0, "terms", 2, 12, 25);
    }
    return noise;
}

void gather_3(const T x[N_X], int f, T in[42], T dat[211]) {
    const int vb = FACTOR_VAR_BEGIN[f];
    const int line = FACTOR_DATA_OFF[f];
    for (int i = 0; i < 12; ++i) in[0 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 0]] + i];
    for (int i = 0; i < 3; ++i) in[12 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 1]] + i];
    for (int i = 0; i < 12; ++i) in[15 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 2]] + i];
    for (int i = 0; i < 3; ++i) in[27 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 3]] + i];
    for (int i = 0; i < 6; ++i) in[30 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 4]] + i];
    for (int i = 0; i < 6; ++i) in[36 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 5]] + i];
    for (int i = 0; i < 73; ++i) dat[0 + i] = DATA_BUF[line + 0 + i];
    for (int i = 0; i < 12; ++i) dat[73 + i] = DATA_BUF[line + 195 + i];
    for (int i = 0; i < 120; ++i) dat[85 + i] = DATA_BUF[line + 73 + i];
    for (int i = 0; i < 6; ++i) dat[205 + i] = DATA_BUF[line + 207 + i];
}

void gather_trial_3(const T x[N_X], int f, T in[42], T dat[211]) {
    const int vb = FACTOR_VAR_BEGIN[f];
    const int line = FACTOR_DATA_OFF[f], h = line >> 1, p = line & 1;
    for (int i = 0; i < 12; ++i) in[0 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 0]] + i];
    for (int i = 0; i < 3; ++i) in[12 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 1]] + i];
    for (int i = 0; i < 12; ++i) in[15 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 2]] + i];
    for (int i = 0; i < 3; ++i) in[27 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 3]] + i];
    for (int i = 0; i < 6; ++i) in[30 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 4]] + i];
    for (int i = 0; i < 6; ++i) in[36 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 5]] + i];
    T w[214];  // DATA_BUF[2 h + 0 ...]: the line's words from 0 at w[p ...]
#pragma HLS ARRAY_PARTITION variable=w complete
    for (int i = 0; i < 213; ++i) w[i] = DATA_BUF[2 * h + 0 + i];
    w[213] = p ? DATA_BUF[2 * h + 213] : T(0);  // an odd line's last word
    for (int i = 0; i < 73; ++i) dat[0 + i] = p ? w[1 + i] : w[0 + i];
    for (int i = 0; i < 12; ++i) dat[73 + i] = p ? w[196 + i] : w[195 + i];
    for (int i = 0; i < 120; ++i) dat[85 + i] = p ? w[74 + i] : w[73 + i];
    for (int i = 0; i < 6; ++i) dat[205 + i] = p ? w[208 + i] : w[207 + i];
}

// block 3, member 0: its rows 9 ... 14 of 15 hold only 0 and +-1 left of the right-hand side;
// their share of the whitened rows, row by row in order: +-R_ij at j's constant entries, R_ij b_j
void whiten_tail_3_0(const T raw[], T ab[], const T p[]) {
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

// block 3, Jacobian mode: per instance residual + Jacobian (its 240 structural non-zeros of
// 21 x 31), whitening, into AB; one instance every II=336 cycles (the plan's)
void evaluate_3(const T x[N_X], hls::stream<GradWord>& grad) {
    for (int i = 0; i < 7; ++i) {
#pragma HLS PIPELINE II=336
        const int f = BLOCK3_INSTANCES[i];
        T in[42], dat[211];
        gather_3(x, f, in, dat);
        T raw[672];  // the Jacobian writes only its structural non-zeros
        T ab[672];
        for (int c = 0; c < 672; ++c) raw[c] = T(0);
        factor_3(in, dat, raw);
        whiten<32, 31, 15, 2, 9>(raw + 0, ab + 0, dat + 85);
        whiten_tail_3_0(raw + 0, ab + 0, dat + 85);
        whiten<32, 31, 6, 1, 6>(raw + 480, ab + 480, dat + 205);
        const int a0 = FACTOR_A_OFF[f];
        for (int r = 0; r < 21; ++r) {
            for (int c = 0; c < 31; ++c) AB[a0 + r * 31 + c] = ab[r * 32 + c];
        }
        // and beside AB, to the gradient (reduce_all, the same DATAFLOW region): 336 stream words
        for (int r = 0; r < 21; ++r) grad_row<32, 31>(ab + r * 32, grad);
    }
    // (one process of linearize_rows' region: the datapaths one after another)
    FGC_CYCLES("datapaths", 0, "factor_3_jacobian", 7, 336, 621);
}

// block 3's whitened rows of instance f from AB, padded to 32 columns (a multiple of PORTS)
void load_rows_3(int f, T ab[672]) {
    const int a0 = FACTOR_A_OFF[f];
    for (int e = 0; e < 672; e += PORTS) {  // PORTS words a cycle
#pragma HLS PIPELINE II=1
        for (int h = 0; h < PORTS; ++h) {
            const int r = (e + h) / 32, c = (e + h) % 32;
            ab[e + h] = c < 31 ? T(AB[a0 + r * 31 + c]) : T(0);
        }
    }
}

// block 3: the gradient of each instance from the datapath's stream; false if not
// finite. INLINE into reduce_all, whose ALLOCATION makes every block type's accumulate one module
bool reduce_3(hls::stream<GradWord>& grad, T& sq) {
#pragma HLS INLINE
    bool finite = true;
    for (int i = 0; i < 7; ++i) {
        const int f = BLOCK3_INSTANCES[i];
        const int vb = FACTOR_VAR_BEGIN[f];
        int col[GRAD_COLS];  // per column: its tangent entry
        for (int j = 0; j < 6; ++j) col[0 + j] = VAR_T_OFF[FACTOR_VARS[vb + 0]] + j;
        for (int j = 0; j < 3; ++j) col[6 + j] = VAR_T_OFF[FACTOR_VARS[vb + 1]] + j;
        for (int j = 0; j < 6; ++j) col[9 + j] = VAR_T_OFF[FACTOR_VARS[vb + 2]] + j;
        for (int j = 0; j < 3; ++j) col[15 + j] = VAR_T_OFF[FACTOR_VARS[vb + 3]] + j;
        for (int j = 0; j < 6; ++j) col[18 + j] = VAR_T_OFF[FACTOR_VARS[vb + 4]] + j;
        for (int j = 0; j < 6; ++j) col[24 + j] = VAR_T_OFF[FACTOR_VARS[vb + 5]] + j;
        finite = accumulate(grad, col, 32, 31, 21, sq) && finite;
        // column map, A^T b PORTS columns a cycle from the stream (a dot product of m rows x
        // STRIDE / PORTS groups: the plan's rule), the scatter into G
        FGC_CYCLES("gradient", 0, "reduce_3_columns", 30, 1, 1);
        if (i == 0) FGC_WAIT("gradient", 0, "datapaths", 0, "factor_3_jacobian");
        FGC_CYCLES("gradient", 0, "reduce_3_rows", 336, fgc_units::dot_ii(336, T_PARTIALS, T_ADD_LAT),
                   fgc_units::dot_depth(336, T_PARTIALS, T_ADD_LAT, T_MUL_LAT));
        FGC_CYCLES("gradient", 0, "reduce_3_scatter", 31, 1, 6 + T_ADD_LAT * fgc_units::ceil_log2(T_PARTIALS));
    }
    return finite;
}

// block 3: `noise` plus the cost's rounding noise of its instances at the linearisation point (from AB);
// INLINE: the block types' running sums land in rounding_noise_all's body, one after another, so
// they share its one adder, and its ALLOCATION makes their rounding_noise calls one module
T noise_3(T noise, T ab[NOISE_AB]) {
#pragma HLS INLINE
    for (int i = 0; i < 7; ++i) {
        const int f = BLOCK3_INSTANCES[i];
        const int vb = FACTOR_VAR_BEGIN[f];
        load_rows_3(f, ab);  // into rounding_noise_all's one row buffer
        T scale[NOISE_STRIDE];  // per column: largest storage entry of its variable (0: b, padding)
        for (int c = 0; c < 32; ++c) scale[c] = T(0);
        for (int j = 0; j < 6; ++j) scale[0 + j] = VAR_SCALE[FACTOR_VARS[vb + 0]];
        for (int j = 0; j < 3; ++j) scale[6 + j] = VAR_SCALE[FACTOR_VARS[vb + 1]];
        for (int j = 0; j < 6; ++j) scale[9 + j] = VAR_SCALE[FACTOR_VARS[vb + 2]];
        for (int j = 0; j < 3; ++j) scale[15 + j] = VAR_SCALE[FACTOR_VARS[vb + 3]];
        for (int j = 0; j < 6; ++j) scale[18 + j] = VAR_SCALE[FACTOR_VARS[vb + 4]];
        for (int j = 0; j < 6; ++j) scale[24 + j] = VAR_SCALE[FACTOR_VARS[vb + 5]];
        noise += rounding_noise(ab, scale, 32, 31, 21);
        FGC_CYCLES("noise_3", 0, "load", 336, 1, 2);
        FGC_CYCLES("noise_3", 0, "scales", 32, 1, 1);
        FGC_CYCLES("noise_3", 0, "rows", 21, 35, 49);
        FGC_CYCLES("noise_3", 0, "terms", 6, 12, 25);
    }
    return noise;
}

void gather_4(const T x[N_X], int f, T in[12], T dat[4]) {
    const int vb = FACTOR_VAR_BEGIN[f];
    const int line = FACTOR_DATA_OFF[f];
    for (int i = 0; i < 12; ++i) in[0 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 0]] + i];
    for (int i = 0; i < 3; ++i) dat[0 + i] = DATA_BUF[line + 0 + i];
    for (int i = 0; i < 1; ++i) dat[3 + i] = DATA_BUF[line + 3 + i];
}


// block 4's whitened rows of instance f from AB, padded to 8 columns (a multiple of PORTS)
void load_rows_4(int f, T ab[24]) {
    const int a0 = FACTOR_A_OFF[f];
    for (int e = 0; e < 24; e += PORTS) {  // PORTS words a cycle
#pragma HLS PIPELINE II=1
        for (int h = 0; h < PORTS; ++h) {
            const int r = (e + h) / 8, c = (e + h) % 8;
            ab[e + h] = c < 7 ? T(AB[a0 + r * 7 + c]) : T(0);
        }
    }
}

// block 4: the gradient of each instance from the datapath's stream; false if not
// finite. INLINE into reduce_all, whose ALLOCATION makes every block type's accumulate one module
// block 4: `noise` plus the cost's rounding noise of its instances at the linearisation point (from AB);
// INLINE: the block types' running sums land in rounding_noise_all's body, one after another, so
// they share its one adder, and its ALLOCATION makes their rounding_noise calls one module
T noise_4(T noise, T ab[NOISE_AB]) {
#pragma HLS INLINE
    for (int i = 0; i < 8; ++i) {
        const int f = BLOCK4_INSTANCES[i];
        const int vb = FACTOR_VAR_BEGIN[f];
        load_rows_4(f, ab);  // into rounding_noise_all's one row buffer
        T scale[NOISE_STRIDE];  // per column: largest storage entry of its variable (0: b, padding)
        for (int c = 0; c < 8; ++c) scale[c] = T(0);
        for (int j = 0; j < 6; ++j) scale[0 + j] = VAR_SCALE[FACTOR_VARS[vb + 0]];
        noise += rounding_noise(ab, scale, 8, 7, 3);
        FGC_CYCLES("noise_4", 0, "load", 12, 1, 2);
        FGC_CYCLES("noise_4", 0, "scales", 8, 1, 1);
        FGC_CYCLES("noise_4", 0, "rows", 3, 35, 49);
        FGC_CYCLES("noise_4", 0, "terms", 1, 12, 25);
    }
    return noise;
}

// The small block types (PriorFactorVector3, PriorFactorImuBias, GPSFactor): one time-multiplexed datapath per mode. One
// pipelined loop over all their instances (block type by block type) runs one branch a block
// type of one function, all under that function's ALLOCATION: the branches are exclusive, so
// they share its operators (their factor_<b> / factor_cost_<b> inlined into it).
const int SMALL_BLOCK[10] = { 1, 2, 4, 4, 4, 4, 4, 4, 4, 4 };
const int SMALL_FACTOR[10] = { 1, 2, 10, 11, 12, 13, 14, 15, 16, 17 };

// Jacobian mode of small block type b's instance f (evaluate_<b>'s body)
void evaluate_small_one(const T x[N_X], int b, int f, hls::stream<GradWord>& grad) {
#pragma HLS INLINE off
#pragma HLS ALLOCATION operation instances=fadd limit=1
#pragma HLS ALLOCATION operation instances=fmul limit=2
    if (b == 1) {
        T in[3], dat[4];
        gather_1(x, f, in, dat);
        T raw[12];  // the Jacobian writes only its structural non-zeros
        T ab[12];
        for (int c = 0; c < 12; ++c) raw[c] = T(0);
        factor_1(in, dat, raw);
        whiten<4, 4, 3, 0, 3>(raw + 0, ab + 0, dat + 3);
        const int a0 = FACTOR_A_OFF[f];
        for (int r = 0; r < 3; ++r) {
            for (int c = 0; c < 4; ++c) AB[a0 + r * 4 + c] = ab[r * 4 + c];
        }
        // and beside AB, to the gradient (reduce_all, the same DATAFLOW region): 6 stream words
        for (int r = 0; r < 3; ++r) grad_row<4, 4>(ab + r * 4, grad);
    } else if (b == 2) {
        T in[6], dat[7];
        gather_2(x, f, in, dat);
        T raw[48];  // the Jacobian writes only its structural non-zeros
        T ab[48];
        for (int c = 0; c < 48; ++c) raw[c] = T(0);
        factor_2(in, dat, raw);
        whiten<8, 7, 6, 0, 6>(raw + 0, ab + 0, dat + 6);
        const int a0 = FACTOR_A_OFF[f];
        for (int r = 0; r < 6; ++r) {
            for (int c = 0; c < 7; ++c) AB[a0 + r * 7 + c] = ab[r * 8 + c];
        }
        // and beside AB, to the gradient (reduce_all, the same DATAFLOW region): 24 stream words
        for (int r = 0; r < 6; ++r) grad_row<8, 7>(ab + r * 8, grad);
    } else if (b == 4) {
        T in[12], dat[4];
        gather_4(x, f, in, dat);
        T raw[24];  // the Jacobian writes only its structural non-zeros
        T ab[24];
        for (int c = 0; c < 24; ++c) raw[c] = T(0);
        factor_4(in, dat, raw);
        whiten<8, 7, 3, 0, 3>(raw + 0, ab + 0, dat + 3);
        const int a0 = FACTOR_A_OFF[f];
        for (int r = 0; r < 3; ++r) {
            for (int c = 0; c < 7; ++c) AB[a0 + r * 7 + c] = ab[r * 8 + c];
        }
        // and beside AB, to the gradient (reduce_all, the same DATAFLOW region): 12 stream words
        for (int r = 0; r < 3; ++r) grad_row<8, 7>(ab + r * 8, grad);
    }
}

// every small block type's instances in Jacobian mode, one every II=42 cycles (the plan's)
void evaluate_small(const T x[N_X], hls::stream<GradWord>& grad) {
    for (int i = 0; i < 10; ++i) {
#pragma HLS PIPELINE II=42
        evaluate_small_one(x, SMALL_BLOCK[i], SMALL_FACTOR[i], grad);
    }
    FGC_CYCLES("datapaths", 0, "factor_small_jacobian", 10, 42, 24);
}

// every small block type's instances' gradient from the stream, in evaluate_small's order
// (INLINE into reduce_all: its one accumulate)
bool reduce_small(hls::stream<GradWord>& grad, T& sq) {
#pragma HLS INLINE
    bool finite = true;
    for (int i = 0; i < 10; ++i) {
        const int k = i;
        const int b = SMALL_BLOCK[k], f = SMALL_FACTOR[k];
        if (b == 1) {
        const int vb = FACTOR_VAR_BEGIN[f];
        int col[GRAD_COLS];  // per column: its tangent entry
        for (int j = 0; j < 3; ++j) col[0 + j] = VAR_T_OFF[FACTOR_VARS[vb + 0]] + j;
        finite = accumulate(grad, col, 4, 4, 3, sq) && finite;
        // column map, A^T b PORTS columns a cycle from the stream (a dot product of m rows x
        // STRIDE / PORTS groups: the plan's rule), the scatter into G
        FGC_CYCLES("gradient", 0, "reduce_1_columns", 3, 1, 1);
        if (i == 0) FGC_WAIT("gradient", 0, "datapaths", 0, "factor_small_jacobian");
        FGC_CYCLES("gradient", 0, "reduce_1_rows", 6, fgc_units::dot_ii(6, T_PARTIALS, T_ADD_LAT),
                   fgc_units::dot_depth(6, T_PARTIALS, T_ADD_LAT, T_MUL_LAT));
        FGC_CYCLES("gradient", 0, "reduce_1_scatter", 4, 1, 6 + T_ADD_LAT * fgc_units::ceil_log2(T_PARTIALS));
        } else if (b == 2) {
        const int vb = FACTOR_VAR_BEGIN[f];
        int col[GRAD_COLS];  // per column: its tangent entry
        for (int j = 0; j < 6; ++j) col[0 + j] = VAR_T_OFF[FACTOR_VARS[vb + 0]] + j;
        finite = accumulate(grad, col, 8, 7, 6, sq) && finite;
        // column map, A^T b PORTS columns a cycle from the stream (a dot product of m rows x
        // STRIDE / PORTS groups: the plan's rule), the scatter into G
        FGC_CYCLES("gradient", 0, "reduce_2_columns", 6, 1, 1);
        if (i == 0) FGC_WAIT("gradient", 0, "datapaths", 0, "factor_small_jacobian");
        FGC_CYCLES("gradient", 0, "reduce_2_rows", 24, fgc_units::dot_ii(24, T_PARTIALS, T_ADD_LAT),
                   fgc_units::dot_depth(24, T_PARTIALS, T_ADD_LAT, T_MUL_LAT));
        FGC_CYCLES("gradient", 0, "reduce_2_scatter", 7, 1, 6 + T_ADD_LAT * fgc_units::ceil_log2(T_PARTIALS));
        } else if (b == 4) {
        const int vb = FACTOR_VAR_BEGIN[f];
        int col[GRAD_COLS];  // per column: its tangent entry
        for (int j = 0; j < 6; ++j) col[0 + j] = VAR_T_OFF[FACTOR_VARS[vb + 0]] + j;
        finite = accumulate(grad, col, 8, 7, 3, sq) && finite;
        // column map, A^T b PORTS columns a cycle from the stream (a dot product of m rows x
        // STRIDE / PORTS groups: the plan's rule), the scatter into G
        FGC_CYCLES("gradient", 0, "reduce_4_columns", 6, 1, 1);
        if (i == 0) FGC_WAIT("gradient", 0, "datapaths", 0, "factor_small_jacobian");
        FGC_CYCLES("gradient", 0, "reduce_4_rows", 12, fgc_units::dot_ii(12, T_PARTIALS, T_ADD_LAT),
                   fgc_units::dot_depth(12, T_PARTIALS, T_ADD_LAT, T_MUL_LAT));
        FGC_CYCLES("gradient", 0, "reduce_4_scatter", 7, 1, 6 + T_ADD_LAT * fgc_units::ceil_log2(T_PARTIALS));
        }
    }
    return finite;
}

// cost mode of small block type b's instance f: its members' costs summed (cost_of_<b>'s body)
T cost_small_one(const T x[N_X], int b, int f) {
#pragma HLS INLINE off
#pragma HLS ALLOCATION operation instances=fadd limit=2
#pragma HLS ALLOCATION operation instances=fmul limit=2
    T total = T(0);
    if (b == 1) {
        T in[3], dat[4], half[1];
        gather_1(x, f, in, dat);
        factor_cost_1(in, dat, half);
        T cost = T(0);
        cost += half[0];  // no robust loss on this member (the Program's flag)
        total = cost;
    } else if (b == 2) {
        T in[6], dat[7], half[1];
        gather_2(x, f, in, dat);
        factor_cost_2(in, dat, half);
        T cost = T(0);
        cost += half[0];  // no robust loss on this member (the Program's flag)
        total = cost;
    } else if (b == 4) {
        T in[12], dat[4], half[1];
        gather_4(x, f, in, dat);
        factor_cost_4(in, dat, half);
        T cost = T(0);
        cost += half[0];  // no robust loss on this member (the Program's flag)
        total = cost;
    }
    return total;
}

// linearize_rows' processes. The datapaths in Jacobian mode one after another, each instance's
// whitened rows into AB and to the gradient's stream:
void evaluate_all(const T x[N_X], hls::stream<GradWord>& grad) {
    evaluate_0(x, grad);
    evaluate_small(x, grad);
    evaluate_3(x, grad);
}

// G zeroed, then the gradient of every instance in the datapaths' order, from the stream (one
// accumulate for every block type: reduce_<b> INLINE, they run one after another)
void reduce_all(hls::stream<GradWord>& grad, bool& finite, T& sq) {
#pragma HLS ALLOCATION function instances=accumulate limit=1
    for (int i = 0; i < N_TANGENT; i += PORTS) {  // PORTS words a cycle (G's two ports)
#pragma HLS PIPELINE II=1
        for (int h = 0; h < PORTS; ++h) {
            if (i + h < N_TANGENT) G[i + h] = T(0);
        }
    }
    FGC_CYCLES("gradient", 0, "zero", (N_TANGENT + PORTS - 1) / PORTS, 1, 1);
    bool ok = true;
    T s = T(0);  // sum of b^T b over the instances: twice the cost at x
    ok = reduce_0(grad, s) && ok;
    ok = reduce_small(grad, s) && ok;
    ok = reduce_3(grad, s) && ok;
    finite = ok;
    sq = s;
}

// The linearisation, one DATAFLOW region: evaluate_all (the datapaths: the rows into AB and, a
// stream word PORTS columns, to the gradient) alongside reduce_all (A^T b, the finiteness check and b^T b
// from the stream): an instance's gradient is formed while the datapaths evaluate the next ones,
// and AB is not read a second time. The stream holds the largest instance's words.
void linearize_rows(const T x[N_X], bool& finite, T& sq) {
#pragma HLS DATAFLOW
    hls::stream<GradWord> grad;
#pragma HLS STREAM variable=grad depth=GRAD_DEPTH
    FGC_REGION("linearize");
    evaluate_all(x, grad);
    reduce_all(grad, finite, sq);
    FGC_DRAINED(&grad, 1);
}

// Linearise every factor: linearize_rows (the datapaths into AB, the gradient beside them).
bool linearize_all(const T x[N_X]) {
    FGC_EVENT("linearize");
    FGC_PHASE("factor_jacobian");  // the region's records: the plan's factor_jacobian phase
    bool finite = true;
    T sq = T(0);  // sum of b^T b over the instances: twice the cost at x
    linearize_rows(x, finite, sq);
    FGC_SEQUENTIAL();
    LIN_COST = T(0.5) * sq;
    return finite;
}

// The cost's rounding noise at x, the linearisation point (AB holds its whitened rows).
T rounding_noise_all(const T x[N_X]) {
    // one rounding_noise for every block type (noise_<b> INLINE: they run one after another)
#pragma HLS ALLOCATION function instances=rounding_noise limit=1
    FGC_EVENT("noise");
    FGC_PHASE("rounding_noise");
    for (int v = 0; v < N_VARIABLES; ++v) {  // largest storage entry of each variable, at least 1
        T scale = T(1);
        for (int i = VAR_X_OFF[v]; i < VAR_X_OFF[v + 1]; ++i) {
#pragma HLS LOOP_TRIPCOUNT max=12
            scale = fgc_abs(x[i]) > scale ? fgc_abs(x[i]) : scale;
        }
        VAR_SCALE[v] = scale;
        FGC_CYCLES("variable_scale", 0, "scale", VAR_X_OFF[v + 1] - VAR_X_OFF[v], 1, 3);
    }
    T noise = T(0);
    T ab[NOISE_AB];  // one row buffer for every block type's rows (rounding_noise's banks)
#pragma HLS ARRAY_PARTITION variable=ab cyclic factor=NOISE_STRIDE
    noise = noise_0(noise, ab);
    noise = noise_1(noise, ab);
    noise = noise_2(noise, ab);
    noise = noise_3(noise, ab);
    noise = noise_4(noise, ab);
    return noise;
}

// ---- the graph's cost (GTSAM's error), beside back-substitution (issue 33): trial_cost is the
// third process of fgc_backsub.h's back_substitute region, fed by backsub_retire one variable's
// storage words a stream word (X_TRIAL's as they are retired, or X's for the cost at X), into
// its own copy `x`; a loop per datapath (the plan's order: the most work first, or, in the
// slot design, as their last instances are ready where that ends sooner), each entry
// first taking the variables retired since (up to K, in back-substitution's order) and then
// costing the instance whose last variable that was (TRIAL_F_<d>: the instance, -1 none), all
// into one running total (entries in that order: the simulator's order was never the
// kernel's). The datapaths' cost-mode functions have this one call site each.
const int MAX_STORAGE = 12;  // the widest variable's storage words
struct TrialVar { T word[MAX_STORAGE]; };  // a retired variable's storage words
T TRIAL_COST = T(0);  // the cost of the variables back_substitute last sent
const int TRIAL_F_3[7] = {  // per entry of cost loop 3: its instance (-1: none)
    6, 5, 7, 4, 8, 3, 9,
};
const int TRIAL_X0_3[42] = {  // per entry, 6 a row: where each variable it takes goes in x
    63, 75, 78, 84, 96, 99, 42, 54, 57, 0, 0, 0, 105, 117, 120, 0,
    0, 0, 21, 33, 36, 0, 0, 0, 126, 138, 141, 0, 0, 0, 0, 12,
    15, 0, 0, 0, 147, 159, 162, 0, 0, 0,
};
const int TRIAL_X1_3[42] = {  // and where it ends (x0 = x1: none)
    75, 78, 84, 96, 99, 105, 54, 57, 63, 0, 0, 0, 117, 120, 126, 0,
    0, 0, 33, 36, 42, 0, 0, 0, 138, 141, 147, 0, 0, 0, 12, 15,
    21, 0, 0, 0, 159, 162, 168, 0, 0, 0,
};
const int TRIAL_F_small[10] = {  // per entry of cost loop small: its instance (-1: none)
    13, 14, 12, 15, 11, 16, 10, 1, 2, 17,
};
const int TRIAL_B_small[10] = {  // per entry: its instance's block type (-1: none)
    4, 4, 4, 4, 4, 4, 4, 1, 2, 4,
};
const int TRIAL_F_0[1] = {  // per entry of cost loop 0: its instance (-1: none)
    0,
};
void trial_cost(hls::stream<TrialVar>& tx, hls::stream<TrialVar>& tx2) {
    (void)tx2;  // (back-substitution by columns: the second cost process's stream, none here)
#pragma HLS ARRAY_PARTITION variable=DATA_BUF cyclic factor=2
    FGC_OUTER_BRANCH();  // csim cycle counting only: the third process of back_substitute
    T x[N_X];  // the variables taken so far
    T total = T(0);
    // block 3 (CombinedImuFactor+LidarOdometryFactor): 7 entries, one every II=66 cycles (the plan's)
    for (int e = 0; e < 7; ++e) {
#pragma HLS PIPELINE II=66
        for (int j = 0; j < 6; ++j) {  // the variables retired since, in order
            const int x0 = TRIAL_X0_3[e * 6 + j], x1 = TRIAL_X1_3[e * 6 + j];
            if (x0 < x1) {
                FGC_OUTER_ABSORB();  // csim cycle counting: no earlier than it was sent
                const TrialVar t = tx.read();
                for (int w = 0; w < MAX_STORAGE; ++w) {
                    if (x0 + w < x1) x[x0 + w] = t.word[w];
                }
            }
        }
        const int f = TRIAL_F_3[e];
        if (f >= 0) {
        T in[42], dat[211], half[2];
        gather_trial_3(x, f, in, dat);
        factor_cost_3(in, dat, half);
        T cost = T(0);
        cost += half[0];  // no robust loss on this member (the Program's flag)
        cost += half[1];  // no robust loss on this member (the Program's flag)
            total += cost;
        }
        FGC_CYCLES("trial_cost", 0, "cost_3", 1, 66, 602);
    }
    // the small datapath (GPSFactor, PriorFactorImuBias, PriorFactorVector3): 10 entries, one every II=11 cycles (the plan's)
    for (int e = 0; e < 10; ++e) {
#pragma HLS PIPELINE II=11
        const int f = TRIAL_F_small[e];
        if (f >= 0) {
            total += cost_small_one(x, TRIAL_B_small[e], f);
        }
        FGC_CYCLES("trial_cost", 0, "cost_small", 1, 11, 22);
    }
    // block 0 (PriorFactorPose3): 1 entries, one every II=48 cycles (the plan's)
    for (int e = 0; e < 1; ++e) {
#pragma HLS PIPELINE II=48
        const int f = TRIAL_F_0[e];
        if (f >= 0) {
        T in[12], dat[18], half[1];
        gather_trial_0(x, f, in, dat);
        factor_cost_0(in, dat, half);
        T cost = T(0);
        cost += half[0];  // no robust loss on this member (the Program's flag)
            total += cost;
        }
        FGC_CYCLES("trial_cost", 0, "cost_0", 1, 48, 377);
    }
    TRIAL_COST = total;
}

// ---- state update: retraction x (+) delta, one datapath per variable type; the ALLOCATION
// limits are the plan's operators of unit state_update_<k> (the factor datapaths' limits)
// kind 0: Pose3
void retract_0(const T x[12], const T d[6], T out[12]) {
#pragma HLS INLINE off
#pragma HLS ALLOCATION operation instances=fadd limit=4
#pragma HLS ALLOCATION operation instances=fmul limit=6
    const T r0 = (d[1]*d[1]);
    const T r1 = (d[2]*d[2]);
    const T r2 = r0 + r1;
    const T r3 = -r2;
    const T r4 = (d[0]*d[0]);
    const T r5 = r4 + r2;
    const T r6 = lie_B(r5);
    const T r7 = T(1) + r3*r6;
    const T r8 = lie_A(r5);
    const T r9 = d[2]*r8;
    const T r10 = d[1]*r6;
    const T r11 = d[0]*r10;
    const T r12 = r9 + r11;
    const T r13 = d[1]*r8;
    const T r14 = d[2]*r6;
    const T r15 = d[0]*r14;
    const T r16 = r15 - r13;
    const T r17 = r11 - r9;
    const T r18 = -(r1 + r4);
    const T r19 = T(1) + r18*r6;
    const T r20 = d[0]*r8;
    const T r21 = r20 + d[1]*r14;
    const T r22 = r13 + r15;
    const T r23 = (d[1]*d[2])*r6 - r20;
    const T r24 = -(r0 + r4);
    const T r25 = T(1) + r24*r6;
    const T r26 = lie_C(r5);
    const T r27 = d[0]*r26;
    const T r28 = d[1]*r27;
    const T r29 = d[2]*r27;
    const T r30 = d[5]*(r10 + r29) + (d[3]*(T(1) + r3*r26) + d[4]*(r28 - r14));
    const T r31 = d[0]*r6;
    const T r32 = d[3]*(r14 + r28) + (d[4]*(T(1) + r18*r26) + d[5]*((d[1]*d[2])*r26 - r31));
    const T r33 = d[3]*(r29 - r10) + (d[4]*((d[1]*d[2])*r26 + r31) + d[5]*(T(1) + r24*r26));
    out[0] = x[2]*r16 + (x[0]*r7 + x[1]*r12);
    out[1] = x[2]*r21 + (x[1]*r19 + x[0]*r17);
    out[2] = x[0]*r22 + (x[1]*r23 + x[2]*r25);
    out[3] = x[5]*r16 + (x[3]*r7 + x[4]*r12);
    out[4] = x[5]*r21 + (x[4]*r19 + x[3]*r17);
    out[5] = x[3]*r22 + (x[4]*r23 + x[5]*r25);
    out[6] = x[8]*r16 + (x[6]*r7 + x[7]*r12);
    out[7] = x[8]*r21 + (x[7]*r19 + x[6]*r17);
    out[8] = x[6]*r22 + (x[7]*r23 + x[8]*r25);
    out[9] = (x[9] + x[1]*r32) + (x[2]*r33 + x[0]*r30);
    out[10] = (x[10] + x[4]*r32) + (x[5]*r33 + x[3]*r30);
    out[11] = (x[11] + x[7]*r32) + (x[8]*r33 + x[6]*r30);
}

// kind 1: Vector3
void retract_1(const T x[3], const T d[3], T out[3]) {
#pragma HLS INLINE off
#pragma HLS ALLOCATION operation instances=fadd limit=3
    out[0] = d[0] + x[0];
    out[1] = d[1] + x[1];
    out[2] = d[2] + x[2];
}

// kind 2: ImuBias
void retract_2(const T x[6], const T d[6], T out[6]) {
#pragma HLS INLINE off
#pragma HLS ALLOCATION operation instances=fadd limit=4
    out[0] = d[0] + x[0];
    out[1] = d[1] + x[1];
    out[2] = d[2] + x[2];
    out[3] = d[3] + x[3];
    out[4] = d[4] + x[4];
    out[5] = d[5] + x[5];
}

// The state update of variable v, fed by back-substitution (fgc_backsub.h's backsub_retire, a
// variable an iteration as its step is solved): X_TRIAL = X (+) delta on v, through its type's
// datapath (the branches exclusive: each datapath one instance)
const int VAR_KIND[24] = {  // per variable its type (retract_<k>)
    0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0,
    1, 2, 0, 1, 2, 0, 1, 2,
};
const int RETIRE_VARS[24] = {  // the variables in the order back-substitution solves them
    9, 10, 11, 12, 13, 14, 6, 7, 8, 15, 16, 17, 3, 4, 5, 18,
    19, 20, 0, 1, 2, 21, 22, 23,
};
const int RETIRE_STEP[24] = {  // per entry of RETIRE_VARS: its step if it is the step's first variable, else -1
    6, -1, -1, -1, -1, -1, 4, -1, -1, 5, -1, -1, 2, -1, -1, 3,
    -1, -1, 0, -1, -1, 1, -1, -1,
};
// (at_x: no solve ran, X's words go to trial_cost for the cost at X). Its words go on to
// trial_cost (back_substitute's third process) as one stream word.
void retract_variable(int v, const L delta[N_TANGENT], bool at_x, hls::stream<TrialVar>& tx) {
    TrialVar out;
    for (int k = 0; k < MAX_STORAGE; ++k) out.word[k] = T(0);
    if (VAR_KIND[v] == 0) {
        T xv[12], dv[6], ov[12];
        for (int k = 0; k < 12; ++k) xv[k] = X[VAR_X_OFF[v] + k];
        for (int k = 0; k < 6; ++k) dv[k] = at_x ? T(0) : T(delta[VAR_T_OFF[v] + k]);
        retract_0(xv, dv, ov);
        for (int k = 0; k < 12; ++k) {
            const T o = at_x ? xv[k] : ov[k];
            X_TRIAL[VAR_X_OFF[v] + k] = o;
            out.word[k] = o;
        }
    } else if (VAR_KIND[v] == 1) {
        T xv[3], dv[3], ov[3];
        for (int k = 0; k < 3; ++k) xv[k] = X[VAR_X_OFF[v] + k];
        for (int k = 0; k < 3; ++k) dv[k] = at_x ? T(0) : T(delta[VAR_T_OFF[v] + k]);
        retract_1(xv, dv, ov);
        for (int k = 0; k < 3; ++k) {
            const T o = at_x ? xv[k] : ov[k];
            X_TRIAL[VAR_X_OFF[v] + k] = o;
            out.word[k] = o;
        }
    } else if (VAR_KIND[v] == 2) {
        T xv[6], dv[6], ov[6];
        for (int k = 0; k < 6; ++k) xv[k] = X[VAR_X_OFF[v] + k];
        for (int k = 0; k < 6; ++k) dv[k] = at_x ? T(0) : T(delta[VAR_T_OFF[v] + k]);
        retract_2(xv, dv, ov);
        for (int k = 0; k < 6; ++k) {
            const T o = at_x ? xv[k] : ov[k];
            X_TRIAL[VAR_X_OFF[v] + k] = o;
            out.word[k] = o;
        }
    }
    tx.write(out);
}

// ---- the linear solver's units: fixed headers (include/fgc_qr.h, fgc_cpe.h, fgc_backsub.h)
// configured by the constants below; what each DATAFLOW region holds is documented there.
// CFG::T is L, the linear solver's scalar; latencies are the plan's operator table for L.
struct LesConfig {
    typedef ::fgc::L T;
    static const int MAX_ROWS = ::fgc::MAX_ROWS;  // stacked rows of a step, damping rows included
    static const int MAX_COLS = ::fgc::MAX_W + 1;  // w + 1: frontal, separator, right-hand side
    static const int MAX_F = ::fgc::MAX_F;
    static const int N_UNITS = ::fgc::N_UNITS;
    static const int LOCAL_COLS = ::fgc::LOCAL_COLS;
    static const bool LM = true;  // false: Gauss-Newton, no damping rows
    static const int MAX_W = ::fgc::MAX_W;
    static const int UNIT_SETS = 2;  // a level's steps go UNIT_SETS at a time to the unit sets
    static const int MAX_LEVEL_WIDTH = 2;
    static const int ROOT_II = 1, ROOT_DEPTH = 15;  // sqrt(mu), once per solve
    // fgc_eliminate.h's loops: the tables' largest trip counts, the plan's (II, depth) of L
    static const int MAX_STEP_FACTORS = 5, MAX_CHILDREN = 2;
    static const int TRIP_COND = 465;  // a conditional, PORTS words a cycle
    static const int TRIP_BANKS = 696;  // a step's rows in the banks
    static const int TRIP_ROWS = 1349;  // a factor's rows, PORTS words a cycle
    static const int TRIP_UPDATE = 481;  // a new factor, PORTS words a cycle
    static const bool BANKS_ZERO = true;  // qr_step leaves its banks zero: qr_stack writes a step's rows only
    static const unsigned LEAF_SKIP = 0u;  // no marginal: qr_eliminate_all has no leaf step
    static const int LEAF_LIVE_ROWS = 0;
    static const int FILL_II = 1, FILL_DEPTH = 1;
    static const int MOVE_II = 1, MOVE_DEPTH = 2;
    static const int SCATTER_II = 1, SCATTER_DEPTH = 6;
    static const int PARTIALS = 4;  // interleaved partial sums (= ADD_LAT: II 1)
    static const int FOLD_LAT = 11;  // fgc_qr.h's dot_axpy: ADD_LAT ceil(log2 PARTIALS) + MUL_LAT
    static const int ADD_LAT = 4;  // one a line: the second reader resolves them by name
    static const int MUL_LAT = 3;
    static const int DIV_LAT = 15, SQRT_LAT = 15;
    static constexpr double SINGULAR_EPS = 1.1920928955078125e-06;  // 10 eps of L
    // back_substitute's state update (fgc_backsub.h's backsub_retire): a variable an iteration
    static const int N_TANGENT = ::fgc::N_TANGENT, N_VARIABLES = ::fgc::N_VARIABLES;
    static const int RETIRE_II = 22, RETIRE_DEPTH = 218;
    static void retract_variable(int v, const T delta[N_TANGENT], bool at_x,
                                 hls::stream<::fgc::TrialVar>& tx) {
        ::fgc::retract_variable(v, delta, at_x, tx);
    }
};

// ---- partial QR (paper A): per step the stacked rows [A | b] of its factors, its children's new
// factors and the damping rows sqrt(mu) I, column c in bank c % N_UNITS of its unit set's work
// memory; qr_step runs one DATAFLOW region per reflection (qr_broadcast, qr_finish -> 4 qr_update
// units -> qr_evaluate, qr_collect; 24 streams) and stores the conditional and the new factor. A schedule
// level's steps go 2 at a time to the unit sets, side by side in one DATAFLOW region.
L WORK0[N_UNITS][MAX_ROWS][LOCAL_COLS];  // unit set 0's banks (partitioned by bank in eliminate_all)
L CONDBUF0[MAX_F * LesConfig::MAX_COLS];  // its step's conditional
L UPDBUF0[LesConfig::MAX_COLS * LesConfig::MAX_COLS];  // its step's new factor
L WORK1[N_UNITS][MAX_ROWS][LOCAL_COLS];  // unit set 1's banks (partitioned by bank in eliminate_all)
L CONDBUF1[MAX_F * LesConfig::MAX_COLS];  // its step's conditional
L UPDBUF1[LesConfig::MAX_COLS * LesConfig::MAX_COLS];  // its step's new factor

// Unit set 0: one step (rows = 0: none this time).
void qr_set0(int rows, int f, int s, L work[N_UNITS][MAX_ROWS][LOCAL_COLS],
             L cond[MAX_F * LesConfig::MAX_COLS], L update[LesConfig::MAX_COLS * LesConfig::MAX_COLS],
             bool* singular) {
    FGC_BRANCH();  // csim cycle counting only: the unit sets of a level run side by side
    fgc_units::qr_step<LesConfig>(work, rows, f, s, cond, update, singular);
}

// Unit set 1: one step (rows = 0: none this time).
void qr_set1(int rows, int f, int s, L work[N_UNITS][MAX_ROWS][LOCAL_COLS],
             L cond[MAX_F * LesConfig::MAX_COLS], L update[LesConfig::MAX_COLS * LesConfig::MAX_COLS],
             bool* singular) {
    FGC_BRANCH();  // csim cycle counting only: the unit sets of a level run side by side
    fgc_units::qr_step<LesConfig>(work, rows, f, s, cond, update, singular);
}

// One level's steps on the 2 unit set(s) side by side: each on its own memories.
void qr_level(int rows0, int f0, int s0,
              L work0[N_UNITS][MAX_ROWS][LOCAL_COLS],
              L cond0[MAX_F * LesConfig::MAX_COLS],
              L update0[LesConfig::MAX_COLS * LesConfig::MAX_COLS], bool* bad0,
              int rows1, int f1, int s1,
              L work1[N_UNITS][MAX_ROWS][LOCAL_COLS],
              L cond1[MAX_F * LesConfig::MAX_COLS],
              L update1[LesConfig::MAX_COLS * LesConfig::MAX_COLS], bool* bad1) {
#pragma HLS DATAFLOW
    qr_set0(rows0, f0, s0, work0, cond0, update0, bad0);
    qr_set1(rows1, f1, s1, work1, cond1, update1, bad1);
}

// the elimination driver (fgc_eliminate.h) on these tables and memories, the unit sets'
// wiring its hooks: each set's banks, the qr_level region, each set's buffers
#define FGC_ELIMINATE_QR
#include "fgc_eliminate.h"

struct QrSets {
    static void stack(int u, int s, T root_mu, unsigned skip, int rows, bool solve) {
        (void)solve;  // (no rows are written into the banks before the stack)
        if (u == 0) qr_stack_rows<LesConfig>(s, root_mu, WORK0, skip, rows);
        if (u == 1) qr_stack_rows<LesConfig>(s, root_mu, WORK1, skip, rows);
    }
    static void level(const bool has[2], const int s[2], const int rows[2], bool bad[2]) {
        qr_level(rows[0], has[0] ? STEP_F[s[0]] : 0,
                 has[0] ? STEP_W[s[0]] - STEP_F[s[0]] : 0, WORK0, CONDBUF0, UPDBUF0, &bad[0],
                 rows[1], has[1] ? STEP_F[s[1]] : 0,
                 has[1] ? STEP_W[s[1]] - STEP_F[s[1]] : 0, WORK1, CONDBUF1, UPDBUF1, &bad[1]);
    }
    static void commit(int u, int s) {
        if (u == 0) qr_commit<LesConfig>(s, CONDBUF0, UPDBUF0);
        if (u == 1) qr_commit<LesConfig>(s, CONDBUF1, UPDBUF1);
    }
};

bool eliminate_all(T mu) {
    // each unit set's banks: the global itself partitioned (what qr_stack and the Update units
    // read and write), one memory per bank, N_UNITS words a cycle
    // (each bank two memories by row parity: fgc_qr.h streams the next pivot column two rows a
    // cycle)
#pragma HLS ARRAY_PARTITION variable=WORK0 complete dim=1
#pragma HLS ARRAY_PARTITION variable=WORK0 cyclic factor=2 dim=2
#pragma HLS ARRAY_PARTITION variable=WORK1 complete dim=1
#pragma HLS ARRAY_PARTITION variable=WORK1 cyclic factor=2 dim=2
    return qr_eliminate_all<LesConfig, QrSets>(mu);
}

// ---- back-substitution on two lanes (fgc_backsub.h's driver: back_substitute), slot by slot:
// the step each slot solves and loads (-1: none) and the lane that solves
const int BS_SLOTS = 9;
const int BS_SOLVE[BS_SLOTS] = {-1, 6, -1, 4, 5, 2, 3, 0, 1};
const int BS_LOAD[BS_SLOTS] = {6, -1, 4, 5, 2, 3, 0, 1, -1};
const int BS_LANE[BS_SLOTS] = {1, 0, 0, 1, 0, 1, 0, 1, 0};
// the loaded separator's solution in the loading lane's BS_X from this offset (-1: from DELTA)
const int BS_XOFF[BS_SLOTS] = {-1, -1, -1, 15, 0, 0, 0, 0, -1};
// HlsConfig backsub_lanes = 4: back-substitution by columns, one process per end of the chain
// (fgc_backsub.h's backsub_loader, backsub_end0 / backsub_end1; units/backsub.py's column_*)
#define FGC_BS_COLUMNS 1
const int BSC_SEQ[7] = {  // per end (from BSC_SEQ_BEGIN[e]) its steps, the root first on end 0: the loader streams their groups in this order
    6, 4, 2, 0, 5, 3, 1,
};
const int BSC_SEQ_BEGIN[3] = {
    0, 4, 7,
};
const int BSC_PASS_BEGIN[3] = {  // per end its passes from here
    0, 6, 12,
};
const int BSC_STEP[12] = {  // per pass: the step whose columns it runs (-1: none)
    -1, -1, 6, 4, 2, 0, -1, -1, 6, 5, 3, 1,
};
const int BSC_CHILD[12] = {  // the step whose rows its columns update too (-1: none)
    -1, -1, 4, 2, 0, -1, -1, -1, 5, 3, 1, -1,
};
const int BSC_INGEST[12] = {  // the step whose groups it takes in (-1: none)
    6, 4, 2, 0, -1, -1, 5, 3, -1, 1, -1, -1,
};
const int BSC_SLOT[12] = {  // the buffer slots of the three
    -1, -1, 0, 1, 2, 0, -1, -1, -1, 0, 1, 2,
};
const int BSC_CSLOT[12] = {
    -1, -1, 1, 2, 0, -1, -1, -1, 0, 1, 2, -1,
};
const int BSC_ISLOT[12] = {
    0, 1, 2, 0, -1, -1, 0, 1, -1, 2, -1, -1,
};
const int BSC_FEED[12] = {  // end 1's pass over the root's columns (x_r from end 0)
    0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0,
};
const int BSC_ROOT[12] = {  // end 0's pass sending the root's x_r to end 1
    0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0,
};
const int BSC_COLA_BEGIN[12] = {
    0, 0, 0, 30, 45, 60, 75, 75, 75, 105, 120, 135,
};
const int BSC_COLA[150] = {  // per pass column r: its position in the child's separator (-1: none)
    0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, -1,
    -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 0, 1,
    2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 0, 1, 2,
    3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, -1, -1, -1, -1,
    -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1,
    -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, 0, 1, 2, 3, 4, 5,
    6, 7, 8, 9, 10, 11, 12, 13, 14, 0, 1, 2, 3, 4, 5, 6,
    7, 8, 9, 10, 11, 12, 13, 14, 0, 1, 2, 3, 4, 5, 6, 7,
    8, 9, 10, 11, 12, 13, 14, -1, -1, -1, -1, -1, -1, -1, -1, -1,
    -1, -1, -1, -1, -1, -1,
};
const int BSC_END_OF[7] = {  // per step: its end (the state update's stream)
    0, 1, 0, 1, 0, 1, 0,
};
#define BSC_FIFO0 97  // the loader's streams (as deep as an end lags it)
#define BSC_FIFO1 100
#define BSC_DX0 39  // the ends' solution streams (all their steps' pairs)
#define BSC_DX1 24
#define FGC_BACKSUB_DRIVER
#include "fgc_backsub.h"

// back_substitute's region (the cost pass at X_TRIAL, or at X, beside it) behind one name:
// the on-chip stream's kernels, which inline solve, limit it to one instance (fgc_stream.h)
void back_substitute_at(bool at_x) {
    back_substitute<LesConfig>(at_x);
}

// The linear solve at mu: eliminate, then back-substitute, the cost at X_TRIAL beside it
// (trial_cost). False if singular. at_x: no solve, back_substitute's cost pass at X (LM
// control's cost_x). One RTL instance: LM control's two calls share it (fgc_lm.h's ALLOCATION;
// inlined in the on-chip stream's kernels, whose ALLOCATION shares back_substitute_at).
bool solve(T mu, bool at_x) {
    if (!at_x && !eliminate_all(mu)) return false;  // a failed solve back-substitutes nothing
    if (!at_x) FGC_EVENT("backsub");
    back_substitute_at(at_x);
    return true;
}

// ---- LM control (paper B): the rules in fgc_lm.h (shared with the native solver), its
// reductions in fgc_lm_units.h (interleaved partial sums at II 1); here the kernel's constants
// and hooks. fgc_lm::optimize<LmConfig>: GN/LM iterations from X.
T LM_X_NORM = T(0);  // |X| at the linearisation point: gradient_max() finds it, x_norm() reads it
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
    static T cost_x() {
        #pragma HLS INLINE
        FGC_EVENT("cost");
        solve(T(0), true);  // no solve: X's variables to trial_cost
        return TRIAL_COST;
    }
    static bool linearize_x(T) { return linearize_all(X); }  // (mu: the HLS Cholesky kernel's)
    static bool solve_at(T mu) {
        #pragma HLS INLINE
        return solve(mu, false);
    }
    static void retract_trial() {}  // X_TRIAL: written by back_substitute's backsub_retire
    static T cost_trial() {
        return TRIAL_COST;  // trial_cost's, beside the solve's back-substitution
    }
    static T noise_x() { return rounding_noise_all(X); }
    static const int N_X = ::fgc::N_X, N_TANGENT = ::fgc::N_TANGENT;
    static const int PARTIALS = T_PARTIALS, ADD_LAT = T_ADD_LAT, MUL_LAT = T_MUL_LAT;
    static const int MAXIMA = T_MAXIMA, CMP_LAT = T_CMP_LAT, ABS_LAT = T_ABS_LAT;
    static const int MOVE_II = 1, MOVE_DEPTH = 2;
    static const int N_DATA = ::fgc::N_DATA;
    static const int DECISION_II = 1, DECISION_DEPTH = 30;
    static T x_norm() { return LM_X_NORM; }  // |X|, found beside the gradient's maximum
    static T linearized_cost() { return LIN_COST; }  // the cost at X, from linearize_all's gradient pass
    static bool step_test(bool solved, T mu, T out[2]) {
#pragma HLS INLINE
        return fgc_units::lm_step_test<LmConfig>(solved, mu, DELTA, G, out);
    }
    static T gradient_max() {  // once per linearisation; |X| with it for x_norm (same X)
#pragma HLS INLINE
        T out[2];
        fgc_units::lm_iterate<LmConfig>(G, X, out);
        LM_X_NORM = out[1];
        return out[0];
    }
    static void accept_trial() { fgc_units::lm_accept<LmConfig>(X, X_TRIAL); }
    static void accepted(int, T, T, T) {}  // no host to tell on chip
};

}  // namespace
}  // namespace fgc

void lio_top(const fgc::T x_in[fgc::N_X], const fgc::T data[fgc::N_DATA],
                    fgc::T x_out[fgc::N_X], fgc::T errors[2], int info[3]) {
#pragma HLS INTERFACE m_axi port=x_in offset=slave bundle=gmem0 depth=168
#pragma HLS INTERFACE m_axi port=data offset=slave bundle=gmem1 depth=1588
#pragma HLS INTERFACE m_axi port=x_out offset=slave bundle=gmem0 depth=168
#pragma HLS INTERFACE s_axilite port=errors
#pragma HLS INTERFACE s_axilite port=info
#pragma HLS INTERFACE s_axilite port=return
    fgc_units::lm_top<fgc::LmConfig>(x_in, data, x_out, fgc::X, fgc::DATA_BUF, errors, info);
}
