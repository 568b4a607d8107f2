// generated from template accel.cpp.jinja by fgc 0.1.0 — do not edit
// Problem: imu_window
// chain graph, two-ended ordering; solver: lm cholesky auto n_u=4 cpe=20
//
// The dataflow accelerator of the accelerator plan (fgc_backends.hls.plan, docs/hls.md). One
// Levenberg-Marquardt iteration: the factor datapaths (Jacobian mode) -> whitened rows [A | b] (AB)
// -> the HGC (Gram of each factor) -> per step the frontal matrix through the #CPE cascade
// -> back-substitution -> state update (retract) -> the factor datapaths (cost mode) -> LM control.
//
// The linear solver's process network (from the plan): the units' DATAFLOW regions, then
// back_substitute's by columns (the loader streaming COND to a process per end of the chain,
// the state update fed by both):
//   51 processes, 89 streams (cpe=20)
//   process cpe_feed
//   process cpe_tap0
//   process cpe0
//   process cpe_tap1
//   process cpe1
//   process cpe_tap2
//   process cpe2
//   process cpe_tap3
//   process cpe3
//   process cpe_tap4
//   process cpe4
//   process cpe_tap5
//   process cpe5
//   process cpe_tap6
//   process cpe6
//   process cpe_tap7
//   process cpe7
//   process cpe_tap8
//   process cpe8
//   process cpe_tap9
//   process cpe9
//   process cpe_tap10
//   process cpe10
//   process cpe_tap11
//   process cpe11
//   process cpe_tap12
//   process cpe12
//   process cpe_tap13
//   process cpe13
//   process cpe_tap14
//   process cpe14
//   process cpe_tap15
//   process cpe15
//   process cpe_tap16
//   process cpe16
//   process cpe_tap17
//   process cpe17
//   process cpe_tap18
//   process cpe18
//   process cpe_tap19
//   process cpe19
//   process cpe_drain
//   process cholesky_gram_source
//   process cholesky_assembler
//   process cholesky_cascade
//   process backsub_loader
//   process backsub_end0
//   process backsub_end1
//   process backsub_retire
//   process trial_cost
//   process trial_cost_b
//   stream cpe_link0 depth=30: cpe_feed -> cpe_tap0
//   stream cpe_link1 depth=30: cpe0 -> cpe_tap1
//   stream cpe_link2 depth=30: cpe1 -> cpe_tap2
//   stream cpe_link3 depth=30: cpe2 -> cpe_tap3
//   stream cpe_link4 depth=30: cpe3 -> cpe_tap4
//   stream cpe_link5 depth=30: cpe4 -> cpe_tap5
//   stream cpe_link6 depth=30: cpe5 -> cpe_tap6
//   stream cpe_link7 depth=30: cpe6 -> cpe_tap7
//   stream cpe_link8 depth=30: cpe7 -> cpe_tap8
//   stream cpe_link9 depth=30: cpe8 -> cpe_tap9
//   stream cpe_link10 depth=30: cpe9 -> cpe_tap10
//   stream cpe_link11 depth=30: cpe10 -> cpe_tap11
//   stream cpe_link12 depth=30: cpe11 -> cpe_tap12
//   stream cpe_link13 depth=30: cpe12 -> cpe_tap13
//   stream cpe_link14 depth=30: cpe13 -> cpe_tap14
//   stream cpe_link15 depth=30: cpe14 -> cpe_tap15
//   stream cpe_link16 depth=30: cpe15 -> cpe_tap16
//   stream cpe_link17 depth=30: cpe16 -> cpe_tap17
//   stream cpe_link18 depth=30: cpe17 -> cpe_tap18
//   stream cpe_link19 depth=30: cpe18 -> cpe_tap19
//   stream cpe_tail0 depth=2: cpe0 -> cpe_drain
//   stream cpe_tapped0 depth=48: cpe_tap0 -> cpe0
//   stream cpe_recip0 depth=2: cpe_tap0 -> cpe0
//   stream cpe_tail1 depth=2: cpe1 -> cpe_drain
//   stream cpe_tapped1 depth=48: cpe_tap1 -> cpe1
//   stream cpe_recip1 depth=2: cpe_tap1 -> cpe1
//   stream cpe_tail2 depth=2: cpe2 -> cpe_drain
//   stream cpe_tapped2 depth=48: cpe_tap2 -> cpe2
//   stream cpe_recip2 depth=2: cpe_tap2 -> cpe2
//   stream cpe_tail3 depth=2: cpe3 -> cpe_drain
//   stream cpe_tapped3 depth=48: cpe_tap3 -> cpe3
//   stream cpe_recip3 depth=2: cpe_tap3 -> cpe3
//   stream cpe_tail4 depth=2: cpe4 -> cpe_drain
//   stream cpe_tapped4 depth=48: cpe_tap4 -> cpe4
//   stream cpe_recip4 depth=2: cpe_tap4 -> cpe4
//   stream cpe_tail5 depth=2: cpe5 -> cpe_drain
//   stream cpe_tapped5 depth=48: cpe_tap5 -> cpe5
//   stream cpe_recip5 depth=2: cpe_tap5 -> cpe5
//   stream cpe_tail6 depth=2: cpe6 -> cpe_drain
//   stream cpe_tapped6 depth=48: cpe_tap6 -> cpe6
//   stream cpe_recip6 depth=2: cpe_tap6 -> cpe6
//   stream cpe_tail7 depth=2: cpe7 -> cpe_drain
//   stream cpe_tapped7 depth=48: cpe_tap7 -> cpe7
//   stream cpe_recip7 depth=2: cpe_tap7 -> cpe7
//   stream cpe_tail8 depth=2: cpe8 -> cpe_drain
//   stream cpe_tapped8 depth=48: cpe_tap8 -> cpe8
//   stream cpe_recip8 depth=2: cpe_tap8 -> cpe8
//   stream cpe_tail9 depth=2: cpe9 -> cpe_drain
//   stream cpe_tapped9 depth=48: cpe_tap9 -> cpe9
//   stream cpe_recip9 depth=2: cpe_tap9 -> cpe9
//   stream cpe_tail10 depth=2: cpe10 -> cpe_drain
//   stream cpe_tapped10 depth=48: cpe_tap10 -> cpe10
//   stream cpe_recip10 depth=2: cpe_tap10 -> cpe10
//   stream cpe_tail11 depth=2: cpe11 -> cpe_drain
//   stream cpe_tapped11 depth=48: cpe_tap11 -> cpe11
//   stream cpe_recip11 depth=2: cpe_tap11 -> cpe11
//   stream cpe_tail12 depth=2: cpe12 -> cpe_drain
//   stream cpe_tapped12 depth=48: cpe_tap12 -> cpe12
//   stream cpe_recip12 depth=2: cpe_tap12 -> cpe12
//   stream cpe_tail13 depth=2: cpe13 -> cpe_drain
//   stream cpe_tapped13 depth=48: cpe_tap13 -> cpe13
//   stream cpe_recip13 depth=2: cpe_tap13 -> cpe13
//   stream cpe_tail14 depth=2: cpe14 -> cpe_drain
//   stream cpe_tapped14 depth=48: cpe_tap14 -> cpe14
//   stream cpe_recip14 depth=2: cpe_tap14 -> cpe14
//   stream cpe_tail15 depth=2: cpe15 -> cpe_drain
//   stream cpe_tapped15 depth=48: cpe_tap15 -> cpe15
//   stream cpe_recip15 depth=2: cpe_tap15 -> cpe15
//   stream cpe_tail16 depth=2: cpe16 -> cpe_drain
//   stream cpe_tapped16 depth=48: cpe_tap16 -> cpe16
//   stream cpe_recip16 depth=2: cpe_tap16 -> cpe16
//   stream cpe_tail17 depth=2: cpe17 -> cpe_drain
//   stream cpe_tapped17 depth=48: cpe_tap17 -> cpe17
//   stream cpe_recip17 depth=2: cpe_tap17 -> cpe17
//   stream cpe_tail18 depth=2: cpe18 -> cpe_drain
//   stream cpe_tapped18 depth=48: cpe_tap18 -> cpe18
//   stream cpe_recip18 depth=2: cpe_tap18 -> cpe18
//   stream cpe_tail19 depth=2: cpe19 -> cpe_drain
//   stream cpe_tapped19 depth=48: cpe_tap19 -> cpe19
//   stream cpe_recip19 depth=2: cpe_tap19 -> cpe19
//   stream grams depth=248: reduce_0 -> gram_source
//   stream frontal depth=139: cholesky_assembler -> cpe_feed
//   stream backsub_groups0 depth=97: backsub_loader -> backsub_end0
//   stream backsub_dx0 depth=39: backsub_end0 -> backsub_retire
//   stream backsub_groups1 depth=100: backsub_loader -> backsub_end1
//   stream backsub_dx1 depth=24: backsub_end1 -> backsub_retire
//   stream backsub_xroot depth=30: backsub_end0 -> backsub_end1
//   stream trial_tx depth=24: backsub_retire -> trial_cost
//   stream trial_tx2 depth=24: backsub_retire -> trial_cost_b
#include "imu_window.h"

#include "hls_stream.h"
#include "fgc_cpe.h"
#include "fgc_backsub.h"
#define FGC_LM_COST_IN_LINEARIZE  // fgc_lm.h: the first linearisation gives the cost at X (linearized_cost)
#define FGC_LM_GRADIENT_IN_SOLVE  // fgc_lm.h: the small-gradient test after the solve (its state update's maximum)
#define FGC_LM_TRIAL_IN_X  // fgc_lm.h: the solve's state update writes the trial into X (restore_x: not taken)
#define FGC_LM_LINEARIZE_SOLVE  // fgc_lm.h: linearize_x and solve_at share linearize_solve's one instance
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
const int N_CPE = 20;  // --cpe: process elements of the cascade

// ---- the schedule and layout as constant tables (ROMs; see fgc_backends/hls/tables.py)
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

// ---- the accelerator's memories: static, sized at compile time; nothing is allocated
T X[N_X];          // current estimate (storage)
T X_BACK[N_X];     // X as the last solve's state update read it (X then holds x (+) delta)
T DATA_BUF[N_DATA];  // the factor data, copied in once per call
// trial_cost_b's copy of DATA_BUF's words TRIAL_B_LO ... (its instances' lines; the top's data
// copy writes both): back_substitute's fourth process reads it, DATA_BUF the third
const int TRIAL_B_LO = 1364, TRIAL_B_WORDS = 31;
T DATA_B[TRIAL_B_WORDS];
L AB[N_A];         // whitened rows [A | b] of every factor instance (row-major, d + 1 columns)
T G[N_TANGENT];    // gradient A^T b
T G_BACK[N_TANGENT];  // G as the first solve after a linearisation read it (that solve zeroes G)
bool G_MOVED = false;  // G is in G_BACK (a solve ran since the linearisation), G zero
T LIN_SQ = T(0);  // sum of the instances' b^T b (their Grams' last diagonal entry): twice the cost at the linearisation point
T VAR_SCALE[N_VARIABLES];
T DELTA[N_TANGENT];
L COND[N_COND];    // conditionals (R | d), one block per elimination step
L NF[2][N_NF];     // update matrices passed to the parent step: the t-th step's in NF[t % 2] (the assembly reads one lane while the cascade writes the other)
L GRAM[N_GRAM] = {};  // per factor instance: packed lower triangle of [A | b]^T [A | b] (structural zeros never written)

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
// block 0: CombinedImuFactor (15 rows, 30 columns, 7 instances)
void factor_0(const T in[42], const T dat[193],
              T raw[480]) {
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
    const T t97 = t10*t21;
    const T t98 = t8*t21;
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
    const T t119 = t72*t105 + t8*t97;
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
    const T t203 = -in[15];
    const T t204 = -in[16];
    const T t205 = -in[17];
    const T t206 = -in[18];
    const T t207 = -in[19];
    const T t208 = -in[20];
    const T t209 = -in[21];
    const T t210 = -in[22];
    const T t211 = -in[23];
    const T t212 = (dat[47]*t5 + (dat[3] + dat[18]*t0)) + ((dat[19]*t1 + dat[20]*t2) + (dat[45]*t3 + dat[46]*t4));
    const T t213 = (dat[50]*t5 + (dat[4] + dat[21]*t0)) + ((dat[22]*t1 + dat[23]*t2) + (dat[48]*t3 + dat[49]*t4));
    const T t214 = (dat[53]*t5 + (dat[5] + dat[24]*t0)) + ((dat[25]*t1 + dat[26]*t2) + (dat[51]*t3 + dat[52]*t4));
    const T t215 = (T(0.5))*(dat[69]*dat[69]);
    const T t216 = (((dat[69]*in[12] + (in[9] - in[24])) + dat[70]*t215) + in[0]*t212) + (in[1]*t213 + in[2]*t214);
    const T t217 = (((dat[69]*in[13] + (in[10] - in[25])) + dat[71]*t215) + in[3]*t212) + (in[4]*t213 + in[5]*t214);
    const T t218 = (((dat[69]*in[14] + (in[11] - in[26])) + dat[72]*t215) + in[6]*t212) + (in[7]*t213 + in[8]*t214);
    const T t219 = in[21]*t218 + (in[15]*t216 + in[18]*t217);
    const T t220 = in[23]*t218 + (in[17]*t216 + in[20]*t217);
    const T t221 = in[22]*t218 + (in[16]*t216 + in[19]*t217);
    const T t222 = -(t198 + t200);
    const T t223 = t57;
    const T t224 = t68;
    const T t225 = t223*t107 + t224*t110;
    const T t226 = t223*t113 + t224*t114;
    const T t227 = t224*t117 + t223*t119;
    const T t228 = t71;
    const T t229 = t102;
    const T t230 = t228*t107 + t229*t110;
    const T t231 = t228*t113 + t229*t114;
    const T t232 = t229*t117 + t228*t119;
    const T t233 = t69;
    const T t234 = t66;
    const T t235 = t233*t107 + t234*t110;
    const T t236 = t233*t113 + t234*t114;
    const T t237 = t234*t117 + t233*t119;
    const T t238 = ((t230*t155 + t231*t156) + (t232*t157 + t235*t158)) + ((t236*t159 + t237*t160) + (t225*t161 + (t226*t147 + t227*t152)));
    const T t239 = t196*t238;
    const T t240 = lie_D(t201);
    const T t241 = t240*t239;
    const T t242 = t58;
    const T t243 = t56;
    const T t244 = t242*t103 + t243*t110;
    const T t245 = t243*t114 + t242*t115;
    const T t246 = t243*t117 + t242*t118;
    const T t247 = t100;
    const T t248 = t62;
    const T t249 = t247*t103 + t248*t110;
    const T t250 = t248*t114 + t247*t115;
    const T t251 = t248*t117 + t247*t118;
    const T t252 = t70;
    const T t253 = t60;
    const T t254 = t252*t103 + t253*t110;
    const T t255 = t253*t114 + t252*t115;
    const T t256 = t253*t117 + t252*t118;
    const T t257 = ((t249*t155 + t250*t156) + (t251*t157 + t254*t158)) + ((t255*t159 + t256*t160) + (t244*t161 + (t245*t147 + t246*t152)));
    const T t258 = t196*t257;
    const T t259 = t240*t258;
    const T t260 = t59;
    const T t261 = t64;
    const T t262 = t260*t103 + t261*t107;
    const T t263 = t261*t113 + t260*t115;
    const T t264 = t260*t118 + t261*t119;
    const T t265 = t67;
    const T t266 = t101;
    const T t267 = t265*t103 + t266*t107;
    const T t268 = t266*t113 + t265*t115;
    const T t269 = t265*t118 + t266*t119;
    const T t270 = t65;
    const T t271 = t61;
    const T t272 = t270*t103 + t271*t107;
    const T t273 = t271*t113 + t270*t115;
    const T t274 = t270*t118 + t271*t119;
    const T t275 = ((t267*t155 + t268*t156) + (t269*t157 + t272*t158)) + ((t273*t159 + t274*t160) + (t262*t161 + (t263*t147 + t264*t152)));
    const T t276 = t196*t275;
    const T t277 = t240*t276;
    const T t278 = t60;
    const T t279 = t65;
    const T t280 = t69;
    const T t281 = t280*t110 + (t278*t103 + t279*t107);
    const T t282 = t278*t115 + (t279*t113 + t280*t114);
    const T t283 = t279*t119 + (t280*t117 + t278*t118);
    const T t284 = t101;
    const T t285 = t102;
    const T t286 = t100;
    const T t287 = t286*t110 + (t284*t103 + t285*t107);
    const T t288 = t284*t115 + (t285*t113 + t286*t114);
    const T t289 = t285*t119 + (t286*t117 + t284*t118);
    const T t290 = (t288*t159 + t289*t160) + ((t281*t155 + t282*t156) + (t283*t157 + t287*t158));
    const T t291 = t196*t290;
    const T t292 = t240*t291;
    const T t293 = t61;
    const T t294 = t66;
    const T t295 = t70;
    const T t296 = t295*t110 + (t293*t103 + t294*t107);
    const T t297 = t293*t115 + (t294*t113 + t295*t114);
    const T t298 = t294*t119 + (t295*t117 + t293*t118);
    const T t299 = t56;
    const T t300 = t59;
    const T t301 = t57;
    const T t302 = t301*t110 + (t299*t103 + t300*t107);
    const T t303 = t299*t115 + (t300*t113 + t301*t114);
    const T t304 = t300*t119 + (t301*t117 + t299*t118);
    const T t305 = (t304*t160 + t296*t161) + ((t297*t147 + t298*t152) + (t302*t158 + t303*t159));
    const T t306 = t196*t305;
    const T t307 = t240*t306;
    const T t308 = t62;
    const T t309 = t67;
    const T t310 = t71;
    const T t311 = t310*t110 + (t308*t103 + t309*t107);
    const T t312 = t308*t115 + (t309*t113 + t310*t114);
    const T t313 = t309*t119 + (t310*t117 + t308*t118);
    const T t314 = t64;
    const T t315 = t68;
    const T t316 = t58;
    const T t317 = t316*t110 + (t314*t103 + t315*t107);
    const T t318 = t314*t115 + (t315*t113 + t316*t114);
    const T t319 = t315*t119 + (t316*t117 + t314*t118);
    const T t320 = (t319*t157 + t311*t161) + ((t312*t147 + t313*t152) + (t317*t155 + t318*t156));
    const T t321 = t196*t320;
    const T t322 = t240*t321;
    const T t323 = dat[15]*t11 + (dat[9]*t7 + dat[12]*t9);
    const T t324 = t323*t13;
    const T t325 = t18*t324 + (t22 + t25);
    const T t326 = t323*t63;
    const T t327 = t23*t21 + t14*t324;
    const T t328 = t72*t327 + (t10*t326 + (dat[15]*t105 + t75*t106));
    const T t329 = dat[9]*t21 + t6*t324;
    const T t330 = t10*t329 + (t14*t326 + (t23*t105 + dat[15]*t109));
    const T t331 = t111*t330 + (t104*t325 + t108*t328);
    const T t332 = t74*t324 + (t77 + t22);
    const T t333 = t16*t327 + (t19*t106 + (dat[9]*t105 + t6*t326));
    const T t334 = t8*t329 + (dat[12]*t109 + (t19*t105 + t16*t326));
    const T t335 = t111*t333 + (t108*t332 + t104*t334);
    const T t336 = t93*t324 + (t77 + t25);
    const T t337 = (t95*t324 + t19*t96) + (t8*t326 + (dat[12]*t105 + t75*t94));
    const T t338 = (dat[15]*t98 + t99*t324) + (t72*t326 + (t75*t105 + dat[12]*t97));
    const T t339 = t108*t338 + (t111*t336 + t104*t337);
    const T t340 = t123*t330 + (t121*t325 + t122*t328);
    const T t341 = t123*t333 + (t122*t332 + t121*t334);
    const T t342 = t122*t338 + (t123*t336 + t121*t337);
    const T t343 = t129*t330 + (t127*t325 + t128*t328);
    const T t344 = t129*t333 + (t128*t332 + t127*t334);
    const T t345 = t128*t338 + (t129*t336 + t127*t337);
    const T t346 = ((t340*t155 + t341*t156) + (t342*t157 + t343*t158)) + ((t344*t159 + t345*t160) + (t331*t161 + (t335*t147 + t339*t152)));
    const T t347 = t196*t346;
    const T t348 = t240*t347;
    const T t349 = dat[16]*t11 + (dat[10]*t7 + dat[13]*t9);
    const T t350 = t349*t13;
    const T t351 = t18*t350 + (t28 + t31);
    const T t352 = t349*t63;
    const T t353 = t29*t21 + t14*t350;
    const T t354 = t72*t353 + (t10*t352 + (dat[16]*t105 + t78*t106));
    const T t355 = dat[10]*t21 + t6*t350;
    const T t356 = t10*t355 + (t14*t352 + (t29*t105 + dat[16]*t109));
    const T t357 = t111*t356 + (t104*t351 + t108*t354);
    const T t358 = t74*t350 + (t80 + t28);
    const T t359 = t16*t353 + (t26*t106 + (dat[10]*t105 + t6*t352));
    const T t360 = t8*t355 + (dat[13]*t109 + (t26*t105 + t16*t352));
    const T t361 = t111*t359 + (t108*t358 + t104*t360);
    const T t362 = t93*t350 + (t80 + t31);
    const T t363 = (t95*t350 + t26*t96) + (t8*t352 + (dat[13]*t105 + t78*t94));
    const T t364 = (dat[16]*t98 + t99*t350) + (t72*t352 + (t78*t105 + dat[13]*t97));
    const T t365 = t108*t364 + (t111*t362 + t104*t363);
    const T t366 = t123*t356 + (t121*t351 + t122*t354);
    const T t367 = t123*t359 + (t122*t358 + t121*t360);
    const T t368 = t122*t364 + (t123*t362 + t121*t363);
    const T t369 = t129*t356 + (t127*t351 + t128*t354);
    const T t370 = t129*t359 + (t128*t358 + t127*t360);
    const T t371 = t128*t364 + (t129*t362 + t127*t363);
    const T t372 = ((t366*t155 + t367*t156) + (t368*t157 + t369*t158)) + ((t370*t159 + t371*t160) + (t357*t161 + (t361*t147 + t365*t152)));
    const T t373 = t196*t372;
    const T t374 = t240*t373;
    const T t375 = dat[17]*t11 + (dat[11]*t7 + dat[14]*t9);
    const T t376 = t375*t13;
    const T t377 = t18*t376 + (t37 + t34);
    const T t378 = t375*t63;
    const T t379 = t35*t21 + t14*t376;
    const T t380 = t72*t379 + (t10*t378 + (dat[17]*t105 + t81*t106));
    const T t381 = dat[11]*t21 + t6*t376;
    const T t382 = t10*t381 + (t14*t378 + (t35*t105 + dat[17]*t109));
    const T t383 = t111*t382 + (t104*t377 + t108*t380);
    const T t384 = t74*t376 + (t83 + t34);
    const T t385 = t16*t379 + (t32*t106 + (dat[11]*t105 + t6*t378));
    const T t386 = t8*t381 + (dat[14]*t109 + (t32*t105 + t16*t378));
    const T t387 = t111*t385 + (t108*t384 + t104*t386);
    const T t388 = t93*t376 + (t37 + t83);
    const T t389 = (t95*t376 + t32*t96) + (t8*t378 + (dat[14]*t105 + t81*t94));
    const T t390 = (dat[17]*t98 + t99*t376) + (t72*t378 + (t81*t105 + dat[14]*t97));
    const T t391 = t108*t390 + (t111*t388 + t104*t389);
    const T t392 = t123*t382 + (t121*t377 + t122*t380);
    const T t393 = t123*t385 + (t122*t384 + t121*t386);
    const T t394 = t122*t390 + (t123*t388 + t121*t389);
    const T t395 = t129*t382 + (t127*t377 + t128*t380);
    const T t396 = t129*t385 + (t128*t384 + t127*t386);
    const T t397 = t128*t390 + (t129*t388 + t127*t389);
    const T t398 = ((t392*t155 + t393*t156) + (t394*t157 + t395*t158)) + ((t396*t159 + t397*t160) + (t383*t161 + (t387*t147 + t391*t152)));
    const T t399 = t196*t398;
    const T t400 = t240*t399;
    const T t401 = dat[42]*t11 + (dat[36]*t7 + dat[39]*t9);
    const T t402 = t401*t13;
    const T t403 = t18*t402 + (t40 + t43);
    const T t404 = t401*t63;
    const T t405 = t41*t21 + t14*t402;
    const T t406 = t72*t405 + (t10*t404 + (dat[42]*t105 + t84*t106));
    const T t407 = dat[36]*t21 + t6*t402;
    const T t408 = t10*t407 + (t14*t404 + (t41*t105 + dat[42]*t109));
    const T t409 = t111*t408 + (t104*t403 + t108*t406);
    const T t410 = t74*t402 + (t40 + t86);
    const T t411 = t16*t405 + (t38*t106 + (dat[36]*t105 + t6*t404));
    const T t412 = t8*t407 + (dat[39]*t109 + (t38*t105 + t16*t404));
    const T t413 = t111*t411 + (t108*t410 + t104*t412);
    const T t414 = t93*t402 + (t43 + t86);
    const T t415 = (t95*t402 + t38*t96) + (t8*t404 + (dat[39]*t105 + t84*t94));
    const T t416 = (dat[42]*t98 + t99*t402) + (t72*t404 + (t84*t105 + dat[39]*t97));
    const T t417 = t108*t416 + (t111*t414 + t104*t415);
    const T t418 = t123*t408 + (t121*t403 + t122*t406);
    const T t419 = t123*t411 + (t122*t410 + t121*t412);
    const T t420 = t122*t416 + (t123*t414 + t121*t415);
    const T t421 = t129*t408 + (t127*t403 + t128*t406);
    const T t422 = t129*t411 + (t128*t410 + t127*t412);
    const T t423 = t128*t416 + (t129*t414 + t127*t415);
    const T t424 = ((t418*t155 + t419*t156) + (t420*t157 + t421*t158)) + ((t422*t159 + t423*t160) + (t409*t161 + (t413*t147 + t417*t152)));
    const T t425 = t196*t424;
    const T t426 = t240*t425;
    const T t427 = dat[43]*t11 + (dat[37]*t7 + dat[40]*t9);
    const T t428 = t427*t13;
    const T t429 = t18*t428 + (t46 + t49);
    const T t430 = t427*t63;
    const T t431 = t44*t21 + t14*t428;
    const T t432 = t72*t431 + (t10*t430 + (dat[43]*t105 + t87*t106));
    const T t433 = dat[37]*t21 + t6*t428;
    const T t434 = t10*t433 + (t14*t430 + (t44*t105 + dat[43]*t109));
    const T t435 = t111*t434 + (t104*t429 + t108*t432);
    const T t436 = t74*t428 + (t49 + t89);
    const T t437 = t16*t431 + (t47*t106 + (dat[37]*t105 + t6*t430));
    const T t438 = t8*t433 + (dat[40]*t109 + (t47*t105 + t16*t430));
    const T t439 = t111*t437 + (t108*t436 + t104*t438);
    const T t440 = t93*t428 + (t46 + t89);
    const T t441 = (t95*t428 + t47*t96) + (t8*t430 + (dat[40]*t105 + t87*t94));
    const T t442 = (dat[43]*t98 + t99*t428) + (t72*t430 + (t87*t105 + dat[40]*t97));
    const T t443 = t108*t442 + (t111*t440 + t104*t441);
    const T t444 = t123*t434 + (t121*t429 + t122*t432);
    const T t445 = t123*t437 + (t122*t436 + t121*t438);
    const T t446 = t122*t442 + (t123*t440 + t121*t441);
    const T t447 = t129*t434 + (t127*t429 + t128*t432);
    const T t448 = t129*t437 + (t128*t436 + t127*t438);
    const T t449 = t128*t442 + (t129*t440 + t127*t441);
    const T t450 = ((t444*t155 + t445*t156) + (t446*t157 + t447*t158)) + ((t448*t159 + t449*t160) + (t435*t161 + (t439*t147 + t443*t152)));
    const T t451 = t196*t450;
    const T t452 = t240*t451;
    const T t453 = dat[44]*t11 + (dat[38]*t7 + dat[41]*t9);
    const T t454 = t453*t13;
    const T t455 = t18*t454 + (t52 + t55);
    const T t456 = t453*t63;
    const T t457 = t50*t21 + t14*t454;
    const T t458 = t72*t457 + (t10*t456 + (dat[44]*t105 + t90*t106));
    const T t459 = dat[38]*t21 + t6*t454;
    const T t460 = t10*t459 + (t14*t456 + (t50*t105 + dat[44]*t109));
    const T t461 = t111*t460 + (t104*t455 + t108*t458);
    const T t462 = t74*t454 + (t55 + t92);
    const T t463 = t16*t457 + (t53*t106 + (dat[38]*t105 + t6*t456));
    const T t464 = t8*t459 + (dat[41]*t109 + (t53*t105 + t16*t456));
    const T t465 = t111*t463 + (t108*t462 + t104*t464);
    const T t466 = t93*t454 + (t52 + t92);
    const T t467 = (t95*t454 + t53*t96) + (t8*t456 + (dat[41]*t105 + t90*t94));
    const T t468 = (dat[44]*t98 + t99*t454) + (t72*t456 + (t90*t105 + dat[41]*t97));
    const T t469 = t108*t468 + (t111*t466 + t104*t467);
    const T t470 = t123*t460 + (t121*t455 + t122*t458);
    const T t471 = t123*t463 + (t122*t462 + t121*t464);
    const T t472 = t122*t468 + (t123*t466 + t121*t467);
    const T t473 = t129*t460 + (t127*t455 + t128*t458);
    const T t474 = t129*t463 + (t128*t462 + t127*t464);
    const T t475 = t128*t468 + (t129*t466 + t127*t467);
    const T t476 = ((t470*t155 + t471*t156) + (t472*t157 + t473*t158)) + ((t474*t159 + t475*t160) + (t461*t161 + (t465*t147 + t469*t152)));
    const T t477 = t196*t476;
    const T t478 = t240*t477;
    const T t479 = t133*t240;
    const T t480 = t138*t240;
    const T t481 = -(t197 + t200);
    const T t482 = (dat[56]*t5 + (dat[6] + dat[27]*t0)) + ((dat[28]*t1 + dat[29]*t2) + (dat[54]*t3 + dat[55]*t4));
    const T t483 = (dat[59]*t5 + (dat[7] + dat[30]*t0)) + ((dat[31]*t1 + dat[32]*t2) + (dat[57]*t3 + dat[58]*t4));
    const T t484 = (dat[62]*t5 + (dat[8] + dat[33]*t0)) + ((dat[34]*t1 + dat[35]*t2) + (dat[60]*t3 + dat[61]*t4));
    const T t485 = ((dat[69]*dat[70] + (in[12] - in[27])) + in[0]*t482) + (in[1]*t483 + in[2]*t484);
    const T t486 = ((dat[69]*dat[71] + (in[13] - in[28])) + in[3]*t482) + (in[4]*t483 + in[5]*t484);
    const T t487 = ((dat[69]*dat[72] + (in[14] - in[29])) + in[6]*t482) + (in[7]*t483 + in[8]*t484);
    const T t488 = in[21]*t487 + (in[15]*t485 + in[18]*t486);
    const T t489 = in[23]*t487 + (in[17]*t485 + in[20]*t486);
    const T t490 = in[22]*t487 + (in[16]*t485 + in[19]*t486);
    const T t491 = ((t231*t172 + t235*t174) + (t236*t175 + t225*t177)) + ((t227*t168 + t232*t173) + (t237*t176 + (t226*t165 + t230*t171)));
    const T t492 = ((t250*t172 + t254*t174) + (t255*t175 + t244*t177)) + ((t246*t168 + t251*t173) + (t256*t176 + (t245*t165 + t249*t171)));
    const T t493 = ((t268*t172 + t272*t174) + (t273*t175 + t262*t177)) + ((t264*t168 + t269*t173) + (t274*t176 + (t263*t165 + t267*t171)));
    const T t494 = (t283*t173 + t289*t176) + ((t281*t171 + t282*t172) + (t287*t174 + t288*t175));
    const T t495 = (t298*t168 + t304*t176) + ((t297*t165 + t302*t174) + (t303*t175 + t296*t177));
    const T t496 = (t313*t168 + t319*t173) + ((t312*t165 + t317*t171) + (t318*t172 + t311*t177));
    const T t497 = ((t341*t172 + t343*t174) + (t344*t175 + t331*t177)) + ((t339*t168 + t342*t173) + (t345*t176 + (t335*t165 + t340*t171)));
    const T t498 = ((t367*t172 + t369*t174) + (t370*t175 + t357*t177)) + ((t365*t168 + t368*t173) + (t371*t176 + (t361*t165 + t366*t171)));
    const T t499 = ((t393*t172 + t395*t174) + (t396*t175 + t383*t177)) + ((t391*t168 + t394*t173) + (t397*t176 + (t387*t165 + t392*t171)));
    const T t500 = ((t419*t172 + t421*t174) + (t422*t175 + t409*t177)) + ((t417*t168 + t420*t173) + (t423*t176 + (t413*t165 + t418*t171)));
    const T t501 = ((t445*t172 + t447*t174) + (t448*t175 + t435*t177)) + ((t443*t168 + t446*t173) + (t449*t176 + (t439*t165 + t444*t171)));
    const T t502 = ((t471*t172 + t473*t174) + (t474*t175 + t461*t177)) + ((t469*t168 + t472*t173) + (t475*t176 + (t465*t165 + t470*t171)));
    const T t503 = ((t235*t190 + t236*t191) + (t225*t193 + t226*t180)) + ((t232*t189 + t237*t192) + (t227*t184 + (t230*t187 + t231*t188)));
    const T t504 = ((t254*t190 + t255*t191) + (t244*t193 + t245*t180)) + ((t251*t189 + t256*t192) + (t246*t184 + (t249*t187 + t250*t188)));
    const T t505 = ((t272*t190 + t273*t191) + (t262*t193 + t263*t180)) + ((t269*t189 + t274*t192) + (t264*t184 + (t267*t187 + t268*t188)));
    const T t506 = (t283*t189 + t289*t192) + ((t281*t187 + t282*t188) + (t287*t190 + t288*t191));
    const T t507 = (t304*t192 + t298*t184) + ((t302*t190 + t303*t191) + (t296*t193 + t297*t180));
    const T t508 = (t319*t189 + t313*t184) + ((t317*t187 + t318*t188) + (t311*t193 + t312*t180));
    const T t509 = ((t343*t190 + t344*t191) + (t331*t193 + t335*t180)) + ((t342*t189 + t345*t192) + (t339*t184 + (t340*t187 + t341*t188)));
    const T t510 = ((t369*t190 + t370*t191) + (t357*t193 + t361*t180)) + ((t368*t189 + t371*t192) + (t365*t184 + (t366*t187 + t367*t188)));
    const T t511 = ((t395*t190 + t396*t191) + (t383*t193 + t387*t180)) + ((t394*t189 + t397*t192) + (t391*t184 + (t392*t187 + t393*t188)));
    const T t512 = ((t421*t190 + t422*t191) + (t409*t193 + t413*t180)) + ((t420*t189 + t423*t192) + (t417*t184 + (t418*t187 + t419*t188)));
    const T t513 = ((t447*t190 + t448*t191) + (t435*t193 + t439*t180)) + ((t446*t189 + t449*t192) + (t443*t184 + (t444*t187 + t445*t188)));
    const T t514 = ((t473*t190 + t474*t191) + (t461*t193 + t465*t180)) + ((t472*t189 + t475*t192) + (t469*t184 + (t470*t187 + t471*t188)));
    const T t515 = t194*t491;
    const T t516 = t194*t492;
    const T t517 = t194*t493;
    const T t518 = t194*t494;
    const T t519 = t194*t495;
    const T t520 = t194*t496;
    const T t521 = t194*t497;
    const T t522 = t194*t498;
    const T t523 = t194*t499;
    const T t524 = t194*t500;
    const T t525 = t194*t501;
    const T t526 = t194*t502;
    const T t527 = t195*t503;
    const T t528 = t195*t504;
    const T t529 = t195*t505;
    const T t530 = t195*t506;
    const T t531 = t195*t507;
    const T t532 = t195*t508;
    const T t533 = t195*t509;
    const T t534 = t195*t510;
    const T t535 = t195*t511;
    const T t536 = t195*t512;
    const T t537 = t195*t513;
    const T t538 = t195*t514;
    const T t539 = t515 + t527;
    const T t540 = t516 + t528;
    const T t541 = t517 + t529;
    const T t542 = t518 + t530;
    const T t543 = t519 + t531;
    const T t544 = t520 + t532;
    const T t545 = t521 + t533;
    const T t546 = t522 + t534;
    const T t547 = t523 + t535;
    const T t548 = t524 + t536;
    const T t549 = t525 + t537;
    const T t550 = t526 + t538;
    const T t551 = t202*t239 + t202*t539;
    const T t552 = t202*t258 + t202*t540;
    const T t553 = t202*t276 + t202*t541;
    const T t554 = t202*t291 + t202*t542;
    const T t555 = t202*t306 + t202*t543;
    const T t556 = t202*t321 + t202*t544;
    const T t557 = t202*t347 + t202*t545;
    const T t558 = t202*t373 + t202*t546;
    const T t559 = t202*t399 + t202*t547;
    const T t560 = t202*t425 + t202*t548;
    const T t561 = t202*t451 + t202*t549;
    const T t562 = t202*t477 + t202*t550;
    const T t563 = T(1) - t199*t240;
    const T t564 = -(t240*t539 + t199*t551);
    const T t565 = -(t240*t540 + t199*t552);
    const T t566 = -(t240*t541 + t199*t553);
    const T t567 = -(t240*t542 + t199*t554);
    const T t568 = -(t240*t543 + t199*t555);
    const T t569 = -(t240*t544 + t199*t556);
    const T t570 = -(t240*t545 + t199*t557);
    const T t571 = -(t240*t546 + t199*t558);
    const T t572 = -(t240*t547 + t199*t559);
    const T t573 = -(t240*t548 + t199*t560);
    const T t574 = -(t240*t549 + t199*t561);
    const T t575 = -(t240*t550 + t199*t562);
    const T t576 = in[2]*t213 - in[1]*t214;
    const T t577 = in[0]*t214 - in[2]*t212;
    const T t578 = in[1]*t212 - in[0]*t213;
    const T t579 = t203;
    const T t580 = t204;
    const T t581 = t205;
    const T t582 = dat[24]*in[2] + (dat[18]*in[0] + dat[21]*in[1]);
    const T t583 = dat[25]*in[2] + (dat[19]*in[0] + dat[22]*in[1]);
    const T t584 = dat[26]*in[2] + (dat[20]*in[0] + dat[23]*in[1]);
    const T t585 = dat[51]*in[2] + (dat[45]*in[0] + dat[48]*in[1]);
    const T t586 = dat[52]*in[2] + (dat[46]*in[0] + dat[49]*in[1]);
    const T t587 = dat[53]*in[2] + (dat[47]*in[0] + dat[50]*in[1]);
    const T t588 = in[5]*t213 - in[4]*t214;
    const T t589 = in[3]*t214 - in[5]*t212;
    const T t590 = in[4]*t212 - in[3]*t213;
    const T t591 = t206;
    const T t592 = t207;
    const T t593 = t208;
    const T t594 = dat[24]*in[5] + (dat[18]*in[3] + dat[21]*in[4]);
    const T t595 = dat[25]*in[5] + (dat[19]*in[3] + dat[22]*in[4]);
    const T t596 = dat[26]*in[5] + (dat[20]*in[3] + dat[23]*in[4]);
    const T t597 = dat[51]*in[5] + (dat[45]*in[3] + dat[48]*in[4]);
    const T t598 = dat[52]*in[5] + (dat[46]*in[3] + dat[49]*in[4]);
    const T t599 = dat[53]*in[5] + (dat[47]*in[3] + dat[50]*in[4]);
    const T t600 = in[8]*t213 - in[7]*t214;
    const T t601 = in[6]*t214 - in[8]*t212;
    const T t602 = in[7]*t212 - in[6]*t213;
    const T t603 = t209;
    const T t604 = t210;
    const T t605 = t211;
    const T t606 = dat[24]*in[8] + (dat[18]*in[6] + dat[21]*in[7]);
    const T t607 = dat[25]*in[8] + (dat[19]*in[6] + dat[22]*in[7]);
    const T t608 = dat[26]*in[8] + (dat[20]*in[6] + dat[23]*in[7]);
    const T t609 = dat[51]*in[8] + (dat[45]*in[6] + dat[48]*in[7]);
    const T t610 = dat[52]*in[8] + (dat[46]*in[6] + dat[49]*in[7]);
    const T t611 = dat[53]*in[8] + (dat[47]*in[6] + dat[50]*in[7]);
    const T t612 = t219;
    const T t613 = in[21]*t600 + (in[15]*t576 + in[18]*t588);
    const T t614 = in[21]*t601 + (in[15]*t577 + in[18]*t589);
    const T t615 = in[21]*t602 + (in[15]*t578 + in[18]*t590);
    const T t616 = t56;
    const T t617 = t59;
    const T t618 = t57;
    const T t619 = dat[69]*in[15];
    const T t620 = dat[69]*in[18];
    const T t621 = dat[69]*in[21];
    const T t622 = -t220;
    const T t623 = t221;
    const T t624 = t603*in[21] + (t579*in[15] + t591*in[18]);
    const T t625 = t604*in[21] + (t580*in[15] + t592*in[18]);
    const T t626 = t605*in[21] + (t581*in[15] + t593*in[18]);
    const T t627 = in[21]*t606 + (in[15]*t582 + in[18]*t594);
    const T t628 = in[21]*t607 + (in[15]*t583 + in[18]*t595);
    const T t629 = in[21]*t608 + (in[15]*t584 + in[18]*t596);
    const T t630 = in[21]*t609 + (in[15]*t585 + in[18]*t597);
    const T t631 = in[21]*t610 + (in[15]*t586 + in[18]*t598);
    const T t632 = in[21]*t611 + (in[15]*t587 + in[18]*t599);
    const T t633 = t148;
    const T t634 = (T(0.5))*t503;
    const T t635 = (T(0.5))*t504;
    const T t636 = (T(0.5))*t505;
    const T t637 = (T(0.5))*t506;
    const T t638 = (T(0.5))*t507;
    const T t639 = (T(0.5))*t508;
    const T t640 = (T(0.5))*t509;
    const T t641 = (T(0.5))*t510;
    const T t642 = (T(0.5))*t511;
    const T t643 = (T(0.5))*t512;
    const T t644 = (T(0.5))*t513;
    const T t645 = (T(0.5))*t514;
    const T t646 = t135*t240;
    const T t647 = t240*t238 + t135*t551;
    const T t648 = t240*t257 + t135*t552;
    const T t649 = t240*t275 + t135*t553;
    const T t650 = t240*t290 + t135*t554;
    const T t651 = t240*t305 + t135*t555;
    const T t652 = t240*t320 + t135*t556;
    const T t653 = t240*t346 + t135*t557;
    const T t654 = t240*t372 + t135*t558;
    const T t655 = t240*t398 + t135*t559;
    const T t656 = t240*t424 + t135*t560;
    const T t657 = t240*t450 + t135*t561;
    const T t658 = t240*t476 + t135*t562;
    const T t659 = t133*t646;
    const T t660 = t646*t491 + t133*t647;
    const T t661 = t646*t492 + t133*t648;
    const T t662 = t646*t493 + t133*t649;
    const T t663 = t646*t494 + t133*t650;
    const T t664 = t646*t495 + t133*t651;
    const T t665 = t646*t496 + t133*t652;
    const T t666 = t646*t497 + t133*t653;
    const T t667 = t646*t498 + t133*t654;
    const T t668 = t646*t499 + t133*t655;
    const T t669 = t646*t500 + t133*t656;
    const T t670 = t646*t501 + t133*t657;
    const T t671 = t646*t502 + t133*t658;
    const T t672 = t633 + t659;
    const T t673 = t634 + t660;
    const T t674 = t635 + t661;
    const T t675 = t636 + t662;
    const T t676 = t637 + t663;
    const T t677 = t638 + t664;
    const T t678 = t639 + t665;
    const T t679 = t640 + t666;
    const T t680 = t641 + t667;
    const T t681 = t642 + t668;
    const T t682 = t643 + t669;
    const T t683 = t644 + t670;
    const T t684 = t645 + t671;
    const T t685 = t221;
    const T t686 = in[22]*t600 + (in[16]*t576 + in[19]*t588);
    const T t687 = in[22]*t601 + (in[16]*t577 + in[19]*t589);
    const T t688 = in[22]*t602 + (in[16]*t578 + in[19]*t590);
    const T t689 = t62;
    const T t690 = t67;
    const T t691 = t71;
    const T t692 = dat[69]*in[16];
    const T t693 = dat[69]*in[19];
    const T t694 = dat[69]*in[22];
    const T t695 = t220;
    const T t696 = -t219;
    const T t697 = t603*in[22] + (t579*in[16] + t591*in[19]);
    const T t698 = t604*in[22] + (t580*in[16] + t592*in[19]);
    const T t699 = t605*in[22] + (t581*in[16] + t593*in[19]);
    const T t700 = in[22]*t606 + (in[16]*t582 + in[19]*t594);
    const T t701 = in[22]*t607 + (in[16]*t583 + in[19]*t595);
    const T t702 = in[22]*t608 + (in[16]*t584 + in[19]*t596);
    const T t703 = in[22]*t609 + (in[16]*t585 + in[19]*t597);
    const T t704 = in[22]*t610 + (in[16]*t586 + in[19]*t598);
    const T t705 = in[22]*t611 + (in[16]*t587 + in[19]*t599);
    const T t706 = t134;
    const T t707 = (T(0.5))*t491;
    const T t708 = (T(0.5))*t492;
    const T t709 = (T(0.5))*t493;
    const T t710 = (T(0.5))*t494;
    const T t711 = (T(0.5))*t495;
    const T t712 = (T(0.5))*t496;
    const T t713 = (T(0.5))*t497;
    const T t714 = (T(0.5))*t498;
    const T t715 = (T(0.5))*t499;
    const T t716 = (T(0.5))*t500;
    const T t717 = (T(0.5))*t501;
    const T t718 = (T(0.5))*t502;
    const T t719 = t138*t646;
    const T t720 = t646*t503 + t138*t647;
    const T t721 = t646*t504 + t138*t648;
    const T t722 = t646*t505 + t138*t649;
    const T t723 = t646*t506 + t138*t650;
    const T t724 = t646*t507 + t138*t651;
    const T t725 = t646*t508 + t138*t652;
    const T t726 = t646*t509 + t138*t653;
    const T t727 = t646*t510 + t138*t654;
    const T t728 = t646*t511 + t138*t655;
    const T t729 = t646*t512 + t138*t656;
    const T t730 = t646*t513 + t138*t657;
    const T t731 = t646*t514 + t138*t658;
    const T t732 = t719 - t706;
    const T t733 = t720 - t707;
    const T t734 = t721 - t708;
    const T t735 = t722 - t709;
    const T t736 = t723 - t710;
    const T t737 = t724 - t711;
    const T t738 = t725 - t712;
    const T t739 = t726 - t713;
    const T t740 = t727 - t714;
    const T t741 = t728 - t715;
    const T t742 = t729 - t716;
    const T t743 = t730 - t717;
    const T t744 = t731 - t718;
    const T t745 = t220;
    const T t746 = in[23]*t600 + (in[17]*t576 + in[20]*t588);
    const T t747 = in[23]*t601 + (in[17]*t577 + in[20]*t589);
    const T t748 = in[23]*t602 + (in[17]*t578 + in[20]*t590);
    const T t749 = t60;
    const T t750 = t65;
    const T t751 = t69;
    const T t752 = dat[69]*in[17];
    const T t753 = dat[69]*in[20];
    const T t754 = dat[69]*in[23];
    const T t755 = -t221;
    const T t756 = t219;
    const T t757 = t603*in[23] + (t579*in[17] + t591*in[20]);
    const T t758 = t604*in[23] + (t580*in[17] + t592*in[20]);
    const T t759 = t605*in[23] + (t581*in[17] + t593*in[20]);
    const T t760 = in[23]*t606 + (in[17]*t582 + in[20]*t594);
    const T t761 = in[23]*t607 + (in[17]*t583 + in[20]*t595);
    const T t762 = in[23]*t608 + (in[17]*t584 + in[20]*t596);
    const T t763 = in[23]*t609 + (in[17]*t585 + in[20]*t597);
    const T t764 = in[23]*t610 + (in[17]*t586 + in[20]*t598);
    const T t765 = in[23]*t611 + (in[17]*t587 + in[20]*t599);
    const T t766 = T(1) + t222*t240;
    const T t767 = t222*t551 - (t241 + t240*t527);
    const T t768 = t222*t552 - (t259 + t240*t528);
    const T t769 = t222*t553 - (t277 + t240*t529);
    const T t770 = t222*t554 - (t240*t530 + t292);
    const T t771 = t222*t555 - (t240*t531 + t307);
    const T t772 = t222*t556 - (t240*t532 + t322);
    const T t773 = t222*t557 - (t348 + t240*t533);
    const T t774 = t222*t558 - (t374 + t240*t534);
    const T t775 = t222*t559 - (t400 + t240*t535);
    const T t776 = t222*t560 - (t426 + t240*t536);
    const T t777 = t222*t561 - (t452 + t240*t537);
    const T t778 = t222*t562 - (t478 + t240*t538);
    const T t779 = t162;
    const T t780 = (T(0.5))*t238;
    const T t781 = (T(0.5))*t257;
    const T t782 = (T(0.5))*t275;
    const T t783 = (T(0.5))*t290;
    const T t784 = (T(0.5))*t305;
    const T t785 = (T(0.5))*t320;
    const T t786 = (T(0.5))*t346;
    const T t787 = (T(0.5))*t372;
    const T t788 = (T(0.5))*t398;
    const T t789 = (T(0.5))*t424;
    const T t790 = (T(0.5))*t450;
    const T t791 = (T(0.5))*t476;
    const T t792 = t181*t240;
    const T t793 = (t479*t503 + t480*t491) + t181*t551;
    const T t794 = (t479*t504 + t480*t492) + t181*t552;
    const T t795 = (t479*t505 + t480*t493) + t181*t553;
    const T t796 = (t479*t506 + t480*t494) + t181*t554;
    const T t797 = (t479*t507 + t480*t495) + t181*t555;
    const T t798 = (t479*t508 + t480*t496) + t181*t556;
    const T t799 = (t479*t509 + t480*t497) + t181*t557;
    const T t800 = (t479*t510 + t480*t498) + t181*t558;
    const T t801 = (t479*t511 + t480*t499) + t181*t559;
    const T t802 = (t479*t512 + t480*t500) + t181*t560;
    const T t803 = (t479*t513 + t480*t501) + t181*t561;
    const T t804 = (t479*t514 + t480*t502) + t181*t562;
    const T t805 = t779 + t792;
    const T t806 = t780 + t793;
    const T t807 = t781 + t794;
    const T t808 = t782 + t795;
    const T t809 = t783 + t796;
    const T t810 = t784 + t797;
    const T t811 = t785 + t798;
    const T t812 = t786 + t799;
    const T t813 = t787 + t800;
    const T t814 = t788 + t801;
    const T t815 = t789 + t802;
    const T t816 = t790 + t803;
    const T t817 = t791 + t804;
    const T t818 = t659 - t633;
    const T t819 = t660 - t634;
    const T t820 = t661 - t635;
    const T t821 = t662 - t636;
    const T t822 = t663 - t637;
    const T t823 = t664 - t638;
    const T t824 = t665 - t639;
    const T t825 = t666 - t640;
    const T t826 = t667 - t641;
    const T t827 = t668 - t642;
    const T t828 = t669 - t643;
    const T t829 = t670 - t644;
    const T t830 = t671 - t645;
    const T t831 = T(1) + t481*t240;
    const T t832 = t481*t551 - (t241 + t240*t515);
    const T t833 = t481*t552 - (t259 + t240*t516);
    const T t834 = t481*t553 - (t277 + t240*t517);
    const T t835 = t481*t554 - (t240*t518 + t292);
    const T t836 = t481*t555 - (t240*t519 + t307);
    const T t837 = t481*t556 - (t240*t520 + t322);
    const T t838 = t481*t557 - (t348 + t240*t521);
    const T t839 = t481*t558 - (t374 + t240*t522);
    const T t840 = t481*t559 - (t400 + t240*t523);
    const T t841 = t481*t560 - (t426 + t240*t524);
    const T t842 = t481*t561 - (t452 + t240*t525);
    const T t843 = t481*t562 - (t478 + t240*t526);
    const T t844 = t706 + t719;
    const T t845 = t707 + t720;
    const T t846 = t708 + t721;
    const T t847 = t709 + t722;
    const T t848 = t710 + t723;
    const T t849 = t711 + t724;
    const T t850 = t712 + t725;
    const T t851 = t713 + t726;
    const T t852 = t714 + t727;
    const T t853 = t715 + t728;
    const T t854 = t716 + t729;
    const T t855 = t717 + t730;
    const T t856 = t718 + t731;
    const T t857 = t792 - t779;
    const T t858 = t793 - t780;
    const T t859 = t794 - t781;
    const T t860 = t795 - t782;
    const T t861 = t796 - t783;
    const T t862 = t797 - t784;
    const T t863 = t798 - t785;
    const T t864 = t799 - t786;
    const T t865 = t800 - t787;
    const T t866 = t801 - t788;
    const T t867 = t802 - t789;
    const T t868 = t803 - t790;
    const T t869 = t804 - t791;
    const T t870 = in[2]*t483 - in[1]*t484;
    const T t871 = in[0]*t484 - in[2]*t482;
    const T t872 = in[1]*t482 - in[0]*t483;
    const T t873 = dat[33]*in[2] + (dat[27]*in[0] + dat[30]*in[1]);
    const T t874 = dat[34]*in[2] + (dat[28]*in[0] + dat[31]*in[1]);
    const T t875 = dat[35]*in[2] + (dat[29]*in[0] + dat[32]*in[1]);
    const T t876 = dat[60]*in[2] + (dat[54]*in[0] + dat[57]*in[1]);
    const T t877 = dat[61]*in[2] + (dat[55]*in[0] + dat[58]*in[1]);
    const T t878 = dat[62]*in[2] + (dat[56]*in[0] + dat[59]*in[1]);
    const T t879 = in[5]*t483 - in[4]*t484;
    const T t880 = in[3]*t484 - in[5]*t482;
    const T t881 = in[4]*t482 - in[3]*t483;
    const T t882 = dat[33]*in[5] + (dat[27]*in[3] + dat[30]*in[4]);
    const T t883 = dat[34]*in[5] + (dat[28]*in[3] + dat[31]*in[4]);
    const T t884 = dat[35]*in[5] + (dat[29]*in[3] + dat[32]*in[4]);
    const T t885 = dat[60]*in[5] + (dat[54]*in[3] + dat[57]*in[4]);
    const T t886 = dat[61]*in[5] + (dat[55]*in[3] + dat[58]*in[4]);
    const T t887 = dat[62]*in[5] + (dat[56]*in[3] + dat[59]*in[4]);
    const T t888 = in[8]*t483 - in[7]*t484;
    const T t889 = in[6]*t484 - in[8]*t482;
    const T t890 = in[7]*t482 - in[6]*t483;
    const T t891 = dat[33]*in[8] + (dat[27]*in[6] + dat[30]*in[7]);
    const T t892 = dat[34]*in[8] + (dat[28]*in[6] + dat[31]*in[7]);
    const T t893 = dat[35]*in[8] + (dat[29]*in[6] + dat[32]*in[7]);
    const T t894 = dat[60]*in[8] + (dat[54]*in[6] + dat[57]*in[7]);
    const T t895 = dat[61]*in[8] + (dat[55]*in[6] + dat[58]*in[7]);
    const T t896 = dat[62]*in[8] + (dat[56]*in[6] + dat[59]*in[7]);
    const T t897 = t488;
    const T t898 = in[21]*t888 + (in[15]*t870 + in[18]*t879);
    const T t899 = in[21]*t889 + (in[15]*t871 + in[18]*t880);
    const T t900 = in[21]*t890 + (in[15]*t872 + in[18]*t881);
    const T t901 = -t489;
    const T t902 = t490;
    const T t903 = t203;
    const T t904 = t206;
    const T t905 = t209;
    const T t906 = in[21]*t891 + (in[15]*t873 + in[18]*t882);
    const T t907 = in[21]*t892 + (in[15]*t874 + in[18]*t883);
    const T t908 = in[21]*t893 + (in[15]*t875 + in[18]*t884);
    const T t909 = in[21]*t894 + (in[15]*t876 + in[18]*t885);
    const T t910 = in[21]*t895 + (in[15]*t877 + in[18]*t886);
    const T t911 = in[21]*t896 + (in[15]*t878 + in[18]*t887);
    const T t912 = t490;
    const T t913 = in[22]*t888 + (in[16]*t870 + in[19]*t879);
    const T t914 = in[22]*t889 + (in[16]*t871 + in[19]*t880);
    const T t915 = in[22]*t890 + (in[16]*t872 + in[19]*t881);
    const T t916 = t489;
    const T t917 = -t488;
    const T t918 = t204;
    const T t919 = t207;
    const T t920 = t210;
    const T t921 = in[22]*t891 + (in[16]*t873 + in[19]*t882);
    const T t922 = in[22]*t892 + (in[16]*t874 + in[19]*t883);
    const T t923 = in[22]*t893 + (in[16]*t875 + in[19]*t884);
    const T t924 = in[22]*t894 + (in[16]*t876 + in[19]*t885);
    const T t925 = in[22]*t895 + (in[16]*t877 + in[19]*t886);
    const T t926 = in[22]*t896 + (in[16]*t878 + in[19]*t887);
    const T t927 = t489;
    const T t928 = in[23]*t888 + (in[17]*t870 + in[20]*t879);
    const T t929 = in[23]*t889 + (in[17]*t871 + in[20]*t880);
    const T t930 = in[23]*t890 + (in[17]*t872 + in[20]*t881);
    const T t931 = -t490;
    const T t932 = t488;
    const T t933 = t205;
    const T t934 = t208;
    const T t935 = t211;
    const T t936 = in[23]*t891 + (in[17]*t873 + in[20]*t882);
    const T t937 = in[23]*t892 + (in[17]*t874 + in[20]*t883);
    const T t938 = in[23]*t893 + (in[17]*t875 + in[20]*t884);
    const T t939 = in[23]*t894 + (in[17]*t876 + in[20]*t885);
    const T t940 = in[23]*t895 + (in[17]*t877 + in[20]*t886);
    const T t941 = in[23]*t896 + (in[17]*t878 + in[20]*t887);
    raw[0] = t238;
    raw[1] = t257;
    raw[2] = t275;
    raw[9] = t290;
    raw[10] = t305;
    raw[11] = t320;
    raw[18] = t346;
    raw[19] = t372;
    raw[20] = t398;
    raw[21] = t424;
    raw[22] = t450;
    raw[23] = t476;
    raw[30] = t135;
    raw[32] = t491;
    raw[33] = t492;
    raw[34] = t493;
    raw[41] = t494;
    raw[42] = t495;
    raw[43] = t496;
    raw[50] = t497;
    raw[51] = t498;
    raw[52] = t499;
    raw[53] = t500;
    raw[54] = t501;
    raw[55] = t502;
    raw[62] = t133;
    raw[64] = t503;
    raw[65] = t504;
    raw[66] = t505;
    raw[73] = t506;
    raw[74] = t507;
    raw[75] = t508;
    raw[82] = t509;
    raw[83] = t510;
    raw[84] = t511;
    raw[85] = t512;
    raw[86] = t513;
    raw[87] = t514;
    raw[94] = t138;
    raw[96] = t745*t733 + (((t746*t732 + (t613*t563 + t686*t672)) + t612*t564) + t685*t673);
    raw[97] = t745*t734 + (((t747*t732 + (t614*t563 + t687*t672)) + t612*t565) + t685*t674);
    raw[98] = t745*t735 + (((t748*t732 + (t615*t563 + t688*t672)) + t612*t566) + t685*t675);
    raw[99] = t749*t732 + (t616*t563 + t689*t672);
    raw[100] = t750*t732 + (t617*t563 + t690*t672);
    raw[101] = t751*t732 + (t618*t563 + t691*t672);
    raw[102] = t752*t732 + (t619*t563 + t692*t672);
    raw[103] = t753*t732 + (t620*t563 + t693*t672);
    raw[104] = t754*t732 + (t621*t563 + t694*t672);
    raw[105] = t745*t736 + (((t695*t672 + t755*t732) + t612*t567) + t685*t676);
    raw[106] = t745*t737 + (((t622*t563 + t756*t732) + t612*t568) + t685*t677);
    raw[107] = t745*t738 + (((t623*t563 + t696*t672) + t612*t569) + t685*t678);
    raw[108] = t757*t732 + (t624*t563 + t697*t672);
    raw[109] = t758*t732 + (t625*t563 + t698*t672);
    raw[110] = t759*t732 + (t626*t563 + t699*t672);
    raw[114] = t745*t739 + (((t760*t732 + (t627*t563 + t700*t672)) + t612*t570) + t685*t679);
    raw[115] = t745*t740 + (((t761*t732 + (t628*t563 + t701*t672)) + t612*t571) + t685*t680);
    raw[116] = t745*t741 + (((t762*t732 + (t629*t563 + t702*t672)) + t612*t572) + t685*t681);
    raw[117] = t745*t742 + (((t763*t732 + (t630*t563 + t703*t672)) + t612*t573) + t685*t682);
    raw[118] = t745*t743 + (((t764*t732 + (t631*t563 + t704*t672)) + t612*t574) + t685*t683);
    raw[119] = t745*t744 + (((t765*t732 + (t632*t563 + t705*t672)) + t612*t575) + t685*t684);
    raw[126] = t745*t732 + (t612*t563 + t685*t672);
    raw[128] = (t745*t806 + ((t613*t818 + (t686*t766 + t746*t805)) + t685*t767)) + t612*t819;
    raw[129] = (t745*t807 + ((t614*t818 + (t687*t766 + t747*t805)) + t685*t768)) + t612*t820;
    raw[130] = (t745*t808 + ((t615*t818 + (t688*t766 + t748*t805)) + t685*t769)) + t612*t821;
    raw[131] = t616*t818 + (t689*t766 + t749*t805);
    raw[132] = t617*t818 + (t690*t766 + t750*t805);
    raw[133] = t618*t818 + (t691*t766 + t751*t805);
    raw[134] = t619*t818 + (t692*t766 + t752*t805);
    raw[135] = t620*t818 + (t693*t766 + t753*t805);
    raw[136] = t621*t818 + (t694*t766 + t754*t805);
    raw[137] = (t745*t809 + ((t695*t766 + t755*t805) + t685*t770)) + t612*t822;
    raw[138] = (t745*t810 + ((t756*t805 + t622*t818) + t685*t771)) + t612*t823;
    raw[139] = (t745*t811 + ((t696*t766 + t623*t818) + t685*t772)) + t612*t824;
    raw[140] = t624*t818 + (t697*t766 + t757*t805);
    raw[141] = t625*t818 + (t698*t766 + t758*t805);
    raw[142] = t626*t818 + (t699*t766 + t759*t805);
    raw[146] = (t745*t812 + ((t627*t818 + (t700*t766 + t760*t805)) + t685*t773)) + t612*t825;
    raw[147] = (t745*t813 + ((t628*t818 + (t701*t766 + t761*t805)) + t685*t774)) + t612*t826;
    raw[148] = (t745*t814 + ((t629*t818 + (t702*t766 + t762*t805)) + t685*t775)) + t612*t827;
    raw[149] = (t745*t815 + ((t630*t818 + (t703*t766 + t763*t805)) + t685*t776)) + t612*t828;
    raw[150] = (t745*t816 + ((t631*t818 + (t704*t766 + t764*t805)) + t685*t777)) + t612*t829;
    raw[151] = (t745*t817 + ((t632*t818 + (t705*t766 + t765*t805)) + t685*t778)) + t612*t830;
    raw[158] = t612*t818 + (t685*t766 + t745*t805);
    raw[160] = (t685*t858 + ((t613*t844 + (t746*t831 + t686*t857)) + t745*t832)) + t612*t845;
    raw[161] = (t685*t859 + ((t614*t844 + (t747*t831 + t687*t857)) + t745*t833)) + t612*t846;
    raw[162] = (t685*t860 + ((t615*t844 + (t748*t831 + t688*t857)) + t745*t834)) + t612*t847;
    raw[163] = t616*t844 + (t749*t831 + t689*t857);
    raw[164] = t617*t844 + (t750*t831 + t690*t857);
    raw[165] = t618*t844 + (t751*t831 + t691*t857);
    raw[166] = t619*t844 + (t752*t831 + t692*t857);
    raw[167] = t620*t844 + (t753*t831 + t693*t857);
    raw[168] = t621*t844 + (t754*t831 + t694*t857);
    raw[169] = (t685*t861 + ((t755*t831 + t695*t857) + t745*t835)) + t612*t848;
    raw[170] = (t685*t862 + ((t756*t831 + t622*t844) + t745*t836)) + t612*t849;
    raw[171] = (t685*t863 + ((t696*t857 + t623*t844) + t745*t837)) + t612*t850;
    raw[172] = t624*t844 + (t757*t831 + t697*t857);
    raw[173] = t625*t844 + (t758*t831 + t698*t857);
    raw[174] = t626*t844 + (t759*t831 + t699*t857);
    raw[178] = (t685*t864 + ((t627*t844 + (t760*t831 + t700*t857)) + t745*t838)) + t612*t851;
    raw[179] = (t685*t865 + ((t628*t844 + (t761*t831 + t701*t857)) + t745*t839)) + t612*t852;
    raw[180] = (t685*t866 + ((t629*t844 + (t762*t831 + t702*t857)) + t745*t840)) + t612*t853;
    raw[181] = (t685*t867 + ((t630*t844 + (t763*t831 + t703*t857)) + t745*t841)) + t612*t854;
    raw[182] = (t685*t868 + ((t631*t844 + (t764*t831 + t704*t857)) + t745*t842)) + t612*t855;
    raw[183] = (t685*t869 + ((t632*t844 + (t765*t831 + t705*t857)) + t745*t843)) + t612*t856;
    raw[190] = t612*t844 + (t685*t857 + t745*t831);
    raw[192] = t927*t733 + (((t928*t732 + (t898*t563 + t913*t672)) + t897*t564) + t912*t673);
    raw[193] = t927*t734 + (((t929*t732 + (t899*t563 + t914*t672)) + t897*t565) + t912*t674);
    raw[194] = t927*t735 + (((t930*t732 + (t900*t563 + t915*t672)) + t897*t566) + t912*t675);
    raw[198] = in[17]*t732 + (in[15]*t563 + in[16]*t672);
    raw[199] = in[20]*t732 + (in[18]*t563 + in[19]*t672);
    raw[200] = in[23]*t732 + (in[21]*t563 + in[22]*t672);
    raw[201] = t927*t736 + (((t916*t672 + t931*t732) + t897*t567) + t912*t676);
    raw[202] = t927*t737 + (((t901*t563 + t932*t732) + t897*t568) + t912*t677);
    raw[203] = t927*t738 + (((t902*t563 + t917*t672) + t897*t569) + t912*t678);
    raw[207] = t933*t732 + (t903*t563 + t918*t672);
    raw[208] = t934*t732 + (t904*t563 + t919*t672);
    raw[209] = t935*t732 + (t905*t563 + t920*t672);
    raw[210] = t927*t739 + (((t936*t732 + (t906*t563 + t921*t672)) + t897*t570) + t912*t679);
    raw[211] = t927*t740 + (((t937*t732 + (t907*t563 + t922*t672)) + t897*t571) + t912*t680);
    raw[212] = t927*t741 + (((t938*t732 + (t908*t563 + t923*t672)) + t897*t572) + t912*t681);
    raw[213] = t927*t742 + (((t939*t732 + (t909*t563 + t924*t672)) + t897*t573) + t912*t682);
    raw[214] = t927*t743 + (((t940*t732 + (t910*t563 + t925*t672)) + t897*t574) + t912*t683);
    raw[215] = t927*t744 + (((t941*t732 + (t911*t563 + t926*t672)) + t897*t575) + t912*t684);
    raw[222] = t927*t732 + (t897*t563 + t912*t672);
    raw[224] = (t927*t806 + ((t898*t818 + (t913*t766 + t928*t805)) + t912*t767)) + t897*t819;
    raw[225] = (t927*t807 + ((t899*t818 + (t914*t766 + t929*t805)) + t912*t768)) + t897*t820;
    raw[226] = (t927*t808 + ((t900*t818 + (t915*t766 + t930*t805)) + t912*t769)) + t897*t821;
    raw[230] = in[15]*t818 + (in[16]*t766 + in[17]*t805);
    raw[231] = in[18]*t818 + (in[19]*t766 + in[20]*t805);
    raw[232] = in[21]*t818 + (in[22]*t766 + in[23]*t805);
    raw[233] = (t927*t809 + ((t916*t766 + t931*t805) + t912*t770)) + t897*t822;
    raw[234] = (t927*t810 + ((t932*t805 + t901*t818) + t912*t771)) + t897*t823;
    raw[235] = (t927*t811 + ((t917*t766 + t902*t818) + t912*t772)) + t897*t824;
    raw[239] = t903*t818 + (t918*t766 + t933*t805);
    raw[240] = t904*t818 + (t919*t766 + t934*t805);
    raw[241] = t905*t818 + (t920*t766 + t935*t805);
    raw[242] = (t927*t812 + ((t906*t818 + (t921*t766 + t936*t805)) + t912*t773)) + t897*t825;
    raw[243] = (t927*t813 + ((t907*t818 + (t922*t766 + t937*t805)) + t912*t774)) + t897*t826;
    raw[244] = (t927*t814 + ((t908*t818 + (t923*t766 + t938*t805)) + t912*t775)) + t897*t827;
    raw[245] = (t927*t815 + ((t909*t818 + (t924*t766 + t939*t805)) + t912*t776)) + t897*t828;
    raw[246] = (t927*t816 + ((t910*t818 + (t925*t766 + t940*t805)) + t912*t777)) + t897*t829;
    raw[247] = (t927*t817 + ((t911*t818 + (t926*t766 + t941*t805)) + t912*t778)) + t897*t830;
    raw[254] = t897*t818 + (t912*t766 + t927*t805);
    raw[256] = (t912*t858 + ((t898*t844 + (t928*t831 + t913*t857)) + t927*t832)) + t897*t845;
    raw[257] = (t912*t859 + ((t899*t844 + (t929*t831 + t914*t857)) + t927*t833)) + t897*t846;
    raw[258] = (t912*t860 + ((t900*t844 + (t930*t831 + t915*t857)) + t927*t834)) + t897*t847;
    raw[262] = in[15]*t844 + (in[17]*t831 + in[16]*t857);
    raw[263] = in[18]*t844 + (in[20]*t831 + in[19]*t857);
    raw[264] = in[21]*t844 + (in[23]*t831 + in[22]*t857);
    raw[265] = (t912*t861 + ((t931*t831 + t916*t857) + t927*t835)) + t897*t848;
    raw[266] = (t912*t862 + ((t932*t831 + t901*t844) + t927*t836)) + t897*t849;
    raw[267] = (t912*t863 + ((t917*t857 + t902*t844) + t927*t837)) + t897*t850;
    raw[271] = t903*t844 + (t933*t831 + t918*t857);
    raw[272] = t904*t844 + (t934*t831 + t919*t857);
    raw[273] = t905*t844 + (t935*t831 + t920*t857);
    raw[274] = (t912*t864 + ((t906*t844 + (t936*t831 + t921*t857)) + t927*t838)) + t897*t851;
    raw[275] = (t912*t865 + ((t907*t844 + (t937*t831 + t922*t857)) + t927*t839)) + t897*t852;
    raw[276] = (t912*t866 + ((t908*t844 + (t938*t831 + t923*t857)) + t927*t840)) + t897*t853;
    raw[277] = (t912*t867 + ((t909*t844 + (t939*t831 + t924*t857)) + t927*t841)) + t897*t854;
    raw[278] = (t912*t868 + ((t910*t844 + (t940*t831 + t925*t857)) + t927*t842)) + t897*t855;
    raw[279] = (t912*t869 + ((t911*t844 + (t941*t831 + t926*t857)) + t927*t843)) + t897*t856;
    raw[286] = t897*t844 + (t927*t831 + t912*t857);
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
}

void factor_cost_0(const T in[42], const T dat[193],
                   T half[1]) {
#pragma HLS INLINE off
#pragma HLS ALLOCATION operation instances=fadd limit=6
#pragma HLS ALLOCATION operation instances=fmul limit=7
#pragma HLS ALLOCATION operation instances=fdiv limit=1
#pragma HLS ALLOCATION operation instances=fsqrt limit=1
    const T t0 = in[30] - dat[63];
    const T t1 = in[31] - dat[64];
    const T t2 = in[32] - dat[65];
    const T t3 = in[33] - dat[66];
    const T t4 = in[34] - dat[67];
    const T t5 = in[35] - dat[68];
    const T t6 = (dat[41]*t5 + (dat[1] + dat[12]*t0)) + ((dat[13]*t1 + dat[14]*t2) + (dat[39]*t3 + dat[40]*t4));
    const T t7 = -t6;
    const T t8 = t6*t7;
    const T t9 = (dat[44]*t5 + (dat[2] + dat[15]*t0)) + ((dat[16]*t1 + dat[17]*t2) + (dat[42]*t3 + dat[43]*t4));
    const T t10 = -t9;
    const T t11 = t10*t9;
    const T t12 = t11 + t8;
    const T t13 = (dat[38]*t5 + (dat[0] + dat[9]*t0)) + ((dat[10]*t1 + dat[11]*t2) + (dat[36]*t3 + dat[37]*t4));
    const T t14 = (t9*t9) + ((t13*t13) + (t6*t6));
    const T t15 = lie_B(t14);
    const T t16 = T(1) + t12*t15;
    const T t17 = in[6]*in[21] + (in[0]*in[15] + in[3]*in[18]);
    const T t18 = t17;
    const T t19 = -t13;
    const T t20 = lie_A(t14);
    const T t21 = t7*t15;
    const T t22 = t9*t20 + t19*t21;
    const T t23 = in[7]*in[21] + (in[1]*in[15] + in[4]*in[18]);
    const T t24 = t23;
    const T t25 = t13*t15;
    const T t26 = t7*t20 + t9*t25;
    const T t27 = in[8]*in[21] + (in[2]*in[15] + in[5]*in[18]);
    const T t28 = t27;
    const T t29 = t28*t26 + (t18*t16 + t24*t22);
    const T t30 = t13*t19;
    const T t31 = t11 + t30;
    const T t32 = T(1) + t31*t15;
    const T t33 = t13*t20 + t10*t21;
    const T t34 = t10*t20 + t6*t25;
    const T t35 = t28*t33 + (t24*t32 + t18*t34);
    const T t36 = t30 + t8;
    const T t37 = T(1) + t36*t15;
    const T t38 = t10*t15;
    const T t39 = t6*t20 + t19*t38;
    const T t40 = t9*t15;
    const T t41 = t19*t20 + t6*t40;
    const T t42 = t24*t41 + (t28*t37 + t18*t39);
    const T t43 = in[6]*in[22] + (in[0]*in[16] + in[3]*in[19]);
    const T t44 = t43;
    const T t45 = in[7]*in[22] + (in[1]*in[16] + in[4]*in[19]);
    const T t46 = t45;
    const T t47 = in[8]*in[22] + (in[2]*in[16] + in[5]*in[19]);
    const T t48 = t47;
    const T t49 = t48*t26 + (t44*t16 + t46*t22);
    const T t50 = t44*t34 + (t46*t32 + t48*t33);
    const T t51 = t46*t41 + (t48*t37 + t44*t39);
    const T t52 = in[6]*in[23] + (in[0]*in[17] + in[3]*in[20]);
    const T t53 = t52;
    const T t54 = in[7]*in[23] + (in[1]*in[17] + in[4]*in[20]);
    const T t55 = t54;
    const T t56 = in[8]*in[23] + (in[2]*in[17] + in[5]*in[20]);
    const T t57 = t56;
    const T t58 = t57*t26 + (t53*t16 + t55*t22);
    const T t59 = t53*t34 + (t55*t32 + t57*t33);
    const T t60 = t55*t41 + (t57*t37 + t53*t39);
    T tlog0[3]; so3_log(t29, t35, t42, t49, t50, t51, t58, t59, t60, tlog0);
    const T t61 = tlog0[1];
    const T t62 = (t61*t61);
    const T t63 = t62;
    const T t64 = tlog0[2];
    const T t65 = (t64*t64);
    const T t66 = t65;
    const T t67 = t63 + t66;
    const T t68 = tlog0[0];
    const T t69 = (t68*t68);
    const T t70 = t69;
    const T t71 = t70 + t67;
    const T t72 = lie_D(t71);
    const T t73 = T(1) - t67*t72;
    const T t74 = (dat[47]*t5 + (dat[3] + dat[18]*t0)) + ((dat[19]*t1 + dat[20]*t2) + (dat[45]*t3 + dat[46]*t4));
    const T t75 = (dat[50]*t5 + (dat[4] + dat[21]*t0)) + ((dat[22]*t1 + dat[23]*t2) + (dat[48]*t3 + dat[49]*t4));
    const T t76 = (dat[53]*t5 + (dat[5] + dat[24]*t0)) + ((dat[25]*t1 + dat[26]*t2) + (dat[51]*t3 + dat[52]*t4));
    const T t77 = (T(0.5))*(dat[69]*dat[69]);
    const T t78 = (((dat[69]*in[12] + (in[9] - in[24])) + dat[70]*t77) + in[0]*t74) + (in[1]*t75 + in[2]*t76);
    const T t79 = (((dat[69]*in[13] + (in[10] - in[25])) + dat[71]*t77) + in[3]*t74) + (in[4]*t75 + in[5]*t76);
    const T t80 = (((dat[69]*in[14] + (in[11] - in[26])) + dat[72]*t77) + in[6]*t74) + (in[7]*t75 + in[8]*t76);
    const T t81 = in[21]*t80 + (in[15]*t78 + in[18]*t79);
    const T t82 = t81;
    const T t83 = (T(0.5))*t64;
    const T t84 = t83;
    const T t85 = t68*t72;
    const T t86 = t61*t85;
    const T t87 = t84 + t86;
    const T t88 = in[22]*t80 + (in[16]*t78 + in[19]*t79);
    const T t89 = t88;
    const T t90 = (T(0.5))*t61;
    const T t91 = t90;
    const T t92 = t64*t85;
    const T t93 = t92 - t91;
    const T t94 = in[23]*t80 + (in[17]*t78 + in[20]*t79);
    const T t95 = t94;
    const T t96 = t95*t93 + (t82*t73 + t89*t87);
    const T t97 = -(t66 + t70);
    const T t98 = T(1) + t97*t72;
    const T t99 = (T(0.5))*t68;
    const T t100 = t99;
    const T t101 = t61*t64;
    const T t102 = t101*t72;
    const T t103 = t100 + t102;
    const T t104 = t86 - t84;
    const T t105 = t82*t104 + (t89*t98 + t95*t103);
    const T t106 = -(t63 + t70);
    const T t107 = T(1) + t106*t72;
    const T t108 = t91 + t92;
    const T t109 = t102 - t100;
    const T t110 = t82*t108 + (t89*t109 + t95*t107);
    const T t111 = (dat[56]*t5 + (dat[6] + dat[27]*t0)) + ((dat[28]*t1 + dat[29]*t2) + (dat[54]*t3 + dat[55]*t4));
    const T t112 = (dat[59]*t5 + (dat[7] + dat[30]*t0)) + ((dat[31]*t1 + dat[32]*t2) + (dat[57]*t3 + dat[58]*t4));
    const T t113 = (dat[62]*t5 + (dat[8] + dat[33]*t0)) + ((dat[34]*t1 + dat[35]*t2) + (dat[60]*t3 + dat[61]*t4));
    const T t114 = ((dat[69]*dat[70] + (in[12] - in[27])) + in[0]*t111) + (in[1]*t112 + in[2]*t113);
    const T t115 = ((dat[69]*dat[71] + (in[13] - in[28])) + in[3]*t111) + (in[4]*t112 + in[5]*t113);
    const T t116 = ((dat[69]*dat[72] + (in[14] - in[29])) + in[6]*t111) + (in[7]*t112 + in[8]*t113);
    const T t117 = in[21]*t116 + (in[15]*t114 + in[18]*t115);
    const T t118 = t117;
    const T t119 = in[22]*t116 + (in[16]*t114 + in[19]*t115);
    const T t120 = t119;
    const T t121 = in[23]*t116 + (in[17]*t114 + in[20]*t115);
    const T t122 = t121;
    const T t123 = t122*t93 + (t118*t73 + t120*t87);
    const T t124 = t118*t104 + (t120*t98 + t122*t103);
    const T t125 = t118*t108 + (t122*t107 + t120*t109);
    const T t126 = in[30] - in[36];
    const T t127 = in[31] - in[37];
    const T t128 = in[32] - in[38];
    const T t129 = in[33] - in[39];
    const T t130 = in[34] - in[40];
    const T t131 = in[35] - in[41];
    const T t132 = (((T(0.5))*(((((dat[152]*t127 + dat[153]*t128) + ((dat[154]*t129 + dat[155]*t130) + (dat[156]*t131 + dat[151]*t126))) + dat[149]*t124) + (dat[150]*t125 + dat[148]*t123))*((((dat[152]*t127 + dat[153]*t128) + ((dat[154]*t129 + dat[155]*t130) + (dat[156]*t131 + dat[151]*t126))) + dat[149]*t124) + (dat[150]*t125 + dat[148]*t123))) + (T(0.5))*(((dat[140]*t124 + dat[141]*t125) + (dat[139]*t123 + (((dat[143]*t127 + dat[144]*t128) + ((dat[145]*t129 + dat[146]*t130) + (dat[147]*t131 + dat[142]*t126))) + dat[138]*t110)))*((dat[140]*t124 + dat[141]*t125) + (dat[139]*t123 + (((dat[143]*t127 + dat[144]*t128) + ((dat[145]*t129 + dat[146]*t130) + (dat[147]*t131 + dat[142]*t126))) + dat[138]*t110))))) + ((T(0.5))*(((dat[131]*t125 + dat[129]*t123) + ((((dat[133]*t127 + dat[134]*t128) + ((dat[135]*t129 + dat[136]*t130) + (dat[137]*t131 + dat[132]*t126))) + dat[127]*t105) + (dat[128]*t110 + dat[130]*t124)))*((dat[131]*t125 + dat[129]*t123) + ((((dat[133]*t127 + dat[134]*t128) + ((dat[135]*t129 + dat[136]*t130) + (dat[137]*t131 + dat[132]*t126))) + dat[127]*t105) + (dat[128]*t110 + dat[130]*t124)))) + ((T(0.5))*((dat[158]*t125 + (((dat[160]*t127 + dat[161]*t128) + ((dat[162]*t129 + dat[163]*t130) + (dat[164]*t131 + dat[159]*t126))) + dat[157]*t124))*(dat[158]*t125 + (((dat[160]*t127 + dat[161]*t128) + ((dat[162]*t129 + dat[163]*t130) + (dat[164]*t131 + dat[159]*t126))) + dat[157]*t124))) + ((((((T(0.5))*(dat[192]*dat[192]))*(t131*t131) + (T(0.5))*((dat[190]*t130 + dat[191]*t131)*(dat[190]*t130 + dat[191]*t131))) + (T(0.5))*(((dat[182]*t131 + dat[178]*t127) + (dat[179]*t128 + (dat[180]*t129 + dat[181]*t130)))*((dat[182]*t131 + dat[178]*t127) + (dat[179]*t128 + (dat[180]*t129 + dat[181]*t130))))) + ((T(0.5))*(((dat[173]*t127 + dat[174]*t128) + ((dat[175]*t129 + dat[176]*t130) + (dat[177]*t131 + dat[172]*t126)))*((dat[173]*t127 + dat[174]*t128) + ((dat[175]*t129 + dat[176]*t130) + (dat[177]*t131 + dat[172]*t126)))) + ((T(0.5))*((dat[189]*t131 + (dat[187]*t129 + dat[188]*t130))*(dat[189]*t131 + (dat[187]*t129 + dat[188]*t130))) + (T(0.5))*(((dat[184]*t129 + dat[185]*t130) + (dat[186]*t131 + dat[183]*t128))*((dat[184]*t129 + dat[185]*t130) + (dat[186]*t131 + dat[183]*t128)))))) + (T(0.5))*((((dat[167]*t127 + dat[168]*t128) + ((dat[169]*t129 + dat[170]*t130) + (dat[171]*t131 + dat[166]*t126))) + dat[165]*t125)*(((dat[167]*t127 + dat[168]*t128) + ((dat[169]*t129 + dat[170]*t130) + (dat[171]*t131 + dat[166]*t126))) + dat[165]*t125)))))) + (((T(0.5))*(((dat[118]*t123 + (((dat[122]*t127 + dat[123]*t128) + ((dat[124]*t129 + dat[125]*t130) + (dat[126]*t131 + dat[121]*t126))) + dat[116]*t105)) + ((dat[117]*t110 + dat[119]*t124) + (dat[120]*t125 + dat[115]*t96)))*((dat[118]*t123 + (((dat[122]*t127 + dat[123]*t128) + ((dat[124]*t129 + dat[125]*t130) + (dat[126]*t131 + dat[121]*t126))) + dat[116]*t105)) + ((dat[117]*t110 + dat[119]*t124) + (dat[120]*t125 + dat[115]*t96)))) + (T(0.5))*(((dat[106]*t123 + ((((dat[110]*t127 + dat[111]*t128) + ((dat[112]*t129 + dat[113]*t130) + (dat[114]*t131 + dat[109]*t126))) + dat[102]*t64) + dat[104]*t105)) + ((dat[105]*t110 + dat[107]*t124) + (dat[108]*t125 + dat[103]*t96)))*((dat[106]*t123 + ((((dat[110]*t127 + dat[111]*t128) + ((dat[112]*t129 + dat[113]*t130) + (dat[114]*t131 + dat[109]*t126))) + dat[102]*t64) + dat[104]*t105)) + ((dat[105]*t110 + dat[107]*t124) + (dat[108]*t125 + dat[103]*t96))))) + ((T(0.5))*(((dat[93]*t123 + ((dat[89]*t64 + (((dat[97]*t127 + dat[98]*t128) + ((dat[99]*t129 + dat[100]*t130) + (dat[101]*t131 + dat[96]*t126))) + dat[88]*t61)) + dat[91]*t105)) + ((dat[92]*t110 + dat[94]*t124) + (dat[95]*t125 + dat[90]*t96)))*((dat[93]*t123 + ((dat[89]*t64 + (((dat[97]*t127 + dat[98]*t128) + ((dat[99]*t129 + dat[100]*t130) + (dat[101]*t131 + dat[96]*t126))) + dat[88]*t61)) + dat[91]*t105)) + ((dat[92]*t110 + dat[94]*t124) + (dat[95]*t125 + dat[90]*t96)))) + (T(0.5))*(((dat[79]*t123 + (((((dat[83]*t127 + dat[84]*t128) + ((dat[85]*t129 + dat[86]*t130) + (dat[87]*t131 + dat[82]*t126))) + dat[73]*t68) + (dat[74]*t61 + dat[75]*t64)) + dat[77]*t105)) + ((dat[78]*t110 + dat[80]*t124) + (dat[81]*t125 + dat[76]*t96)))*((dat[79]*t123 + (((((dat[83]*t127 + dat[84]*t128) + ((dat[85]*t129 + dat[86]*t130) + (dat[87]*t131 + dat[82]*t126))) + dat[73]*t68) + (dat[74]*t61 + dat[75]*t64)) + dat[77]*t105)) + ((dat[78]*t110 + dat[80]*t124) + (dat[81]*t125 + dat[76]*t96))))));
    half[0] = t132;
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

// block 2: PriorFactorVector3 (3 rows, 3 columns, 1 instances)
void factor_2(const T in[3], const T dat[4],
              T raw[12]) {
#pragma HLS INLINE off
#pragma HLS ALLOCATION operation instances=fadd limit=1
    raw[0] = T(1);
    raw[3] = in[0] - dat[0];
    raw[5] = T(1);
    raw[7] = in[1] - dat[1];
    raw[10] = T(1);
    raw[11] = in[2] - dat[2];
}

void factor_cost_2(const T in[3], const T dat[4],
                   T half[1]) {
#pragma HLS INLINE off
#pragma HLS ALLOCATION operation instances=fadd limit=2
#pragma HLS ALLOCATION operation instances=fmul limit=2
    const T t0 = in[0] - dat[0];
    const T t1 = in[1] - dat[1];
    const T t2 = in[2] - dat[2];
    const T t3 = (T(0.5))*(dat[3]*dat[3]);
    const T t4 = t3*(t2*t2) + (t3*(t0*t0) + t3*(t1*t1));
    half[0] = t4;
}

// block 3: PriorFactorImuBias (6 rows, 6 columns, 1 instances)
void factor_3(const T in[6], const T dat[7],
              T raw[48]) {
#pragma HLS INLINE off
#pragma HLS ALLOCATION operation instances=fadd limit=1
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

void factor_cost_3(const T in[6], const T dat[7],
                   T half[1]) {
#pragma HLS INLINE off
#pragma HLS ALLOCATION operation instances=fadd limit=3
#pragma HLS ALLOCATION operation instances=fmul limit=4
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
const int NOISE_AB = 480;  // the largest block type's padded rows
const int NOISE_ROWS = 15;  // the most rows of a block type
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
#pragma HLS LOOP_TRIPCOUNT max=4
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

// One whitened row of a block type as evaluate_<b> streams it to its HGC (reduce_<b>) in the
// linearize_<b> region: a word per column of the widest block type's padded row.
struct GramRow { T word[32]; };

// The HGC beside the elimination (block 0, the longest HGC region): one word of its Gram
// stream a gram_entries_stream iteration, the iteration's lane-A entries then its lane-B entry
// (unused slots of an iteration with fewer entries are not read)
struct GramWord { L v[2]; };

// HGC (paper B): a block type's Grams of [A | b], instance after instance, as one pipelined
// loop of N x STEPS iterations (no drain between instances). Iteration (i, e): entry e of
// instance i's packed lower triangle, the structurally non-zero entries (p, q), q <= p (the
// block's tables P, Q), one every GII cycles, each the dot product of columns p and q over the
// instance's ROWS rows (gram_entry: ROWS products folded in a binary tree, La ceil(log2 ROWS)
// deep, so at II GII Vitis binds ceil(ROWS / GII) multipliers and ceil((ROWS - 1) / GII)
// adders: the plan's hgc_<b>; no accumulator is carried from one entry to the next). Written
// into GRAM at FACTOR_GRAM_OFF[f] + p (p + 1) / 2 + q (entries left out are structural zeros,
// never written: GRAM keeps its initial zeros there); an entry of the last row (b^T A, column
// q < COLS - 1) also through one adder into the gradient G at its tangent entry (VAR_T_OFF of
// the factor's variable CV[q], plus CO[q]); a diagonal entry (p == q, a column's squared norm)
// checked finite (an infinite or NaN entry of [A | b] makes its column's diagonal so: no
// operator). The same iteration's first ROWS e read the next instance's rows from the stream
// into the other bank of `ab` (two banks of registers, partitioned completely by the caller: a
// whole row written, two columns of every row read a cycle), so an instance costs its STEPS
// iterations: its entries, at least ROWS + 3 (a bank is read no sooner than 3 iterations after
// it is written: the DEPENDENCE on ab is false) and at least the distance that keeps two
// instances' += into G (which may share a variable) the adder's latency apart (the plan's
// gram_steps: the DEPENDENCE on G is false; every entry of every instance has its own word of
// GRAM, so none on GRAM either). The caller has read instance 0's rows into bank 0.
// gram_entries_two adds a second lane of K multipliers (lane B: entries PB, QB, over the first
// K rows, the only rows that touch both their columns) beside the first, two entries an
// iteration (GRAM's two ports, one write each); G's += stay in the first lane.
template <int PADDED, int ROWS, int K>
L gram_entry(const T bank[ROWS * PADDED], int p, int q) {
#pragma HLS INLINE
    L prod[K];
    for (int r = 0; r < K; ++r) prod[r] = L(bank[r * PADDED + p]) * L(bank[r * PADDED + q]);
    return fgc_units::fold_partials<L, K>(prod);
}

template <int ROWS, int COLS, int N>
void gram_gradient(const int INST[N], const int CV[COLS - 1], const int CO[COLS - 1], int i, int p,
                   int q, L v, bool& finite) {
#pragma HLS INLINE
    const int f = INST[i];
    if (p == q) finite = finite && fgc_isfinite(T(v));
    // the last row through one adder: b^T A into G, b^T b (the cost's) into LIN_SQ
    if (p == COLS - 1) {
        const bool rhs = q == COLS - 1;
        const int at = VAR_T_OFF[FACTOR_VARS[FACTOR_VAR_BEGIN[f] + CV[rhs ? 0 : q]]] + CO[rhs ? 0 : q];
        const T sum = (rhs ? LIN_SQ : G[at]) + T(v);
        if (rhs) {
            LIN_SQ = sum;
        } else {
            G[at] = sum;
        }
    }
}

template <int ROWS, int COLS, int N>
void gram_store(const int INST[N], const int CV[COLS - 1], const int CO[COLS - 1], int i, int p,
                int q, L v, bool& finite) {
#pragma HLS INLINE
    GRAM[FACTOR_GRAM_OFF[INST[i]] + p * (p + 1) / 2 + q] = v;
    gram_gradient<ROWS, COLS, N>(INST, CV, CO, i, p, q, v, finite);
}

template <int PADDED, int ROWS>
void gram_next_row(hls::stream<GramRow>& rows, T bank[ROWS * PADDED], int r) {
#pragma HLS INLINE
    const GramRow row = rows.read();
    for (int c = 0; c < PADDED; ++c) bank[r * PADDED + c] = row.word[c];
}

template <int PADDED, int ROWS, int COLS, int ENTRIES, int STEPS, int N, int GII>
bool gram_entries(hls::stream<GramRow>& rows, T ab[2][ROWS * PADDED], const int INST[N],
                  const int P[ENTRIES], const int Q[ENTRIES], const int CV[COLS - 1],
                  const int CO[COLS - 1]) {
    bool finite = true;
    int i = 0, e = 0;
    for (int t = 0; t < N * STEPS; ++t) {
#pragma HLS PIPELINE II=GII
#pragma HLS DEPENDENCE variable=G inter false
#pragma HLS DEPENDENCE variable=GRAM inter false
#pragma HLS DEPENDENCE variable=ab inter false
        const int cur = i % 2;
        if (e < ROWS && i + 1 < N) gram_next_row<PADDED, ROWS>(rows, ab[1 - cur], e);
        if (e < ENTRIES) {
            const int p = P[e], q = Q[e];
            gram_store<ROWS, COLS, N>(INST, CV, CO, i, p, q, gram_entry<PADDED, ROWS, ROWS>(ab[cur], p, q), finite);
        }
        if (++e == STEPS) {
            e = 0;
            ++i;
        }
    }
    return finite;
}

template <int PADDED, int ROWS, int COLS, int ENTRIES, int ENTRIES_B, int K, int STEPS, int N>
bool gram_entries_two(hls::stream<GramRow>& rows, T ab[2][ROWS * PADDED], const int INST[N],
                      const int P[ENTRIES], const int Q[ENTRIES], const int PB[ENTRIES_B],
                      const int QB[ENTRIES_B], const int CV[COLS - 1], const int CO[COLS - 1]) {
    bool finite = true;
    int i = 0, e = 0;
    for (int t = 0; t < N * STEPS; ++t) {
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=G inter false
#pragma HLS DEPENDENCE variable=GRAM inter false
#pragma HLS DEPENDENCE variable=ab inter false
        const int cur = i % 2;
        if (e < ROWS && i + 1 < N) gram_next_row<PADDED, ROWS>(rows, ab[1 - cur], e);
        if (e < ENTRIES) {
            const int p = P[e], q = Q[e];
            gram_store<ROWS, COLS, N>(INST, CV, CO, i, p, q, gram_entry<PADDED, ROWS, ROWS>(ab[cur], p, q), finite);
        }
        if (e < ENTRIES_B) {  // lane B: never the last row, so never into G
            const int p = PB[e], q = QB[e];
            const L v = gram_entry<PADDED, ROWS, K>(ab[cur], p, q);
            GRAM[FACTOR_GRAM_OFF[INST[i]] + p * (p + 1) / 2 + q] = v;
            if (p == q) finite = finite && fgc_isfinite(T(v));
        }
        if (++e == STEPS) {
            e = 0;
            ++i;
        }
    }
    return finite;
}

// gram_entries_stream: gram_entries (A_PER = 1, ENTRIES_B = 0), gram_entries_two (A_PER = 1)
// or gram_entries_pair (A_PER = 2, GII = 2) of the first n instances of INST, their entries not into
// GRAM but a word an iteration into `grams` (the Gram source of the elimination puts them in
// place); the gradient and the finiteness check as gram_store's.
template <int PADDED, int ROWS, int COLS, int ENTRIES, int ENTRIES_B, int K, int STEPS, int N,
          int GII, int A_PER, int SLOTS>
bool gram_entries_stream(hls::stream<GramRow>& rows, hls::stream<GramWord>& grams,
                         T ab[2][ROWS * PADDED], int n, const int INST[N], const int P[ENTRIES],
                         const int Q[ENTRIES], const int PB[ENTRIES_B > 0 ? ENTRIES_B : 1],
                         const int QB[ENTRIES_B > 0 ? ENTRIES_B : 1],
                         const int CV[COLS - 1], const int CO[COLS - 1]) {
    bool finite = true;
    int i = 0, e = 0;
    for (int t = 0; t < n * STEPS; ++t) {
#pragma HLS LOOP_TRIPCOUNT max=N*STEPS
#pragma HLS PIPELINE II=GII
#pragma HLS DEPENDENCE variable=G inter false
#pragma HLS DEPENDENCE variable=ab inter false
        const int cur = i % 2;
        if (e < ROWS && i + 1 < n) gram_next_row<PADDED, ROWS>(rows, ab[1 - cur], e);
        GramWord word;
        for (int h = 0; h < SLOTS; ++h) word.v[h] = L(0);
        for (int h = 0; h < A_PER; ++h) {  // lane A
            if (A_PER * e + h < ENTRIES) {
                const int p = P[A_PER * e + h], q = Q[A_PER * e + h];
                const L v = gram_entry<PADDED, ROWS, ROWS>(ab[cur], p, q);
                gram_gradient<ROWS, COLS, N>(INST, CV, CO, i, p, q, v, finite);
                word.v[h] = v;
            }
        }
        if (ENTRIES_B > 0 && e < ENTRIES_B) {  // lane B: never the last row, so never into G
            const int p = PB[e], q = QB[e];
            const L v = gram_entry<PADDED, ROWS, K>(ab[cur], p, q);
            if (p == q) finite = finite && fgc_isfinite(T(v));
            word.v[A_PER] = v;
        }
        grams.write(word);
        if (++e == STEPS) {
            e = 0;
            ++i;
        }
    }
    return finite;
}

// gram_entries_pair: the two lanes at II 2, two lane-A entries (P, Q at 2e and 2e + 1) and one
// lane-B entry an iteration, so Vitis binds ROWS + ceil(K / 2) multipliers (the two lane-A
// entries' 2 ROWS products over the II's two cycles) for 1.5 entries a cycle; the next
// instance's rows a row an iteration (STEPS >= ROWS + 3); G's += stay in lane A (four
// accesses of G an iteration through its two ports in two cycles), three GRAM writes.
template <int PADDED, int ROWS, int COLS, int ENTRIES, int ENTRIES_B, int K, int STEPS, int N>
bool gram_entries_pair(hls::stream<GramRow>& rows, T ab[2][ROWS * PADDED], const int INST[N],
                       const int P[ENTRIES], const int Q[ENTRIES], const int PB[ENTRIES_B],
                       const int QB[ENTRIES_B], const int CV[COLS - 1], const int CO[COLS - 1]) {
    bool finite = true;
    int i = 0, e = 0;
    for (int t = 0; t < N * STEPS; ++t) {
#pragma HLS PIPELINE II=2
#pragma HLS DEPENDENCE variable=G inter false
#pragma HLS DEPENDENCE variable=GRAM inter false
#pragma HLS DEPENDENCE variable=ab inter false
        const int cur = i % 2;
        if (e < ROWS && i + 1 < N) gram_next_row<PADDED, ROWS>(rows, ab[1 - cur], e);
        for (int h = 0; h < 2; ++h) {  // lane A: entries 2e and 2e + 1
            if (2 * e + h < ENTRIES) {
                const int p = P[2 * e + h], q = Q[2 * e + h];
                gram_store<ROWS, COLS, N>(INST, CV, CO, i, p, q, gram_entry<PADDED, ROWS, ROWS>(ab[cur], p, q), finite);
            }
        }
        if (e < ENTRIES_B) {  // lane B: never the last row, so never into G
            const int p = PB[e], q = QB[e];
            const L v = gram_entry<PADDED, ROWS, K>(ab[cur], p, q);
            GRAM[FACTOR_GRAM_OFF[INST[i]] + p * (p + 1) / 2 + q] = v;
            if (p == q) finite = finite && fgc_isfinite(T(v));
        }
        if (++e == STEPS) {
            e = 0;
            ++i;
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
void gather_0(const T x[N_X], int f, T in[42], T dat[193]) {
    const int vb = FACTOR_VAR_BEGIN[f];
    const int line = FACTOR_DATA_OFF[f];
    for (int i = 0; i < 12; ++i) in[0 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 0]] + i];
    for (int i = 0; i < 3; ++i) in[12 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 1]] + i];
    for (int i = 0; i < 12; ++i) in[15 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 2]] + i];
    for (int i = 0; i < 3; ++i) in[27 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 3]] + i];
    for (int i = 0; i < 6; ++i) in[30 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 4]] + i];
    for (int i = 0; i < 6; ++i) in[36 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 5]] + i];
    for (int i = 0; i < 73; ++i) dat[0 + i] = DATA_BUF[line + 0 + i];
    for (int i = 0; i < 120; ++i) dat[73 + i] = DATA_BUF[line + 73 + i];
}

void gather_trial_0(const T x[N_X], int f, T in[42], T dat[193]) {
    const int vb = FACTOR_VAR_BEGIN[f];
    const int line = FACTOR_DATA_OFF[f], h = line >> 1, p = line & 1;
    for (int i = 0; i < 12; ++i) in[0 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 0]] + i];
    for (int i = 0; i < 3; ++i) in[12 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 1]] + i];
    for (int i = 0; i < 12; ++i) in[15 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 2]] + i];
    for (int i = 0; i < 3; ++i) in[27 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 3]] + i];
    for (int i = 0; i < 6; ++i) in[30 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 4]] + i];
    for (int i = 0; i < 6; ++i) in[36 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 5]] + i];
    T w[194];  // DATA_BUF[2 h + 0 ...]: the line's words from 0 at w[p ...]
#pragma HLS ARRAY_PARTITION variable=w complete
    for (int i = 0; i < 193; ++i) w[i] = DATA_BUF[2 * h + 0 + i];
    w[193] = p ? DATA_BUF[2 * h + 193] : T(0);  // an odd line's last word
    for (int i = 0; i < 73; ++i) dat[0 + i] = p ? w[1 + i] : w[0 + i];
    for (int i = 0; i < 120; ++i) dat[73 + i] = p ? w[74 + i] : w[73 + i];
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

// block 0, Jacobian mode: per instance residual + Jacobian (its 180 structural non-zeros of
// 15 x 31), whitening, into AB; one instance every II=233 cycles (the plan's)
// (the HGC beside the elimination: the first n instances in the order the elimination reaches
// their steps, BLOCK0_STEP_ORDER; n = 0 on LM's retries)
const int BLOCK0_STEP_ORDER[7] = {
    0, 6, 1, 5, 2, 4, 3,
};
void evaluate_0(const T x[N_X], int n, hls::stream<GramRow>& rows) {
    for (int i = 0; i < n; ++i) {
#pragma HLS LOOP_TRIPCOUNT max=7
#pragma HLS PIPELINE II=233
        const int f = BLOCK0_STEP_ORDER[i];
        T in[42], dat[193];
        gather_0(x, f, in, dat);
        T raw[480];  // the Jacobian writes only its structural non-zeros
        T ab[480];
        for (int c = 0; c < 480; ++c) raw[c] = T(0);
        factor_0(in, dat, raw);
        whiten<32, 31, 15, 2, 9>(raw + 0, ab + 0, dat + 73);
        whiten_tail_0_0(raw + 0, ab + 0, dat + 73);
        const int a0 = FACTOR_A_OFF[f];
        for (int r = 0; r < 15; ++r) {
            for (int c = 0; c < 31; ++c) AB[a0 + r * 31 + c] = ab[r * 32 + c];
        }
        for (int r = 0; r < 15; ++r) {  // the rows to the HGC, a stream word a row
            GramRow row;
            for (int c = 0; c < 32; ++c) row.word[c] = ab[r * 32 + c];
            rows.write(row);
        }
    }
    FGC_CYCLES("factor_0_jacobian", 0, "instances", n, 233, 621);
}

// block 0's whitened rows of instance f from AB, padded to 32 columns (a multiple of PORTS)
void load_rows_0(int f, T ab[480]) {
    const int a0 = FACTOR_A_OFF[f];
    for (int e = 0; e < 480; e += PORTS) {  // PORTS words a cycle
#pragma HLS PIPELINE II=1
        for (int h = 0; h < PORTS; ++h) {
            const int r = (e + h) / 32, c = (e + h) % 32;
            ab[e + h] = c < 31 ? T(AB[a0 + r * 31 + c]) : T(0);
        }
    }
}

// block 0: the (p, q) of its Gram's structurally non-zero entries, q <= p, in packed order (gram_entries)
const int BLOCK0_GRAM_P[248] = {
    18, 19, 19, 20, 20, 20, 21, 21, 21, 21, 22, 22, 22, 22, 22, 22,
    22, 22, 22, 22, 22, 22, 22, 22, 22, 22, 22, 22, 23, 23, 23, 23,
    23, 23, 23, 23, 23, 23, 23, 23, 23, 23, 23, 23, 23, 23, 23, 23,
    23, 23, 23, 23, 24, 24, 24, 24, 24, 24, 24, 24, 24, 24, 24, 24,
    24, 24, 24, 24, 24, 24, 24, 24, 24, 24, 24, 24, 24, 25, 25, 25,
    25, 25, 25, 25, 25, 25, 25, 25, 25, 25, 25, 25, 25, 25, 25, 25,
    25, 25, 25, 25, 25, 25, 25, 26, 26, 26, 26, 26, 26, 26, 26, 26,
    26, 26, 26, 26, 26, 26, 26, 26, 26, 26, 26, 26, 26, 26, 26, 26,
    26, 26, 27, 27, 27, 27, 27, 27, 27, 27, 27, 27, 27, 27, 27, 27,
    27, 27, 27, 27, 27, 27, 27, 27, 27, 27, 27, 27, 27, 27, 28, 28,
    28, 28, 28, 28, 28, 28, 28, 28, 28, 28, 28, 28, 28, 28, 28, 28,
    28, 28, 28, 28, 28, 28, 28, 28, 28, 28, 28, 29, 29, 29, 29, 29,
    29, 29, 29, 29, 29, 29, 29, 29, 29, 29, 29, 29, 29, 29, 29, 29,
    29, 29, 29, 29, 29, 29, 29, 29, 29, 30, 30, 30, 30, 30, 30, 30,
    30, 30, 30, 30, 30, 30, 30, 30, 30, 30, 30, 30, 30, 30, 30, 30,
    30, 30, 30, 30, 30, 30, 30, 30,
};
const int BLOCK0_GRAM_Q[248] = {
    18, 18, 19, 18, 19, 20, 18, 19, 20, 21, 5, 6, 7, 8, 9, 10,
    11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 0, 1, 2, 3,
    4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19,
    20, 21, 22, 23, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11,
    12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 0, 1, 2,
    3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18,
    19, 20, 21, 22, 23, 24, 25, 0, 1, 2, 3, 4, 5, 6, 7, 8,
    9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24,
    25, 26, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13,
    14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 0, 1,
    2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17,
    18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 0, 1, 2, 3, 4,
    5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20,
    21, 22, 23, 24, 25, 26, 27, 28, 29, 0, 1, 2, 3, 4, 5, 6,
    7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22,
    23, 24, 25, 26, 27, 28, 29, 30,
};
// block 0: the entries of lane B (gram_entries_two: the first 9 rows touch both their columns, no other)
const int BLOCK0_GRAM_PB[248] = {
    0, 1, 1, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 4, 5,
    5, 5, 5, 5, 5, 6, 6, 6, 6, 6, 6, 6, 7, 7, 7, 7,
    7, 7, 7, 7, 8, 8, 8, 8, 8, 8, 8, 8, 8, 9, 9, 9,
    9, 9, 9, 9, 9, 9, 9, 10, 10, 10, 10, 10, 10, 10, 10, 10,
    10, 10, 11, 11, 11, 11, 11, 11, 11, 11, 11, 11, 11, 11, 12, 12,
    12, 12, 12, 12, 12, 12, 12, 12, 12, 12, 12, 13, 13, 13, 13, 13,
    13, 13, 13, 13, 13, 13, 13, 13, 13, 14, 14, 14, 14, 14, 14, 14,
    14, 14, 14, 14, 14, 14, 14, 14, 15, 15, 15, 15, 15, 15, 15, 15,
    15, 15, 15, 15, 15, 15, 15, 15, 16, 16, 16, 16, 16, 16, 16, 16,
    16, 16, 16, 16, 16, 16, 16, 16, 16, 17, 17, 17, 17, 17, 17, 17,
    17, 17, 17, 17, 17, 17, 17, 17, 17, 17, 17, 18, 18, 18, 18, 18,
    18, 18, 18, 18, 18, 18, 18, 18, 18, 18, 18, 18, 18, 19, 19, 19,
    19, 19, 19, 19, 19, 19, 19, 19, 19, 19, 19, 19, 19, 19, 19, 20,
    20, 20, 20, 20, 20, 20, 20, 20, 20, 20, 20, 20, 20, 20, 20, 20,
    20, 21, 21, 21, 21, 21, 21, 21, 21, 21, 21, 21, 21, 21, 21, 21,
    21, 21, 21, 22, 22, 22, 22, 22,
};
const int BLOCK0_GRAM_QB[248] = {
    0, 0, 1, 0, 1, 2, 0, 1, 2, 3, 0, 1, 2, 3, 4, 0,
    1, 2, 3, 4, 5, 0, 1, 2, 3, 4, 5, 6, 0, 1, 2, 3,
    4, 5, 6, 7, 0, 1, 2, 3, 4, 5, 6, 7, 8, 0, 1, 2,
    3, 4, 5, 6, 7, 8, 9, 0, 1, 2, 3, 4, 5, 6, 7, 8,
    9, 10, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 0, 1,
    2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 0, 1, 2, 3, 4,
    5, 6, 7, 8, 9, 10, 11, 12, 13, 0, 1, 2, 3, 4, 5, 6,
    7, 8, 9, 10, 11, 12, 13, 14, 0, 1, 2, 3, 4, 5, 6, 7,
    8, 9, 10, 11, 12, 13, 14, 15, 0, 1, 2, 3, 4, 5, 6, 7,
    8, 9, 10, 11, 12, 13, 14, 15, 16, 0, 1, 2, 3, 4, 5, 6,
    7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 0, 1, 2, 3, 4,
    5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 0, 1, 2,
    3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 0,
    1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16,
    17, 0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14,
    15, 16, 17, 0, 1, 2, 3, 4,
};
// block 0: per column of A its variable (k-th of the factor's) and the column's offset in it (gram_entries' gradient)
const int BLOCK0_COL_VAR[30] = {
    0, 0, 0, 0, 0, 0, 1, 1, 1, 2, 2, 2, 2, 2, 2, 3,
    3, 3, 4, 4, 4, 4, 4, 4, 5, 5, 5, 5, 5, 5,
};
const int BLOCK0_COL_OFF[30] = {
    0, 1, 2, 3, 4, 5, 0, 1, 2, 0, 1, 2, 3, 4, 5, 0,
    1, 2, 0, 1, 2, 3, 4, 5, 0, 1, 2, 3, 4, 5,
};
// block 0's HGC beside the elimination: as reduce_<b> (instance 0's rows, then one loop over
// the first n instances in step order, 248 iterations each), its Grams a word an iteration into
// `grams` instead of GRAM (gram_entries_stream); the gradient into G and `finite` as there
void reduce_0(hls::stream<GramRow>& rows, int n, hls::stream<GramWord>& grams, bool& finite) {
    T ab[2][480];
#pragma HLS ARRAY_PARTITION variable=ab complete dim=0
    for (int r = 0; r < (n > 0 ? 15 : 0); ++r) {
#pragma HLS LOOP_TRIPCOUNT max=15
#pragma HLS PIPELINE II=1
        const GramRow row = rows.read();
        for (int c = 0; c < 32; ++c) ab[0][r * 32 + c] = row.word[c];
    }
    FGC_CYCLES("reduce_0", 0, "rows", n > 0 ? 15 : 0, 1, 2);
    finite = gram_entries_stream<32, 15, 31, 248, 248, 9, 248, 7, 1, 1, 2>(
        rows, grams, ab, n, BLOCK0_STEP_ORDER, BLOCK0_GRAM_P, BLOCK0_GRAM_Q, BLOCK0_GRAM_PB, BLOCK0_GRAM_QB,
        BLOCK0_COL_VAR, BLOCK0_COL_OFF);
    FGC_CYCLES("reduce_0", 0, "entries", n * 248, 1, 26);
    // csim only: when each instance's Gram is complete (the elimination's passes wait for them)
    FGC_BESIDE_READY(n, 233, 621, 16, 248, 1, 26);
}

// block 0's producer beside the elimination, one DATAFLOW region: evaluate_0 (the datapath:
// the whitened rows into AB and, a stream word a row, to the HGC) alongside reduce_0 (the Grams
// into `grams`, the gradient into G); n instances in step order (0: LM's retry, nothing to do)
void produce_0(const T x[N_X], int n, hls::stream<GramWord>& grams, bool& finite) {
#pragma HLS DATAFLOW
    hls::stream<GramRow> rows;
#pragma HLS STREAM variable=rows depth=15
    FGC_REGION("linearize_0");
    evaluate_0(x, n, rows);
    reduce_0(rows, n, grams, finite);
    FGC_DRAINED(&rows, 1);
}

// block 0: `noise` plus the cost's rounding noise of its instances at the linearisation point (from AB);
// INLINE: the block types' running sums land in rounding_noise_all's body, one after another, so
// they share its one adder, and its ALLOCATION makes their rounding_noise calls one module
T noise_0(T noise, T ab[NOISE_AB]) {
#pragma HLS INLINE
    for (int i = 0; i < 7; ++i) {
        const int f = BLOCK0_INSTANCES[i];
        const int vb = FACTOR_VAR_BEGIN[f];
        load_rows_0(f, ab);  // into rounding_noise_all's one row buffer
        T scale[NOISE_STRIDE];  // per column: largest storage entry of its variable (0: b, padding)
        for (int c = 0; c < 32; ++c) scale[c] = T(0);
        for (int j = 0; j < 6; ++j) scale[0 + j] = VAR_SCALE[FACTOR_VARS[vb + 0]];
        for (int j = 0; j < 3; ++j) scale[6 + j] = VAR_SCALE[FACTOR_VARS[vb + 1]];
        for (int j = 0; j < 6; ++j) scale[9 + j] = VAR_SCALE[FACTOR_VARS[vb + 2]];
        for (int j = 0; j < 3; ++j) scale[15 + j] = VAR_SCALE[FACTOR_VARS[vb + 3]];
        for (int j = 0; j < 6; ++j) scale[18 + j] = VAR_SCALE[FACTOR_VARS[vb + 4]];
        for (int j = 0; j < 6; ++j) scale[24 + j] = VAR_SCALE[FACTOR_VARS[vb + 5]];
        noise += rounding_noise(ab, scale, 32, 31, 15);
        FGC_CYCLES("noise_0", 0, "load", 240, 1, 2);
        FGC_CYCLES("noise_0", 0, "scales", 32, 1, 1);
        FGC_CYCLES("noise_0", 0, "rows", 15, 35, 49);
        FGC_CYCLES("noise_0", 0, "terms", 4, 12, 25);
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

// gather_trial_b_1: gather_trial_'s rule on DATA_B (trial_cost_b's copy of its lines from TRIAL_B_LO, even)
void gather_trial_b_1(const T x[N_X], int f, T in[12], T dat[13]) {
    const int vb = FACTOR_VAR_BEGIN[f];
    const int line = FACTOR_DATA_OFF[f], h = line >> 1, p = line & 1;
    for (int i = 0; i < 12; ++i) in[0 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 0]] + i];
    T w[14];  // DATA_B[-TRIAL_B_LO + 2 h + 0 ...]: the line's words from 0 at w[p ...]
#pragma HLS ARRAY_PARTITION variable=w complete
    for (int i = 0; i < 13; ++i) w[i] = DATA_B[-TRIAL_B_LO + 2 * h + 0 + i];
    w[13] = p ? DATA_B[-TRIAL_B_LO + 2 * h + 13] : T(0);  // an odd line's last word
    for (int i = 0; i < 12; ++i) dat[0 + i] = p ? w[1 + i] : w[0 + i];
    for (int i = 0; i < 1; ++i) dat[12 + i] = p ? w[13 + i] : w[12 + i];
}

// block 1, Jacobian mode: per instance residual + Jacobian (its 33 structural non-zeros of
// 6 x 7), whitening, into AB; one instance every II=111 cycles (the plan's)
void evaluate_1(const T x[N_X], hls::stream<GramRow>& rows) {
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
        for (int r = 0; r < 6; ++r) {  // the rows to the HGC, a stream word a row
            GramRow row;
            for (int c = 0; c < 8; ++c) row.word[c] = ab[r * 8 + c];
            rows.write(row);
        }
    }
    FGC_CYCLES("factor_1_jacobian", 0, "instances", 1, 111, 416);
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

// block 1: the (p, q) of its Gram's structurally non-zero entries, q <= p, in packed order (gram_entries)
const int BLOCK1_GRAM_P[28] = {
    0, 1, 1, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 4, 5,
    5, 5, 5, 5, 5, 6, 6, 6, 6, 6, 6, 6,
};
const int BLOCK1_GRAM_Q[28] = {
    0, 0, 1, 0, 1, 2, 0, 1, 2, 3, 0, 1, 2, 3, 4, 0,
    1, 2, 3, 4, 5, 0, 1, 2, 3, 4, 5, 6,
};
// block 1: per column of A its variable (k-th of the factor's) and the column's offset in it (gram_entries' gradient)
const int BLOCK1_COL_VAR[6] = {
    0, 0, 0, 0, 0, 0,
};
const int BLOCK1_COL_OFF[6] = {
    0, 1, 2, 3, 4, 5,
};
// block 1's HGC: instance 0's 6 whitened rows from evaluate_1's stream, a row a cycle, into
// bank 0 of the registers, then gram_entries over all 1 instances (28 iterations each: its
// Grams into GRAM, the last rows into the gradient, the diagonals checked, the next instance's
// rows read alongside); `finite` false if not finite
void reduce_1(hls::stream<GramRow>& rows, bool& finite) {
    T ab[2][48];
#pragma HLS ARRAY_PARTITION variable=ab complete dim=0
    for (int r = 0; r < 6; ++r) {
#pragma HLS PIPELINE II=1
        const GramRow row = rows.read();
        for (int c = 0; c < 8; ++c) ab[0][r * 8 + c] = row.word[c];
    }
    FGC_CYCLES("reduce_1", 0, "rows", 6, 1, 2);
    finite = gram_entries<8, 6, 7, 28, 28, 1, 6>(
        rows, ab, BLOCK1_INSTANCES, BLOCK1_GRAM_P, BLOCK1_GRAM_Q, BLOCK1_COL_VAR, BLOCK1_COL_OFF);
    FGC_CYCLES("reduce_1", 0, "entries", 28, 6, 22);
}

// block 1's linearisation, one DATAFLOW region: evaluate_1 (the datapath: the whitened rows
// into AB and, a stream word a row, to the HGC) alongside reduce_1 (their Gram and gradient), so
// an instance's Gram is computed while the datapath evaluates the next instances
void linearize_1(const T x[N_X], bool& finite) {
#pragma HLS DATAFLOW
    hls::stream<GramRow> rows;
#pragma HLS STREAM variable=rows depth=6
    FGC_REGION("linearize_1");
    evaluate_1(x, rows);
    reduce_1(rows, finite);
    FGC_DRAINED(&rows, 1);
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
        FGC_CYCLES("noise_1", 0, "rows", 6, 35, 49);
        FGC_CYCLES("noise_1", 0, "terms", 2, 12, 25);
    }
    return noise;
}

void gather_2(const T x[N_X], int f, T in[3], T dat[4]) {
    const int vb = FACTOR_VAR_BEGIN[f];
    const int line = FACTOR_DATA_OFF[f];
    for (int i = 0; i < 3; ++i) in[0 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 0]] + i];
    for (int i = 0; i < 3; ++i) dat[0 + i] = DATA_BUF[line + 0 + i];
    for (int i = 0; i < 1; ++i) dat[3 + i] = DATA_BUF[line + 3 + i];
}

// gather_trial_b_2: gather_trial_'s rule on DATA_B (trial_cost_b's copy of its lines from TRIAL_B_LO, even)
void gather_trial_b_2(const T x[N_X], int f, T in[3], T dat[4]) {
    const int vb = FACTOR_VAR_BEGIN[f];
    const int line = FACTOR_DATA_OFF[f], h = line >> 1, p = line & 1;
    for (int i = 0; i < 3; ++i) in[0 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 0]] + i];
    T w[5];  // DATA_B[-TRIAL_B_LO + 2 h + 0 ...]: the line's words from 0 at w[p ...]
#pragma HLS ARRAY_PARTITION variable=w complete
    for (int i = 0; i < 4; ++i) w[i] = DATA_B[-TRIAL_B_LO + 2 * h + 0 + i];
    w[4] = p ? DATA_B[-TRIAL_B_LO + 2 * h + 4] : T(0);  // an odd line's last word
    for (int i = 0; i < 3; ++i) dat[0 + i] = p ? w[1 + i] : w[0 + i];
    for (int i = 0; i < 1; ++i) dat[3 + i] = p ? w[4 + i] : w[3 + i];
}

// block 2, Jacobian mode: per instance residual + Jacobian (its 6 structural non-zeros of
// 3 x 4), whitening, into AB; one instance every II=6 cycles (the plan's)
void evaluate_2(const T x[N_X], hls::stream<GramRow>& rows) {
    for (int i = 0; i < 1; ++i) {
#pragma HLS PIPELINE II=6
        const int f = BLOCK2_INSTANCES[i];
        T in[3], dat[4];
        gather_2(x, f, in, dat);
        T raw[12];  // the Jacobian writes only its structural non-zeros
        T ab[12];
        for (int c = 0; c < 12; ++c) raw[c] = T(0);
        factor_2(in, dat, raw);
        whiten<4, 4, 3, 0, 3>(raw + 0, ab + 0, dat + 3);
        const int a0 = FACTOR_A_OFF[f];
        for (int r = 0; r < 3; ++r) {
            for (int c = 0; c < 4; ++c) AB[a0 + r * 4 + c] = ab[r * 4 + c];
        }
        for (int r = 0; r < 3; ++r) {  // the rows to the HGC, a stream word a row
            GramRow row;
            for (int c = 0; c < 4; ++c) row.word[c] = ab[r * 4 + c];
            rows.write(row);
        }
    }
    FGC_CYCLES("factor_2_jacobian", 0, "instances", 1, 6, 4);
}

// block 2's whitened rows of instance f from AB, padded to 4 columns (a multiple of PORTS)
void load_rows_2(int f, T ab[12]) {
    const int a0 = FACTOR_A_OFF[f];
    for (int e = 0; e < 12; e += PORTS) {  // PORTS words a cycle
#pragma HLS PIPELINE II=1
        for (int h = 0; h < PORTS; ++h) {
            const int r = (e + h) / 4, c = (e + h) % 4;
            ab[e + h] = c < 4 ? T(AB[a0 + r * 4 + c]) : T(0);
        }
    }
}

// block 2: the (p, q) of its Gram's structurally non-zero entries, q <= p, in packed order (gram_entries)
const int BLOCK2_GRAM_P[7] = {
    0, 1, 2, 3, 3, 3, 3,
};
const int BLOCK2_GRAM_Q[7] = {
    0, 1, 2, 0, 1, 2, 3,
};
// block 2: per column of A its variable (k-th of the factor's) and the column's offset in it (gram_entries' gradient)
const int BLOCK2_COL_VAR[3] = {
    0, 0, 0,
};
const int BLOCK2_COL_OFF[3] = {
    0, 1, 2,
};
// block 2's HGC: instance 0's 3 whitened rows from evaluate_2's stream, a row a cycle, into
// bank 0 of the registers, then gram_entries over all 1 instances (7 iterations each: its
// Grams into GRAM, the last rows into the gradient, the diagonals checked, the next instance's
// rows read alongside); `finite` false if not finite
void reduce_2(hls::stream<GramRow>& rows, bool& finite) {
    T ab[2][12];
#pragma HLS ARRAY_PARTITION variable=ab complete dim=0
    for (int r = 0; r < 3; ++r) {
#pragma HLS PIPELINE II=1
        const GramRow row = rows.read();
        for (int c = 0; c < 4; ++c) ab[0][r * 4 + c] = row.word[c];
    }
    FGC_CYCLES("reduce_2", 0, "rows", 3, 1, 2);
    finite = gram_entries<4, 3, 4, 7, 7, 1, 3>(
        rows, ab, BLOCK2_INSTANCES, BLOCK2_GRAM_P, BLOCK2_GRAM_Q, BLOCK2_COL_VAR, BLOCK2_COL_OFF);
    FGC_CYCLES("reduce_2", 0, "entries", 7, 3, 18);
}

// block 2's linearisation, one DATAFLOW region: evaluate_2 (the datapath: the whitened rows
// into AB and, a stream word a row, to the HGC) alongside reduce_2 (their Gram and gradient), so
// an instance's Gram is computed while the datapath evaluates the next instances
void linearize_2(const T x[N_X], bool& finite) {
#pragma HLS DATAFLOW
    hls::stream<GramRow> rows;
#pragma HLS STREAM variable=rows depth=3
    FGC_REGION("linearize_2");
    evaluate_2(x, rows);
    reduce_2(rows, finite);
    FGC_DRAINED(&rows, 1);
}

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
        for (int c = 0; c < 4; ++c) scale[c] = T(0);
        for (int j = 0; j < 3; ++j) scale[0 + j] = VAR_SCALE[FACTOR_VARS[vb + 0]];
        noise += rounding_noise(ab, scale, 4, 4, 3);
        FGC_CYCLES("noise_2", 0, "load", 6, 1, 2);
        FGC_CYCLES("noise_2", 0, "scales", 4, 1, 1);
        FGC_CYCLES("noise_2", 0, "rows", 3, 35, 49);
        FGC_CYCLES("noise_2", 0, "terms", 1, 12, 25);
    }
    return noise;
}

void gather_3(const T x[N_X], int f, T in[6], T dat[7]) {
    const int vb = FACTOR_VAR_BEGIN[f];
    const int line = FACTOR_DATA_OFF[f];
    for (int i = 0; i < 6; ++i) in[0 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 0]] + i];
    for (int i = 0; i < 6; ++i) dat[0 + i] = DATA_BUF[line + 0 + i];
    for (int i = 0; i < 1; ++i) dat[6 + i] = DATA_BUF[line + 6 + i];
}

// gather_trial_b_3: gather_trial_'s rule on DATA_B (trial_cost_b's copy of its lines from TRIAL_B_LO, even)
void gather_trial_b_3(const T x[N_X], int f, T in[6], T dat[7]) {
    const int vb = FACTOR_VAR_BEGIN[f];
    const int line = FACTOR_DATA_OFF[f], h = line >> 1, p = line & 1;
    for (int i = 0; i < 6; ++i) in[0 + i] = x[VAR_X_OFF[FACTOR_VARS[vb + 0]] + i];
    T w[8];  // DATA_B[-TRIAL_B_LO + 2 h + 0 ...]: the line's words from 0 at w[p ...]
#pragma HLS ARRAY_PARTITION variable=w complete
    for (int i = 0; i < 7; ++i) w[i] = DATA_B[-TRIAL_B_LO + 2 * h + 0 + i];
    w[7] = p ? DATA_B[-TRIAL_B_LO + 2 * h + 7] : T(0);  // an odd line's last word
    for (int i = 0; i < 6; ++i) dat[0 + i] = p ? w[1 + i] : w[0 + i];
    for (int i = 0; i < 1; ++i) dat[6 + i] = p ? w[7 + i] : w[6 + i];
}

// block 3, Jacobian mode: per instance residual + Jacobian (its 12 structural non-zeros of
// 6 x 7), whitening, into AB; one instance every II=21 cycles (the plan's)
void evaluate_3(const T x[N_X], hls::stream<GramRow>& rows) {
    for (int i = 0; i < 1; ++i) {
#pragma HLS PIPELINE II=21
        const int f = BLOCK3_INSTANCES[i];
        T in[6], dat[7];
        gather_3(x, f, in, dat);
        T raw[48];  // the Jacobian writes only its structural non-zeros
        T ab[48];
        for (int c = 0; c < 48; ++c) raw[c] = T(0);
        factor_3(in, dat, raw);
        whiten<8, 7, 6, 0, 6>(raw + 0, ab + 0, dat + 6);
        const int a0 = FACTOR_A_OFF[f];
        for (int r = 0; r < 6; ++r) {
            for (int c = 0; c < 7; ++c) AB[a0 + r * 7 + c] = ab[r * 8 + c];
        }
        for (int r = 0; r < 6; ++r) {  // the rows to the HGC, a stream word a row
            GramRow row;
            for (int c = 0; c < 8; ++c) row.word[c] = ab[r * 8 + c];
            rows.write(row);
        }
    }
    FGC_CYCLES("factor_3_jacobian", 0, "instances", 1, 21, 4);
}

// block 3's whitened rows of instance f from AB, padded to 8 columns (a multiple of PORTS)
void load_rows_3(int f, T ab[48]) {
    const int a0 = FACTOR_A_OFF[f];
    for (int e = 0; e < 48; e += PORTS) {  // PORTS words a cycle
#pragma HLS PIPELINE II=1
        for (int h = 0; h < PORTS; ++h) {
            const int r = (e + h) / 8, c = (e + h) % 8;
            ab[e + h] = c < 7 ? T(AB[a0 + r * 7 + c]) : T(0);
        }
    }
}

// block 3: the (p, q) of its Gram's structurally non-zero entries, q <= p, in packed order (gram_entries)
const int BLOCK3_GRAM_P[13] = {
    0, 1, 2, 3, 4, 5, 6, 6, 6, 6, 6, 6, 6,
};
const int BLOCK3_GRAM_Q[13] = {
    0, 1, 2, 3, 4, 5, 0, 1, 2, 3, 4, 5, 6,
};
// block 3: per column of A its variable (k-th of the factor's) and the column's offset in it (gram_entries' gradient)
const int BLOCK3_COL_VAR[6] = {
    0, 0, 0, 0, 0, 0,
};
const int BLOCK3_COL_OFF[6] = {
    0, 1, 2, 3, 4, 5,
};
// block 3's HGC: instance 0's 6 whitened rows from evaluate_3's stream, a row a cycle, into
// bank 0 of the registers, then gram_entries over all 1 instances (13 iterations each: its
// Grams into GRAM, the last rows into the gradient, the diagonals checked, the next instance's
// rows read alongside); `finite` false if not finite
void reduce_3(hls::stream<GramRow>& rows, bool& finite) {
    T ab[2][48];
#pragma HLS ARRAY_PARTITION variable=ab complete dim=0
    for (int r = 0; r < 6; ++r) {
#pragma HLS PIPELINE II=1
        const GramRow row = rows.read();
        for (int c = 0; c < 8; ++c) ab[0][r * 8 + c] = row.word[c];
    }
    FGC_CYCLES("reduce_3", 0, "rows", 6, 1, 2);
    finite = gram_entries<8, 6, 7, 13, 13, 1, 6>(
        rows, ab, BLOCK3_INSTANCES, BLOCK3_GRAM_P, BLOCK3_GRAM_Q, BLOCK3_COL_VAR, BLOCK3_COL_OFF);
    FGC_CYCLES("reduce_3", 0, "entries", 13, 6, 22);
}

// block 3's linearisation, one DATAFLOW region: evaluate_3 (the datapath: the whitened rows
// into AB and, a stream word a row, to the HGC) alongside reduce_3 (their Gram and gradient), so
// an instance's Gram is computed while the datapath evaluates the next instances
void linearize_3(const T x[N_X], bool& finite) {
#pragma HLS DATAFLOW
    hls::stream<GramRow> rows;
#pragma HLS STREAM variable=rows depth=6
    FGC_REGION("linearize_3");
    evaluate_3(x, rows);
    reduce_3(rows, finite);
    FGC_DRAINED(&rows, 1);
}

// block 3: `noise` plus the cost's rounding noise of its instances at the linearisation point (from AB);
// INLINE: the block types' running sums land in rounding_noise_all's body, one after another, so
// they share its one adder, and its ALLOCATION makes their rounding_noise calls one module
T noise_3(T noise, T ab[NOISE_AB]) {
#pragma HLS INLINE
    for (int i = 0; i < 1; ++i) {
        const int f = BLOCK3_INSTANCES[i];
        const int vb = FACTOR_VAR_BEGIN[f];
        load_rows_3(f, ab);  // into rounding_noise_all's one row buffer
        T scale[NOISE_STRIDE];  // per column: largest storage entry of its variable (0: b, padding)
        for (int c = 0; c < 8; ++c) scale[c] = T(0);
        for (int j = 0; j < 6; ++j) scale[0 + j] = VAR_SCALE[FACTOR_VARS[vb + 0]];
        noise += rounding_noise(ab, scale, 8, 7, 6);
        FGC_CYCLES("noise_3", 0, "load", 24, 1, 2);
        FGC_CYCLES("noise_3", 0, "scales", 8, 1, 1);
        FGC_CYCLES("noise_3", 0, "rows", 6, 35, 49);
        FGC_CYCLES("noise_3", 0, "terms", 2, 12, 25);
    }
    return noise;
}

// Linearise every factor: the datapaths in Jacobian mode into AB, then the gradient and Grams (per block type one region, datapath alongside its HGC).
bool linearize_all(const T x[N_X]) {
    FGC_EVENT("linearize");
    FGC_PHASE("hgc");
    // G is zero here: the top's data copy zeroes it (fgc_lm_units.h's lm_top_norm), and so does
    // every solve's state update as it reads G (retract_variable: G moved to G_BACK for the
    // retries); LM linearises only at the start and after an accepted step, a solve that ran
    G_MOVED = false;
    LIN_SQ = T(0);  // (the HGC adds every instance's b^T b, the block beside the elimination's too)
    bool finite = true;
    bool ok1 = true;
    linearize_1(x, ok1);
    FGC_SEQUENTIAL();
    finite = ok1 && finite;
    bool ok2 = true;
    linearize_2(x, ok2);
    FGC_SEQUENTIAL();
    finite = ok2 && finite;
    bool ok3 = true;
    linearize_3(x, ok3);
    FGC_SEQUENTIAL();
    finite = ok3 && finite;
    // block 0: beside the elimination (linearize_solve, which reads x = X itself)
    (void)x;
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
// LM's step test, formed by back_substitute's state update (fgc_backsub.h's backsub_retire_cols)
// as each variable's delta arrives: |delta|^2, delta^T g, every entry of delta finite, and the
// gradient's largest |entry| (the small-gradient test: fgc_lm.h's FGC_LM_GRADIENT_IN_SOLVE)
T TRIAL_DD = T(0), TRIAL_DG = T(0), TRIAL_GMAX = T(0);
bool TRIAL_FINITE = true;
T TRIAL_XX = T(0);  // |x (+) delta|^2 over the variables (X's words as the state update writes them)
const int TRIAL_F_0[7] = {  // per entry of cost loop 0: its instance (-1: none)
    3, 2, 4, 1, 5, 0, 6,
};
const int TRIAL_X0_0[42] = {  // per entry, 6 a row: where each variable it takes goes in x
    63, 75, 78, 84, 96, 99, 42, 54, 57, 0, 0, 0, 105, 117, 120, 0,
    0, 0, 21, 33, 36, 0, 0, 0, 126, 138, 141, 0, 0, 0, 0, 12,
    15, 0, 0, 0, 147, 159, 162, 0, 0, 0,
};
const int TRIAL_X1_0[42] = {  // and where it ends (x0 = x1: none)
    75, 78, 84, 96, 99, 105, 54, 57, 63, 0, 0, 0, 117, 120, 126, 0,
    0, 0, 33, 36, 42, 0, 0, 0, 138, 141, 147, 0, 0, 0, 12, 15,
    21, 0, 0, 0, 159, 162, 168, 0, 0, 0,
};
const int TRIAL_AT_0[42] = {  // its place in RETIRE_VARS (-1: none; the counting build's marks)
    0, 1, 2, 3, 4, 5, 6, 7, 8, -1, -1, -1, 9, 10, 11, -1,
    -1, -1, 12, 13, 14, -1, -1, -1, 15, 16, 17, -1, -1, -1, 18, 19,
    20, -1, -1, -1, 21, 22, 23, -1, -1, -1,
};
const int TRIAL_F_1[1] = {  // per entry of cost loop 1: its instance (-1: none)
    7,
};
const int TRIAL_X0_1[1] = {  // per entry, 1 a row: where each variable it takes goes in x
    0,
};
const int TRIAL_X1_1[1] = {  // and where it ends (x0 = x1: none)
    12,
};
const int TRIAL_AT_1[1] = {  // its place in RETIRE_VARS (-1: none; the counting build's marks)
    18,
};
const int TRIAL_F_2[1] = {  // per entry of cost loop 2: its instance (-1: none)
    8,
};
const int TRIAL_X0_2[1] = {  // per entry, 1 a row: where each variable it takes goes in x
    12,
};
const int TRIAL_X1_2[1] = {  // and where it ends (x0 = x1: none)
    15,
};
const int TRIAL_AT_2[1] = {  // its place in RETIRE_VARS (-1: none; the counting build's marks)
    19,
};
const int TRIAL_F_3[1] = {  // per entry of cost loop 3: its instance (-1: none)
    9,
};
const int TRIAL_X0_3[1] = {  // per entry, 1 a row: where each variable it takes goes in x
    15,
};
const int TRIAL_X1_3[1] = {  // and where it ends (x0 = x1: none)
    21,
};
const int TRIAL_AT_3[1] = {  // its place in RETIRE_VARS (-1: none; the counting build's marks)
    20,
};
// trial_cost_b: back_substitute's fourth process (units/datapath.py's split_trial_loops), the
// datapaths after the one with the most work, fed their variables by a stream of their own
// (tx2: TRIAL_SEND), their instances' data lines from DATA_B, its own copy of DATA_BUF's words
// TRIAL_B_LO ... (the top's data copy writes both): no memory read by two processes
T TRIAL_COST_B = T(0);  // trial_cost_b's part of the cost
void trial_cost_a(hls::stream<TrialVar>& tx) {
#pragma HLS ARRAY_PARTITION variable=DATA_BUF cyclic factor=2
    FGC_OUTER_BRANCH();  // csim cycle counting only: the third process of back_substitute
    T x[N_X];  // the variables taken so far
    T total = T(0);
    // block 0 (CombinedImuFactor): 7 entries, one every II=72 cycles (the plan's)
    for (int e = 0; e < 7; ++e) {
#pragma HLS PIPELINE II=72
        for (int j = 0; j < 6; ++j) {  // the variables retired since, in order
            const int x0 = TRIAL_X0_0[e * 6 + j], x1 = TRIAL_X1_0[e * 6 + j];
            if (x0 < x1) {
                FGC_OUTER_ABSORB_AT(TRIAL_AT_0[e * 6 + j]);  // csim cycle counting: no earlier than it was sent
                const TrialVar t = tx.read();
                for (int w = 0; w < MAX_STORAGE; ++w) {
                    if (x0 + w < x1) x[x0 + w] = t.word[w];
                }
            }
        }
        const int f = TRIAL_F_0[e];
        if (f >= 0) {
        T in[42], dat[193], half[1];
        gather_trial_0(x, f, in, dat);
        factor_cost_0(in, dat, half);
        T cost = T(0);
        cost += half[0];  // no robust loss on this member (the Program's flag)
            total += cost;
        }
        FGC_CYCLES("trial_cost", 0, "cost_0", 1, 72, 598);
    }
    TRIAL_COST = total;
}

void trial_cost_b(hls::stream<TrialVar>& tx2) {
#pragma HLS ARRAY_PARTITION variable=DATA_B cyclic factor=2
    FGC_OUTER_BRANCH();  // csim cycle counting only: its fourth (trial_cost's second)
    T x[N_X];  // the variables taken so far
    T total = T(0);
    // block 1 (PriorFactorPose3): 1 entries, one every II=48 cycles (the plan's)
    for (int e = 0; e < 1; ++e) {
#pragma HLS PIPELINE II=48
        for (int j = 0; j < 1; ++j) {  // the variables retired since, in order
            const int x0 = TRIAL_X0_1[e * 1 + j], x1 = TRIAL_X1_1[e * 1 + j];
            if (x0 < x1) {
                FGC_OUTER_ABSORB_AT(TRIAL_AT_1[e * 1 + j]);  // csim cycle counting: no earlier than it was sent
                const TrialVar t = tx2.read();
                for (int w = 0; w < MAX_STORAGE; ++w) {
                    if (x0 + w < x1) x[x0 + w] = t.word[w];
                }
            }
        }
        const int f = TRIAL_F_1[e];
        if (f >= 0) {
        T in[12], dat[13], half_b[1];
        gather_trial_b_1(x, f, in, dat);
        factor_cost_1(in, dat, half_b);
        T cost = T(0);
        cost += half_b[0];  // no robust loss on this member (the Program's flag)
            total += cost;
        }
        FGC_CYCLES("trial_cost", 0, "cost_1", 1, 48, 379);
    }
    // block 2 (PriorFactorVector3): 1 entries, one every II=8 cycles (the plan's)
    for (int e = 0; e < 1; ++e) {
#pragma HLS PIPELINE II=8
        for (int j = 0; j < 1; ++j) {  // the variables retired since, in order
            const int x0 = TRIAL_X0_2[e * 1 + j], x1 = TRIAL_X1_2[e * 1 + j];
            if (x0 < x1) {
                FGC_OUTER_ABSORB_AT(TRIAL_AT_2[e * 1 + j]);  // csim cycle counting: no earlier than it was sent
                const TrialVar t = tx2.read();
                for (int w = 0; w < MAX_STORAGE; ++w) {
                    if (x0 + w < x1) x[x0 + w] = t.word[w];
                }
            }
        }
        const int f = TRIAL_F_2[e];
        if (f >= 0) {
        T in[3], dat[4], half_b[1];
        gather_trial_b_2(x, f, in, dat);
        factor_cost_2(in, dat, half_b);
        T cost = T(0);
        cost += half_b[0];  // no robust loss on this member (the Program's flag)
            total += cost;
        }
        FGC_CYCLES("trial_cost", 0, "cost_2", 1, 8, 20);
    }
    // block 3 (PriorFactorImuBias): 1 entries, one every II=9 cycles (the plan's)
    for (int e = 0; e < 1; ++e) {
#pragma HLS PIPELINE II=9
        for (int j = 0; j < 1; ++j) {  // the variables retired since, in order
            const int x0 = TRIAL_X0_3[e * 1 + j], x1 = TRIAL_X1_3[e * 1 + j];
            if (x0 < x1) {
                FGC_OUTER_ABSORB_AT(TRIAL_AT_3[e * 1 + j]);  // csim cycle counting: no earlier than it was sent
                const TrialVar t = tx2.read();
                for (int w = 0; w < MAX_STORAGE; ++w) {
                    if (x0 + w < x1) x[x0 + w] = t.word[w];
                }
            }
        }
        const int f = TRIAL_F_3[e];
        if (f >= 0) {
        T in[6], dat[7], half_b[1];
        gather_trial_b_3(x, f, in, dat);
        factor_cost_3(in, dat, half_b);
        T cost = T(0);
        cost += half_b[0];  // no robust loss on this member (the Program's flag)
            total += cost;
        }
        FGC_CYCLES("trial_cost", 0, "cost_3", 1, 9, 24);
    }
    TRIAL_COST_B = total;
}

// the cost at X_TRIAL (back_substitute's third process): trial_cost_a beside trial_cost_b
void trial_cost(hls::stream<TrialVar>& tx, hls::stream<TrialVar>& tx2) {
#pragma HLS DATAFLOW
    trial_cost_a(tx);
    trial_cost_b(tx2);
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
const int TRIAL_SEND[24] = {  // per variable the trial-cost processes it goes to (bit 0: trial_cost, 1: trial_cost_b)
    3, 3, 3, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1,
    1, 1, 1, 1, 1, 1, 1, 1,
};
// (at_x: no solve ran, X's words go to trial_cost for the cost at X). Its words go on to
// trial_cost (back_substitute's third process) as one stream word.
// With LM's step test here (retire_test): dd, dg, gm, fin, xx = the variable's delta^T delta,
// delta^T g, largest |g|, its delta finite and |x (+) delta|^2 (summed, maximised over the
// variables by the retire; at_x: delta taken as zero). The trial is held in X itself (fgc_lm.h's
// FGC_LM_TRIAL_IN_X): X's words backed up into X_BACK as they are read, x (+) delta written
// back in their place; G's read from G, moved to G_BACK and zeroed there (the next
// linearisation's HGC adds into zeros) by the first solve after a linearisation, read from
// G_BACK by LM's retries (G_MOVED). at_x writes nothing but the stream.
void retract_variable(int v, const L delta[N_TANGENT], bool at_x, hls::stream<TrialVar>& tx,
                      hls::stream<TrialVar>& tx2, T& dd, T& dg, T& gm, bool& fin, T& xx) {
    TrialVar out;
    for (int k = 0; k < MAX_STORAGE; ++k) out.word[k] = T(0);
    if (VAR_KIND[v] == 0) {
        T xv[12], dv[6], ov[12];
        for (int k = 0; k < 12; ++k) xv[k] = X[VAR_X_OFF[v] + k];
        for (int k = 0; k < 6; ++k) dv[k] = at_x ? T(0) : T(delta[VAR_T_OFF[v] + k]);
        retract_0(xv, dv, ov);
        T sd = T(0), sg = T(0), sm = T(0);
        bool ok = true;
        for (int k = 0; k < 6; ++k) {  // the step test's terms of v
            const int at = VAR_T_OFF[v] + k;
            const T gk = G_MOVED ? G_BACK[at] : G[at];
            if (!at_x) {
                G_BACK[at] = gk;
                G[at] = T(0);
            }
            ok = ok && fgc_isfinite(dv[k]);
            sd += dv[k] * dv[k];
            sg += dv[k] * gk;
            sm = fgc_abs(gk) > sm ? fgc_abs(gk) : sm;
        }
        dd = sd;
        dg = sg;
        gm = sm;
        fin = ok;
        T sx = T(0);
        for (int k = 0; k < 12; ++k) {
            const T o = at_x ? xv[k] : ov[k];
            if (!at_x) {
                X_BACK[VAR_X_OFF[v] + k] = xv[k];
                X[VAR_X_OFF[v] + k] = o;
            }
            sx += o * o;  // |x (+) delta|^2: the next linearisation's |X| if the step is taken
            out.word[k] = o;
        }
        xx = sx;
    } else if (VAR_KIND[v] == 1) {
        T xv[3], dv[3], ov[3];
        for (int k = 0; k < 3; ++k) xv[k] = X[VAR_X_OFF[v] + k];
        for (int k = 0; k < 3; ++k) dv[k] = at_x ? T(0) : T(delta[VAR_T_OFF[v] + k]);
        retract_1(xv, dv, ov);
        T sd = T(0), sg = T(0), sm = T(0);
        bool ok = true;
        for (int k = 0; k < 3; ++k) {  // the step test's terms of v
            const int at = VAR_T_OFF[v] + k;
            const T gk = G_MOVED ? G_BACK[at] : G[at];
            if (!at_x) {
                G_BACK[at] = gk;
                G[at] = T(0);
            }
            ok = ok && fgc_isfinite(dv[k]);
            sd += dv[k] * dv[k];
            sg += dv[k] * gk;
            sm = fgc_abs(gk) > sm ? fgc_abs(gk) : sm;
        }
        dd = sd;
        dg = sg;
        gm = sm;
        fin = ok;
        T sx = T(0);
        for (int k = 0; k < 3; ++k) {
            const T o = at_x ? xv[k] : ov[k];
            if (!at_x) {
                X_BACK[VAR_X_OFF[v] + k] = xv[k];
                X[VAR_X_OFF[v] + k] = o;
            }
            sx += o * o;  // |x (+) delta|^2: the next linearisation's |X| if the step is taken
            out.word[k] = o;
        }
        xx = sx;
    } else if (VAR_KIND[v] == 2) {
        T xv[6], dv[6], ov[6];
        for (int k = 0; k < 6; ++k) xv[k] = X[VAR_X_OFF[v] + k];
        for (int k = 0; k < 6; ++k) dv[k] = at_x ? T(0) : T(delta[VAR_T_OFF[v] + k]);
        retract_2(xv, dv, ov);
        T sd = T(0), sg = T(0), sm = T(0);
        bool ok = true;
        for (int k = 0; k < 6; ++k) {  // the step test's terms of v
            const int at = VAR_T_OFF[v] + k;
            const T gk = G_MOVED ? G_BACK[at] : G[at];
            if (!at_x) {
                G_BACK[at] = gk;
                G[at] = T(0);
            }
            ok = ok && fgc_isfinite(dv[k]);
            sd += dv[k] * dv[k];
            sg += dv[k] * gk;
            sm = fgc_abs(gk) > sm ? fgc_abs(gk) : sm;
        }
        dd = sd;
        dg = sg;
        gm = sm;
        fin = ok;
        T sx = T(0);
        for (int k = 0; k < 6; ++k) {
            const T o = at_x ? xv[k] : ov[k];
            if (!at_x) {
                X_BACK[VAR_X_OFF[v] + k] = xv[k];
                X[VAR_X_OFF[v] + k] = o;
            }
            sx += o * o;  // |x (+) delta|^2: the next linearisation's |X| if the step is taken
            out.word[k] = o;
        }
        xx = sx;
    }
    if (TRIAL_SEND[v] & 1) tx.write(out);  // to the cost processes whose instances read v
    if (TRIAL_SEND[v] & 2) tx2.write(out);
}

// ---- the linear solver's units: fixed headers (include/fgc_qr.h, fgc_cpe.h, fgc_backsub.h)
// configured by the constants below; what each DATAFLOW region holds is documented there.
// CFG::T is L, the linear solver's scalar; latencies are the plan's operator table for L.
// ---- the HGC beside the elimination: block 0's Grams (496 packed words each) streamed in step
// order; per factor its offset in a stage lane (-1: not streamed, its Gram in GRAM), per step its
// first streamed instance (in the stream's order) and how many
const int FACTOR_STAGE[10] = {
    0, 0, 0, 0, 0, 0, 0, -1, -1, -1,
};
const int STEP_STREAMED_FIRST[7] = {
    0, 1, 2, 3, 4, 5, 6,
};
const int STEP_STREAMED_COUNT[7] = {
    1, 1, 1, 1, 1, 1, 1,
};
struct LesConfig {
    typedef ::fgc::L T;
    static const int MAX_W = ::fgc::MAX_W;
    static const int MAX_COLS = ::fgc::MAX_W + 1;  // w + 1: frontal, separator, right-hand side
    static const int MAX_F = ::fgc::MAX_F;
    static const int N_CPE = ::fgc::N_CPE;
    static const int STREAM_WORDS = 1;  // --cascade-lanes: words a cycle through the cascade
    static const int N_COND = ::fgc::N_COND, N_NF = ::fgc::N_NF;  // the cascade's drain writes them
    static const bool LM = true;  // false: Gauss-Newton, no damping rows
    // fgc_eliminate.h's loops: the tables' largest trip counts, the plan's (II, depth) of L
    static const int MAX_STEP_FACTORS = 4, MAX_CHILDREN = 2;
    static const int TRIP_COND = 465;  // a conditional, PORTS words a cycle
    static const int TRIP_PACKED = 495;  // a packed Gram or update matrix
    static const int TRIP_UPDATE = 465;  // an update matrix, PORTS words a cycle
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
    typedef ::fgc::T TestT;  // the step test's sums (LM's scalar)
    static void retract_variable(int v, const T delta[N_TANGENT], bool at_x,
                                 hls::stream<::fgc::TrialVar>& tx, hls::stream<::fgc::TrialVar>& tx2,
                                 TestT& dd, TestT& dg, TestT& gm, bool& fin, TestT& xx) {
        ::fgc::retract_variable(v, delta, at_x, tx, tx2, dd, dg, gm, fin, xx);
    }
    static void retire_test(TestT dd, TestT dg, TestT gm, bool fin, TestT xx) {  // to LM's step test
        ::fgc::TRIAL_DD = dd;
        ::fgc::TRIAL_DG = dg;
        ::fgc::TRIAL_GMAX = gm;
        ::fgc::TRIAL_FINITE = fin;
        ::fgc::TRIAL_XX = xx;
    }
    // the HGC beside the elimination (fgc_eliminate.h's cholesky_eliminate_beside): block 0's
    // Grams come as a stream, a step's put into a stage lane by gram_source a pass before the
    // assembler reads them
    typedef GramWord Word;
    static const int N_STAGE = 496;  // a stage lane: the most streamed Grams of a step
    static int staged(int fac) { return FACTOR_STAGE[fac]; }
    static bool streams(int s) { return STEP_STREAMED_COUNT[s] > 0; }
    static int last_streamed(int s) { return STEP_STREAMED_FIRST[s] + STEP_STREAMED_COUNT[s] - 1; }
    static void gram_source(int s, bool relin, T lane[N_STAGE], hls::stream<Word>& grams);
};

// ---- multifrontal Cholesky (paper B): per step the frontal matrix [H | g] (upper triangle,
// row-major, the gradient in column w) from its factors' Grams and its children's update
// matrices, assembled into lane t % 2 of HA (the t-th step) while the cascade factors the step
// before (fgc_eliminate.h's cholesky_overlap region: cholesky_assembler -> cholesky_cascade, one
// stream); cpe_step runs the rounds of the #CPE cascade (one DATAFLOW region per round:
// cpe_feed (+ mu) -> cpe_tap<0>, cpe<0> ... cpe_tap<19>, cpe<19> -> cpe_drain, 80 streams:
// the drain reads the tail of the round's last pivot's CPE, the CPEs past it idle),
// whose drain writes the conditional into COND and the update matrix into NF.
L HA_L0[MAX_W][LesConfig::MAX_COLS / 2 + 1][2];  // the assembly's lane 0, (i, c) at [i][c >> 1][c & 1]; all zero between steps (the source clears what it reads)
L HA_L1[MAX_W][LesConfig::MAX_COLS / 2 + 1][2];  // its lane 1
L HF[MAX_W][LesConfig::MAX_COLS];  // the rows a round leaves for the next (multi-round steps); all zero between steps
// each step's pivot check in the next region's assembler (fgc_eliminate.h)
#define FGC_CHECK_BESIDE
L DPIV[2][MAX_F];  // the t-th step's pivots in [t % 2] (FGC_CHECK_BESIDE: the next region's assembler checks them)
L RMAX[2][MAX_F];  // its pivot rows' largest frontal |h|

// block 0's Gram entries' packed positions p (p + 1) / 2 + q, lane A's and lane B's (gram_entries_stream's order)
const int STREAMED_POS_A[248] = {
    189, 208, 209, 228, 229, 230, 249, 250, 251, 252, 258, 259, 260, 261, 262, 263,
    264, 265, 266, 267, 268, 269, 270, 271, 272, 273, 274, 275, 276, 277, 278, 279,
    280, 281, 282, 283, 284, 285, 286, 287, 288, 289, 290, 291, 292, 293, 294, 295,
    296, 297, 298, 299, 300, 301, 302, 303, 304, 305, 306, 307, 308, 309, 310, 311,
    312, 313, 314, 315, 316, 317, 318, 319, 320, 321, 322, 323, 324, 325, 326, 327,
    328, 329, 330, 331, 332, 333, 334, 335, 336, 337, 338, 339, 340, 341, 342, 343,
    344, 345, 346, 347, 348, 349, 350, 351, 352, 353, 354, 355, 356, 357, 358, 359,
    360, 361, 362, 363, 364, 365, 366, 367, 368, 369, 370, 371, 372, 373, 374, 375,
    376, 377, 378, 379, 380, 381, 382, 383, 384, 385, 386, 387, 388, 389, 390, 391,
    392, 393, 394, 395, 396, 397, 398, 399, 400, 401, 402, 403, 404, 405, 406, 407,
    408, 409, 410, 411, 412, 413, 414, 415, 416, 417, 418, 419, 420, 421, 422, 423,
    424, 425, 426, 427, 428, 429, 430, 431, 432, 433, 434, 435, 436, 437, 438, 439,
    440, 441, 442, 443, 444, 445, 446, 447, 448, 449, 450, 451, 452, 453, 454, 455,
    456, 457, 458, 459, 460, 461, 462, 463, 464, 465, 466, 467, 468, 469, 470, 471,
    472, 473, 474, 475, 476, 477, 478, 479, 480, 481, 482, 483, 484, 485, 486, 487,
    488, 489, 490, 491, 492, 493, 494, 495,
};
const int STREAMED_POS_B[248] = {
    0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15,
    16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31,
    32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47,
    48, 49, 50, 51, 52, 53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63,
    64, 65, 66, 67, 68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79,
    80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95,
    96, 97, 98, 99, 100, 101, 102, 103, 104, 105, 106, 107, 108, 109, 110, 111,
    112, 113, 114, 115, 116, 117, 118, 119, 120, 121, 122, 123, 124, 125, 126, 127,
    128, 129, 130, 131, 132, 133, 134, 135, 136, 137, 138, 139, 140, 141, 142, 143,
    144, 145, 146, 147, 148, 149, 150, 151, 152, 153, 154, 155, 156, 157, 158, 159,
    160, 161, 162, 163, 164, 165, 166, 167, 168, 169, 170, 171, 172, 173, 174, 175,
    176, 177, 178, 179, 180, 181, 182, 183, 184, 185, 186, 187, 188, 190, 191, 192,
    193, 194, 195, 196, 197, 198, 199, 200, 201, 202, 203, 204, 205, 206, 207, 210,
    211, 212, 213, 214, 215, 216, 217, 218, 219, 220, 221, 222, 223, 224, 225, 226,
    227, 231, 232, 233, 234, 235, 236, 237, 238, 239, 240, 241, 242, 243, 244, 245,
    246, 247, 248, 253, 254, 255, 256, 257,
};
L STAGE[2][LesConfig::N_STAGE];  // the stage lanes: step t's streamed Grams in STAGE[t % 2] (structural zeros never written)
L GRAM_B[3472];  // the streamed Grams kept for LM's retries (instance k's at k x 496)

// The Gram source (a process of each cholesky_overlap_beside pass): step s's streamed Grams into
// `lane`. relin: from the stream, a word an iteration of reduce_0's loop at its II (1), each
// entry also into GRAM_B; else from GRAM_B, two words a cycle (its two ports and the lane's).
void LesConfig::gram_source(int s, bool relin, T lane[N_STAGE], hls::stream<Word>& grams) {
    const int k0 = STEP_STREAMED_FIRST[s], n = STEP_STREAMED_COUNT[s];
    if (relin) {
        for (int t = 0, j = 0, e = 0; t < n * 248; ++t) {
#pragma HLS LOOP_TRIPCOUNT max=248
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=lane inter false
#pragma HLS DEPENDENCE variable=GRAM_B inter false
            const Word w = grams.read();
            for (int h = 0; h < 1; ++h) {
                if (1 * e + h < 248) {
                    const int pos = STREAMED_POS_A[1 * e + h];
                    lane[j * 496 + pos] = w.v[h];
                    GRAM_B[(k0 + j) * 496 + pos] = w.v[h];
                }
            }
            if (e < 248) {
                const int pos = STREAMED_POS_B[e];
                lane[j * 496 + pos] = w.v[1];
                GRAM_B[(k0 + j) * 496 + pos] = w.v[1];
            }
            if (++e == 248) {
                e = 0;
                ++j;
            }
        }
        FGC_CYCLES("gram_source", 0, "stream", n * 248, 1, MOVE_DEPTH);
    } else {
        for (int t = 0; t < n * 496; t += 2) {  // two words a cycle
#pragma HLS LOOP_TRIPCOUNT max=248
#pragma HLS PIPELINE II=1
            for (int h = 0; h < 2; ++h) {
                if (t + h < n * 496) lane[t + h] = GRAM_B[k0 * 496 + t + h];
            }
        }
        FGC_CYCLES("gram_source", 0, "kept", (n * 496 + 1) / 2, MOVE_II, MOVE_DEPTH);
    }
}

// the elimination driver (fgc_eliminate.h) on these tables and memories
#define FGC_ELIMINATE_CHOLESKY
#define FGC_ELIMINATE_BESIDE
#include "fgc_eliminate.h"

// The linearisation's block 0 beside the elimination, one DATAFLOW region: produce_0 (its
// instances in step order, their Grams into `grams`, the gradient into G) alongside
// cholesky_eliminate_beside (which takes them from the stream as its steps need them). relin
// false: LM's retry at a raised mu, the Grams from GRAM_B (the producer idle).
void linearize_solve(T mu, bool relin, bool& finite, bool& solved) {
#pragma HLS DATAFLOW
    hls::stream<GramWord> grams;
#pragma HLS STREAM variable=grams depth=248
    FGC_PHASE(relin ? "hgc_beside" : "reassemble");
    FGC_BESIDE_PRODUCER();  // csim only: the producer's records, then the consumer's
    produce_0(X, relin ? 7 : 0, grams, finite);
    FGC_SEQUENTIAL();
    FGC_BESIDE_CONSUMER();
    cholesky_eliminate_beside<LesConfig>(mu, relin, grams, solved);
    FGC_BESIDE_END();
    FGC_DRAINED(&grams, 1);
}

bool BESIDE_PENDING = false;  // the linearisation's first solve was factored beside it
bool BESIDE_SOLVED = false;   // and its result (false: not positive definite)

// LM's hook linearize_x(mu): the other block types' regions (linearize_all), then block 0
// beside the factorisation at mu, whose result the next solve takes. False if not finite.
bool linearize_beside(T mu) {
#pragma HLS INLINE
    const bool finite = linearize_all(X);
    bool fin = true, solved = false;
    linearize_solve(mu, true, fin, solved);
    BESIDE_PENDING = true;
    BESIDE_SOLVED = solved;
    return finite && fin;
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
// the state update forms LM's step test (backsub_retire_cols: LesConfig's retire_test)
#define FGC_BS_STEP_TEST 1
// the cost at X_TRIAL in two processes (trial_cost, trial_cost_b: units/datapath.py's split_trial_loops)
#define FGC_BS_TRIAL_B 1
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

// The linear solve at mu: the factorisation linearize_beside ran (the first solve of a
// linearisation) or linearize_solve on the kept Grams (LM's retry), then back-substitute, the
// cost at X_TRIAL beside it (trial_cost). False if singular. at_x: no solve, back_substitute's
// cost pass at X (LM control's cost_x; the linearisation LM has pending is left as it is).
bool solve(T mu, bool at_x) {
#pragma HLS INLINE
    if (at_x) {
        back_substitute_at(true);
        return true;
    }
    FGC_EVENT("solve");
    bool solved = BESIDE_SOLVED;
    if (BESIDE_PENDING) {
        BESIDE_PENDING = false;
    } else {
        FGC_EVENT("resolve");
        bool fin = true;
        linearize_solve(mu, false, fin, solved);
    }
    if (!solved) return false;  // a failed solve back-substitutes nothing
    FGC_EVENT("backsub");
    back_substitute_at(false);
    G_MOVED = true;  // (its state update moved G to G_BACK)
    return true;
}

// ---- LM control (paper B): the rules in fgc_lm.h (shared with the native solver), its
// reductions in fgc_lm_units.h (interleaved partial sums at II 1); here the kernel's constants
// and hooks. fgc_lm::optimize<LmConfig>: GN/LM iterations from X.
T LM_XX = T(0);  // |X|^2: the top's x copy forms it, then the state update of each step taken
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
        return TRIAL_COST + TRIAL_COST_B;
    }
    // INLINE: the on-chip stream's kernels share linearize_all / eliminate_all between LM and
    // their own calls after it (fgc_stream.h's ALLOCATION, LM's body inlined there); the HGC
    // beside the elimination's hooks share linearize_solve (fgc_lm.h's ALLOCATION)
    static bool linearize_x(T mu) {
#pragma HLS INLINE
        return linearize_beside(mu);
    }
    static bool solve_at(T mu) {
        #pragma HLS INLINE
        return solve(mu, false);
    }
    static void retract_trial() {}  // X (+) DELTA: written into X by back_substitute's backsub_retire (X_BACK: X)
    static T cost_trial() {
        return TRIAL_COST + TRIAL_COST_B;  // trial_cost's, beside the solve's back-substitution
    }
    static T noise_x() { return rounding_noise_all(X_BACK); }
    static const int N_X = ::fgc::N_X, N_TANGENT = ::fgc::N_TANGENT;
    static const int PARTIALS = T_PARTIALS, ADD_LAT = T_ADD_LAT, MUL_LAT = T_MUL_LAT;
    static const int MAXIMA = T_MAXIMA, CMP_LAT = T_CMP_LAT, ABS_LAT = T_ABS_LAT;
    static const int MOVE_II = 1, MOVE_DEPTH = 2;
    static const int N_DATA = ::fgc::N_DATA;
    static const int DECISION_II = 1, DECISION_DEPTH = 30;
    static T x_norm() { return root(LM_XX); }  // |X|: the copies into X sum |X|^2
    static T linearized_cost() { return T(0.5) * LIN_SQ; }  // the cost at X, from the HGC's b^T b
    // the step test's sums from back_substitute's state update, |X| from the copies into X
    static bool step_test(bool solved, T mu, T out[2]) {
#pragma HLS INLINE
        return fgc_units::lm_step_sums<LmConfig>(solved, mu, TRIAL_DD, TRIAL_DG, TRIAL_FINITE, out);
    }
    static T solved_gradient_max() { return TRIAL_GMAX; }  // the solve's state update's
    static T gradient_max() {  // no solve of the linearisation succeeded: before LM gives up
#pragma HLS INLINE
        return fgc_units::lm_gradient_max<LmConfig>(G);
    }
    static void data_word(int i, T v) {  // trial_cost_b's copy of its lines (DATA_B)
#pragma HLS INLINE
        const int j = i - TRIAL_B_LO;
        if (j >= 0 && j < TRIAL_B_WORDS) DATA_B[j] = v;
    }
    static void accept_trial() {  // X holds x (+) delta already: its |X|^2, the state update's
#pragma HLS INLINE
        FGC_EVENT("accept");
        LM_XX = TRIAL_XX;
    }
    static void restore_x() {  // the trial not taken: X back from X_BACK (fgc_lm.h's FGC_LM_TRIAL_IN_X)
#pragma HLS INLINE
        fgc_units::lm_restore<LmConfig>(X, X_BACK);
    }
    static void accepted(int, T, T, T) {}  // no host to tell on chip
};

}  // namespace
}  // namespace fgc

void imu_window_top(const fgc::T x_in[fgc::N_X], const fgc::T data[fgc::N_DATA],
                    fgc::T x_out[fgc::N_X], fgc::T errors[2], int info[3]) {
#pragma HLS INTERFACE m_axi port=x_in offset=slave bundle=gmem0 depth=168
#pragma HLS INTERFACE m_axi port=data offset=slave bundle=gmem1 depth=1395
#pragma HLS INTERFACE m_axi port=x_out offset=slave bundle=gmem0 depth=168
#pragma HLS INTERFACE s_axilite port=errors
#pragma HLS INTERFACE s_axilite port=info
#pragma HLS INTERFACE s_axilite port=return
    fgc_units::lm_top_norm<fgc::LmConfig>(x_in, data, x_out, fgc::X, fgc::DATA_BUF, fgc::G, fgc::LM_XX, errors, info);
}
