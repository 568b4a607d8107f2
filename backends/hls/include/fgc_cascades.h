// fgc_cascades.h: the elimination driver of the two-cascade Cholesky design (unit_sets = 2;
// fgc_backends/hls/units/cholesky.py's cascade_regions / cascades_phases price it): two
// independent steps at a time factored side by side by two copies of fgc_cpe.h's cascade, in
// place of fgc_eliminate.h's one-cascade driver (cholesky_eliminate_all).
//
//   bool cholesky_eliminate_sets<CFG>(mu)  every step, region by region; false if singular.
//   cholesky_eliminate_sets_beside<CFG>(mu, relin, grams, ok)  (FGC_CASCADES_BESIDE: the HGC
//        beside the elimination) the same with the streamed block type's Grams taken from the
//        Gram stream (relin) or GRAM_B (LM's retry) by a Gram source, a region at a time.
//
// Included by the kernel inside its namespace after its schedule tables and memories, which
// these functions name: the tables of fgc_eliminate.h's Cholesky driver (STEP_W, STEP_F,
// STEP_FACTOR_BEGIN, STEP_FACTORS, STEP_CHILD_BEGIN, STEP_CHILDREN, STEP_SEPMAP_BEGIN,
// STEP_SEPMAP, STEP_NF_OFF, STEP_COND_OFF, FACTOR_COLMAP_BEGIN, FACTOR_COLMAP, FACTOR_GRAM_OFF,
// N_STEPS) and N_REGIONS, REGION_STEP, STEP_REGION, STEP_CASCADE, STEP_STREAMED (below); the
// memories GRAM, COND, NF0, NF1, HA0, HA1, HF0, HF1, CONDBUF_K0[2], CONDBUF_K1[2], DPIV[4],
// RMAX[4]. CFG is the
// kernel's SetConfig: its LesConfig with N_COND the size of a CONDBUF lane (a step's
// conditional from 0).
//
// The Grams are read in cholesky_set_step_grams (as fgc_eliminate.h's cholesky_assemble_first
// and cholesky_add_segment read them for the one-cascade driver; a streamed factor's from its
// region's stage lane, CFG::staged): a change to where the assembly gets its Grams changes both.
// Without the HGC beside, the kernel's STAGE_NONE0 / STAGE_NONE1 (never read) stand for the
// stage lane's two memories.
#ifndef FGC_CASCADES_H
#define FGC_CASCADES_H

#include "fgc_cpe.h"
#include "fgc_cycles.h"
#include "hls_stream.h"

// A schedule without children prints its children's tables with no entries: their code is
// left out at compile time (as CHOLESKY_HAS_CHILDREN's).
enum { CHOLESKY_SETS_HAS_CHILDREN = sizeof(STEP_CHILDREN) > 0 && sizeof(STEP_SEPMAP) > 0 };

// ---- two cascades (unit_sets = 2; units/cholesky.py's cascades_phases) ------------------------
// The steps go in regions of at most two independent ones (the kernel's tables N_REGIONS,
// REGION_STEP[2 r + k]: cascade k's step of region r, -1 none; STEP_REGION, STEP_CASCADE: each
// step's; STEP_STREAMED: the child its own cascade factored in the region just before, -1
// none), factored side by side by two cascades, each with its own CPEs, feed and drain.
// Memories (the kernel's): HA0, HA1 (cascade k's two lanes of [H | g], lane r % 2 region r's),
// HF0, HF1 (each cascade's trailing rows between rounds), NF0 / NF1[r % 2] (the update
// matrices cascade 0's / 1's drain writes in region r), CONDBUF_Kk[r % 2] (its conditional, copied into
// COND beside the next region: COND has one writer, the committer). One cholesky_sets region,
// five processes:
//   cholesky_set_source   both steps' words out of their lanes into the two cascades, two
//                         words of a row a cycle each, each word cleared as read and its
//                         streamed child's update-matrix word (from NF, where the drain left it
//                         in the region before) added on the way: no pass adds that child;
//   cholesky_set_cascade  x2: cpe_step's rounds on its step (fgc_cpe.h's cpe_rounds: its
//                         drain writes CONDBUF and NF, its pivots and rows' largest |h| DPIV
//                         and RMAX);
//   cholesky_set_grams    the next region's steps' factor Grams into the other lanes;
//   cholesky_set_commit   the region before's conditionals from CONDBUF into COND, and their
//                         pivot checks (fgc_cpe.h's cpe_check): off the cascade's path.
// A step's other children (the other cascade's, or older) are added before its region by
// cholesky_set_alone (sequential: it reads any NF lane).

// The column maps of steps s0's and s1's first factors (-1, or no factor: none) into the
// registers map0, map1, an entry of each a cycle (FACTOR_COLMAP's two ports; trip the larger
// factor's width), each closed by its step's w (the gradient column), so that the two steps'
// Grams follow each other without a map loop between them.
template <class CFG>
void cholesky_set_maps(int s0, int s1, int map0[CFG::MAX_W + 1], int map1[CFG::MAX_W + 1]) {
    const bool h0 = s0 >= 0 && STEP_FACTOR_BEGIN[s0] < STEP_FACTOR_BEGIN[s0 + 1];
    const bool h1 = s1 >= 0 && STEP_FACTOR_BEGIN[s1] < STEP_FACTOR_BEGIN[s1 + 1];
    const int fa0 = h0 ? STEP_FACTORS[STEP_FACTOR_BEGIN[s0]] : 0;
    const int fa1 = h1 ? STEP_FACTORS[STEP_FACTOR_BEGIN[s1]] : 0;
    const int cb0 = FACTOR_COLMAP_BEGIN[fa0], cb1 = FACTOR_COLMAP_BEGIN[fa1];
    const int d0 = h0 ? FACTOR_COLMAP_BEGIN[fa0 + 1] - cb0 : 0;
    const int d1 = h1 ? FACTOR_COLMAP_BEGIN[fa1 + 1] - cb1 : 0;
    const int d = d0 > d1 ? d0 : d1;
    for (int c = 0; c < d; ++c) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_W
#pragma HLS PIPELINE II=1
        if (c < d0) map0[c] = FACTOR_COLMAP[cb0 + c];
        if (c < d1) map1[c] = FACTOR_COLMAP[cb1 + c];
    }
    if (h0) map0[d0] = STEP_W[s0];
    if (h1) map1[d1] = STEP_W[s1];
    FGC_CYCLES("assemble", 0, "map", d, CFG::MOVE_II, CFG::MOVE_DEPTH);
}

// Step s's factor Grams into ha (all zero): the first stored two entries a cycle through its
// column map (map: cholesky_set_maps'; not with first_done: cholesky_set_firsts stored it), the
// further ones added one entry a cycle (as cholesky_assemble_first / _adds). A factor whose Gram
// the HGC streams beside the elimination (CFG::staged(fac) >= 0: its offset in its step's memory
// of its region's stage lane) is read from `stage` (the lane the Gram source filled a pass
// before) instead of GRAM.
template <class CFG>
void cholesky_set_step_grams(int s, typename CFG::T ha[CFG::MAX_W][CFG::MAX_COLS / 2 + 1][2],
                             const typename CFG::T stage[CFG::N_STAGE],
                             const int map[CFG::MAX_W + 1], bool first_done) {
    if (s < 0) return;
    const int w = STEP_W[s];
    for (int e = STEP_FACTOR_BEGIN[s] + (first_done ? 1 : 0); e < STEP_FACTOR_BEGIN[s + 1];
         ++e) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_STEP_FACTORS
        const int fac = STEP_FACTORS[e];
        const int cb = FACTOR_COLMAP_BEGIN[fac];
        const int d = FACTOR_COLMAP_BEGIN[fac + 1] - cb;
        const int g0 = FACTOR_GRAM_OFF[fac];
        const int so = CFG::staged(fac);
        const int n = d * (d + 1) / 2 + d;
        if (e == STEP_FACTOR_BEGIN[s]) {
            for (int k = 0, p = 0, q = 0; k < n; k += 2) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::TRIP_PACKED/2
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=ha inter false
                for (int h = 0; h < 2; ++h) {
                    if (k + h < n) {
                        const int a = map[p], b = map[q];
                        const int lo = b < a ? b : a, hi = b < a ? a : b;
                        ha[lo][hi >> 1][hi & 1] = so >= 0 ? stage[so + k + h] : GRAM[g0 + k + h];
                        if (q == p) {
                            q = 0;
                            ++p;
                        } else {
                            ++q;
                        }
                    }
                }
            }
            FGC_CYCLES("assemble", 0, "gram_first", (n + 1) / 2, CFG::MOVE_II, CFG::MOVE_DEPTH);
            continue;
        }
        for (int k = 0, x = 0, y = 0; k < n; ++k) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::TRIP_PACKED
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=ha inter false
            const int a = x < d ? FACTOR_COLMAP[cb + x] : w;
            const int b = FACTOR_COLMAP[cb + y];
            const int lo = b < a ? b : a, hi = b < a ? a : b;
            ha[lo][hi >> 1][hi & 1] += so >= 0 ? stage[so + k] : GRAM[g0 + k];
            if (y == x) {
                ++x;
                y = 0;
            } else {
                ++y;
            }
        }
        FGC_CYCLES("assemble", 0, "gram", n, CFG::SCATTER_II, CFG::SCATTER_DEPTH);
    }
}

// Step s's first factor, -1 if none.
inline int cholesky_set_first_factor(int s) {
    return s >= 0 && STEP_FACTOR_BEGIN[s] < STEP_FACTOR_BEGIN[s + 1]
               ? STEP_FACTORS[STEP_FACTOR_BEGIN[s]] : -1;
}

// Both steps' first factors' Grams, both streamed (CFG::staged >= 0), stored side by side into
// ha0 and ha1 (all zero) through their column maps: one loop, two entries of each a cycle - two
// reads of each step's memory of the stage lane (stage0, stage1: two memories, so four reads a
// cycle at their two ports each) and two writes into each lane - trip the larger's pairs.
template <class CFG>
void cholesky_set_firsts(int n0, int n1,
                         typename CFG::T ha0[CFG::MAX_W][CFG::MAX_COLS / 2 + 1][2],
                         typename CFG::T ha1[CFG::MAX_W][CFG::MAX_COLS / 2 + 1][2],
                         const typename CFG::T stage0[CFG::N_STAGE],
                         const typename CFG::T stage1[CFG::N_STAGE],
                         const int map0[CFG::MAX_W + 1], const int map1[CFG::MAX_W + 1]) {
    const int f0 = cholesky_set_first_factor(n0), f1 = cholesky_set_first_factor(n1);
    const int d0 = FACTOR_COLMAP_BEGIN[f0 + 1] - FACTOR_COLMAP_BEGIN[f0];
    const int d1 = FACTOR_COLMAP_BEGIN[f1 + 1] - FACTOR_COLMAP_BEGIN[f1];
    const int m0 = d0 * (d0 + 1) / 2 + d0, m1 = d1 * (d1 + 1) / 2 + d1;
    const int so0 = CFG::staged(f0), so1 = CFG::staged(f1);
    const int pairs = ((m0 > m1 ? m0 : m1) + 1) / 2;
    for (int t = 0, k = 0, p0 = 0, q0 = 0, p1 = 0, q1 = 0; t < pairs; ++t, k += 2) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::TRIP_PACKED/2
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=ha0 inter false
#pragma HLS DEPENDENCE variable=ha1 inter false
        for (int h = 0; h < 2; ++h) {
            if (k + h < m0) {
                const int a = map0[p0], b = map0[q0];
                const int lo = b < a ? b : a, hi = b < a ? a : b;
                ha0[lo][hi >> 1][hi & 1] = stage0[so0 + k + h];
                if (q0 == p0) {
                    q0 = 0;
                    ++p0;
                } else {
                    ++q0;
                }
            }
            if (k + h < m1) {
                const int a = map1[p1], b = map1[q1];
                const int lo = b < a ? b : a, hi = b < a ? a : b;
                ha1[lo][hi >> 1][hi & 1] = stage1[so1 + k + h];
                if (q1 == p1) {
                    q1 = 0;
                    ++p1;
                } else {
                    ++q1;
                }
            }
        }
    }
    FGC_CYCLES("assemble", 0, "gram_firsts", pairs, CFG::MOVE_II, CFG::MOVE_DEPTH);
}

// The grams process: steps n0, n1 (cascade 0's, 1's of the next region; -1 none) into their
// lanes, both first factors' column maps in one loop, then - both first factors streamed - both
// first Grams side by side (cholesky_set_firsts), then one step after the other through one
// copy of the loops (one adder); their streamed Grams from `stage0` / `stage1` (the next
// region's stage lane, a memory per cascade's step: STAGE_K0, STAGE_K1; without the HGC beside,
// STAGE_NONE0 / STAGE_NONE1, never read).
template <class CFG>
void cholesky_set_grams(int n0, int n1, typename CFG::T ha0[CFG::MAX_W][CFG::MAX_COLS / 2 + 1][2],
                        typename CFG::T ha1[CFG::MAX_W][CFG::MAX_COLS / 2 + 1][2],
                        const typename CFG::T stage0[CFG::N_STAGE],
                        const typename CFG::T stage1[CFG::N_STAGE]) {
#pragma HLS ALLOCATION function instances=cholesky_set_step_grams<CFG> limit=1
    FGC_BRANCH();
    int map0[CFG::MAX_W + 1], map1[CFG::MAX_W + 1];
#pragma HLS ARRAY_PARTITION variable=map0 complete
#pragma HLS ARRAY_PARTITION variable=map1 complete
    cholesky_set_maps<CFG>(n0, n1, map0, map1);
    const int f0 = cholesky_set_first_factor(n0), f1 = cholesky_set_first_factor(n1);
    const bool both = f0 >= 0 && f1 >= 0 && CFG::staged(f0) >= 0 && CFG::staged(f1) >= 0;
    if (both) cholesky_set_firsts<CFG>(n0, n1, ha0, ha1, stage0, stage1, map0, map1);
    cholesky_set_step_grams<CFG>(n0, ha0, stage0, map0, both);
    cholesky_set_step_grams<CFG>(n1, ha1, stage1, map1, both);
}

// Step s's streamed child's separator map inverted into inv (parent column -> its index in
// the child, -1 none; the gradient column w -> sc) and off (child row x's first word in nf).
template <class CFG>
inline void cholesky_set_inv_init(int inv[CFG::MAX_W + 2]) {
#pragma HLS INLINE
    for (int k = 0; k < CFG::MAX_W + 2; ++k) {
#pragma HLS UNROLL
        inv[k] = -1;
    }
}

// One word of the source: x (column c of row i) plus the streamed child's entry there, if the
// child has one (inv of both columns >= 0: the child's upper triangle at the smaller, the
// larger).
template <class CFG>
inline typename CFG::T cholesky_set_with_child(typename CFG::T x, int i, int c,
                                               const int inv[CFG::MAX_W + 2],
                                               const int off[CFG::MAX_W + 1],
                                               const typename CFG::T nf[CFG::N_NF]) {
#pragma HLS INLINE
    typedef typename CFG::T T;
    const int a = inv[i], b = inv[c];
    const int lo = b < a ? b : a, hi = b < a ? a : b;
    const T v = a >= 0 && b >= 0 ? nf[off[lo] + hi] : T(0);
    return x + v;
}

// One lane's pair of the source (row i, columns j and j + 1 of a step of width w): read out
// of ha and cleared, each with its streamed child's word added, written to out; (i, j) moved
// on to the next pair in the feed's order. INLINE: the source's loop holds both lanes' calls.
template <class CFG>
inline void cholesky_set_source_pair(typename CFG::T ha[CFG::MAX_W][CFG::MAX_COLS / 2 + 1][2],
                                     int w, const int inv[CFG::MAX_W + 2],
                                     const int off[CFG::MAX_W + 1],
                                     const typename CFG::T nf[CFG::N_NF], int& i, int& j,
                                     hls::stream<fgc_units::cpe_pair<typename CFG::T> >& out) {
#pragma HLS INLINE
    typedef typename CFG::T T;
    const int odd_c = j & 1;
    const int e = (j + odd_c) >> 1, o = j >> 1;
    const T v0 = ha[i][e][0], v1 = ha[i][o][1];
    ha[i][e][0] = T(0);
    ha[i][o][1] = T(0);
    const fgc_units::cpe_pair<T> p = {
        cholesky_set_with_child<CFG>(odd_c ? v1 : v0, i, j, inv, off, nf),
        cholesky_set_with_child<CFG>(odd_c ? v0 : v1, i, j + 1, inv, off, nf)};
    out.write(p);
    if (j + 2 > w) {
        ++i;
        j = i;
    } else {
        j += 2;
    }
}

// The source process: steps s0, s1 (cascade 0's, 1's; -1 none) out of lanes ha0, ha1 into
// out0, out1 in the feed's order (fgc_cpe.h's cpe_pair, as cholesky_assembler), both in one
// loop at II 1 (trip the larger step's pairs), each word cleared as read, with its streamed
// child's word (STEP_STREAMED, from nf0 / nf1: the lanes the drains wrote in the region
// before) added: two reads of each lane and of each NF lane a cycle, four adders.
template <class CFG>
void cholesky_set_source(int s0, int s1,
                         typename CFG::T ha0[CFG::MAX_W][CFG::MAX_COLS / 2 + 1][2],
                         typename CFG::T ha1[CFG::MAX_W][CFG::MAX_COLS / 2 + 1][2],
                         const typename CFG::T nf0[CFG::N_NF], const typename CFG::T nf1[CFG::N_NF],
                         hls::stream<fgc_units::cpe_pair<typename CFG::T> >& out0,
                         hls::stream<fgc_units::cpe_pair<typename CFG::T> >& out1) {
    enum { MAX_PAIRS = CFG::MAX_W * (CFG::MAX_W + 4) / 4 + 1 };
    // the lanes' even and odd columns in two banks (HA0 / HA1's last dimension, partitioned):
    // a read and a write of each bank a cycle
#pragma HLS ARRAY_PARTITION variable=ha0 complete dim=3
#pragma HLS ARRAY_PARTITION variable=ha1 complete dim=3
    FGC_BRANCH();
    int inv0[CFG::MAX_W + 2], inv1[CFG::MAX_W + 2], off0[CFG::MAX_W + 1], off1[CFG::MAX_W + 1];
#pragma HLS ARRAY_PARTITION variable=inv0 complete
#pragma HLS ARRAY_PARTITION variable=inv1 complete
#pragma HLS ARRAY_PARTITION variable=off0 complete
#pragma HLS ARRAY_PARTITION variable=off1 complete
    cholesky_set_inv_init<CFG>(inv0);
    cholesky_set_inv_init<CFG>(inv1);
    const int w0 = s0 >= 0 ? STEP_W[s0] : 0, w1 = s1 >= 0 ? STEP_W[s1] : 0;
    const int c0 = s0 >= 0 ? STEP_STREAMED[s0] : -1, c1 = s1 >= 0 ? STEP_STREAMED[s1] : -1;
    const int sc0 = c0 >= 0 ? STEP_W[c0] - STEP_F[c0] : 0;
    const int sc1 = c1 >= 0 ? STEP_W[c1] - STEP_F[c1] : 0;
    const int mb0 = c0 >= 0 ? STEP_SEPMAP_BEGIN[c0] : 0;
    const int mb1 = c1 >= 0 ? STEP_SEPMAP_BEGIN[c1] : 0;
    const int m = sc0 > sc1 ? sc0 : sc1;
    // trip the larger separator, II 1, depth of a move: the two maps side by side
    for (int x = 0, o0 = c0 >= 0 ? STEP_NF_OFF[c0] : 0, o1 = c1 >= 0 ? STEP_NF_OFF[c1] : 0;
         x < m; ++x) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_W
#pragma HLS PIPELINE II=1
        if (CHOLESKY_SETS_HAS_CHILDREN && x < sc0) {
            inv0[STEP_SEPMAP[mb0 + x]] = x;
            off0[x] = o0;
        }
        if (CHOLESKY_SETS_HAS_CHILDREN && x < sc1) {
            inv1[STEP_SEPMAP[mb1 + x]] = x;
            off1[x] = o1;
        }
        o0 += sc0 + 1;
        o1 += sc1 + 1;
    }
    if (c0 >= 0) inv0[w0] = sc0;  // the gradient: the child's column sc
    if (c1 >= 0) inv1[w1] = sc1;
    if (m > 0) FGC_CYCLES("assemble", 0, "inv", m, CFG::MOVE_II, CFG::MOVE_DEPTH);
    const int p0 = s0 >= 0 && fgc_units::cpe_fits<CFG>(STEP_F[s0], w0 - STEP_F[s0])
                       ? fgc_units::cpe_pairs(w0) : 0;
    const int p1 = s1 >= 0 && fgc_units::cpe_fits<CFG>(STEP_F[s1], w1 - STEP_F[s1])
                       ? fgc_units::cpe_pairs(w1) : 0;
    const int pairs = p0 > p1 ? p0 : p1;
    // trip the larger step's pairs, II 1, depth of a move (+ the add: a scatter's) with a
    // streamed child
    for (int t = 0, i0 = 0, j0 = 0, i1 = 0, j1 = 0; t < pairs; ++t) {
#pragma HLS LOOP_TRIPCOUNT max=MAX_PAIRS
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=ha0 inter false
#pragma HLS DEPENDENCE variable=ha1 inter false
        if (t < p0) cholesky_set_source_pair<CFG>(ha0, w0, inv0, off0, nf0, i0, j0, out0);
        if (t < p1) cholesky_set_source_pair<CFG>(ha1, w1, inv1, off1, nf1, i1, j1, out1);
    }
    // a streamed child's add: a scatter's (II, depth)
    FGC_CYCLES("assemble", 0, "source", pairs, c0 >= 0 || c1 >= 0 ? CFG::SCATTER_II : CFG::MOVE_II,
               c0 >= 0 || c1 >= 0 ? CFG::SCATTER_DEPTH : CFG::MOVE_DEPTH);
}

// A cascade's process: step s (-1: none) from src through cpe_step's rounds, its conditional
// into cond (a CONDBUF lane, from 0), its update matrix into nfw, its pivots and rows' largest
// |h| into dpiv, rmax (the committer checks them beside the next region); *unfit: the step is
// outside the configuration (nothing computed).
template <class CFG>
void cholesky_set_cascade(int s, typename CFG::T mu,
                          hls::stream<fgc_units::cpe_pair<typename CFG::T> >& src,
                          typename CFG::T hf[CFG::MAX_W][CFG::MAX_COLS],
                          typename CFG::T cond[CFG::N_COND], typename CFG::T nfw[CFG::N_NF],
                          typename CFG::T dpiv[CFG::MAX_F], typename CFG::T rmax[CFG::MAX_F],
                          bool* not_pd, bool* unfit) {
    FGC_BRANCH();
    if (s < 0) return;
    const int w = STEP_W[s], f = STEP_F[s];
    *unfit = !fgc_units::cpe_rounds<CFG>(src, hf, f, w - f, mu, cond, 0, nfw, STEP_NF_OFF[s],
                                         dpiv, rmax, not_pd);
}

// Step q's conditional (-1: none) from cb into COND, two words a cycle, then its pivot check
// (fgc_cpe.h's cpe_check on its pivots dp and rows' largest |h| rm): *tiny, a pivot too small.
template <class CFG>
void cholesky_set_commit_one(int q, const typename CFG::T cb[CFG::N_COND],
                             const typename CFG::T dp[CFG::MAX_F],
                             const typename CFG::T rm[CFG::MAX_F], bool* tiny) {
    if (q < 0) return;
    const int n = STEP_F[q] * (STEP_W[q] + 1), c0 = STEP_COND_OFF[q];
    for (int k = 0; k < n; k += 2) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::N_COND/2
#pragma HLS PIPELINE II=1
        for (int h = 0; h < 2; ++h) {
            if (k + h < n) COND[c0 + k + h] = cb[k + h];
        }
    }
    FGC_CYCLES("assemble", 0, "cond", (n + 1) / 2, CFG::MOVE_II, CFG::MOVE_DEPTH);
    *tiny = fgc_units::cpe_check<CFG>(dp, rm, STEP_F[q]);
}

// COND's aligned word pairs (2 g, 2 g + 1) the conditional of step q (-1: none) touches, from
// the pair g0 holding its first word (cholesky_set_commit_both's trip).
template <class CFG>
int cholesky_set_cond_pairs(int q, int* g0) {
    if (q < 0) {
        *g0 = 0;
        return 0;
    }
    const int c0 = STEP_COND_OFF[q], n = STEP_F[q] * (STEP_W[q] + 1);
    *g0 = c0 >> 1;
    return ((c0 + n - 1) >> 1) - (c0 >> 1) + 1;
}

#ifdef FGC_COND_BANKS  // COND in banks (the kernel defines it with backsub_lanes > 1)
// COND cyclic over FGC_COND_BANKS = B >= 2 banks (HlsConfig backsub_lanes, fgc_backsub.h's
// partition; two ports a bank): both conditionals q0, q1 from cb0, cb1 in one loop, each an
// aligned pair of COND's words a cycle (trip: the larger step's pairs,
// cholesky_set_cond_pairs). A step reads its pair's two words from its CONDBUF lane (two reads
// of its two ports) and writes word x of it through the unrolled lane b = x % B of the
// B-word group B (a / B) + b holding the pair (a static bank, as fgc_backsub.h's
// cond_load_wide reads COND): the pair's two words are in two banks, so each bank takes at most
// one write a step a cycle (its two ports for the two steps). Then the two pivot checks, one
// after the other (one cpe_check).
template <class CFG>
void cholesky_set_commit_both(int q0, int q1, const typename CFG::T cb0[CFG::N_COND],
                              const typename CFG::T cb1[CFG::N_COND],
                              const typename CFG::T dp0[CFG::MAX_F],
                              const typename CFG::T rm0[CFG::MAX_F],
                              const typename CFG::T dp1[CFG::MAX_F],
                              const typename CFG::T rm1[CFG::MAX_F], bool* tiny0, bool* tiny1) {
#pragma HLS ALLOCATION function instances=fgc_units::cpe_check<CFG> limit=1
    typedef typename CFG::T T;
    enum { B = FGC_COND_BANKS };
    static_assert(B >= 2 && (B & (B - 1)) == 0, "COND cyclic over a power of two >= 2 banks");
    int g0, g1;
    const int p0 = cholesky_set_cond_pairs<CFG>(q0, &g0), p1 = cholesky_set_cond_pairs<CFG>(q1, &g1);
    const int c0 = q0 >= 0 ? STEP_COND_OFF[q0] : 0, c1 = q1 >= 0 ? STEP_COND_OFF[q1] : 0;
    const int n0 = q0 >= 0 ? STEP_F[q0] * (STEP_W[q0] + 1) : 0;
    const int n1 = q1 >= 0 ? STEP_F[q1] * (STEP_W[q1] + 1) : 0;
    const int trip = p0 > p1 ? p0 : p1;
    for (int t = 0; t < trip; ++t) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::N_COND/2+1
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=COND inter false
        const int a0 = 2 * (g0 + t), a1 = 2 * (g1 + t);  // each step's pair's first word
        const int i0 = a0 - c0, i1 = a1 - c1;  // its index in the step's conditional
        const bool on0 = t < p0, on1 = t < p1;
        const T v00 = on0 && i0 >= 0 ? cb0[i0] : T(0);
        const T v01 = on0 && i0 + 1 < n0 ? cb0[i0 + 1] : T(0);
        const T v10 = on1 && i1 >= 0 ? cb1[i1] : T(0);
        const T v11 = on1 && i1 + 1 < n1 ? cb1[i1 + 1] : T(0);
        for (int b = 0; b < B; ++b) {
#pragma HLS UNROLL
            const int x0 = B * (a0 / B) + b, x1 = B * (a1 / B) + b;  // bank b's word
            if (on0 && (b >> 1) == ((a0 % B) >> 1) && x0 >= c0 && x0 < c0 + n0)
                COND[x0] = (b & 1) ? v01 : v00;
            if (on1 && (b >> 1) == ((a1 % B) >> 1) && x1 >= c1 && x1 < c1 + n1)
                COND[x1] = (b & 1) ? v11 : v10;
        }
    }
    FGC_CYCLES("assemble", 0, "cond", trip, CFG::MOVE_II, CFG::MOVE_DEPTH);
    if (q0 >= 0) *tiny0 = fgc_units::cpe_check<CFG>(dp0, rm0, STEP_F[q0]);
    if (q1 >= 0) *tiny1 = fgc_units::cpe_check<CFG>(dp1, rm1, STEP_F[q1]);
}
#endif

// The committer: the region before's steps q0, q1 (cascade 0's, 1's) into COND, each checked
// (*tiny0, *tiny1). COND in one bank: its two ports are one step's two words a cycle, so one
// step after the other; in more (FGC_COND_BANKS: back-substitution's width), both at once
// (cholesky_set_commit_both).
template <class CFG>
void cholesky_set_commit(int q0, int q1, const typename CFG::T cb0[CFG::N_COND],
                         const typename CFG::T cb1[CFG::N_COND],
                         const typename CFG::T dp0[CFG::MAX_F], const typename CFG::T rm0[CFG::MAX_F],
                         const typename CFG::T dp1[CFG::MAX_F], const typename CFG::T rm1[CFG::MAX_F],
                         bool* tiny0, bool* tiny1) {
#ifndef FGC_COND_BANKS
#pragma HLS ALLOCATION function instances=cholesky_set_commit_one<CFG> limit=1
#endif
    FGC_BRANCH();
#ifdef FGC_COND_BANKS
    cholesky_set_commit_both<CFG>(q0, q1, cb0, cb1, dp0, rm0, dp1, rm1, tiny0, tiny1);
#else
    cholesky_set_commit_one<CFG>(q0, cb0, dp0, rm0, tiny0);
    cholesky_set_commit_one<CFG>(q1, cb1, dp1, rm1, tiny1);
#endif
}

#ifndef FGC_CASCADES_BESIDE  // (else: cholesky_sets_beside, below)
// The region: steps s0, s1 factored (their words streamed out of ha0s, ha1s, their streamed
// children read from nf0r, nf1r; conditionals into cb0w, cb1w, update matrices into nf0w,
// nf1w) beside the next region's Grams (n0, n1 into ha0n, ha1n) and the region before's
// conditionals (q0, q1 from cb0r, cb1r into COND, their pivots checked from the DPIV / RMAX
// lanes d0r, r0r, d1r, r1r: *tinyk; the cascades' into d0w, r0w, d1w, r1w). *npdk: cascade
// k's step was not positive definite; *unfitk: outside the configuration.
template <class CFG>
void cholesky_sets(int s0, int s1, int n0, int n1, int q0, int q1, typename CFG::T mu,
                   typename CFG::T ha0s[CFG::MAX_W][CFG::MAX_COLS / 2 + 1][2],
                   typename CFG::T ha1s[CFG::MAX_W][CFG::MAX_COLS / 2 + 1][2],
                   typename CFG::T ha0n[CFG::MAX_W][CFG::MAX_COLS / 2 + 1][2],
                   typename CFG::T ha1n[CFG::MAX_W][CFG::MAX_COLS / 2 + 1][2],
                   const typename CFG::T nf0r[CFG::N_NF], const typename CFG::T nf1r[CFG::N_NF],
                   typename CFG::T nf0w[CFG::N_NF], typename CFG::T nf1w[CFG::N_NF],
                   typename CFG::T cb0w[CFG::N_COND], typename CFG::T cb1w[CFG::N_COND],
                   const typename CFG::T cb0r[CFG::N_COND], const typename CFG::T cb1r[CFG::N_COND],
                   typename CFG::T d0w[CFG::MAX_F], typename CFG::T r0w[CFG::MAX_F],
                   typename CFG::T d1w[CFG::MAX_F], typename CFG::T r1w[CFG::MAX_F],
                   const typename CFG::T d0r[CFG::MAX_F], const typename CFG::T r0r[CFG::MAX_F],
                   const typename CFG::T d1r[CFG::MAX_F], const typename CFG::T r1r[CFG::MAX_F],
                   bool* npd0, bool* npd1, bool* unfit0, bool* unfit1, bool* tiny0,
                   bool* tiny1) {
#pragma HLS DATAFLOW
    enum { DEPTH = CFG::MAX_W * (CFG::MAX_W + 4) / 8 + CFG::ADD_LAT + 8 };
    hls::stream<fgc_units::cpe_pair<typename CFG::T> > frontal0;
    hls::stream<fgc_units::cpe_pair<typename CFG::T> > frontal1;
#pragma HLS STREAM variable=frontal0 depth=DEPTH
#pragma HLS STREAM variable=frontal1 depth=DEPTH
    cholesky_set_source<CFG>(s0, s1, ha0s, ha1s, nf0r, nf1r, frontal0, frontal1);
    cholesky_set_grams<CFG>(n0, n1, ha0n, ha1n, STAGE_NONE0, STAGE_NONE1);
    cholesky_set_cascade<CFG>(s0, mu, frontal0, HF0, cb0w, nf0w, d0w, r0w, npd0,
                              unfit0);
    cholesky_set_cascade<CFG>(s1, mu, frontal1, HF1, cb1w, nf1w, d1w, r1w, npd1,
                              unfit1);
    cholesky_set_commit<CFG>(q0, q1, cb0r, cb1r, d0r, r0r, d1r, r1r, tiny0, tiny1);
    FGC_DRAINED(&frontal0, 1);  // csim only (fgc_cycles.h)
    FGC_DRAINED(&frontal1, 1);
}
#endif  // !FGC_CASCADES_BESIDE

// Step s's children other than its streamed one added into its lane (before its region): one
// scatter loop a child, from the NF lane its cascade's drain wrote (one adder).
template <class CFG>
void cholesky_set_alone(int s) {
    typedef typename CFG::T T;
    if (!CHOLESKY_SETS_HAS_CHILDREN || s < 0) return;
    const int w = STEP_W[s], k = STEP_CASCADE[s], hl = STEP_REGION[s] & 1;
    for (int e = STEP_CHILD_BEGIN[s]; e < STEP_CHILD_BEGIN[s + 1]; ++e) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_CHILDREN
        const int c = STEP_CHILDREN[e];
        if (c == STEP_STREAMED[s]) continue;
        const int kc = STEP_CASCADE[c], lane = STEP_REGION[c] & 1;
        const int sc = STEP_W[c] - STEP_F[c], mb = STEP_SEPMAP_BEGIN[c], u0 = STEP_NF_OFF[c];
        const int n = sc * (sc + 1) / 2 + sc;
        for (int q = 0, x = 0, y = 0; q < n; ++q) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::TRIP_PACKED
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=HA0 inter false
#pragma HLS DEPENDENCE variable=HA1 inter false
            const int a = STEP_SEPMAP[mb + x];
            const int b = y < sc ? STEP_SEPMAP[mb + y] : w;
            const int at = u0 + x * (sc + 1) + y;
            const T v = kc ? NF1[lane][at] : NF0[lane][at];
            const int lo = b < a ? b : a, hi = b < a ? a : b;
            const T old = k ? HA1[hl][lo][hi >> 1][hi & 1] : HA0[hl][lo][hi >> 1][hi & 1];
            const T sum = old + v;
            if (k) {
                HA1[hl][lo][hi >> 1][hi & 1] = sum;
            } else {
                HA0[hl][lo][hi >> 1][hi & 1] = sum;
            }
            if (y == sc) {
                ++x;
                y = x;
            } else {
                ++y;
            }
        }
        FGC_CYCLES("assemble", 0, "child", n, CFG::SCATTER_II, CFG::SCATTER_DEPTH);
    }
}

#ifndef FGC_CASCADES_BESIDE  // (else: cholesky_eliminate_sets_beside, below)
// Eliminate every step, region by region (REGION_STEP): passes of the one cholesky_sets
// region (its two parity call sites, one RTL copy), j = -1 the grams process alone (the first
// region's Grams into lanes 0), j = 0 ... N_REGIONS - 1 region j (after its steps' children
// other than the streamed ones, cholesky_set_alone), j = N_REGIONS the committer alone (the
// last region's conditionals). Region j streams lanes j % 2 and writes NFk[j % 2] and
// CONDBUF_Kk[j % 2] (cascade k's); the grams process fills lanes 1 - j % 2, the source reads
// NFk[1 - j % 2] and the committer CONDBUF_Kk[1 - j % 2] (what region j - 1 wrote).
// Every step runs even after one fails; false if any was not positive definite or had a
// pivot too small.
template <class CFG>
bool cholesky_eliminate_sets(typename CFG::T mu) {
#pragma HLS ARRAY_PARTITION variable=HA0 complete dim=1
#pragma HLS ARRAY_PARTITION variable=HA0 complete dim=4
#pragma HLS ARRAY_PARTITION variable=HA1 complete dim=1
#pragma HLS ARRAY_PARTITION variable=HA1 complete dim=4
#pragma HLS ARRAY_PARTITION variable=NF0 complete dim=1
#pragma HLS ARRAY_PARTITION variable=NF1 complete dim=1
#pragma HLS ARRAY_PARTITION variable=CONDBUF_K0 complete dim=1
#pragma HLS ARRAY_PARTITION variable=CONDBUF_K1 complete dim=1
#pragma HLS ARRAY_PARTITION variable=DPIV complete dim=1
#pragma HLS ARRAY_PARTITION variable=RMAX complete dim=1
    FGC_EVENT("solve");
    bool ok = true;
#pragma HLS ALLOCATION function instances=cholesky_sets<CFG> limit=1
    for (int j = -1; j <= N_REGIONS; ++j) {
#pragma HLS LOOP_TRIPCOUNT max=N_REGIONS+2
        const bool in = j >= 0 && j < N_REGIONS;
        if (in && CHOLESKY_SETS_HAS_CHILDREN) {
            FGC_PHASE("assemble");
            cholesky_set_alone<CFG>(REGION_STEP[2 * j]);
            cholesky_set_alone<CFG>(REGION_STEP[2 * j + 1]);
        }
        const int s0 = in ? REGION_STEP[2 * j] : -1, s1 = in ? REGION_STEP[2 * j + 1] : -1;
        const bool nx = j + 1 < N_REGIONS;
        const int n0 = nx ? REGION_STEP[2 * j + 2] : -1, n1 = nx ? REGION_STEP[2 * j + 3] : -1;
        const bool pv = j >= 1;
        const int q0 = pv ? REGION_STEP[2 * j - 2] : -1, q1 = pv ? REGION_STEP[2 * j - 1] : -1;
        FGC_PHASE(j < 0 ? "assemble" : "cholesky");
        bool npd0 = false, npd1 = false, unfit0 = false, unfit1 = false;
        bool tiny0 = false, tiny1 = false;
        if ((j & 1) == 0) {
            cholesky_sets<CFG>(s0, s1, n0, n1, q0, q1, mu, HA0[0], HA1[0], HA0[1], HA1[1],
                               NF0[1], NF1[1], NF0[0], NF1[0], CONDBUF_K0[0], CONDBUF_K1[0], CONDBUF_K0[1],
                               CONDBUF_K1[1], DPIV[0], RMAX[0], DPIV[2], RMAX[2], DPIV[1], RMAX[1],
                               DPIV[3], RMAX[3], &npd0, &npd1, &unfit0, &unfit1, &tiny0, &tiny1);
        } else {
            cholesky_sets<CFG>(s0, s1, n0, n1, q0, q1, mu, HA0[1], HA1[1], HA0[0], HA1[0],
                               NF0[0], NF1[0], NF0[1], NF1[1], CONDBUF_K0[1], CONDBUF_K1[1], CONDBUF_K0[0],
                               CONDBUF_K1[0], DPIV[1], RMAX[1], DPIV[3], RMAX[3], DPIV[0], RMAX[0],
                               DPIV[2], RMAX[2], &npd0, &npd1, &unfit0, &unfit1, &tiny0, &tiny1);
        }
        FGC_JOIN();
        ok = ok && !npd0 && !npd1 && !unfit0 && !unfit1 && !tiny0 && !tiny1;
    }
    return ok;
}
#endif  // !FGC_CASCADES_BESIDE

#ifdef FGC_CASCADES_BESIDE
// ---- the HGC beside the elimination with two cascades (accel.cpp.jinja's linearize_solve;
// units/cholesky.py's beside_set_passes). The streamed block type's instances come in the order
// of the regions (each region's cascade 0 step's, then cascade 1's) as a Gram stream, and each
// cholesky_sets_beside pass gains a sixth process, the Gram source (CFG::gram_source, on the
// kernel's per-region tables): it puts region r + 2's streamed Grams into stage lane r % 2 -
// from the stream on the first solve of a linearisation (keeping them in GRAM_B), from GRAM_B on
// LM's retries - while the grams process reads region r + 1's from the other lane. The stage
// lanes follow NF's scheme: the two parity call sites pass (lane written, lane read) as
// different arrays, so each lane has one process a pass. A lane is two memories, lane[k] the
// streamed Grams of the region's cascade k step (the grams process reads both steps' first Grams
// side by side, cholesky_set_firsts; STAGE_K0, STAGE_K1 the two). CFG: SetConfig with the LesConfig's Word, N_STAGE (a
// step's streamed words: a memory of a lane), staged(fac) (the offset in its step's memory),
// streams(r), last_streamed(r) and gram_source(r, relin, lane, grams).

// The source's process: region r's streamed Grams into `stage0w` (its cascade 0 step's) and
// `stage1w` (none if r < 0).
template <class CFG>
void cholesky_set_gram_source(int r, bool relin, typename CFG::T stage0w[CFG::N_STAGE],
                              typename CFG::T stage1w[CFG::N_STAGE],
                              hls::stream<typename CFG::Word>& grams) {
    FGC_BRANCH();  // csim cycle counting only: beside the region's other processes
    if (r >= 0) CFG::gram_source(r, relin, stage0w, stage1w, grams);
}

// The region (cholesky_sets') with the Gram source putting region `src`'s streamed Grams into
// stage0w / stage1w while the grams process reads the next region's from stage0r / stage1r.
template <class CFG>
void cholesky_sets_beside(int s0, int s1, int n0, int n1, int q0, int q1, int src, bool relin,
                          typename CFG::T mu,
                          typename CFG::T ha0s[CFG::MAX_W][CFG::MAX_COLS / 2 + 1][2],
                          typename CFG::T ha1s[CFG::MAX_W][CFG::MAX_COLS / 2 + 1][2],
                          typename CFG::T ha0n[CFG::MAX_W][CFG::MAX_COLS / 2 + 1][2],
                          typename CFG::T ha1n[CFG::MAX_W][CFG::MAX_COLS / 2 + 1][2],
                          const typename CFG::T nf0r[CFG::N_NF], const typename CFG::T nf1r[CFG::N_NF],
                          typename CFG::T nf0w[CFG::N_NF], typename CFG::T nf1w[CFG::N_NF],
                          typename CFG::T cb0w[CFG::N_COND], typename CFG::T cb1w[CFG::N_COND],
                          const typename CFG::T cb0r[CFG::N_COND], const typename CFG::T cb1r[CFG::N_COND],
                          typename CFG::T d0w[CFG::MAX_F], typename CFG::T r0w[CFG::MAX_F],
                          typename CFG::T d1w[CFG::MAX_F], typename CFG::T r1w[CFG::MAX_F],
                          const typename CFG::T d0r[CFG::MAX_F], const typename CFG::T r0r[CFG::MAX_F],
                          const typename CFG::T d1r[CFG::MAX_F], const typename CFG::T r1r[CFG::MAX_F],
                          const typename CFG::T stage0r[CFG::N_STAGE],
                          const typename CFG::T stage1r[CFG::N_STAGE],
                          typename CFG::T stage0w[CFG::N_STAGE],
                          typename CFG::T stage1w[CFG::N_STAGE],
                          hls::stream<typename CFG::Word>& grams, bool* npd0, bool* npd1,
                          bool* unfit0, bool* unfit1, bool* tiny0, bool* tiny1) {
#pragma HLS DATAFLOW
    enum { DEPTH = CFG::MAX_W * (CFG::MAX_W + 4) / 8 + CFG::ADD_LAT + 8 };
    hls::stream<fgc_units::cpe_pair<typename CFG::T> > frontal0;
    hls::stream<fgc_units::cpe_pair<typename CFG::T> > frontal1;
#pragma HLS STREAM variable=frontal0 depth=DEPTH
#pragma HLS STREAM variable=frontal1 depth=DEPTH
    cholesky_set_gram_source<CFG>(src, relin, stage0w, stage1w, grams);
    cholesky_set_source<CFG>(s0, s1, ha0s, ha1s, nf0r, nf1r, frontal0, frontal1);
    cholesky_set_grams<CFG>(n0, n1, ha0n, ha1n, stage0r, stage1r);
    cholesky_set_cascade<CFG>(s0, mu, frontal0, HF0, cb0w, nf0w, d0w, r0w, npd0,
                              unfit0);
    cholesky_set_cascade<CFG>(s1, mu, frontal1, HF1, cb1w, nf1w, d1w, r1w, npd1,
                              unfit1);
    cholesky_set_commit<CFG>(q0, q1, cb0r, cb1r, d0r, r0r, d1r, r1r, tiny0, tiny1);
    FGC_DRAINED(&frontal0, 1);  // csim only (fgc_cycles.h)
    FGC_DRAINED(&frontal1, 1);
}

// cholesky_eliminate_sets with the Gram source: passes j = -2 (the source alone: region 0's
// streamed Grams into stage lane 0), j = -1 (the grams process alone on region 0 beside the
// source of region 1), j = 0 ... N_REGIONS - 1 (region j, after its steps' children added
// alone, beside the source of region j + 2 into stage lane j % 2 while the grams process reads
// region j + 1's from the other), j = N_REGIONS (the committer alone). relin: the first solve of
// a linearisation (the Grams from the stream, phase hgc_beside, each pass whose source reads
// the stream gated by the producer's last instance of its region), else a retry (from GRAM_B).
// ok false if any step was not positive definite or had a pivot too small.
template <class CFG>
void cholesky_eliminate_sets_beside(typename CFG::T mu, bool relin,
                                    hls::stream<typename CFG::Word>& grams, bool& ok) {
#pragma HLS ARRAY_PARTITION variable=HA0 complete dim=1
#pragma HLS ARRAY_PARTITION variable=HA0 complete dim=4
#pragma HLS ARRAY_PARTITION variable=HA1 complete dim=1
#pragma HLS ARRAY_PARTITION variable=HA1 complete dim=4
#pragma HLS ARRAY_PARTITION variable=NF0 complete dim=1
#pragma HLS ARRAY_PARTITION variable=NF1 complete dim=1
#pragma HLS ARRAY_PARTITION variable=CONDBUF_K0 complete dim=1
#pragma HLS ARRAY_PARTITION variable=CONDBUF_K1 complete dim=1
#pragma HLS ARRAY_PARTITION variable=DPIV complete dim=1
#pragma HLS ARRAY_PARTITION variable=RMAX complete dim=1
#pragma HLS ARRAY_PARTITION variable=STAGE_K0 complete dim=1
#pragma HLS ARRAY_PARTITION variable=STAGE_K1 complete dim=1
    FGC_PHASE(relin ? "hgc_beside" : "reassemble");
    bool good = true;
#pragma HLS ALLOCATION function instances=cholesky_sets_beside<CFG> limit=1
    for (int j = -2; j <= N_REGIONS; ++j) {
#pragma HLS LOOP_TRIPCOUNT max=N_REGIONS+3
        const bool in = j >= 0 && j < N_REGIONS;
        if (in && CHOLESKY_SETS_HAS_CHILDREN) {
            FGC_PHASE(relin ? "hgc_beside" : "reassemble");
            cholesky_set_alone<CFG>(REGION_STEP[2 * j]);
            cholesky_set_alone<CFG>(REGION_STEP[2 * j + 1]);
        }
        const int s0 = in ? REGION_STEP[2 * j] : -1, s1 = in ? REGION_STEP[2 * j + 1] : -1;
        const bool nx = j + 1 >= 0 && j + 1 < N_REGIONS;
        const int n0 = nx ? REGION_STEP[2 * j + 2] : -1, n1 = nx ? REGION_STEP[2 * j + 3] : -1;
        const bool pv = j >= 1;
        const int q0 = pv ? REGION_STEP[2 * j - 2] : -1, q1 = pv ? REGION_STEP[2 * j - 1] : -1;
        const int src = j + 2 < N_REGIONS && CFG::streams(j + 2) ? j + 2 : -1;
        FGC_PHASE(relin ? "hgc_beside" : (j < 0 ? "reassemble" : "recholesky"));
        if (relin && src >= 0) FGC_BESIDE_GATE(CFG::last_streamed(src), CFG::MOVE_DEPTH);
        bool npd0 = false, npd1 = false, unfit0 = false, unfit1 = false;
        bool tiny0 = false, tiny1 = false;
        if ((j & 1) == 0) {
            cholesky_sets_beside<CFG>(s0, s1, n0, n1, q0, q1, src, relin, mu, HA0[0], HA1[0],
                                      HA0[1], HA1[1], NF0[1], NF1[1], NF0[0], NF1[0], CONDBUF_K0[0],
                                      CONDBUF_K1[0], CONDBUF_K0[1], CONDBUF_K1[1], DPIV[0], RMAX[0],
                                      DPIV[2], RMAX[2], DPIV[1], RMAX[1], DPIV[3], RMAX[3],
                                      STAGE_K0[1], STAGE_K1[1], STAGE_K0[0], STAGE_K1[0], grams,
                                      &npd0, &npd1, &unfit0, &unfit1, &tiny0, &tiny1);
        } else {
            cholesky_sets_beside<CFG>(s0, s1, n0, n1, q0, q1, src, relin, mu, HA0[1], HA1[1],
                                      HA0[0], HA1[0], NF0[0], NF1[0], NF0[1], NF1[1], CONDBUF_K0[1],
                                      CONDBUF_K1[1], CONDBUF_K0[0], CONDBUF_K1[0], DPIV[1], RMAX[1],
                                      DPIV[3], RMAX[3], DPIV[0], RMAX[0], DPIV[2], RMAX[2],
                                      STAGE_K0[0], STAGE_K1[0], STAGE_K0[1], STAGE_K1[1], grams,
                                      &npd0, &npd1, &unfit0, &unfit1, &tiny0, &tiny1);
        }
        FGC_JOIN();
        good = good && !npd0 && !npd1 && !unfit0 && !unfit1 && !tiny0 && !tiny1;
    }
    ok = good;
}
#endif  // FGC_CASCADES_BESIDE

#endif  // FGC_CASCADES_H
