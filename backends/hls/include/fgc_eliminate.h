// fgc_eliminate.h: the elimination driver of the dataflow kernel, around its linear-solver units
// (fgc_cpe.h's cascade, fgc_qr.h's QR unit): what goes into a step's unit and where its result
// goes. Per step s of the schedule:
//
//   Cholesky: bool cholesky_eliminate_all<CFG>(mu)  every step in schedule order: [H | g]
//             assembled from the step's factors' Grams and its children's update matrices
//             (while the cascade factors the step before: the cholesky_overlap region, two
//             lanes HA_L0, HA_L1), streamed into the cascade, whose drain writes the
//             conditional into COND and the update matrix into NF[t % 2] (the t-th step's);
//             false if singular.
//   QR:       void qr_stack_rows<CFG>(s, root_mu, bank, skip, m)  the step's m rows into a
//             unit set's banks (its factors' [A | b] less the skipped ones, its children's
//             new factors, sqrt(mu) I if CFG::LM).
//             void qr_commit<CFG>(s, cond, update)  a unit set's result into COND and NF.
//             bool qr_eliminate_all<CFG, SETS>(mu)  every step, level by level: a level's
//             steps go CFG::UNIT_SETS at a time to the unit sets (stacked, the sets'
//             DATAFLOW region, committed); false if rank deficient.
//             qr_eliminate_all<CFG, SETS>(0, s, live)  step s alone once more at mu = 0 on
//             unit set 0 (the on-chip window's marginalisation: the same sets and region, one
//             instance with LM's solve; live: without the factors that hold nothing once
//             keyframe 0 has left); false if rank deficient.
//
// The unit-set wiring stays the kernel's (it depends on the number of unit sets: each set its
// own memories and RTL instance): SETS holds its hooks, static functions the kernel defines
// after its qr_set<u> and qr_level -
//   SETS::stack(u, s, root_mu, skip, m, solve)  qr_stack_rows<CFG>(s, root_mu, WORK<u>, skip,
//                                m, in_place, dirty) (solve: not the leaf step; the kernel
//                                decides whether the datapaths left step s's factor rows in
//                                set u's banks, or rows of another step to zero first)
//   SETS::level(has, s, m, bad)  the qr_level region: set u takes step s[u]'s m[u] rows where
//                                has[u] (else none), bad[u] set if rank deficient
//   SETS::commit(u, s)           qr_commit<CFG>(s, CONDBUF<u>, UPDBUF<u>)
//   SETS::WAVE_ROOT_LEVEL        (a kernel built with HlsConfig root_wave only) the root step
//                                in a wavefront: qr_eliminate_all stops before the last level,
//                                whose root SETS::level ran on set 1 in the level before's
//                                region (set 0 step s[0] passing its rows by stream, set 1 step
//                                s[1], its commit, the root's stack and the root fed those
//                                rows), and commits the root from set 1
//
// Included by the kernel inside its namespace (fgc::, or fgc::les for the mixed design), after
// its schedule tables and memories, which these functions name: STEP_W, STEP_F, STEP_ROWS,
// STEP_FACTOR_BEGIN, STEP_FACTORS, STEP_CHILD_BEGIN, STEP_CHILDREN, STEP_SEPMAP_BEGIN,
// STEP_SEPMAP, STEP_NF_OFF, STEP_NF_ROWS, STEP_COND_OFF, FACTOR_COLMAP_BEGIN, FACTOR_COLMAP,
// FACTOR_A_OFF, FACTOR_GRAM_OFF, LEVEL_STEPS, LEVEL_BEGIN, N_LEVELS, N_STEPS (tables); AB, GRAM,
// COND, NF (Cholesky: NF[2], two lanes), PORTS, fgc_sqrt and, for Cholesky, HA_L0, HA_L1 and HF
// (memories). CFG is the kernel's LesConfig: T (the linear solver's scalar), the unit's sizes,
// LM, the tables' largest trip counts (MAX_STEP_FACTORS, MAX_CHILDREN, TRIP_*) and the (II,
// depth) of the plan's fill, move and scatter loops (QR: UNIT_SETS, MAX_LEVEL_WIDTH and the
// (II, depth) ROOT_II, ROOT_DEPTH of sqrt(mu) too); cycles to FGC_CYCLES as the plan prices
// them. Define FGC_ELIMINATE_CHOLESKY or FGC_ELIMINATE_QR
// first: the other solver's memories do not exist.
#ifndef FGC_ELIMINATE_H
#define FGC_ELIMINATE_H

#ifdef FGC_ELIMINATE_CHOLESKY
// The assembly buffers HA_L0, HA_L1 (the kernel's memories, two lanes of a step's [H | g],
// "HA[lane]" below: two arrays, so that a loop reading one and writing the other is seen to
// touch two memories): the t-th
// step of the schedule is assembled into lane t % 2 while the cascade factors the (t - 1)-th
// from the other lane's words. Word (i, c) is HA_Lk[i][c >> 1][c & 1]: two banks (the last
// dimension partitioned), even and odd columns, so the source reads two words of a row a cycle. A lane is all zero when its assembly starts: the source that
// streams a step's words into the cascade clears each word it reads, and the assembly writes
// only words it reads (the upper triangle and the gradient of rows < w).

// The assembler's one loop (cholesky_assembler): step s's words streamed out of the lane src
// (its `pairs` pairs, none if s < 0) while step `next`'s first factor's packed Gram is stored,
// not added, into the other lane dst (all zero: its assembly starts here). The lanes are two
// memories of two column banks each (two ports a bank) and come in as two arrays (the
// caller's two call sites, HA_L0, HA_L1 or HA_L1, HA_L0: two copies of this loop, no operator
// in them), so they are different memories in every iteration:
//   - the source reads and clears a word of each of src's banks a cycle (its two ports),
//     two columns of a row (fgc_cpe.h's cpe_pair: columns i + 2j and i + 2j + 1, one from
//     each bank, the word past the gradient of a row of an odd count a zero nobody writes),
//     in the feed's order (rows 0 ... w - 1, row i from its diagonal to the gradient);
//   - the first Gram (d columns) is stored two entries a cycle into dst (within one
//     factor every entry has its own address; two writes a cycle into any of its banks: their
//     two ports; GRAM's or the stage lane's two ports read), after its column map is copied
//     into registers in iterations 0 ... d - 1, three iterations before its first read (a
//     register array is read no sooner than 3 iterations after it is written, as
//     gram_entries' banks).
// Trip max(pairs, d + 3 + ceil(n / 2)) (n = d (d + 1) / 2 + d; no Gram: pairs) at II 1: before
// this loop the source and the Gram store ran one after the other, pairs + d + ceil(n / 2).
// A factor whose Gram the HGC streams beside the elimination (CFG::staged(fac) >= 0: its
// offset in a stage lane) is read from `stage` (the lane the Gram source filled a pass before)
// instead of GRAM.
template <class CFG>
void cholesky_source_first(typename CFG::T src[CFG::MAX_W][CFG::MAX_COLS / 2 + 1][2],
                           typename CFG::T dst[CFG::MAX_W][CFG::MAX_COLS / 2 + 1][2], int w,
                           int pairs, int next, int trip,
                           const typename CFG::T stage[CFG::N_STAGE],
                           hls::stream<fgc_units::cpe_pair<typename CFG::T> >& out) {
#pragma HLS ARRAY_PARTITION variable=src complete dim=3
#pragma HLS ARRAY_PARTITION variable=dst complete dim=3
    typedef typename CFG::T T;
    enum { MAX_TRIP = CFG::MAX_W * (CFG::MAX_W + 4) / 4 + 1 > CFG::MAX_W + 3 +
                                         CFG::TRIP_PACKED / 2
                                         ? CFG::MAX_W * (CFG::MAX_W + 4) / 4 + 1
                                         : CFG::MAX_W + 3 + CFG::TRIP_PACKED / 2 };
    const bool first = next >= 0 && STEP_FACTOR_BEGIN[next] < STEP_FACTOR_BEGIN[next + 1];
    const int fac = first ? STEP_FACTORS[STEP_FACTOR_BEGIN[next]] : 0;
    const int cb = FACTOR_COLMAP_BEGIN[fac];
    const int d = first ? FACTOR_COLMAP_BEGIN[fac + 1] - cb : 0;
    const int g0 = FACTOR_GRAM_OFF[fac];
    const int so = first ? CFG::staged(fac) : -1;
    const int n = first ? d * (d + 1) / 2 + d : 0;
    int map[CFG::MAX_W + 1];
#pragma HLS ARRAY_PARTITION variable=map complete
    map[d] = first ? STEP_W[next] : 0;  // row d of the packed Gram: the gradient, column w
    for (int t = 0, i = 0, c = 0, k = 0, p = 0, q = 0; t < trip; ++t) {
#pragma HLS LOOP_TRIPCOUNT max=MAX_TRIP
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=src inter false
#pragma HLS DEPENDENCE variable=dst inter false
        // map[j] is written in iteration j < d and read from iteration d + 3 on: three
        // iterations apart at least, as gram_entries' register banks
#pragma HLS DEPENDENCE variable=map inter false
        if (t < pairs) {
            const int odd_c = c & 1;  // column c in bank 1: the pair's even column is c + 1
            const int e = (c + odd_c) >> 1, o = c >> 1;  // the even column's and the odd one's
            const T v0 = src[i][e][0], v1 = src[i][o][1];
            src[i][e][0] = T(0);
            src[i][o][1] = T(0);
            const fgc_units::cpe_pair<T> pr = {odd_c ? v1 : v0, odd_c ? v0 : v1};
            out.write(pr);
            if (c + 2 > w) {
                ++i;
                c = i;
            } else {
                c += 2;
            }
        }
        if (t < d) {
            map[t] = FACTOR_COLMAP[cb + t];
        } else if (t >= d + 3 && k < n) {
            for (int h = 0; h < 2; ++h) {
                if (k + h < n) {
                    const int a = map[p], b = map[q];
                    const int lo = b < a ? b : a, hi = b < a ? a : b;
                    dst[lo][hi >> 1][hi & 1] = so >= 0 ? stage[so + k + h] : GRAM[g0 + k + h];
                    if (q == p) {
                        q = 0;
                        ++p;
                    } else {
                        ++q;
                    }
                }
            }
            k += 2;
        }
    }
}

// One segment of entries added, not stored, into HA[lane] (cholesky_assemble_adds'): a further
// factor's packed Gram from GRAM at g0 (child false: its column map from cb, d columns; entry
// (x, y), y <= x, at x (x + 1) / 2 + y, row d: g) or a child's update matrix from nf at u0
// (child true: its separator map from mb, sc columns; row x: columns x ... sc - 1, then its g,
// column sc). One entry a cycle: within a segment every entry goes to its own address (the
// column and separator maps are one-to-one), so no iteration waits for another's add (II 1); a
// later segment's entry may meet the same address.
// A schedule without children prints its children's tables with no entries: their code is
// left out at compile time (no access to an empty table, even on a path that never runs).
enum { CHOLESKY_HAS_CHILDREN = sizeof(STEP_CHILDREN) > 0 && sizeof(STEP_SEPMAP) > 0 };

// Where a step's pivot check (fgc_cpe.h's cpe_check) runs: with FGC_CHECK_BESIDE (the kernel
// defines it where the plan finds it faster: units/cholesky.py's check_beside) in the next
// region's assembler, beside the next step's cascade, on the pivots the cascade left in DPIV /
// RMAX (cpe_rounds), and a last pass checks the last step's; else at the end of the step's own
// cascade (cpe_step). The former takes it off the cascade's path where the cascade is the
// slower process (a chain's steps), the latter off the assembler's where the assembler is (a
// step with many factors). One copy of the check's operators either way.
#ifdef FGC_CHECK_BESIDE
enum { CHOLESKY_CHECK_PASS = 1 };
#else
enum { CHOLESKY_CHECK_PASS = 0 };
#endif

template <class CFG>
void cholesky_add_segment(bool child, int cb, int d, int g0, int so, int mb, int sc, int u0,
                          int w, const typename CFG::T nf[CFG::N_NF],
                          const typename CFG::T stage[CFG::N_STAGE], int lane) {
    typedef typename CFG::T T;
    const int n = child ? sc * (sc + 1) / 2 + sc : d * (d + 1) / 2 + d;
    for (int k = 0, x = 0, y = 0; k < n; ++k) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::TRIP_PACKED
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=HA_L0 inter false
#pragma HLS DEPENDENCE variable=HA_L1 inter false
        int a, b;
        T v;
        if (CHOLESKY_HAS_CHILDREN && child) {
            a = STEP_SEPMAP[mb + x];
            b = y < sc ? STEP_SEPMAP[mb + y] : w;
            v = nf[u0 + x * (sc + 1) + y];
        } else {
            a = x < d ? FACTOR_COLMAP[cb + x] : w;
            b = FACTOR_COLMAP[cb + y];
            v = so >= 0 ? stage[so + k] : GRAM[g0 + k];
        }
        const int lo = b < a ? b : a, hi = b < a ? a : b;
        // one adder: the lane's word read, summed, written back (as cholesky_set_alone)
        const T sum = (lane ? HA_L1[lo][hi >> 1][hi & 1] : HA_L0[lo][hi >> 1][hi & 1]) + v;
        if (lane) {
            HA_L1[lo][hi >> 1][hi & 1] = sum;
        } else {
            HA_L0[lo][hi >> 1][hi & 1] = sum;
        }
        if (child ? y == sc : y == x) {
            ++x;
            y = child ? x : 0;
        } else {
            ++y;
        }
    }
    FGC_CYCLES("assemble", 0, child ? "child" : "gram", n, CFG::SCATTER_II, CFG::SCATTER_DEPTH);
}

// The entries added, not stored, into HA[lane]: step fs's factors after its first (fs >= 0),
// then step kids's children (kids >= 0) whose position in the schedule has the parity `par`
// (odd[c]), from nf, the NF lane the steps at those positions wrote (the t-th step's drain
// writes NF[t % 2]); fs and kids are the same step when both are given. A segment each, all
// through one RTL copy of cholesky_add_segment (its two call sites run one after the other):
// one adder.
template <class CFG>
void cholesky_assemble_adds(int fs, int kids, int par, const bool odd[N_STEPS],
                            const typename CFG::T nf[CFG::N_NF],
                            const typename CFG::T stage[CFG::N_STAGE], int lane) {
#pragma HLS ALLOCATION function instances=cholesky_add_segment<CFG> limit=1
    if (fs >= 0) {
        const int w = STEP_W[fs];
        for (int e = STEP_FACTOR_BEGIN[fs] + 1; e < STEP_FACTOR_BEGIN[fs + 1]; ++e) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_STEP_FACTORS
            const int fac = STEP_FACTORS[e];
            const int cb = FACTOR_COLMAP_BEGIN[fac];
            cholesky_add_segment<CFG>(false, cb, FACTOR_COLMAP_BEGIN[fac + 1] - cb,
                                      FACTOR_GRAM_OFF[fac], CFG::staged(fac), 0, 0, 0, w, nf,
                                      stage, lane);
        }
    }
    if (CHOLESKY_HAS_CHILDREN && kids >= 0) {
        const int w = STEP_W[kids];
        for (int e = STEP_CHILD_BEGIN[kids]; e < STEP_CHILD_BEGIN[kids + 1]; ++e) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_CHILDREN
            const int c = STEP_CHILDREN[e];
            if (int(odd[c]) != par) continue;  // in the other NF lane: the other pass's
            cholesky_add_segment<CFG>(true, 0, 0, 0, -1, STEP_SEPMAP_BEGIN[c],
                                      STEP_W[c] - STEP_F[c], STEP_NF_OFF[c], w, nf, stage, lane);
        }
    }
}

// The assembly's process of the cholesky_overlap region: step s's words from HA[lane] into the
// cascade's stream (none if s < 0) while step `next`'s first factor's Gram goes into the other
// lane (none if next < 0), in one loop (cholesky_source_first; whenever next >= 0, kid_lane is
// 1 - lane); then step `next`'s further factor Grams (streamed ones from the stage lane
// `stage`) and step kids's children at positions of parity rd from nfr (NF[rd]) into
// HA[kid_lane] (none if kids < 0); last the pivot check of step q (the step before s, -1
// none: fgc_cpe.h's cpe_check on the pivots dpr and rows' largest |h| rmr its cascade left in
// DPIV[rd] / RMAX[rd]; *tiny, a pivot too small), off the cascade's path: the one copy of the
// check's multiplier and dividers.
template <class CFG>
void cholesky_assembler(int s, int lane, int next, int kids, int kid_lane, int rd, int q,
                        const bool odd[N_STEPS], const typename CFG::T nfr[CFG::N_NF],
                        const typename CFG::T stage[CFG::N_STAGE],
                        const typename CFG::T dpr[CFG::MAX_F],
                        const typename CFG::T rmr[CFG::MAX_F], bool* tiny,
                        hls::stream<fgc_units::cpe_pair<typename CFG::T> >& out) {
    FGC_BRANCH();  // csim cycle counting only: beside the cascade
    const int w = s >= 0 ? STEP_W[s] : 0;
    const int pairs = s >= 0 && fgc_units::cpe_fits<CFG>(STEP_F[s], w - STEP_F[s])
                          ? fgc_units::cpe_pairs(w) : 0;
    int trip = pairs;
    if (next >= 0 && STEP_FACTOR_BEGIN[next] < STEP_FACTOR_BEGIN[next + 1]) {
        const int fac = STEP_FACTORS[STEP_FACTOR_BEGIN[next]];
        const int d = FACTOR_COLMAP_BEGIN[fac + 1] - FACTOR_COLMAP_BEGIN[fac];
        const int gram = d + 3 + (d * (d + 1) / 2 + d + 1) / 2;
        trip = gram > trip ? gram : trip;
    }
    if (lane == 0) {
        cholesky_source_first<CFG>(HA_L0, HA_L1, w, pairs, next, trip, stage, out);
    } else {
        cholesky_source_first<CFG>(HA_L1, HA_L0, w, pairs, next, trip, stage, out);
    }
    FGC_CYCLES("assemble", 0, "source", trip, CFG::MOVE_II, CFG::MOVE_DEPTH);
    cholesky_assemble_adds<CFG>(next, kids, rd, odd, nfr, stage, kid_lane);
#ifdef FGC_CHECK_BESIDE
    if (q >= 0) *tiny = fgc_units::cpe_check<CFG>(dpr, rmr, STEP_F[q]);
#else  // the check ends the cascade
    (void)q;
    (void)dpr;
    (void)rmr;
    (void)tiny;
#endif
}

// The cascade's process of the cholesky_overlap region: step s factored from the stream, the
// conditional straight into COND and the update matrix into nfw (the cascade's drain). With
// FGC_CHECK_BESIDE its rounds alone (fgc_cpe.h's cpe_rounds), its pivots and rows' largest |h|
// into dpw, rmw (the next region's assembler checks them), *unfit: the step is outside the
// configuration (nothing computed); else cpe_step, the check after the rounds (*unfit: outside,
// or a pivot too small).
template <class CFG>
void cholesky_cascade(int s, typename CFG::T mu,
                      hls::stream<fgc_units::cpe_pair<typename CFG::T> >& src,
                      typename CFG::T nfw[CFG::N_NF], typename CFG::T dpw[CFG::MAX_F],
                      typename CFG::T rmw[CFG::MAX_F], bool* not_pd, bool* unfit) {
    FGC_BRANCH();
    if (s < 0) return;  // a region of the assembler alone: nothing to factor
    const int w = STEP_W[s], f = STEP_F[s];
#ifdef FGC_CHECK_BESIDE
    *unfit = !fgc_units::cpe_rounds<CFG>(src, HF, f, w - f, mu, COND, STEP_COND_OFF[s], nfw,
                                         STEP_NF_OFF[s], dpw, rmw, not_pd);
#else  // the check after the rounds (cpe_step): *unfit, a pivot too small or outside
    (void)dpw;
    (void)rmw;
    fgc_units::cpe_step<CFG>(src, HF, f, w - f, mu, COND, STEP_COND_OFF[s], nfw, STEP_NF_OFF[s],
                             not_pd, unfit);
#endif
}

#ifndef FGC_ELIMINATE_BESIDE  // (else: cholesky_eliminate_beside, below)
// One DATAFLOW region: step s streamed from HA[lane] through the cascade (its update matrix
// into nfw, its pivots into dpw / rmw) while the assembler puts step `next`'s factor Grams into
// the other lane, adds step kids's children that nfr holds and checks step q's pivots from
// dpr / rmr (cholesky_assembler). nfr and nfw are the two NF lanes, dpr / rmr and dpw / rmw
// the two DPIV / RMAX lanes: the assembler reads one while the cascade writes the other.
template <class CFG>
void cholesky_overlap(int s, int lane, int next, int kids, int kid_lane, int rd, int q,
                      typename CFG::T mu, const bool odd[N_STEPS],
                      const typename CFG::T nfr[CFG::N_NF], typename CFG::T nfw[CFG::N_NF],
                      const typename CFG::T dpr[CFG::MAX_F], const typename CFG::T rmr[CFG::MAX_F],
                      typename CFG::T dpw[CFG::MAX_F], typename CFG::T rmw[CFG::MAX_F],
                      bool* not_pd, bool* unfit, bool* tiny) {
#pragma HLS DATAFLOW
    // deep enough that the assembler never waits for the feed (it writes a pair a cycle, the
    // feed reads a word a cycle): half a step's pairs and the feed's start
    enum { DEPTH = CFG::MAX_W * (CFG::MAX_W + 4) / 8 + CFG::ADD_LAT + 8 };
    hls::stream<fgc_units::cpe_pair<typename CFG::T> > frontal;
#pragma HLS STREAM variable=frontal depth=DEPTH
    cholesky_assembler<CFG>(s, lane, next, kids, kid_lane, rd, q, odd, nfr, STAGE_NONE, dpr,
                            rmr, tiny, frontal);
    cholesky_cascade<CFG>(s, mu, frontal, nfw, dpw, rmw, not_pd, unfit);
    FGC_DRAINED(&frontal, 1);  // csim only (fgc_cycles.h)
}

// Eliminate every step in schedule order (LEVEL_STEPS): the t-th step on lane t % 2 of HA and
// of NF (its drain writes NF[t % 2]). Passes of the one cholesky_overlap region (its two parity
// call sites, one RTL copy): first the assembler alone puts the first step's Grams into lane 0;
// then per step t
//   - the assembler alone adds the step's children at positions of parity 1 - t % 2 (the step
//     before among them: its update matrix was written in the region just run) from NF[1 - t %
//     2] into lane t % 2;
//   - the region: the step's cascade (its update matrix into NF[t % 2]) beside the assembler,
//     which streams the step's words, puts step t + 1's Grams into the other lane and adds step
//     t + 1's children at positions of parity 1 - t % 2 (all written before this region) from
//     NF[1 - t % 2], and checks the pivots of step t - 1 (DPIV / RMAX[1 - t % 2]; its cascade
//     wrote them into lane (t - 1) % 2);
// and last the assembler alone checks the last step's pivots.
// Every step runs even after one fails (a lane must not be left holding a step's words); false
// if any step was not positive definite or had a pivot too small.
template <class CFG>
bool cholesky_eliminate_all(typename CFG::T mu) {
#pragma HLS ARRAY_PARTITION variable=HA_L0 complete dim=3
#pragma HLS ARRAY_PARTITION variable=HA_L1 complete dim=3
#pragma HLS ARRAY_PARTITION variable=NF complete dim=1
#pragma HLS ARRAY_PARTITION variable=DPIV complete dim=1
#pragma HLS ARRAY_PARTITION variable=RMAX complete dim=1
    FGC_EVENT("solve");
    FGC_PHASE("assemble");
    bool odd[N_STEPS];  // each step's position parity: the NF lane its drain writes
    for (int i = 0; i < N_STEPS; ++i) {
#pragma HLS PIPELINE II=1
        odd[LEVEL_STEPS[i]] = (i & 1) != 0;
    }
    FGC_CYCLES("assemble", 0, "lanes", N_STEPS, CFG::FILL_II, CFG::FILL_DEPTH);
    bool ok = true;
    // the two parity call sites below are exclusive and sequential: one RTL copy of the region
    // serves both (UG1399, ALLOCATION of a function: one instance for its call sites)
#pragma HLS ALLOCATION function instances=cholesky_overlap<CFG> limit=1
    for (int j = 0; j <= 2 * N_STEPS + CHOLESKY_CHECK_PASS; ++j) {
        const bool last = j > 2 * N_STEPS;  // the last step's pivot check alone
        const int i = last ? -1 : (j - 1) >> 1;  // the step (position) of the pass, -1: none
        const bool region = j > 0 && (j & 1) == 0 && !last;  // its cascade; else the assembler
        const int rd = last ? (N_STEPS - 1) & 1 : (i >= 0 ? 1 - (i & 1) : 0), lane = 1 - rd;
        const int step = i >= 0 ? LEVEL_STEPS[i] : -1;
        const int next = !last && i + 1 < N_STEPS ? LEVEL_STEPS[i + 1] : -1;
        const int s = region ? step : -1;
        const int grams = region || j == 0 ? next : -1;
        const int kids = region || j == 0 ? next : step, kid_lane = region || j == 0 ? rd : lane;
        const int q = last ? LEVEL_STEPS[N_STEPS - 1] : (region && i >= 1 ? LEVEL_STEPS[i - 1]
                                                                          : -1);
        FGC_PHASE(region || last ? "cholesky" : "assemble");
        bool not_pd = false, unfit = false, tiny = false;
        if (rd == 1) {
            cholesky_overlap<CFG>(s, lane, grams, kids, kid_lane, 1, q, mu, odd, NF[1], NF[0],
                                  DPIV[1], RMAX[1], DPIV[0], RMAX[0], &not_pd, &unfit, &tiny);
        } else {
            cholesky_overlap<CFG>(s, lane, grams, kids, kid_lane, 0, q, mu, odd, NF[0], NF[1],
                                  DPIV[0], RMAX[0], DPIV[1], RMAX[1], &not_pd, &unfit, &tiny);
        }
        FGC_JOIN();
        ok = ok && !not_pd && !unfit && !tiny;
    }
    return ok;
}
#endif  // !FGC_ELIMINATE_BESIDE

#ifdef FGC_ELIMINATE_BESIDE
// ---- the HGC beside the elimination (accel.cpp.jinja's linearize_solve; units/cholesky.py's
// beside_passes). The block type with the longest HGC region (the kernel's streamed type)
// writes its Grams into a stream, its instances in the order the elimination reaches their
// steps, while the elimination runs: each pass of cholesky_overlap_beside gains a third
// process, the Gram source (CFG::gram_source: the kernel's, on the streamed type's tables),
// which puts a step's streamed Grams into a stage lane - from the stream on the first solve of
// a linearisation (and keeps them in GRAM_B), from GRAM_B on LM's retries - one pass before the
// assembler reads them from that lane. The stage lanes follow NF's scheme: the two parity call
// sites pass (lane written, lane read) as different arrays, so each lane has one process a pass.
// CFG: LesConfig plus Word (the stream's word), N_STAGE (a lane's words), staged(fac) (the
// factor's offset in a lane, -1 if not streamed) and gram_source(s, relin, lane, grams).

// The source's process: step s's streamed Grams into `stagew` (none if s < 0).
template <class CFG>
void cholesky_gram_source(int s, bool relin, typename CFG::T stagew[CFG::N_STAGE],
                          hls::stream<typename CFG::Word>& grams) {
    FGC_BRANCH();  // csim cycle counting only: beside the assembler and the cascade
    if (s >= 0) CFG::gram_source(s, relin, stagew, grams);
}

// One pass: cholesky_overlap's region (the cascade on step s beside the assembler) with the
// Gram source putting step `src`'s streamed Grams into stagew while the assembler reads step
// `next`'s from stager.
template <class CFG>
void cholesky_overlap_beside(int s, int lane, int next, int kids, int kid_lane, int rd, int q,
                             int src, bool relin, typename CFG::T mu, const bool odd[N_STEPS],
                             const typename CFG::T nfr[CFG::N_NF], typename CFG::T nfw[CFG::N_NF],
                             const typename CFG::T dpr[CFG::MAX_F],
                             const typename CFG::T rmr[CFG::MAX_F],
                             typename CFG::T dpw[CFG::MAX_F], typename CFG::T rmw[CFG::MAX_F],
                             const typename CFG::T stager[CFG::N_STAGE],
                             typename CFG::T stagew[CFG::N_STAGE],
                             hls::stream<typename CFG::Word>& grams, bool* not_pd, bool* unfit,
                             bool* tiny) {
#pragma HLS DATAFLOW
    enum { DEPTH = CFG::MAX_W * (CFG::MAX_W + 4) / 8 + CFG::ADD_LAT + 8 };
    hls::stream<fgc_units::cpe_pair<typename CFG::T> > frontal;
#pragma HLS STREAM variable=frontal depth=DEPTH
    cholesky_gram_source<CFG>(src, relin, stagew, grams);
    cholesky_assembler<CFG>(s, lane, next, kids, kid_lane, rd, q, odd, nfr, stager, dpr, rmr,
                            tiny, frontal);
    cholesky_cascade<CFG>(s, mu, frontal, nfw, dpw, rmw, not_pd, unfit);
    FGC_DRAINED(&frontal, 1);  // csim only (fgc_cycles.h)
}

// cholesky_eliminate_all with the Gram source: the passes of cholesky_overlap_beside, first the
// source alone (the first step's streamed Grams into stage lane 0), then as
// cholesky_eliminate_all's, the source of the pass that assembles step t + 1 (the region of
// step t, or the first step's Grams for t = -1) putting step t + 2's into stage lane t % 2;
// the assembler of step t's region checks step t - 1's pivots, and a last pass the last step's.
// relin: the first solve of a linearisation (the Grams from the stream, the phase hgc_beside,
// each pass whose source reads the stream gated by the producer's last instance of its step),
// else a retry (from GRAM_B). ok false if any step was not positive definite.
template <class CFG>
void cholesky_eliminate_beside(typename CFG::T mu, bool relin,
                               hls::stream<typename CFG::Word>& grams, bool& ok) {
#pragma HLS ARRAY_PARTITION variable=HA_L0 complete dim=3
#pragma HLS ARRAY_PARTITION variable=HA_L1 complete dim=3
#pragma HLS ARRAY_PARTITION variable=NF complete dim=1
#pragma HLS ARRAY_PARTITION variable=DPIV complete dim=1
#pragma HLS ARRAY_PARTITION variable=RMAX complete dim=1
#pragma HLS ARRAY_PARTITION variable=STAGE complete dim=1
    FGC_PHASE(relin ? "hgc_beside" : "reassemble");
    bool odd[N_STEPS];
    for (int i = 0; i < N_STEPS; ++i) {
#pragma HLS PIPELINE II=1
        odd[LEVEL_STEPS[i]] = (i & 1) != 0;
    }
    FGC_CYCLES("assemble", 0, "lanes", N_STEPS, CFG::FILL_II, CFG::FILL_DEPTH);
    bool good = true;
#pragma HLS ALLOCATION function instances=cholesky_overlap_beside<CFG> limit=1
    for (int j = -1; j <= 2 * N_STEPS + CHOLESKY_CHECK_PASS; ++j) {
        const bool last = j > 2 * N_STEPS;  // the last step's pivot check alone
        const int i = j < 0 || last ? -2 : (j - 1) >> 1;  // the step (position) of the pass
        const bool region = j > 0 && (j & 1) == 0 && !last;
        const int lane = last ? 1 - ((N_STEPS - 1) & 1) : (i >= 0 ? (i & 1) : (j < 0 ? 0 : 1));
        const int rd = 1 - lane;
        const int step = i >= 0 ? LEVEL_STEPS[i] : -1;
        const int next = j >= 0 && !last && i + 1 < N_STEPS ? LEVEL_STEPS[i + 1] : -1;
        const int s = region ? step : -1;
        const int grams_of = region || j == 0 ? next : -1;
        const int kids = region || j == 0 ? next : (j < 0 || last ? -1 : step);
        const int q = last ? LEVEL_STEPS[N_STEPS - 1] : (region && i >= 1 ? LEVEL_STEPS[i - 1]
                                                                          : -1);
        const int kid_lane = region || j == 0 ? rd : lane;
        // the source: the step two positions on (j < 0: the first; j == 0: the second)
        const int at = j < 0 ? 0 : (region || j == 0 ? i + 2 : -1);  // (last: none)
        const int src = at >= 0 && at < N_STEPS && CFG::streams(LEVEL_STEPS[at])
                            ? LEVEL_STEPS[at] : -1;
        FGC_PHASE(relin ? "hgc_beside" : (region || last ? "recholesky" : "reassemble"));
        if (relin && src >= 0) FGC_BESIDE_GATE(CFG::last_streamed(src), CFG::MOVE_DEPTH);
        bool not_pd = false, unfit = false, tiny = false;
        if (rd == 1) {
            cholesky_overlap_beside<CFG>(s, lane, grams_of, kids, kid_lane, 1, q, src, relin, mu,
                                         odd, NF[1], NF[0], DPIV[1], RMAX[1], DPIV[0], RMAX[0],
                                         STAGE[1], STAGE[0], grams, &not_pd, &unfit, &tiny);
        } else {
            cholesky_overlap_beside<CFG>(s, lane, grams_of, kids, kid_lane, 0, q, src, relin, mu,
                                         odd, NF[0], NF[1], DPIV[0], RMAX[0], DPIV[1], RMAX[1],
                                         STAGE[0], STAGE[1], grams, &not_pd, &unfit, &tiny);
        }
        FGC_JOIN();
        good = good && !not_pd && !unfit && !tiny;
    }
    ok = good;
}
#endif  // FGC_ELIMINATE_BESIDE
#endif  // FGC_ELIMINATE_CHOLESKY

#ifdef FGC_ELIMINATE_QR
// Stack step s into a unit set's banks: every entry of its rows, zeros included. With
// CFG::BANKS_ZERO (fgc_qr.h's qr_step, which leaves the banks zero; they start zero) only its
// rows' entries are written, else the rows are zeroed first, a word of all N_UNITS banks a cycle
// (fgc_qr_stream.h's banks). The rows go PORTS words a cycle (AB's or NF's two ports, into any
// banks: each bank has two ports too), the damping rows a word a cycle; counted as the plan's
// stack_loops price them. `skip`: bit k set, the k-th of the step's factors is not stacked (the
// marginal's step once its rows hold nothing: qr_eliminate_all's live leaf step), `m` the rows stacked
// (STEP_ROWS[s] less the skipped factors'; skip 0: all of them). `in_place`: the step's factor
// rows are in the banks already (the kernel's datapaths wrote them: only the row count
// advances past them); `dirty` > 0: that many rows hold another step's factor rows the
// datapaths wrote for a solve that did not come (zeroed first, as the unzeroed banks' rows).
// `fed` >= 0: that child's rows are not stacked (the root step in a wavefront reads them from
// their unit set's stream, fgc_qr.h's qr_step_io); `phase` false: counted under the caller's
// phase (the wave region's unit set 1, which stacks the root inside the region); `own` >= 0:
// neither that child's (lin_level's wave: set 1 moves its own step's rows from its UPDBUF).
template <class CFG>
void qr_stack_zero(typename CFG::T bank[CFG::N_UNITS][CFG::MAX_ROWS][CFG::LOCAL_COLS],
                   int rows) {  // qr_stack_rows' first rows zeroed, a word of all banks a cycle
    typedef typename CFG::T T;
    const int zero = rows * CFG::LOCAL_COLS;
    for (int e = 0, i = 0, c = 0; e < zero; ++e) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::TRIP_BANKS
#pragma HLS PIPELINE II=1
        for (int u = 0; u < CFG::N_UNITS; ++u) {
#pragma HLS UNROLL
            bank[u][i][c] = T(0);
        }
        if (c == CFG::LOCAL_COLS - 1) {
            c = 0;
            ++i;
        } else {
            ++c;
        }
    }
    if (zero > 0) FGC_CYCLES("stack", 0, "zero", zero, CFG::FILL_II, CFG::FILL_DEPTH);
}
template <class CFG>
void qr_stack_damping(typename CFG::T bank[CFG::N_UNITS][CFG::MAX_ROWS][CFG::LOCAL_COLS],
                      int row, int f, typename CFG::T root_mu) {  // its damping rows from `row`
    if (CFG::LM) {  // Gauss-Newton: no damping rows
        for (int j = 0; j < f; ++j) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_F
#pragma HLS PIPELINE II=1
            bank[j % CFG::N_UNITS][row + j][j / CFG::N_UNITS] = root_mu;
        }
        FGC_CYCLES("stack", 0, "damping", f, CFG::FILL_II, CFG::FILL_DEPTH);
    }
}
template <class CFG>
void qr_stack_rows(int s, typename CFG::T root_mu,
                   typename CFG::T bank[CFG::N_UNITS][CFG::MAX_ROWS][CFG::LOCAL_COLS],
                   unsigned skip, int m, bool in_place = false, int dirty = 0, int fed = -1,
                   bool phase = true, int own = -1) {
    if (phase) FGC_PHASE("qr_stack");
    const int w = STEP_W[s], f = STEP_F[s];
    qr_stack_zero<CFG>(bank, CFG::BANKS_ZERO ? dirty : (dirty > m ? dirty : m));
    int row = 0;
    for (int e = STEP_FACTOR_BEGIN[s]; e < STEP_FACTOR_BEGIN[s + 1]; ++e) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_STEP_FACTORS
        const int k0 = e - STEP_FACTOR_BEGIN[s];
        if (k0 < 32 && ((skip >> k0) & 1u)) continue;
        const int fac = STEP_FACTORS[e];
        const int cb = FACTOR_COLMAP_BEGIN[fac];
        const int d = FACTOR_COLMAP_BEGIN[fac + 1] - cb;
        const int a0 = FACTOR_A_OFF[fac];
        const int words = FACTOR_A_OFF[fac + 1] - a0;  // its rows x (d + 1)
        if (in_place) {  // the datapath wrote them there (the kernel's rows into the banks)
            row = row + words / (d + 1);
            continue;
        }
        // row r, column c of its [A | b] into the step's row `row + r`
        for (int k = 0, r = 0, c = 0; k < words; k += PORTS) {  // PORTS words a cycle
#pragma HLS LOOP_TRIPCOUNT max=CFG::TRIP_ROWS
#pragma HLS PIPELINE II=1
            for (int h = 0; h < PORTS; ++h) {
                if (k + h < words) {
                    const int t = c < d ? FACTOR_COLMAP[cb + c] : w;
                    bank[t % CFG::N_UNITS][row + r][t / CFG::N_UNITS] = AB[a0 + k + h];
                    if (c == d) {
                        c = 0;
                        ++r;
                    } else {
                        ++c;
                    }
                }
            }
        }
        FGC_CYCLES("stack", 0, "factor_rows", (words + PORTS - 1) / PORTS, CFG::MOVE_II,
                   CFG::MOVE_DEPTH);
        row = row + words / (d + 1);
    }
    for (int e = STEP_CHILD_BEGIN[s]; e < STEP_CHILD_BEGIN[s + 1]; ++e) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_CHILDREN
        const int c = STEP_CHILDREN[e];
        // its rows come by stream, or (own) the caller moves them from its set's buffer: only
        // the row count advances
        const bool by_stream = c == fed || c == own;
        const int sc = STEP_W[c] - STEP_F[c];
        const int mb = STEP_SEPMAP_BEGIN[c];
        const int n0 = STEP_NF_OFF[c];
        const int words = by_stream ? 0 : STEP_NF_ROWS[c] * (sc + 1);
        for (int k = 0, r = 0, q = 0; k < words; k += PORTS) {  // PORTS words a cycle
#pragma HLS LOOP_TRIPCOUNT max=CFG::TRIP_UPDATE
#pragma HLS PIPELINE II=1
            for (int h = 0; h < PORTS; ++h) {
                if (k + h < words) {
                    const int t = q < sc ? STEP_SEPMAP[mb + q] : w;
                    bank[t % CFG::N_UNITS][row + r][t / CFG::N_UNITS] = NF[n0 + k + h];
                    if (q == sc) {
                        q = 0;
                        ++r;
                    } else {
                        ++q;
                    }
                }
            }
        }
        if (!by_stream)
            FGC_CYCLES("stack", 0, "child_rows", (words + PORTS - 1) / PORTS, CFG::MOVE_II,
                       CFG::MOVE_DEPTH);
        row = row + STEP_NF_ROWS[c];
    }
    qr_stack_damping<CFG>(bank, row, f, root_mu);
}

// lin_level's root step in a wavefront, its stack on unit set 1 (the kernel's qr_set1): what
// qr_stack_rows(s, root_mu, bank, 0, m, true, 0, c0, false, c1) does - its own rows in place
// (the datapaths sent them), both children's taken by the set (c0's by stream, c1's from its
// buffer): the zeroing, the rows past them, the damping rows - reading neither AB nor NF (the
// commit process of the same region writes NF: one writer, no reader).
template <class CFG>
void qr_stack_wave_root(int s, typename CFG::T root_mu,
                        typename CFG::T bank[CFG::N_UNITS][CFG::MAX_ROWS][CFG::LOCAL_COLS],
                        int m) {
    qr_stack_zero<CFG>(bank, CFG::BANKS_ZERO ? 0 : m);
    int row = 0;
    for (int e = STEP_FACTOR_BEGIN[s]; e < STEP_FACTOR_BEGIN[s + 1]; ++e) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_STEP_FACTORS
        const int fac = STEP_FACTORS[e];
        const int d = FACTOR_COLMAP_BEGIN[fac + 1] - FACTOR_COLMAP_BEGIN[fac];
        row = row + (FACTOR_A_OFF[fac + 1] - FACTOR_A_OFF[fac]) / (d + 1);
    }
    for (int e = STEP_CHILD_BEGIN[s]; e < STEP_CHILD_BEGIN[s + 1]; ++e) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_CHILDREN
        row = row + STEP_NF_ROWS[STEP_CHILDREN[e]];
    }
    qr_stack_damping<CFG>(bank, row, STEP_F[s], root_mu);
}

// A unit set's result for step s into COND and NF, PORTS words a cycle (`phase` false: counted
// under the caller's phase, as qr_stack_rows; lin_level's wave commits its three steps as its
// sets' collectors write them: qr_commit_pairs).
template <class CFG>
void qr_commit(int s, const typename CFG::T cond[CFG::MAX_F * CFG::MAX_COLS],
               const typename CFG::T update[CFG::MAX_COLS * CFG::MAX_COLS], bool phase = true) {
    if (phase) FGC_PHASE("qr_commit");
    const int w = STEP_W[s], f = STEP_F[s], sw = w - f;
    const int c0 = STEP_COND_OFF[s], n0 = STEP_NF_OFF[s];
    const int nc = f * (w + 1), nu = STEP_NF_ROWS[s] * (sw + 1);
    for (int i = 0; i < nc; i += PORTS) {  // PORTS words a cycle
#pragma HLS LOOP_TRIPCOUNT max=CFG::TRIP_COND
#pragma HLS PIPELINE II=1
        for (int h = 0; h < PORTS; ++h) {
            if (i + h < nc) {
                const typename CFG::T v = cond[i + h];
                COND[c0 + i + h] = v;
#ifdef FGC_SPEC_MARGINAL  // the leaving keyframe's conditional twice (the stream's KEEP_COND)
                if (s == SPEC_STEP) KEEP_COND[i + h] = v;
#endif
#ifdef FGC_BS_ROOT_COMMIT  // the root's into back-substitution's lane 0 (its load, fgc_backsub.h)
                if (s == BS_ROOT) BS_COND0[i + h] = v;
#endif
            }
        }
    }
    FGC_CYCLES("commit", 0, "cond", (nc + PORTS - 1) / PORTS, CFG::MOVE_II, CFG::MOVE_DEPTH);
    for (int i = 0; i < nu; i += PORTS) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::TRIP_UPDATE
#pragma HLS PIPELINE II=1
        for (int h = 0; h < PORTS; ++h) {
            if (i + h < nu) NF[n0 + i + h] = update[i + h];
        }
    }
    FGC_CYCLES("commit", 0, "nf", (nu + PORTS - 1) / PORTS, CFG::MOVE_II, CFG::MOVE_DEPTH);
}

// A unit set's result for step s into COND and NF as its collector writes it (lin_level's root
// step in a wavefront: fgc_qr.h's COMMIT stream, a pair of one row's words a stream word), two
// words a cycle: rc rows of the conditional (w + 1 words each), then rn rows of the new factor
// (s + 1 each; set 1's steps none: c1's passed rows went into the root from its buffer), in
// qr_commit's places (the root's conditional into back-substitution's lane 0 too, and the
// leaving keyframe's into KEEP_COND, as qr_commit writes them). The process of the region beside
// the sets (the kernel's qr_commit_wave) calls it for set 0's step, then set 1's two, each
// stream holding what its reader has not taken yet (set 0's: depth 2, the commit keeps up;
// set 1's: every pair, it is read after set 0's). `wait` (csim counting only, fgc_cycles.h's
// FGC_WAIT): the unit set whose step's span this loop ends no earlier than (the set's last pair
// comes before its last region and pivot check end: an upper bound; units/qr.py's
// wave_commit_end), -1 none.
template <class CFG>
void qr_commit_pairs(int s, int rc, int rn,
                     hls::stream<fgc_units::qr_commit_pair<typename CFG::T> >& q, int wait) {
    typedef typename CFG::T T;
    enum { TRIP = CFG::TRIP_COND + CFG::TRIP_UPDATE };  // (two words a cycle)
    const int w = STEP_W[s], f = STEP_F[s], cols = w + 1, sc = w - f + 1;
    const int pc = rc * ((cols + 1) / 2), pn = rn * ((sc + 1) / 2);
    const int c0 = STEP_COND_OFF[s], n0 = STEP_NF_OFF[s];
    int r = 0, p = 0;
    for (int k = 0; k < pc + pn; ++k) {
#pragma HLS LOOP_TRIPCOUNT max=TRIP
#pragma HLS PIPELINE II=1
        const bool nf = k >= pc;
        const int len = nf ? sc : cols;
        const int i = r * len + 2 * p;  // the pair's first word in the conditional / new factor
        const bool two = 2 * p + 1 < len;
        const fgc_units::qr_commit_pair<T> x = q.read();
        if (nf) {
            NF[n0 + i] = x.pw[0];
            if (two) NF[n0 + i + 1] = x.pw[1];
        } else {
            COND[c0 + i] = x.pw[0];
            if (two) COND[c0 + i + 1] = x.pw[1];
#ifdef FGC_SPEC_MARGINAL  // the leaving keyframe's conditional twice (the stream's KEEP_COND)
            if (s == SPEC_STEP) {
                KEEP_COND[i] = x.pw[0];
                if (two) KEEP_COND[i + 1] = x.pw[1];
            }
#endif
#ifdef FGC_BS_ROOT_COMMIT  // the root's into back-substitution's lane 0 (its load, fgc_backsub.h)
            if (s == BS_ROOT) {
                BS_COND0[i] = x.pw[0];
                if (two) BS_COND0[i + 1] = x.pw[1];
            }
#endif
        }
        if (2 * p + 2 >= len) {  // the row's last pair
            p = 0;
            r = k == pc - 1 ? 0 : r + 1;
        } else {
            ++p;
        }
    }
    if (wait >= 0) FGC_WAIT("commit", 0, "qr_set", wait, "step");
    FGC_CYCLES("commit", 0, "pairs", pc + pn, CFG::MOVE_II, CFG::MOVE_DEPTH);
}

// Whether the kernel's SETS runs the root step in a wavefront (HlsConfig root_wave: it declares
// WAVE_ROOT_LEVEL); a kernel without it eliminates level by level.
template <class X>
struct qr_void {
    typedef void type;
};
template <class SETS, class = void>
struct qr_wave_hook {
    enum { value = 0 };
};
template <class SETS>
struct qr_wave_hook<SETS, typename qr_void<decltype(SETS::WAVE_ROOT_LEVEL)>::type> {
    enum { value = 1 };
};

// Eliminate every step, level by level: a level's steps are independent, the unit sets take
// them CFG::UNIT_SETS at a time (stack each, the sets' DATAFLOW region, commit each). False if
// rank deficient. leaf >= 0 (the on-chip window's marginalisation): step leaf alone, once
// more at mu = 0 (no damping rows, no square root), on unit set 0 (the other sets idle) - one
// "level" of one step through the same stack, region and commit, so the marginal's step is
// LM's unit set 0, not a copy of it. `live` (a leaf step once keyframe 0 has left the window):
// the step's factors that hold nothing from then on (CFG::LEAF_SKIP, bit k the k-th of its
// factors) are neither stacked nor reflected, the unit takes CFG::LEAF_LIVE_ROWS rows.
template <class CFG, class SETS>
bool qr_eliminate_all(typename CFG::T mu, int leaf = -1, bool live = false) {
    // INLINE: its SETS hooks' calls are the kernel's eliminate_all's (the one-step window's
    // lin_level is called there too: its ALLOCATION makes the two one instance)
#pragma HLS INLINE
    typedef typename CFG::T T;
    const bool one = leaf >= 0;
    const bool gone = one && live;  // the leaf step's rows without the gone factors'
    T root_mu = T(0);
    if (one) {
        FGC_EVENT("marginal_solve");
    } else {
        FGC_EVENT("solve");
        FGC_PHASE("qr_stack");
        if (CFG::LM) {  // the damping rows' sqrt(mu) (Gauss-Newton: qr_stack_rows writes none)
            root_mu = fgc_sqrt(mu);
            FGC_CYCLES("stack", 0, "root_mu", 1, CFG::ROOT_II, CFG::ROOT_DEPTH);
        }
    }
    bool ok = true;
    for (int l = 0; l < (one ? 1 : N_LEVELS); ++l) {
#pragma HLS LOOP_TRIPCOUNT max=N_LEVELS
        // SETS::WAVE_ROOT_LEVEL: the root step in a wavefront behind its two children - the
        // last two levels are one region (set 0 the first child, set 1 the second, then its
        // commit and the root: the kernel's SETS::level), set 1's commit the root's
        const bool waves = qr_wave_hook<SETS>::value != 0;
        const bool wave = waves && !one && l == N_LEVELS - 2;
        if (waves && !one && l == N_LEVELS - 1) break;
        const int begin = one ? 0 : LEVEL_BEGIN[l], end = one ? 1 : LEVEL_BEGIN[l + 1];
        for (int i = begin; i < end; i += CFG::UNIT_SETS) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_LEVEL_WIDTH
            bool has[CFG::UNIT_SETS], bad[CFG::UNIT_SETS];
            int s[CFG::UNIT_SETS], m[CFG::UNIT_SETS];
#pragma HLS ARRAY_PARTITION variable=has complete
#pragma HLS ARRAY_PARTITION variable=bad complete
#pragma HLS ARRAY_PARTITION variable=s complete
#pragma HLS ARRAY_PARTITION variable=m complete
            for (int u = 0; u < CFG::UNIT_SETS; ++u) {  // set by set, as the sets' banks fill
#pragma HLS UNROLL
                has[u] = i + u < end;
                s[u] = !has[u] ? 0 : one ? leaf : LEVEL_STEPS[i + u];
                m[u] = !has[u] ? 0 : gone ? CFG::LEAF_LIVE_ROWS : STEP_ROWS[s[u]];
                if (has[u]) SETS::stack(u, s[u], root_mu, gone ? CFG::LEAF_SKIP : 0u, m[u], !one);
                bad[u] = false;
            }
            FGC_PHASE("qr");
            SETS::level(has, s, m, bad);  // (with the wave: the kernel's qr_level sees it)
            FGC_JOIN();
            for (int u = 0; u < CFG::UNIT_SETS; ++u) {
#pragma HLS UNROLL
                if (has[u]) {
                    ok = ok && !bad[u];
                    SETS::commit(u, wave && u == 1 ? LEVEL_STEPS[LEVEL_BEGIN[N_LEVELS - 1]] : s[u]);
                }
            }
        }
    }
    return ok;
}
#endif  // FGC_ELIMINATE_QR


#endif  // FGC_ELIMINATE_H
