// generated from template kernel.cpp.jinja by fgc 0.1.0 — do not edit
// Problem: lio
// chain graph, two-ended ordering; solver: lm qr auto n_u=4 cpe=20
//
// A CPU program, not a hardware design (fgc_backends.native): built with the host compiler as a
// shared library, with SIMD lanes and host-only paths; g++ ignores the `#pragma HLS` lines, which
// stay only while the HLS backend renders this template too.
//
// Dataflow of one Levenberg-Marquardt iteration:
//   factor blocks (residual + Jacobian mode) -> whitened rows [A | b] per factor instance
//   -> elimination steps along the schedule (partial QR: Evaluate + Update units), level by level,
//      2 unit set(s) side by side -> conditionals (R | d) per step
//   -> back-substitution root first -> retraction x (+) delta -> factor blocks (cost mode) -> accept?
//   (a step that does not lower the cost is judged against the cost's rounding noise at x: the
//   factor blocks in noise mode, once per iteration that needs it)
#include "lio.h"

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
const int STEP_PATTERN[7] = {
    -1, -1, 0, 1, 0, 1, -1,
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
const int PATTERN0_PLAN[952] = {  // per column: n, then the n rows it reflects
    17, 0, 1, 2, 3, 4, 5, 6, 7, 8, 15, 16, 17, 18, 19, 20,
    24, 39, 18, 1, 2, 3, 4, 5, 6, 7, 8, 15, 16, 17, 18, 19,
    20, 24, 25, 39, 40, 19, 2, 3, 4, 5, 6, 7, 8, 15, 16, 17,
    18, 19, 20, 24, 25, 26, 39, 40, 41, 23, 3, 4, 5, 6, 7, 8,
    15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 39, 40, 41,
    42, 24, 4, 5, 6, 7, 8, 15, 16, 17, 18, 19, 20, 21, 22, 23,
    24, 25, 26, 27, 28, 39, 40, 41, 42, 43, 25, 5, 6, 7, 8, 15,
    16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 39, 40,
    41, 42, 43, 44, 26, 6, 7, 8, 15, 16, 17, 18, 19, 20, 21, 22,
    23, 24, 25, 26, 27, 28, 29, 30, 39, 40, 41, 42, 43, 44, 45, 27,
    7, 8, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28,
    29, 30, 31, 39, 40, 41, 42, 43, 44, 45, 46, 28, 8, 15, 16, 17,
    18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 39,
    40, 41, 42, 43, 44, 45, 46, 47, 30, 9, 15, 16, 17, 18, 19, 20,
    21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 39, 40, 41,
    42, 43, 44, 45, 46, 47, 48, 32, 10, 15, 16, 17, 18, 19, 20, 21,
    22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 39, 40, 41,
    42, 43, 44, 45, 46, 47, 48, 49, 34, 11, 15, 16, 17, 18, 19, 20,
    21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 39,
    40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 36, 12, 15, 16, 17,
    18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33,
    34, 35, 36, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51,
    38, 13, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28,
    29, 30, 31, 32, 33, 34, 35, 36, 37, 39, 40, 41, 42, 43, 44, 45,
    46, 47, 48, 49, 50, 51, 52, 40, 14, 15, 16, 17, 18, 19, 20, 21,
    22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37,
    38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53,
    39, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29,
    30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45,
    46, 47, 48, 49, 50, 51, 52, 53, 38, 16, 17, 18, 19, 20, 21, 22,
    23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38,
    39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 37,
    17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32,
    33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48,
    49, 50, 51, 52, 53, 36, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27,
    28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43,
    44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 35, 19, 20, 21, 22, 23,
    24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39,
    40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 34, 20,
    21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36,
    37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52,
    53, 33, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34,
    35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50,
    51, 52, 53, 32, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33,
    34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49,
    50, 51, 52, 53, 31, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33,
    34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49,
    50, 51, 52, 53, 30, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34,
    35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50,
    51, 52, 53, 29, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36,
    37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52,
    53, 28, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39,
    40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 27, 27,
    28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43,
    44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 26, 28, 29, 30, 31, 32,
    33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48,
    49, 50, 51, 52, 53, 25, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38,
    39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 24,
    30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45,
    46, 47, 48, 49, 50, 51, 52, 53,
};
const int PATTERN1_PLAN[952] = {  // per column: n, then the n rows it reflects
    17, 0, 1, 2, 3, 4, 5, 6, 7, 8, 15, 16, 17, 18, 19, 20,
    24, 39, 18, 1, 2, 3, 4, 5, 6, 7, 8, 15, 16, 17, 18, 19,
    20, 24, 25, 39, 40, 19, 2, 3, 4, 5, 6, 7, 8, 15, 16, 17,
    18, 19, 20, 24, 25, 26, 39, 40, 41, 23, 3, 4, 5, 6, 7, 8,
    15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 39, 40, 41,
    42, 24, 4, 5, 6, 7, 8, 15, 16, 17, 18, 19, 20, 21, 22, 23,
    24, 25, 26, 27, 28, 39, 40, 41, 42, 43, 25, 5, 6, 7, 8, 15,
    16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 39, 40,
    41, 42, 43, 44, 26, 6, 7, 8, 15, 16, 17, 18, 19, 20, 21, 22,
    23, 24, 25, 26, 27, 28, 29, 30, 39, 40, 41, 42, 43, 44, 45, 27,
    7, 8, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28,
    29, 30, 31, 39, 40, 41, 42, 43, 44, 45, 46, 28, 8, 15, 16, 17,
    18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 39,
    40, 41, 42, 43, 44, 45, 46, 47, 30, 9, 15, 16, 17, 18, 19, 20,
    21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 39, 40, 41,
    42, 43, 44, 45, 46, 47, 48, 32, 10, 15, 16, 17, 18, 19, 20, 21,
    22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 39, 40, 41,
    42, 43, 44, 45, 46, 47, 48, 49, 34, 11, 15, 16, 17, 18, 19, 20,
    21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 39,
    40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 36, 12, 15, 16, 17,
    18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33,
    34, 35, 36, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51,
    38, 13, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28,
    29, 30, 31, 32, 33, 34, 35, 36, 37, 39, 40, 41, 42, 43, 44, 45,
    46, 47, 48, 49, 50, 51, 52, 40, 14, 15, 16, 17, 18, 19, 20, 21,
    22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37,
    38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53,
    39, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29,
    30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45,
    46, 47, 48, 49, 50, 51, 52, 53, 38, 16, 17, 18, 19, 20, 21, 22,
    23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38,
    39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 37,
    17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32,
    33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48,
    49, 50, 51, 52, 53, 36, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27,
    28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43,
    44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 35, 19, 20, 21, 22, 23,
    24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39,
    40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 34, 20,
    21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36,
    37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52,
    53, 33, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34,
    35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50,
    51, 52, 53, 32, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33,
    34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49,
    50, 51, 52, 53, 31, 23, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33,
    34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49,
    50, 51, 52, 53, 30, 24, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34,
    35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50,
    51, 52, 53, 29, 25, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36,
    37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52,
    53, 28, 26, 27, 28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39,
    40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 27, 27,
    28, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43,
    44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 26, 28, 29, 30, 31, 32,
    33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45, 46, 47, 48,
    49, 50, 51, 52, 53, 25, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38,
    39, 40, 41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 24,
    30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40, 41, 42, 43, 44, 45,
    46, 47, 48, 49, 50, 51, 52, 53,
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
// block 0: PriorFactorPose3 (6 rows, 6 columns, 1 instances)
void jacobian_0(const V* in, const V* dat, T ab[LANES][48]) {
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

void cost_0(const V* in, const V* dat, T half[LANES][1]) {
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
    const V t61 = (T(0.5))*t19*(dat[12]*dat[12]) + (T(0.5))*t21*(dat[13]*dat[13]) + (T(0.5))*t23*(dat[14]*dat[14]) + (T(0.5))*(t46*t46)*(dat[15]*dat[15]) + (T(0.5))*(t55*t55)*(dat[16]*dat[16]) + (T(0.5))*(t60*t60)*(dat[17]*dat[17]);
    const V o0 = t61;
    for (int l = 0; l < LANES; ++l) {
        half[l][0] = lane(o0, l);
    }
}

// block 1: PriorFactorVector3 (3 rows, 3 columns, 1 instances)
void jacobian_1(const V* in, const V* dat, T ab[LANES][12]) {
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

void cost_1(const V* in, const V* dat, T half[LANES][1]) {
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

// block 2: PriorFactorImuBias (6 rows, 6 columns, 1 instances)
void jacobian_2(const V* in, const V* dat, T ab[LANES][48]) {
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

void cost_2(const V* in, const V* dat, T half[LANES][1]) {
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

// block 3: CombinedImuFactor+LidarOdometryFactor (21 rows, 30 columns, 7 instances)
void jacobian_3(const V* in, const V* dat, T ab[LANES][672]) {
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
    const V t97 = t21*t8;
    const V t98 = t21*t10;
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
    const V t119 = t97*t10 + t105*t72;
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
    const V t203 = in[9] - in[24];
    const V t204 = -in[15];
    const V t205 = -in[16];
    const V t206 = -in[17];
    const V t207 = in[10] - in[25];
    const V t208 = -in[18];
    const V t209 = -in[19];
    const V t210 = -in[20];
    const V t211 = in[11] - in[26];
    const V t212 = -in[21];
    const V t213 = -in[22];
    const V t214 = -in[23];
    const V t215 = t0*dat[18] + t1*dat[19] + t2*dat[20] + t3*dat[45] + t4*dat[46] + t5*dat[47] + dat[3];
    const V t216 = t0*dat[21] + t1*dat[22] + t2*dat[23] + t3*dat[48] + t4*dat[49] + t5*dat[50] + dat[4];
    const V t217 = t0*dat[24] + t1*dat[25] + t2*dat[26] + t3*dat[51] + t4*dat[52] + t5*dat[53] + dat[5];
    const V t218 = (T(0.5))*(dat[69]*dat[69]);
    const V t219 = t203 + t215*in[0] + t216*in[1] + t217*in[2] + t218*dat[70] + dat[69]*in[12];
    const V t220 = t207 + t215*in[3] + t216*in[4] + t217*in[5] + t218*dat[71] + dat[69]*in[13];
    const V t221 = t211 + t215*in[6] + t216*in[7] + t217*in[8] + t218*dat[72] + dat[69]*in[14];
    const V t222 = t219*in[15] + t220*in[18] + t221*in[21];
    const V t223 = t219*in[17] + t220*in[20] + t221*in[23];
    const V t224 = t219*in[16] + t220*in[19] + t221*in[22];
    const V t225 = -t198 - t200;
    const V t226 = t57;
    const V t227 = t68;
    const V t228 = t107*t226 + t110*t227;
    const V t229 = t113*t226 + t114*t227;
    const V t230 = t117*t227 + t119*t226;
    const V t231 = t71;
    const V t232 = t102;
    const V t233 = t107*t231 + t110*t232;
    const V t234 = t113*t231 + t114*t232;
    const V t235 = t117*t232 + t119*t231;
    const V t236 = t69;
    const V t237 = t66;
    const V t238 = t107*t236 + t110*t237;
    const V t239 = t113*t236 + t114*t237;
    const V t240 = t117*t237 + t119*t236;
    const V t241 = t147*t229 + t152*t230 + t155*t233 + t156*t234 + t157*t235 + t158*t238 + t159*t239 + t160*t240 + t161*t228;
    const V t242 = t196*t241;
    const V t243 = v_lie_D(t201);
    const V t244 = t243*t242;
    const V t245 = t58;
    const V t246 = t56;
    const V t247 = t103*t245 + t110*t246;
    const V t248 = t114*t246 + t115*t245;
    const V t249 = t117*t246 + t118*t245;
    const V t250 = t100;
    const V t251 = t62;
    const V t252 = t103*t250 + t110*t251;
    const V t253 = t114*t251 + t115*t250;
    const V t254 = t117*t251 + t118*t250;
    const V t255 = t70;
    const V t256 = t60;
    const V t257 = t103*t255 + t110*t256;
    const V t258 = t114*t256 + t115*t255;
    const V t259 = t117*t256 + t118*t255;
    const V t260 = t147*t248 + t152*t249 + t155*t252 + t156*t253 + t157*t254 + t158*t257 + t159*t258 + t160*t259 + t161*t247;
    const V t261 = t196*t260;
    const V t262 = t243*t261;
    const V t263 = t59;
    const V t264 = t64;
    const V t265 = t103*t263 + t107*t264;
    const V t266 = t113*t264 + t115*t263;
    const V t267 = t118*t263 + t119*t264;
    const V t268 = t67;
    const V t269 = t101;
    const V t270 = t103*t268 + t107*t269;
    const V t271 = t113*t269 + t115*t268;
    const V t272 = t118*t268 + t119*t269;
    const V t273 = t65;
    const V t274 = t61;
    const V t275 = t103*t273 + t107*t274;
    const V t276 = t113*t274 + t115*t273;
    const V t277 = t118*t273 + t119*t274;
    const V t278 = t147*t266 + t152*t267 + t155*t270 + t156*t271 + t157*t272 + t158*t275 + t159*t276 + t160*t277 + t161*t265;
    const V t279 = t196*t278;
    const V t280 = t243*t279;
    const V t281 = t60;
    const V t282 = t65;
    const V t283 = t69;
    const V t284 = t103*t281 + t107*t282 + t110*t283;
    const V t285 = t113*t282 + t114*t283 + t115*t281;
    const V t286 = t117*t283 + t118*t281 + t119*t282;
    const V t287 = t101;
    const V t288 = t102;
    const V t289 = t100;
    const V t290 = t103*t287 + t107*t288 + t110*t289;
    const V t291 = t113*t288 + t114*t289 + t115*t287;
    const V t292 = t117*t289 + t118*t287 + t119*t288;
    const V t293 = t155*t284 + t156*t285 + t157*t286 + t158*t290 + t159*t291 + t160*t292;
    const V t294 = t196*t293;
    const V t295 = t243*t294;
    const V t296 = t61;
    const V t297 = t66;
    const V t298 = t70;
    const V t299 = t103*t296 + t107*t297 + t110*t298;
    const V t300 = t113*t297 + t114*t298 + t115*t296;
    const V t301 = t117*t298 + t118*t296 + t119*t297;
    const V t302 = t56;
    const V t303 = t59;
    const V t304 = t57;
    const V t305 = t103*t302 + t107*t303 + t110*t304;
    const V t306 = t113*t303 + t114*t304 + t115*t302;
    const V t307 = t117*t304 + t118*t302 + t119*t303;
    const V t308 = t147*t300 + t152*t301 + t158*t305 + t159*t306 + t160*t307 + t161*t299;
    const V t309 = t196*t308;
    const V t310 = t243*t309;
    const V t311 = t62;
    const V t312 = t67;
    const V t313 = t71;
    const V t314 = t103*t311 + t107*t312 + t110*t313;
    const V t315 = t113*t312 + t114*t313 + t115*t311;
    const V t316 = t117*t313 + t118*t311 + t119*t312;
    const V t317 = t64;
    const V t318 = t68;
    const V t319 = t58;
    const V t320 = t103*t317 + t107*t318 + t110*t319;
    const V t321 = t113*t318 + t114*t319 + t115*t317;
    const V t322 = t117*t319 + t118*t317 + t119*t318;
    const V t323 = t147*t315 + t152*t316 + t155*t320 + t156*t321 + t157*t322 + t161*t314;
    const V t324 = t196*t323;
    const V t325 = t243*t324;
    const V t326 = t7*dat[9] + t9*dat[12] + t11*dat[15];
    const V t327 = t13*t326;
    const V t328 = t18*t327 + t22 + t25;
    const V t329 = t63*t326;
    const V t330 = t21*t23 + t14*t327;
    const V t331 = t105*dat[15] + t72*t330 + t106*t75 + t10*t329;
    const V t332 = t6*t327 + t21*dat[9];
    const V t333 = t105*t23 + t109*dat[15] + t14*t329 + t10*t332;
    const V t334 = t104*t328 + t108*t331 + t111*t333;
    const V t335 = t74*t327 + t77 + t22;
    const V t336 = t16*t330 + t6*t329 + t105*dat[9] + t106*t19;
    const V t337 = t16*t329 + t105*t19 + t109*dat[12] + t8*t332;
    const V t338 = t104*t337 + t108*t335 + t111*t336;
    const V t339 = t77 + t93*t327 + t25;
    const V t340 = t94*t75 + t95*t327 + t96*t19 + t105*dat[12] + t8*t329;
    const V t341 = t97*dat[15] + t98*dat[12] + t99*t327 + t105*t75 + t72*t329;
    const V t342 = t104*t340 + t108*t341 + t111*t339;
    const V t343 = t121*t328 + t122*t331 + t123*t333;
    const V t344 = t121*t337 + t122*t335 + t123*t336;
    const V t345 = t121*t340 + t122*t341 + t123*t339;
    const V t346 = t127*t328 + t128*t331 + t129*t333;
    const V t347 = t127*t337 + t128*t335 + t129*t336;
    const V t348 = t127*t340 + t128*t341 + t129*t339;
    const V t349 = t147*t338 + t152*t342 + t155*t343 + t156*t344 + t157*t345 + t158*t346 + t159*t347 + t160*t348 + t161*t334;
    const V t350 = t196*t349;
    const V t351 = t243*t350;
    const V t352 = t7*dat[10] + t9*dat[13] + t11*dat[16];
    const V t353 = t13*t352;
    const V t354 = t18*t353 + t28 + t31;
    const V t355 = t63*t352;
    const V t356 = t21*t29 + t14*t353;
    const V t357 = t105*dat[16] + t72*t356 + t106*t78 + t10*t355;
    const V t358 = t6*t353 + t21*dat[10];
    const V t359 = t105*t29 + t109*dat[16] + t14*t355 + t10*t358;
    const V t360 = t104*t354 + t108*t357 + t111*t359;
    const V t361 = t74*t353 + t80 + t28;
    const V t362 = t16*t356 + t6*t355 + t105*dat[10] + t106*t26;
    const V t363 = t16*t355 + t105*t26 + t109*dat[13] + t8*t358;
    const V t364 = t104*t363 + t108*t361 + t111*t362;
    const V t365 = t80 + t93*t353 + t31;
    const V t366 = t94*t78 + t95*t353 + t96*t26 + t105*dat[13] + t8*t355;
    const V t367 = t97*dat[16] + t98*dat[13] + t99*t353 + t105*t78 + t72*t355;
    const V t368 = t104*t366 + t108*t367 + t111*t365;
    const V t369 = t121*t354 + t122*t357 + t123*t359;
    const V t370 = t121*t363 + t122*t361 + t123*t362;
    const V t371 = t121*t366 + t122*t367 + t123*t365;
    const V t372 = t127*t354 + t128*t357 + t129*t359;
    const V t373 = t127*t363 + t128*t361 + t129*t362;
    const V t374 = t127*t366 + t128*t367 + t129*t365;
    const V t375 = t147*t364 + t152*t368 + t155*t369 + t156*t370 + t157*t371 + t158*t372 + t159*t373 + t160*t374 + t161*t360;
    const V t376 = t196*t375;
    const V t377 = t243*t376;
    const V t378 = t7*dat[11] + t9*dat[14] + t11*dat[17];
    const V t379 = t13*t378;
    const V t380 = t37 + t18*t379 + t34;
    const V t381 = t63*t378;
    const V t382 = t21*t35 + t14*t379;
    const V t383 = t105*dat[17] + t72*t382 + t106*t81 + t10*t381;
    const V t384 = t6*t379 + t21*dat[11];
    const V t385 = t105*t35 + t109*dat[17] + t14*t381 + t10*t384;
    const V t386 = t104*t380 + t108*t383 + t111*t385;
    const V t387 = t74*t379 + t83 + t34;
    const V t388 = t16*t382 + t6*t381 + t105*dat[11] + t106*t32;
    const V t389 = t16*t381 + t105*t32 + t109*dat[14] + t8*t384;
    const V t390 = t104*t389 + t108*t387 + t111*t388;
    const V t391 = t37 + t83 + t93*t379;
    const V t392 = t94*t81 + t95*t379 + t96*t32 + t105*dat[14] + t8*t381;
    const V t393 = t97*dat[17] + t98*dat[14] + t99*t379 + t105*t81 + t72*t381;
    const V t394 = t104*t392 + t108*t393 + t111*t391;
    const V t395 = t121*t380 + t122*t383 + t123*t385;
    const V t396 = t121*t389 + t122*t387 + t123*t388;
    const V t397 = t121*t392 + t122*t393 + t123*t391;
    const V t398 = t127*t380 + t128*t383 + t129*t385;
    const V t399 = t127*t389 + t128*t387 + t129*t388;
    const V t400 = t127*t392 + t128*t393 + t129*t391;
    const V t401 = t147*t390 + t152*t394 + t155*t395 + t156*t396 + t157*t397 + t158*t398 + t159*t399 + t160*t400 + t161*t386;
    const V t402 = t196*t401;
    const V t403 = t243*t402;
    const V t404 = t7*dat[36] + t9*dat[39] + t11*dat[42];
    const V t405 = t13*t404;
    const V t406 = t40 + t43 + t18*t405;
    const V t407 = t63*t404;
    const V t408 = t21*t41 + t14*t405;
    const V t409 = t105*dat[42] + t72*t408 + t106*t84 + t10*t407;
    const V t410 = t6*t405 + t21*dat[36];
    const V t411 = t105*t41 + t109*dat[42] + t14*t407 + t10*t410;
    const V t412 = t104*t406 + t108*t409 + t111*t411;
    const V t413 = t40 + t74*t405 + t86;
    const V t414 = t16*t408 + t6*t407 + t105*dat[36] + t106*t38;
    const V t415 = t16*t407 + t105*t38 + t109*dat[39] + t8*t410;
    const V t416 = t104*t415 + t108*t413 + t111*t414;
    const V t417 = t43 + t86 + t93*t405;
    const V t418 = t94*t84 + t95*t405 + t96*t38 + t105*dat[39] + t8*t407;
    const V t419 = t97*dat[42] + t98*dat[39] + t99*t405 + t105*t84 + t72*t407;
    const V t420 = t104*t418 + t108*t419 + t111*t417;
    const V t421 = t121*t406 + t122*t409 + t123*t411;
    const V t422 = t121*t415 + t122*t413 + t123*t414;
    const V t423 = t121*t418 + t122*t419 + t123*t417;
    const V t424 = t127*t406 + t128*t409 + t129*t411;
    const V t425 = t127*t415 + t128*t413 + t129*t414;
    const V t426 = t127*t418 + t128*t419 + t129*t417;
    const V t427 = t147*t416 + t152*t420 + t155*t421 + t156*t422 + t157*t423 + t158*t424 + t159*t425 + t160*t426 + t161*t412;
    const V t428 = t196*t427;
    const V t429 = t243*t428;
    const V t430 = t7*dat[37] + t9*dat[40] + t11*dat[43];
    const V t431 = t13*t430;
    const V t432 = t46 + t49 + t18*t431;
    const V t433 = t63*t430;
    const V t434 = t21*t44 + t14*t431;
    const V t435 = t105*dat[43] + t72*t434 + t106*t87 + t10*t433;
    const V t436 = t6*t431 + t21*dat[37];
    const V t437 = t105*t44 + t109*dat[43] + t14*t433 + t10*t436;
    const V t438 = t104*t432 + t108*t435 + t111*t437;
    const V t439 = t49 + t74*t431 + t89;
    const V t440 = t16*t434 + t6*t433 + t105*dat[37] + t106*t47;
    const V t441 = t16*t433 + t105*t47 + t109*dat[40] + t8*t436;
    const V t442 = t104*t441 + t108*t439 + t111*t440;
    const V t443 = t46 + t89 + t93*t431;
    const V t444 = t94*t87 + t95*t431 + t96*t47 + t105*dat[40] + t8*t433;
    const V t445 = t97*dat[43] + t98*dat[40] + t99*t431 + t105*t87 + t72*t433;
    const V t446 = t104*t444 + t108*t445 + t111*t443;
    const V t447 = t121*t432 + t122*t435 + t123*t437;
    const V t448 = t121*t441 + t122*t439 + t123*t440;
    const V t449 = t121*t444 + t122*t445 + t123*t443;
    const V t450 = t127*t432 + t128*t435 + t129*t437;
    const V t451 = t127*t441 + t128*t439 + t129*t440;
    const V t452 = t127*t444 + t128*t445 + t129*t443;
    const V t453 = t147*t442 + t152*t446 + t155*t447 + t156*t448 + t157*t449 + t158*t450 + t159*t451 + t160*t452 + t161*t438;
    const V t454 = t196*t453;
    const V t455 = t243*t454;
    const V t456 = t7*dat[38] + t9*dat[41] + t11*dat[44];
    const V t457 = t13*t456;
    const V t458 = t52 + t55 + t18*t457;
    const V t459 = t63*t456;
    const V t460 = t21*t50 + t14*t457;
    const V t461 = t105*dat[44] + t72*t460 + t106*t90 + t10*t459;
    const V t462 = t6*t457 + t21*dat[38];
    const V t463 = t105*t50 + t109*dat[44] + t14*t459 + t10*t462;
    const V t464 = t104*t458 + t108*t461 + t111*t463;
    const V t465 = t55 + t74*t457 + t92;
    const V t466 = t16*t460 + t6*t459 + t105*dat[38] + t106*t53;
    const V t467 = t16*t459 + t105*t53 + t109*dat[41] + t8*t462;
    const V t468 = t104*t467 + t108*t465 + t111*t466;
    const V t469 = t52 + t92 + t93*t457;
    const V t470 = t94*t90 + t95*t457 + t96*t53 + t105*dat[41] + t8*t459;
    const V t471 = t97*dat[44] + t98*dat[41] + t99*t457 + t105*t90 + t72*t459;
    const V t472 = t104*t470 + t108*t471 + t111*t469;
    const V t473 = t121*t458 + t122*t461 + t123*t463;
    const V t474 = t121*t467 + t122*t465 + t123*t466;
    const V t475 = t121*t470 + t122*t471 + t123*t469;
    const V t476 = t127*t458 + t128*t461 + t129*t463;
    const V t477 = t127*t467 + t128*t465 + t129*t466;
    const V t478 = t127*t470 + t128*t471 + t129*t469;
    const V t479 = t147*t468 + t152*t472 + t155*t473 + t156*t474 + t157*t475 + t158*t476 + t159*t477 + t160*t478 + t161*t464;
    const V t480 = t196*t479;
    const V t481 = t243*t480;
    const V t482 = t133*t243;
    const V t483 = t138*t243;
    const V t484 = -t197 - t200;
    const V t485 = t0*dat[27] + t1*dat[28] + t2*dat[29] + t3*dat[54] + t4*dat[55] + t5*dat[56] + dat[6];
    const V t486 = t0*dat[30] + t1*dat[31] + t2*dat[32] + t3*dat[57] + t4*dat[58] + t5*dat[59] + dat[7];
    const V t487 = t0*dat[33] + t1*dat[34] + t2*dat[35] + t3*dat[60] + t4*dat[61] + t5*dat[62] + dat[8];
    const V t488 = t485*in[0] + t486*in[1] + t487*in[2] + dat[69]*dat[70] + in[12] - in[27];
    const V t489 = t485*in[3] + t486*in[4] + t487*in[5] + dat[69]*dat[71] + in[13] - in[28];
    const V t490 = t485*in[6] + t486*in[7] + t487*in[8] + dat[69]*dat[72] + in[14] - in[29];
    const V t491 = t488*in[15] + t489*in[18] + t490*in[21];
    const V t492 = t488*in[17] + t489*in[20] + t490*in[23];
    const V t493 = t488*in[16] + t489*in[19] + t490*in[22];
    const V t494 = t104*dat[73] + t108*dat[76] + t111*dat[79];
    const V t495 = t121*dat[73] + t122*dat[76] + t123*dat[79];
    const V t496 = t127*dat[73] + t128*dat[76] + t129*dat[79];
    const V t497 = t104*dat[74] + t108*dat[77] + t111*dat[80];
    const V t498 = t121*dat[74] + t122*dat[77] + t123*dat[80];
    const V t499 = t127*dat[74] + t128*dat[77] + t129*dat[80];
    const V t500 = t104*dat[75] + t108*dat[78] + t111*dat[81];
    const V t501 = t121*dat[75] + t122*dat[78] + t123*dat[81];
    const V t502 = t127*dat[75] + t128*dat[78] + t129*dat[81];
    V tlog1[3]; v_so3_log(t494, t495, t496, t497, t498, t499, t500, t501, t502, tlog1);
    const V t503 = tlog1[1];
    const V t504 = (T(0.5))*t503;
    const V t505 = tlog1[0];
    const V t506 = (t505*t505);
    const V t507 = (t503*t503);
    const V t508 = tlog1[2];
    const V t509 = (t508*t508);
    const V t510 = t507 + t509;
    const V t511 = v_lie_D(t506 + t510);
    const V t512 = t511*t505;
    const V t513 = (T(0.5))*t504 + (T(0.5))*t512*t508;
    const V t514 = (T(0.5))*t508;
    const V t515 = t512*t503;
    const V t516 = -t514 + t515;
    const V t517 = (T(0.5))*t496;
    const V t518 = t513*t495 - t516*t517;
    const V t519 = -t510*t511 + T(1);
    const V t520 = -t513*t494 + (T(0.5))*t519*t496;
    const V t521 = (T(0.5))*t516;
    const V t522 = (T(0.5))*t519;
    const V t523 = t521*t494 - t522*t495;
    const V t524 = t513*t498 - t521*t499;
    const V t525 = -t513*t497 + (T(0.5))*t519*t499;
    const V t526 = t521*t497 - t522*t498;
    const V t527 = t513*t501 - t521*t502;
    const V t528 = -t513*t500 + (T(0.5))*t519*t502;
    const V t529 = t521*t500 - t522*t501;
    const V t530 = (T(0.5))*t505;
    const V t531 = t503*t508;
    const V t532 = t511*t531;
    const V t533 = -T(0.5)*t530 + (T(0.5))*t532;
    const V t534 = t511*(-t506 - t509) + T(1);
    const V t535 = -t517*t534 + t533*t495;
    const V t536 = t514 + t515;
    const V t537 = -t533*t494 + (T(0.5))*t536*t496;
    const V t538 = (T(0.5))*t534;
    const V t539 = (T(0.5))*t536;
    const V t540 = t538*t494 - t539*t495;
    const V t541 = t533*t498 - t538*t499;
    const V t542 = -t533*t497 + (T(0.5))*t536*t499;
    const V t543 = t538*t497 - t539*t498;
    const V t544 = t533*t501 - t538*t502;
    const V t545 = -t533*t500 + (T(0.5))*t536*t502;
    const V t546 = t538*t500 - t539*t501;
    const V t547 = (T(0.5))*t511*(-t506 - t507) + T(0.5);
    const V t548 = t530 + t532;
    const V t549 = -t517*t548 + t547*t495;
    const V t550 = -t504 + t511*t508*t505;
    const V t551 = -t547*t494 + (T(0.5))*t550*t496;
    const V t552 = (T(0.5))*t548;
    const V t553 = (T(0.5))*t550;
    const V t554 = t552*t494 - t553*t495;
    const V t555 = t547*t498 - t552*t499;
    const V t556 = -t547*t497 + (T(0.5))*t550*t499;
    const V t557 = t552*t497 - t553*t498;
    const V t558 = t547*t501 - t552*t502;
    const V t559 = -t547*t500 + (T(0.5))*t550*t502;
    const V t560 = t552*t500 - t553*t501;
    const V t561 = T(2)*t503;
    const V t562 = T(2)*t508;
    const V t563 = T(2)*t505;
    const V t564 = t507;
    const V t565 = t509;
    const V t566 = t564 + t565;
    const V t567 = t506;
    const V t568 = t566 + t567;
    const V t569 = v_lie_D1(t568);
    const V t570 = -t203;
    const V t571 = -t207;
    const V t572 = -t211;
    const V t573 = t570*in[2] + t571*in[5] + t572*in[8];
    const V t574 = t570*in[1] + t571*in[4] + t572*in[7];
    const V t575 = -in[0]*in[1] - in[3]*in[4] - in[6]*in[7];
    const V t576 = -in[0]*in[2] - in[3]*in[5] - in[6]*in[8];
    const V t577 = t570*in[0] + t571*in[3] + t572*in[6];
    const V t578 = -in[1]*in[2] - in[4]*in[5] - in[7]*in[8];
    const V t579 = v_lie_D(t568);
    const V t580 = t503*t579;
    const V t581 = t508*t579;
    const V t582 = -t566*t579 + T(1);
    const V t583 = t514;
    const V t584 = t579*t505;
    const V t585 = t503*t584;
    const V t586 = t583 + t585;
    const V t587 = t504;
    const V t588 = t508*t584;
    const V t589 = -t587 + t588;
    const V t590 = -t583 + t585;
    const V t591 = -t565 - t567;
    const V t592 = t591*t579 + T(1);
    const V t593 = t530;
    const V t594 = t531*t579;
    const V t595 = t593 + t594;
    const V t596 = t587 + t588;
    const V t597 = -t593 + t594;
    const V t598 = -t564 - t567;
    const V t599 = t598*t579 + T(1);
    const V t600 = -in[0]*in[9] + in[0]*in[24] - in[3]*in[10] + in[3]*in[25] - in[6]*in[11] + in[6]*in[26];
    const V t601 = -in[1]*in[9] + in[1]*in[24] - in[4]*in[10] + in[4]*in[25] - in[7]*in[11] + in[7]*in[26];
    const V t602 = -in[2]*in[9] + in[2]*in[24] - in[5]*in[10] + in[5]*in[25] - in[8]*in[11] + in[8]*in[26];
    const V t603 = t600*dat[73] + t601*dat[76] + t602*dat[79] - dat[73]*dat[82] - dat[76]*dat[83] - dat[79]*dat[84];
    const V t604 = t566*t603;
    const V t605 = t579*t603;
    const V t606 = t600*dat[74] + t601*dat[77] + t602*dat[80] - dat[74]*dat[82] - dat[77]*dat[83] - dat[80]*dat[84];
    const V t607 = t591*t606;
    const V t608 = t579*t606;
    const V t609 = t600*dat[75] + t601*dat[78] + t602*dat[81] - dat[75]*dat[82] - dat[78]*dat[83] - dat[81]*dat[84];
    const V t610 = t598*t609;
    const V t611 = t579*t609;
    const V t612 = t165*t229 + t168*t230 + t171*t233 + t172*t234 + t173*t235 + t174*t238 + t175*t239 + t176*t240 + t177*t228;
    const V t613 = t165*t248 + t168*t249 + t171*t252 + t172*t253 + t173*t254 + t174*t257 + t175*t258 + t176*t259 + t177*t247;
    const V t614 = t165*t266 + t168*t267 + t171*t270 + t172*t271 + t173*t272 + t174*t275 + t175*t276 + t176*t277 + t177*t265;
    const V t615 = t171*t284 + t172*t285 + t173*t286 + t174*t290 + t175*t291 + t176*t292;
    const V t616 = t165*t300 + t168*t301 + t174*t305 + t175*t306 + t176*t307 + t177*t299;
    const V t617 = t165*t315 + t168*t316 + t171*t320 + t172*t321 + t173*t322 + t177*t314;
    const V t618 = t165*t338 + t168*t342 + t171*t343 + t172*t344 + t173*t345 + t174*t346 + t175*t347 + t176*t348 + t177*t334;
    const V t619 = t165*t364 + t168*t368 + t171*t369 + t172*t370 + t173*t371 + t174*t372 + t175*t373 + t176*t374 + t177*t360;
    const V t620 = t165*t390 + t168*t394 + t171*t395 + t172*t396 + t173*t397 + t174*t398 + t175*t399 + t176*t400 + t177*t386;
    const V t621 = t165*t416 + t168*t420 + t171*t421 + t172*t422 + t173*t423 + t174*t424 + t175*t425 + t176*t426 + t177*t412;
    const V t622 = t165*t442 + t168*t446 + t171*t447 + t172*t448 + t173*t449 + t174*t450 + t175*t451 + t176*t452 + t177*t438;
    const V t623 = t165*t468 + t168*t472 + t171*t473 + t172*t474 + t173*t475 + t174*t476 + t175*t477 + t176*t478 + t177*t464;
    const V t624 = t187*t233 + t188*t234 + t189*t235 + t190*t238 + t191*t239 + t192*t240 + t193*t228 + t180*t229 + t184*t230;
    const V t625 = t187*t252 + t188*t253 + t189*t254 + t190*t257 + t191*t258 + t192*t259 + t193*t247 + t180*t248 + t184*t249;
    const V t626 = t187*t270 + t188*t271 + t189*t272 + t190*t275 + t191*t276 + t192*t277 + t193*t265 + t180*t266 + t184*t267;
    const V t627 = t187*t284 + t188*t285 + t189*t286 + t190*t290 + t191*t291 + t192*t292;
    const V t628 = t190*t305 + t191*t306 + t192*t307 + t193*t299 + t180*t300 + t184*t301;
    const V t629 = t187*t320 + t188*t321 + t189*t322 + t193*t314 + t180*t315 + t184*t316;
    const V t630 = t187*t343 + t188*t344 + t189*t345 + t190*t346 + t191*t347 + t192*t348 + t193*t334 + t180*t338 + t184*t342;
    const V t631 = t187*t369 + t188*t370 + t189*t371 + t190*t372 + t191*t373 + t192*t374 + t193*t360 + t180*t364 + t184*t368;
    const V t632 = t187*t395 + t188*t396 + t189*t397 + t190*t398 + t191*t399 + t192*t400 + t193*t386 + t180*t390 + t184*t394;
    const V t633 = t187*t421 + t188*t422 + t189*t423 + t190*t424 + t191*t425 + t192*t426 + t193*t412 + t180*t416 + t184*t420;
    const V t634 = t187*t447 + t188*t448 + t189*t449 + t190*t450 + t191*t451 + t192*t452 + t193*t438 + t180*t442 + t184*t446;
    const V t635 = t187*t473 + t188*t474 + t189*t475 + t190*t476 + t191*t477 + t192*t478 + t193*t464 + t180*t468 + t184*t472;
    const V t636 = t194*t612;
    const V t637 = t194*t613;
    const V t638 = t194*t614;
    const V t639 = t194*t615;
    const V t640 = t194*t616;
    const V t641 = t194*t617;
    const V t642 = t194*t618;
    const V t643 = t194*t619;
    const V t644 = t194*t620;
    const V t645 = t194*t621;
    const V t646 = t194*t622;
    const V t647 = t194*t623;
    const V t648 = t195*t624;
    const V t649 = t195*t625;
    const V t650 = t195*t626;
    const V t651 = t195*t627;
    const V t652 = t195*t628;
    const V t653 = t195*t629;
    const V t654 = t195*t630;
    const V t655 = t195*t631;
    const V t656 = t195*t632;
    const V t657 = t195*t633;
    const V t658 = t195*t634;
    const V t659 = t195*t635;
    const V t660 = t636 + t648;
    const V t661 = t637 + t649;
    const V t662 = t638 + t650;
    const V t663 = t639 + t651;
    const V t664 = t640 + t652;
    const V t665 = t641 + t653;
    const V t666 = t642 + t654;
    const V t667 = t643 + t655;
    const V t668 = t644 + t656;
    const V t669 = t645 + t657;
    const V t670 = t646 + t658;
    const V t671 = t647 + t659;
    const V t672 = t202*t660 + t202*t242;
    const V t673 = t202*t661 + t202*t261;
    const V t674 = t202*t662 + t202*t279;
    const V t675 = t202*t663 + t202*t294;
    const V t676 = t202*t664 + t202*t309;
    const V t677 = t202*t665 + t202*t324;
    const V t678 = t202*t666 + t202*t350;
    const V t679 = t202*t667 + t202*t376;
    const V t680 = t202*t668 + t202*t402;
    const V t681 = t202*t669 + t202*t428;
    const V t682 = t202*t670 + t202*t454;
    const V t683 = t202*t671 + t202*t480;
    const V t684 = -t199*t243 + T(1);
    const V t685 = -t199*t672 - t243*t660;
    const V t686 = -t199*t673 - t243*t661;
    const V t687 = -t199*t674 - t243*t662;
    const V t688 = -t199*t675 - t243*t663;
    const V t689 = -t199*t676 - t243*t664;
    const V t690 = -t199*t677 - t243*t665;
    const V t691 = -t199*t678 - t243*t666;
    const V t692 = -t199*t679 - t243*t667;
    const V t693 = -t199*t680 - t243*t668;
    const V t694 = -t199*t681 - t243*t669;
    const V t695 = -t199*t682 - t243*t670;
    const V t696 = -t199*t683 - t243*t671;
    const V t697 = t216*in[2] - t217*in[1];
    const V t698 = -t215*in[2] + t217*in[0];
    const V t699 = t215*in[1] - t216*in[0];
    const V t700 = t204;
    const V t701 = t205;
    const V t702 = t206;
    const V t703 = dat[18]*in[0] + dat[21]*in[1] + dat[24]*in[2];
    const V t704 = dat[19]*in[0] + dat[22]*in[1] + dat[25]*in[2];
    const V t705 = dat[20]*in[0] + dat[23]*in[1] + dat[26]*in[2];
    const V t706 = dat[45]*in[0] + dat[48]*in[1] + dat[51]*in[2];
    const V t707 = dat[46]*in[0] + dat[49]*in[1] + dat[52]*in[2];
    const V t708 = dat[47]*in[0] + dat[50]*in[1] + dat[53]*in[2];
    const V t709 = t216*in[5] - t217*in[4];
    const V t710 = -t215*in[5] + t217*in[3];
    const V t711 = t215*in[4] - t216*in[3];
    const V t712 = t208;
    const V t713 = t209;
    const V t714 = t210;
    const V t715 = dat[18]*in[3] + dat[21]*in[4] + dat[24]*in[5];
    const V t716 = dat[19]*in[3] + dat[22]*in[4] + dat[25]*in[5];
    const V t717 = dat[20]*in[3] + dat[23]*in[4] + dat[26]*in[5];
    const V t718 = dat[45]*in[3] + dat[48]*in[4] + dat[51]*in[5];
    const V t719 = dat[46]*in[3] + dat[49]*in[4] + dat[52]*in[5];
    const V t720 = dat[47]*in[3] + dat[50]*in[4] + dat[53]*in[5];
    const V t721 = t216*in[8] - t217*in[7];
    const V t722 = -t215*in[8] + t217*in[6];
    const V t723 = t215*in[7] - t216*in[6];
    const V t724 = t212;
    const V t725 = t213;
    const V t726 = t214;
    const V t727 = dat[18]*in[6] + dat[21]*in[7] + dat[24]*in[8];
    const V t728 = dat[19]*in[6] + dat[22]*in[7] + dat[25]*in[8];
    const V t729 = dat[20]*in[6] + dat[23]*in[7] + dat[26]*in[8];
    const V t730 = dat[45]*in[6] + dat[48]*in[7] + dat[51]*in[8];
    const V t731 = dat[46]*in[6] + dat[49]*in[7] + dat[52]*in[8];
    const V t732 = dat[47]*in[6] + dat[50]*in[7] + dat[53]*in[8];
    const V t733 = t222;
    const V t734 = t697*in[15] + t709*in[18] + t721*in[21];
    const V t735 = t698*in[15] + t710*in[18] + t722*in[21];
    const V t736 = t699*in[15] + t711*in[18] + t723*in[21];
    const V t737 = t56;
    const V t738 = t59;
    const V t739 = t57;
    const V t740 = dat[69]*in[15];
    const V t741 = dat[69]*in[18];
    const V t742 = dat[69]*in[21];
    const V t743 = -t223;
    const V t744 = t224;
    const V t745 = t700*in[15] + t712*in[18] + t724*in[21];
    const V t746 = t701*in[15] + t713*in[18] + t725*in[21];
    const V t747 = t702*in[15] + t714*in[18] + t726*in[21];
    const V t748 = t703*in[15] + t715*in[18] + t727*in[21];
    const V t749 = t704*in[15] + t716*in[18] + t728*in[21];
    const V t750 = t705*in[15] + t717*in[18] + t729*in[21];
    const V t751 = t706*in[15] + t718*in[18] + t730*in[21];
    const V t752 = t707*in[15] + t719*in[18] + t731*in[21];
    const V t753 = t708*in[15] + t720*in[18] + t732*in[21];
    const V t754 = t148;
    const V t755 = (T(0.5))*t624;
    const V t756 = (T(0.5))*t625;
    const V t757 = (T(0.5))*t626;
    const V t758 = (T(0.5))*t627;
    const V t759 = (T(0.5))*t628;
    const V t760 = (T(0.5))*t629;
    const V t761 = (T(0.5))*t630;
    const V t762 = (T(0.5))*t631;
    const V t763 = (T(0.5))*t632;
    const V t764 = (T(0.5))*t633;
    const V t765 = (T(0.5))*t634;
    const V t766 = (T(0.5))*t635;
    const V t767 = t135*t243;
    const V t768 = t135*t672 + t243*t241;
    const V t769 = t135*t673 + t243*t260;
    const V t770 = t135*t674 + t243*t278;
    const V t771 = t135*t675 + t243*t293;
    const V t772 = t135*t676 + t243*t308;
    const V t773 = t135*t677 + t243*t323;
    const V t774 = t135*t678 + t243*t349;
    const V t775 = t135*t679 + t243*t375;
    const V t776 = t135*t680 + t243*t401;
    const V t777 = t135*t681 + t243*t427;
    const V t778 = t135*t682 + t243*t453;
    const V t779 = t135*t683 + t243*t479;
    const V t780 = t133*t767;
    const V t781 = t133*t768 + t767*t612;
    const V t782 = t133*t769 + t767*t613;
    const V t783 = t133*t770 + t767*t614;
    const V t784 = t133*t771 + t767*t615;
    const V t785 = t133*t772 + t767*t616;
    const V t786 = t133*t773 + t767*t617;
    const V t787 = t133*t774 + t767*t618;
    const V t788 = t133*t775 + t767*t619;
    const V t789 = t133*t776 + t767*t620;
    const V t790 = t133*t777 + t767*t621;
    const V t791 = t133*t778 + t767*t622;
    const V t792 = t133*t779 + t767*t623;
    const V t793 = t754 + t780;
    const V t794 = t755 + t781;
    const V t795 = t756 + t782;
    const V t796 = t757 + t783;
    const V t797 = t758 + t784;
    const V t798 = t759 + t785;
    const V t799 = t760 + t786;
    const V t800 = t761 + t787;
    const V t801 = t762 + t788;
    const V t802 = t763 + t789;
    const V t803 = t764 + t790;
    const V t804 = t765 + t791;
    const V t805 = t766 + t792;
    const V t806 = t224;
    const V t807 = t697*in[16] + t709*in[19] + t721*in[22];
    const V t808 = t698*in[16] + t710*in[19] + t722*in[22];
    const V t809 = t699*in[16] + t711*in[19] + t723*in[22];
    const V t810 = t62;
    const V t811 = t67;
    const V t812 = t71;
    const V t813 = dat[69]*in[16];
    const V t814 = dat[69]*in[19];
    const V t815 = dat[69]*in[22];
    const V t816 = t223;
    const V t817 = -t222;
    const V t818 = t700*in[16] + t712*in[19] + t724*in[22];
    const V t819 = t701*in[16] + t713*in[19] + t725*in[22];
    const V t820 = t702*in[16] + t714*in[19] + t726*in[22];
    const V t821 = t703*in[16] + t715*in[19] + t727*in[22];
    const V t822 = t704*in[16] + t716*in[19] + t728*in[22];
    const V t823 = t705*in[16] + t717*in[19] + t729*in[22];
    const V t824 = t706*in[16] + t718*in[19] + t730*in[22];
    const V t825 = t707*in[16] + t719*in[19] + t731*in[22];
    const V t826 = t708*in[16] + t720*in[19] + t732*in[22];
    const V t827 = t134;
    const V t828 = (T(0.5))*t612;
    const V t829 = (T(0.5))*t613;
    const V t830 = (T(0.5))*t614;
    const V t831 = (T(0.5))*t615;
    const V t832 = (T(0.5))*t616;
    const V t833 = (T(0.5))*t617;
    const V t834 = (T(0.5))*t618;
    const V t835 = (T(0.5))*t619;
    const V t836 = (T(0.5))*t620;
    const V t837 = (T(0.5))*t621;
    const V t838 = (T(0.5))*t622;
    const V t839 = (T(0.5))*t623;
    const V t840 = t138*t767;
    const V t841 = t138*t768 + t767*t624;
    const V t842 = t138*t769 + t767*t625;
    const V t843 = t138*t770 + t767*t626;
    const V t844 = t138*t771 + t767*t627;
    const V t845 = t138*t772 + t767*t628;
    const V t846 = t138*t773 + t767*t629;
    const V t847 = t138*t774 + t767*t630;
    const V t848 = t138*t775 + t767*t631;
    const V t849 = t138*t776 + t767*t632;
    const V t850 = t138*t777 + t767*t633;
    const V t851 = t138*t778 + t767*t634;
    const V t852 = t138*t779 + t767*t635;
    const V t853 = -t827 + t840;
    const V t854 = -t828 + t841;
    const V t855 = -t829 + t842;
    const V t856 = -t830 + t843;
    const V t857 = -t831 + t844;
    const V t858 = -t832 + t845;
    const V t859 = -t833 + t846;
    const V t860 = -t834 + t847;
    const V t861 = -t835 + t848;
    const V t862 = -t836 + t849;
    const V t863 = -t837 + t850;
    const V t864 = -t838 + t851;
    const V t865 = -t839 + t852;
    const V t866 = t223;
    const V t867 = t697*in[17] + t709*in[20] + t721*in[23];
    const V t868 = t698*in[17] + t710*in[20] + t722*in[23];
    const V t869 = t699*in[17] + t711*in[20] + t723*in[23];
    const V t870 = t60;
    const V t871 = t65;
    const V t872 = t69;
    const V t873 = dat[69]*in[17];
    const V t874 = dat[69]*in[20];
    const V t875 = dat[69]*in[23];
    const V t876 = -t224;
    const V t877 = t222;
    const V t878 = t700*in[17] + t712*in[20] + t724*in[23];
    const V t879 = t701*in[17] + t713*in[20] + t725*in[23];
    const V t880 = t702*in[17] + t714*in[20] + t726*in[23];
    const V t881 = t703*in[17] + t715*in[20] + t727*in[23];
    const V t882 = t704*in[17] + t716*in[20] + t728*in[23];
    const V t883 = t705*in[17] + t717*in[20] + t729*in[23];
    const V t884 = t706*in[17] + t718*in[20] + t730*in[23];
    const V t885 = t707*in[17] + t719*in[20] + t731*in[23];
    const V t886 = t708*in[17] + t720*in[20] + t732*in[23];
    const V t887 = t225*t243 + T(1);
    const V t888 = t225*t672 - t244 - t243*t648;
    const V t889 = t225*t673 - t262 - t243*t649;
    const V t890 = t225*t674 - t280 - t243*t650;
    const V t891 = t225*t675 - t295 - t243*t651;
    const V t892 = t225*t676 - t310 - t243*t652;
    const V t893 = t225*t677 - t325 - t243*t653;
    const V t894 = t225*t678 - t351 - t243*t654;
    const V t895 = t225*t679 - t377 - t243*t655;
    const V t896 = t225*t680 - t403 - t243*t656;
    const V t897 = t225*t681 - t429 - t243*t657;
    const V t898 = t225*t682 - t455 - t243*t658;
    const V t899 = t225*t683 - t481 - t243*t659;
    const V t900 = t162;
    const V t901 = (T(0.5))*t241;
    const V t902 = (T(0.5))*t260;
    const V t903 = (T(0.5))*t278;
    const V t904 = (T(0.5))*t293;
    const V t905 = (T(0.5))*t308;
    const V t906 = (T(0.5))*t323;
    const V t907 = (T(0.5))*t349;
    const V t908 = (T(0.5))*t375;
    const V t909 = (T(0.5))*t401;
    const V t910 = (T(0.5))*t427;
    const V t911 = (T(0.5))*t453;
    const V t912 = (T(0.5))*t479;
    const V t913 = t181*t243;
    const V t914 = t482*t624 + t483*t612 + t181*t672;
    const V t915 = t482*t625 + t483*t613 + t181*t673;
    const V t916 = t482*t626 + t483*t614 + t181*t674;
    const V t917 = t482*t627 + t483*t615 + t181*t675;
    const V t918 = t482*t628 + t483*t616 + t181*t676;
    const V t919 = t482*t629 + t483*t617 + t181*t677;
    const V t920 = t482*t630 + t483*t618 + t181*t678;
    const V t921 = t482*t631 + t483*t619 + t181*t679;
    const V t922 = t482*t632 + t483*t620 + t181*t680;
    const V t923 = t482*t633 + t483*t621 + t181*t681;
    const V t924 = t482*t634 + t483*t622 + t181*t682;
    const V t925 = t482*t635 + t483*t623 + t181*t683;
    const V t926 = t900 + t913;
    const V t927 = t901 + t914;
    const V t928 = t902 + t915;
    const V t929 = t903 + t916;
    const V t930 = t904 + t917;
    const V t931 = t905 + t918;
    const V t932 = t906 + t919;
    const V t933 = t907 + t920;
    const V t934 = t908 + t921;
    const V t935 = t909 + t922;
    const V t936 = t910 + t923;
    const V t937 = t911 + t924;
    const V t938 = t912 + t925;
    const V t939 = -t754 + t780;
    const V t940 = -t755 + t781;
    const V t941 = -t756 + t782;
    const V t942 = -t757 + t783;
    const V t943 = -t758 + t784;
    const V t944 = -t759 + t785;
    const V t945 = -t760 + t786;
    const V t946 = -t761 + t787;
    const V t947 = -t762 + t788;
    const V t948 = -t763 + t789;
    const V t949 = -t764 + t790;
    const V t950 = -t765 + t791;
    const V t951 = -t766 + t792;
    const V t952 = t484*t243 + T(1);
    const V t953 = -t244 + t484*t672 - t243*t636;
    const V t954 = -t262 + t484*t673 - t243*t637;
    const V t955 = -t280 + t484*t674 - t243*t638;
    const V t956 = -t295 + t484*t675 - t243*t639;
    const V t957 = -t310 + t484*t676 - t243*t640;
    const V t958 = -t325 + t484*t677 - t243*t641;
    const V t959 = -t351 + t484*t678 - t243*t642;
    const V t960 = -t377 + t484*t679 - t243*t643;
    const V t961 = -t403 + t484*t680 - t243*t644;
    const V t962 = -t429 + t484*t681 - t243*t645;
    const V t963 = -t455 + t484*t682 - t243*t646;
    const V t964 = -t481 + t484*t683 - t243*t647;
    const V t965 = t827 + t840;
    const V t966 = t828 + t841;
    const V t967 = t829 + t842;
    const V t968 = t830 + t843;
    const V t969 = t831 + t844;
    const V t970 = t832 + t845;
    const V t971 = t833 + t846;
    const V t972 = t834 + t847;
    const V t973 = t835 + t848;
    const V t974 = t836 + t849;
    const V t975 = t837 + t850;
    const V t976 = t838 + t851;
    const V t977 = t839 + t852;
    const V t978 = -t900 + t913;
    const V t979 = -t901 + t914;
    const V t980 = -t902 + t915;
    const V t981 = -t903 + t916;
    const V t982 = -t904 + t917;
    const V t983 = -t905 + t918;
    const V t984 = -t906 + t919;
    const V t985 = -t907 + t920;
    const V t986 = -t908 + t921;
    const V t987 = -t909 + t922;
    const V t988 = -t910 + t923;
    const V t989 = -t911 + t924;
    const V t990 = -t912 + t925;
    const V t991 = t486*in[2] - t487*in[1];
    const V t992 = -t485*in[2] + t487*in[0];
    const V t993 = t485*in[1] - t486*in[0];
    const V t994 = dat[27]*in[0] + dat[30]*in[1] + dat[33]*in[2];
    const V t995 = dat[28]*in[0] + dat[31]*in[1] + dat[34]*in[2];
    const V t996 = dat[29]*in[0] + dat[32]*in[1] + dat[35]*in[2];
    const V t997 = dat[54]*in[0] + dat[57]*in[1] + dat[60]*in[2];
    const V t998 = dat[55]*in[0] + dat[58]*in[1] + dat[61]*in[2];
    const V t999 = dat[56]*in[0] + dat[59]*in[1] + dat[62]*in[2];
    const V t1000 = t486*in[5] - t487*in[4];
    const V t1001 = -t485*in[5] + t487*in[3];
    const V t1002 = t485*in[4] - t486*in[3];
    const V t1003 = dat[27]*in[3] + dat[30]*in[4] + dat[33]*in[5];
    const V t1004 = dat[28]*in[3] + dat[31]*in[4] + dat[34]*in[5];
    const V t1005 = dat[29]*in[3] + dat[32]*in[4] + dat[35]*in[5];
    const V t1006 = dat[54]*in[3] + dat[57]*in[4] + dat[60]*in[5];
    const V t1007 = dat[55]*in[3] + dat[58]*in[4] + dat[61]*in[5];
    const V t1008 = dat[56]*in[3] + dat[59]*in[4] + dat[62]*in[5];
    const V t1009 = t486*in[8] - t487*in[7];
    const V t1010 = -t485*in[8] + t487*in[6];
    const V t1011 = t485*in[7] - t486*in[6];
    const V t1012 = dat[27]*in[6] + dat[30]*in[7] + dat[33]*in[8];
    const V t1013 = dat[28]*in[6] + dat[31]*in[7] + dat[34]*in[8];
    const V t1014 = dat[29]*in[6] + dat[32]*in[7] + dat[35]*in[8];
    const V t1015 = dat[54]*in[6] + dat[57]*in[7] + dat[60]*in[8];
    const V t1016 = dat[55]*in[6] + dat[58]*in[7] + dat[61]*in[8];
    const V t1017 = dat[56]*in[6] + dat[59]*in[7] + dat[62]*in[8];
    const V t1018 = t491;
    const V t1019 = t991*in[15] + t1000*in[18] + t1009*in[21];
    const V t1020 = t992*in[15] + t1001*in[18] + t1010*in[21];
    const V t1021 = t993*in[15] + t1002*in[18] + t1011*in[21];
    const V t1022 = -t492;
    const V t1023 = t493;
    const V t1024 = t204;
    const V t1025 = t208;
    const V t1026 = t212;
    const V t1027 = t994*in[15] + t1003*in[18] + t1012*in[21];
    const V t1028 = t995*in[15] + t1004*in[18] + t1013*in[21];
    const V t1029 = t996*in[15] + t1005*in[18] + t1014*in[21];
    const V t1030 = t997*in[15] + t1006*in[18] + t1015*in[21];
    const V t1031 = t998*in[15] + t1007*in[18] + t1016*in[21];
    const V t1032 = t999*in[15] + t1008*in[18] + t1017*in[21];
    const V t1033 = t493;
    const V t1034 = t991*in[16] + t1000*in[19] + t1009*in[22];
    const V t1035 = t992*in[16] + t1001*in[19] + t1010*in[22];
    const V t1036 = t993*in[16] + t1002*in[19] + t1011*in[22];
    const V t1037 = t492;
    const V t1038 = -t491;
    const V t1039 = t205;
    const V t1040 = t209;
    const V t1041 = t213;
    const V t1042 = t994*in[16] + t1003*in[19] + t1012*in[22];
    const V t1043 = t995*in[16] + t1004*in[19] + t1013*in[22];
    const V t1044 = t996*in[16] + t1005*in[19] + t1014*in[22];
    const V t1045 = t997*in[16] + t1006*in[19] + t1015*in[22];
    const V t1046 = t998*in[16] + t1007*in[19] + t1016*in[22];
    const V t1047 = t999*in[16] + t1008*in[19] + t1017*in[22];
    const V t1048 = t492;
    const V t1049 = t991*in[17] + t1000*in[20] + t1009*in[23];
    const V t1050 = t992*in[17] + t1001*in[20] + t1010*in[23];
    const V t1051 = t993*in[17] + t1002*in[20] + t1011*in[23];
    const V t1052 = -t493;
    const V t1053 = t491;
    const V t1054 = t206;
    const V t1055 = t210;
    const V t1056 = t214;
    const V t1057 = t994*in[17] + t1003*in[20] + t1012*in[23];
    const V t1058 = t995*in[17] + t1004*in[20] + t1013*in[23];
    const V t1059 = t996*in[17] + t1005*in[20] + t1014*in[23];
    const V t1060 = t997*in[17] + t1006*in[20] + t1015*in[23];
    const V t1061 = t998*in[17] + t1007*in[20] + t1016*in[23];
    const V t1062 = t999*in[17] + t1008*in[20] + t1017*in[23];
    const V t1063 = t226*dat[76] + t227*dat[79];
    const V t1064 = t245*dat[73] + t246*dat[79];
    const V t1065 = t263*dat[73] + t264*dat[76];
    const V t1066 = t296*dat[73] + t297*dat[76] + t298*dat[79];
    const V t1067 = t311*dat[73] + t312*dat[76] + t313*dat[79];
    const V t1068 = t231*dat[76] + t232*dat[79];
    const V t1069 = t250*dat[73] + t251*dat[79];
    const V t1070 = t268*dat[73] + t269*dat[76];
    const V t1071 = t281*dat[73] + t282*dat[76] + t283*dat[79];
    const V t1072 = t317*dat[73] + t318*dat[76] + t319*dat[79];
    const V t1073 = t236*dat[76] + t237*dat[79];
    const V t1074 = t255*dat[73] + t256*dat[79];
    const V t1075 = t273*dat[73] + t274*dat[76];
    const V t1076 = t287*dat[73] + t288*dat[76] + t289*dat[79];
    const V t1077 = t302*dat[73] + t303*dat[76] + t304*dat[79];
    const V t1078 = t226*dat[77] + t227*dat[80];
    const V t1079 = t245*dat[74] + t246*dat[80];
    const V t1080 = t263*dat[74] + t264*dat[77];
    const V t1081 = t296*dat[74] + t297*dat[77] + t298*dat[80];
    const V t1082 = t311*dat[74] + t312*dat[77] + t313*dat[80];
    const V t1083 = t231*dat[77] + t232*dat[80];
    const V t1084 = t250*dat[74] + t251*dat[80];
    const V t1085 = t268*dat[74] + t269*dat[77];
    const V t1086 = t281*dat[74] + t282*dat[77] + t283*dat[80];
    const V t1087 = t317*dat[74] + t318*dat[77] + t319*dat[80];
    const V t1088 = t236*dat[77] + t237*dat[80];
    const V t1089 = t255*dat[74] + t256*dat[80];
    const V t1090 = t273*dat[74] + t274*dat[77];
    const V t1091 = t287*dat[74] + t288*dat[77] + t289*dat[80];
    const V t1092 = t302*dat[74] + t303*dat[77] + t304*dat[80];
    const V t1093 = t226*dat[78] + t227*dat[81];
    const V t1094 = t245*dat[75] + t246*dat[81];
    const V t1095 = t263*dat[75] + t264*dat[78];
    const V t1096 = t296*dat[75] + t297*dat[78] + t298*dat[81];
    const V t1097 = t311*dat[75] + t312*dat[78] + t313*dat[81];
    const V t1098 = t231*dat[78] + t232*dat[81];
    const V t1099 = t250*dat[75] + t251*dat[81];
    const V t1100 = t268*dat[75] + t269*dat[78];
    const V t1101 = t281*dat[75] + t282*dat[78] + t283*dat[81];
    const V t1102 = t317*dat[75] + t318*dat[78] + t319*dat[81];
    const V t1103 = t236*dat[78] + t237*dat[81];
    const V t1104 = t255*dat[75] + t256*dat[81];
    const V t1105 = t273*dat[75] + t274*dat[78];
    const V t1106 = t287*dat[75] + t288*dat[78] + t289*dat[81];
    const V t1107 = t302*dat[75] + t303*dat[78] + t304*dat[81];
    const V t1108 = t518*t1063 + t520*t1068 + t523*t1073 + t524*t1078 + t525*t1083 + t526*t1088 + t527*t1093 + t528*t1098 + t529*t1103;
    const V t1109 = t518*t1064 + t520*t1069 + t523*t1074 + t524*t1079 + t525*t1084 + t526*t1089 + t527*t1094 + t528*t1099 + t529*t1104;
    const V t1110 = t518*t1065 + t520*t1070 + t523*t1075 + t524*t1080 + t525*t1085 + t526*t1090 + t527*t1095 + t528*t1100 + t529*t1105;
    const V t1111 = t520*t1071 + t523*t1076 + t525*t1086 + t526*t1091 + t528*t1101 + t529*t1106;
    const V t1112 = t518*t1066 + t523*t1077 + t524*t1081 + t526*t1092 + t527*t1096 + t529*t1107;
    const V t1113 = t518*t1067 + t520*t1072 + t524*t1082 + t525*t1087 + t527*t1097 + t528*t1102;
    const V t1114 = t535*t1063 + t537*t1068 + t540*t1073 + t541*t1078 + t542*t1083 + t543*t1088 + t544*t1093 + t545*t1098 + t546*t1103;
    const V t1115 = t535*t1064 + t537*t1069 + t540*t1074 + t541*t1079 + t542*t1084 + t543*t1089 + t544*t1094 + t545*t1099 + t546*t1104;
    const V t1116 = t535*t1065 + t537*t1070 + t540*t1075 + t541*t1080 + t542*t1085 + t543*t1090 + t544*t1095 + t545*t1100 + t546*t1105;
    const V t1117 = t537*t1071 + t540*t1076 + t542*t1086 + t543*t1091 + t545*t1101 + t546*t1106;
    const V t1118 = t535*t1066 + t540*t1077 + t541*t1081 + t543*t1092 + t544*t1096 + t546*t1107;
    const V t1119 = t535*t1067 + t537*t1072 + t541*t1082 + t542*t1087 + t544*t1097 + t545*t1102;
    const V t1120 = t549*t1063 + t551*t1068 + t554*t1073 + t555*t1078 + t556*t1083 + t557*t1088 + t558*t1093 + t559*t1098 + t560*t1103;
    const V t1121 = t549*t1064 + t551*t1069 + t554*t1074 + t555*t1079 + t556*t1084 + t557*t1089 + t558*t1094 + t559*t1099 + t560*t1104;
    const V t1122 = t549*t1065 + t551*t1070 + t554*t1075 + t555*t1080 + t556*t1085 + t557*t1090 + t558*t1095 + t559*t1100 + t560*t1105;
    const V t1123 = t551*t1071 + t554*t1076 + t556*t1086 + t557*t1091 + t559*t1101 + t560*t1106;
    const V t1124 = t549*t1066 + t554*t1077 + t555*t1081 + t557*t1092 + t558*t1096 + t560*t1107;
    const V t1125 = t549*t1067 + t551*t1072 + t555*t1082 + t556*t1087 + t558*t1097 + t559*t1102;
    const V t1126 = t561*t1114;
    const V t1127 = t561*t1115;
    const V t1128 = t561*t1116;
    const V t1129 = t561*t1117;
    const V t1130 = t561*t1118;
    const V t1131 = t561*t1119;
    const V t1132 = t562*t1120;
    const V t1133 = t562*t1121;
    const V t1134 = t562*t1122;
    const V t1135 = t562*t1123;
    const V t1136 = t562*t1124;
    const V t1137 = t562*t1125;
    const V t1138 = t1126 + t1132;
    const V t1139 = t1127 + t1133;
    const V t1140 = t1128 + t1134;
    const V t1141 = t1129 + t1135;
    const V t1142 = t1130 + t1136;
    const V t1143 = t1131 + t1137;
    const V t1144 = t563*t1108;
    const V t1145 = t563*t1109;
    const V t1146 = t563*t1110;
    const V t1147 = t563*t1111;
    const V t1148 = t563*t1112;
    const V t1149 = t563*t1113;
    const V t1150 = t569*t1138 + t569*t1144;
    const V t1151 = t569*t1139 + t569*t1145;
    const V t1152 = t569*t1140 + t569*t1146;
    const V t1153 = t569*t1141 + t569*t1147;
    const V t1154 = t569*t1142 + t569*t1148;
    const V t1155 = t569*t1143 + t569*t1149;
    const V t1156 = -t573;
    const V t1157 = t574;
    const V t1158 = -(in[0]*in[0]) - (in[3]*in[3]) - (in[6]*in[6]);
    const V t1159 = t575;
    const V t1160 = t576;
    const V t1161 = t56;
    const V t1162 = t62;
    const V t1163 = t60;
    const V t1164 = t573;
    const V t1165 = -t577;
    const V t1166 = t575;
    const V t1167 = -(in[1]*in[1]) - (in[4]*in[4]) - (in[7]*in[7]);
    const V t1168 = t578;
    const V t1169 = t59;
    const V t1170 = t67;
    const V t1171 = t65;
    const V t1172 = -t574;
    const V t1173 = t577;
    const V t1174 = t576;
    const V t1175 = t578;
    const V t1176 = -(in[2]*in[2]) - (in[5]*in[5]) - (in[8]*in[8]);
    const V t1177 = t57;
    const V t1178 = t71;
    const V t1179 = t69;
    const V t1180 = t1164*dat[76] + t1172*dat[79];
    const V t1181 = t1156*dat[73] + t1173*dat[79];
    const V t1182 = t1157*dat[73] + t1165*dat[76];
    const V t1183 = t1158*dat[73] + t1166*dat[76] + t1174*dat[79];
    const V t1184 = t1159*dat[73] + t1167*dat[76] + t1175*dat[79];
    const V t1185 = t1160*dat[73] + t1168*dat[76] + t1176*dat[79];
    const V t1186 = t1161*dat[73] + t1169*dat[76] + t1177*dat[79];
    const V t1187 = t1162*dat[73] + t1170*dat[76] + t1178*dat[79];
    const V t1188 = t1163*dat[73] + t1171*dat[76] + t1179*dat[79];
    const V t1189 = (T(0.5))*t1120;
    const V t1190 = (T(0.5))*t1121;
    const V t1191 = (T(0.5))*t1122;
    const V t1192 = (T(0.5))*t1123;
    const V t1193 = (T(0.5))*t1124;
    const V t1194 = (T(0.5))*t1125;
    const V t1195 = t579*t1108 + t505*t1150;
    const V t1196 = t579*t1109 + t505*t1151;
    const V t1197 = t579*t1110 + t505*t1152;
    const V t1198 = t579*t1111 + t505*t1153;
    const V t1199 = t579*t1112 + t505*t1154;
    const V t1200 = t579*t1113 + t505*t1155;
    const V t1201 = t503*t1195 + t584*t1114;
    const V t1202 = t503*t1196 + t584*t1115;
    const V t1203 = t503*t1197 + t584*t1116;
    const V t1204 = t503*t1198 + t584*t1117;
    const V t1205 = t503*t1199 + t584*t1118;
    const V t1206 = t503*t1200 + t584*t1119;
    const V t1207 = t1164*dat[77] + t1172*dat[80];
    const V t1208 = t1156*dat[74] + t1173*dat[80];
    const V t1209 = t1157*dat[74] + t1165*dat[77];
    const V t1210 = t1158*dat[74] + t1166*dat[77] + t1174*dat[80];
    const V t1211 = t1159*dat[74] + t1167*dat[77] + t1175*dat[80];
    const V t1212 = t1160*dat[74] + t1168*dat[77] + t1176*dat[80];
    const V t1213 = t1161*dat[74] + t1169*dat[77] + t1177*dat[80];
    const V t1214 = t1162*dat[74] + t1170*dat[77] + t1178*dat[80];
    const V t1215 = t1163*dat[74] + t1171*dat[77] + t1179*dat[80];
    const V t1216 = (T(0.5))*t1114;
    const V t1217 = (T(0.5))*t1115;
    const V t1218 = (T(0.5))*t1116;
    const V t1219 = (T(0.5))*t1117;
    const V t1220 = (T(0.5))*t1118;
    const V t1221 = (T(0.5))*t1119;
    const V t1222 = t508*t1195 + t584*t1120;
    const V t1223 = t508*t1196 + t584*t1121;
    const V t1224 = t508*t1197 + t584*t1122;
    const V t1225 = t508*t1198 + t584*t1123;
    const V t1226 = t508*t1199 + t584*t1124;
    const V t1227 = t508*t1200 + t584*t1125;
    const V t1228 = t1164*dat[78] + t1172*dat[81];
    const V t1229 = t1156*dat[75] + t1173*dat[81];
    const V t1230 = t1157*dat[75] + t1165*dat[78];
    const V t1231 = t1158*dat[75] + t1166*dat[78] + t1174*dat[81];
    const V t1232 = t1159*dat[75] + t1167*dat[78] + t1175*dat[81];
    const V t1233 = t1160*dat[75] + t1168*dat[78] + t1176*dat[81];
    const V t1234 = t1161*dat[75] + t1169*dat[78] + t1177*dat[81];
    const V t1235 = t1162*dat[75] + t1170*dat[78] + t1178*dat[81];
    const V t1236 = t1163*dat[75] + t1171*dat[78] + t1179*dat[81];
    const V t1237 = (T(0.5))*t1108;
    const V t1238 = (T(0.5))*t1109;
    const V t1239 = (T(0.5))*t1110;
    const V t1240 = (T(0.5))*t1111;
    const V t1241 = (T(0.5))*t1112;
    const V t1242 = (T(0.5))*t1113;
    const V t1243 = t531*t1150 + t580*t1120 + t581*t1114;
    const V t1244 = t531*t1151 + t580*t1121 + t581*t1115;
    const V t1245 = t531*t1152 + t580*t1122 + t581*t1116;
    const V t1246 = t531*t1153 + t580*t1123 + t581*t1117;
    const V t1247 = t531*t1154 + t580*t1124 + t581*t1118;
    const V t1248 = t531*t1155 + t580*t1125 + t581*t1119;
    // every output once, as a whole V, before it is taken apart lane by lane
    const V o0 = t241;
    const V o1 = t260;
    const V o2 = t278;
    const V o3 = t293;
    const V o4 = t308;
    const V o5 = t323;
    const V o6 = t349;
    const V o7 = t375;
    const V o8 = t401;
    const V o9 = t427;
    const V o10 = t453;
    const V o11 = t479;
    const V o12 = t135;
    const V o13 = t612;
    const V o14 = t613;
    const V o15 = t614;
    const V o16 = t615;
    const V o17 = t616;
    const V o18 = t617;
    const V o19 = t618;
    const V o20 = t619;
    const V o21 = t620;
    const V o22 = t621;
    const V o23 = t622;
    const V o24 = t623;
    const V o25 = t133;
    const V o26 = t624;
    const V o27 = t625;
    const V o28 = t626;
    const V o29 = t627;
    const V o30 = t628;
    const V o31 = t629;
    const V o32 = t630;
    const V o33 = t631;
    const V o34 = t632;
    const V o35 = t633;
    const V o36 = t634;
    const V o37 = t635;
    const V o38 = t138;
    const V o39 = t684*t734 + t733*t685 + t793*t807 + t806*t794 + t853*t867 + t866*t854;
    const V o40 = t684*t735 + t733*t686 + t793*t808 + t806*t795 + t853*t868 + t866*t855;
    const V o41 = t684*t736 + t733*t687 + t793*t809 + t806*t796 + t853*t869 + t866*t856;
    const V o42 = t684*t737 + t793*t810 + t853*t870;
    const V o43 = t684*t738 + t793*t811 + t853*t871;
    const V o44 = t684*t739 + t793*t812 + t853*t872;
    const V o45 = t684*t740 + t793*t813 + t853*t873;
    const V o46 = t684*t741 + t793*t814 + t853*t874;
    const V o47 = t684*t742 + t793*t815 + t853*t875;
    const V o48 = t733*t688 + t793*t816 + t806*t797 + t853*t876 + t866*t857;
    const V o49 = t684*t743 + t733*t689 + t806*t798 + t853*t877 + t866*t858;
    const V o50 = t684*t744 + t733*t690 + t793*t817 + t806*t799 + t866*t859;
    const V o51 = t684*t745 + t793*t818 + t853*t878;
    const V o52 = t684*t746 + t793*t819 + t853*t879;
    const V o53 = t684*t747 + t793*t820 + t853*t880;
    const V o54 = t684*t748 + t733*t691 + t793*t821 + t806*t800 + t853*t881 + t866*t860;
    const V o55 = t684*t749 + t733*t692 + t793*t822 + t806*t801 + t853*t882 + t866*t861;
    const V o56 = t684*t750 + t733*t693 + t793*t823 + t806*t802 + t853*t883 + t866*t862;
    const V o57 = t684*t751 + t733*t694 + t793*t824 + t806*t803 + t853*t884 + t866*t863;
    const V o58 = t684*t752 + t733*t695 + t793*t825 + t806*t804 + t853*t885 + t866*t864;
    const V o59 = t684*t753 + t733*t696 + t793*t826 + t806*t805 + t853*t886 + t866*t865;
    const V o60 = t684*t733 + t793*t806 + t853*t866;
    const V o61 = t733*t940 + t806*t888 + t866*t927 + t887*t807 + t926*t867 + t939*t734;
    const V o62 = t733*t941 + t806*t889 + t866*t928 + t887*t808 + t926*t868 + t939*t735;
    const V o63 = t733*t942 + t806*t890 + t866*t929 + t887*t809 + t926*t869 + t939*t736;
    const V o64 = t887*t810 + t926*t870 + t939*t737;
    const V o65 = t887*t811 + t926*t871 + t939*t738;
    const V o66 = t887*t812 + t926*t872 + t939*t739;
    const V o67 = t887*t813 + t926*t873 + t939*t740;
    const V o68 = t887*t814 + t926*t874 + t939*t741;
    const V o69 = t887*t815 + t926*t875 + t939*t742;
    const V o70 = t733*t943 + t806*t891 + t866*t930 + t887*t816 + t926*t876;
    const V o71 = t733*t944 + t806*t892 + t866*t931 + t926*t877 + t939*t743;
    const V o72 = t733*t945 + t806*t893 + t866*t932 + t887*t817 + t939*t744;
    const V o73 = t887*t818 + t926*t878 + t939*t745;
    const V o74 = t887*t819 + t926*t879 + t939*t746;
    const V o75 = t887*t820 + t926*t880 + t939*t747;
    const V o76 = t733*t946 + t806*t894 + t866*t933 + t887*t821 + t926*t881 + t939*t748;
    const V o77 = t733*t947 + t806*t895 + t866*t934 + t887*t822 + t926*t882 + t939*t749;
    const V o78 = t733*t948 + t806*t896 + t866*t935 + t887*t823 + t926*t883 + t939*t750;
    const V o79 = t733*t949 + t806*t897 + t866*t936 + t887*t824 + t926*t884 + t939*t751;
    const V o80 = t733*t950 + t806*t898 + t866*t937 + t887*t825 + t926*t885 + t939*t752;
    const V o81 = t733*t951 + t806*t899 + t866*t938 + t887*t826 + t926*t886 + t939*t753;
    const V o82 = t733*t939 + t806*t887 + t866*t926;
    const V o83 = t733*t966 + t806*t979 + t866*t953 + t952*t867 + t965*t734 + t978*t807;
    const V o84 = t733*t967 + t806*t980 + t866*t954 + t952*t868 + t965*t735 + t978*t808;
    const V o85 = t733*t968 + t806*t981 + t866*t955 + t952*t869 + t965*t736 + t978*t809;
    const V o86 = t952*t870 + t965*t737 + t978*t810;
    const V o87 = t952*t871 + t965*t738 + t978*t811;
    const V o88 = t952*t872 + t965*t739 + t978*t812;
    const V o89 = t952*t873 + t965*t740 + t978*t813;
    const V o90 = t952*t874 + t965*t741 + t978*t814;
    const V o91 = t952*t875 + t965*t742 + t978*t815;
    const V o92 = t733*t969 + t806*t982 + t866*t956 + t952*t876 + t978*t816;
    const V o93 = t733*t970 + t806*t983 + t866*t957 + t952*t877 + t965*t743;
    const V o94 = t733*t971 + t806*t984 + t866*t958 + t965*t744 + t978*t817;
    const V o95 = t952*t878 + t965*t745 + t978*t818;
    const V o96 = t952*t879 + t965*t746 + t978*t819;
    const V o97 = t952*t880 + t965*t747 + t978*t820;
    const V o98 = t733*t972 + t806*t985 + t866*t959 + t952*t881 + t965*t748 + t978*t821;
    const V o99 = t733*t973 + t806*t986 + t866*t960 + t952*t882 + t965*t749 + t978*t822;
    const V o100 = t733*t974 + t806*t987 + t866*t961 + t952*t883 + t965*t750 + t978*t823;
    const V o101 = t733*t975 + t806*t988 + t866*t962 + t952*t884 + t965*t751 + t978*t824;
    const V o102 = t733*t976 + t806*t989 + t866*t963 + t952*t885 + t965*t752 + t978*t825;
    const V o103 = t733*t977 + t806*t990 + t866*t964 + t952*t886 + t965*t753 + t978*t826;
    const V o104 = t733*t965 + t806*t978 + t866*t952;
    const V o105 = t684*t1019 + t793*t1034 + t853*t1049 + t1018*t685 + t1033*t794 + t1048*t854;
    const V o106 = t684*t1020 + t793*t1035 + t853*t1050 + t1018*t686 + t1033*t795 + t1048*t855;
    const V o107 = t684*t1021 + t793*t1036 + t853*t1051 + t1018*t687 + t1033*t796 + t1048*t856;
    const V o108 = t684*in[15] + t793*in[16] + t853*in[17];
    const V o109 = t684*in[18] + t793*in[19] + t853*in[20];
    const V o110 = t684*in[21] + t793*in[22] + t853*in[23];
    const V o111 = t793*t1037 + t853*t1052 + t1018*t688 + t1033*t797 + t1048*t857;
    const V o112 = t684*t1022 + t853*t1053 + t1018*t689 + t1033*t798 + t1048*t858;
    const V o113 = t684*t1023 + t793*t1038 + t1018*t690 + t1033*t799 + t1048*t859;
    const V o114 = t684*t1024 + t793*t1039 + t853*t1054;
    const V o115 = t684*t1025 + t793*t1040 + t853*t1055;
    const V o116 = t684*t1026 + t793*t1041 + t853*t1056;
    const V o117 = t684*t1027 + t793*t1042 + t853*t1057 + t1018*t691 + t1033*t800 + t1048*t860;
    const V o118 = t684*t1028 + t793*t1043 + t853*t1058 + t1018*t692 + t1033*t801 + t1048*t861;
    const V o119 = t684*t1029 + t793*t1044 + t853*t1059 + t1018*t693 + t1033*t802 + t1048*t862;
    const V o120 = t684*t1030 + t793*t1045 + t853*t1060 + t1018*t694 + t1033*t803 + t1048*t863;
    const V o121 = t684*t1031 + t793*t1046 + t853*t1061 + t1018*t695 + t1033*t804 + t1048*t864;
    const V o122 = t684*t1032 + t793*t1047 + t853*t1062 + t1018*t696 + t1033*t805 + t1048*t865;
    const V o123 = t684*t1018 + t793*t1033 + t853*t1048;
    const V o124 = t887*t1034 + t926*t1049 + t939*t1019 + t1018*t940 + t1033*t888 + t1048*t927;
    const V o125 = t887*t1035 + t926*t1050 + t939*t1020 + t1018*t941 + t1033*t889 + t1048*t928;
    const V o126 = t887*t1036 + t926*t1051 + t939*t1021 + t1018*t942 + t1033*t890 + t1048*t929;
    const V o127 = t887*in[16] + t926*in[17] + t939*in[15];
    const V o128 = t887*in[19] + t926*in[20] + t939*in[18];
    const V o129 = t887*in[22] + t926*in[23] + t939*in[21];
    const V o130 = t887*t1037 + t926*t1052 + t1018*t943 + t1033*t891 + t1048*t930;
    const V o131 = t926*t1053 + t939*t1022 + t1018*t944 + t1033*t892 + t1048*t931;
    const V o132 = t887*t1038 + t939*t1023 + t1018*t945 + t1033*t893 + t1048*t932;
    const V o133 = t887*t1039 + t926*t1054 + t939*t1024;
    const V o134 = t887*t1040 + t926*t1055 + t939*t1025;
    const V o135 = t887*t1041 + t926*t1056 + t939*t1026;
    const V o136 = t887*t1042 + t926*t1057 + t939*t1027 + t1018*t946 + t1033*t894 + t1048*t933;
    const V o137 = t887*t1043 + t926*t1058 + t939*t1028 + t1018*t947 + t1033*t895 + t1048*t934;
    const V o138 = t887*t1044 + t926*t1059 + t939*t1029 + t1018*t948 + t1033*t896 + t1048*t935;
    const V o139 = t887*t1045 + t926*t1060 + t939*t1030 + t1018*t949 + t1033*t897 + t1048*t936;
    const V o140 = t887*t1046 + t926*t1061 + t939*t1031 + t1018*t950 + t1033*t898 + t1048*t937;
    const V o141 = t887*t1047 + t926*t1062 + t939*t1032 + t1018*t951 + t1033*t899 + t1048*t938;
    const V o142 = t887*t1033 + t926*t1048 + t939*t1018;
    const V o143 = t952*t1049 + t965*t1019 + t978*t1034 + t1018*t966 + t1033*t979 + t1048*t953;
    const V o144 = t952*t1050 + t965*t1020 + t978*t1035 + t1018*t967 + t1033*t980 + t1048*t954;
    const V o145 = t952*t1051 + t965*t1021 + t978*t1036 + t1018*t968 + t1033*t981 + t1048*t955;
    const V o146 = t952*in[17] + t965*in[15] + t978*in[16];
    const V o147 = t952*in[20] + t965*in[18] + t978*in[19];
    const V o148 = t952*in[23] + t965*in[21] + t978*in[22];
    const V o149 = t952*t1052 + t978*t1037 + t1018*t969 + t1033*t982 + t1048*t956;
    const V o150 = t952*t1053 + t965*t1022 + t1018*t970 + t1033*t983 + t1048*t957;
    const V o151 = t965*t1023 + t978*t1038 + t1018*t971 + t1033*t984 + t1048*t958;
    const V o152 = t952*t1054 + t965*t1024 + t978*t1039;
    const V o153 = t952*t1055 + t965*t1025 + t978*t1040;
    const V o154 = t952*t1056 + t965*t1026 + t978*t1041;
    const V o155 = t952*t1057 + t965*t1027 + t978*t1042 + t1018*t972 + t1033*t985 + t1048*t959;
    const V o156 = t952*t1058 + t965*t1028 + t978*t1043 + t1018*t973 + t1033*t986 + t1048*t960;
    const V o157 = t952*t1059 + t965*t1029 + t978*t1044 + t1018*t974 + t1033*t987 + t1048*t961;
    const V o158 = t952*t1060 + t965*t1030 + t978*t1045 + t1018*t975 + t1033*t988 + t1048*t962;
    const V o159 = t952*t1061 + t965*t1031 + t978*t1046 + t1018*t976 + t1033*t989 + t1048*t963;
    const V o160 = t952*t1062 + t965*t1032 + t978*t1047 + t1018*t977 + t1033*t990 + t1048*t964;
    const V o161 = t952*t1048 + t965*t1018 + t978*t1033;
    const V o164 = in[30] - in[36];
    const V o167 = in[31] - in[37];
    const V o170 = in[32] - in[38];
    const V o173 = in[33] - in[39];
    const V o176 = in[34] - in[40];
    const V o179 = in[35] - in[41];
    const V o180 = t1108;
    const V o181 = t1109;
    const V o182 = t1110;
    const V o183 = t1111;
    const V o184 = t1112;
    const V o185 = t1113;
    const V o186 = t505;
    const V o187 = t1114;
    const V o188 = t1115;
    const V o189 = t1116;
    const V o190 = t1117;
    const V o191 = t1118;
    const V o192 = t1119;
    const V o193 = t503;
    const V o194 = t1120;
    const V o195 = t1121;
    const V o196 = t1122;
    const V o197 = t1123;
    const V o198 = t1124;
    const V o199 = t1125;
    const V o200 = t508;
    const V o201 = t582*t1180 + t586*t1207 + t589*t1228 - t604*t1150 - t605*t1138 + t606*t1189 + t606*t1201 - t609*t1216 + t609*t1222;
    const V o202 = t582*t1181 + t586*t1208 + t589*t1229 - t604*t1151 - t605*t1139 + t606*t1190 + t606*t1202 - t609*t1217 + t609*t1223;
    const V o203 = t582*t1182 + t586*t1209 + t589*t1230 - t604*t1152 - t605*t1140 + t606*t1191 + t606*t1203 - t609*t1218 + t609*t1224;
    const V o204 = t582*t1183 + t586*t1210 + t589*t1231;
    const V o205 = t582*t1184 + t586*t1211 + t589*t1232;
    const V o206 = t582*t1185 + t586*t1212 + t589*t1233;
    const V o207 = -t604*t1153 - t605*t1141 + t606*t1192 + t606*t1204 - t609*t1219 + t609*t1225;
    const V o208 = -t604*t1154 - t605*t1142 + t606*t1193 + t606*t1205 - t609*t1220 + t609*t1226;
    const V o209 = -t604*t1155 - t605*t1143 + t606*t1194 + t606*t1206 - t609*t1221 + t609*t1227;
    const V o210 = t582*t1186 + t586*t1213 + t589*t1234;
    const V o211 = t582*t1187 + t586*t1214 + t589*t1235;
    const V o212 = t582*t1188 + t586*t1215 + t589*t1236;
    const V o213 = t582*t603 + t586*t606 + t589*t609;
    const V o214 = t590*t1180 + t592*t1207 + t595*t1228 + t607*t1150 - t608*t1132 - t608*t1144 - t603*t1189 + t603*t1201 + t609*t1237 + t609*t1243;
    const V o215 = t590*t1181 + t592*t1208 + t595*t1229 + t607*t1151 - t608*t1133 - t608*t1145 - t603*t1190 + t603*t1202 + t609*t1238 + t609*t1244;
    const V o216 = t590*t1182 + t592*t1209 + t595*t1230 + t607*t1152 - t608*t1134 - t608*t1146 - t603*t1191 + t603*t1203 + t609*t1239 + t609*t1245;
    const V o217 = t590*t1183 + t592*t1210 + t595*t1231;
    const V o218 = t590*t1184 + t592*t1211 + t595*t1232;
    const V o219 = t590*t1185 + t592*t1212 + t595*t1233;
    const V o220 = t607*t1153 - t608*t1135 - t608*t1147 - t603*t1192 + t603*t1204 + t609*t1240 + t609*t1246;
    const V o221 = t607*t1154 - t608*t1136 - t608*t1148 - t603*t1193 + t603*t1205 + t609*t1241 + t609*t1247;
    const V o222 = t607*t1155 - t608*t1137 - t608*t1149 - t603*t1194 + t603*t1206 + t609*t1242 + t609*t1248;
    const V o223 = t590*t1186 + t592*t1213 + t595*t1234;
    const V o224 = t590*t1187 + t592*t1214 + t595*t1235;
    const V o225 = t590*t1188 + t592*t1215 + t595*t1236;
    const V o226 = t590*t603 + t592*t606 + t595*t609;
    const V o227 = t596*t1180 + t597*t1207 + t599*t1228 + t610*t1150 - t611*t1126 - t611*t1144 + t603*t1216 + t603*t1222 - t606*t1237 + t606*t1243;
    const V o228 = t596*t1181 + t597*t1208 + t599*t1229 + t610*t1151 - t611*t1127 - t611*t1145 + t603*t1217 + t603*t1223 - t606*t1238 + t606*t1244;
    const V o229 = t596*t1182 + t597*t1209 + t599*t1230 + t610*t1152 - t611*t1128 - t611*t1146 + t603*t1218 + t603*t1224 - t606*t1239 + t606*t1245;
    const V o230 = t596*t1183 + t597*t1210 + t599*t1231;
    const V o231 = t596*t1184 + t597*t1211 + t599*t1232;
    const V o232 = t596*t1185 + t597*t1212 + t599*t1233;
    const V o233 = t610*t1153 - t611*t1129 - t611*t1147 + t603*t1219 + t603*t1225 - t606*t1240 + t606*t1246;
    const V o234 = t610*t1154 - t611*t1130 - t611*t1148 + t603*t1220 + t603*t1226 - t606*t1241 + t606*t1247;
    const V o235 = t610*t1155 - t611*t1131 - t611*t1149 + t603*t1221 + t603*t1227 - t606*t1242 + t606*t1248;
    const V o236 = t596*t1186 + t597*t1213 + t599*t1234;
    const V o237 = t596*t1187 + t597*t1214 + t599*t1235;
    const V o238 = t596*t1188 + t597*t1215 + t599*t1236;
    const V o239 = t596*t603 + t597*t606 + t599*t609;
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
        ab[l][480] = lane(o180, l);
        ab[l][481] = lane(o181, l);
        ab[l][482] = lane(o182, l);
        ab[l][489] = lane(o183, l);
        ab[l][490] = lane(o184, l);
        ab[l][491] = lane(o185, l);
        ab[l][510] = lane(o186, l);
        ab[l][512] = lane(o187, l);
        ab[l][513] = lane(o188, l);
        ab[l][514] = lane(o189, l);
        ab[l][521] = lane(o190, l);
        ab[l][522] = lane(o191, l);
        ab[l][523] = lane(o192, l);
        ab[l][542] = lane(o193, l);
        ab[l][544] = lane(o194, l);
        ab[l][545] = lane(o195, l);
        ab[l][546] = lane(o196, l);
        ab[l][553] = lane(o197, l);
        ab[l][554] = lane(o198, l);
        ab[l][555] = lane(o199, l);
        ab[l][574] = lane(o200, l);
        ab[l][576] = lane(o201, l);
        ab[l][577] = lane(o202, l);
        ab[l][578] = lane(o203, l);
        ab[l][579] = lane(o204, l);
        ab[l][580] = lane(o205, l);
        ab[l][581] = lane(o206, l);
        ab[l][585] = lane(o207, l);
        ab[l][586] = lane(o208, l);
        ab[l][587] = lane(o209, l);
        ab[l][588] = lane(o210, l);
        ab[l][589] = lane(o211, l);
        ab[l][590] = lane(o212, l);
        ab[l][606] = lane(o213, l);
        ab[l][608] = lane(o214, l);
        ab[l][609] = lane(o215, l);
        ab[l][610] = lane(o216, l);
        ab[l][611] = lane(o217, l);
        ab[l][612] = lane(o218, l);
        ab[l][613] = lane(o219, l);
        ab[l][617] = lane(o220, l);
        ab[l][618] = lane(o221, l);
        ab[l][619] = lane(o222, l);
        ab[l][620] = lane(o223, l);
        ab[l][621] = lane(o224, l);
        ab[l][622] = lane(o225, l);
        ab[l][638] = lane(o226, l);
        ab[l][640] = lane(o227, l);
        ab[l][641] = lane(o228, l);
        ab[l][642] = lane(o229, l);
        ab[l][643] = lane(o230, l);
        ab[l][644] = lane(o231, l);
        ab[l][645] = lane(o232, l);
        ab[l][649] = lane(o233, l);
        ab[l][650] = lane(o234, l);
        ab[l][651] = lane(o235, l);
        ab[l][652] = lane(o236, l);
        ab[l][653] = lane(o237, l);
        ab[l][654] = lane(o238, l);
        ab[l][670] = lane(o239, l);
    }
}

void cost_3(const V* in, const V* dat, T half[LANES][2]) {
#pragma HLS PIPELINE II=1
    const V t0 = in[0]*in[15] + in[3]*in[18] + in[6]*in[21];
    const V t1 = t0;
    const V t2 = in[1]*in[15] + in[4]*in[18] + in[7]*in[21];
    const V t3 = t2;
    const V t4 = in[2]*in[15] + in[5]*in[18] + in[8]*in[21];
    const V t5 = t4;
    const V t6 = t1*dat[73] + t3*dat[76] + t5*dat[79];
    const V t7 = in[0]*in[16] + in[3]*in[19] + in[6]*in[22];
    const V t8 = t7;
    const V t9 = in[1]*in[16] + in[4]*in[19] + in[7]*in[22];
    const V t10 = t9;
    const V t11 = in[2]*in[16] + in[5]*in[19] + in[8]*in[22];
    const V t12 = t11;
    const V t13 = t8*dat[73] + t10*dat[76] + t12*dat[79];
    const V t14 = in[0]*in[17] + in[3]*in[20] + in[6]*in[23];
    const V t15 = t14;
    const V t16 = in[1]*in[17] + in[4]*in[20] + in[7]*in[23];
    const V t17 = t16;
    const V t18 = in[2]*in[17] + in[5]*in[20] + in[8]*in[23];
    const V t19 = t18;
    const V t20 = t15*dat[73] + t17*dat[76] + t19*dat[79];
    const V t21 = t1*dat[74] + t3*dat[77] + t5*dat[80];
    const V t22 = t8*dat[74] + t10*dat[77] + t12*dat[80];
    const V t23 = t15*dat[74] + t17*dat[77] + t19*dat[80];
    const V t24 = t1*dat[75] + t3*dat[78] + t5*dat[81];
    const V t25 = t8*dat[75] + t10*dat[78] + t12*dat[81];
    const V t26 = t15*dat[75] + t17*dat[78] + t19*dat[81];
    V tlog0[3]; v_so3_log(t6, t13, t20, t21, t22, t23, t24, t25, t26, tlog0);
    const V t27 = tlog0[0];
    const V t28 = (t27*t27);
    const V t29 = tlog0[1];
    const V t30 = (t29*t29);
    const V t31 = tlog0[2];
    const V t32 = (t31*t31);
    const V t33 = in[30] - dat[63];
    const V t34 = in[31] - dat[64];
    const V t35 = in[32] - dat[65];
    const V t36 = in[33] - dat[66];
    const V t37 = in[34] - dat[67];
    const V t38 = in[35] - dat[68];
    const V t39 = t33*dat[12] + t34*dat[13] + t35*dat[14] + t36*dat[39] + t37*dat[40] + t38*dat[41] + dat[1];
    const V t40 = -t39;
    const V t41 = t39*t40;
    const V t42 = t33*dat[15] + t34*dat[16] + t35*dat[17] + t36*dat[42] + t37*dat[43] + t38*dat[44] + dat[2];
    const V t43 = -t42;
    const V t44 = t43*t42;
    const V t45 = t44 + t41;
    const V t46 = t33*dat[9] + t34*dat[10] + t35*dat[11] + t36*dat[36] + t37*dat[37] + t38*dat[38] + dat[0];
    const V t47 = (t46*t46) + (t39*t39) + (t42*t42);
    const V t48 = v_lie_B(t47);
    const V t49 = t45*t48 + T(1);
    const V t50 = -t46;
    const V t51 = v_lie_A(t47);
    const V t52 = t48*t40;
    const V t53 = t51*t42 + t50*t52;
    const V t54 = t46*t48;
    const V t55 = t51*t40 + t54*t42;
    const V t56 = t49*t1 + t53*t3 + t55*t5;
    const V t57 = t46*t50;
    const V t58 = t44 + t57;
    const V t59 = t58*t48 + T(1);
    const V t60 = t43*t52 + t46*t51;
    const V t61 = t43*t51 + t54*t39;
    const V t62 = t1*t61 + t3*t59 + t5*t60;
    const V t63 = t57 + t41;
    const V t64 = t63*t48 + T(1);
    const V t65 = t43*t48;
    const V t66 = t65*t50 + t51*t39;
    const V t67 = t48*t39;
    const V t68 = t67*t42 + t51*t50;
    const V t69 = t1*t66 + t3*t68 + t5*t64;
    const V t70 = t49*t8 + t53*t10 + t55*t12;
    const V t71 = t59*t10 + t60*t12 + t61*t8;
    const V t72 = t64*t12 + t66*t8 + t68*t10;
    const V t73 = t49*t15 + t53*t17 + t55*t19;
    const V t74 = t59*t17 + t60*t19 + t61*t15;
    const V t75 = t64*t19 + t66*t15 + t68*t17;
    V tlog1[3]; v_so3_log(t56, t62, t69, t70, t71, t72, t73, t74, t75, tlog1);
    const V t76 = tlog1[1];
    const V t77 = (t76*t76);
    const V t78 = t77;
    const V t79 = tlog1[2];
    const V t80 = (t79*t79);
    const V t81 = t80;
    const V t82 = t78 + t81;
    const V t83 = tlog1[0];
    const V t84 = (t83*t83);
    const V t85 = t84;
    const V t86 = t82 + t85;
    const V t87 = v_lie_D(t86);
    const V t88 = -t82*t87 + T(1);
    const V t89 = in[9] - in[24];
    const V t90 = t33*dat[18] + t34*dat[19] + t35*dat[20] + t36*dat[45] + t37*dat[46] + t38*dat[47] + dat[3];
    const V t91 = t33*dat[21] + t34*dat[22] + t35*dat[23] + t36*dat[48] + t37*dat[49] + t38*dat[50] + dat[4];
    const V t92 = t33*dat[24] + t34*dat[25] + t35*dat[26] + t36*dat[51] + t37*dat[52] + t38*dat[53] + dat[5];
    const V t93 = (T(0.5))*(dat[69]*dat[69]);
    const V t94 = t89 + t90*in[0] + t91*in[1] + t92*in[2] + t93*dat[70] + dat[69]*in[12];
    const V t95 = in[10] - in[25];
    const V t96 = t95 + t90*in[3] + t91*in[4] + t92*in[5] + t93*dat[71] + dat[69]*in[13];
    const V t97 = in[11] - in[26];
    const V t98 = t97 + t90*in[6] + t91*in[7] + t92*in[8] + t93*dat[72] + dat[69]*in[14];
    const V t99 = t94*in[15] + t96*in[18] + t98*in[21];
    const V t100 = t99;
    const V t101 = (T(0.5))*t79;
    const V t102 = t101;
    const V t103 = t83*t87;
    const V t104 = t76*t103;
    const V t105 = t102 + t104;
    const V t106 = t94*in[16] + t96*in[19] + t98*in[22];
    const V t107 = t106;
    const V t108 = (T(0.5))*t76;
    const V t109 = t108;
    const V t110 = t79*t103;
    const V t111 = -t109 + t110;
    const V t112 = t94*in[17] + t96*in[20] + t98*in[23];
    const V t113 = t112;
    const V t114 = t88*t100 + t105*t107 + t111*t113;
    const V t115 = -t81 - t85;
    const V t116 = t115*t87 + T(1);
    const V t117 = (T(0.5))*t83;
    const V t118 = t117;
    const V t119 = t76*t79;
    const V t120 = t119*t87;
    const V t121 = t118 + t120;
    const V t122 = -t102 + t104;
    const V t123 = t100*t122 + t107*t116 + t113*t121;
    const V t124 = -t78 - t85;
    const V t125 = t124*t87 + T(1);
    const V t126 = t109 + t110;
    const V t127 = -t118 + t120;
    const V t128 = t100*t126 + t107*t127 + t113*t125;
    const V t129 = t33*dat[27] + t34*dat[28] + t35*dat[29] + t36*dat[54] + t37*dat[55] + t38*dat[56] + dat[6];
    const V t130 = t33*dat[30] + t34*dat[31] + t35*dat[32] + t36*dat[57] + t37*dat[58] + t38*dat[59] + dat[7];
    const V t131 = t33*dat[33] + t34*dat[34] + t35*dat[35] + t36*dat[60] + t37*dat[61] + t38*dat[62] + dat[8];
    const V t132 = t129*in[0] + t130*in[1] + t131*in[2] + dat[69]*dat[70] + in[12] - in[27];
    const V t133 = t129*in[3] + t130*in[4] + t131*in[5] + dat[69]*dat[71] + in[13] - in[28];
    const V t134 = t129*in[6] + t130*in[7] + t131*in[8] + dat[69]*dat[72] + in[14] - in[29];
    const V t135 = t132*in[15] + t133*in[18] + t134*in[21];
    const V t136 = t135;
    const V t137 = t132*in[16] + t133*in[19] + t134*in[22];
    const V t138 = t137;
    const V t139 = t132*in[17] + t133*in[20] + t134*in[23];
    const V t140 = t139;
    const V t141 = t88*t136 + t105*t138 + t111*t140;
    const V t142 = t116*t138 + t121*t140 + t122*t136;
    const V t143 = t125*t140 + t126*t136 + t127*t138;
    const V t144 = in[30] - in[36];
    const V t145 = in[31] - in[37];
    const V t146 = in[32] - in[38];
    const V t147 = in[33] - in[39];
    const V t148 = in[34] - in[40];
    const V t149 = in[35] - in[41];
    const V t150 = t30;
    const V t151 = t150;
    const V t152 = t32;
    const V t153 = t152;
    const V t154 = t151 + t153;
    const V t155 = t28;
    const V t156 = t155;
    const V t157 = t154 + t156;
    const V t158 = v_lie_D(t157);
    const V t159 = -t154*t158 + T(1);
    const V t160 = (T(0.5))*t31;
    const V t161 = t160;
    const V t162 = t158*t27;
    const V t163 = t29*t162;
    const V t164 = t161 + t163;
    const V t165 = (T(0.5))*t29;
    const V t166 = t165;
    const V t167 = t31*t162;
    const V t168 = -t166 + t167;
    const V t169 = -in[0]*in[9] + in[0]*in[24] - in[3]*in[10] + in[3]*in[25] - in[6]*in[11] + in[6]*in[26];
    const V t170 = -in[1]*in[9] + in[1]*in[24] - in[4]*in[10] + in[4]*in[25] - in[7]*in[11] + in[7]*in[26];
    const V t171 = -in[2]*in[9] + in[2]*in[24] - in[5]*in[10] + in[5]*in[25] - in[8]*in[11] + in[8]*in[26];
    const V t172 = t169*dat[73] + t170*dat[76] + t171*dat[79] - dat[73]*dat[82] - dat[76]*dat[83] - dat[79]*dat[84];
    const V t173 = t169*dat[74] + t170*dat[77] + t171*dat[80] - dat[74]*dat[82] - dat[77]*dat[83] - dat[80]*dat[84];
    const V t174 = t169*dat[75] + t170*dat[78] + t171*dat[81] - dat[75]*dat[82] - dat[78]*dat[83] - dat[81]*dat[84];
    const V t175 = t159*t172 + t164*t173 + t168*t174;
    const V t176 = -t161 + t163;
    const V t177 = -t153 - t156;
    const V t178 = t177*t158 + T(1);
    const V t179 = (T(0.5))*t27;
    const V t180 = t179;
    const V t181 = t29*t31;
    const V t182 = t181*t158;
    const V t183 = t180 + t182;
    const V t184 = t176*t172 + t178*t173 + t183*t174;
    const V t185 = t166 + t167;
    const V t186 = -t180 + t182;
    const V t187 = -t151 - t156;
    const V t188 = t187*t158 + T(1);
    const V t189 = t185*t172 + t186*t173 + t188*t174;
    const V t190 = (T(0.5))*(t149*t149)*(dat[204]*dat[204]) + (T(0.5))*((t148*dat[202] + t149*dat[203])*(t148*dat[202] + t149*dat[203])) + (T(0.5))*((t147*dat[199] + t148*dat[200] + t149*dat[201])*(t147*dat[199] + t148*dat[200] + t149*dat[201])) + (T(0.5))*((t146*dat[195] + t147*dat[196] + t148*dat[197] + t149*dat[198])*(t146*dat[195] + t147*dat[196] + t148*dat[197] + t149*dat[198])) + (T(0.5))*((t145*dat[190] + t146*dat[191] + t147*dat[192] + t148*dat[193] + t149*dat[194])*(t145*dat[190] + t146*dat[191] + t147*dat[192] + t148*dat[193] + t149*dat[194])) + (T(0.5))*((t144*dat[184] + t145*dat[185] + t146*dat[186] + t147*dat[187] + t148*dat[188] + t149*dat[189])*(t144*dat[184] + t145*dat[185] + t146*dat[186] + t147*dat[187] + t148*dat[188] + t149*dat[189])) + (T(0.5))*((t144*dat[178] + t145*dat[179] + t146*dat[180] + t147*dat[181] + t148*dat[182] + t149*dat[183] + t143*dat[177])*(t144*dat[178] + t145*dat[179] + t146*dat[180] + t147*dat[181] + t148*dat[182] + t149*dat[183] + t143*dat[177])) + (T(0.5))*((t144*dat[171] + t145*dat[172] + t146*dat[173] + t147*dat[174] + t148*dat[175] + t149*dat[176] + t142*dat[169] + t143*dat[170])*(t144*dat[171] + t145*dat[172] + t146*dat[173] + t147*dat[174] + t148*dat[175] + t149*dat[176] + t142*dat[169] + t143*dat[170])) + (T(0.5))*((t144*dat[163] + t145*dat[164] + t146*dat[165] + t147*dat[166] + t148*dat[167] + t149*dat[168] + t141*dat[160] + t142*dat[161] + t143*dat[162])*(t144*dat[163] + t145*dat[164] + t146*dat[165] + t147*dat[166] + t148*dat[167] + t149*dat[168] + t141*dat[160] + t142*dat[161] + t143*dat[162])) + (T(0.5))*((t144*dat[154] + t145*dat[155] + t146*dat[156] + t147*dat[157] + t148*dat[158] + t149*dat[159] + t128*dat[150] + t141*dat[151] + t142*dat[152] + t143*dat[153])*(t144*dat[154] + t145*dat[155] + t146*dat[156] + t147*dat[157] + t148*dat[158] + t149*dat[159] + t128*dat[150] + t141*dat[151] + t142*dat[152] + t143*dat[153])) + (T(0.5))*((t144*dat[144] + t145*dat[145] + t146*dat[146] + t147*dat[147] + t148*dat[148] + t149*dat[149] + t123*dat[139] + t128*dat[140] + t141*dat[141] + t142*dat[142] + t143*dat[143])*(t144*dat[144] + t145*dat[145] + t146*dat[146] + t147*dat[147] + t148*dat[148] + t149*dat[149] + t123*dat[139] + t128*dat[140] + t141*dat[141] + t142*dat[142] + t143*dat[143])) + (T(0.5))*((t144*dat[133] + t145*dat[134] + t146*dat[135] + t147*dat[136] + t148*dat[137] + t149*dat[138] + t114*dat[127] + t123*dat[128] + t128*dat[129] + t141*dat[130] + t142*dat[131] + t143*dat[132])*(t144*dat[133] + t145*dat[134] + t146*dat[135] + t147*dat[136] + t148*dat[137] + t149*dat[138] + t114*dat[127] + t123*dat[128] + t128*dat[129] + t141*dat[130] + t142*dat[131] + t143*dat[132])) + (T(0.5))*((t144*dat[121] + t145*dat[122] + t146*dat[123] + t147*dat[124] + t148*dat[125] + t149*dat[126] + t114*dat[115] + t123*dat[116] + t128*dat[117] + t141*dat[118] + t142*dat[119] + t143*dat[120] + t79*dat[114])*(t144*dat[121] + t145*dat[122] + t146*dat[123] + t147*dat[124] + t148*dat[125] + t149*dat[126] + t114*dat[115] + t123*dat[116] + t128*dat[117] + t141*dat[118] + t142*dat[119] + t143*dat[120] + t79*dat[114])) + (T(0.5))*((t144*dat[108] + t145*dat[109] + t146*dat[110] + t147*dat[111] + t148*dat[112] + t149*dat[113] + t114*dat[102] + t123*dat[103] + t128*dat[104] + t141*dat[105] + t142*dat[106] + t143*dat[107] + t76*dat[100] + t79*dat[101])*(t144*dat[108] + t145*dat[109] + t146*dat[110] + t147*dat[111] + t148*dat[112] + t149*dat[113] + t114*dat[102] + t123*dat[103] + t128*dat[104] + t141*dat[105] + t142*dat[106] + t143*dat[107] + t76*dat[100] + t79*dat[101])) + (T(0.5))*((t144*dat[94] + t145*dat[95] + t146*dat[96] + t147*dat[97] + t148*dat[98] + t149*dat[99] + t114*dat[88] + t123*dat[89] + t128*dat[90] + t141*dat[91] + t142*dat[92] + t143*dat[93] + t83*dat[85] + t76*dat[86] + t79*dat[87])*(t144*dat[94] + t145*dat[95] + t146*dat[96] + t147*dat[97] + t148*dat[98] + t149*dat[99] + t114*dat[88] + t123*dat[89] + t128*dat[90] + t141*dat[91] + t142*dat[92] + t143*dat[93] + t83*dat[85] + t76*dat[86] + t79*dat[87]));
    const V t191 = (T(0.5))*t28*(dat[205]*dat[205]) + (T(0.5))*t30*(dat[206]*dat[206]) + (T(0.5))*(t175*t175)*(dat[208]*dat[208]) + (T(0.5))*(t184*t184)*(dat[209]*dat[209]) + (T(0.5))*t32*(dat[207]*dat[207]) + (T(0.5))*(t189*t189)*(dat[210]*dat[210]);
    const V o0 = t190;
    const V o1 = t191;
    for (int l = 0; l < LANES; ++l) {
        half[l][0] = lane(o0, l);
        half[l][1] = lane(o1, l);
    }
}

// block 4: GPSFactor (3 rows, 6 columns, 8 instances)
void jacobian_4(const V* in, const V* dat, T ab[LANES][24]) {
#pragma HLS PIPELINE II=1
    // every output once, as a whole V, before it is taken apart lane by lane
    const V o0 = in[0];
    const V o1 = in[1];
    const V o2 = in[2];
    const V o3 = -dat[0] + in[9];
    const V o4 = in[3];
    const V o5 = in[4];
    const V o6 = in[5];
    const V o7 = -dat[1] + in[10];
    const V o8 = in[6];
    const V o9 = in[7];
    const V o10 = in[8];
    const V o11 = -dat[2] + in[11];
    for (int l = 0; l < LANES; ++l) {
        ab[l][3] = lane(o0, l);
        ab[l][4] = lane(o1, l);
        ab[l][5] = lane(o2, l);
        ab[l][6] = lane(o3, l);
        ab[l][11] = lane(o4, l);
        ab[l][12] = lane(o5, l);
        ab[l][13] = lane(o6, l);
        ab[l][14] = lane(o7, l);
        ab[l][19] = lane(o8, l);
        ab[l][20] = lane(o9, l);
        ab[l][21] = lane(o10, l);
        ab[l][22] = lane(o11, l);
    }
}

void cost_4(const V* in, const V* dat, T half[LANES][1]) {
#pragma HLS PIPELINE II=1
    const V t0 = -dat[0] + in[9];
    const V t1 = -dat[1] + in[10];
    const V t2 = -dat[2] + in[11];
    const V t3 = (T(0.5))*(dat[3]*dat[3]);
    const V t4 = (t0*t0)*t3 + (t1*t1)*t3 + (t2*t2)*t3;
    const V o0 = t4;
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
V BLOCK0_LANED[(1 + LANES - 1) / LANES][18];

void lane_data_0() {
    for (int first = 0; first < 1; first += LANES) {
        T laned[18][LANES];
        for (int l = 0; l < LANES; ++l) {
            const int f = BLOCK0_INSTANCES[first + l < 1 ? first + l : 0];
            const T* line = DATA_BUF + FACTOR_DATA_OFF[f];
            for (int i = 0; i < 12; ++i) laned[0 + i][l] = line[0 + i];
            for (int i = 0; i < 6; ++i) laned[12 + i][l] = line[12 + i];
        }
        for (int i = 0; i < 18; ++i) BLOCK0_LANED[first / LANES][i] = load_lanes(laned[i]);
    }
}
#endif

// The inputs of instances BLOCK0_INSTANCES[first ...] into the lanes (lanes past the last
// instance repeat it; their results are not used): x's storage into `in`; returns where the data
// inputs are (on the host the laned data, in hardware the rest of `in`).
const V* gather_0(const T* x, int first, bool cost, V in[30]) {
#ifndef __SYNTHESIS__
    T buf[12][LANES];
    for (int l = 0; l < LANES; ++l) {
        const int f = BLOCK0_INSTANCES[first + l < 1 ? first + l : 0];
        const int vb = FACTOR_VAR_BEGIN[f];
        for (int i = 0; i < 12; ++i) buf[0 + i][l] = x[VAR_X_OFF[FACTOR_VARS[vb + 0]] + i];
    }
    for (int i = 0; i < 12; ++i) in[i] = load_lanes(buf[i]);
    (void)cost;
    return BLOCK0_LANED[first / LANES];
#else
    T buf[30][LANES];
    for (int l = 0; l < LANES; ++l) {
        const int f = BLOCK0_INSTANCES[first + l < 1 ? first + l : 0];
        const int vb = FACTOR_VAR_BEGIN[f];
        for (int i = 0; i < 12; ++i) buf[0 + i][l] = x[VAR_X_OFF[FACTOR_VARS[vb + 0]] + i];
        const T* line = DATA_BUF + FACTOR_DATA_OFF[f];
        for (int i = 0; i < 12; ++i) buf[12 + i][l] = line[0 + i];
        if (!cost) continue;
        for (int i = 0; i < 6; ++i) buf[24 + i][l] = line[12 + i];
    }
    for (int i = 0; i < (cost ? 30 : 24); ++i) {
#pragma HLS LOOP_TRIPCOUNT max=30
        in[i] = load_lanes(buf[i]);
    }
    return in + 12;
#endif
}

// block 0, instances first ... first + LANES - 1: residual + Jacobian (its 33
// structural non-zeros of 6 x 7), whiten. Mode 1 (noise_mode false): accumulate the gradient
// and the whitened rows into the A buffer; false if not finite. Mode 3 (true): only add
// the cost's rounding noise (how far the cost moves when x is rounded to T) to *noise. Mode 4
// (rows_out given, host only): copy each instance's whitened rows [A | b] (6 x 7, row-major)
// to rows_out + instance * 42, nothing else.
bool linearize_0(const T* x, int first, bool noise_mode, T* noise,
                   double* rows_out = nullptr) {
    V in[30];
    const V* dat = gather_0(x, first, false, in);
    // rows [J | r] padded to 8 (whole tiles): the Jacobian writes only its structural
    // non-zeros, so the zeros this buffer starts with are never overwritten
    static T raw[LANES][48];
    static T ab[LANES][48];  // the whitened rows, every entry written
    jacobian_0(in, dat, raw);
    bool finite = true;
    for (int l = 0; l < LANES; ++l) {
        if (first + l >= 1) continue;
        const int f = BLOCK0_INSTANCES[first + l];
        const int vb = FACTOR_VAR_BEGIN[f];
        const T* line = DATA_BUF + FACTOR_DATA_OFF[f];
        whiten<8, 7, 6, 1, 6>(raw[l] + 0, ab[l] + 0, line + 12);
        reweight<8, 7, 6>(ab[l] + 0, line[18], line[19]);
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

// block 0, mode 2: add the cost of instances first ... first + LANES - 1 to *total, in order
void cost_of_0(const T* x, int first, T* total) {
    V in[30];
    const V* dat = gather_0(x, first, true, in);
    T half[LANES][1];
    cost_0(in, dat, half);
    for (int l = 0; l < LANES; ++l) {
        if (first + l >= 1) continue;
        const T* line = DATA_BUF + FACTOR_DATA_OFF[BLOCK0_INSTANCES[first + l]];
        T cost = T(0);
        cost += robust_loss(half[l][0], line[18], line[19]);
        *total += cost;
    }
}

#ifndef __SYNTHESIS__
// The data inputs (measurements, then noise parameters) of every LANES instances, laned once per
// call by lane_data(): they are the same in every iteration, so a gather only lanes x and the
// kernels read the data in place.
V BLOCK1_LANED[(1 + LANES - 1) / LANES][4];

void lane_data_1() {
    for (int first = 0; first < 1; first += LANES) {
        T laned[4][LANES];
        for (int l = 0; l < LANES; ++l) {
            const int f = BLOCK1_INSTANCES[first + l < 1 ? first + l : 0];
            const T* line = DATA_BUF + FACTOR_DATA_OFF[f];
            for (int i = 0; i < 3; ++i) laned[0 + i][l] = line[0 + i];
            for (int i = 0; i < 1; ++i) laned[3 + i][l] = line[3 + i];
        }
        for (int i = 0; i < 4; ++i) BLOCK1_LANED[first / LANES][i] = load_lanes(laned[i]);
    }
}
#endif

// The inputs of instances BLOCK1_INSTANCES[first ...] into the lanes (lanes past the last
// instance repeat it; their results are not used): x's storage into `in`; returns where the data
// inputs are (on the host the laned data, in hardware the rest of `in`).
const V* gather_1(const T* x, int first, bool cost, V in[7]) {
#ifndef __SYNTHESIS__
    T buf[3][LANES];
    for (int l = 0; l < LANES; ++l) {
        const int f = BLOCK1_INSTANCES[first + l < 1 ? first + l : 0];
        const int vb = FACTOR_VAR_BEGIN[f];
        for (int i = 0; i < 3; ++i) buf[0 + i][l] = x[VAR_X_OFF[FACTOR_VARS[vb + 0]] + i];
    }
    for (int i = 0; i < 3; ++i) in[i] = load_lanes(buf[i]);
    (void)cost;
    return BLOCK1_LANED[first / LANES];
#else
    T buf[7][LANES];
    for (int l = 0; l < LANES; ++l) {
        const int f = BLOCK1_INSTANCES[first + l < 1 ? first + l : 0];
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

// block 1, instances first ... first + LANES - 1: residual + Jacobian (its 6
// structural non-zeros of 3 x 4), whiten. Mode 1 (noise_mode false): accumulate the gradient
// and the whitened rows into the A buffer; false if not finite. Mode 3 (true): only add
// the cost's rounding noise (how far the cost moves when x is rounded to T) to *noise. Mode 4
// (rows_out given, host only): copy each instance's whitened rows [A | b] (3 x 4, row-major)
// to rows_out + instance * 12, nothing else.
bool linearize_1(const T* x, int first, bool noise_mode, T* noise,
                   double* rows_out = nullptr) {
    V in[7];
    const V* dat = gather_1(x, first, false, in);
    // rows [J | r] padded to 4 (whole tiles): the Jacobian writes only its structural
    // non-zeros, so the zeros this buffer starts with are never overwritten
    static T raw[LANES][12];
    static T ab[LANES][12];  // the whitened rows, every entry written
    jacobian_1(in, dat, raw);
    bool finite = true;
    for (int l = 0; l < LANES; ++l) {
        if (first + l >= 1) continue;
        const int f = BLOCK1_INSTANCES[first + l];
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
        finite = accumulate<4, 4, 3>(ab[l], col) && finite;
        L* rows = AB + FACTOR_A_OFF[f];
        for (int r = 0; r < 3; ++r) {
            for (int c = 0; c < 4; ++c) rows[r * 4 + c] = ab[l][r * 4 + c];
        }
    }
    return finite;
}

// block 1, mode 2: add the cost of instances first ... first + LANES - 1 to *total, in order
void cost_of_1(const T* x, int first, T* total) {
    V in[7];
    const V* dat = gather_1(x, first, true, in);
    T half[LANES][1];
    cost_1(in, dat, half);
    for (int l = 0; l < LANES; ++l) {
        if (first + l >= 1) continue;
        const T* line = DATA_BUF + FACTOR_DATA_OFF[BLOCK1_INSTANCES[first + l]];
        T cost = T(0);
        cost += robust_loss(half[l][0], line[4], line[5]);
        *total += cost;
    }
}

#ifndef __SYNTHESIS__
// The data inputs (measurements, then noise parameters) of every LANES instances, laned once per
// call by lane_data(): they are the same in every iteration, so a gather only lanes x and the
// kernels read the data in place.
V BLOCK2_LANED[(1 + LANES - 1) / LANES][7];

void lane_data_2() {
    for (int first = 0; first < 1; first += LANES) {
        T laned[7][LANES];
        for (int l = 0; l < LANES; ++l) {
            const int f = BLOCK2_INSTANCES[first + l < 1 ? first + l : 0];
            const T* line = DATA_BUF + FACTOR_DATA_OFF[f];
            for (int i = 0; i < 6; ++i) laned[0 + i][l] = line[0 + i];
            for (int i = 0; i < 1; ++i) laned[6 + i][l] = line[6 + i];
        }
        for (int i = 0; i < 7; ++i) BLOCK2_LANED[first / LANES][i] = load_lanes(laned[i]);
    }
}
#endif

// The inputs of instances BLOCK2_INSTANCES[first ...] into the lanes (lanes past the last
// instance repeat it; their results are not used): x's storage into `in`; returns where the data
// inputs are (on the host the laned data, in hardware the rest of `in`).
const V* gather_2(const T* x, int first, bool cost, V in[13]) {
#ifndef __SYNTHESIS__
    T buf[6][LANES];
    for (int l = 0; l < LANES; ++l) {
        const int f = BLOCK2_INSTANCES[first + l < 1 ? first + l : 0];
        const int vb = FACTOR_VAR_BEGIN[f];
        for (int i = 0; i < 6; ++i) buf[0 + i][l] = x[VAR_X_OFF[FACTOR_VARS[vb + 0]] + i];
    }
    for (int i = 0; i < 6; ++i) in[i] = load_lanes(buf[i]);
    (void)cost;
    return BLOCK2_LANED[first / LANES];
#else
    T buf[13][LANES];
    for (int l = 0; l < LANES; ++l) {
        const int f = BLOCK2_INSTANCES[first + l < 1 ? first + l : 0];
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

// block 2, instances first ... first + LANES - 1: residual + Jacobian (its 12
// structural non-zeros of 6 x 7), whiten. Mode 1 (noise_mode false): accumulate the gradient
// and the whitened rows into the A buffer; false if not finite. Mode 3 (true): only add
// the cost's rounding noise (how far the cost moves when x is rounded to T) to *noise. Mode 4
// (rows_out given, host only): copy each instance's whitened rows [A | b] (6 x 7, row-major)
// to rows_out + instance * 42, nothing else.
bool linearize_2(const T* x, int first, bool noise_mode, T* noise,
                   double* rows_out = nullptr) {
    V in[13];
    const V* dat = gather_2(x, first, false, in);
    // rows [J | r] padded to 8 (whole tiles): the Jacobian writes only its structural
    // non-zeros, so the zeros this buffer starts with are never overwritten
    static T raw[LANES][48];
    static T ab[LANES][48];  // the whitened rows, every entry written
    jacobian_2(in, dat, raw);
    bool finite = true;
    for (int l = 0; l < LANES; ++l) {
        if (first + l >= 1) continue;
        const int f = BLOCK2_INSTANCES[first + l];
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
        finite = accumulate<8, 7, 6>(ab[l], col) && finite;
        L* rows = AB + FACTOR_A_OFF[f];
        for (int r = 0; r < 6; ++r) {
            for (int c = 0; c < 7; ++c) rows[r * 7 + c] = ab[l][r * 8 + c];
        }
    }
    return finite;
}

// block 2, mode 2: add the cost of instances first ... first + LANES - 1 to *total, in order
void cost_of_2(const T* x, int first, T* total) {
    V in[13];
    const V* dat = gather_2(x, first, true, in);
    T half[LANES][1];
    cost_2(in, dat, half);
    for (int l = 0; l < LANES; ++l) {
        if (first + l >= 1) continue;
        const T* line = DATA_BUF + FACTOR_DATA_OFF[BLOCK2_INSTANCES[first + l]];
        T cost = T(0);
        cost += robust_loss(half[l][0], line[7], line[8]);
        *total += cost;
    }
}

#ifndef __SYNTHESIS__
// The data inputs (measurements, then noise parameters) of every LANES instances, laned once per
// call by lane_data(): they are the same in every iteration, so a gather only lanes x and the
// kernels read the data in place.
V BLOCK3_LANED[(7 + LANES - 1) / LANES][211];

void lane_data_3() {
    for (int first = 0; first < 7; first += LANES) {
        T laned[211][LANES];
        for (int l = 0; l < LANES; ++l) {
            const int f = BLOCK3_INSTANCES[first + l < 7 ? first + l : 6];
            const T* line = DATA_BUF + FACTOR_DATA_OFF[f];
            for (int i = 0; i < 73; ++i) laned[0 + i][l] = line[0 + i];
            for (int i = 0; i < 12; ++i) laned[73 + i][l] = line[195 + i];
            for (int i = 0; i < 120; ++i) laned[85 + i][l] = line[73 + i];
            for (int i = 0; i < 6; ++i) laned[205 + i][l] = line[207 + i];
        }
        for (int i = 0; i < 211; ++i) BLOCK3_LANED[first / LANES][i] = load_lanes(laned[i]);
    }
}
#endif

// The inputs of instances BLOCK3_INSTANCES[first ...] into the lanes (lanes past the last
// instance repeat it; their results are not used): x's storage into `in`; returns where the data
// inputs are (on the host the laned data, in hardware the rest of `in`).
const V* gather_3(const T* x, int first, bool cost, V in[253]) {
#ifndef __SYNTHESIS__
    T buf[42][LANES];
    for (int l = 0; l < LANES; ++l) {
        const int f = BLOCK3_INSTANCES[first + l < 7 ? first + l : 6];
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
    return BLOCK3_LANED[first / LANES];
#else
    T buf[253][LANES];
    for (int l = 0; l < LANES; ++l) {
        const int f = BLOCK3_INSTANCES[first + l < 7 ? first + l : 6];
        const int vb = FACTOR_VAR_BEGIN[f];
        for (int i = 0; i < 12; ++i) buf[0 + i][l] = x[VAR_X_OFF[FACTOR_VARS[vb + 0]] + i];
        for (int i = 0; i < 3; ++i) buf[12 + i][l] = x[VAR_X_OFF[FACTOR_VARS[vb + 1]] + i];
        for (int i = 0; i < 12; ++i) buf[15 + i][l] = x[VAR_X_OFF[FACTOR_VARS[vb + 2]] + i];
        for (int i = 0; i < 3; ++i) buf[27 + i][l] = x[VAR_X_OFF[FACTOR_VARS[vb + 3]] + i];
        for (int i = 0; i < 6; ++i) buf[30 + i][l] = x[VAR_X_OFF[FACTOR_VARS[vb + 4]] + i];
        for (int i = 0; i < 6; ++i) buf[36 + i][l] = x[VAR_X_OFF[FACTOR_VARS[vb + 5]] + i];
        const T* line = DATA_BUF + FACTOR_DATA_OFF[f];
        for (int i = 0; i < 73; ++i) buf[42 + i][l] = line[0 + i];
        for (int i = 0; i < 12; ++i) buf[115 + i][l] = line[195 + i];
        if (!cost) continue;
        for (int i = 0; i < 120; ++i) buf[127 + i][l] = line[73 + i];
        for (int i = 0; i < 6; ++i) buf[247 + i][l] = line[207 + i];
    }
    for (int i = 0; i < (cost ? 253 : 127); ++i) {
#pragma HLS LOOP_TRIPCOUNT max=253
        in[i] = load_lanes(buf[i]);
    }
    return in + 42;
#endif
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

// block 3, instances first ... first + LANES - 1: residual + Jacobian (its 240
// structural non-zeros of 21 x 31), whiten. Mode 1 (noise_mode false): accumulate the gradient
// and the whitened rows into the A buffer; false if not finite. Mode 3 (true): only add
// the cost's rounding noise (how far the cost moves when x is rounded to T) to *noise. Mode 4
// (rows_out given, host only): copy each instance's whitened rows [A | b] (21 x 31, row-major)
// to rows_out + instance * 651, nothing else.
bool linearize_3(const T* x, int first, bool noise_mode, T* noise,
                   double* rows_out = nullptr) {
    V in[253];
    const V* dat = gather_3(x, first, false, in);
    // rows [J | r] padded to 32 (whole tiles): the Jacobian writes only its structural
    // non-zeros, so the zeros this buffer starts with are never overwritten
    static T raw[LANES][672];
    static T ab[LANES][672];  // the whitened rows, every entry written
    jacobian_3(in, dat, raw);
    bool finite = true;
    for (int l = 0; l < LANES; ++l) {
        if (first + l >= 7) continue;
        const int f = BLOCK3_INSTANCES[first + l];
        const int vb = FACTOR_VAR_BEGIN[f];
        const T* line = DATA_BUF + FACTOR_DATA_OFF[f];
        whiten<32, 31, 15, 2, 9>(raw[l] + 0, ab[l] + 0, line + 73);
        whiten_tail_3_0(raw[l] + 0, ab[l] + 0, line + 73);
        reweight<32, 31, 15>(ab[l] + 0, line[193], line[194]);
        whiten<32, 31, 6, 1, 6>(raw[l] + 480, ab[l] + 480, line + 207);
        reweight<32, 31, 6>(ab[l] + 480, line[213], line[214]);
#ifndef __SYNTHESIS__
        if (rows_out != nullptr) {
            double* out = rows_out + (first + l) * 651;
            for (int r = 0; r < 21; ++r) {
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
            *noise += rounding_noise<32, 31, 21>(ab[l], scale);
            continue;
        }
        int col[30];  // per column: its tangent entry
        for (int j = 0; j < 6; ++j) col[0 + j] = VAR_T_OFF[FACTOR_VARS[vb + 0]] + j;
        for (int j = 0; j < 3; ++j) col[6 + j] = VAR_T_OFF[FACTOR_VARS[vb + 1]] + j;
        for (int j = 0; j < 6; ++j) col[9 + j] = VAR_T_OFF[FACTOR_VARS[vb + 2]] + j;
        for (int j = 0; j < 3; ++j) col[15 + j] = VAR_T_OFF[FACTOR_VARS[vb + 3]] + j;
        for (int j = 0; j < 6; ++j) col[18 + j] = VAR_T_OFF[FACTOR_VARS[vb + 4]] + j;
        for (int j = 0; j < 6; ++j) col[24 + j] = VAR_T_OFF[FACTOR_VARS[vb + 5]] + j;
        finite = accumulate<32, 31, 21>(ab[l], col) && finite;
        L* rows = AB + FACTOR_A_OFF[f];
        for (int r = 0; r < 21; ++r) {
            for (int c = 0; c < 31; ++c) rows[r * 31 + c] = ab[l][r * 32 + c];
        }
    }
    return finite;
}

// block 3, mode 2: add the cost of instances first ... first + LANES - 1 to *total, in order
void cost_of_3(const T* x, int first, T* total) {
    V in[253];
    const V* dat = gather_3(x, first, true, in);
    T half[LANES][2];
    cost_3(in, dat, half);
    for (int l = 0; l < LANES; ++l) {
        if (first + l >= 7) continue;
        const T* line = DATA_BUF + FACTOR_DATA_OFF[BLOCK3_INSTANCES[first + l]];
        T cost = T(0);
        cost += robust_loss(half[l][0], line[193], line[194]);
        cost += robust_loss(half[l][1], line[213], line[214]);
        *total += cost;
    }
}

#ifndef __SYNTHESIS__
// The data inputs (measurements, then noise parameters) of every LANES instances, laned once per
// call by lane_data(): they are the same in every iteration, so a gather only lanes x and the
// kernels read the data in place.
V BLOCK4_LANED[(8 + LANES - 1) / LANES][4];

void lane_data_4() {
    for (int first = 0; first < 8; first += LANES) {
        T laned[4][LANES];
        for (int l = 0; l < LANES; ++l) {
            const int f = BLOCK4_INSTANCES[first + l < 8 ? first + l : 7];
            const T* line = DATA_BUF + FACTOR_DATA_OFF[f];
            for (int i = 0; i < 3; ++i) laned[0 + i][l] = line[0 + i];
            for (int i = 0; i < 1; ++i) laned[3 + i][l] = line[3 + i];
        }
        for (int i = 0; i < 4; ++i) BLOCK4_LANED[first / LANES][i] = load_lanes(laned[i]);
    }
}
#endif

// The inputs of instances BLOCK4_INSTANCES[first ...] into the lanes (lanes past the last
// instance repeat it; their results are not used): x's storage into `in`; returns where the data
// inputs are (on the host the laned data, in hardware the rest of `in`).
const V* gather_4(const T* x, int first, bool cost, V in[16]) {
#ifndef __SYNTHESIS__
    T buf[12][LANES];
    for (int l = 0; l < LANES; ++l) {
        const int f = BLOCK4_INSTANCES[first + l < 8 ? first + l : 7];
        const int vb = FACTOR_VAR_BEGIN[f];
        for (int i = 0; i < 12; ++i) buf[0 + i][l] = x[VAR_X_OFF[FACTOR_VARS[vb + 0]] + i];
    }
    for (int i = 0; i < 12; ++i) in[i] = load_lanes(buf[i]);
    (void)cost;
    return BLOCK4_LANED[first / LANES];
#else
    T buf[16][LANES];
    for (int l = 0; l < LANES; ++l) {
        const int f = BLOCK4_INSTANCES[first + l < 8 ? first + l : 7];
        const int vb = FACTOR_VAR_BEGIN[f];
        for (int i = 0; i < 12; ++i) buf[0 + i][l] = x[VAR_X_OFF[FACTOR_VARS[vb + 0]] + i];
        const T* line = DATA_BUF + FACTOR_DATA_OFF[f];
        for (int i = 0; i < 3; ++i) buf[12 + i][l] = line[0 + i];
        if (!cost) continue;
        for (int i = 0; i < 1; ++i) buf[15 + i][l] = line[3 + i];
    }
    for (int i = 0; i < (cost ? 16 : 15); ++i) {
#pragma HLS LOOP_TRIPCOUNT max=16
        in[i] = load_lanes(buf[i]);
    }
    return in + 12;
#endif
}

// block 4, instances first ... first + LANES - 1: residual + Jacobian (its 12
// structural non-zeros of 3 x 7), whiten. Mode 1 (noise_mode false): accumulate the gradient
// and the whitened rows into the A buffer; false if not finite. Mode 3 (true): only add
// the cost's rounding noise (how far the cost moves when x is rounded to T) to *noise. Mode 4
// (rows_out given, host only): copy each instance's whitened rows [A | b] (3 x 7, row-major)
// to rows_out + instance * 21, nothing else.
bool linearize_4(const T* x, int first, bool noise_mode, T* noise,
                   double* rows_out = nullptr) {
    V in[16];
    const V* dat = gather_4(x, first, false, in);
    // rows [J | r] padded to 8 (whole tiles): the Jacobian writes only its structural
    // non-zeros, so the zeros this buffer starts with are never overwritten
    static T raw[LANES][24];
    static T ab[LANES][24];  // the whitened rows, every entry written
    jacobian_4(in, dat, raw);
    bool finite = true;
    for (int l = 0; l < LANES; ++l) {
        if (first + l >= 8) continue;
        const int f = BLOCK4_INSTANCES[first + l];
        const int vb = FACTOR_VAR_BEGIN[f];
        const T* line = DATA_BUF + FACTOR_DATA_OFF[f];
        whiten<8, 7, 3, 0, 3>(raw[l] + 0, ab[l] + 0, line + 3);
        reweight<8, 7, 3>(ab[l] + 0, line[4], line[5]);
#ifndef __SYNTHESIS__
        if (rows_out != nullptr) {
            double* out = rows_out + (first + l) * 21;
            for (int r = 0; r < 3; ++r) {
                for (int c = 0; c < 7; ++c) out[r * 7 + c] = static_cast<double>(ab[l][r * 8 + c]);
            }
            continue;
        }
#endif
        if (noise_mode) {
            T scale[8];  // per column: largest storage entry of its variable (0: b, padding)
            for (int c = 0; c < 8; ++c) scale[c] = T(0);
            for (int j = 0; j < 6; ++j) scale[0 + j] = VAR_SCALE[FACTOR_VARS[vb + 0]];
            *noise += rounding_noise<8, 7, 3>(ab[l], scale);
            continue;
        }
        int col[6];  // per column: its tangent entry
        for (int j = 0; j < 6; ++j) col[0 + j] = VAR_T_OFF[FACTOR_VARS[vb + 0]] + j;
        finite = accumulate<8, 7, 3>(ab[l], col) && finite;
        L* rows = AB + FACTOR_A_OFF[f];
        for (int r = 0; r < 3; ++r) {
            for (int c = 0; c < 7; ++c) rows[r * 7 + c] = ab[l][r * 8 + c];
        }
    }
    return finite;
}

// block 4, mode 2: add the cost of instances first ... first + LANES - 1 to *total, in order
void cost_of_4(const T* x, int first, T* total) {
    V in[16];
    const V* dat = gather_4(x, first, true, in);
    T half[LANES][1];
    cost_4(in, dat, half);
    for (int l = 0; l < LANES; ++l) {
        if (first + l >= 8) continue;
        const T* line = DATA_BUF + FACTOR_DATA_OFF[BLOCK4_INSTANCES[first + l]];
        T cost = T(0);
        cost += robust_loss(half[l][0], line[4], line[5]);
        *total += cost;
    }
}

// Linearise every factor (each block type is its own pipelined unit); false if not finite.
bool linearize_all(const T* x) {
    for (int i = 0; i < N_TANGENT; ++i) G[i] = T(0);
    bool finite = true;
    T unused = T(0);  // mode 1 adds no noise
    for (int i = 0; i < 1; i += LANES) finite = linearize_0(x, i, false, &unused) && finite;
    for (int i = 0; i < 1; i += LANES) finite = linearize_1(x, i, false, &unused) && finite;
    for (int i = 0; i < 1; i += LANES) finite = linearize_2(x, i, false, &unused) && finite;
    for (int i = 0; i < 7; i += LANES) finite = linearize_3(x, i, false, &unused) && finite;
    for (int i = 0; i < 8; i += LANES) finite = linearize_4(x, i, false, &unused) && finite;
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
    for (int i = 0; i < 1; i += LANES) linearize_0(x, i, true, &noise);
    for (int i = 0; i < 1; i += LANES) linearize_1(x, i, true, &noise);
    for (int i = 0; i < 1; i += LANES) linearize_2(x, i, true, &noise);
    for (int i = 0; i < 7; i += LANES) linearize_3(x, i, true, &noise);
    for (int i = 0; i < 8; i += LANES) linearize_4(x, i, true, &noise);
    return noise;
}

#ifndef __SYNTHESIS__
// The whitened rows [A | b] of every factor instance at x (mode 4), block by block, each block's
// instances in order: what a caller eliminating part of the graph itself (the fixed-lag
// stream's marginalisation) needs.
void linearized_rows(const T* x, double* out) {
    T unused = T(0);
    for (int i = 0; i < 1; i += LANES) linearize_0(x, i, false, &unused, out + 0);
    for (int i = 0; i < 1; i += LANES) linearize_1(x, i, false, &unused, out + 42);
    for (int i = 0; i < 1; i += LANES) linearize_2(x, i, false, &unused, out + 54);
    for (int i = 0; i < 7; i += LANES) linearize_3(x, i, false, &unused, out + 96);
    for (int i = 0; i < 8; i += LANES) linearize_4(x, i, false, &unused, out + 4653);
}
#endif

// The graph's cost (GTSAM's error) at x: every block in cost mode.
T total_cost(const T* x) {
    T total = T(0);
    for (int i = 0; i < 1; i += LANES) cost_of_0(x, i, &total);
    for (int i = 0; i < 1; i += LANES) cost_of_1(x, i, &total);
    for (int i = 0; i < 1; i += LANES) cost_of_2(x, i, &total);
    for (int i = 0; i < 7; i += LANES) cost_of_3(x, i, &total);
    for (int i = 0; i < 8; i += LANES) cost_of_4(x, i, &total);
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
#pragma HLS LOOP_TRIPCOUNT max=30
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
#pragma HLS LOOP_TRIPCOUNT max=87
                if (i == j || W[i][j] != T(0)) scanned[n++] = i;
            }
        }
        // the column scaled by its largest magnitude: |v| <= 1, so v.v neither underflows on a
        // tiny non-zero column (float32: 1e-20 squared is 0, and tau would be inf) nor
        // overflows; the reflection I - tau v v^T does not depend on v's scale.
        T big = T(0);
        for (int a = 0; a < n; ++a) {
#pragma HLS LOOP_TRIPCOUNT max=87
            const T e = fgc_abs(W[active[a]][j]);
            big = e > big ? e : big;
        }
        if (big == T(0)) continue;
        for (int a = 0; a < n; ++a) {
#pragma HLS LOOP_TRIPCOUNT max=87
            v[a] = W[active[a]][j] / big;
        }
        T part[TILE];  // TILE interleaved partial sums of the squares: short chains, fixed order
        for (int t = 0; t < TILE; ++t) part[t] = T(0);
        int a = 0;
        for (; a + TILE <= n; a += TILE) {
#pragma HLS LOOP_TRIPCOUNT max=21
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
#pragma HLS LOOP_TRIPCOUNT max=5
            const int width = end - c < 2 * TILE ? TILE : 2 * TILE;
            T acc[2 * TILE];
            for (int t = 0; t < 2 * TILE; ++t) acc[t] = T(0);
            if (width == 2 * TILE) {
                for (int a = 0; a < n; ++a) {
#pragma HLS LOOP_TRIPCOUNT max=87
#pragma HLS PIPELINE
                    const T va = v[a];
                    const T* row = W[active[a]] + c;
                    for (int t = 0; t < 2 * TILE; ++t) acc[t] += va * row[t];
                }
            } else {
                for (int a = 0; a < n; ++a) {
#pragma HLS LOOP_TRIPCOUNT max=87
#pragma HLS PIPELINE
                    const T va = v[a];
                    const T* row = W[active[a]] + c;
                    for (int t = 0; t < TILE; ++t) acc[t] += va * row[t];
                }
            }
            for (int t = 0; t < 2 * TILE; ++t) dots[c + t] = acc[t];  // past end: unused
        }
        for (int a = 0; a < n; ++a) {
#pragma HLS LOOP_TRIPCOUNT max=87
            const T tv = tau * v[a];
            T* row = W[active[a]];
            for (int c = c0; c < end; ++c) {
#pragma HLS LOOP_TRIPCOUNT max=32
#pragma HLS UNROLL factor=4
                row[c] -= tv * dots[c];
            }
            row[j] = T(0);
        }
        W[j][j] = alpha * big;
    }
    T scale = T(0);
    for (int i = 0; i < k; ++i) {
#pragma HLS LOOP_TRIPCOUNT max=30
        for (int c = i; c <= w; ++c) {
#pragma HLS LOOP_TRIPCOUNT max=30
            scale = fgc_abs(W[i][c]) > scale ? fgc_abs(W[i][c]) : scale;
        }
    }
    if (k < f) return false;
    T* cond = COND + STEP_COND_OFF[s];
    for (int i = 0; i < f; ++i) {
#pragma HLS LOOP_TRIPCOUNT max=30
        if (!(fgc_abs(W[i][i]) > SINGULAR_EPS * scale)) return false;
        for (int c = 0; c <= w; ++c) {
#pragma HLS LOOP_TRIPCOUNT max=30
            cond[i * (w + 1) + c] = W[i][c];
        }
    }
    const int sw = w - f;
    T* nf = NF + STEP_NF_OFF[s];
    for (int r = 0; r < STEP_NF_ROWS[s]; ++r) {
#pragma HLS LOOP_TRIPCOUNT max=30
        for (int c = 0; c <= sw; ++c) {
#pragma HLS LOOP_TRIPCOUNT max=30
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
#pragma HLS LOOP_TRIPCOUNT max=87
        for (int c = 0; c < end; ++c) W[i][c] = T(0);
    }
    int row = 0;
    for (int e = STEP_FACTOR_BEGIN[s]; e < STEP_FACTOR_BEGIN[s + 1]; ++e) {
#pragma HLS LOOP_TRIPCOUNT max=5
        const int fac = STEP_FACTORS[e];
        const int* cm = FACTOR_COLMAP + FACTOR_COLMAP_BEGIN[fac];
        const int d = FACTOR_COLMAP_BEGIN[fac + 1] - FACTOR_COLMAP_BEGIN[fac];
        const int rows = (FACTOR_A_OFF[fac + 1] - FACTOR_A_OFF[fac]) / (d + 1);
        const T* ab = AB + FACTOR_A_OFF[fac];
        for (int r = 0; r < rows; ++r, ++row) {
#pragma HLS LOOP_TRIPCOUNT max=87
            for (int c = 0; c < d; ++c) {
#pragma HLS LOOP_TRIPCOUNT max=30
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
#pragma HLS LOOP_TRIPCOUNT max=30
            for (int k = 0; k < sc; ++k) {
#pragma HLS LOOP_TRIPCOUNT max=30
                W[row][map[k]] = nf[r * (sc + 1) + k];
            }
            W[row][w] = nf[r * (sc + 1) + sc];
        }
    }
    for (int j = 0; j < f; ++j, ++row) {
#pragma HLS LOOP_TRIPCOUNT max=30
        W[row][j] = root_mu;
    }
    return householder<MAX_LD, (MAX_ROWS > TILE ? MAX_ROWS : TILE)>(W, m, w, f, s, nullptr);
}

// Step pattern 0 (2 steps): W = 30, F = 15, 54 rows from 2 factor(s),
// 1 child(ren) and the damping rows; 516 moves of their structural non-zeros.
template <int U>
bool eliminate_pattern_0(int s, T root_mu) {
    static T W[54][32];
#pragma HLS ARRAY_PARTITION variable=W cyclic factor=4 dim=2
    for (int i = 0; i < 54; ++i) {
        for (int c = 0; c < 32; ++c) W[i][c] = T(0);
    }
    const T* op0 = AB + FACTOR_A_OFF[STEP_FACTORS[STEP_FACTOR_BEGIN[s] + 0]];
    const T* op1 = AB + FACTOR_A_OFF[STEP_FACTORS[STEP_FACTOR_BEGIN[s] + 1]];
    const T* op2 = NF + STEP_NF_OFF[STEP_CHILDREN[STEP_CHILD_BEGIN[s] + 0]];
    W[0][0] = op0[0];
    W[0][1] = op0[1];
    W[0][2] = op0[2];
    W[0][3] = op0[3];
    W[0][4] = op0[4];
    W[0][5] = op0[5];
    W[0][6] = op0[6];
    W[0][7] = op0[7];
    W[0][8] = op0[8];
    W[0][15] = op0[9];
    W[0][16] = op0[10];
    W[0][17] = op0[11];
    W[0][18] = op0[12];
    W[0][19] = op0[13];
    W[0][20] = op0[14];
    W[0][21] = op0[15];
    W[0][22] = op0[16];
    W[0][23] = op0[17];
    W[0][9] = op0[18];
    W[0][10] = op0[19];
    W[0][11] = op0[20];
    W[0][12] = op0[21];
    W[0][13] = op0[22];
    W[0][14] = op0[23];
    W[0][24] = op0[24];
    W[0][25] = op0[25];
    W[0][26] = op0[26];
    W[0][27] = op0[27];
    W[0][28] = op0[28];
    W[0][29] = op0[29];
    W[0][30] = op0[30];
    W[1][0] = op0[31];
    W[1][1] = op0[32];
    W[1][2] = op0[33];
    W[1][3] = op0[34];
    W[1][4] = op0[35];
    W[1][5] = op0[36];
    W[1][6] = op0[37];
    W[1][7] = op0[38];
    W[1][8] = op0[39];
    W[1][15] = op0[40];
    W[1][16] = op0[41];
    W[1][17] = op0[42];
    W[1][18] = op0[43];
    W[1][19] = op0[44];
    W[1][20] = op0[45];
    W[1][21] = op0[46];
    W[1][22] = op0[47];
    W[1][23] = op0[48];
    W[1][9] = op0[49];
    W[1][10] = op0[50];
    W[1][11] = op0[51];
    W[1][12] = op0[52];
    W[1][13] = op0[53];
    W[1][14] = op0[54];
    W[1][24] = op0[55];
    W[1][25] = op0[56];
    W[1][26] = op0[57];
    W[1][27] = op0[58];
    W[1][28] = op0[59];
    W[1][29] = op0[60];
    W[1][30] = op0[61];
    W[2][0] = op0[62];
    W[2][1] = op0[63];
    W[2][2] = op0[64];
    W[2][3] = op0[65];
    W[2][4] = op0[66];
    W[2][5] = op0[67];
    W[2][6] = op0[68];
    W[2][7] = op0[69];
    W[2][8] = op0[70];
    W[2][15] = op0[71];
    W[2][16] = op0[72];
    W[2][17] = op0[73];
    W[2][18] = op0[74];
    W[2][19] = op0[75];
    W[2][20] = op0[76];
    W[2][21] = op0[77];
    W[2][22] = op0[78];
    W[2][23] = op0[79];
    W[2][9] = op0[80];
    W[2][10] = op0[81];
    W[2][11] = op0[82];
    W[2][12] = op0[83];
    W[2][13] = op0[84];
    W[2][14] = op0[85];
    W[2][24] = op0[86];
    W[2][25] = op0[87];
    W[2][26] = op0[88];
    W[2][27] = op0[89];
    W[2][28] = op0[90];
    W[2][29] = op0[91];
    W[2][30] = op0[92];
    W[3][0] = op0[93];
    W[3][1] = op0[94];
    W[3][2] = op0[95];
    W[3][3] = op0[96];
    W[3][4] = op0[97];
    W[3][5] = op0[98];
    W[3][6] = op0[99];
    W[3][7] = op0[100];
    W[3][8] = op0[101];
    W[3][15] = op0[102];
    W[3][16] = op0[103];
    W[3][17] = op0[104];
    W[3][18] = op0[105];
    W[3][19] = op0[106];
    W[3][20] = op0[107];
    W[3][21] = op0[108];
    W[3][22] = op0[109];
    W[3][23] = op0[110];
    W[3][9] = op0[111];
    W[3][10] = op0[112];
    W[3][11] = op0[113];
    W[3][12] = op0[114];
    W[3][13] = op0[115];
    W[3][14] = op0[116];
    W[3][24] = op0[117];
    W[3][25] = op0[118];
    W[3][26] = op0[119];
    W[3][27] = op0[120];
    W[3][28] = op0[121];
    W[3][29] = op0[122];
    W[3][30] = op0[123];
    W[4][0] = op0[124];
    W[4][1] = op0[125];
    W[4][2] = op0[126];
    W[4][3] = op0[127];
    W[4][4] = op0[128];
    W[4][5] = op0[129];
    W[4][6] = op0[130];
    W[4][7] = op0[131];
    W[4][8] = op0[132];
    W[4][15] = op0[133];
    W[4][16] = op0[134];
    W[4][17] = op0[135];
    W[4][18] = op0[136];
    W[4][19] = op0[137];
    W[4][20] = op0[138];
    W[4][21] = op0[139];
    W[4][22] = op0[140];
    W[4][23] = op0[141];
    W[4][9] = op0[142];
    W[4][10] = op0[143];
    W[4][11] = op0[144];
    W[4][12] = op0[145];
    W[4][13] = op0[146];
    W[4][14] = op0[147];
    W[4][24] = op0[148];
    W[4][25] = op0[149];
    W[4][26] = op0[150];
    W[4][27] = op0[151];
    W[4][28] = op0[152];
    W[4][29] = op0[153];
    W[4][30] = op0[154];
    W[5][0] = op0[155];
    W[5][1] = op0[156];
    W[5][2] = op0[157];
    W[5][3] = op0[158];
    W[5][4] = op0[159];
    W[5][5] = op0[160];
    W[5][6] = op0[161];
    W[5][7] = op0[162];
    W[5][8] = op0[163];
    W[5][15] = op0[164];
    W[5][16] = op0[165];
    W[5][17] = op0[166];
    W[5][18] = op0[167];
    W[5][19] = op0[168];
    W[5][20] = op0[169];
    W[5][21] = op0[170];
    W[5][22] = op0[171];
    W[5][23] = op0[172];
    W[5][9] = op0[173];
    W[5][10] = op0[174];
    W[5][11] = op0[175];
    W[5][12] = op0[176];
    W[5][13] = op0[177];
    W[5][14] = op0[178];
    W[5][24] = op0[179];
    W[5][25] = op0[180];
    W[5][26] = op0[181];
    W[5][27] = op0[182];
    W[5][28] = op0[183];
    W[5][29] = op0[184];
    W[5][30] = op0[185];
    W[6][0] = op0[186];
    W[6][1] = op0[187];
    W[6][2] = op0[188];
    W[6][6] = op0[192];
    W[6][7] = op0[193];
    W[6][8] = op0[194];
    W[6][15] = op0[195];
    W[6][16] = op0[196];
    W[6][17] = op0[197];
    W[6][21] = op0[201];
    W[6][22] = op0[202];
    W[6][23] = op0[203];
    W[6][9] = op0[204];
    W[6][10] = op0[205];
    W[6][11] = op0[206];
    W[6][12] = op0[207];
    W[6][13] = op0[208];
    W[6][14] = op0[209];
    W[6][24] = op0[210];
    W[6][25] = op0[211];
    W[6][26] = op0[212];
    W[6][27] = op0[213];
    W[6][28] = op0[214];
    W[6][29] = op0[215];
    W[6][30] = op0[216];
    W[7][0] = op0[217];
    W[7][1] = op0[218];
    W[7][2] = op0[219];
    W[7][6] = op0[223];
    W[7][7] = op0[224];
    W[7][8] = op0[225];
    W[7][15] = op0[226];
    W[7][16] = op0[227];
    W[7][17] = op0[228];
    W[7][21] = op0[232];
    W[7][22] = op0[233];
    W[7][23] = op0[234];
    W[7][9] = op0[235];
    W[7][10] = op0[236];
    W[7][11] = op0[237];
    W[7][12] = op0[238];
    W[7][13] = op0[239];
    W[7][14] = op0[240];
    W[7][24] = op0[241];
    W[7][25] = op0[242];
    W[7][26] = op0[243];
    W[7][27] = op0[244];
    W[7][28] = op0[245];
    W[7][29] = op0[246];
    W[7][30] = op0[247];
    W[8][0] = op0[248];
    W[8][1] = op0[249];
    W[8][2] = op0[250];
    W[8][6] = op0[254];
    W[8][7] = op0[255];
    W[8][8] = op0[256];
    W[8][15] = op0[257];
    W[8][16] = op0[258];
    W[8][17] = op0[259];
    W[8][21] = op0[263];
    W[8][22] = op0[264];
    W[8][23] = op0[265];
    W[8][9] = op0[266];
    W[8][10] = op0[267];
    W[8][11] = op0[268];
    W[8][12] = op0[269];
    W[8][13] = op0[270];
    W[8][14] = op0[271];
    W[8][24] = op0[272];
    W[8][25] = op0[273];
    W[8][26] = op0[274];
    W[8][27] = op0[275];
    W[8][28] = op0[276];
    W[8][29] = op0[277];
    W[8][30] = op0[278];
    W[9][9] = op0[297];
    W[9][10] = op0[298];
    W[9][11] = op0[299];
    W[9][12] = op0[300];
    W[9][13] = op0[301];
    W[9][14] = op0[302];
    W[9][24] = op0[303];
    W[9][25] = op0[304];
    W[9][26] = op0[305];
    W[9][27] = op0[306];
    W[9][28] = op0[307];
    W[9][29] = op0[308];
    W[9][30] = op0[309];
    W[10][10] = op0[329];
    W[10][11] = op0[330];
    W[10][12] = op0[331];
    W[10][13] = op0[332];
    W[10][14] = op0[333];
    W[10][25] = op0[335];
    W[10][26] = op0[336];
    W[10][27] = op0[337];
    W[10][28] = op0[338];
    W[10][29] = op0[339];
    W[10][30] = op0[340];
    W[11][11] = op0[361];
    W[11][12] = op0[362];
    W[11][13] = op0[363];
    W[11][14] = op0[364];
    W[11][26] = op0[367];
    W[11][27] = op0[368];
    W[11][28] = op0[369];
    W[11][29] = op0[370];
    W[11][30] = op0[371];
    W[12][12] = op0[393];
    W[12][13] = op0[394];
    W[12][14] = op0[395];
    W[12][27] = op0[399];
    W[12][28] = op0[400];
    W[12][29] = op0[401];
    W[12][30] = op0[402];
    W[13][13] = op0[425];
    W[13][14] = op0[426];
    W[13][28] = op0[431];
    W[13][29] = op0[432];
    W[13][30] = op0[433];
    W[14][14] = op0[457];
    W[14][29] = op0[463];
    W[14][30] = op0[464];
    W[15][0] = op0[465];
    W[15][1] = op0[466];
    W[15][2] = op0[467];
    W[15][15] = op0[474];
    W[15][16] = op0[475];
    W[15][17] = op0[476];
    W[15][30] = op0[495];
    W[16][0] = op0[496];
    W[16][1] = op0[497];
    W[16][2] = op0[498];
    W[16][15] = op0[505];
    W[16][16] = op0[506];
    W[16][17] = op0[507];
    W[16][30] = op0[526];
    W[17][0] = op0[527];
    W[17][1] = op0[528];
    W[17][2] = op0[529];
    W[17][15] = op0[536];
    W[17][16] = op0[537];
    W[17][17] = op0[538];
    W[17][30] = op0[557];
    W[18][0] = op0[558];
    W[18][1] = op0[559];
    W[18][2] = op0[560];
    W[18][3] = op0[561];
    W[18][4] = op0[562];
    W[18][5] = op0[563];
    W[18][15] = op0[567];
    W[18][16] = op0[568];
    W[18][17] = op0[569];
    W[18][18] = op0[570];
    W[18][19] = op0[571];
    W[18][20] = op0[572];
    W[18][30] = op0[588];
    W[19][0] = op0[589];
    W[19][1] = op0[590];
    W[19][2] = op0[591];
    W[19][3] = op0[592];
    W[19][4] = op0[593];
    W[19][5] = op0[594];
    W[19][15] = op0[598];
    W[19][16] = op0[599];
    W[19][17] = op0[600];
    W[19][18] = op0[601];
    W[19][19] = op0[602];
    W[19][20] = op0[603];
    W[19][30] = op0[619];
    W[20][0] = op0[620];
    W[20][1] = op0[621];
    W[20][2] = op0[622];
    W[20][3] = op0[623];
    W[20][4] = op0[624];
    W[20][5] = op0[625];
    W[20][15] = op0[629];
    W[20][16] = op0[630];
    W[20][17] = op0[631];
    W[20][18] = op0[632];
    W[20][19] = op0[633];
    W[20][20] = op0[634];
    W[20][30] = op0[650];
    W[21][3] = op1[3];
    W[21][4] = op1[4];
    W[21][5] = op1[5];
    W[21][30] = op1[6];
    W[22][3] = op1[10];
    W[22][4] = op1[11];
    W[22][5] = op1[12];
    W[22][30] = op1[13];
    W[23][3] = op1[17];
    W[23][4] = op1[18];
    W[23][5] = op1[19];
    W[23][30] = op1[20];
    W[24][0] = op2[0];
    W[24][1] = op2[1];
    W[24][2] = op2[2];
    W[24][3] = op2[3];
    W[24][4] = op2[4];
    W[24][5] = op2[5];
    W[24][6] = op2[6];
    W[24][7] = op2[7];
    W[24][8] = op2[8];
    W[24][9] = op2[9];
    W[24][10] = op2[10];
    W[24][11] = op2[11];
    W[24][12] = op2[12];
    W[24][13] = op2[13];
    W[24][14] = op2[14];
    W[24][30] = op2[15];
    W[25][1] = op2[17];
    W[25][2] = op2[18];
    W[25][3] = op2[19];
    W[25][4] = op2[20];
    W[25][5] = op2[21];
    W[25][6] = op2[22];
    W[25][7] = op2[23];
    W[25][8] = op2[24];
    W[25][9] = op2[25];
    W[25][10] = op2[26];
    W[25][11] = op2[27];
    W[25][12] = op2[28];
    W[25][13] = op2[29];
    W[25][14] = op2[30];
    W[25][30] = op2[31];
    W[26][2] = op2[34];
    W[26][3] = op2[35];
    W[26][4] = op2[36];
    W[26][5] = op2[37];
    W[26][6] = op2[38];
    W[26][7] = op2[39];
    W[26][8] = op2[40];
    W[26][9] = op2[41];
    W[26][10] = op2[42];
    W[26][11] = op2[43];
    W[26][12] = op2[44];
    W[26][13] = op2[45];
    W[26][14] = op2[46];
    W[26][30] = op2[47];
    W[27][3] = op2[51];
    W[27][4] = op2[52];
    W[27][5] = op2[53];
    W[27][6] = op2[54];
    W[27][7] = op2[55];
    W[27][8] = op2[56];
    W[27][9] = op2[57];
    W[27][10] = op2[58];
    W[27][11] = op2[59];
    W[27][12] = op2[60];
    W[27][13] = op2[61];
    W[27][14] = op2[62];
    W[27][30] = op2[63];
    W[28][4] = op2[68];
    W[28][5] = op2[69];
    W[28][6] = op2[70];
    W[28][7] = op2[71];
    W[28][8] = op2[72];
    W[28][9] = op2[73];
    W[28][10] = op2[74];
    W[28][11] = op2[75];
    W[28][12] = op2[76];
    W[28][13] = op2[77];
    W[28][14] = op2[78];
    W[28][30] = op2[79];
    W[29][5] = op2[85];
    W[29][6] = op2[86];
    W[29][7] = op2[87];
    W[29][8] = op2[88];
    W[29][9] = op2[89];
    W[29][10] = op2[90];
    W[29][11] = op2[91];
    W[29][12] = op2[92];
    W[29][13] = op2[93];
    W[29][14] = op2[94];
    W[29][30] = op2[95];
    W[30][6] = op2[102];
    W[30][7] = op2[103];
    W[30][8] = op2[104];
    W[30][9] = op2[105];
    W[30][10] = op2[106];
    W[30][11] = op2[107];
    W[30][12] = op2[108];
    W[30][13] = op2[109];
    W[30][14] = op2[110];
    W[30][30] = op2[111];
    W[31][7] = op2[119];
    W[31][8] = op2[120];
    W[31][9] = op2[121];
    W[31][10] = op2[122];
    W[31][11] = op2[123];
    W[31][12] = op2[124];
    W[31][13] = op2[125];
    W[31][14] = op2[126];
    W[31][30] = op2[127];
    W[32][8] = op2[136];
    W[32][9] = op2[137];
    W[32][10] = op2[138];
    W[32][11] = op2[139];
    W[32][12] = op2[140];
    W[32][13] = op2[141];
    W[32][14] = op2[142];
    W[32][30] = op2[143];
    W[33][9] = op2[153];
    W[33][10] = op2[154];
    W[33][11] = op2[155];
    W[33][12] = op2[156];
    W[33][13] = op2[157];
    W[33][14] = op2[158];
    W[33][30] = op2[159];
    W[34][10] = op2[170];
    W[34][11] = op2[171];
    W[34][12] = op2[172];
    W[34][13] = op2[173];
    W[34][14] = op2[174];
    W[34][30] = op2[175];
    W[35][11] = op2[187];
    W[35][12] = op2[188];
    W[35][13] = op2[189];
    W[35][14] = op2[190];
    W[35][30] = op2[191];
    W[36][12] = op2[204];
    W[36][13] = op2[205];
    W[36][14] = op2[206];
    W[36][30] = op2[207];
    W[37][13] = op2[221];
    W[37][14] = op2[222];
    W[37][30] = op2[223];
    W[38][14] = op2[238];
    W[38][30] = op2[239];
    for (int j = 0; j < 15; ++j) W[39 + j][j] = root_mu;
    // MR (the size of householder's row lists) at least one TILE: its tiled sum loop over fewer
    // rows is dead code, which g++ -Werror would otherwise prove to index past the list
    return householder<32, 54>(W, 54, 30, 15, s, PATTERN0_PLAN);
}

// Step pattern 1 (2 steps): W = 30, F = 15, 54 rows from 2 factor(s),
// 1 child(ren) and the damping rows; 516 moves of their structural non-zeros.
template <int U>
bool eliminate_pattern_1(int s, T root_mu) {
    static T W[54][32];
#pragma HLS ARRAY_PARTITION variable=W cyclic factor=4 dim=2
    for (int i = 0; i < 54; ++i) {
        for (int c = 0; c < 32; ++c) W[i][c] = T(0);
    }
    const T* op0 = AB + FACTOR_A_OFF[STEP_FACTORS[STEP_FACTOR_BEGIN[s] + 0]];
    const T* op1 = AB + FACTOR_A_OFF[STEP_FACTORS[STEP_FACTOR_BEGIN[s] + 1]];
    const T* op2 = NF + STEP_NF_OFF[STEP_CHILDREN[STEP_CHILD_BEGIN[s] + 0]];
    W[0][15] = op0[0];
    W[0][16] = op0[1];
    W[0][17] = op0[2];
    W[0][18] = op0[3];
    W[0][19] = op0[4];
    W[0][20] = op0[5];
    W[0][21] = op0[6];
    W[0][22] = op0[7];
    W[0][23] = op0[8];
    W[0][0] = op0[9];
    W[0][1] = op0[10];
    W[0][2] = op0[11];
    W[0][3] = op0[12];
    W[0][4] = op0[13];
    W[0][5] = op0[14];
    W[0][6] = op0[15];
    W[0][7] = op0[16];
    W[0][8] = op0[17];
    W[0][24] = op0[18];
    W[0][25] = op0[19];
    W[0][26] = op0[20];
    W[0][27] = op0[21];
    W[0][28] = op0[22];
    W[0][29] = op0[23];
    W[0][9] = op0[24];
    W[0][10] = op0[25];
    W[0][11] = op0[26];
    W[0][12] = op0[27];
    W[0][13] = op0[28];
    W[0][14] = op0[29];
    W[0][30] = op0[30];
    W[1][15] = op0[31];
    W[1][16] = op0[32];
    W[1][17] = op0[33];
    W[1][18] = op0[34];
    W[1][19] = op0[35];
    W[1][20] = op0[36];
    W[1][21] = op0[37];
    W[1][22] = op0[38];
    W[1][23] = op0[39];
    W[1][0] = op0[40];
    W[1][1] = op0[41];
    W[1][2] = op0[42];
    W[1][3] = op0[43];
    W[1][4] = op0[44];
    W[1][5] = op0[45];
    W[1][6] = op0[46];
    W[1][7] = op0[47];
    W[1][8] = op0[48];
    W[1][24] = op0[49];
    W[1][25] = op0[50];
    W[1][26] = op0[51];
    W[1][27] = op0[52];
    W[1][28] = op0[53];
    W[1][29] = op0[54];
    W[1][9] = op0[55];
    W[1][10] = op0[56];
    W[1][11] = op0[57];
    W[1][12] = op0[58];
    W[1][13] = op0[59];
    W[1][14] = op0[60];
    W[1][30] = op0[61];
    W[2][15] = op0[62];
    W[2][16] = op0[63];
    W[2][17] = op0[64];
    W[2][18] = op0[65];
    W[2][19] = op0[66];
    W[2][20] = op0[67];
    W[2][21] = op0[68];
    W[2][22] = op0[69];
    W[2][23] = op0[70];
    W[2][0] = op0[71];
    W[2][1] = op0[72];
    W[2][2] = op0[73];
    W[2][3] = op0[74];
    W[2][4] = op0[75];
    W[2][5] = op0[76];
    W[2][6] = op0[77];
    W[2][7] = op0[78];
    W[2][8] = op0[79];
    W[2][24] = op0[80];
    W[2][25] = op0[81];
    W[2][26] = op0[82];
    W[2][27] = op0[83];
    W[2][28] = op0[84];
    W[2][29] = op0[85];
    W[2][9] = op0[86];
    W[2][10] = op0[87];
    W[2][11] = op0[88];
    W[2][12] = op0[89];
    W[2][13] = op0[90];
    W[2][14] = op0[91];
    W[2][30] = op0[92];
    W[3][15] = op0[93];
    W[3][16] = op0[94];
    W[3][17] = op0[95];
    W[3][18] = op0[96];
    W[3][19] = op0[97];
    W[3][20] = op0[98];
    W[3][21] = op0[99];
    W[3][22] = op0[100];
    W[3][23] = op0[101];
    W[3][0] = op0[102];
    W[3][1] = op0[103];
    W[3][2] = op0[104];
    W[3][3] = op0[105];
    W[3][4] = op0[106];
    W[3][5] = op0[107];
    W[3][6] = op0[108];
    W[3][7] = op0[109];
    W[3][8] = op0[110];
    W[3][24] = op0[111];
    W[3][25] = op0[112];
    W[3][26] = op0[113];
    W[3][27] = op0[114];
    W[3][28] = op0[115];
    W[3][29] = op0[116];
    W[3][9] = op0[117];
    W[3][10] = op0[118];
    W[3][11] = op0[119];
    W[3][12] = op0[120];
    W[3][13] = op0[121];
    W[3][14] = op0[122];
    W[3][30] = op0[123];
    W[4][15] = op0[124];
    W[4][16] = op0[125];
    W[4][17] = op0[126];
    W[4][18] = op0[127];
    W[4][19] = op0[128];
    W[4][20] = op0[129];
    W[4][21] = op0[130];
    W[4][22] = op0[131];
    W[4][23] = op0[132];
    W[4][0] = op0[133];
    W[4][1] = op0[134];
    W[4][2] = op0[135];
    W[4][3] = op0[136];
    W[4][4] = op0[137];
    W[4][5] = op0[138];
    W[4][6] = op0[139];
    W[4][7] = op0[140];
    W[4][8] = op0[141];
    W[4][24] = op0[142];
    W[4][25] = op0[143];
    W[4][26] = op0[144];
    W[4][27] = op0[145];
    W[4][28] = op0[146];
    W[4][29] = op0[147];
    W[4][9] = op0[148];
    W[4][10] = op0[149];
    W[4][11] = op0[150];
    W[4][12] = op0[151];
    W[4][13] = op0[152];
    W[4][14] = op0[153];
    W[4][30] = op0[154];
    W[5][15] = op0[155];
    W[5][16] = op0[156];
    W[5][17] = op0[157];
    W[5][18] = op0[158];
    W[5][19] = op0[159];
    W[5][20] = op0[160];
    W[5][21] = op0[161];
    W[5][22] = op0[162];
    W[5][23] = op0[163];
    W[5][0] = op0[164];
    W[5][1] = op0[165];
    W[5][2] = op0[166];
    W[5][3] = op0[167];
    W[5][4] = op0[168];
    W[5][5] = op0[169];
    W[5][6] = op0[170];
    W[5][7] = op0[171];
    W[5][8] = op0[172];
    W[5][24] = op0[173];
    W[5][25] = op0[174];
    W[5][26] = op0[175];
    W[5][27] = op0[176];
    W[5][28] = op0[177];
    W[5][29] = op0[178];
    W[5][9] = op0[179];
    W[5][10] = op0[180];
    W[5][11] = op0[181];
    W[5][12] = op0[182];
    W[5][13] = op0[183];
    W[5][14] = op0[184];
    W[5][30] = op0[185];
    W[6][15] = op0[186];
    W[6][16] = op0[187];
    W[6][17] = op0[188];
    W[6][21] = op0[192];
    W[6][22] = op0[193];
    W[6][23] = op0[194];
    W[6][0] = op0[195];
    W[6][1] = op0[196];
    W[6][2] = op0[197];
    W[6][6] = op0[201];
    W[6][7] = op0[202];
    W[6][8] = op0[203];
    W[6][24] = op0[204];
    W[6][25] = op0[205];
    W[6][26] = op0[206];
    W[6][27] = op0[207];
    W[6][28] = op0[208];
    W[6][29] = op0[209];
    W[6][9] = op0[210];
    W[6][10] = op0[211];
    W[6][11] = op0[212];
    W[6][12] = op0[213];
    W[6][13] = op0[214];
    W[6][14] = op0[215];
    W[6][30] = op0[216];
    W[7][15] = op0[217];
    W[7][16] = op0[218];
    W[7][17] = op0[219];
    W[7][21] = op0[223];
    W[7][22] = op0[224];
    W[7][23] = op0[225];
    W[7][0] = op0[226];
    W[7][1] = op0[227];
    W[7][2] = op0[228];
    W[7][6] = op0[232];
    W[7][7] = op0[233];
    W[7][8] = op0[234];
    W[7][24] = op0[235];
    W[7][25] = op0[236];
    W[7][26] = op0[237];
    W[7][27] = op0[238];
    W[7][28] = op0[239];
    W[7][29] = op0[240];
    W[7][9] = op0[241];
    W[7][10] = op0[242];
    W[7][11] = op0[243];
    W[7][12] = op0[244];
    W[7][13] = op0[245];
    W[7][14] = op0[246];
    W[7][30] = op0[247];
    W[8][15] = op0[248];
    W[8][16] = op0[249];
    W[8][17] = op0[250];
    W[8][21] = op0[254];
    W[8][22] = op0[255];
    W[8][23] = op0[256];
    W[8][0] = op0[257];
    W[8][1] = op0[258];
    W[8][2] = op0[259];
    W[8][6] = op0[263];
    W[8][7] = op0[264];
    W[8][8] = op0[265];
    W[8][24] = op0[266];
    W[8][25] = op0[267];
    W[8][26] = op0[268];
    W[8][27] = op0[269];
    W[8][28] = op0[270];
    W[8][29] = op0[271];
    W[8][9] = op0[272];
    W[8][10] = op0[273];
    W[8][11] = op0[274];
    W[8][12] = op0[275];
    W[8][13] = op0[276];
    W[8][14] = op0[277];
    W[8][30] = op0[278];
    W[9][24] = op0[297];
    W[9][25] = op0[298];
    W[9][26] = op0[299];
    W[9][27] = op0[300];
    W[9][28] = op0[301];
    W[9][29] = op0[302];
    W[9][9] = op0[303];
    W[9][10] = op0[304];
    W[9][11] = op0[305];
    W[9][12] = op0[306];
    W[9][13] = op0[307];
    W[9][14] = op0[308];
    W[9][30] = op0[309];
    W[10][25] = op0[329];
    W[10][26] = op0[330];
    W[10][27] = op0[331];
    W[10][28] = op0[332];
    W[10][29] = op0[333];
    W[10][10] = op0[335];
    W[10][11] = op0[336];
    W[10][12] = op0[337];
    W[10][13] = op0[338];
    W[10][14] = op0[339];
    W[10][30] = op0[340];
    W[11][26] = op0[361];
    W[11][27] = op0[362];
    W[11][28] = op0[363];
    W[11][29] = op0[364];
    W[11][11] = op0[367];
    W[11][12] = op0[368];
    W[11][13] = op0[369];
    W[11][14] = op0[370];
    W[11][30] = op0[371];
    W[12][27] = op0[393];
    W[12][28] = op0[394];
    W[12][29] = op0[395];
    W[12][12] = op0[399];
    W[12][13] = op0[400];
    W[12][14] = op0[401];
    W[12][30] = op0[402];
    W[13][28] = op0[425];
    W[13][29] = op0[426];
    W[13][13] = op0[431];
    W[13][14] = op0[432];
    W[13][30] = op0[433];
    W[14][29] = op0[457];
    W[14][14] = op0[463];
    W[14][30] = op0[464];
    W[15][15] = op0[465];
    W[15][16] = op0[466];
    W[15][17] = op0[467];
    W[15][0] = op0[474];
    W[15][1] = op0[475];
    W[15][2] = op0[476];
    W[15][30] = op0[495];
    W[16][15] = op0[496];
    W[16][16] = op0[497];
    W[16][17] = op0[498];
    W[16][0] = op0[505];
    W[16][1] = op0[506];
    W[16][2] = op0[507];
    W[16][30] = op0[526];
    W[17][15] = op0[527];
    W[17][16] = op0[528];
    W[17][17] = op0[529];
    W[17][0] = op0[536];
    W[17][1] = op0[537];
    W[17][2] = op0[538];
    W[17][30] = op0[557];
    W[18][15] = op0[558];
    W[18][16] = op0[559];
    W[18][17] = op0[560];
    W[18][18] = op0[561];
    W[18][19] = op0[562];
    W[18][20] = op0[563];
    W[18][0] = op0[567];
    W[18][1] = op0[568];
    W[18][2] = op0[569];
    W[18][3] = op0[570];
    W[18][4] = op0[571];
    W[18][5] = op0[572];
    W[18][30] = op0[588];
    W[19][15] = op0[589];
    W[19][16] = op0[590];
    W[19][17] = op0[591];
    W[19][18] = op0[592];
    W[19][19] = op0[593];
    W[19][20] = op0[594];
    W[19][0] = op0[598];
    W[19][1] = op0[599];
    W[19][2] = op0[600];
    W[19][3] = op0[601];
    W[19][4] = op0[602];
    W[19][5] = op0[603];
    W[19][30] = op0[619];
    W[20][15] = op0[620];
    W[20][16] = op0[621];
    W[20][17] = op0[622];
    W[20][18] = op0[623];
    W[20][19] = op0[624];
    W[20][20] = op0[625];
    W[20][0] = op0[629];
    W[20][1] = op0[630];
    W[20][2] = op0[631];
    W[20][3] = op0[632];
    W[20][4] = op0[633];
    W[20][5] = op0[634];
    W[20][30] = op0[650];
    W[21][3] = op1[3];
    W[21][4] = op1[4];
    W[21][5] = op1[5];
    W[21][30] = op1[6];
    W[22][3] = op1[10];
    W[22][4] = op1[11];
    W[22][5] = op1[12];
    W[22][30] = op1[13];
    W[23][3] = op1[17];
    W[23][4] = op1[18];
    W[23][5] = op1[19];
    W[23][30] = op1[20];
    W[24][0] = op2[0];
    W[24][1] = op2[1];
    W[24][2] = op2[2];
    W[24][3] = op2[3];
    W[24][4] = op2[4];
    W[24][5] = op2[5];
    W[24][6] = op2[6];
    W[24][7] = op2[7];
    W[24][8] = op2[8];
    W[24][9] = op2[9];
    W[24][10] = op2[10];
    W[24][11] = op2[11];
    W[24][12] = op2[12];
    W[24][13] = op2[13];
    W[24][14] = op2[14];
    W[24][30] = op2[15];
    W[25][1] = op2[17];
    W[25][2] = op2[18];
    W[25][3] = op2[19];
    W[25][4] = op2[20];
    W[25][5] = op2[21];
    W[25][6] = op2[22];
    W[25][7] = op2[23];
    W[25][8] = op2[24];
    W[25][9] = op2[25];
    W[25][10] = op2[26];
    W[25][11] = op2[27];
    W[25][12] = op2[28];
    W[25][13] = op2[29];
    W[25][14] = op2[30];
    W[25][30] = op2[31];
    W[26][2] = op2[34];
    W[26][3] = op2[35];
    W[26][4] = op2[36];
    W[26][5] = op2[37];
    W[26][6] = op2[38];
    W[26][7] = op2[39];
    W[26][8] = op2[40];
    W[26][9] = op2[41];
    W[26][10] = op2[42];
    W[26][11] = op2[43];
    W[26][12] = op2[44];
    W[26][13] = op2[45];
    W[26][14] = op2[46];
    W[26][30] = op2[47];
    W[27][3] = op2[51];
    W[27][4] = op2[52];
    W[27][5] = op2[53];
    W[27][6] = op2[54];
    W[27][7] = op2[55];
    W[27][8] = op2[56];
    W[27][9] = op2[57];
    W[27][10] = op2[58];
    W[27][11] = op2[59];
    W[27][12] = op2[60];
    W[27][13] = op2[61];
    W[27][14] = op2[62];
    W[27][30] = op2[63];
    W[28][4] = op2[68];
    W[28][5] = op2[69];
    W[28][6] = op2[70];
    W[28][7] = op2[71];
    W[28][8] = op2[72];
    W[28][9] = op2[73];
    W[28][10] = op2[74];
    W[28][11] = op2[75];
    W[28][12] = op2[76];
    W[28][13] = op2[77];
    W[28][14] = op2[78];
    W[28][30] = op2[79];
    W[29][5] = op2[85];
    W[29][6] = op2[86];
    W[29][7] = op2[87];
    W[29][8] = op2[88];
    W[29][9] = op2[89];
    W[29][10] = op2[90];
    W[29][11] = op2[91];
    W[29][12] = op2[92];
    W[29][13] = op2[93];
    W[29][14] = op2[94];
    W[29][30] = op2[95];
    W[30][6] = op2[102];
    W[30][7] = op2[103];
    W[30][8] = op2[104];
    W[30][9] = op2[105];
    W[30][10] = op2[106];
    W[30][11] = op2[107];
    W[30][12] = op2[108];
    W[30][13] = op2[109];
    W[30][14] = op2[110];
    W[30][30] = op2[111];
    W[31][7] = op2[119];
    W[31][8] = op2[120];
    W[31][9] = op2[121];
    W[31][10] = op2[122];
    W[31][11] = op2[123];
    W[31][12] = op2[124];
    W[31][13] = op2[125];
    W[31][14] = op2[126];
    W[31][30] = op2[127];
    W[32][8] = op2[136];
    W[32][9] = op2[137];
    W[32][10] = op2[138];
    W[32][11] = op2[139];
    W[32][12] = op2[140];
    W[32][13] = op2[141];
    W[32][14] = op2[142];
    W[32][30] = op2[143];
    W[33][9] = op2[153];
    W[33][10] = op2[154];
    W[33][11] = op2[155];
    W[33][12] = op2[156];
    W[33][13] = op2[157];
    W[33][14] = op2[158];
    W[33][30] = op2[159];
    W[34][10] = op2[170];
    W[34][11] = op2[171];
    W[34][12] = op2[172];
    W[34][13] = op2[173];
    W[34][14] = op2[174];
    W[34][30] = op2[175];
    W[35][11] = op2[187];
    W[35][12] = op2[188];
    W[35][13] = op2[189];
    W[35][14] = op2[190];
    W[35][30] = op2[191];
    W[36][12] = op2[204];
    W[36][13] = op2[205];
    W[36][14] = op2[206];
    W[36][30] = op2[207];
    W[37][13] = op2[221];
    W[37][14] = op2[222];
    W[37][30] = op2[223];
    W[38][14] = op2[238];
    W[38][30] = op2[239];
    for (int j = 0; j < 15; ++j) W[39 + j][j] = root_mu;
    // MR (the size of householder's row lists) at least one TILE: its tiled sum loop over fewer
    // rows is dead code, which g++ -Werror would otherwise prove to index past the list
    return householder<32, 54>(W, 54, 30, 15, s, PATTERN1_PLAN);
}

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
    const T root_mu = fgc_sqrt(mu);
    bool ok = true;
    for (int l = 0; l < N_LEVELS; ++l) {
        for (int i = LEVEL_BEGIN[l]; i < LEVEL_BEGIN[l + 1]; i += UNIT_SETS) {
#pragma HLS LOOP_TRIPCOUNT max=2
#pragma HLS DATAFLOW
            if (i + 0 < LEVEL_BEGIN[l + 1]) ok = eliminate<0>(LEVEL_STEPS[i + 0], root_mu) && ok;
            if (i + 1 < LEVEL_BEGIN[l + 1]) ok = eliminate<1>(LEVEL_STEPS[i + 1], root_mu) && ok;
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
    lane_data_4();
}
#endif

}  // namespace

void (*progress_hook)(int, double, double, double) = nullptr;

}  // namespace fgc

void lio_top(const fgc::T x_in[fgc::N_X], const fgc::T data[fgc::N_DATA],
                    fgc::T x_out[fgc::N_X], fgc::T errors[2], int info[3]) {
#pragma HLS INTERFACE m_axi port=x_in offset=slave bundle=gmem0 depth=168
#pragma HLS INTERFACE m_axi port=data offset=slave bundle=gmem1 depth=1588
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
void lio_probe(const fgc::T x_in[fgc::N_X], const fgc::T data[fgc::N_DATA], fgc::T out[2]) {
    fgc::host_inputs(x_in, data);
    out[0] = fgc::total_cost(fgc::X);
    out[1] = fgc::rounding_noise_all(fgc::X);
}

void lio_rows(const fgc::T x_in[fgc::N_X], const fgc::T data[fgc::N_DATA], double* out) {
    fgc::host_inputs(x_in, data);
    fgc::linearized_rows(fgc::X, out);
}
#endif
