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
    const T t0 = in[0]*in[12] + in[3]*in[15] + in[6]*in[18];
    const T t1 = in[2]*in[12] + in[5]*in[15] + in[8]*in[18];
    const T t2 = -t1;
    const T t3 = in[1]*in[12] + in[4]*in[15] + in[7]*in[18];
    const T t4 = in[0]*in[14] + in[3]*in[17] + in[6]*in[20];
    const T t5 = -t4;
    const T t6 = in[0]*in[13] + in[3]*in[16] + in[6]*in[19];
    const T t7 = -t0;
    const T t8 = in[1]*in[14] + in[4]*in[17] + in[7]*in[20];
    const T t9 = -t8;
    const T t10 = in[1]*in[13] + in[4]*in[16] + in[7]*in[19];
    const T t11 = -t3;
    const T t12 = in[2]*in[14] + in[5]*in[17] + in[8]*in[20];
    const T t13 = -t12;
    const T t14 = in[2]*in[13] + in[5]*in[16] + in[8]*in[19];
    const T t15 = -t14;
    const T t16 = -t6;
    const T t17 = -t10;
    const T t18 = t0;
    const T t19 = t3;
    const T t20 = t1;
    const T t21 = t18*dat[0] + t19*dat[3] + t20*dat[6];
    const T t22 = t6;
    const T t23 = t10;
    const T t24 = t14;
    const T t25 = t22*dat[0] + t23*dat[3] + t24*dat[6];
    const T t26 = t4;
    const T t27 = t8;
    const T t28 = t12;
    const T t29 = t28*dat[6] + t26*dat[0] + t27*dat[3];
    const T t30 = t18*dat[1] + t19*dat[4] + t20*dat[7];
    const T t31 = t22*dat[1] + t23*dat[4] + t24*dat[7];
    const T t32 = t28*dat[7] + t26*dat[1] + t27*dat[4];
    const T t33 = t18*dat[2] + t19*dat[5] + t20*dat[8];
    const T t34 = t22*dat[2] + t23*dat[5] + t24*dat[8];
    const T t35 = t28*dat[8] + t26*dat[2] + t27*dat[5];
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
    const T t45 = t44*t38;
    const T t46 = t45*t40;
    const T t47 = -t37 + t46;
    const T t48 = (T(0.5))*t29;
    const T t49 = (T(0.5))*t40;
    const T t50 = t45*t36;
    const T t51 = t49 + t50;
    const T t52 = -t47*t48 + (T(0.5))*t51*t25;
    const T t53 = -t43*t44 + T(1);
    const T t54 = (T(0.5))*t51;
    const T t55 = t48*t53 - t54*t21;
    const T t56 = (T(0.5))*t47;
    const T t57 = (T(0.5))*t53;
    const T t58 = t56*t21 - t57*t25;
    const T t59 = t54*t31 - t56*t32;
    const T t60 = (T(0.5))*t53*t32 - t54*t30;
    const T t61 = t56*t30 - t57*t31;
    const T t62 = t54*t34 - t56*t35;
    const T t63 = (T(0.5))*t53*t35 - t54*t33;
    const T t64 = t56*t33 - t57*t34;
    const T t65 = t44*(-t39 - t42) + T(1);
    const T t66 = (T(0.5))*t38;
    const T t67 = t44*t40*t36 - t66;
    const T t68 = -t48*t65 + (T(0.5))*t67*t25;
    const T t69 = t37 + t46;
    const T t70 = (T(0.5))*t67;
    const T t71 = t48*t69 - t70*t21;
    const T t72 = (T(0.5))*t65;
    const T t73 = (T(0.5))*t69;
    const T t74 = t72*t21 - t73*t25;
    const T t75 = t70*t31 - t72*t32;
    const T t76 = (T(0.5))*t69*t32 - t70*t30;
    const T t77 = t72*t30 - t73*t31;
    const T t78 = t70*t34 - t72*t35;
    const T t79 = (T(0.5))*t69*t35 - t70*t33;
    const T t80 = t72*t33 - t73*t34;
    const T t81 = t40*t36;
    const T t82 = t44*t81 + t66;
    const T t83 = t44*(-t39 - t41) + T(1);
    const T t84 = -t48*t82 + (T(0.5))*t83*t25;
    const T t85 = -t49 + t50;
    const T t86 = (T(0.5))*t83;
    const T t87 = t48*t85 - t86*t21;
    const T t88 = (T(0.5))*t82;
    const T t89 = (T(0.5))*t85;
    const T t90 = t88*t21 - t89*t25;
    const T t91 = t86*t31 - t88*t32;
    const T t92 = (T(0.5))*t85*t32 - t86*t30;
    const T t93 = t88*t30 - t89*t31;
    const T t94 = t86*t34 - t88*t35;
    const T t95 = (T(0.5))*t85*t35 - t86*t33;
    const T t96 = t88*t33 - t89*t34;
    const T t97 = T(2)*t40;
    const T t98 = T(2)*t36;
    const T t99 = T(2)*t38;
    const T t100 = t41;
    const T t101 = t42;
    const T t102 = t100 + t101;
    const T t103 = t39;
    const T t104 = t102 + t103;
    const T t105 = lie_D1(t104);
    const T t106 = -in[9] + in[21];
    const T t107 = -in[10] + in[22];
    const T t108 = -in[11] + in[23];
    const T t109 = t106*in[2] + t107*in[5] + t108*in[8];
    const T t110 = t106*in[1] + t107*in[4] + t108*in[7];
    const T t111 = -in[0]*in[1] - in[3]*in[4] - in[6]*in[7];
    const T t112 = -in[0]*in[2] - in[3]*in[5] - in[6]*in[8];
    const T t113 = t106*in[0] + t107*in[3] + t108*in[6];
    const T t114 = -in[1]*in[2] - in[4]*in[5] - in[7]*in[8];
    const T t115 = lie_D(t104);
    const T t116 = t40*t115;
    const T t117 = t36*t115;
    const T t118 = -t102*t115 + T(1);
    const T t119 = t37;
    const T t120 = t38*t115;
    const T t121 = t40*t120;
    const T t122 = t119 + t121;
    const T t123 = t49;
    const T t124 = t36*t120;
    const T t125 = -t123 + t124;
    const T t126 = -t119 + t121;
    const T t127 = -t101 - t103;
    const T t128 = t127*t115 + T(1);
    const T t129 = t66;
    const T t130 = t81*t115;
    const T t131 = t129 + t130;
    const T t132 = t123 + t124;
    const T t133 = -t129 + t130;
    const T t134 = -t100 - t103;
    const T t135 = t134*t115 + T(1);
    const T t136 = -in[0]*in[9] + in[0]*in[21] - in[3]*in[10] + in[3]*in[22] - in[6]*in[11] + in[6]*in[23];
    const T t137 = -in[1]*in[9] + in[1]*in[21] - in[4]*in[10] + in[4]*in[22] - in[7]*in[11] + in[7]*in[23];
    const T t138 = -in[2]*in[9] + in[2]*in[21] - in[5]*in[10] + in[5]*in[22] - in[8]*in[11] + in[8]*in[23];
    const T t139 = t136*dat[0] + t137*dat[3] + t138*dat[6] - dat[0]*dat[9] - dat[3]*dat[10] - dat[6]*dat[11];
    const T t140 = t102*t139;
    const T t141 = t115*t139;
    const T t142 = t136*dat[1] + t137*dat[4] + t138*dat[7] - dat[1]*dat[9] - dat[4]*dat[10] - dat[7]*dat[11];
    const T t143 = t127*t142;
    const T t144 = t115*t142;
    const T t145 = t136*dat[2] + t137*dat[5] + t138*dat[8] - dat[2]*dat[9] - dat[5]*dat[10] - dat[8]*dat[11];
    const T t146 = t134*t145;
    const T t147 = t115*t145;
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
    const T t160 = t152*dat[3] + t156*dat[6];
    const T t161 = t148*dat[0] + t157*dat[6];
    const T t162 = t149*dat[0] + t153*dat[3];
    const T t163 = t158*dat[6] + t150*dat[0] + t154*dat[3];
    const T t164 = t159*dat[6] + t151*dat[0] + t155*dat[3];
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
    const T t177 = t169*dat[3] + t173*dat[6];
    const T t178 = t165*dat[0] + t174*dat[6];
    const T t179 = t166*dat[0] + t170*dat[3];
    const T t180 = t167*dat[0] + t171*dat[3] + t175*dat[6];
    const T t181 = t168*dat[0] + t172*dat[3] + t176*dat[6];
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
    const T t194 = t186*dat[3] + t190*dat[6];
    const T t195 = t182*dat[0] + t191*dat[6];
    const T t196 = t183*dat[0] + t187*dat[3];
    const T t197 = t184*dat[0] + t188*dat[3] + t192*dat[6];
    const T t198 = t185*dat[0] + t189*dat[3] + t193*dat[6];
    const T t199 = t152*dat[4] + t156*dat[7];
    const T t200 = t148*dat[1] + t157*dat[7];
    const T t201 = t149*dat[1] + t153*dat[4];
    const T t202 = t158*dat[7] + t150*dat[1] + t154*dat[4];
    const T t203 = t159*dat[7] + t151*dat[1] + t155*dat[4];
    const T t204 = t169*dat[4] + t173*dat[7];
    const T t205 = t165*dat[1] + t174*dat[7];
    const T t206 = t166*dat[1] + t170*dat[4];
    const T t207 = t167*dat[1] + t171*dat[4] + t175*dat[7];
    const T t208 = t168*dat[1] + t172*dat[4] + t176*dat[7];
    const T t209 = t186*dat[4] + t190*dat[7];
    const T t210 = t182*dat[1] + t191*dat[7];
    const T t211 = t183*dat[1] + t187*dat[4];
    const T t212 = t184*dat[1] + t188*dat[4] + t192*dat[7];
    const T t213 = t185*dat[1] + t189*dat[4] + t193*dat[7];
    const T t214 = t152*dat[5] + t156*dat[8];
    const T t215 = t148*dat[2] + t157*dat[8];
    const T t216 = t149*dat[2] + t153*dat[5];
    const T t217 = t158*dat[8] + t150*dat[2] + t154*dat[5];
    const T t218 = t159*dat[8] + t151*dat[2] + t155*dat[5];
    const T t219 = t169*dat[5] + t173*dat[8];
    const T t220 = t165*dat[2] + t174*dat[8];
    const T t221 = t166*dat[2] + t170*dat[5];
    const T t222 = t167*dat[2] + t171*dat[5] + t175*dat[8];
    const T t223 = t168*dat[2] + t172*dat[5] + t176*dat[8];
    const T t224 = t186*dat[5] + t190*dat[8];
    const T t225 = t182*dat[2] + t191*dat[8];
    const T t226 = t183*dat[2] + t187*dat[5];
    const T t227 = t184*dat[2] + t188*dat[5] + t192*dat[8];
    const T t228 = t185*dat[2] + t189*dat[5] + t193*dat[8];
    const T t229 = t52*t160 + t55*t177 + t58*t194 + t59*t199 + t60*t204 + t61*t209 + t62*t214 + t63*t219 + t64*t224;
    const T t230 = t52*t161 + t55*t178 + t58*t195 + t59*t200 + t60*t205 + t61*t210 + t62*t215 + t63*t220 + t64*t225;
    const T t231 = t52*t162 + t55*t179 + t58*t196 + t59*t201 + t60*t206 + t61*t211 + t62*t216 + t63*t221 + t64*t226;
    const T t232 = t55*t180 + t58*t197 + t60*t207 + t61*t212 + t63*t222 + t64*t227;
    const T t233 = t52*t163 + t58*t198 + t59*t202 + t61*t213 + t62*t217 + t64*t228;
    const T t234 = t52*t164 + t55*t181 + t59*t203 + t60*t208 + t62*t218 + t63*t223;
    const T t235 = t68*t160 + t71*t177 + t74*t194 + t75*t199 + t76*t204 + t77*t209 + t78*t214 + t79*t219 + t80*t224;
    const T t236 = t68*t161 + t71*t178 + t74*t195 + t75*t200 + t76*t205 + t77*t210 + t78*t215 + t79*t220 + t80*t225;
    const T t237 = t68*t162 + t71*t179 + t74*t196 + t75*t201 + t76*t206 + t77*t211 + t78*t216 + t79*t221 + t80*t226;
    const T t238 = t71*t180 + t74*t197 + t76*t207 + t77*t212 + t79*t222 + t80*t227;
    const T t239 = t68*t163 + t74*t198 + t75*t202 + t77*t213 + t78*t217 + t80*t228;
    const T t240 = t68*t164 + t71*t181 + t75*t203 + t76*t208 + t78*t218 + t79*t223;
    const T t241 = t84*t160 + t87*t177 + t90*t194 + t91*t199 + t92*t204 + t93*t209 + t94*t214 + t95*t219 + t96*t224;
    const T t242 = t84*t161 + t87*t178 + t90*t195 + t91*t200 + t92*t205 + t93*t210 + t94*t215 + t95*t220 + t96*t225;
    const T t243 = t84*t162 + t87*t179 + t90*t196 + t91*t201 + t92*t206 + t93*t211 + t94*t216 + t95*t221 + t96*t226;
    const T t244 = t87*t180 + t90*t197 + t92*t207 + t93*t212 + t95*t222 + t96*t227;
    const T t245 = t84*t163 + t90*t198 + t91*t202 + t93*t213 + t94*t217 + t96*t228;
    const T t246 = t84*t164 + t87*t181 + t91*t203 + t92*t208 + t94*t218 + t95*t223;
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
    const T t271 = t105*t259 + t105*t265;
    const T t272 = t105*t260 + t105*t266;
    const T t273 = t105*t261 + t105*t267;
    const T t274 = t105*t262 + t105*t268;
    const T t275 = t105*t263 + t105*t269;
    const T t276 = t105*t264 + t105*t270;
    const T t277 = -t109;
    const T t278 = t110;
    const T t279 = -(in[0]*in[0]) - (in[3]*in[3]) - (in[6]*in[6]);
    const T t280 = t111;
    const T t281 = t112;
    const T t282 = t0;
    const T t283 = t6;
    const T t284 = t4;
    const T t285 = t109;
    const T t286 = -t113;
    const T t287 = t111;
    const T t288 = -(in[1]*in[1]) - (in[4]*in[4]) - (in[7]*in[7]);
    const T t289 = t114;
    const T t290 = t3;
    const T t291 = t10;
    const T t292 = t8;
    const T t293 = -t110;
    const T t294 = t113;
    const T t295 = t112;
    const T t296 = t114;
    const T t297 = -(in[2]*in[2]) - (in[5]*in[5]) - (in[8]*in[8]);
    const T t298 = t1;
    const T t299 = t14;
    const T t300 = t12;
    const T t301 = t285*dat[3] + t293*dat[6];
    const T t302 = t277*dat[0] + t294*dat[6];
    const T t303 = t278*dat[0] + t286*dat[3];
    const T t304 = t279*dat[0] + t287*dat[3] + t295*dat[6];
    const T t305 = t280*dat[0] + t288*dat[3] + t296*dat[6];
    const T t306 = t281*dat[0] + t289*dat[3] + t297*dat[6];
    const T t307 = t282*dat[0] + t290*dat[3] + t298*dat[6];
    const T t308 = t283*dat[0] + t291*dat[3] + t299*dat[6];
    const T t309 = t284*dat[0] + t292*dat[3] + t300*dat[6];
    const T t310 = (T(0.5))*t241;
    const T t311 = (T(0.5))*t242;
    const T t312 = (T(0.5))*t243;
    const T t313 = (T(0.5))*t244;
    const T t314 = (T(0.5))*t245;
    const T t315 = (T(0.5))*t246;
    const T t316 = t38*t271 + t115*t229;
    const T t317 = t38*t272 + t115*t230;
    const T t318 = t38*t273 + t115*t231;
    const T t319 = t38*t274 + t115*t232;
    const T t320 = t38*t275 + t115*t233;
    const T t321 = t38*t276 + t115*t234;
    const T t322 = t40*t316 + t120*t235;
    const T t323 = t40*t317 + t120*t236;
    const T t324 = t40*t318 + t120*t237;
    const T t325 = t40*t319 + t120*t238;
    const T t326 = t40*t320 + t120*t239;
    const T t327 = t40*t321 + t120*t240;
    const T t328 = t285*dat[4] + t293*dat[7];
    const T t329 = t277*dat[1] + t294*dat[7];
    const T t330 = t278*dat[1] + t286*dat[4];
    const T t331 = t279*dat[1] + t287*dat[4] + t295*dat[7];
    const T t332 = t280*dat[1] + t288*dat[4] + t296*dat[7];
    const T t333 = t281*dat[1] + t289*dat[4] + t297*dat[7];
    const T t334 = t282*dat[1] + t290*dat[4] + t298*dat[7];
    const T t335 = t283*dat[1] + t291*dat[4] + t299*dat[7];
    const T t336 = t284*dat[1] + t292*dat[4] + t300*dat[7];
    const T t337 = (T(0.5))*t235;
    const T t338 = (T(0.5))*t236;
    const T t339 = (T(0.5))*t237;
    const T t340 = (T(0.5))*t238;
    const T t341 = (T(0.5))*t239;
    const T t342 = (T(0.5))*t240;
    const T t343 = t36*t316 + t120*t241;
    const T t344 = t36*t317 + t120*t242;
    const T t345 = t36*t318 + t120*t243;
    const T t346 = t36*t319 + t120*t244;
    const T t347 = t36*t320 + t120*t245;
    const T t348 = t36*t321 + t120*t246;
    const T t349 = t285*dat[5] + t293*dat[8];
    const T t350 = t277*dat[2] + t294*dat[8];
    const T t351 = t278*dat[2] + t286*dat[5];
    const T t352 = t279*dat[2] + t287*dat[5] + t295*dat[8];
    const T t353 = t280*dat[2] + t288*dat[5] + t296*dat[8];
    const T t354 = t281*dat[2] + t289*dat[5] + t297*dat[8];
    const T t355 = t282*dat[2] + t290*dat[5] + t298*dat[8];
    const T t356 = t283*dat[2] + t291*dat[5] + t299*dat[8];
    const T t357 = t284*dat[2] + t292*dat[5] + t300*dat[8];
    const T t358 = (T(0.5))*t229;
    const T t359 = (T(0.5))*t230;
    const T t360 = (T(0.5))*t231;
    const T t361 = (T(0.5))*t232;
    const T t362 = (T(0.5))*t233;
    const T t363 = (T(0.5))*t234;
    const T t364 = t81*t271 + t116*t241 + t117*t235;
    const T t365 = t81*t272 + t116*t242 + t117*t236;
    const T t366 = t81*t273 + t116*t243 + t117*t237;
    const T t367 = t81*t274 + t116*t244 + t117*t238;
    const T t368 = t81*t275 + t116*t245 + t117*t239;
    const T t369 = t81*t276 + t116*t246 + t117*t240;
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
    raw[48] = -t140*t271 - t141*t259 + t118*t301 + t122*t328 + t125*t349 + t142*t310 + t142*t322 - t145*t337 + t145*t343;
    raw[49] = -t140*t272 - t141*t260 + t118*t302 + t122*t329 + t125*t350 + t142*t311 + t142*t323 - t145*t338 + t145*t344;
    raw[50] = -t140*t273 - t141*t261 + t118*t303 + t122*t330 + t125*t351 + t142*t312 + t142*t324 - t145*t339 + t145*t345;
    raw[51] = t118*t304 + t122*t331 + t125*t352;
    raw[52] = t118*t305 + t122*t332 + t125*t353;
    raw[53] = t118*t306 + t122*t333 + t125*t354;
    raw[54] = -t140*t274 - t141*t262 + t142*t313 + t142*t325 - t145*t340 + t145*t346;
    raw[55] = -t140*t275 - t141*t263 + t142*t314 + t142*t326 - t145*t341 + t145*t347;
    raw[56] = -t140*t276 - t141*t264 + t142*t315 + t142*t327 - t145*t342 + t145*t348;
    raw[57] = t118*t307 + t122*t334 + t125*t355;
    raw[58] = t118*t308 + t122*t335 + t125*t356;
    raw[59] = t118*t309 + t122*t336 + t125*t357;
    raw[60] = t118*t139 + t122*t142 + t125*t145;
    raw[64] = t143*t271 - t144*t253 - t144*t265 + t126*t301 + t128*t328 + t131*t349 - t139*t310 + t139*t322 + t145*t358 + t145*t364;
    raw[65] = t143*t272 - t144*t254 - t144*t266 + t126*t302 + t128*t329 + t131*t350 - t139*t311 + t139*t323 + t145*t359 + t145*t365;
    raw[66] = t143*t273 - t144*t255 - t144*t267 + t126*t303 + t128*t330 + t131*t351 - t139*t312 + t139*t324 + t145*t360 + t145*t366;
    raw[67] = t126*t304 + t128*t331 + t131*t352;
    raw[68] = t126*t305 + t128*t332 + t131*t353;
    raw[69] = t126*t306 + t128*t333 + t131*t354;
    raw[70] = t143*t274 - t144*t256 - t144*t268 - t139*t313 + t139*t325 + t145*t361 + t145*t367;
    raw[71] = t143*t275 - t144*t257 - t144*t269 - t139*t314 + t139*t326 + t145*t362 + t145*t368;
    raw[72] = t143*t276 - t144*t258 - t144*t270 - t139*t315 + t139*t327 + t145*t363 + t145*t369;
    raw[73] = t126*t307 + t128*t334 + t131*t355;
    raw[74] = t126*t308 + t128*t335 + t131*t356;
    raw[75] = t126*t309 + t128*t336 + t131*t357;
    raw[76] = t126*t139 + t128*t142 + t131*t145;
    raw[80] = t133*t328 + t135*t349 + t146*t271 - t147*t265 - t147*t247 + t132*t301 + t139*t337 + t139*t343 - t142*t358 + t142*t364;
    raw[81] = t133*t329 + t135*t350 + t146*t272 - t147*t248 - t147*t266 + t132*t302 + t139*t338 + t139*t344 - t142*t359 + t142*t365;
    raw[82] = t133*t330 + t135*t351 + t146*t273 - t147*t249 - t147*t267 + t132*t303 + t139*t339 + t139*t345 - t142*t360 + t142*t366;
    raw[83] = t133*t331 + t135*t352 + t132*t304;
    raw[84] = t133*t332 + t135*t353 + t132*t305;
    raw[85] = t133*t333 + t135*t354 + t132*t306;
    raw[86] = t146*t274 - t147*t250 - t147*t268 + t139*t340 + t139*t346 - t142*t361 + t142*t367;
    raw[87] = t146*t275 - t147*t251 - t147*t269 + t139*t341 + t139*t347 - t142*t362 + t142*t368;
    raw[88] = t146*t276 - t147*t252 - t147*t270 + t139*t342 + t139*t348 - t142*t363 + t142*t369;
    raw[89] = t133*t334 + t135*t355 + t132*t307;
    raw[90] = t133*t335 + t135*t356 + t132*t308;
    raw[91] = t133*t336 + t135*t357 + t132*t309;
    raw[92] = t133*t142 + t135*t145 + t132*t139;
}

void factor_cost_0(const T in[24], const T dat[13],
                   T half[1]) {
#pragma HLS INLINE off
#pragma HLS ALLOCATION operation instances=fadd limit=6
#pragma HLS ALLOCATION operation instances=fmul limit=8
#pragma HLS ALLOCATION operation instances=fdiv limit=1
#pragma HLS ALLOCATION operation instances=fsqrt limit=1
    const T t0 = in[0]*in[12] + in[3]*in[15] + in[6]*in[18];
    const T t1 = t0;
    const T t2 = in[1]*in[12] + in[4]*in[15] + in[7]*in[18];
    const T t3 = t2;
    const T t4 = in[2]*in[12] + in[5]*in[15] + in[8]*in[18];
    const T t5 = t4;
    const T t6 = t1*dat[0] + t3*dat[3] + t5*dat[6];
    const T t7 = in[0]*in[13] + in[3]*in[16] + in[6]*in[19];
    const T t8 = t7;
    const T t9 = in[1]*in[13] + in[4]*in[16] + in[7]*in[19];
    const T t10 = t9;
    const T t11 = in[2]*in[13] + in[5]*in[16] + in[8]*in[19];
    const T t12 = t11;
    const T t13 = t8*dat[0] + t10*dat[3] + t12*dat[6];
    const T t14 = in[0]*in[14] + in[3]*in[17] + in[6]*in[20];
    const T t15 = t14;
    const T t16 = in[1]*in[14] + in[4]*in[17] + in[7]*in[20];
    const T t17 = t16;
    const T t18 = in[2]*in[14] + in[5]*in[17] + in[8]*in[20];
    const T t19 = t18;
    const T t20 = t19*dat[6] + t15*dat[0] + t17*dat[3];
    const T t21 = t1*dat[1] + t3*dat[4] + t5*dat[7];
    const T t22 = t8*dat[1] + t10*dat[4] + t12*dat[7];
    const T t23 = t19*dat[7] + t15*dat[1] + t17*dat[4];
    const T t24 = t1*dat[2] + t3*dat[5] + t5*dat[8];
    const T t25 = t8*dat[2] + t10*dat[5] + t12*dat[8];
    const T t26 = t19*dat[8] + t15*dat[2] + t17*dat[5];
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
    const T t40 = t37 + t39;
    const T t41 = lie_D(t40);
    const T t42 = -t37*t41 + T(1);
    const T t43 = (T(0.5))*t31;
    const T t44 = t43;
    const T t45 = t27*t41;
    const T t46 = t29*t45;
    const T t47 = t44 + t46;
    const T t48 = (T(0.5))*t29;
    const T t49 = t48;
    const T t50 = t31*t45;
    const T t51 = -t49 + t50;
    const T t52 = -in[0]*in[9] + in[0]*in[21] - in[3]*in[10] + in[3]*in[22] - in[6]*in[11] + in[6]*in[23];
    const T t53 = -in[1]*in[9] + in[1]*in[21] - in[4]*in[10] + in[4]*in[22] - in[7]*in[11] + in[7]*in[23];
    const T t54 = -in[2]*in[9] + in[2]*in[21] - in[5]*in[10] + in[5]*in[22] - in[8]*in[11] + in[8]*in[23];
    const T t55 = t52*dat[0] + t53*dat[3] + t54*dat[6] - dat[0]*dat[9] - dat[3]*dat[10] - dat[6]*dat[11];
    const T t56 = t52*dat[1] + t53*dat[4] + t54*dat[7] - dat[1]*dat[9] - dat[4]*dat[10] - dat[7]*dat[11];
    const T t57 = t52*dat[2] + t53*dat[5] + t54*dat[8] - dat[2]*dat[9] - dat[5]*dat[10] - dat[8]*dat[11];
    const T t58 = t42*t55 + t47*t56 + t51*t57;
    const T t59 = -t44 + t46;
    const T t60 = -t36 - t39;
    const T t61 = t60*t41 + T(1);
    const T t62 = (T(0.5))*t27;
    const T t63 = t62;
    const T t64 = t29*t31;
    const T t65 = t64*t41;
    const T t66 = t63 + t65;
    const T t67 = t59*t55 + t61*t56 + t66*t57;
    const T t68 = t49 + t50;
    const T t69 = -t63 + t65;
    const T t70 = -t34 - t39;
    const T t71 = t70*t41 + T(1);
    const T t72 = t69*t56 + t71*t57 + t68*t55;
    const T t73 = (T(0.5))*(dat[12]*dat[12]);
    const T t74 = (t67*t67)*t73 + (t72*t72)*t73 + t73*t28 + t73*t30 + t73*t32 + t73*(t58*t58);
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

void factor_cost_1(const T in[12], const T dat[13],
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
    const T t61 = (T(0.5))*(dat[12]*dat[12]);
    const T t62 = t19*t61 + t21*t61 + t23*t61 + (t46*t46)*t61 + (t55*t55)*t61 + (t60*t60)*t61;
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
