// generated from template accel.cpp.jinja by fgc 0.1.0 — do not edit
// Problem: pose_graph
// general graph, min-degree ordering; solver: lm qr auto n_u=4 cpe=20
//
// The dataflow accelerator of the accelerator plan (fgc_backends.hls.plan, docs/hls.md). One
// Levenberg-Marquardt iteration: the factor datapaths (Jacobian mode) -> whitened rows [A | b] (AB)
// -> per schedule level the QR unit set(s): Evaluate + n_u Update units over streams
// -> back-substitution -> state update (retract) -> the factor datapaths (cost mode) -> LM control.
//
// The linear solver's process network (from the plan): the units' DATAFLOW regions, then
// back_substitute's by columns (the loader streaming COND to a process per end of the chain,
// the state update fed by both):
//   13 processes, 31 streams (n_u=4, 1 unit set(s))
//   process qr0_broadcast
//   process qr0_finish
//   process qr0_update0
//   process qr0_update1
//   process qr0_update2
//   process qr0_update3
//   process qr0_evaluate
//   process qr0_collect
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
//   stream qr0_col0_even depth=27: qr0_update0 -> qr0_evaluate
//   stream qr0_col0_odd depth=27: qr0_update0 -> qr0_evaluate
//   stream qr0_row0 depth=2: qr0_update0 -> qr0_collect
//   stream qr0_col1_even depth=27: qr0_update1 -> qr0_evaluate
//   stream qr0_col1_odd depth=27: qr0_update1 -> qr0_evaluate
//   stream qr0_row1 depth=2: qr0_update1 -> qr0_collect
//   stream qr0_col2_even depth=27: qr0_update2 -> qr0_evaluate
//   stream qr0_col2_odd depth=27: qr0_update2 -> qr0_evaluate
//   stream qr0_row2 depth=2: qr0_update2 -> qr0_collect
//   stream qr0_col3_even depth=27: qr0_update3 -> qr0_evaluate
//   stream qr0_col3_odd depth=27: qr0_update3 -> qr0_evaluate
//   stream qr0_row3 depth=2: qr0_update3 -> qr0_collect
//   stream qr0_ve depth=2: qr0_broadcast -> qr0_evaluate
//   stream qr0_te depth=3: qr0_finish -> qr0_evaluate
//   stream qr0_e depth=2: qr0_evaluate -> qr0_collect
//   stream backsub_groups0 depth=21: backsub_loader -> backsub_end0
//   stream backsub_dx0 depth=12: backsub_end0 -> backsub_retire
//   stream backsub_groups1 depth=2: backsub_loader -> backsub_end1
//   stream backsub_dx1 depth=3: backsub_end1 -> backsub_retire
//   stream backsub_xroot depth=18: backsub_end0 -> backsub_end1
//   stream trial_tx depth=5: backsub_retire -> trial_cost
//   stream trial_tx2 depth=5: backsub_retire -> trial_cost
#include "pose_graph.h"

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
const int MAX_LD = 20;  // padded row length of the widest step
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
// block 0: BetweenFactorPose3 (6 rows, 12 columns, 6 instances)
void factor_0(const T in[24], const T dat[13],
              T raw[96]) {
#pragma HLS INLINE off
#pragma HLS ALLOCATION operation instances=fadd limit=14
#pragma HLS ALLOCATION operation instances=fmul limit=20
#pragma HLS ALLOCATION operation instances=fdiv limit=1
#pragma HLS ALLOCATION operation instances=fsqrt limit=1
    const T t0 = in[6]*in[18] + (in[0]*in[12] + in[3]*in[15]);
    const T t1 = in[8]*in[18] + (in[2]*in[12] + in[5]*in[15]);
    const T t2 = -t1;
    const T t3 = in[7]*in[18] + (in[1]*in[12] + in[4]*in[15]);
    const T t4 = in[6]*in[20] + (in[0]*in[14] + in[3]*in[17]);
    const T t5 = -t4;
    const T t6 = in[6]*in[19] + (in[0]*in[13] + in[3]*in[16]);
    const T t7 = -t0;
    const T t8 = in[7]*in[20] + (in[1]*in[14] + in[4]*in[17]);
    const T t9 = -t8;
    const T t10 = in[7]*in[19] + (in[1]*in[13] + in[4]*in[16]);
    const T t11 = -t3;
    const T t12 = in[8]*in[20] + (in[2]*in[14] + in[5]*in[17]);
    const T t13 = -t12;
    const T t14 = in[8]*in[19] + (in[2]*in[13] + in[5]*in[16]);
    const T t15 = -t14;
    const T t16 = -t6;
    const T t17 = -t10;
    const T t18 = t0;
    const T t19 = t3;
    const T t20 = t1;
    const T t21 = dat[6]*t20 + (dat[0]*t18 + dat[3]*t19);
    const T t22 = t6;
    const T t23 = t10;
    const T t24 = t14;
    const T t25 = dat[6]*t24 + (dat[0]*t22 + dat[3]*t23);
    const T t26 = t4;
    const T t27 = t8;
    const T t28 = t12;
    const T t29 = dat[3]*t27 + (dat[6]*t28 + dat[0]*t26);
    const T t30 = dat[7]*t20 + (dat[1]*t18 + dat[4]*t19);
    const T t31 = dat[7]*t24 + (dat[1]*t22 + dat[4]*t23);
    const T t32 = dat[4]*t27 + (dat[7]*t28 + dat[1]*t26);
    const T t33 = dat[8]*t20 + (dat[2]*t18 + dat[5]*t19);
    const T t34 = dat[8]*t24 + (dat[2]*t22 + dat[5]*t23);
    const T t35 = dat[5]*t27 + (dat[8]*t28 + dat[2]*t26);
    T tlog0[3]; so3_log(t21, t25, t29, t30, t31, t32, t33, t34, t35, tlog0);
    const T t36 = tlog0[2];
    const T t37 = (T(0.5))*t36;
    const T t38 = tlog0[0];
    const T t39 = (t38*t38);
    const T t40 = tlog0[1];
    const T t41 = (t40*t40);
    const T t42 = (t36*t36);
    const T t43 = t41 + t42;
    const T t44 = lie_D(t39 + t43);
    const T t45 = t38*t44;
    const T t46 = t40*t45;
    const T t47 = t46 - t37;
    const T t48 = (T(0.5))*t29;
    const T t49 = (T(0.5))*t40;
    const T t50 = t36*t45;
    const T t51 = t49 + t50;
    const T t52 = ((T(0.5))*t25)*t51 - t48*t47;
    const T t53 = T(1) - t43*t44;
    const T t54 = (T(0.5))*t51;
    const T t55 = t48*t53 - t21*t54;
    const T t56 = (T(0.5))*t47;
    const T t57 = (T(0.5))*t53;
    const T t58 = t21*t56 - t25*t57;
    const T t59 = t31*t54 - t32*t56;
    const T t60 = ((T(0.5))*t32)*t53 - t30*t54;
    const T t61 = t30*t56 - t31*t57;
    const T t62 = t34*t54 - t35*t56;
    const T t63 = ((T(0.5))*t35)*t53 - t33*t54;
    const T t64 = t33*t56 - t34*t57;
    const T t65 = T(1) + (-(t39 + t42))*t44;
    const T t66 = (T(0.5))*t38;
    const T t67 = (t40*t36)*t44 - t66;
    const T t68 = ((T(0.5))*t25)*t67 - t48*t65;
    const T t69 = t37 + t46;
    const T t70 = (T(0.5))*t67;
    const T t71 = t48*t69 - t21*t70;
    const T t72 = (T(0.5))*t65;
    const T t73 = (T(0.5))*t69;
    const T t74 = t21*t72 - t25*t73;
    const T t75 = t31*t70 - t32*t72;
    const T t76 = ((T(0.5))*t32)*t69 - t30*t70;
    const T t77 = t30*t72 - t31*t73;
    const T t78 = t34*t70 - t35*t72;
    const T t79 = ((T(0.5))*t35)*t69 - t33*t70;
    const T t80 = t33*t72 - t34*t73;
    const T t81 = t40*t36;
    const T t82 = t66 + t81*t44;
    const T t83 = T(1) + (-(t39 + t41))*t44;
    const T t84 = ((T(0.5))*t25)*t83 - t48*t82;
    const T t85 = t50 - t49;
    const T t86 = (T(0.5))*t83;
    const T t87 = t48*t85 - t21*t86;
    const T t88 = (T(0.5))*t82;
    const T t89 = (T(0.5))*t85;
    const T t90 = t21*t88 - t25*t89;
    const T t91 = t31*t86 - t32*t88;
    const T t92 = ((T(0.5))*t32)*t85 - t30*t86;
    const T t93 = t30*t88 - t31*t89;
    const T t94 = t34*t86 - t35*t88;
    const T t95 = ((T(0.5))*t35)*t85 - t33*t86;
    const T t96 = t33*t88 - t34*t89;
    const T t97 = T(2)*t40;
    const T t98 = T(2)*t36;
    const T t99 = T(2)*t38;
    const T t100 = t41;
    const T t101 = t42;
    const T t102 = t100 + t101;
    const T t103 = t39;
    const T t104 = t103 + t102;
    const T t105 = lie_D1(t104);
    const T t106 = in[21] - in[9];
    const T t107 = in[22] - in[10];
    const T t108 = in[23] - in[11];
    const T t109 = in[8]*t108 + (in[2]*t106 + in[5]*t107);
    const T t110 = in[7]*t108 + (in[1]*t106 + in[4]*t107);
    const T t111 = -(in[6]*in[7] + (in[0]*in[1] + in[3]*in[4]));
    const T t112 = -(in[6]*in[8] + (in[0]*in[2] + in[3]*in[5]));
    const T t113 = in[6]*t108 + (in[0]*t106 + in[3]*t107);
    const T t114 = -(in[7]*in[8] + (in[1]*in[2] + in[4]*in[5]));
    const T t115 = lie_D(t104);
    const T t116 = t40*t115;
    const T t117 = t36*t115;
    const T t118 = T(1) - t102*t115;
    const T t119 = t37;
    const T t120 = t38*t115;
    const T t121 = t40*t120;
    const T t122 = t119 + t121;
    const T t123 = t49;
    const T t124 = t36*t120;
    const T t125 = t124 - t123;
    const T t126 = t121 - t119;
    const T t127 = -(t101 + t103);
    const T t128 = T(1) + t127*t115;
    const T t129 = t66;
    const T t130 = t81*t115;
    const T t131 = t129 + t130;
    const T t132 = t123 + t124;
    const T t133 = t130 - t129;
    const T t134 = -(t100 + t103);
    const T t135 = T(1) + t134*t115;
    const T t136 = (in[6]*in[23] - in[6]*in[11]) + ((in[0]*in[21] - in[0]*in[9]) + (in[3]*in[22] - in[3]*in[10]));
    const T t137 = (in[7]*in[23] - in[7]*in[11]) + ((in[1]*in[21] - in[1]*in[9]) + (in[4]*in[22] - in[4]*in[10]));
    const T t138 = (in[8]*in[23] - in[8]*in[11]) + ((in[2]*in[21] - in[2]*in[9]) + (in[5]*in[22] - in[5]*in[10]));
    const T t139 = (dat[0]*t136 - (dat[6]*dat[11] + (dat[0]*dat[9] + dat[3]*dat[10]))) + (dat[3]*t137 + dat[6]*t138);
    const T t140 = t139*t102;
    const T t141 = t139*t115;
    const T t142 = (dat[1]*t136 - (dat[7]*dat[11] + (dat[1]*dat[9] + dat[4]*dat[10]))) + (dat[4]*t137 + dat[7]*t138);
    const T t143 = t142*t127;
    const T t144 = t142*t115;
    const T t145 = (dat[2]*t136 - (dat[8]*dat[11] + (dat[2]*dat[9] + dat[5]*dat[10]))) + (dat[5]*t137 + dat[8]*t138);
    const T t146 = t145*t134;
    const T t147 = t145*t115;
    const T t148 = t2;
    const T t149 = t3;
    const T t150 = t5;
    const T t151 = t6;
    const T t152 = t1;
    const T t153 = t7;
    const T t154 = t9;
    const T t155 = t10;
    const T t156 = t11;
    const T t157 = t0;
    const T t158 = t13;
    const T t159 = t14;
    const T t160 = dat[3]*t152 + dat[6]*t156;
    const T t161 = dat[0]*t148 + dat[6]*t157;
    const T t162 = dat[0]*t149 + dat[3]*t153;
    const T t163 = dat[3]*t154 + (dat[6]*t158 + dat[0]*t150);
    const T t164 = dat[3]*t155 + (dat[6]*t159 + dat[0]*t151);
    const T t165 = t15;
    const T t166 = t10;
    const T t167 = t4;
    const T t168 = t7;
    const T t169 = t14;
    const T t170 = t16;
    const T t171 = t8;
    const T t172 = t11;
    const T t173 = t17;
    const T t174 = t6;
    const T t175 = t12;
    const T t176 = t2;
    const T t177 = dat[3]*t169 + dat[6]*t173;
    const T t178 = dat[0]*t165 + dat[6]*t174;
    const T t179 = dat[0]*t166 + dat[3]*t170;
    const T t180 = dat[6]*t175 + (dat[0]*t167 + dat[3]*t171);
    const T t181 = dat[6]*t176 + (dat[0]*t168 + dat[3]*t172);
    const T t182 = t13;
    const T t183 = t8;
    const T t184 = t16;
    const T t185 = t0;
    const T t186 = t12;
    const T t187 = t5;
    const T t188 = t17;
    const T t189 = t3;
    const T t190 = t9;
    const T t191 = t4;
    const T t192 = t15;
    const T t193 = t1;
    const T t194 = dat[3]*t186 + dat[6]*t190;
    const T t195 = dat[0]*t182 + dat[6]*t191;
    const T t196 = dat[0]*t183 + dat[3]*t187;
    const T t197 = dat[6]*t192 + (dat[0]*t184 + dat[3]*t188);
    const T t198 = dat[6]*t193 + (dat[0]*t185 + dat[3]*t189);
    const T t199 = dat[4]*t152 + dat[7]*t156;
    const T t200 = dat[1]*t148 + dat[7]*t157;
    const T t201 = dat[1]*t149 + dat[4]*t153;
    const T t202 = dat[4]*t154 + (dat[7]*t158 + dat[1]*t150);
    const T t203 = dat[4]*t155 + (dat[7]*t159 + dat[1]*t151);
    const T t204 = dat[4]*t169 + dat[7]*t173;
    const T t205 = dat[1]*t165 + dat[7]*t174;
    const T t206 = dat[1]*t166 + dat[4]*t170;
    const T t207 = dat[7]*t175 + (dat[1]*t167 + dat[4]*t171);
    const T t208 = dat[7]*t176 + (dat[1]*t168 + dat[4]*t172);
    const T t209 = dat[4]*t186 + dat[7]*t190;
    const T t210 = dat[1]*t182 + dat[7]*t191;
    const T t211 = dat[1]*t183 + dat[4]*t187;
    const T t212 = dat[7]*t192 + (dat[1]*t184 + dat[4]*t188);
    const T t213 = dat[7]*t193 + (dat[1]*t185 + dat[4]*t189);
    const T t214 = dat[5]*t152 + dat[8]*t156;
    const T t215 = dat[2]*t148 + dat[8]*t157;
    const T t216 = dat[2]*t149 + dat[5]*t153;
    const T t217 = dat[5]*t154 + (dat[8]*t158 + dat[2]*t150);
    const T t218 = dat[5]*t155 + (dat[8]*t159 + dat[2]*t151);
    const T t219 = dat[5]*t169 + dat[8]*t173;
    const T t220 = dat[2]*t165 + dat[8]*t174;
    const T t221 = dat[2]*t166 + dat[5]*t170;
    const T t222 = dat[8]*t175 + (dat[2]*t167 + dat[5]*t171);
    const T t223 = dat[8]*t176 + (dat[2]*t168 + dat[5]*t172);
    const T t224 = dat[5]*t186 + dat[8]*t190;
    const T t225 = dat[2]*t182 + dat[8]*t191;
    const T t226 = dat[2]*t183 + dat[5]*t187;
    const T t227 = dat[8]*t192 + (dat[2]*t184 + dat[5]*t188);
    const T t228 = dat[8]*t193 + (dat[2]*t185 + dat[5]*t189);
    const T t229 = ((t194*t58 + t199*t59) + (t204*t60 + t209*t61)) + ((t214*t62 + t219*t63) + (t224*t64 + (t160*t52 + t177*t55)));
    const T t230 = ((t195*t58 + t200*t59) + (t205*t60 + t210*t61)) + ((t215*t62 + t220*t63) + (t225*t64 + (t161*t52 + t178*t55)));
    const T t231 = ((t196*t58 + t201*t59) + (t206*t60 + t211*t61)) + ((t216*t62 + t221*t63) + (t226*t64 + (t162*t52 + t179*t55)));
    const T t232 = (t222*t63 + t227*t64) + ((t180*t55 + t197*t58) + (t207*t60 + t212*t61));
    const T t233 = (t217*t62 + t228*t64) + ((t163*t52 + t198*t58) + (t202*t59 + t213*t61));
    const T t234 = (t218*t62 + t223*t63) + ((t164*t52 + t181*t55) + (t203*t59 + t208*t60));
    const T t235 = ((t199*t75 + t204*t76) + (t214*t78 + t219*t79)) + ((t194*t74 + t209*t77) + (t224*t80 + (t160*t68 + t177*t71)));
    const T t236 = ((t200*t75 + t205*t76) + (t215*t78 + t220*t79)) + ((t195*t74 + t210*t77) + (t225*t80 + (t161*t68 + t178*t71)));
    const T t237 = ((t201*t75 + t206*t76) + (t216*t78 + t221*t79)) + ((t196*t74 + t211*t77) + (t226*t80 + (t162*t68 + t179*t71)));
    const T t238 = (t212*t77 + t227*t80) + ((t180*t71 + t207*t76) + (t222*t79 + t197*t74));
    const T t239 = (t213*t77 + t228*t80) + ((t163*t68 + t202*t75) + (t217*t78 + t198*t74));
    const T t240 = (t218*t78 + t223*t79) + ((t164*t68 + t181*t71) + (t203*t75 + t208*t76));
    const T t241 = ((t199*t91 + t204*t92) + (t214*t94 + t219*t95)) + ((t194*t90 + t209*t93) + (t224*t96 + (t160*t84 + t177*t87)));
    const T t242 = ((t200*t91 + t205*t92) + (t215*t94 + t220*t95)) + ((t195*t90 + t210*t93) + (t225*t96 + (t161*t84 + t178*t87)));
    const T t243 = ((t201*t91 + t206*t92) + (t216*t94 + t221*t95)) + ((t196*t90 + t211*t93) + (t226*t96 + (t162*t84 + t179*t87)));
    const T t244 = (t212*t93 + t227*t96) + ((t180*t87 + t207*t92) + (t222*t95 + t197*t90));
    const T t245 = (t213*t93 + t228*t96) + ((t163*t84 + t202*t91) + (t217*t94 + t198*t90));
    const T t246 = (t218*t94 + t223*t95) + ((t164*t84 + t181*t87) + (t203*t91 + t208*t92));
    const T t247 = t97*t235;
    const T t248 = t97*t236;
    const T t249 = t97*t237;
    const T t250 = t97*t238;
    const T t251 = t97*t239;
    const T t252 = t97*t240;
    const T t253 = t98*t241;
    const T t254 = t98*t242;
    const T t255 = t98*t243;
    const T t256 = t98*t244;
    const T t257 = t98*t245;
    const T t258 = t98*t246;
    const T t259 = t253 + t247;
    const T t260 = t248 + t254;
    const T t261 = t249 + t255;
    const T t262 = t250 + t256;
    const T t263 = t251 + t257;
    const T t264 = t252 + t258;
    const T t265 = t99*t229;
    const T t266 = t99*t230;
    const T t267 = t99*t231;
    const T t268 = t99*t232;
    const T t269 = t99*t233;
    const T t270 = t99*t234;
    const T t271 = t105*t265 + t105*t259;
    const T t272 = t105*t266 + t105*t260;
    const T t273 = t105*t267 + t105*t261;
    const T t274 = t105*t268 + t105*t262;
    const T t275 = t105*t269 + t105*t263;
    const T t276 = t105*t270 + t105*t264;
    const T t277 = -t109;
    const T t278 = t110;
    const T t279 = -((in[6]*in[6]) + ((in[0]*in[0]) + (in[3]*in[3])));
    const T t280 = t111;
    const T t281 = t112;
    const T t282 = t0;
    const T t283 = t6;
    const T t284 = t4;
    const T t285 = t109;
    const T t286 = -t113;
    const T t287 = t111;
    const T t288 = -((in[7]*in[7]) + ((in[1]*in[1]) + (in[4]*in[4])));
    const T t289 = t114;
    const T t290 = t3;
    const T t291 = t10;
    const T t292 = t8;
    const T t293 = -t110;
    const T t294 = t113;
    const T t295 = t112;
    const T t296 = t114;
    const T t297 = -((in[8]*in[8]) + ((in[2]*in[2]) + (in[5]*in[5])));
    const T t298 = t1;
    const T t299 = t14;
    const T t300 = t12;
    const T t301 = dat[3]*t285 + dat[6]*t293;
    const T t302 = dat[0]*t277 + dat[6]*t294;
    const T t303 = dat[0]*t278 + dat[3]*t286;
    const T t304 = dat[6]*t295 + (dat[0]*t279 + dat[3]*t287);
    const T t305 = dat[6]*t296 + (dat[0]*t280 + dat[3]*t288);
    const T t306 = dat[6]*t297 + (dat[0]*t281 + dat[3]*t289);
    const T t307 = dat[6]*t298 + (dat[0]*t282 + dat[3]*t290);
    const T t308 = dat[6]*t299 + (dat[0]*t283 + dat[3]*t291);
    const T t309 = dat[6]*t300 + (dat[0]*t284 + dat[3]*t292);
    const T t310 = (T(0.5))*t241;
    const T t311 = (T(0.5))*t242;
    const T t312 = (T(0.5))*t243;
    const T t313 = (T(0.5))*t244;
    const T t314 = (T(0.5))*t245;
    const T t315 = (T(0.5))*t246;
    const T t316 = t115*t229 + t38*t271;
    const T t317 = t115*t230 + t38*t272;
    const T t318 = t115*t231 + t38*t273;
    const T t319 = t115*t232 + t38*t274;
    const T t320 = t115*t233 + t38*t275;
    const T t321 = t115*t234 + t38*t276;
    const T t322 = t120*t235 + t40*t316;
    const T t323 = t120*t236 + t40*t317;
    const T t324 = t120*t237 + t40*t318;
    const T t325 = t120*t238 + t40*t319;
    const T t326 = t120*t239 + t40*t320;
    const T t327 = t120*t240 + t40*t321;
    const T t328 = dat[4]*t285 + dat[7]*t293;
    const T t329 = dat[1]*t277 + dat[7]*t294;
    const T t330 = dat[1]*t278 + dat[4]*t286;
    const T t331 = dat[7]*t295 + (dat[1]*t279 + dat[4]*t287);
    const T t332 = dat[7]*t296 + (dat[1]*t280 + dat[4]*t288);
    const T t333 = dat[7]*t297 + (dat[1]*t281 + dat[4]*t289);
    const T t334 = dat[7]*t298 + (dat[1]*t282 + dat[4]*t290);
    const T t335 = dat[7]*t299 + (dat[1]*t283 + dat[4]*t291);
    const T t336 = dat[7]*t300 + (dat[1]*t284 + dat[4]*t292);
    const T t337 = (T(0.5))*t235;
    const T t338 = (T(0.5))*t236;
    const T t339 = (T(0.5))*t237;
    const T t340 = (T(0.5))*t238;
    const T t341 = (T(0.5))*t239;
    const T t342 = (T(0.5))*t240;
    const T t343 = t120*t241 + t36*t316;
    const T t344 = t120*t242 + t36*t317;
    const T t345 = t120*t243 + t36*t318;
    const T t346 = t120*t244 + t36*t319;
    const T t347 = t120*t245 + t36*t320;
    const T t348 = t120*t246 + t36*t321;
    const T t349 = dat[5]*t285 + dat[8]*t293;
    const T t350 = dat[2]*t277 + dat[8]*t294;
    const T t351 = dat[2]*t278 + dat[5]*t286;
    const T t352 = dat[8]*t295 + (dat[2]*t279 + dat[5]*t287);
    const T t353 = dat[8]*t296 + (dat[2]*t280 + dat[5]*t288);
    const T t354 = dat[8]*t297 + (dat[2]*t281 + dat[5]*t289);
    const T t355 = dat[8]*t298 + (dat[2]*t282 + dat[5]*t290);
    const T t356 = dat[8]*t299 + (dat[2]*t283 + dat[5]*t291);
    const T t357 = dat[8]*t300 + (dat[2]*t284 + dat[5]*t292);
    const T t358 = (T(0.5))*t229;
    const T t359 = (T(0.5))*t230;
    const T t360 = (T(0.5))*t231;
    const T t361 = (T(0.5))*t232;
    const T t362 = (T(0.5))*t233;
    const T t363 = (T(0.5))*t234;
    const T t364 = (t116*t241 + t117*t235) + t81*t271;
    const T t365 = (t116*t242 + t117*t236) + t81*t272;
    const T t366 = (t116*t243 + t117*t237) + t81*t273;
    const T t367 = (t116*t244 + t117*t238) + t81*t274;
    const T t368 = (t116*t245 + t117*t239) + t81*t275;
    const T t369 = (t116*t246 + t117*t240) + t81*t276;
    raw[0] = t229;
    raw[1] = t230;
    raw[2] = t231;
    raw[6] = t232;
    raw[7] = t233;
    raw[8] = t234;
    raw[12] = t38;
    raw[16] = t235;
    raw[17] = t236;
    raw[18] = t237;
    raw[22] = t238;
    raw[23] = t239;
    raw[24] = t240;
    raw[28] = t40;
    raw[32] = t241;
    raw[33] = t242;
    raw[34] = t243;
    raw[38] = t244;
    raw[39] = t245;
    raw[40] = t246;
    raw[44] = t36;
    raw[48] = t145*t343 + (((((t349*t125 + (t301*t118 + t328*t122)) + t142*t310) - (t145*t337 + t141*t259)) - t140*t271) + t142*t322);
    raw[49] = t145*t344 + (((((t350*t125 + (t302*t118 + t329*t122)) + t142*t311) - (t145*t338 + t141*t260)) - t140*t272) + t142*t323);
    raw[50] = t145*t345 + (((((t351*t125 + (t303*t118 + t330*t122)) + t142*t312) - (t145*t339 + t141*t261)) - t140*t273) + t142*t324);
    raw[51] = t352*t125 + (t304*t118 + t331*t122);
    raw[52] = t353*t125 + (t305*t118 + t332*t122);
    raw[53] = t354*t125 + (t306*t118 + t333*t122);
    raw[54] = t145*t346 + ((((t142*t313 - t145*t340) - t141*t262) - t140*t274) + t142*t325);
    raw[55] = t145*t347 + ((((t142*t314 - t145*t341) - t141*t263) - t140*t275) + t142*t326);
    raw[56] = t145*t348 + ((((t142*t315 - t145*t342) - t141*t264) - t140*t276) + t142*t327);
    raw[57] = t355*t125 + (t307*t118 + t334*t122);
    raw[58] = t356*t125 + (t308*t118 + t335*t122);
    raw[59] = t357*t125 + (t309*t118 + t336*t122);
    raw[60] = t145*t125 + (t139*t118 + t142*t122);
    raw[64] = ((t143*t271 + ((t145*t358 + ((t301*t126 + (t328*t128 + t349*t131)) - t144*t253)) - (t139*t310 + t144*t265))) + t145*t364) + t139*t322;
    raw[65] = ((t143*t272 + ((t145*t359 + ((t302*t126 + (t329*t128 + t350*t131)) - t144*t254)) - (t139*t311 + t144*t266))) + t145*t365) + t139*t323;
    raw[66] = ((t143*t273 + ((t145*t360 + ((t303*t126 + (t330*t128 + t351*t131)) - t144*t255)) - (t139*t312 + t144*t267))) + t145*t366) + t139*t324;
    raw[67] = t304*t126 + (t331*t128 + t352*t131);
    raw[68] = t305*t126 + (t332*t128 + t353*t131);
    raw[69] = t306*t126 + (t333*t128 + t354*t131);
    raw[70] = ((((t145*t361 - t139*t313) - (t144*t256 + t144*t268)) + t143*t274) + t145*t367) + t139*t325;
    raw[71] = ((((t145*t362 - t139*t314) - (t144*t257 + t144*t269)) + t143*t275) + t145*t368) + t139*t326;
    raw[72] = ((t143*t276 + ((t145*t363 - t144*t270) - (t144*t258 + t139*t315))) + t145*t369) + t139*t327;
    raw[73] = t307*t126 + (t334*t128 + t355*t131);
    raw[74] = t308*t126 + (t335*t128 + t356*t131);
    raw[75] = t309*t126 + (t336*t128 + t357*t131);
    raw[76] = t139*t126 + (t142*t128 + t145*t131);
    raw[80] = ((t146*t271 + ((t139*t337 - t147*t265) + (((t301*t132 + (t328*t133 + t349*t135)) - t147*t247) - t142*t358))) + t142*t364) + t139*t343;
    raw[81] = ((t146*t272 + ((t139*t338 - t147*t266) + (((t302*t132 + (t329*t133 + t350*t135)) - t147*t248) - t142*t359))) + t142*t365) + t139*t344;
    raw[82] = ((t146*t273 + ((t139*t339 - t147*t267) + (((t303*t132 + (t330*t133 + t351*t135)) - t147*t249) - t142*t360))) + t142*t366) + t139*t345;
    raw[83] = t304*t132 + (t331*t133 + t352*t135);
    raw[84] = t305*t132 + (t332*t133 + t353*t135);
    raw[85] = t306*t132 + (t333*t133 + t354*t135);
    raw[86] = ((((t139*t340 - t142*t361) - (t147*t250 + t147*t268)) + t146*t274) + t142*t367) + t139*t346;
    raw[87] = ((((t139*t341 - t142*t362) - (t147*t251 + t147*t269)) + t146*t275) + t142*t368) + t139*t347;
    raw[88] = ((t146*t276 + ((t139*t342 - t147*t252) - (t147*t270 + t142*t363))) + t142*t369) + t139*t348;
    raw[89] = t307*t132 + (t334*t133 + t355*t135);
    raw[90] = t308*t132 + (t335*t133 + t356*t135);
    raw[91] = t309*t132 + (t336*t133 + t357*t135);
    raw[92] = t139*t132 + (t142*t133 + t145*t135);
}

void factor_cost_0(const T in[24], const T dat[13],
                   T half[1]) {
#pragma HLS INLINE off
#pragma HLS ALLOCATION operation instances=fadd limit=6
#pragma HLS ALLOCATION operation instances=fmul limit=8
#pragma HLS ALLOCATION operation instances=fdiv limit=1
#pragma HLS ALLOCATION operation instances=fsqrt limit=1
    const T t0 = in[6]*in[18] + (in[0]*in[12] + in[3]*in[15]);
    const T t1 = t0;
    const T t2 = in[7]*in[18] + (in[1]*in[12] + in[4]*in[15]);
    const T t3 = t2;
    const T t4 = in[8]*in[18] + (in[2]*in[12] + in[5]*in[15]);
    const T t5 = t4;
    const T t6 = dat[6]*t5 + (dat[0]*t1 + dat[3]*t3);
    const T t7 = in[6]*in[19] + (in[0]*in[13] + in[3]*in[16]);
    const T t8 = t7;
    const T t9 = in[7]*in[19] + (in[1]*in[13] + in[4]*in[16]);
    const T t10 = t9;
    const T t11 = in[8]*in[19] + (in[2]*in[13] + in[5]*in[16]);
    const T t12 = t11;
    const T t13 = dat[6]*t12 + (dat[0]*t8 + dat[3]*t10);
    const T t14 = in[6]*in[20] + (in[0]*in[14] + in[3]*in[17]);
    const T t15 = t14;
    const T t16 = in[7]*in[20] + (in[1]*in[14] + in[4]*in[17]);
    const T t17 = t16;
    const T t18 = in[8]*in[20] + (in[2]*in[14] + in[5]*in[17]);
    const T t19 = t18;
    const T t20 = dat[3]*t17 + (dat[6]*t19 + dat[0]*t15);
    const T t21 = dat[7]*t5 + (dat[1]*t1 + dat[4]*t3);
    const T t22 = dat[7]*t12 + (dat[1]*t8 + dat[4]*t10);
    const T t23 = dat[4]*t17 + (dat[7]*t19 + dat[1]*t15);
    const T t24 = dat[8]*t5 + (dat[2]*t1 + dat[5]*t3);
    const T t25 = dat[8]*t12 + (dat[2]*t8 + dat[5]*t10);
    const T t26 = dat[5]*t17 + (dat[8]*t19 + dat[2]*t15);
    T tlog0[3]; so3_log(t6, t13, t20, t21, t22, t23, t24, t25, t26, tlog0);
    const T t27 = tlog0[0];
    const T t28 = (t27*t27);
    const T t29 = tlog0[1];
    const T t30 = (t29*t29);
    const T t31 = tlog0[2];
    const T t32 = (t31*t31);
    const T t33 = t30;
    const T t34 = t33;
    const T t35 = t32;
    const T t36 = t35;
    const T t37 = t34 + t36;
    const T t38 = t28;
    const T t39 = t38;
    const T t40 = t39 + t37;
    const T t41 = lie_D(t40);
    const T t42 = T(1) - t37*t41;
    const T t43 = (T(0.5))*t31;
    const T t44 = t43;
    const T t45 = t27*t41;
    const T t46 = t29*t45;
    const T t47 = t44 + t46;
    const T t48 = (T(0.5))*t29;
    const T t49 = t48;
    const T t50 = t31*t45;
    const T t51 = t50 - t49;
    const T t52 = (in[6]*in[23] - in[6]*in[11]) + ((in[0]*in[21] - in[0]*in[9]) + (in[3]*in[22] - in[3]*in[10]));
    const T t53 = (in[7]*in[23] - in[7]*in[11]) + ((in[1]*in[21] - in[1]*in[9]) + (in[4]*in[22] - in[4]*in[10]));
    const T t54 = (in[8]*in[23] - in[8]*in[11]) + ((in[2]*in[21] - in[2]*in[9]) + (in[5]*in[22] - in[5]*in[10]));
    const T t55 = (dat[0]*t52 - (dat[6]*dat[11] + (dat[0]*dat[9] + dat[3]*dat[10]))) + (dat[3]*t53 + dat[6]*t54);
    const T t56 = (dat[1]*t52 - (dat[7]*dat[11] + (dat[1]*dat[9] + dat[4]*dat[10]))) + (dat[4]*t53 + dat[7]*t54);
    const T t57 = (dat[2]*t52 - (dat[8]*dat[11] + (dat[2]*dat[9] + dat[5]*dat[10]))) + (dat[5]*t53 + dat[8]*t54);
    const T t58 = t57*t51 + (t55*t42 + t56*t47);
    const T t59 = t46 - t44;
    const T t60 = -(t36 + t39);
    const T t61 = T(1) + t60*t41;
    const T t62 = (T(0.5))*t27;
    const T t63 = t62;
    const T t64 = t29*t31;
    const T t65 = t64*t41;
    const T t66 = t63 + t65;
    const T t67 = t55*t59 + (t56*t61 + t57*t66);
    const T t68 = t49 + t50;
    const T t69 = t65 - t63;
    const T t70 = -(t34 + t39);
    const T t71 = T(1) + t70*t41;
    const T t72 = t55*t68 + (t56*t69 + t57*t71);
    const T t73 = (T(0.5))*(dat[12]*dat[12]);
    const T t74 = ((t73*t32 + (t73*t28 + t73*t30)) + t73*(t67*t67)) + (t73*(t72*t72) + t73*(t58*t58));
    half[0] = t74;
}

// block 1: PriorFactorPose3 (6 rows, 6 columns, 1 instances)
void factor_1(const T in[12], const T dat[13],
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

void factor_cost_1(const T in[12], const T dat[13],
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
    const T t61 = (T(0.5))*(dat[12]*dat[12]);
    const T t62 = ((t61*t23 + (t61*t19 + t61*t21)) + t61*(t55*t55)) + (t61*(t60*t60) + t61*(t46*t46));
    half[0] = t62;
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
const int NOISE_STRIDE = 16;  // the widest block type's padded row
const int NOISE_AB = 96;  // the largest block type's padded rows
const int NOISE_ROWS = 6;  // the most rows of a block type
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
#pragma HLS LOOP_TRIPCOUNT max=2
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
const int GRAD_STRIDE = 16;  // the widest block type's padded row
const int GRAD_ROWS = 6;  // the most rows of a block type
const int GRAD_COLS = 12;  // the most columns of a block type (its tangent entries)
const int GRAD_GROUPS = 48;  // the most PORTS groups of a block type's padded rows
const int GRAD_DIST = 16;  // T_PARTIALS x the narrowest padded row / PORTS
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
void gather_0(const T x[N_X], int f, T in[24], T dat[13]) {
    const int vb = FACTOR_VAR_BEGIN[f];
    const int line = FACTOR_DATA_OFF[f];
    for (int i = 0; i < 12; ++i) in[0 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 0]] + i];
    for (int i = 0; i < 12; ++i) in[12 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 1]] + i];
    for (int i = 0; i < 12; ++i) dat[0 + i] = DATA_BUF[line + 0 + i];
    for (int i = 0; i < 1; ++i) dat[12 + i] = DATA_BUF[line + 12 + i];
}

void gather_trial_0(const T x[N_X], int f, T in[24], T dat[13]) {
    const int vb = FACTOR_VAR_BEGIN[f];
    const int line = FACTOR_DATA_OFF[f], h = line >> 1, p = line & 1;
    for (int i = 0; i < 12; ++i) in[0 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 0]] + i];
    for (int i = 0; i < 12; ++i) in[12 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 1]] + i];
    T w[14];  // DATA_BUF[2 h + 0 ...]: the line's words from 0 at w[p ...]
#pragma HLS ARRAY_PARTITION variable=w complete
    for (int i = 0; i < 13; ++i) w[i] = DATA_BUF[2 * h + 0 + i];
    w[13] = p ? DATA_BUF[2 * h + 13] : T(0);  // an odd line's last word
    for (int i = 0; i < 12; ++i) dat[0 + i] = p ? w[1 + i] : w[0 + i];
    for (int i = 0; i < 1; ++i) dat[12 + i] = p ? w[13 + i] : w[12 + i];
}

// block 0, Jacobian mode: per instance residual + Jacobian (its 60 structural non-zeros of
// 6 x 13), whitening, into AB; one instance every II=48 cycles (the plan's)
void evaluate_0(const T x[N_X], hls::stream<GradWord>& grad) {
    for (int i = 0; i < 6; ++i) {
#pragma HLS PIPELINE II=48
        const int f = BLOCK0_INSTANCES[i];
        T in[24], dat[13];
        gather_0(x, f, in, dat);
        T raw[96];  // the Jacobian writes only its structural non-zeros
        T ab[96];
        for (int c = 0; c < 96; ++c) raw[c] = T(0);
        factor_0(in, dat, raw);
        whiten<16, 13, 6, 0, 6>(raw + 0, ab + 0, dat + 12);
        const int a0 = FACTOR_A_OFF[f];
        for (int r = 0; r < 6; ++r) {
            for (int c = 0; c < 13; ++c) AB[a0 + r * 13 + c] = ab[r * 16 + c];
        }
        // and beside AB, to the gradient (reduce_all, the same DATAFLOW region): 48 stream words
        for (int r = 0; r < 6; ++r) grad_row<16, 13>(ab + r * 16, grad);
    }
    // (one process of linearize_rows' region: the datapaths one after another)
    FGC_CYCLES("datapaths", 0, "factor_0_jacobian", 6, 48, 428);
}

// block 0's whitened rows of instance f from AB, padded to 16 columns (a multiple of PORTS)
void load_rows_0(int f, T ab[96]) {
    const int a0 = FACTOR_A_OFF[f];
    for (int e = 0; e < 96; e += PORTS) {  // PORTS words a cycle
#pragma HLS PIPELINE II=1
        for (int h = 0; h < PORTS; ++h) {
            const int r = (e + h) / 16, c = (e + h) % 16;
            ab[e + h] = c < 13 ? T(AB[a0 + r * 13 + c]) : T(0);
        }
    }
}

// block 0: the gradient of each instance from the datapath's stream; false if not
// finite. INLINE into reduce_all, whose ALLOCATION makes every block type's accumulate one module
bool reduce_0(hls::stream<GradWord>& grad, T& sq) {
#pragma HLS INLINE
    bool finite = true;
    for (int i = 0; i < 6; ++i) {
        const int f = BLOCK0_INSTANCES[i];
        const int vb = FACTOR_VAR_BEGIN[f];
        int col[GRAD_COLS];  // per column: its tangent entry
        for (int j = 0; j < 6; ++j) col[0 + j] = VAR_T_OFF[FACTOR_VARS[vb + 0]] + j;
        for (int j = 0; j < 6; ++j) col[6 + j] = VAR_T_OFF[FACTOR_VARS[vb + 1]] + j;
        finite = accumulate(grad, col, 16, 13, 6, sq) && finite;
        // column map, A^T b PORTS columns a cycle from the stream (a dot product of m rows x
        // STRIDE / PORTS groups: the plan's rule), the scatter into G
        FGC_CYCLES("gradient", 0, "reduce_0_columns", 12, 1, 1);
        if (i == 0) FGC_WAIT("gradient", 0, "datapaths", 0, "factor_0_jacobian");
        FGC_CYCLES("gradient", 0, "reduce_0_rows", 48, fgc_units::dot_ii(48, T_PARTIALS, T_ADD_LAT),
                   fgc_units::dot_depth(48, T_PARTIALS, T_ADD_LAT, T_MUL_LAT));
        FGC_CYCLES("gradient", 0, "reduce_0_scatter", 13, 1, 6 + T_ADD_LAT * fgc_units::ceil_log2(T_PARTIALS));
    }
    return finite;
}

// block 0: `noise` plus the cost's rounding noise of its instances at the linearisation point (from AB);
// INLINE: the block types' running sums land in rounding_noise_all's body, one after another, so
// they share its one adder, and its ALLOCATION makes their rounding_noise calls one module
T noise_0(T noise, T ab[NOISE_AB]) {
#pragma HLS INLINE
    for (int i = 0; i < 6; ++i) {
        const int f = BLOCK0_INSTANCES[i];
        const int vb = FACTOR_VAR_BEGIN[f];
        load_rows_0(f, ab);  // into rounding_noise_all's one row buffer
        T scale[NOISE_STRIDE];  // per column: largest storage entry of its variable (0: b, padding)
        for (int c = 0; c < 16; ++c) scale[c] = T(0);
        for (int j = 0; j < 6; ++j) scale[0 + j] = VAR_SCALE[FACTOR_VARS[vb + 0]];
        for (int j = 0; j < 6; ++j) scale[6 + j] = VAR_SCALE[FACTOR_VARS[vb + 1]];
        noise += rounding_noise(ab, scale, 16, 13, 6);
        FGC_CYCLES("noise_0", 0, "load", 48, 1, 2);
        FGC_CYCLES("noise_0", 0, "scales", 16, 1, 1);
        FGC_CYCLES("noise_0", 0, "rows", 6, 19, 33);
        FGC_CYCLES("noise_0", 0, "terms", 2, 12, 25);
    }
    return noise;
}

void gather_1(const T x[N_X], int f, T in[12], T dat[13]) {
    const int vb = FACTOR_VAR_BEGIN[f];
    const int line = FACTOR_DATA_OFF[f];
    for (int i = 0; i < 12; ++i) in[0 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 0]] + i];
    for (int i = 0; i < 12; ++i) dat[0 + i] = DATA_BUF[line + 0 + i];
    for (int i = 0; i < 1; ++i) dat[12 + i] = DATA_BUF[line + 12 + i];
}

void gather_trial_1(const T x[N_X], int f, T in[12], T dat[13]) {
    const int vb = FACTOR_VAR_BEGIN[f];
    const int line = FACTOR_DATA_OFF[f], h = line >> 1, p = line & 1;
    for (int i = 0; i < 12; ++i) in[0 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 0]] + i];
    T w[14];  // DATA_BUF[2 h + 0 ...]: the line's words from 0 at w[p ...]
#pragma HLS ARRAY_PARTITION variable=w complete
    for (int i = 0; i < 13; ++i) w[i] = DATA_BUF[2 * h + 0 + i];
    w[13] = p ? DATA_BUF[2 * h + 13] : T(0);  // an odd line's last word
    for (int i = 0; i < 12; ++i) dat[0 + i] = p ? w[1 + i] : w[0 + i];
    for (int i = 0; i < 1; ++i) dat[12 + i] = p ? w[13 + i] : w[12 + i];
}

// block 1, Jacobian mode: per instance residual + Jacobian (its 33 structural non-zeros of
// 6 x 7), whitening, into AB; one instance every II=111 cycles (the plan's)
void evaluate_1(const T x[N_X], hls::stream<GradWord>& grad) {
    for (int i = 0; i < 1; ++i) {
#pragma HLS PIPELINE II=111
        const int f = BLOCK1_INSTANCES[i];
        T in[12], dat[13];
        gather_1(x, f, in, dat);
        T raw[48];  // the Jacobian writes only its structural non-zeros
        T ab[48];
        for (int c = 0; c < 48; ++c) raw[c] = T(0);
        factor_1(in, dat, raw);
        whiten<8, 7, 6, 0, 6>(raw + 0, ab + 0, dat + 12);
        const int a0 = FACTOR_A_OFF[f];
        for (int r = 0; r < 6; ++r) {
            for (int c = 0; c < 7; ++c) AB[a0 + r * 7 + c] = ab[r * 8 + c];
        }
        // and beside AB, to the gradient (reduce_all, the same DATAFLOW region): 24 stream words
        for (int r = 0; r < 6; ++r) grad_row<8, 7>(ab + r * 8, grad);
    }
    // (one process of linearize_rows' region: the datapaths one after another)
    FGC_CYCLES("datapaths", 0, "factor_1_jacobian", 1, 111, 416);
}

// block 1's whitened rows of instance f from AB, padded to 8 columns (a multiple of PORTS)
void load_rows_1(int f, T ab[48]) {
    const int a0 = FACTOR_A_OFF[f];
    for (int e = 0; e < 48; e += PORTS) {  // PORTS words a cycle
#pragma HLS PIPELINE II=1
        for (int h = 0; h < PORTS; ++h) {
            const int r = (e + h) / 8, c = (e + h) % 8;
            ab[e + h] = c < 7 ? T(AB[a0 + r * 7 + c]) : T(0);
        }
    }
}

// block 1: the gradient of each instance from the datapath's stream; false if not
// finite. INLINE into reduce_all, whose ALLOCATION makes every block type's accumulate one module
bool reduce_1(hls::stream<GradWord>& grad, T& sq) {
#pragma HLS INLINE
    bool finite = true;
    for (int i = 0; i < 1; ++i) {
        const int f = BLOCK1_INSTANCES[i];
        const int vb = FACTOR_VAR_BEGIN[f];
        int col[GRAD_COLS];  // per column: its tangent entry
        for (int j = 0; j < 6; ++j) col[0 + j] = VAR_T_OFF[FACTOR_VARS[vb + 0]] + j;
        finite = accumulate(grad, col, 8, 7, 6, sq) && finite;
        // column map, A^T b PORTS columns a cycle from the stream (a dot product of m rows x
        // STRIDE / PORTS groups: the plan's rule), the scatter into G
        FGC_CYCLES("gradient", 0, "reduce_1_columns", 6, 1, 1);
        if (i == 0) FGC_WAIT("gradient", 0, "datapaths", 0, "factor_1_jacobian");
        FGC_CYCLES("gradient", 0, "reduce_1_rows", 24, fgc_units::dot_ii(24, T_PARTIALS, T_ADD_LAT),
                   fgc_units::dot_depth(24, T_PARTIALS, T_ADD_LAT, T_MUL_LAT));
        FGC_CYCLES("gradient", 0, "reduce_1_scatter", 7, 1, 6 + T_ADD_LAT * fgc_units::ceil_log2(T_PARTIALS));
    }
    return finite;
}

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
        for (int c = 0; c < 8; ++c) scale[c] = T(0);
        for (int j = 0; j < 6; ++j) scale[0 + j] = VAR_SCALE[FACTOR_VARS[vb + 0]];
        noise += rounding_noise(ab, scale, 8, 7, 6);
        FGC_CYCLES("noise_1", 0, "load", 24, 1, 2);
        FGC_CYCLES("noise_1", 0, "scales", 8, 1, 1);
        FGC_CYCLES("noise_1", 0, "rows", 6, 19, 33);
        FGC_CYCLES("noise_1", 0, "terms", 2, 12, 25);
    }
    return noise;
}

// linearize_rows' processes. The datapaths in Jacobian mode one after another, each instance's
// whitened rows into AB and to the gradient's stream:
void evaluate_all(const T x[N_X], hls::stream<GradWord>& grad) {
    evaluate_0(x, grad);
    evaluate_1(x, grad);
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
    ok = reduce_1(grad, s) && ok;
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
const int TRIAL_F_0[7] = {  // per entry of cost loop 0: its instance (-1: none)
    -1, 3, 4, 0, 5, 1, 2,
};
const int TRIAL_X0_0[14] = {  // per entry, 2 a row: where each variable it takes goes in x
    12, 36, 48, 0, 0, 0, 0, 0, 0, 0, 24, 0, 0, 0,
};
const int TRIAL_X1_0[14] = {  // and where it ends (x0 = x1: none)
    24, 48, 60, 0, 0, 0, 12, 0, 0, 0, 36, 0, 0, 0,
};
const int TRIAL_F_1[1] = {  // per entry of cost loop 1: its instance (-1: none)
    6,
};
void trial_cost(hls::stream<TrialVar>& tx, hls::stream<TrialVar>& tx2) {
    (void)tx2;  // (back-substitution by columns: the second cost process's stream, none here)
#pragma HLS ARRAY_PARTITION variable=DATA_BUF cyclic factor=2
    FGC_OUTER_BRANCH();  // csim cycle counting only: the third process of back_substitute
    T x[N_X];  // the variables taken so far
    T total = T(0);
    // block 0 (BetweenFactorPose3): 7 entries, one every II=24 cycles (the plan's)
    for (int e = 0; e < 7; ++e) {
#pragma HLS PIPELINE II=24
        for (int j = 0; j < 2; ++j) {  // the variables retired since, in order
            const int x0 = TRIAL_X0_0[e * 2 + j], x1 = TRIAL_X1_0[e * 2 + j];
            if (x0 < x1) {
                FGC_OUTER_ABSORB();  // csim cycle counting: no earlier than it was sent
                const TrialVar t = tx.read();
                for (int w = 0; w < MAX_STORAGE; ++w) {
                    if (x0 + w < x1) x[x0 + w] = t.word[w];
                }
            }
        }
        const int f = TRIAL_F_0[e];
        if (f >= 0) {
        T in[24], dat[13], half[1];
        gather_trial_0(x, f, in, dat);
        factor_cost_0(in, dat, half);
        T cost = T(0);
        cost += half[0];  // no robust loss on this member (the Program's flag)
            total += cost;
        }
        FGC_CYCLES("trial_cost", 0, "cost_0", 1, 24, 390);
    }
    // block 1 (PriorFactorPose3): 1 entries, one every II=48 cycles (the plan's)
    for (int e = 0; e < 1; ++e) {
#pragma HLS PIPELINE II=48
        const int f = TRIAL_F_1[e];
        if (f >= 0) {
        T in[12], dat[13], half[1];
        gather_trial_1(x, f, in, dat);
        factor_cost_1(in, dat, half);
        T cost = T(0);
        cost += half[0];  // no robust loss on this member (the Program's flag)
            total += cost;
        }
        FGC_CYCLES("trial_cost", 0, "cost_1", 1, 48, 377);
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

// The state update of variable v, fed by back-substitution (fgc_backsub.h's backsub_retire, a
// variable an iteration as its step is solved): X_TRIAL = X (+) delta on v, through its type's
// datapath (the branches exclusive: each datapath one instance)
const int VAR_KIND[5] = {  // per variable its type (retract_<k>)
    0, 0, 0, 0, 0,
};
const int RETIRE_VARS[5] = {  // the variables in the order back-substitution solves them
    1, 3, 4, 0, 2,
};
const int RETIRE_STEP[5] = {  // per entry of RETIRE_VARS: its step if it is the step's first variable, else -1
    2, -1, -1, 0, 1,
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
    static const int UNIT_SETS = 1;  // a level's steps go UNIT_SETS at a time to the unit sets
    static const int MAX_LEVEL_WIDTH = 2;
    static const int ROOT_II = 1, ROOT_DEPTH = 15;  // sqrt(mu), once per solve
    // fgc_eliminate.h's loops: the tables' largest trip counts, the plan's (II, depth) of L
    static const int MAX_STEP_FACTORS = 3, MAX_CHILDREN = 2;
    static const int TRIP_COND = 171;  // a conditional, PORTS words a cycle
    static const int TRIP_BANKS = 270;  // a step's rows in the banks
    static const int TRIP_ROWS = 513;  // a factor's rows, PORTS words a cycle
    static const int TRIP_UPDATE = 181;  // a new factor, PORTS words a cycle
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
    static const int RETIRE_II = 22, RETIRE_DEPTH = 212;
    static void retract_variable(int v, const T delta[N_TANGENT], bool at_x,
                                 hls::stream<::fgc::TrialVar>& tx) {
        ::fgc::retract_variable(v, delta, at_x, tx);
    }
};

// ---- partial QR (paper A): per step the stacked rows [A | b] of its factors, its children's new
// factors and the damping rows sqrt(mu) I, column c in bank c % N_UNITS of its unit set's work
// memory; qr_step runs one DATAFLOW region per reflection (qr_broadcast, qr_finish -> 4 qr_update
// units -> qr_evaluate, qr_collect; 24 streams) and stores the conditional and the new factor. A schedule
// level's steps go 1 at a time to the unit sets, side by side in one DATAFLOW region.
L WORK0[N_UNITS][MAX_ROWS][LOCAL_COLS];  // unit set 0's banks (partitioned by bank in eliminate_all)
L CONDBUF0[MAX_F * LesConfig::MAX_COLS];  // its step's conditional
L UPDBUF0[LesConfig::MAX_COLS * LesConfig::MAX_COLS];  // its step's new factor

// Unit set 0: one step (rows = 0: none this time).
void qr_set0(int rows, int f, int s, L work[N_UNITS][MAX_ROWS][LOCAL_COLS],
             L cond[MAX_F * LesConfig::MAX_COLS], L update[LesConfig::MAX_COLS * LesConfig::MAX_COLS],
             bool* singular) {
    FGC_BRANCH();  // csim cycle counting only: the unit sets of a level run side by side
    fgc_units::qr_step<LesConfig>(work, rows, f, s, cond, update, singular);
}

// One level's steps on the 1 unit set(s) side by side: each on its own memories.
void qr_level(int rows0, int f0, int s0,
              L work0[N_UNITS][MAX_ROWS][LOCAL_COLS],
              L cond0[MAX_F * LesConfig::MAX_COLS],
              L update0[LesConfig::MAX_COLS * LesConfig::MAX_COLS], bool* bad0) {
#pragma HLS DATAFLOW
    qr_set0(rows0, f0, s0, work0, cond0, update0, bad0);
}

// the elimination driver (fgc_eliminate.h) on these tables and memories, the unit sets'
// wiring its hooks: each set's banks, the qr_level region, each set's buffers
#define FGC_ELIMINATE_QR
#include "fgc_eliminate.h"

struct QrSets {
    static void stack(int u, int s, T root_mu, unsigned skip, int rows, bool solve) {
        (void)solve;  // (no rows are written into the banks before the stack)
        if (u == 0) qr_stack_rows<LesConfig>(s, root_mu, WORK0, skip, rows);
    }
    static void level(const bool has[1], const int s[1], const int rows[1], bool bad[1]) {
        qr_level(rows[0], has[0] ? STEP_F[s[0]] : 0,
                 has[0] ? STEP_W[s[0]] - STEP_F[s[0]] : 0, WORK0, CONDBUF0, UPDBUF0, &bad[0]);
    }
    static void commit(int u, int s) {
        if (u == 0) qr_commit<LesConfig>(s, CONDBUF0, UPDBUF0);
    }
};

bool eliminate_all(T mu) {
    // each unit set's banks: the global itself partitioned (what qr_stack and the Update units
    // read and write), one memory per bank, N_UNITS words a cycle
    // (each bank two memories by row parity: fgc_qr.h streams the next pivot column two rows a
    // cycle)
#pragma HLS ARRAY_PARTITION variable=WORK0 complete dim=1
#pragma HLS ARRAY_PARTITION variable=WORK0 cyclic factor=2 dim=2
    return qr_eliminate_all<LesConfig, QrSets>(mu);
}

// ---- back-substitution on two lanes (fgc_backsub.h's driver: back_substitute), slot by slot:
// the step each slot solves and loads (-1: none) and the lane that solves
const int BS_SLOTS = 5;
const int BS_SOLVE[BS_SLOTS] = {-1, 2, -1, 0, 1};
const int BS_LOAD[BS_SLOTS] = {2, -1, 0, 1, -1};
const int BS_LANE[BS_SLOTS] = {1, 0, 0, 1, 0};
// the loaded separator's solution in the loading lane's BS_X from this offset (-1: from DELTA)
const int BS_XOFF[BS_SLOTS] = {-1, -1, -1, 0, -1};
// HlsConfig backsub_lanes = 4: back-substitution by columns, one process per end of the chain
// (fgc_backsub.h's backsub_loader, backsub_end0 / backsub_end1; units/backsub.py's column_*)
#define FGC_BS_COLUMNS 1
const int BSC_SEQ[3] = {  // per end (from BSC_SEQ_BEGIN[e]) its steps, the root first on end 0: the loader streams their groups in this order
    2, 0, 1,
};
const int BSC_SEQ_BEGIN[3] = {
    0, 2, 3,
};
const int BSC_PASS_BEGIN[3] = {  // per end its passes from here
    0, 4, 7,
};
const int BSC_STEP[7] = {  // per pass: the step whose columns it runs (-1: none)
    -1, -1, 2, 0, -1, 2, 1,
};
const int BSC_CHILD[7] = {  // the step whose rows its columns update too (-1: none)
    -1, -1, 0, -1, -1, 1, -1,
};
const int BSC_INGEST[7] = {  // the step whose groups it takes in (-1: none)
    2, 0, -1, -1, 1, -1, -1,
};
const int BSC_SLOT[7] = {  // the buffer slots of the three
    -1, -1, 0, 1, -1, -1, 0,
};
const int BSC_CSLOT[7] = {
    -1, -1, 1, -1, -1, 0, -1,
};
const int BSC_ISLOT[7] = {
    0, 1, -1, -1, 0, -1, -1,
};
const int BSC_FEED[7] = {  // end 1's pass over the root's columns (x_r from end 0)
    0, 0, 0, 0, 0, 1, 0,
};
const int BSC_ROOT[7] = {  // end 0's pass sending the root's x_r to end 1
    0, 0, 1, 0, 0, 0, 0,
};
const int BSC_COLA_BEGIN[7] = {
    0, 0, 0, 18, 24, 24, 42,
};
const int BSC_COLA[48] = {  // per pass column r: its position in the child's separator (-1: none)
    0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, -1, -1, -1, -1,
    -1, -1, -1, -1, -1, -1, -1, -1, 0, 1, 2, 3, 4, 5, 6, 7,
    8, 9, 10, 11, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1, -1,
};
const int BSC_END_OF[3] = {  // per step: its end (the state update's stream)
    0, 1, 0,
};
#define BSC_FIFO0 21  // the loader's streams (as deep as an end lags it)
#define BSC_FIFO1 2
#define BSC_DX0 12  // the ends' solution streams (all their steps' pairs)
#define BSC_DX1 3
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

void pose_graph_top(const fgc::T x_in[fgc::N_X], const fgc::T data[fgc::N_DATA],
                    fgc::T x_out[fgc::N_X], fgc::T errors[2], int info[3]) {
#pragma HLS INTERFACE m_axi port=x_in offset=slave bundle=gmem0 depth=60
#pragma HLS INTERFACE m_axi port=data offset=slave bundle=gmem1 depth=105
#pragma HLS INTERFACE m_axi port=x_out offset=slave bundle=gmem0 depth=60
#pragma HLS INTERFACE s_axilite port=errors
#pragma HLS INTERFACE s_axilite port=info
#pragma HLS INTERFACE s_axilite port=return
    fgc_units::lm_top<fgc::LmConfig>(x_in, data, x_out, fgc::X, fgc::DATA_BUF, errors, info);
}
