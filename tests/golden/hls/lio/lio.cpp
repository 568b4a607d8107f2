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
    const T t0 = dat[0]*in[0] + dat[3]*in[3] + dat[6]*in[6];
    const T t1 = dat[0]*in[2] + dat[3]*in[5] + dat[6]*in[8];
    const T t2 = dat[0]*in[1] + dat[3]*in[4] + dat[6]*in[7];
    const T t3 = dat[1]*in[0] + dat[4]*in[3] + dat[7]*in[6];
    const T t4 = dat[1]*in[2] + dat[4]*in[5] + dat[7]*in[8];
    const T t5 = dat[1]*in[1] + dat[4]*in[4] + dat[7]*in[7];
    const T t6 = dat[2]*in[0] + dat[5]*in[3] + dat[8]*in[6];
    const T t7 = dat[2]*in[2] + dat[5]*in[5] + dat[8]*in[8];
    const T t8 = dat[2]*in[1] + dat[5]*in[4] + dat[8]*in[7];
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
    const T t27 = t26*t20;
    const T t28 = t27*t22;
    const T t29 = (T(0.5))*t28 - T(0.5)*t19;
    const T t30 = -t25*t26 + T(1);
    const T t31 = (T(0.5))*t30;
    const T t32 = t29*t12 - t31*t13;
    const T t33 = (T(0.5))*t22;
    const T t34 = (T(0.5))*t27*t18 + (T(0.5))*t33;
    const T t35 = (T(0.5))*t30*t17 - t34*t15;
    const T t36 = t29*t15 - t31*t16;
    const T t37 = (T(0.5))*t30*t11 - t34*t9;
    const T t38 = t29*t9 - t31*t10;
    const T t39 = (T(0.5))*t30*t14 - t34*t12;
    const T t40 = -t29*t11 + t34*t10;
    const T t41 = -t29*t17 + t34*t16;
    const T t42 = -t29*t14 + t34*t13;
    const T t43 = (T(0.5))*t26*(-t21 - t24) + T(0.5);
    const T t44 = t28 + t19;
    const T t45 = (T(0.5))*t44;
    const T t46 = t43*t12 - t45*t13;
    const T t47 = (T(0.5))*t20;
    const T t48 = t22*t18;
    const T t49 = t26*t48;
    const T t50 = -T(0.5)*t47 + (T(0.5))*t49;
    const T t51 = (T(0.5))*t44*t17 - t50*t15;
    const T t52 = t43*t15 - t45*t16;
    const T t53 = (T(0.5))*t44*t11 - t50*t9;
    const T t54 = t43*t9 - t45*t10;
    const T t55 = (T(0.5))*t44*t14 - t50*t12;
    const T t56 = -t43*t11 + t50*t10;
    const T t57 = -t43*t17 + t50*t16;
    const T t58 = -t43*t14 + t50*t13;
    const T t59 = (T(0.5))*t47 + (T(0.5))*t49;
    const T t60 = t26*t18*t20 - t33;
    const T t61 = (T(0.5))*t60;
    const T t62 = t59*t12 - t61*t13;
    const T t63 = (T(0.5))*t26*(-t21 - t23) + T(0.5);
    const T t64 = (T(0.5))*t60*t17 - t63*t15;
    const T t65 = t59*t15 - t61*t16;
    const T t66 = (T(0.5))*t60*t11 - t63*t9;
    const T t67 = t59*t9 - t61*t10;
    const T t68 = (T(0.5))*t60*t14 - t63*t12;
    const T t69 = -t59*t11 + t63*t10;
    const T t70 = -t59*t17 + t63*t16;
    const T t71 = -t59*t14 + t63*t13;
    const T t72 = T(2)*t22;
    const T t73 = T(2)*t18;
    const T t74 = T(2)*t20;
    const T t75 = t23;
    const T t76 = t24;
    const T t77 = t75 + t76;
    const T t78 = t21;
    const T t79 = t77 + t78;
    const T t80 = lie_D1(t79);
    const T t81 = lie_D(t79);
    const T t82 = t22*t81;
    const T t83 = t18*t81;
    const T t84 = -t77*t81 + T(1);
    const T t85 = t19;
    const T t86 = t81*t20;
    const T t87 = t22*t86;
    const T t88 = t85 + t87;
    const T t89 = t33;
    const T t90 = t18*t86;
    const T t91 = -t89 + t90;
    const T t92 = -t85 + t87;
    const T t93 = -t76 - t78;
    const T t94 = t93*t81 + T(1);
    const T t95 = t47;
    const T t96 = t48*t81;
    const T t97 = t95 + t96;
    const T t98 = t89 + t90;
    const T t99 = -t95 + t96;
    const T t100 = -t75 - t78;
    const T t101 = t100*t81 + T(1);
    const T t102 = -dat[0]*dat[9] + dat[0]*in[9] - dat[3]*dat[10] + dat[3]*in[10] - dat[6]*dat[11] + dat[6]*in[11];
    const T t103 = t77*t102;
    const T t104 = t81*t102;
    const T t105 = -dat[1]*dat[9] + dat[1]*in[9] - dat[4]*dat[10] + dat[4]*in[10] - dat[7]*dat[11] + dat[7]*in[11];
    const T t106 = t93*t105;
    const T t107 = t81*t105;
    const T t108 = -dat[2]*dat[9] + dat[2]*in[9] - dat[5]*dat[10] + dat[5]*in[10] - dat[8]*dat[11] + dat[8]*in[11];
    const T t109 = t100*t108;
    const T t110 = t81*t108;
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
    const T t129 = t32*t121 + t35*t125 + t36*t127 + t37*t113 + t38*t115 + t39*t119;
    const T t130 = t32*t122 + t36*t128 + t38*t116 + t40*t111 + t41*t123 + t42*t117;
    const T t131 = t35*t126 + t37*t114 + t39*t120 + t40*t112 + t41*t124 + t42*t118;
    const T t132 = t46*t121 + t51*t125 + t52*t127 + t53*t113 + t54*t115 + t55*t119;
    const T t133 = t46*t122 + t52*t128 + t54*t116 + t56*t111 + t57*t123 + t58*t117;
    const T t134 = t51*t126 + t53*t114 + t55*t120 + t56*t112 + t57*t124 + t58*t118;
    const T t135 = t62*t121 + t64*t125 + t65*t127 + t66*t113 + t67*t115 + t68*t119;
    const T t136 = t62*t122 + t65*t128 + t67*t116 + t69*t111 + t70*t123 + t71*t117;
    const T t137 = t64*t126 + t66*t114 + t68*t120 + t69*t112 + t70*t124 + t71*t118;
    const T t138 = t72*t132;
    const T t139 = t72*t133;
    const T t140 = t72*t134;
    const T t141 = t73*t135;
    const T t142 = t73*t136;
    const T t143 = t73*t137;
    const T t144 = t138 + t141;
    const T t145 = t139 + t142;
    const T t146 = t140 + t143;
    const T t147 = t74*t129;
    const T t148 = t74*t130;
    const T t149 = t74*t131;
    const T t150 = t80*t144 + t80*t147;
    const T t151 = t80*t145 + t80*t148;
    const T t152 = t80*t146 + t80*t149;
    const T t153 = t0;
    const T t154 = t2;
    const T t155 = t1;
    const T t156 = (T(0.5))*t135;
    const T t157 = (T(0.5))*t136;
    const T t158 = (T(0.5))*t137;
    const T t159 = t81*t129 + t20*t150;
    const T t160 = t81*t130 + t20*t151;
    const T t161 = t81*t131 + t20*t152;
    const T t162 = t22*t159 + t86*t132;
    const T t163 = t22*t160 + t86*t133;
    const T t164 = t22*t161 + t86*t134;
    const T t165 = t3;
    const T t166 = t5;
    const T t167 = t4;
    const T t168 = (T(0.5))*t132;
    const T t169 = (T(0.5))*t133;
    const T t170 = (T(0.5))*t134;
    const T t171 = t18*t159 + t86*t135;
    const T t172 = t18*t160 + t86*t136;
    const T t173 = t18*t161 + t86*t137;
    const T t174 = t6;
    const T t175 = t8;
    const T t176 = t7;
    const T t177 = (T(0.5))*t129;
    const T t178 = (T(0.5))*t130;
    const T t179 = (T(0.5))*t131;
    const T t180 = t48*t150 + t82*t135 + t83*t132;
    const T t181 = t48*t151 + t82*t136 + t83*t133;
    const T t182 = t48*t152 + t82*t137 + t83*t134;
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
    raw[24] = -t103*t150 - t104*t144 + t105*t156 + t105*t162 - t108*t168 + t108*t171;
    raw[25] = -t103*t151 - t104*t145 + t105*t157 + t105*t163 - t108*t169 + t108*t172;
    raw[26] = -t103*t152 - t104*t146 + t105*t158 + t105*t164 - t108*t170 + t108*t173;
    raw[27] = t84*t153 + t88*t165 + t91*t174;
    raw[28] = t84*t154 + t88*t166 + t91*t175;
    raw[29] = t84*t155 + t88*t167 + t91*t176;
    raw[30] = t84*t102 + t88*t105 + t91*t108;
    raw[32] = t106*t150 - t107*t141 - t107*t147 - t102*t156 + t102*t162 + t108*t177 + t108*t180;
    raw[33] = t106*t151 - t107*t142 - t107*t148 - t102*t157 + t102*t163 + t108*t178 + t108*t181;
    raw[34] = t106*t152 - t107*t143 - t107*t149 - t102*t158 + t102*t164 + t108*t179 + t108*t182;
    raw[35] = t92*t153 + t94*t165 + t97*t174;
    raw[36] = t92*t154 + t94*t166 + t97*t175;
    raw[37] = t92*t155 + t94*t167 + t97*t176;
    raw[38] = t92*t102 + t94*t105 + t97*t108;
    raw[40] = t109*t150 - t110*t138 - t110*t147 + t102*t168 + t102*t171 - t105*t177 + t105*t180;
    raw[41] = t109*t151 - t110*t139 - t110*t148 + t102*t169 + t102*t172 - t105*t178 + t105*t181;
    raw[42] = t109*t152 - t110*t140 - t110*t149 + t102*t170 + t102*t173 - t105*t179 + t105*t182;
    raw[43] = t98*t153 + t99*t165 + t101*t174;
    raw[44] = t98*t154 + t99*t166 + t101*t175;
    raw[45] = t98*t155 + t99*t167 + t101*t176;
    raw[46] = t98*t102 + t99*t105 + t101*t108;
}

void factor_cost_0(const T in[12], const T dat[18],
                   T half[1]) {
#pragma HLS INLINE off
#pragma HLS ALLOCATION operation instances=fadd limit=3
#pragma HLS ALLOCATION operation instances=fmul limit=3
#pragma HLS ALLOCATION operation instances=fdiv limit=1
#pragma HLS ALLOCATION operation instances=fsqrt limit=1
    const T t0 = dat[0]*in[0] + dat[3]*in[3] + dat[6]*in[6];
    const T t1 = t0;
    const T t2 = dat[0]*in[1] + dat[3]*in[4] + dat[6]*in[7];
    const T t3 = t2;
    const T t4 = dat[0]*in[2] + dat[3]*in[5] + dat[6]*in[8];
    const T t5 = t4;
    const T t6 = dat[1]*in[0] + dat[4]*in[3] + dat[7]*in[6];
    const T t7 = t6;
    const T t8 = dat[1]*in[1] + dat[4]*in[4] + dat[7]*in[7];
    const T t9 = t8;
    const T t10 = dat[1]*in[2] + dat[4]*in[5] + dat[7]*in[8];
    const T t11 = t10;
    const T t12 = dat[2]*in[0] + dat[5]*in[3] + dat[8]*in[6];
    const T t13 = t12;
    const T t14 = dat[2]*in[1] + dat[5]*in[4] + dat[8]*in[7];
    const T t15 = t14;
    const T t16 = dat[2]*in[2] + dat[5]*in[5] + dat[8]*in[8];
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
    const T t31 = t28 + t30;
    const T t32 = lie_D(t31);
    const T t33 = -t28*t32 + T(1);
    const T t34 = (T(0.5))*t22;
    const T t35 = t34;
    const T t36 = t32*t18;
    const T t37 = t20*t36;
    const T t38 = t35 + t37;
    const T t39 = (T(0.5))*t20;
    const T t40 = t39;
    const T t41 = t22*t36;
    const T t42 = -t40 + t41;
    const T t43 = -dat[0]*dat[9] + dat[0]*in[9] - dat[3]*dat[10] + dat[3]*in[10] - dat[6]*dat[11] + dat[6]*in[11];
    const T t44 = -dat[1]*dat[9] + dat[1]*in[9] - dat[4]*dat[10] + dat[4]*in[10] - dat[7]*dat[11] + dat[7]*in[11];
    const T t45 = -dat[2]*dat[9] + dat[2]*in[9] - dat[5]*dat[10] + dat[5]*in[10] - dat[8]*dat[11] + dat[8]*in[11];
    const T t46 = t33*t43 + t38*t44 + t42*t45;
    const T t47 = -t35 + t37;
    const T t48 = -t27 - t30;
    const T t49 = t48*t32 + T(1);
    const T t50 = (T(0.5))*t18;
    const T t51 = t50;
    const T t52 = t20*t22;
    const T t53 = t52*t32;
    const T t54 = t51 + t53;
    const T t55 = t47*t43 + t49*t44 + t54*t45;
    const T t56 = t40 + t41;
    const T t57 = -t51 + t53;
    const T t58 = -t25 - t30;
    const T t59 = t58*t32 + T(1);
    const T t60 = t56*t43 + t57*t44 + t59*t45;
    const T t61 = (T(0.5))*t19*(dat[12]*dat[12]) + (T(0.5))*t21*(dat[13]*dat[13]) + (T(0.5))*t23*(dat[14]*dat[14]) + (T(0.5))*(t46*t46)*(dat[15]*dat[15]) + (T(0.5))*(t55*t55)*(dat[16]*dat[16]) + (T(0.5))*(t60*t60)*(dat[17]*dat[17]);
    half[0] = t61;
}

// block 1: PriorFactorVector3 (3 rows, 3 columns, 1 instances)
void factor_1(const T in[3], const T dat[4],
              T raw[12]) {
#pragma HLS INLINE
    raw[0] = T(1);
    raw[3] = -dat[0] + in[0];
    raw[5] = T(1);
    raw[7] = -dat[1] + in[1];
    raw[10] = T(1);
    raw[11] = -dat[2] + in[2];
}

void factor_cost_1(const T in[3], const T dat[4],
                   T half[1]) {
#pragma HLS INLINE
    const T t0 = -dat[0] + in[0];
    const T t1 = -dat[1] + in[1];
    const T t2 = -dat[2] + in[2];
    const T t3 = (T(0.5))*(dat[3]*dat[3]);
    const T t4 = (t0*t0)*t3 + (t1*t1)*t3 + (t2*t2)*t3;
    half[0] = t4;
}

// block 2: PriorFactorImuBias (6 rows, 6 columns, 1 instances)
void factor_2(const T in[6], const T dat[7],
              T raw[48]) {
#pragma HLS INLINE
    raw[0] = T(1);
    raw[6] = -dat[0] + in[0];
    raw[9] = T(1);
    raw[14] = -dat[1] + in[1];
    raw[18] = T(1);
    raw[22] = -dat[2] + in[2];
    raw[27] = T(1);
    raw[30] = -dat[3] + in[3];
    raw[36] = T(1);
    raw[38] = -dat[4] + in[4];
    raw[45] = T(1);
    raw[46] = -dat[5] + in[5];
}

void factor_cost_2(const T in[6], const T dat[7],
                   T half[1]) {
#pragma HLS INLINE
    const T t0 = -dat[0] + in[0];
    const T t1 = -dat[1] + in[1];
    const T t2 = -dat[2] + in[2];
    const T t3 = -dat[3] + in[3];
    const T t4 = -dat[4] + in[4];
    const T t5 = -dat[5] + in[5];
    const T t6 = (T(0.5))*(dat[6]*dat[6]);
    const T t7 = (t0*t0)*t6 + (t1*t1)*t6 + (t2*t2)*t6 + (t3*t3)*t6 + (t4*t4)*t6 + (t5*t5)*t6;
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
    const T t6 = t0*dat[9] + t1*dat[10] + t2*dat[11] + t3*dat[36] + t4*dat[37] + t5*dat[38] + dat[0];
    const T t7 = T(2)*t6;
    const T t8 = t0*dat[12] + t1*dat[13] + t2*dat[14] + t3*dat[39] + t4*dat[40] + t5*dat[41] + dat[1];
    const T t9 = T(2)*t8;
    const T t10 = t0*dat[15] + t1*dat[16] + t2*dat[17] + t3*dat[42] + t4*dat[43] + t5*dat[44] + dat[2];
    const T t11 = T(2)*t10;
    const T t12 = (t6*t6) + (t8*t8) + (t10*t10);
    const T t13 = lie_B1(t12);
    const T t14 = -t8;
    const T t15 = t8*t14;
    const T t16 = -t10;
    const T t17 = t16*t10;
    const T t18 = t17 + t15;
    const T t19 = -dat[15];
    const T t20 = t16*dat[15] + t10*t19;
    const T t21 = lie_B(t12);
    const T t22 = t21*t20;
    const T t23 = -dat[12];
    const T t24 = t8*t23 + t14*dat[12];
    const T t25 = t21*t24;
    const T t26 = -dat[16];
    const T t27 = t16*dat[16] + t10*t26;
    const T t28 = t21*t27;
    const T t29 = -dat[13];
    const T t30 = t8*t29 + t14*dat[13];
    const T t31 = t21*t30;
    const T t32 = -dat[17];
    const T t33 = t16*dat[17] + t10*t32;
    const T t34 = t21*t33;
    const T t35 = -dat[14];
    const T t36 = t8*t35 + t14*dat[14];
    const T t37 = t21*t36;
    const T t38 = -dat[42];
    const T t39 = t16*dat[42] + t10*t38;
    const T t40 = t21*t39;
    const T t41 = -dat[39];
    const T t42 = t8*t41 + t14*dat[39];
    const T t43 = t21*t42;
    const T t44 = -dat[40];
    const T t45 = t8*t44 + t14*dat[40];
    const T t46 = t21*t45;
    const T t47 = -dat[43];
    const T t48 = t16*dat[43] + t10*t47;
    const T t49 = t21*t48;
    const T t50 = -dat[41];
    const T t51 = t8*t50 + t14*dat[41];
    const T t52 = t21*t51;
    const T t53 = -dat[44];
    const T t54 = t16*dat[44] + t10*t53;
    const T t55 = t21*t54;
    const T t56 = in[0]*in[15] + in[3]*in[18] + in[6]*in[21];
    const T t57 = in[2]*in[15] + in[5]*in[18] + in[8]*in[21];
    const T t58 = -t57;
    const T t59 = in[1]*in[15] + in[4]*in[18] + in[7]*in[21];
    const T t60 = in[0]*in[17] + in[3]*in[20] + in[6]*in[23];
    const T t61 = -t60;
    const T t62 = in[0]*in[16] + in[3]*in[19] + in[6]*in[22];
    const T t63 = lie_A1(t12);
    const T t64 = -t56;
    const T t65 = in[1]*in[17] + in[4]*in[20] + in[7]*in[23];
    const T t66 = -t65;
    const T t67 = in[1]*in[16] + in[4]*in[19] + in[7]*in[22];
    const T t68 = -t59;
    const T t69 = in[2]*in[17] + in[5]*in[20] + in[8]*in[23];
    const T t70 = -t69;
    const T t71 = in[2]*in[16] + in[5]*in[19] + in[8]*in[22];
    const T t72 = -t6;
    const T t73 = t6*t72;
    const T t74 = t17 + t73;
    const T t75 = -dat[9];
    const T t76 = t6*t75 + t72*dat[9];
    const T t77 = t21*t76;
    const T t78 = -dat[10];
    const T t79 = t6*t78 + t72*dat[10];
    const T t80 = t21*t79;
    const T t81 = -dat[11];
    const T t82 = t6*t81 + t72*dat[11];
    const T t83 = t21*t82;
    const T t84 = -dat[36];
    const T t85 = t6*t84 + t72*dat[36];
    const T t86 = t21*t85;
    const T t87 = -dat[37];
    const T t88 = t6*t87 + t72*dat[37];
    const T t89 = t21*t88;
    const T t90 = -dat[38];
    const T t91 = t6*t90 + t72*dat[38];
    const T t92 = t21*t91;
    const T t93 = t73 + t15;
    const T t94 = t16*t21;
    const T t95 = t16*t72;
    const T t96 = t21*t72;
    const T t97 = t21*t8;
    const T t98 = t21*t10;
    const T t99 = t8*t10;
    const T t100 = -t71;
    const T t101 = -t62;
    const T t102 = -t67;
    const T t103 = t18*t21 + T(1);
    const T t104 = t56;
    const T t105 = lie_A(t12);
    const T t106 = t21*t14;
    const T t107 = t105*t10 + t72*t106;
    const T t108 = t59;
    const T t109 = t6*t21;
    const T t110 = t105*t14 + t109*t10;
    const T t111 = t57;
    const T t112 = t103*t104 + t107*t108 + t110*t111;
    const T t113 = t74*t21 + T(1);
    const T t114 = t16*t106 + t6*t105;
    const T t115 = t16*t105 + t109*t8;
    const T t116 = t104*t115 + t108*t113 + t111*t114;
    const T t117 = t93*t21 + T(1);
    const T t118 = t94*t72 + t105*t8;
    const T t119 = t97*t10 + t105*t72;
    const T t120 = t104*t118 + t108*t119 + t111*t117;
    const T t121 = t62;
    const T t122 = t67;
    const T t123 = t71;
    const T t124 = t103*t121 + t107*t122 + t110*t123;
    const T t125 = t113*t122 + t114*t123 + t115*t121;
    const T t126 = t117*t123 + t118*t121 + t119*t122;
    const T t127 = t60;
    const T t128 = t65;
    const T t129 = t69;
    const T t130 = t103*t127 + t107*t128 + t110*t129;
    const T t131 = t113*t128 + t114*t129 + t115*t127;
    const T t132 = t117*t129 + t118*t127 + t119*t128;
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
    const T t142 = t141*t135;
    const T t143 = t142*t138;
    const T t144 = t134 + t143;
    const T t145 = (T(0.5))*t112;
    const T t146 = -t140*t141 + T(1);
    const T t147 = -t144*t145 + (T(0.5))*t146*t120;
    const T t148 = (T(0.5))*t138;
    const T t149 = t142*t133;
    const T t150 = -t148 + t149;
    const T t151 = (T(0.5))*t146;
    const T t152 = t145*t150 - t151*t116;
    const T t153 = (T(0.5))*t144;
    const T t154 = (T(0.5))*t150;
    const T t155 = t153*t125 - t154*t126;
    const T t156 = (T(0.5))*t146*t126 - t153*t124;
    const T t157 = -t151*t125 + t154*t124;
    const T t158 = t153*t131 - t154*t132;
    const T t159 = (T(0.5))*t146*t132 - t153*t130;
    const T t160 = -t151*t131 + t154*t130;
    const T t161 = t153*t116 - t154*t120;
    const T t162 = (T(0.5))*t135;
    const T t163 = t141*t133*t138 - t162;
    const T t164 = t148 + t149;
    const T t165 = -t145*t163 + (T(0.5))*t164*t120;
    const T t166 = t141*(-t136 - t139) + T(1);
    const T t167 = (T(0.5))*t164;
    const T t168 = t145*t166 - t167*t116;
    const T t169 = (T(0.5))*t163;
    const T t170 = (T(0.5))*t166;
    const T t171 = t169*t125 - t170*t126;
    const T t172 = (T(0.5))*t164*t126 - t169*t124;
    const T t173 = -t167*t125 + t170*t124;
    const T t174 = t169*t131 - t170*t132;
    const T t175 = (T(0.5))*t164*t132 - t169*t130;
    const T t176 = -t167*t131 + t170*t130;
    const T t177 = t169*t116 - t170*t120;
    const T t178 = t141*(-t136 - t137) + T(1);
    const T t179 = -t134 + t143;
    const T t180 = -t145*t178 + (T(0.5))*t179*t120;
    const T t181 = t133*t138;
    const T t182 = t141*t181 + t162;
    const T t183 = (T(0.5))*t179;
    const T t184 = t145*t182 - t183*t116;
    const T t185 = (T(0.5))*t178;
    const T t186 = (T(0.5))*t182;
    const T t187 = -t186*t126 + t185*t125;
    const T t188 = (T(0.5))*t179*t126 - t185*t124;
    const T t189 = t186*t124 - t183*t125;
    const T t190 = -t186*t132 + t185*t131;
    const T t191 = (T(0.5))*t179*t132 - t185*t130;
    const T t192 = t186*t130 - t183*t131;
    const T t193 = -t186*t120 + t185*t116;
    const T t194 = T(2)*t133;
    const T t195 = T(2)*t138;
    const T t196 = T(2)*t135;
    const T t197 = t137;
    const T t198 = t139;
    const T t199 = t197 + t198;
    const T t200 = t136;
    const T t201 = t199 + t200;
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
    const T t215 = t0*dat[18] + t1*dat[19] + t2*dat[20] + t3*dat[45] + t4*dat[46] + t5*dat[47] + dat[3];
    const T t216 = t0*dat[21] + t1*dat[22] + t2*dat[23] + t3*dat[48] + t4*dat[49] + t5*dat[50] + dat[4];
    const T t217 = t0*dat[24] + t1*dat[25] + t2*dat[26] + t3*dat[51] + t4*dat[52] + t5*dat[53] + dat[5];
    const T t218 = (T(0.5))*(dat[69]*dat[69]);
    const T t219 = t203 + t215*in[0] + t216*in[1] + t217*in[2] + t218*dat[70] + dat[69]*in[12];
    const T t220 = t207 + t215*in[3] + t216*in[4] + t217*in[5] + t218*dat[71] + dat[69]*in[13];
    const T t221 = t211 + t215*in[6] + t216*in[7] + t217*in[8] + t218*dat[72] + dat[69]*in[14];
    const T t222 = t219*in[15] + t220*in[18] + t221*in[21];
    const T t223 = t219*in[17] + t220*in[20] + t221*in[23];
    const T t224 = t219*in[16] + t220*in[19] + t221*in[22];
    const T t225 = -t198 - t200;
    const T t226 = t57;
    const T t227 = t68;
    const T t228 = t107*t226 + t110*t227;
    const T t229 = t113*t226 + t114*t227;
    const T t230 = t117*t227 + t119*t226;
    const T t231 = t71;
    const T t232 = t102;
    const T t233 = t107*t231 + t110*t232;
    const T t234 = t113*t231 + t114*t232;
    const T t235 = t117*t232 + t119*t231;
    const T t236 = t69;
    const T t237 = t66;
    const T t238 = t107*t236 + t110*t237;
    const T t239 = t113*t236 + t114*t237;
    const T t240 = t117*t237 + t119*t236;
    const T t241 = t147*t229 + t152*t230 + t155*t233 + t156*t234 + t157*t235 + t158*t238 + t159*t239 + t160*t240 + t161*t228;
    const T t242 = t196*t241;
    const T t243 = lie_D(t201);
    const T t244 = t243*t242;
    const T t245 = t58;
    const T t246 = t56;
    const T t247 = t103*t245 + t110*t246;
    const T t248 = t114*t246 + t115*t245;
    const T t249 = t117*t246 + t118*t245;
    const T t250 = t100;
    const T t251 = t62;
    const T t252 = t103*t250 + t110*t251;
    const T t253 = t114*t251 + t115*t250;
    const T t254 = t117*t251 + t118*t250;
    const T t255 = t70;
    const T t256 = t60;
    const T t257 = t103*t255 + t110*t256;
    const T t258 = t114*t256 + t115*t255;
    const T t259 = t117*t256 + t118*t255;
    const T t260 = t147*t248 + t152*t249 + t155*t252 + t156*t253 + t157*t254 + t158*t257 + t159*t258 + t160*t259 + t161*t247;
    const T t261 = t196*t260;
    const T t262 = t243*t261;
    const T t263 = t59;
    const T t264 = t64;
    const T t265 = t103*t263 + t107*t264;
    const T t266 = t113*t264 + t115*t263;
    const T t267 = t118*t263 + t119*t264;
    const T t268 = t67;
    const T t269 = t101;
    const T t270 = t103*t268 + t107*t269;
    const T t271 = t113*t269 + t115*t268;
    const T t272 = t118*t268 + t119*t269;
    const T t273 = t65;
    const T t274 = t61;
    const T t275 = t103*t273 + t107*t274;
    const T t276 = t113*t274 + t115*t273;
    const T t277 = t118*t273 + t119*t274;
    const T t278 = t147*t266 + t152*t267 + t155*t270 + t156*t271 + t157*t272 + t158*t275 + t159*t276 + t160*t277 + t161*t265;
    const T t279 = t196*t278;
    const T t280 = t243*t279;
    const T t281 = t60;
    const T t282 = t65;
    const T t283 = t69;
    const T t284 = t103*t281 + t107*t282 + t110*t283;
    const T t285 = t113*t282 + t114*t283 + t115*t281;
    const T t286 = t117*t283 + t118*t281 + t119*t282;
    const T t287 = t101;
    const T t288 = t102;
    const T t289 = t100;
    const T t290 = t103*t287 + t107*t288 + t110*t289;
    const T t291 = t113*t288 + t114*t289 + t115*t287;
    const T t292 = t117*t289 + t118*t287 + t119*t288;
    const T t293 = t155*t284 + t156*t285 + t157*t286 + t158*t290 + t159*t291 + t160*t292;
    const T t294 = t196*t293;
    const T t295 = t243*t294;
    const T t296 = t61;
    const T t297 = t66;
    const T t298 = t70;
    const T t299 = t103*t296 + t107*t297 + t110*t298;
    const T t300 = t113*t297 + t114*t298 + t115*t296;
    const T t301 = t117*t298 + t118*t296 + t119*t297;
    const T t302 = t56;
    const T t303 = t59;
    const T t304 = t57;
    const T t305 = t103*t302 + t107*t303 + t110*t304;
    const T t306 = t113*t303 + t114*t304 + t115*t302;
    const T t307 = t117*t304 + t118*t302 + t119*t303;
    const T t308 = t147*t300 + t152*t301 + t158*t305 + t159*t306 + t160*t307 + t161*t299;
    const T t309 = t196*t308;
    const T t310 = t243*t309;
    const T t311 = t62;
    const T t312 = t67;
    const T t313 = t71;
    const T t314 = t103*t311 + t107*t312 + t110*t313;
    const T t315 = t113*t312 + t114*t313 + t115*t311;
    const T t316 = t117*t313 + t118*t311 + t119*t312;
    const T t317 = t64;
    const T t318 = t68;
    const T t319 = t58;
    const T t320 = t103*t317 + t107*t318 + t110*t319;
    const T t321 = t113*t318 + t114*t319 + t115*t317;
    const T t322 = t117*t319 + t118*t317 + t119*t318;
    const T t323 = t147*t315 + t152*t316 + t155*t320 + t156*t321 + t157*t322 + t161*t314;
    const T t324 = t196*t323;
    const T t325 = t243*t324;
    const T t326 = t7*dat[9] + t9*dat[12] + t11*dat[15];
    const T t327 = t13*t326;
    const T t328 = t18*t327 + t22 + t25;
    const T t329 = t63*t326;
    const T t330 = t21*t23 + t14*t327;
    const T t331 = t105*dat[15] + t72*t330 + t106*t75 + t10*t329;
    const T t332 = t6*t327 + t21*dat[9];
    const T t333 = t105*t23 + t109*dat[15] + t14*t329 + t10*t332;
    const T t334 = t104*t328 + t108*t331 + t111*t333;
    const T t335 = t74*t327 + t77 + t22;
    const T t336 = t16*t330 + t6*t329 + t105*dat[9] + t106*t19;
    const T t337 = t16*t329 + t105*t19 + t109*dat[12] + t8*t332;
    const T t338 = t104*t337 + t108*t335 + t111*t336;
    const T t339 = t77 + t93*t327 + t25;
    const T t340 = t94*t75 + t95*t327 + t96*t19 + t105*dat[12] + t8*t329;
    const T t341 = t97*dat[15] + t98*dat[12] + t99*t327 + t105*t75 + t72*t329;
    const T t342 = t104*t340 + t108*t341 + t111*t339;
    const T t343 = t121*t328 + t122*t331 + t123*t333;
    const T t344 = t121*t337 + t122*t335 + t123*t336;
    const T t345 = t121*t340 + t122*t341 + t123*t339;
    const T t346 = t127*t328 + t128*t331 + t129*t333;
    const T t347 = t127*t337 + t128*t335 + t129*t336;
    const T t348 = t127*t340 + t128*t341 + t129*t339;
    const T t349 = t147*t338 + t152*t342 + t155*t343 + t156*t344 + t157*t345 + t158*t346 + t159*t347 + t160*t348 + t161*t334;
    const T t350 = t196*t349;
    const T t351 = t243*t350;
    const T t352 = t7*dat[10] + t9*dat[13] + t11*dat[16];
    const T t353 = t13*t352;
    const T t354 = t18*t353 + t28 + t31;
    const T t355 = t63*t352;
    const T t356 = t21*t29 + t14*t353;
    const T t357 = t105*dat[16] + t72*t356 + t106*t78 + t10*t355;
    const T t358 = t6*t353 + t21*dat[10];
    const T t359 = t105*t29 + t109*dat[16] + t14*t355 + t10*t358;
    const T t360 = t104*t354 + t108*t357 + t111*t359;
    const T t361 = t74*t353 + t80 + t28;
    const T t362 = t16*t356 + t6*t355 + t105*dat[10] + t106*t26;
    const T t363 = t16*t355 + t105*t26 + t109*dat[13] + t8*t358;
    const T t364 = t104*t363 + t108*t361 + t111*t362;
    const T t365 = t80 + t93*t353 + t31;
    const T t366 = t94*t78 + t95*t353 + t96*t26 + t105*dat[13] + t8*t355;
    const T t367 = t97*dat[16] + t98*dat[13] + t99*t353 + t105*t78 + t72*t355;
    const T t368 = t104*t366 + t108*t367 + t111*t365;
    const T t369 = t121*t354 + t122*t357 + t123*t359;
    const T t370 = t121*t363 + t122*t361 + t123*t362;
    const T t371 = t121*t366 + t122*t367 + t123*t365;
    const T t372 = t127*t354 + t128*t357 + t129*t359;
    const T t373 = t127*t363 + t128*t361 + t129*t362;
    const T t374 = t127*t366 + t128*t367 + t129*t365;
    const T t375 = t147*t364 + t152*t368 + t155*t369 + t156*t370 + t157*t371 + t158*t372 + t159*t373 + t160*t374 + t161*t360;
    const T t376 = t196*t375;
    const T t377 = t243*t376;
    const T t378 = t7*dat[11] + t9*dat[14] + t11*dat[17];
    const T t379 = t13*t378;
    const T t380 = t37 + t18*t379 + t34;
    const T t381 = t63*t378;
    const T t382 = t21*t35 + t14*t379;
    const T t383 = t105*dat[17] + t72*t382 + t106*t81 + t10*t381;
    const T t384 = t6*t379 + t21*dat[11];
    const T t385 = t105*t35 + t109*dat[17] + t14*t381 + t10*t384;
    const T t386 = t104*t380 + t108*t383 + t111*t385;
    const T t387 = t74*t379 + t83 + t34;
    const T t388 = t16*t382 + t6*t381 + t105*dat[11] + t106*t32;
    const T t389 = t16*t381 + t105*t32 + t109*dat[14] + t8*t384;
    const T t390 = t104*t389 + t108*t387 + t111*t388;
    const T t391 = t37 + t83 + t93*t379;
    const T t392 = t94*t81 + t95*t379 + t96*t32 + t105*dat[14] + t8*t381;
    const T t393 = t97*dat[17] + t98*dat[14] + t99*t379 + t105*t81 + t72*t381;
    const T t394 = t104*t392 + t108*t393 + t111*t391;
    const T t395 = t121*t380 + t122*t383 + t123*t385;
    const T t396 = t121*t389 + t122*t387 + t123*t388;
    const T t397 = t121*t392 + t122*t393 + t123*t391;
    const T t398 = t127*t380 + t128*t383 + t129*t385;
    const T t399 = t127*t389 + t128*t387 + t129*t388;
    const T t400 = t127*t392 + t128*t393 + t129*t391;
    const T t401 = t147*t390 + t152*t394 + t155*t395 + t156*t396 + t157*t397 + t158*t398 + t159*t399 + t160*t400 + t161*t386;
    const T t402 = t196*t401;
    const T t403 = t243*t402;
    const T t404 = t7*dat[36] + t9*dat[39] + t11*dat[42];
    const T t405 = t13*t404;
    const T t406 = t40 + t43 + t18*t405;
    const T t407 = t63*t404;
    const T t408 = t21*t41 + t14*t405;
    const T t409 = t105*dat[42] + t72*t408 + t106*t84 + t10*t407;
    const T t410 = t6*t405 + t21*dat[36];
    const T t411 = t105*t41 + t109*dat[42] + t14*t407 + t10*t410;
    const T t412 = t104*t406 + t108*t409 + t111*t411;
    const T t413 = t40 + t74*t405 + t86;
    const T t414 = t16*t408 + t6*t407 + t105*dat[36] + t106*t38;
    const T t415 = t16*t407 + t105*t38 + t109*dat[39] + t8*t410;
    const T t416 = t104*t415 + t108*t413 + t111*t414;
    const T t417 = t43 + t86 + t93*t405;
    const T t418 = t94*t84 + t95*t405 + t96*t38 + t105*dat[39] + t8*t407;
    const T t419 = t97*dat[42] + t98*dat[39] + t99*t405 + t105*t84 + t72*t407;
    const T t420 = t104*t418 + t108*t419 + t111*t417;
    const T t421 = t121*t406 + t122*t409 + t123*t411;
    const T t422 = t121*t415 + t122*t413 + t123*t414;
    const T t423 = t121*t418 + t122*t419 + t123*t417;
    const T t424 = t127*t406 + t128*t409 + t129*t411;
    const T t425 = t127*t415 + t128*t413 + t129*t414;
    const T t426 = t127*t418 + t128*t419 + t129*t417;
    const T t427 = t147*t416 + t152*t420 + t155*t421 + t156*t422 + t157*t423 + t158*t424 + t159*t425 + t160*t426 + t161*t412;
    const T t428 = t196*t427;
    const T t429 = t243*t428;
    const T t430 = t7*dat[37] + t9*dat[40] + t11*dat[43];
    const T t431 = t13*t430;
    const T t432 = t46 + t49 + t18*t431;
    const T t433 = t63*t430;
    const T t434 = t21*t44 + t14*t431;
    const T t435 = t105*dat[43] + t72*t434 + t106*t87 + t10*t433;
    const T t436 = t6*t431 + t21*dat[37];
    const T t437 = t105*t44 + t109*dat[43] + t14*t433 + t10*t436;
    const T t438 = t104*t432 + t108*t435 + t111*t437;
    const T t439 = t49 + t74*t431 + t89;
    const T t440 = t16*t434 + t6*t433 + t105*dat[37] + t106*t47;
    const T t441 = t16*t433 + t105*t47 + t109*dat[40] + t8*t436;
    const T t442 = t104*t441 + t108*t439 + t111*t440;
    const T t443 = t46 + t89 + t93*t431;
    const T t444 = t94*t87 + t95*t431 + t96*t47 + t105*dat[40] + t8*t433;
    const T t445 = t97*dat[43] + t98*dat[40] + t99*t431 + t105*t87 + t72*t433;
    const T t446 = t104*t444 + t108*t445 + t111*t443;
    const T t447 = t121*t432 + t122*t435 + t123*t437;
    const T t448 = t121*t441 + t122*t439 + t123*t440;
    const T t449 = t121*t444 + t122*t445 + t123*t443;
    const T t450 = t127*t432 + t128*t435 + t129*t437;
    const T t451 = t127*t441 + t128*t439 + t129*t440;
    const T t452 = t127*t444 + t128*t445 + t129*t443;
    const T t453 = t147*t442 + t152*t446 + t155*t447 + t156*t448 + t157*t449 + t158*t450 + t159*t451 + t160*t452 + t161*t438;
    const T t454 = t196*t453;
    const T t455 = t243*t454;
    const T t456 = t7*dat[38] + t9*dat[41] + t11*dat[44];
    const T t457 = t13*t456;
    const T t458 = t52 + t55 + t18*t457;
    const T t459 = t63*t456;
    const T t460 = t21*t50 + t14*t457;
    const T t461 = t105*dat[44] + t72*t460 + t106*t90 + t10*t459;
    const T t462 = t6*t457 + t21*dat[38];
    const T t463 = t105*t50 + t109*dat[44] + t14*t459 + t10*t462;
    const T t464 = t104*t458 + t108*t461 + t111*t463;
    const T t465 = t55 + t74*t457 + t92;
    const T t466 = t16*t460 + t6*t459 + t105*dat[38] + t106*t53;
    const T t467 = t16*t459 + t105*t53 + t109*dat[41] + t8*t462;
    const T t468 = t104*t467 + t108*t465 + t111*t466;
    const T t469 = t52 + t92 + t93*t457;
    const T t470 = t94*t90 + t95*t457 + t96*t53 + t105*dat[41] + t8*t459;
    const T t471 = t97*dat[44] + t98*dat[41] + t99*t457 + t105*t90 + t72*t459;
    const T t472 = t104*t470 + t108*t471 + t111*t469;
    const T t473 = t121*t458 + t122*t461 + t123*t463;
    const T t474 = t121*t467 + t122*t465 + t123*t466;
    const T t475 = t121*t470 + t122*t471 + t123*t469;
    const T t476 = t127*t458 + t128*t461 + t129*t463;
    const T t477 = t127*t467 + t128*t465 + t129*t466;
    const T t478 = t127*t470 + t128*t471 + t129*t469;
    const T t479 = t147*t468 + t152*t472 + t155*t473 + t156*t474 + t157*t475 + t158*t476 + t159*t477 + t160*t478 + t161*t464;
    const T t480 = t196*t479;
    const T t481 = t243*t480;
    const T t482 = t133*t243;
    const T t483 = t138*t243;
    const T t484 = -t197 - t200;
    const T t485 = t0*dat[27] + t1*dat[28] + t2*dat[29] + t3*dat[54] + t4*dat[55] + t5*dat[56] + dat[6];
    const T t486 = t0*dat[30] + t1*dat[31] + t2*dat[32] + t3*dat[57] + t4*dat[58] + t5*dat[59] + dat[7];
    const T t487 = t0*dat[33] + t1*dat[34] + t2*dat[35] + t3*dat[60] + t4*dat[61] + t5*dat[62] + dat[8];
    const T t488 = t485*in[0] + t486*in[1] + t487*in[2] + dat[69]*dat[70] + in[12] - in[27];
    const T t489 = t485*in[3] + t486*in[4] + t487*in[5] + dat[69]*dat[71] + in[13] - in[28];
    const T t490 = t485*in[6] + t486*in[7] + t487*in[8] + dat[69]*dat[72] + in[14] - in[29];
    const T t491 = t488*in[15] + t489*in[18] + t490*in[21];
    const T t492 = t488*in[17] + t489*in[20] + t490*in[23];
    const T t493 = t488*in[16] + t489*in[19] + t490*in[22];
    const T t494 = t104*dat[73] + t108*dat[76] + t111*dat[79];
    const T t495 = t121*dat[73] + t122*dat[76] + t123*dat[79];
    const T t496 = t127*dat[73] + t128*dat[76] + t129*dat[79];
    const T t497 = t104*dat[74] + t108*dat[77] + t111*dat[80];
    const T t498 = t121*dat[74] + t122*dat[77] + t123*dat[80];
    const T t499 = t127*dat[74] + t128*dat[77] + t129*dat[80];
    const T t500 = t104*dat[75] + t108*dat[78] + t111*dat[81];
    const T t501 = t121*dat[75] + t122*dat[78] + t123*dat[81];
    const T t502 = t127*dat[75] + t128*dat[78] + t129*dat[81];
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
    const T t512 = t511*t505;
    const T t513 = (T(0.5))*t504 + (T(0.5))*t512*t508;
    const T t514 = (T(0.5))*t508;
    const T t515 = t512*t503;
    const T t516 = -t514 + t515;
    const T t517 = (T(0.5))*t496;
    const T t518 = t513*t495 - t516*t517;
    const T t519 = -t510*t511 + T(1);
    const T t520 = -t513*t494 + (T(0.5))*t519*t496;
    const T t521 = (T(0.5))*t516;
    const T t522 = (T(0.5))*t519;
    const T t523 = t521*t494 - t522*t495;
    const T t524 = t513*t498 - t521*t499;
    const T t525 = -t513*t497 + (T(0.5))*t519*t499;
    const T t526 = t521*t497 - t522*t498;
    const T t527 = t513*t501 - t521*t502;
    const T t528 = -t513*t500 + (T(0.5))*t519*t502;
    const T t529 = t521*t500 - t522*t501;
    const T t530 = (T(0.5))*t505;
    const T t531 = t503*t508;
    const T t532 = t511*t531;
    const T t533 = -T(0.5)*t530 + (T(0.5))*t532;
    const T t534 = t511*(-t506 - t509) + T(1);
    const T t535 = -t517*t534 + t533*t495;
    const T t536 = t514 + t515;
    const T t537 = -t533*t494 + (T(0.5))*t536*t496;
    const T t538 = (T(0.5))*t534;
    const T t539 = (T(0.5))*t536;
    const T t540 = t538*t494 - t539*t495;
    const T t541 = t533*t498 - t538*t499;
    const T t542 = -t533*t497 + (T(0.5))*t536*t499;
    const T t543 = t538*t497 - t539*t498;
    const T t544 = t533*t501 - t538*t502;
    const T t545 = -t533*t500 + (T(0.5))*t536*t502;
    const T t546 = t538*t500 - t539*t501;
    const T t547 = (T(0.5))*t511*(-t506 - t507) + T(0.5);
    const T t548 = t530 + t532;
    const T t549 = -t517*t548 + t547*t495;
    const T t550 = -t504 + t511*t508*t505;
    const T t551 = -t547*t494 + (T(0.5))*t550*t496;
    const T t552 = (T(0.5))*t548;
    const T t553 = (T(0.5))*t550;
    const T t554 = t552*t494 - t553*t495;
    const T t555 = t547*t498 - t552*t499;
    const T t556 = -t547*t497 + (T(0.5))*t550*t499;
    const T t557 = t552*t497 - t553*t498;
    const T t558 = t547*t501 - t552*t502;
    const T t559 = -t547*t500 + (T(0.5))*t550*t502;
    const T t560 = t552*t500 - t553*t501;
    const T t561 = T(2)*t503;
    const T t562 = T(2)*t508;
    const T t563 = T(2)*t505;
    const T t564 = t507;
    const T t565 = t509;
    const T t566 = t564 + t565;
    const T t567 = t506;
    const T t568 = t566 + t567;
    const T t569 = lie_D1(t568);
    const T t570 = -t203;
    const T t571 = -t207;
    const T t572 = -t211;
    const T t573 = t570*in[2] + t571*in[5] + t572*in[8];
    const T t574 = t570*in[1] + t571*in[4] + t572*in[7];
    const T t575 = -in[0]*in[1] - in[3]*in[4] - in[6]*in[7];
    const T t576 = -in[0]*in[2] - in[3]*in[5] - in[6]*in[8];
    const T t577 = t570*in[0] + t571*in[3] + t572*in[6];
    const T t578 = -in[1]*in[2] - in[4]*in[5] - in[7]*in[8];
    const T t579 = lie_D(t568);
    const T t580 = t503*t579;
    const T t581 = t508*t579;
    const T t582 = -t566*t579 + T(1);
    const T t583 = t514;
    const T t584 = t579*t505;
    const T t585 = t503*t584;
    const T t586 = t583 + t585;
    const T t587 = t504;
    const T t588 = t508*t584;
    const T t589 = -t587 + t588;
    const T t590 = -t583 + t585;
    const T t591 = -t565 - t567;
    const T t592 = t591*t579 + T(1);
    const T t593 = t530;
    const T t594 = t531*t579;
    const T t595 = t593 + t594;
    const T t596 = t587 + t588;
    const T t597 = -t593 + t594;
    const T t598 = -t564 - t567;
    const T t599 = t598*t579 + T(1);
    const T t600 = -in[0]*in[9] + in[0]*in[24] - in[3]*in[10] + in[3]*in[25] - in[6]*in[11] + in[6]*in[26];
    const T t601 = -in[1]*in[9] + in[1]*in[24] - in[4]*in[10] + in[4]*in[25] - in[7]*in[11] + in[7]*in[26];
    const T t602 = -in[2]*in[9] + in[2]*in[24] - in[5]*in[10] + in[5]*in[25] - in[8]*in[11] + in[8]*in[26];
    const T t603 = t600*dat[73] + t601*dat[76] + t602*dat[79] - dat[73]*dat[82] - dat[76]*dat[83] - dat[79]*dat[84];
    const T t604 = t566*t603;
    const T t605 = t579*t603;
    const T t606 = t600*dat[74] + t601*dat[77] + t602*dat[80] - dat[74]*dat[82] - dat[77]*dat[83] - dat[80]*dat[84];
    const T t607 = t591*t606;
    const T t608 = t579*t606;
    const T t609 = t600*dat[75] + t601*dat[78] + t602*dat[81] - dat[75]*dat[82] - dat[78]*dat[83] - dat[81]*dat[84];
    const T t610 = t598*t609;
    const T t611 = t579*t609;
    const T t612 = t165*t229 + t168*t230 + t171*t233 + t172*t234 + t173*t235 + t174*t238 + t175*t239 + t176*t240 + t177*t228;
    const T t613 = t165*t248 + t168*t249 + t171*t252 + t172*t253 + t173*t254 + t174*t257 + t175*t258 + t176*t259 + t177*t247;
    const T t614 = t165*t266 + t168*t267 + t171*t270 + t172*t271 + t173*t272 + t174*t275 + t175*t276 + t176*t277 + t177*t265;
    const T t615 = t171*t284 + t172*t285 + t173*t286 + t174*t290 + t175*t291 + t176*t292;
    const T t616 = t165*t300 + t168*t301 + t174*t305 + t175*t306 + t176*t307 + t177*t299;
    const T t617 = t165*t315 + t168*t316 + t171*t320 + t172*t321 + t173*t322 + t177*t314;
    const T t618 = t165*t338 + t168*t342 + t171*t343 + t172*t344 + t173*t345 + t174*t346 + t175*t347 + t176*t348 + t177*t334;
    const T t619 = t165*t364 + t168*t368 + t171*t369 + t172*t370 + t173*t371 + t174*t372 + t175*t373 + t176*t374 + t177*t360;
    const T t620 = t165*t390 + t168*t394 + t171*t395 + t172*t396 + t173*t397 + t174*t398 + t175*t399 + t176*t400 + t177*t386;
    const T t621 = t165*t416 + t168*t420 + t171*t421 + t172*t422 + t173*t423 + t174*t424 + t175*t425 + t176*t426 + t177*t412;
    const T t622 = t165*t442 + t168*t446 + t171*t447 + t172*t448 + t173*t449 + t174*t450 + t175*t451 + t176*t452 + t177*t438;
    const T t623 = t165*t468 + t168*t472 + t171*t473 + t172*t474 + t173*t475 + t174*t476 + t175*t477 + t176*t478 + t177*t464;
    const T t624 = t187*t233 + t188*t234 + t189*t235 + t190*t238 + t191*t239 + t192*t240 + t193*t228 + t180*t229 + t184*t230;
    const T t625 = t187*t252 + t188*t253 + t189*t254 + t190*t257 + t191*t258 + t192*t259 + t193*t247 + t180*t248 + t184*t249;
    const T t626 = t187*t270 + t188*t271 + t189*t272 + t190*t275 + t191*t276 + t192*t277 + t193*t265 + t180*t266 + t184*t267;
    const T t627 = t187*t284 + t188*t285 + t189*t286 + t190*t290 + t191*t291 + t192*t292;
    const T t628 = t190*t305 + t191*t306 + t192*t307 + t193*t299 + t180*t300 + t184*t301;
    const T t629 = t187*t320 + t188*t321 + t189*t322 + t193*t314 + t180*t315 + t184*t316;
    const T t630 = t187*t343 + t188*t344 + t189*t345 + t190*t346 + t191*t347 + t192*t348 + t193*t334 + t180*t338 + t184*t342;
    const T t631 = t187*t369 + t188*t370 + t189*t371 + t190*t372 + t191*t373 + t192*t374 + t193*t360 + t180*t364 + t184*t368;
    const T t632 = t187*t395 + t188*t396 + t189*t397 + t190*t398 + t191*t399 + t192*t400 + t193*t386 + t180*t390 + t184*t394;
    const T t633 = t187*t421 + t188*t422 + t189*t423 + t190*t424 + t191*t425 + t192*t426 + t193*t412 + t180*t416 + t184*t420;
    const T t634 = t187*t447 + t188*t448 + t189*t449 + t190*t450 + t191*t451 + t192*t452 + t193*t438 + t180*t442 + t184*t446;
    const T t635 = t187*t473 + t188*t474 + t189*t475 + t190*t476 + t191*t477 + t192*t478 + t193*t464 + t180*t468 + t184*t472;
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
    const T t672 = t202*t660 + t202*t242;
    const T t673 = t202*t661 + t202*t261;
    const T t674 = t202*t662 + t202*t279;
    const T t675 = t202*t663 + t202*t294;
    const T t676 = t202*t664 + t202*t309;
    const T t677 = t202*t665 + t202*t324;
    const T t678 = t202*t666 + t202*t350;
    const T t679 = t202*t667 + t202*t376;
    const T t680 = t202*t668 + t202*t402;
    const T t681 = t202*t669 + t202*t428;
    const T t682 = t202*t670 + t202*t454;
    const T t683 = t202*t671 + t202*t480;
    const T t684 = -t199*t243 + T(1);
    const T t685 = -t199*t672 - t243*t660;
    const T t686 = -t199*t673 - t243*t661;
    const T t687 = -t199*t674 - t243*t662;
    const T t688 = -t199*t675 - t243*t663;
    const T t689 = -t199*t676 - t243*t664;
    const T t690 = -t199*t677 - t243*t665;
    const T t691 = -t199*t678 - t243*t666;
    const T t692 = -t199*t679 - t243*t667;
    const T t693 = -t199*t680 - t243*t668;
    const T t694 = -t199*t681 - t243*t669;
    const T t695 = -t199*t682 - t243*t670;
    const T t696 = -t199*t683 - t243*t671;
    const T t697 = t216*in[2] - t217*in[1];
    const T t698 = -t215*in[2] + t217*in[0];
    const T t699 = t215*in[1] - t216*in[0];
    const T t700 = t204;
    const T t701 = t205;
    const T t702 = t206;
    const T t703 = dat[18]*in[0] + dat[21]*in[1] + dat[24]*in[2];
    const T t704 = dat[19]*in[0] + dat[22]*in[1] + dat[25]*in[2];
    const T t705 = dat[20]*in[0] + dat[23]*in[1] + dat[26]*in[2];
    const T t706 = dat[45]*in[0] + dat[48]*in[1] + dat[51]*in[2];
    const T t707 = dat[46]*in[0] + dat[49]*in[1] + dat[52]*in[2];
    const T t708 = dat[47]*in[0] + dat[50]*in[1] + dat[53]*in[2];
    const T t709 = t216*in[5] - t217*in[4];
    const T t710 = -t215*in[5] + t217*in[3];
    const T t711 = t215*in[4] - t216*in[3];
    const T t712 = t208;
    const T t713 = t209;
    const T t714 = t210;
    const T t715 = dat[18]*in[3] + dat[21]*in[4] + dat[24]*in[5];
    const T t716 = dat[19]*in[3] + dat[22]*in[4] + dat[25]*in[5];
    const T t717 = dat[20]*in[3] + dat[23]*in[4] + dat[26]*in[5];
    const T t718 = dat[45]*in[3] + dat[48]*in[4] + dat[51]*in[5];
    const T t719 = dat[46]*in[3] + dat[49]*in[4] + dat[52]*in[5];
    const T t720 = dat[47]*in[3] + dat[50]*in[4] + dat[53]*in[5];
    const T t721 = t216*in[8] - t217*in[7];
    const T t722 = -t215*in[8] + t217*in[6];
    const T t723 = t215*in[7] - t216*in[6];
    const T t724 = t212;
    const T t725 = t213;
    const T t726 = t214;
    const T t727 = dat[18]*in[6] + dat[21]*in[7] + dat[24]*in[8];
    const T t728 = dat[19]*in[6] + dat[22]*in[7] + dat[25]*in[8];
    const T t729 = dat[20]*in[6] + dat[23]*in[7] + dat[26]*in[8];
    const T t730 = dat[45]*in[6] + dat[48]*in[7] + dat[51]*in[8];
    const T t731 = dat[46]*in[6] + dat[49]*in[7] + dat[52]*in[8];
    const T t732 = dat[47]*in[6] + dat[50]*in[7] + dat[53]*in[8];
    const T t733 = t222;
    const T t734 = t697*in[15] + t709*in[18] + t721*in[21];
    const T t735 = t698*in[15] + t710*in[18] + t722*in[21];
    const T t736 = t699*in[15] + t711*in[18] + t723*in[21];
    const T t737 = t56;
    const T t738 = t59;
    const T t739 = t57;
    const T t740 = dat[69]*in[15];
    const T t741 = dat[69]*in[18];
    const T t742 = dat[69]*in[21];
    const T t743 = -t223;
    const T t744 = t224;
    const T t745 = t700*in[15] + t712*in[18] + t724*in[21];
    const T t746 = t701*in[15] + t713*in[18] + t725*in[21];
    const T t747 = t702*in[15] + t714*in[18] + t726*in[21];
    const T t748 = t703*in[15] + t715*in[18] + t727*in[21];
    const T t749 = t704*in[15] + t716*in[18] + t728*in[21];
    const T t750 = t705*in[15] + t717*in[18] + t729*in[21];
    const T t751 = t706*in[15] + t718*in[18] + t730*in[21];
    const T t752 = t707*in[15] + t719*in[18] + t731*in[21];
    const T t753 = t708*in[15] + t720*in[18] + t732*in[21];
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
    const T t768 = t135*t672 + t243*t241;
    const T t769 = t135*t673 + t243*t260;
    const T t770 = t135*t674 + t243*t278;
    const T t771 = t135*t675 + t243*t293;
    const T t772 = t135*t676 + t243*t308;
    const T t773 = t135*t677 + t243*t323;
    const T t774 = t135*t678 + t243*t349;
    const T t775 = t135*t679 + t243*t375;
    const T t776 = t135*t680 + t243*t401;
    const T t777 = t135*t681 + t243*t427;
    const T t778 = t135*t682 + t243*t453;
    const T t779 = t135*t683 + t243*t479;
    const T t780 = t133*t767;
    const T t781 = t133*t768 + t767*t612;
    const T t782 = t133*t769 + t767*t613;
    const T t783 = t133*t770 + t767*t614;
    const T t784 = t133*t771 + t767*t615;
    const T t785 = t133*t772 + t767*t616;
    const T t786 = t133*t773 + t767*t617;
    const T t787 = t133*t774 + t767*t618;
    const T t788 = t133*t775 + t767*t619;
    const T t789 = t133*t776 + t767*t620;
    const T t790 = t133*t777 + t767*t621;
    const T t791 = t133*t778 + t767*t622;
    const T t792 = t133*t779 + t767*t623;
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
    const T t807 = t697*in[16] + t709*in[19] + t721*in[22];
    const T t808 = t698*in[16] + t710*in[19] + t722*in[22];
    const T t809 = t699*in[16] + t711*in[19] + t723*in[22];
    const T t810 = t62;
    const T t811 = t67;
    const T t812 = t71;
    const T t813 = dat[69]*in[16];
    const T t814 = dat[69]*in[19];
    const T t815 = dat[69]*in[22];
    const T t816 = t223;
    const T t817 = -t222;
    const T t818 = t700*in[16] + t712*in[19] + t724*in[22];
    const T t819 = t701*in[16] + t713*in[19] + t725*in[22];
    const T t820 = t702*in[16] + t714*in[19] + t726*in[22];
    const T t821 = t703*in[16] + t715*in[19] + t727*in[22];
    const T t822 = t704*in[16] + t716*in[19] + t728*in[22];
    const T t823 = t705*in[16] + t717*in[19] + t729*in[22];
    const T t824 = t706*in[16] + t718*in[19] + t730*in[22];
    const T t825 = t707*in[16] + t719*in[19] + t731*in[22];
    const T t826 = t708*in[16] + t720*in[19] + t732*in[22];
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
    const T t841 = t138*t768 + t767*t624;
    const T t842 = t138*t769 + t767*t625;
    const T t843 = t138*t770 + t767*t626;
    const T t844 = t138*t771 + t767*t627;
    const T t845 = t138*t772 + t767*t628;
    const T t846 = t138*t773 + t767*t629;
    const T t847 = t138*t774 + t767*t630;
    const T t848 = t138*t775 + t767*t631;
    const T t849 = t138*t776 + t767*t632;
    const T t850 = t138*t777 + t767*t633;
    const T t851 = t138*t778 + t767*t634;
    const T t852 = t138*t779 + t767*t635;
    const T t853 = -t827 + t840;
    const T t854 = -t828 + t841;
    const T t855 = -t829 + t842;
    const T t856 = -t830 + t843;
    const T t857 = -t831 + t844;
    const T t858 = -t832 + t845;
    const T t859 = -t833 + t846;
    const T t860 = -t834 + t847;
    const T t861 = -t835 + t848;
    const T t862 = -t836 + t849;
    const T t863 = -t837 + t850;
    const T t864 = -t838 + t851;
    const T t865 = -t839 + t852;
    const T t866 = t223;
    const T t867 = t697*in[17] + t709*in[20] + t721*in[23];
    const T t868 = t698*in[17] + t710*in[20] + t722*in[23];
    const T t869 = t699*in[17] + t711*in[20] + t723*in[23];
    const T t870 = t60;
    const T t871 = t65;
    const T t872 = t69;
    const T t873 = dat[69]*in[17];
    const T t874 = dat[69]*in[20];
    const T t875 = dat[69]*in[23];
    const T t876 = -t224;
    const T t877 = t222;
    const T t878 = t700*in[17] + t712*in[20] + t724*in[23];
    const T t879 = t701*in[17] + t713*in[20] + t725*in[23];
    const T t880 = t702*in[17] + t714*in[20] + t726*in[23];
    const T t881 = t703*in[17] + t715*in[20] + t727*in[23];
    const T t882 = t704*in[17] + t716*in[20] + t728*in[23];
    const T t883 = t705*in[17] + t717*in[20] + t729*in[23];
    const T t884 = t706*in[17] + t718*in[20] + t730*in[23];
    const T t885 = t707*in[17] + t719*in[20] + t731*in[23];
    const T t886 = t708*in[17] + t720*in[20] + t732*in[23];
    const T t887 = t225*t243 + T(1);
    const T t888 = t225*t672 - t244 - t243*t648;
    const T t889 = t225*t673 - t262 - t243*t649;
    const T t890 = t225*t674 - t280 - t243*t650;
    const T t891 = t225*t675 - t295 - t243*t651;
    const T t892 = t225*t676 - t310 - t243*t652;
    const T t893 = t225*t677 - t325 - t243*t653;
    const T t894 = t225*t678 - t351 - t243*t654;
    const T t895 = t225*t679 - t377 - t243*t655;
    const T t896 = t225*t680 - t403 - t243*t656;
    const T t897 = t225*t681 - t429 - t243*t657;
    const T t898 = t225*t682 - t455 - t243*t658;
    const T t899 = t225*t683 - t481 - t243*t659;
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
    const T t914 = t482*t624 + t483*t612 + t181*t672;
    const T t915 = t482*t625 + t483*t613 + t181*t673;
    const T t916 = t482*t626 + t483*t614 + t181*t674;
    const T t917 = t482*t627 + t483*t615 + t181*t675;
    const T t918 = t482*t628 + t483*t616 + t181*t676;
    const T t919 = t482*t629 + t483*t617 + t181*t677;
    const T t920 = t482*t630 + t483*t618 + t181*t678;
    const T t921 = t482*t631 + t483*t619 + t181*t679;
    const T t922 = t482*t632 + t483*t620 + t181*t680;
    const T t923 = t482*t633 + t483*t621 + t181*t681;
    const T t924 = t482*t634 + t483*t622 + t181*t682;
    const T t925 = t482*t635 + t483*t623 + t181*t683;
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
    const T t939 = -t754 + t780;
    const T t940 = -t755 + t781;
    const T t941 = -t756 + t782;
    const T t942 = -t757 + t783;
    const T t943 = -t758 + t784;
    const T t944 = -t759 + t785;
    const T t945 = -t760 + t786;
    const T t946 = -t761 + t787;
    const T t947 = -t762 + t788;
    const T t948 = -t763 + t789;
    const T t949 = -t764 + t790;
    const T t950 = -t765 + t791;
    const T t951 = -t766 + t792;
    const T t952 = t484*t243 + T(1);
    const T t953 = -t244 + t484*t672 - t243*t636;
    const T t954 = -t262 + t484*t673 - t243*t637;
    const T t955 = -t280 + t484*t674 - t243*t638;
    const T t956 = -t295 + t484*t675 - t243*t639;
    const T t957 = -t310 + t484*t676 - t243*t640;
    const T t958 = -t325 + t484*t677 - t243*t641;
    const T t959 = -t351 + t484*t678 - t243*t642;
    const T t960 = -t377 + t484*t679 - t243*t643;
    const T t961 = -t403 + t484*t680 - t243*t644;
    const T t962 = -t429 + t484*t681 - t243*t645;
    const T t963 = -t455 + t484*t682 - t243*t646;
    const T t964 = -t481 + t484*t683 - t243*t647;
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
    const T t978 = -t900 + t913;
    const T t979 = -t901 + t914;
    const T t980 = -t902 + t915;
    const T t981 = -t903 + t916;
    const T t982 = -t904 + t917;
    const T t983 = -t905 + t918;
    const T t984 = -t906 + t919;
    const T t985 = -t907 + t920;
    const T t986 = -t908 + t921;
    const T t987 = -t909 + t922;
    const T t988 = -t910 + t923;
    const T t989 = -t911 + t924;
    const T t990 = -t912 + t925;
    const T t991 = t486*in[2] - t487*in[1];
    const T t992 = -t485*in[2] + t487*in[0];
    const T t993 = t485*in[1] - t486*in[0];
    const T t994 = dat[27]*in[0] + dat[30]*in[1] + dat[33]*in[2];
    const T t995 = dat[28]*in[0] + dat[31]*in[1] + dat[34]*in[2];
    const T t996 = dat[29]*in[0] + dat[32]*in[1] + dat[35]*in[2];
    const T t997 = dat[54]*in[0] + dat[57]*in[1] + dat[60]*in[2];
    const T t998 = dat[55]*in[0] + dat[58]*in[1] + dat[61]*in[2];
    const T t999 = dat[56]*in[0] + dat[59]*in[1] + dat[62]*in[2];
    const T t1000 = t486*in[5] - t487*in[4];
    const T t1001 = -t485*in[5] + t487*in[3];
    const T t1002 = t485*in[4] - t486*in[3];
    const T t1003 = dat[27]*in[3] + dat[30]*in[4] + dat[33]*in[5];
    const T t1004 = dat[28]*in[3] + dat[31]*in[4] + dat[34]*in[5];
    const T t1005 = dat[29]*in[3] + dat[32]*in[4] + dat[35]*in[5];
    const T t1006 = dat[54]*in[3] + dat[57]*in[4] + dat[60]*in[5];
    const T t1007 = dat[55]*in[3] + dat[58]*in[4] + dat[61]*in[5];
    const T t1008 = dat[56]*in[3] + dat[59]*in[4] + dat[62]*in[5];
    const T t1009 = t486*in[8] - t487*in[7];
    const T t1010 = -t485*in[8] + t487*in[6];
    const T t1011 = t485*in[7] - t486*in[6];
    const T t1012 = dat[27]*in[6] + dat[30]*in[7] + dat[33]*in[8];
    const T t1013 = dat[28]*in[6] + dat[31]*in[7] + dat[34]*in[8];
    const T t1014 = dat[29]*in[6] + dat[32]*in[7] + dat[35]*in[8];
    const T t1015 = dat[54]*in[6] + dat[57]*in[7] + dat[60]*in[8];
    const T t1016 = dat[55]*in[6] + dat[58]*in[7] + dat[61]*in[8];
    const T t1017 = dat[56]*in[6] + dat[59]*in[7] + dat[62]*in[8];
    const T t1018 = t491;
    const T t1019 = t991*in[15] + t1000*in[18] + t1009*in[21];
    const T t1020 = t992*in[15] + t1001*in[18] + t1010*in[21];
    const T t1021 = t993*in[15] + t1002*in[18] + t1011*in[21];
    const T t1022 = -t492;
    const T t1023 = t493;
    const T t1024 = t204;
    const T t1025 = t208;
    const T t1026 = t212;
    const T t1027 = t994*in[15] + t1003*in[18] + t1012*in[21];
    const T t1028 = t995*in[15] + t1004*in[18] + t1013*in[21];
    const T t1029 = t996*in[15] + t1005*in[18] + t1014*in[21];
    const T t1030 = t997*in[15] + t1006*in[18] + t1015*in[21];
    const T t1031 = t998*in[15] + t1007*in[18] + t1016*in[21];
    const T t1032 = t999*in[15] + t1008*in[18] + t1017*in[21];
    const T t1033 = t493;
    const T t1034 = t991*in[16] + t1000*in[19] + t1009*in[22];
    const T t1035 = t992*in[16] + t1001*in[19] + t1010*in[22];
    const T t1036 = t993*in[16] + t1002*in[19] + t1011*in[22];
    const T t1037 = t492;
    const T t1038 = -t491;
    const T t1039 = t205;
    const T t1040 = t209;
    const T t1041 = t213;
    const T t1042 = t994*in[16] + t1003*in[19] + t1012*in[22];
    const T t1043 = t995*in[16] + t1004*in[19] + t1013*in[22];
    const T t1044 = t996*in[16] + t1005*in[19] + t1014*in[22];
    const T t1045 = t997*in[16] + t1006*in[19] + t1015*in[22];
    const T t1046 = t998*in[16] + t1007*in[19] + t1016*in[22];
    const T t1047 = t999*in[16] + t1008*in[19] + t1017*in[22];
    const T t1048 = t492;
    const T t1049 = t991*in[17] + t1000*in[20] + t1009*in[23];
    const T t1050 = t992*in[17] + t1001*in[20] + t1010*in[23];
    const T t1051 = t993*in[17] + t1002*in[20] + t1011*in[23];
    const T t1052 = -t493;
    const T t1053 = t491;
    const T t1054 = t206;
    const T t1055 = t210;
    const T t1056 = t214;
    const T t1057 = t994*in[17] + t1003*in[20] + t1012*in[23];
    const T t1058 = t995*in[17] + t1004*in[20] + t1013*in[23];
    const T t1059 = t996*in[17] + t1005*in[20] + t1014*in[23];
    const T t1060 = t997*in[17] + t1006*in[20] + t1015*in[23];
    const T t1061 = t998*in[17] + t1007*in[20] + t1016*in[23];
    const T t1062 = t999*in[17] + t1008*in[20] + t1017*in[23];
    const T t1063 = t226*dat[76] + t227*dat[79];
    const T t1064 = t245*dat[73] + t246*dat[79];
    const T t1065 = t263*dat[73] + t264*dat[76];
    const T t1066 = t296*dat[73] + t297*dat[76] + t298*dat[79];
    const T t1067 = t311*dat[73] + t312*dat[76] + t313*dat[79];
    const T t1068 = t231*dat[76] + t232*dat[79];
    const T t1069 = t250*dat[73] + t251*dat[79];
    const T t1070 = t268*dat[73] + t269*dat[76];
    const T t1071 = t281*dat[73] + t282*dat[76] + t283*dat[79];
    const T t1072 = t317*dat[73] + t318*dat[76] + t319*dat[79];
    const T t1073 = t236*dat[76] + t237*dat[79];
    const T t1074 = t255*dat[73] + t256*dat[79];
    const T t1075 = t273*dat[73] + t274*dat[76];
    const T t1076 = t287*dat[73] + t288*dat[76] + t289*dat[79];
    const T t1077 = t302*dat[73] + t303*dat[76] + t304*dat[79];
    const T t1078 = t226*dat[77] + t227*dat[80];
    const T t1079 = t245*dat[74] + t246*dat[80];
    const T t1080 = t263*dat[74] + t264*dat[77];
    const T t1081 = t296*dat[74] + t297*dat[77] + t298*dat[80];
    const T t1082 = t311*dat[74] + t312*dat[77] + t313*dat[80];
    const T t1083 = t231*dat[77] + t232*dat[80];
    const T t1084 = t250*dat[74] + t251*dat[80];
    const T t1085 = t268*dat[74] + t269*dat[77];
    const T t1086 = t281*dat[74] + t282*dat[77] + t283*dat[80];
    const T t1087 = t317*dat[74] + t318*dat[77] + t319*dat[80];
    const T t1088 = t236*dat[77] + t237*dat[80];
    const T t1089 = t255*dat[74] + t256*dat[80];
    const T t1090 = t273*dat[74] + t274*dat[77];
    const T t1091 = t287*dat[74] + t288*dat[77] + t289*dat[80];
    const T t1092 = t302*dat[74] + t303*dat[77] + t304*dat[80];
    const T t1093 = t226*dat[78] + t227*dat[81];
    const T t1094 = t245*dat[75] + t246*dat[81];
    const T t1095 = t263*dat[75] + t264*dat[78];
    const T t1096 = t296*dat[75] + t297*dat[78] + t298*dat[81];
    const T t1097 = t311*dat[75] + t312*dat[78] + t313*dat[81];
    const T t1098 = t231*dat[78] + t232*dat[81];
    const T t1099 = t250*dat[75] + t251*dat[81];
    const T t1100 = t268*dat[75] + t269*dat[78];
    const T t1101 = t281*dat[75] + t282*dat[78] + t283*dat[81];
    const T t1102 = t317*dat[75] + t318*dat[78] + t319*dat[81];
    const T t1103 = t236*dat[78] + t237*dat[81];
    const T t1104 = t255*dat[75] + t256*dat[81];
    const T t1105 = t273*dat[75] + t274*dat[78];
    const T t1106 = t287*dat[75] + t288*dat[78] + t289*dat[81];
    const T t1107 = t302*dat[75] + t303*dat[78] + t304*dat[81];
    const T t1108 = t518*t1063 + t520*t1068 + t523*t1073 + t524*t1078 + t525*t1083 + t526*t1088 + t527*t1093 + t528*t1098 + t529*t1103;
    const T t1109 = t518*t1064 + t520*t1069 + t523*t1074 + t524*t1079 + t525*t1084 + t526*t1089 + t527*t1094 + t528*t1099 + t529*t1104;
    const T t1110 = t518*t1065 + t520*t1070 + t523*t1075 + t524*t1080 + t525*t1085 + t526*t1090 + t527*t1095 + t528*t1100 + t529*t1105;
    const T t1111 = t520*t1071 + t523*t1076 + t525*t1086 + t526*t1091 + t528*t1101 + t529*t1106;
    const T t1112 = t518*t1066 + t523*t1077 + t524*t1081 + t526*t1092 + t527*t1096 + t529*t1107;
    const T t1113 = t518*t1067 + t520*t1072 + t524*t1082 + t525*t1087 + t527*t1097 + t528*t1102;
    const T t1114 = t535*t1063 + t537*t1068 + t540*t1073 + t541*t1078 + t542*t1083 + t543*t1088 + t544*t1093 + t545*t1098 + t546*t1103;
    const T t1115 = t535*t1064 + t537*t1069 + t540*t1074 + t541*t1079 + t542*t1084 + t543*t1089 + t544*t1094 + t545*t1099 + t546*t1104;
    const T t1116 = t535*t1065 + t537*t1070 + t540*t1075 + t541*t1080 + t542*t1085 + t543*t1090 + t544*t1095 + t545*t1100 + t546*t1105;
    const T t1117 = t537*t1071 + t540*t1076 + t542*t1086 + t543*t1091 + t545*t1101 + t546*t1106;
    const T t1118 = t535*t1066 + t540*t1077 + t541*t1081 + t543*t1092 + t544*t1096 + t546*t1107;
    const T t1119 = t535*t1067 + t537*t1072 + t541*t1082 + t542*t1087 + t544*t1097 + t545*t1102;
    const T t1120 = t549*t1063 + t551*t1068 + t554*t1073 + t555*t1078 + t556*t1083 + t557*t1088 + t558*t1093 + t559*t1098 + t560*t1103;
    const T t1121 = t549*t1064 + t551*t1069 + t554*t1074 + t555*t1079 + t556*t1084 + t557*t1089 + t558*t1094 + t559*t1099 + t560*t1104;
    const T t1122 = t549*t1065 + t551*t1070 + t554*t1075 + t555*t1080 + t556*t1085 + t557*t1090 + t558*t1095 + t559*t1100 + t560*t1105;
    const T t1123 = t551*t1071 + t554*t1076 + t556*t1086 + t557*t1091 + t559*t1101 + t560*t1106;
    const T t1124 = t549*t1066 + t554*t1077 + t555*t1081 + t557*t1092 + t558*t1096 + t560*t1107;
    const T t1125 = t549*t1067 + t551*t1072 + t555*t1082 + t556*t1087 + t558*t1097 + t559*t1102;
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
    const T t1138 = t1126 + t1132;
    const T t1139 = t1127 + t1133;
    const T t1140 = t1128 + t1134;
    const T t1141 = t1129 + t1135;
    const T t1142 = t1130 + t1136;
    const T t1143 = t1131 + t1137;
    const T t1144 = t563*t1108;
    const T t1145 = t563*t1109;
    const T t1146 = t563*t1110;
    const T t1147 = t563*t1111;
    const T t1148 = t563*t1112;
    const T t1149 = t563*t1113;
    const T t1150 = t569*t1138 + t569*t1144;
    const T t1151 = t569*t1139 + t569*t1145;
    const T t1152 = t569*t1140 + t569*t1146;
    const T t1153 = t569*t1141 + t569*t1147;
    const T t1154 = t569*t1142 + t569*t1148;
    const T t1155 = t569*t1143 + t569*t1149;
    const T t1156 = -t573;
    const T t1157 = t574;
    const T t1158 = -(in[0]*in[0]) - (in[3]*in[3]) - (in[6]*in[6]);
    const T t1159 = t575;
    const T t1160 = t576;
    const T t1161 = t56;
    const T t1162 = t62;
    const T t1163 = t60;
    const T t1164 = t573;
    const T t1165 = -t577;
    const T t1166 = t575;
    const T t1167 = -(in[1]*in[1]) - (in[4]*in[4]) - (in[7]*in[7]);
    const T t1168 = t578;
    const T t1169 = t59;
    const T t1170 = t67;
    const T t1171 = t65;
    const T t1172 = -t574;
    const T t1173 = t577;
    const T t1174 = t576;
    const T t1175 = t578;
    const T t1176 = -(in[2]*in[2]) - (in[5]*in[5]) - (in[8]*in[8]);
    const T t1177 = t57;
    const T t1178 = t71;
    const T t1179 = t69;
    const T t1180 = t1164*dat[76] + t1172*dat[79];
    const T t1181 = t1156*dat[73] + t1173*dat[79];
    const T t1182 = t1157*dat[73] + t1165*dat[76];
    const T t1183 = t1158*dat[73] + t1166*dat[76] + t1174*dat[79];
    const T t1184 = t1159*dat[73] + t1167*dat[76] + t1175*dat[79];
    const T t1185 = t1160*dat[73] + t1168*dat[76] + t1176*dat[79];
    const T t1186 = t1161*dat[73] + t1169*dat[76] + t1177*dat[79];
    const T t1187 = t1162*dat[73] + t1170*dat[76] + t1178*dat[79];
    const T t1188 = t1163*dat[73] + t1171*dat[76] + t1179*dat[79];
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
    const T t1201 = t503*t1195 + t584*t1114;
    const T t1202 = t503*t1196 + t584*t1115;
    const T t1203 = t503*t1197 + t584*t1116;
    const T t1204 = t503*t1198 + t584*t1117;
    const T t1205 = t503*t1199 + t584*t1118;
    const T t1206 = t503*t1200 + t584*t1119;
    const T t1207 = t1164*dat[77] + t1172*dat[80];
    const T t1208 = t1156*dat[74] + t1173*dat[80];
    const T t1209 = t1157*dat[74] + t1165*dat[77];
    const T t1210 = t1158*dat[74] + t1166*dat[77] + t1174*dat[80];
    const T t1211 = t1159*dat[74] + t1167*dat[77] + t1175*dat[80];
    const T t1212 = t1160*dat[74] + t1168*dat[77] + t1176*dat[80];
    const T t1213 = t1161*dat[74] + t1169*dat[77] + t1177*dat[80];
    const T t1214 = t1162*dat[74] + t1170*dat[77] + t1178*dat[80];
    const T t1215 = t1163*dat[74] + t1171*dat[77] + t1179*dat[80];
    const T t1216 = (T(0.5))*t1114;
    const T t1217 = (T(0.5))*t1115;
    const T t1218 = (T(0.5))*t1116;
    const T t1219 = (T(0.5))*t1117;
    const T t1220 = (T(0.5))*t1118;
    const T t1221 = (T(0.5))*t1119;
    const T t1222 = t508*t1195 + t584*t1120;
    const T t1223 = t508*t1196 + t584*t1121;
    const T t1224 = t508*t1197 + t584*t1122;
    const T t1225 = t508*t1198 + t584*t1123;
    const T t1226 = t508*t1199 + t584*t1124;
    const T t1227 = t508*t1200 + t584*t1125;
    const T t1228 = t1164*dat[78] + t1172*dat[81];
    const T t1229 = t1156*dat[75] + t1173*dat[81];
    const T t1230 = t1157*dat[75] + t1165*dat[78];
    const T t1231 = t1158*dat[75] + t1166*dat[78] + t1174*dat[81];
    const T t1232 = t1159*dat[75] + t1167*dat[78] + t1175*dat[81];
    const T t1233 = t1160*dat[75] + t1168*dat[78] + t1176*dat[81];
    const T t1234 = t1161*dat[75] + t1169*dat[78] + t1177*dat[81];
    const T t1235 = t1162*dat[75] + t1170*dat[78] + t1178*dat[81];
    const T t1236 = t1163*dat[75] + t1171*dat[78] + t1179*dat[81];
    const T t1237 = (T(0.5))*t1108;
    const T t1238 = (T(0.5))*t1109;
    const T t1239 = (T(0.5))*t1110;
    const T t1240 = (T(0.5))*t1111;
    const T t1241 = (T(0.5))*t1112;
    const T t1242 = (T(0.5))*t1113;
    const T t1243 = t531*t1150 + t580*t1120 + t581*t1114;
    const T t1244 = t531*t1151 + t580*t1121 + t581*t1115;
    const T t1245 = t531*t1152 + t580*t1122 + t581*t1116;
    const T t1246 = t531*t1153 + t580*t1123 + t581*t1117;
    const T t1247 = t531*t1154 + t580*t1124 + t581*t1118;
    const T t1248 = t531*t1155 + t580*t1125 + t581*t1119;
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
    raw[96] = t684*t734 + t733*t685 + t793*t807 + t806*t794 + t853*t867 + t866*t854;
    raw[97] = t684*t735 + t733*t686 + t793*t808 + t806*t795 + t853*t868 + t866*t855;
    raw[98] = t684*t736 + t733*t687 + t793*t809 + t806*t796 + t853*t869 + t866*t856;
    raw[99] = t684*t737 + t793*t810 + t853*t870;
    raw[100] = t684*t738 + t793*t811 + t853*t871;
    raw[101] = t684*t739 + t793*t812 + t853*t872;
    raw[102] = t684*t740 + t793*t813 + t853*t873;
    raw[103] = t684*t741 + t793*t814 + t853*t874;
    raw[104] = t684*t742 + t793*t815 + t853*t875;
    raw[105] = t733*t688 + t793*t816 + t806*t797 + t853*t876 + t866*t857;
    raw[106] = t684*t743 + t733*t689 + t806*t798 + t853*t877 + t866*t858;
    raw[107] = t684*t744 + t733*t690 + t793*t817 + t806*t799 + t866*t859;
    raw[108] = t684*t745 + t793*t818 + t853*t878;
    raw[109] = t684*t746 + t793*t819 + t853*t879;
    raw[110] = t684*t747 + t793*t820 + t853*t880;
    raw[114] = t684*t748 + t733*t691 + t793*t821 + t806*t800 + t853*t881 + t866*t860;
    raw[115] = t684*t749 + t733*t692 + t793*t822 + t806*t801 + t853*t882 + t866*t861;
    raw[116] = t684*t750 + t733*t693 + t793*t823 + t806*t802 + t853*t883 + t866*t862;
    raw[117] = t684*t751 + t733*t694 + t793*t824 + t806*t803 + t853*t884 + t866*t863;
    raw[118] = t684*t752 + t733*t695 + t793*t825 + t806*t804 + t853*t885 + t866*t864;
    raw[119] = t684*t753 + t733*t696 + t793*t826 + t806*t805 + t853*t886 + t866*t865;
    raw[126] = t684*t733 + t793*t806 + t853*t866;
    raw[128] = t733*t940 + t806*t888 + t866*t927 + t887*t807 + t926*t867 + t939*t734;
    raw[129] = t733*t941 + t806*t889 + t866*t928 + t887*t808 + t926*t868 + t939*t735;
    raw[130] = t733*t942 + t806*t890 + t866*t929 + t887*t809 + t926*t869 + t939*t736;
    raw[131] = t887*t810 + t926*t870 + t939*t737;
    raw[132] = t887*t811 + t926*t871 + t939*t738;
    raw[133] = t887*t812 + t926*t872 + t939*t739;
    raw[134] = t887*t813 + t926*t873 + t939*t740;
    raw[135] = t887*t814 + t926*t874 + t939*t741;
    raw[136] = t887*t815 + t926*t875 + t939*t742;
    raw[137] = t733*t943 + t806*t891 + t866*t930 + t887*t816 + t926*t876;
    raw[138] = t733*t944 + t806*t892 + t866*t931 + t926*t877 + t939*t743;
    raw[139] = t733*t945 + t806*t893 + t866*t932 + t887*t817 + t939*t744;
    raw[140] = t887*t818 + t926*t878 + t939*t745;
    raw[141] = t887*t819 + t926*t879 + t939*t746;
    raw[142] = t887*t820 + t926*t880 + t939*t747;
    raw[146] = t733*t946 + t806*t894 + t866*t933 + t887*t821 + t926*t881 + t939*t748;
    raw[147] = t733*t947 + t806*t895 + t866*t934 + t887*t822 + t926*t882 + t939*t749;
    raw[148] = t733*t948 + t806*t896 + t866*t935 + t887*t823 + t926*t883 + t939*t750;
    raw[149] = t733*t949 + t806*t897 + t866*t936 + t887*t824 + t926*t884 + t939*t751;
    raw[150] = t733*t950 + t806*t898 + t866*t937 + t887*t825 + t926*t885 + t939*t752;
    raw[151] = t733*t951 + t806*t899 + t866*t938 + t887*t826 + t926*t886 + t939*t753;
    raw[158] = t733*t939 + t806*t887 + t866*t926;
    raw[160] = t733*t966 + t806*t979 + t866*t953 + t952*t867 + t965*t734 + t978*t807;
    raw[161] = t733*t967 + t806*t980 + t866*t954 + t952*t868 + t965*t735 + t978*t808;
    raw[162] = t733*t968 + t806*t981 + t866*t955 + t952*t869 + t965*t736 + t978*t809;
    raw[163] = t952*t870 + t965*t737 + t978*t810;
    raw[164] = t952*t871 + t965*t738 + t978*t811;
    raw[165] = t952*t872 + t965*t739 + t978*t812;
    raw[166] = t952*t873 + t965*t740 + t978*t813;
    raw[167] = t952*t874 + t965*t741 + t978*t814;
    raw[168] = t952*t875 + t965*t742 + t978*t815;
    raw[169] = t733*t969 + t806*t982 + t866*t956 + t952*t876 + t978*t816;
    raw[170] = t733*t970 + t806*t983 + t866*t957 + t952*t877 + t965*t743;
    raw[171] = t733*t971 + t806*t984 + t866*t958 + t965*t744 + t978*t817;
    raw[172] = t952*t878 + t965*t745 + t978*t818;
    raw[173] = t952*t879 + t965*t746 + t978*t819;
    raw[174] = t952*t880 + t965*t747 + t978*t820;
    raw[178] = t733*t972 + t806*t985 + t866*t959 + t952*t881 + t965*t748 + t978*t821;
    raw[179] = t733*t973 + t806*t986 + t866*t960 + t952*t882 + t965*t749 + t978*t822;
    raw[180] = t733*t974 + t806*t987 + t866*t961 + t952*t883 + t965*t750 + t978*t823;
    raw[181] = t733*t975 + t806*t988 + t866*t962 + t952*t884 + t965*t751 + t978*t824;
    raw[182] = t733*t976 + t806*t989 + t866*t963 + t952*t885 + t965*t752 + t978*t825;
    raw[183] = t733*t977 + t806*t990 + t866*t964 + t952*t886 + t965*t753 + t978*t826;
    raw[190] = t733*t965 + t806*t978 + t866*t952;
    raw[192] = t684*t1019 + t793*t1034 + t853*t1049 + t1018*t685 + t1033*t794 + t1048*t854;
    raw[193] = t684*t1020 + t793*t1035 + t853*t1050 + t1018*t686 + t1033*t795 + t1048*t855;
    raw[194] = t684*t1021 + t793*t1036 + t853*t1051 + t1018*t687 + t1033*t796 + t1048*t856;
    raw[198] = t684*in[15] + t793*in[16] + t853*in[17];
    raw[199] = t684*in[18] + t793*in[19] + t853*in[20];
    raw[200] = t684*in[21] + t793*in[22] + t853*in[23];
    raw[201] = t793*t1037 + t853*t1052 + t1018*t688 + t1033*t797 + t1048*t857;
    raw[202] = t684*t1022 + t853*t1053 + t1018*t689 + t1033*t798 + t1048*t858;
    raw[203] = t684*t1023 + t793*t1038 + t1018*t690 + t1033*t799 + t1048*t859;
    raw[207] = t684*t1024 + t793*t1039 + t853*t1054;
    raw[208] = t684*t1025 + t793*t1040 + t853*t1055;
    raw[209] = t684*t1026 + t793*t1041 + t853*t1056;
    raw[210] = t684*t1027 + t793*t1042 + t853*t1057 + t1018*t691 + t1033*t800 + t1048*t860;
    raw[211] = t684*t1028 + t793*t1043 + t853*t1058 + t1018*t692 + t1033*t801 + t1048*t861;
    raw[212] = t684*t1029 + t793*t1044 + t853*t1059 + t1018*t693 + t1033*t802 + t1048*t862;
    raw[213] = t684*t1030 + t793*t1045 + t853*t1060 + t1018*t694 + t1033*t803 + t1048*t863;
    raw[214] = t684*t1031 + t793*t1046 + t853*t1061 + t1018*t695 + t1033*t804 + t1048*t864;
    raw[215] = t684*t1032 + t793*t1047 + t853*t1062 + t1018*t696 + t1033*t805 + t1048*t865;
    raw[222] = t684*t1018 + t793*t1033 + t853*t1048;
    raw[224] = t887*t1034 + t926*t1049 + t939*t1019 + t1018*t940 + t1033*t888 + t1048*t927;
    raw[225] = t887*t1035 + t926*t1050 + t939*t1020 + t1018*t941 + t1033*t889 + t1048*t928;
    raw[226] = t887*t1036 + t926*t1051 + t939*t1021 + t1018*t942 + t1033*t890 + t1048*t929;
    raw[230] = t887*in[16] + t926*in[17] + t939*in[15];
    raw[231] = t887*in[19] + t926*in[20] + t939*in[18];
    raw[232] = t887*in[22] + t926*in[23] + t939*in[21];
    raw[233] = t887*t1037 + t926*t1052 + t1018*t943 + t1033*t891 + t1048*t930;
    raw[234] = t926*t1053 + t939*t1022 + t1018*t944 + t1033*t892 + t1048*t931;
    raw[235] = t887*t1038 + t939*t1023 + t1018*t945 + t1033*t893 + t1048*t932;
    raw[239] = t887*t1039 + t926*t1054 + t939*t1024;
    raw[240] = t887*t1040 + t926*t1055 + t939*t1025;
    raw[241] = t887*t1041 + t926*t1056 + t939*t1026;
    raw[242] = t887*t1042 + t926*t1057 + t939*t1027 + t1018*t946 + t1033*t894 + t1048*t933;
    raw[243] = t887*t1043 + t926*t1058 + t939*t1028 + t1018*t947 + t1033*t895 + t1048*t934;
    raw[244] = t887*t1044 + t926*t1059 + t939*t1029 + t1018*t948 + t1033*t896 + t1048*t935;
    raw[245] = t887*t1045 + t926*t1060 + t939*t1030 + t1018*t949 + t1033*t897 + t1048*t936;
    raw[246] = t887*t1046 + t926*t1061 + t939*t1031 + t1018*t950 + t1033*t898 + t1048*t937;
    raw[247] = t887*t1047 + t926*t1062 + t939*t1032 + t1018*t951 + t1033*t899 + t1048*t938;
    raw[254] = t887*t1033 + t926*t1048 + t939*t1018;
    raw[256] = t952*t1049 + t965*t1019 + t978*t1034 + t1018*t966 + t1033*t979 + t1048*t953;
    raw[257] = t952*t1050 + t965*t1020 + t978*t1035 + t1018*t967 + t1033*t980 + t1048*t954;
    raw[258] = t952*t1051 + t965*t1021 + t978*t1036 + t1018*t968 + t1033*t981 + t1048*t955;
    raw[262] = t952*in[17] + t965*in[15] + t978*in[16];
    raw[263] = t952*in[20] + t965*in[18] + t978*in[19];
    raw[264] = t952*in[23] + t965*in[21] + t978*in[22];
    raw[265] = t952*t1052 + t978*t1037 + t1018*t969 + t1033*t982 + t1048*t956;
    raw[266] = t952*t1053 + t965*t1022 + t1018*t970 + t1033*t983 + t1048*t957;
    raw[267] = t965*t1023 + t978*t1038 + t1018*t971 + t1033*t984 + t1048*t958;
    raw[271] = t952*t1054 + t965*t1024 + t978*t1039;
    raw[272] = t952*t1055 + t965*t1025 + t978*t1040;
    raw[273] = t952*t1056 + t965*t1026 + t978*t1041;
    raw[274] = t952*t1057 + t965*t1027 + t978*t1042 + t1018*t972 + t1033*t985 + t1048*t959;
    raw[275] = t952*t1058 + t965*t1028 + t978*t1043 + t1018*t973 + t1033*t986 + t1048*t960;
    raw[276] = t952*t1059 + t965*t1029 + t978*t1044 + t1018*t974 + t1033*t987 + t1048*t961;
    raw[277] = t952*t1060 + t965*t1030 + t978*t1045 + t1018*t975 + t1033*t988 + t1048*t962;
    raw[278] = t952*t1061 + t965*t1031 + t978*t1046 + t1018*t976 + t1033*t989 + t1048*t963;
    raw[279] = t952*t1062 + t965*t1032 + t978*t1047 + t1018*t977 + t1033*t990 + t1048*t964;
    raw[286] = t952*t1048 + t965*t1018 + t978*t1033;
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
    raw[576] = t582*t1180 + t586*t1207 + t589*t1228 - t604*t1150 - t605*t1138 + t606*t1189 + t606*t1201 - t609*t1216 + t609*t1222;
    raw[577] = t582*t1181 + t586*t1208 + t589*t1229 - t604*t1151 - t605*t1139 + t606*t1190 + t606*t1202 - t609*t1217 + t609*t1223;
    raw[578] = t582*t1182 + t586*t1209 + t589*t1230 - t604*t1152 - t605*t1140 + t606*t1191 + t606*t1203 - t609*t1218 + t609*t1224;
    raw[579] = t582*t1183 + t586*t1210 + t589*t1231;
    raw[580] = t582*t1184 + t586*t1211 + t589*t1232;
    raw[581] = t582*t1185 + t586*t1212 + t589*t1233;
    raw[585] = -t604*t1153 - t605*t1141 + t606*t1192 + t606*t1204 - t609*t1219 + t609*t1225;
    raw[586] = -t604*t1154 - t605*t1142 + t606*t1193 + t606*t1205 - t609*t1220 + t609*t1226;
    raw[587] = -t604*t1155 - t605*t1143 + t606*t1194 + t606*t1206 - t609*t1221 + t609*t1227;
    raw[588] = t582*t1186 + t586*t1213 + t589*t1234;
    raw[589] = t582*t1187 + t586*t1214 + t589*t1235;
    raw[590] = t582*t1188 + t586*t1215 + t589*t1236;
    raw[606] = t582*t603 + t586*t606 + t589*t609;
    raw[608] = t590*t1180 + t592*t1207 + t595*t1228 + t607*t1150 - t608*t1132 - t608*t1144 - t603*t1189 + t603*t1201 + t609*t1237 + t609*t1243;
    raw[609] = t590*t1181 + t592*t1208 + t595*t1229 + t607*t1151 - t608*t1133 - t608*t1145 - t603*t1190 + t603*t1202 + t609*t1238 + t609*t1244;
    raw[610] = t590*t1182 + t592*t1209 + t595*t1230 + t607*t1152 - t608*t1134 - t608*t1146 - t603*t1191 + t603*t1203 + t609*t1239 + t609*t1245;
    raw[611] = t590*t1183 + t592*t1210 + t595*t1231;
    raw[612] = t590*t1184 + t592*t1211 + t595*t1232;
    raw[613] = t590*t1185 + t592*t1212 + t595*t1233;
    raw[617] = t607*t1153 - t608*t1135 - t608*t1147 - t603*t1192 + t603*t1204 + t609*t1240 + t609*t1246;
    raw[618] = t607*t1154 - t608*t1136 - t608*t1148 - t603*t1193 + t603*t1205 + t609*t1241 + t609*t1247;
    raw[619] = t607*t1155 - t608*t1137 - t608*t1149 - t603*t1194 + t603*t1206 + t609*t1242 + t609*t1248;
    raw[620] = t590*t1186 + t592*t1213 + t595*t1234;
    raw[621] = t590*t1187 + t592*t1214 + t595*t1235;
    raw[622] = t590*t1188 + t592*t1215 + t595*t1236;
    raw[638] = t590*t603 + t592*t606 + t595*t609;
    raw[640] = t596*t1180 + t597*t1207 + t599*t1228 + t610*t1150 - t611*t1126 - t611*t1144 + t603*t1216 + t603*t1222 - t606*t1237 + t606*t1243;
    raw[641] = t596*t1181 + t597*t1208 + t599*t1229 + t610*t1151 - t611*t1127 - t611*t1145 + t603*t1217 + t603*t1223 - t606*t1238 + t606*t1244;
    raw[642] = t596*t1182 + t597*t1209 + t599*t1230 + t610*t1152 - t611*t1128 - t611*t1146 + t603*t1218 + t603*t1224 - t606*t1239 + t606*t1245;
    raw[643] = t596*t1183 + t597*t1210 + t599*t1231;
    raw[644] = t596*t1184 + t597*t1211 + t599*t1232;
    raw[645] = t596*t1185 + t597*t1212 + t599*t1233;
    raw[649] = t610*t1153 - t611*t1129 - t611*t1147 + t603*t1219 + t603*t1225 - t606*t1240 + t606*t1246;
    raw[650] = t610*t1154 - t611*t1130 - t611*t1148 + t603*t1220 + t603*t1226 - t606*t1241 + t606*t1247;
    raw[651] = t610*t1155 - t611*t1131 - t611*t1149 + t603*t1221 + t603*t1227 - t606*t1242 + t606*t1248;
    raw[652] = t596*t1186 + t597*t1213 + t599*t1234;
    raw[653] = t596*t1187 + t597*t1214 + t599*t1235;
    raw[654] = t596*t1188 + t597*t1215 + t599*t1236;
    raw[670] = t596*t603 + t597*t606 + t599*t609;
}

void factor_cost_3(const T in[42], const T dat[211],
                   T half[2]) {
#pragma HLS INLINE off
#pragma HLS ALLOCATION operation instances=fadd limit=8
#pragma HLS ALLOCATION operation instances=fmul limit=10
#pragma HLS ALLOCATION operation instances=fdiv limit=1
#pragma HLS ALLOCATION operation instances=fsqrt limit=1
    const T t0 = in[0]*in[15] + in[3]*in[18] + in[6]*in[21];
    const T t1 = t0;
    const T t2 = in[1]*in[15] + in[4]*in[18] + in[7]*in[21];
    const T t3 = t2;
    const T t4 = in[2]*in[15] + in[5]*in[18] + in[8]*in[21];
    const T t5 = t4;
    const T t6 = t1*dat[73] + t3*dat[76] + t5*dat[79];
    const T t7 = in[0]*in[16] + in[3]*in[19] + in[6]*in[22];
    const T t8 = t7;
    const T t9 = in[1]*in[16] + in[4]*in[19] + in[7]*in[22];
    const T t10 = t9;
    const T t11 = in[2]*in[16] + in[5]*in[19] + in[8]*in[22];
    const T t12 = t11;
    const T t13 = t8*dat[73] + t10*dat[76] + t12*dat[79];
    const T t14 = in[0]*in[17] + in[3]*in[20] + in[6]*in[23];
    const T t15 = t14;
    const T t16 = in[1]*in[17] + in[4]*in[20] + in[7]*in[23];
    const T t17 = t16;
    const T t18 = in[2]*in[17] + in[5]*in[20] + in[8]*in[23];
    const T t19 = t18;
    const T t20 = t15*dat[73] + t17*dat[76] + t19*dat[79];
    const T t21 = t1*dat[74] + t3*dat[77] + t5*dat[80];
    const T t22 = t8*dat[74] + t10*dat[77] + t12*dat[80];
    const T t23 = t15*dat[74] + t17*dat[77] + t19*dat[80];
    const T t24 = t1*dat[75] + t3*dat[78] + t5*dat[81];
    const T t25 = t8*dat[75] + t10*dat[78] + t12*dat[81];
    const T t26 = t15*dat[75] + t17*dat[78] + t19*dat[81];
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
    const T t39 = t33*dat[12] + t34*dat[13] + t35*dat[14] + t36*dat[39] + t37*dat[40] + t38*dat[41] + dat[1];
    const T t40 = -t39;
    const T t41 = t39*t40;
    const T t42 = t33*dat[15] + t34*dat[16] + t35*dat[17] + t36*dat[42] + t37*dat[43] + t38*dat[44] + dat[2];
    const T t43 = -t42;
    const T t44 = t43*t42;
    const T t45 = t44 + t41;
    const T t46 = t33*dat[9] + t34*dat[10] + t35*dat[11] + t36*dat[36] + t37*dat[37] + t38*dat[38] + dat[0];
    const T t47 = (t46*t46) + (t39*t39) + (t42*t42);
    const T t48 = lie_B(t47);
    const T t49 = t45*t48 + T(1);
    const T t50 = -t46;
    const T t51 = lie_A(t47);
    const T t52 = t48*t40;
    const T t53 = t51*t42 + t50*t52;
    const T t54 = t46*t48;
    const T t55 = t51*t40 + t54*t42;
    const T t56 = t49*t1 + t53*t3 + t55*t5;
    const T t57 = t46*t50;
    const T t58 = t44 + t57;
    const T t59 = t58*t48 + T(1);
    const T t60 = t43*t52 + t46*t51;
    const T t61 = t43*t51 + t54*t39;
    const T t62 = t1*t61 + t3*t59 + t5*t60;
    const T t63 = t57 + t41;
    const T t64 = t63*t48 + T(1);
    const T t65 = t43*t48;
    const T t66 = t65*t50 + t51*t39;
    const T t67 = t48*t39;
    const T t68 = t67*t42 + t51*t50;
    const T t69 = t1*t66 + t3*t68 + t5*t64;
    const T t70 = t49*t8 + t53*t10 + t55*t12;
    const T t71 = t59*t10 + t60*t12 + t61*t8;
    const T t72 = t64*t12 + t66*t8 + t68*t10;
    const T t73 = t49*t15 + t53*t17 + t55*t19;
    const T t74 = t59*t17 + t60*t19 + t61*t15;
    const T t75 = t64*t19 + t66*t15 + t68*t17;
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
    const T t86 = t82 + t85;
    const T t87 = lie_D(t86);
    const T t88 = -t82*t87 + T(1);
    const T t89 = in[9] - in[24];
    const T t90 = t33*dat[18] + t34*dat[19] + t35*dat[20] + t36*dat[45] + t37*dat[46] + t38*dat[47] + dat[3];
    const T t91 = t33*dat[21] + t34*dat[22] + t35*dat[23] + t36*dat[48] + t37*dat[49] + t38*dat[50] + dat[4];
    const T t92 = t33*dat[24] + t34*dat[25] + t35*dat[26] + t36*dat[51] + t37*dat[52] + t38*dat[53] + dat[5];
    const T t93 = (T(0.5))*(dat[69]*dat[69]);
    const T t94 = t89 + t90*in[0] + t91*in[1] + t92*in[2] + t93*dat[70] + dat[69]*in[12];
    const T t95 = in[10] - in[25];
    const T t96 = t95 + t90*in[3] + t91*in[4] + t92*in[5] + t93*dat[71] + dat[69]*in[13];
    const T t97 = in[11] - in[26];
    const T t98 = t97 + t90*in[6] + t91*in[7] + t92*in[8] + t93*dat[72] + dat[69]*in[14];
    const T t99 = t94*in[15] + t96*in[18] + t98*in[21];
    const T t100 = t99;
    const T t101 = (T(0.5))*t79;
    const T t102 = t101;
    const T t103 = t83*t87;
    const T t104 = t76*t103;
    const T t105 = t102 + t104;
    const T t106 = t94*in[16] + t96*in[19] + t98*in[22];
    const T t107 = t106;
    const T t108 = (T(0.5))*t76;
    const T t109 = t108;
    const T t110 = t79*t103;
    const T t111 = -t109 + t110;
    const T t112 = t94*in[17] + t96*in[20] + t98*in[23];
    const T t113 = t112;
    const T t114 = t88*t100 + t105*t107 + t111*t113;
    const T t115 = -t81 - t85;
    const T t116 = t115*t87 + T(1);
    const T t117 = (T(0.5))*t83;
    const T t118 = t117;
    const T t119 = t76*t79;
    const T t120 = t119*t87;
    const T t121 = t118 + t120;
    const T t122 = -t102 + t104;
    const T t123 = t100*t122 + t107*t116 + t113*t121;
    const T t124 = -t78 - t85;
    const T t125 = t124*t87 + T(1);
    const T t126 = t109 + t110;
    const T t127 = -t118 + t120;
    const T t128 = t100*t126 + t107*t127 + t113*t125;
    const T t129 = t33*dat[27] + t34*dat[28] + t35*dat[29] + t36*dat[54] + t37*dat[55] + t38*dat[56] + dat[6];
    const T t130 = t33*dat[30] + t34*dat[31] + t35*dat[32] + t36*dat[57] + t37*dat[58] + t38*dat[59] + dat[7];
    const T t131 = t33*dat[33] + t34*dat[34] + t35*dat[35] + t36*dat[60] + t37*dat[61] + t38*dat[62] + dat[8];
    const T t132 = t129*in[0] + t130*in[1] + t131*in[2] + dat[69]*dat[70] + in[12] - in[27];
    const T t133 = t129*in[3] + t130*in[4] + t131*in[5] + dat[69]*dat[71] + in[13] - in[28];
    const T t134 = t129*in[6] + t130*in[7] + t131*in[8] + dat[69]*dat[72] + in[14] - in[29];
    const T t135 = t132*in[15] + t133*in[18] + t134*in[21];
    const T t136 = t135;
    const T t137 = t132*in[16] + t133*in[19] + t134*in[22];
    const T t138 = t137;
    const T t139 = t132*in[17] + t133*in[20] + t134*in[23];
    const T t140 = t139;
    const T t141 = t88*t136 + t105*t138 + t111*t140;
    const T t142 = t116*t138 + t121*t140 + t122*t136;
    const T t143 = t125*t140 + t126*t136 + t127*t138;
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
    const T t157 = t154 + t156;
    const T t158 = lie_D(t157);
    const T t159 = -t154*t158 + T(1);
    const T t160 = (T(0.5))*t31;
    const T t161 = t160;
    const T t162 = t158*t27;
    const T t163 = t29*t162;
    const T t164 = t161 + t163;
    const T t165 = (T(0.5))*t29;
    const T t166 = t165;
    const T t167 = t31*t162;
    const T t168 = -t166 + t167;
    const T t169 = -in[0]*in[9] + in[0]*in[24] - in[3]*in[10] + in[3]*in[25] - in[6]*in[11] + in[6]*in[26];
    const T t170 = -in[1]*in[9] + in[1]*in[24] - in[4]*in[10] + in[4]*in[25] - in[7]*in[11] + in[7]*in[26];
    const T t171 = -in[2]*in[9] + in[2]*in[24] - in[5]*in[10] + in[5]*in[25] - in[8]*in[11] + in[8]*in[26];
    const T t172 = t169*dat[73] + t170*dat[76] + t171*dat[79] - dat[73]*dat[82] - dat[76]*dat[83] - dat[79]*dat[84];
    const T t173 = t169*dat[74] + t170*dat[77] + t171*dat[80] - dat[74]*dat[82] - dat[77]*dat[83] - dat[80]*dat[84];
    const T t174 = t169*dat[75] + t170*dat[78] + t171*dat[81] - dat[75]*dat[82] - dat[78]*dat[83] - dat[81]*dat[84];
    const T t175 = t159*t172 + t164*t173 + t168*t174;
    const T t176 = -t161 + t163;
    const T t177 = -t153 - t156;
    const T t178 = t177*t158 + T(1);
    const T t179 = (T(0.5))*t27;
    const T t180 = t179;
    const T t181 = t29*t31;
    const T t182 = t181*t158;
    const T t183 = t180 + t182;
    const T t184 = t176*t172 + t178*t173 + t183*t174;
    const T t185 = t166 + t167;
    const T t186 = -t180 + t182;
    const T t187 = -t151 - t156;
    const T t188 = t187*t158 + T(1);
    const T t189 = t185*t172 + t186*t173 + t188*t174;
    const T t190 = (T(0.5))*(t149*t149)*(dat[204]*dat[204]) + (T(0.5))*((t148*dat[202] + t149*dat[203])*(t148*dat[202] + t149*dat[203])) + (T(0.5))*((t147*dat[199] + t148*dat[200] + t149*dat[201])*(t147*dat[199] + t148*dat[200] + t149*dat[201])) + (T(0.5))*((t146*dat[195] + t147*dat[196] + t148*dat[197] + t149*dat[198])*(t146*dat[195] + t147*dat[196] + t148*dat[197] + t149*dat[198])) + (T(0.5))*((t145*dat[190] + t146*dat[191] + t147*dat[192] + t148*dat[193] + t149*dat[194])*(t145*dat[190] + t146*dat[191] + t147*dat[192] + t148*dat[193] + t149*dat[194])) + (T(0.5))*((t144*dat[184] + t145*dat[185] + t146*dat[186] + t147*dat[187] + t148*dat[188] + t149*dat[189])*(t144*dat[184] + t145*dat[185] + t146*dat[186] + t147*dat[187] + t148*dat[188] + t149*dat[189])) + (T(0.5))*((t144*dat[178] + t145*dat[179] + t146*dat[180] + t147*dat[181] + t148*dat[182] + t149*dat[183] + t143*dat[177])*(t144*dat[178] + t145*dat[179] + t146*dat[180] + t147*dat[181] + t148*dat[182] + t149*dat[183] + t143*dat[177])) + (T(0.5))*((t144*dat[171] + t145*dat[172] + t146*dat[173] + t147*dat[174] + t148*dat[175] + t149*dat[176] + t142*dat[169] + t143*dat[170])*(t144*dat[171] + t145*dat[172] + t146*dat[173] + t147*dat[174] + t148*dat[175] + t149*dat[176] + t142*dat[169] + t143*dat[170])) + (T(0.5))*((t144*dat[163] + t145*dat[164] + t146*dat[165] + t147*dat[166] + t148*dat[167] + t149*dat[168] + t141*dat[160] + t142*dat[161] + t143*dat[162])*(t144*dat[163] + t145*dat[164] + t146*dat[165] + t147*dat[166] + t148*dat[167] + t149*dat[168] + t141*dat[160] + t142*dat[161] + t143*dat[162])) + (T(0.5))*((t144*dat[154] + t145*dat[155] + t146*dat[156] + t147*dat[157] + t148*dat[158] + t149*dat[159] + t128*dat[150] + t141*dat[151] + t142*dat[152] + t143*dat[153])*(t144*dat[154] + t145*dat[155] + t146*dat[156] + t147*dat[157] + t148*dat[158] + t149*dat[159] + t128*dat[150] + t141*dat[151] + t142*dat[152] + t143*dat[153])) + (T(0.5))*((t144*dat[144] + t145*dat[145] + t146*dat[146] + t147*dat[147] + t148*dat[148] + t149*dat[149] + t123*dat[139] + t128*dat[140] + t141*dat[141] + t142*dat[142] + t143*dat[143])*(t144*dat[144] + t145*dat[145] + t146*dat[146] + t147*dat[147] + t148*dat[148] + t149*dat[149] + t123*dat[139] + t128*dat[140] + t141*dat[141] + t142*dat[142] + t143*dat[143])) + (T(0.5))*((t144*dat[133] + t145*dat[134] + t146*dat[135] + t147*dat[136] + t148*dat[137] + t149*dat[138] + t114*dat[127] + t123*dat[128] + t128*dat[129] + t141*dat[130] + t142*dat[131] + t143*dat[132])*(t144*dat[133] + t145*dat[134] + t146*dat[135] + t147*dat[136] + t148*dat[137] + t149*dat[138] + t114*dat[127] + t123*dat[128] + t128*dat[129] + t141*dat[130] + t142*dat[131] + t143*dat[132])) + (T(0.5))*((t144*dat[121] + t145*dat[122] + t146*dat[123] + t147*dat[124] + t148*dat[125] + t149*dat[126] + t114*dat[115] + t123*dat[116] + t128*dat[117] + t141*dat[118] + t142*dat[119] + t143*dat[120] + t79*dat[114])*(t144*dat[121] + t145*dat[122] + t146*dat[123] + t147*dat[124] + t148*dat[125] + t149*dat[126] + t114*dat[115] + t123*dat[116] + t128*dat[117] + t141*dat[118] + t142*dat[119] + t143*dat[120] + t79*dat[114])) + (T(0.5))*((t144*dat[108] + t145*dat[109] + t146*dat[110] + t147*dat[111] + t148*dat[112] + t149*dat[113] + t114*dat[102] + t123*dat[103] + t128*dat[104] + t141*dat[105] + t142*dat[106] + t143*dat[107] + t76*dat[100] + t79*dat[101])*(t144*dat[108] + t145*dat[109] + t146*dat[110] + t147*dat[111] + t148*dat[112] + t149*dat[113] + t114*dat[102] + t123*dat[103] + t128*dat[104] + t141*dat[105] + t142*dat[106] + t143*dat[107] + t76*dat[100] + t79*dat[101])) + (T(0.5))*((t144*dat[94] + t145*dat[95] + t146*dat[96] + t147*dat[97] + t148*dat[98] + t149*dat[99] + t114*dat[88] + t123*dat[89] + t128*dat[90] + t141*dat[91] + t142*dat[92] + t143*dat[93] + t83*dat[85] + t76*dat[86] + t79*dat[87])*(t144*dat[94] + t145*dat[95] + t146*dat[96] + t147*dat[97] + t148*dat[98] + t149*dat[99] + t114*dat[88] + t123*dat[89] + t128*dat[90] + t141*dat[91] + t142*dat[92] + t143*dat[93] + t83*dat[85] + t76*dat[86] + t79*dat[87]));
    const T t191 = (T(0.5))*t28*(dat[205]*dat[205]) + (T(0.5))*t30*(dat[206]*dat[206]) + (T(0.5))*(t175*t175)*(dat[208]*dat[208]) + (T(0.5))*(t184*t184)*(dat[209]*dat[209]) + (T(0.5))*t32*(dat[207]*dat[207]) + (T(0.5))*(t189*t189)*(dat[210]*dat[210]);
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
    raw[6] = -dat[0] + in[9];
    raw[11] = in[3];
    raw[12] = in[4];
    raw[13] = in[5];
    raw[14] = -dat[1] + in[10];
    raw[19] = in[6];
    raw[20] = in[7];
    raw[21] = in[8];
    raw[22] = -dat[2] + in[11];
}

void factor_cost_4(const T in[12], const T dat[4],
                   T half[1]) {
#pragma HLS INLINE
    const T t0 = -dat[0] + in[9];
    const T t1 = -dat[1] + in[10];
    const T t2 = -dat[2] + in[11];
    const T t3 = (T(0.5))*(dat[3]*dat[3]);
    const T t4 = (t0*t0)*t3 + (t1*t1)*t3 + (t2*t2)*t3;
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
