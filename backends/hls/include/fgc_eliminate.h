// fgc_eliminate.h: the elimination driver of the dataflow kernel, around its linear-solver units
// (fgc_cpe.h's cascade, fgc_qr.h's QR unit): what goes into a step's unit and where its result
// goes. Per step s of the schedule:
//
//   Cholesky: bool cholesky_eliminate_all<CFG>(mu)  every step in schedule order: [H | g]
//             assembled from the step's factors' Grams and its children's update matrices
//             (while the cascade factors the step before: the cholesky_overlap region, two
//             lanes HA[0], HA[1]), streamed into the cascade, whose drain writes the
//             conditional into COND and the update matrix into NF[t % 2] (the t-th step's);
//             false if singular.
//   QR:       void qr_stack<CFG>(s, root_mu, bank)  the step's rows into a unit set's banks
//             (its factors' [A | b], its children's new factors, sqrt(mu) I if CFG::LM).
//             void qr_commit<CFG>(s, cond, update)  a unit set's result into COND and NF.
//             bool qr_eliminate_all<CFG, SETS>(mu)  every step, level by level: a level's
//             steps go CFG::UNIT_SETS at a time to the unit sets (stacked, the sets'
//             DATAFLOW region, committed); false if rank deficient.
//             bool qr_eliminate_leaf<CFG, SETS>(s)  step s once more at mu = 0 on unit set 0
//             (the on-chip window's marginalisation); false if rank deficient.
//
// The unit-set wiring stays the kernel's (it depends on the number of unit sets: each set its
// own memories and RTL instance): SETS holds its hooks, static functions the kernel defines
// after its qr_set<u> and qr_level -
//   SETS::stack(u, s, root_mu)   qr_stack<CFG>(s, root_mu, WORK<u>)
//   SETS::level(has, s, bad)     the qr_level region: set u takes step s[u] where has[u]
//                                (else none), bad[u] set if rank deficient
//   SETS::commit(u, s)           qr_commit<CFG>(s, CONDBUF<u>, UPDBUF<u>)
//   SETS::leaf(s, bad)           (qr_eliminate_leaf only) step s on unit set 0 alone, qr_set0
//
// Included by the kernel inside its namespace (fgc::, or fgc::les for the mixed design), after
// its schedule tables and memories, which these functions name: STEP_W, STEP_F, STEP_ROWS,
// STEP_FACTOR_BEGIN, STEP_FACTORS, STEP_CHILD_BEGIN, STEP_CHILDREN, STEP_SEPMAP_BEGIN,
// STEP_SEPMAP, STEP_NF_OFF, STEP_NF_ROWS, STEP_COND_OFF, FACTOR_COLMAP_BEGIN, FACTOR_COLMAP,
// FACTOR_A_OFF, FACTOR_GRAM_OFF, LEVEL_STEPS, LEVEL_BEGIN, N_LEVELS, N_STEPS (tables); AB, GRAM,
// COND, NF (Cholesky: NF[2], two lanes), PORTS, fgc_sqrt and, for Cholesky, HA and HF
// (memories). CFG is the kernel's LesConfig: T (the linear solver's scalar), the unit's sizes,
// LM, the tables' largest trip counts (MAX_STEP_FACTORS, MAX_CHILDREN, TRIP_*) and the (II,
// depth) of the plan's fill, move and scatter loops (QR: UNIT_SETS, MAX_LEVEL_WIDTH and the
// (II, depth) ROOT_II, ROOT_DEPTH of sqrt(mu) too); cycles to FGC_CYCLES as the plan prices
// them. Define FGC_ELIMINATE_CHOLESKY or FGC_ELIMINATE_QR
// first: the other solver's memories do not exist.
#ifndef FGC_ELIMINATE_H
#define FGC_ELIMINATE_H

#ifdef FGC_ELIMINATE_CHOLESKY
// The assembly buffers HA[lane] (the kernel's memory, two lanes of a step's [H | g]): the t-th
// step of the schedule is assembled into lane t % 2 while the cascade factors the (t - 1)-th
// from the other lane's words. Word (i, c) is HA[lane][i][c >> 1][c & 1]: two banks (the last
// dimension partitioned), even and odd columns, so the source reads two words of a row a cycle. A lane is all zero when its assembly starts: the source that
// streams a step's words into the cascade clears each word it reads, and the assembly writes
// only words it reads (the upper triangle and the gradient of rows < w).

// Step s's first factor's packed Gram into HA[lane], stored, not added (the lane is all zero):
// two entries a cycle (GRAM's two ports read, the lane's two ports written; within one factor
// every entry has its own address), its column map first copied into registers (two reads of
// it an entry each). The further factors are cholesky_assemble_adds'.
template <class CFG>
void cholesky_assemble_first(int s, int lane) {
    const int w = STEP_W[s];
    if (STEP_FACTOR_BEGIN[s] < STEP_FACTOR_BEGIN[s + 1]) {
        const int fac = STEP_FACTORS[STEP_FACTOR_BEGIN[s]];
        const int cb = FACTOR_COLMAP_BEGIN[fac];
        const int d = FACTOR_COLMAP_BEGIN[fac + 1] - cb;
        const int g0 = FACTOR_GRAM_OFF[fac];
        const int n = d * (d + 1) / 2 + d;
        int map[CFG::MAX_W + 1];
#pragma HLS ARRAY_PARTITION variable=map complete
        for (int c = 0; c < d; ++c) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_W
#pragma HLS PIPELINE II=1
            map[c] = FACTOR_COLMAP[cb + c];
        }
        map[d] = w;  // row d of the packed Gram: the gradient, column w of the lane
        FGC_CYCLES("assemble", 0, "map", d, CFG::MOVE_II, CFG::MOVE_DEPTH);
        for (int k = 0, p = 0, q = 0; k < n; k += 2) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::TRIP_PACKED/2
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=HA inter false
            for (int h = 0; h < 2; ++h) {
                if (k + h < n) {
                    const int a = map[p], b = map[q];
                    const int lo = b < a ? b : a, hi = b < a ? a : b;
                    HA[lane][lo][hi >> 1][hi & 1] = GRAM[g0 + k + h];
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

template <class CFG>
void cholesky_add_segment(bool child, int cb, int d, int g0, int mb, int sc, int u0, int w,
                          const typename CFG::T nf[CFG::N_NF], int lane) {
    typedef typename CFG::T T;
    const int n = child ? sc * (sc + 1) / 2 + sc : d * (d + 1) / 2 + d;
    for (int k = 0, x = 0, y = 0; k < n; ++k) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::TRIP_PACKED
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=HA inter false
        int a, b;
        T v;
        if (CHOLESKY_HAS_CHILDREN && child) {
            a = STEP_SEPMAP[mb + x];
            b = y < sc ? STEP_SEPMAP[mb + y] : w;
            v = nf[u0 + x * (sc + 1) + y];
        } else {
            a = x < d ? FACTOR_COLMAP[cb + x] : w;
            b = FACTOR_COLMAP[cb + y];
            v = GRAM[g0 + k];
        }
        const int lo = b < a ? b : a, hi = b < a ? a : b;
        HA[lane][lo][hi >> 1][hi & 1] += v;
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
                            const typename CFG::T nf[CFG::N_NF], int lane) {
#pragma HLS ALLOCATION function instances=cholesky_add_segment<CFG> limit=1
    if (fs >= 0) {
        const int w = STEP_W[fs];
        for (int e = STEP_FACTOR_BEGIN[fs] + 1; e < STEP_FACTOR_BEGIN[fs + 1]; ++e) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_STEP_FACTORS
            const int fac = STEP_FACTORS[e];
            const int cb = FACTOR_COLMAP_BEGIN[fac];
            cholesky_add_segment<CFG>(false, cb, FACTOR_COLMAP_BEGIN[fac + 1] - cb,
                                      FACTOR_GRAM_OFF[fac], 0, 0, 0, w, nf, lane);
        }
    }
    if (CHOLESKY_HAS_CHILDREN && kids >= 0) {
        const int w = STEP_W[kids];
        for (int e = STEP_CHILD_BEGIN[kids]; e < STEP_CHILD_BEGIN[kids + 1]; ++e) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_CHILDREN
            const int c = STEP_CHILDREN[e];
            if (int(odd[c]) != par) continue;  // in the other NF lane: the other pass's
            cholesky_add_segment<CFG>(true, 0, 0, 0, STEP_SEPMAP_BEGIN[c], STEP_W[c] - STEP_F[c],
                                      STEP_NF_OFF[c], w, nf, lane);
        }
    }
}

// The assembly's process of the cholesky_overlap region: step s's words from HA[lane] into the
// cascade's stream in its feed's order (rows 0 ... w - 1, row i from its diagonal to the
// gradient), two columns of a row a cycle (fgc_cpe.h's cpe_pair: columns i + 2j and
// i + 2j + 1, one from each bank, the word past the gradient of a row of an odd count a zero
// nobody writes), each cleared as it is read (a read and a write a cycle in each bank); then
// step `next`'s factor Grams into the other lane (none if next < 0); then step kids's children
// at positions of parity rd from nfr (NF[rd]) into HA[kid_lane] (none if kids < 0).
template <class CFG>
void cholesky_assembler(int s, int lane, int next, int kids, int kid_lane, int rd,
                        const bool odd[N_STEPS], const typename CFG::T nfr[CFG::N_NF],
                        hls::stream<fgc_units::cpe_pair<typename CFG::T> >& out) {
    typedef typename CFG::T T;
    enum { MAX_PAIRS = CFG::MAX_W * (CFG::MAX_W + 4) / 4 + 1 };
    FGC_BRANCH();  // csim cycle counting only: beside the cascade
    const int w = s >= 0 ? STEP_W[s] : 0;
    const int pairs = s >= 0 && fgc_units::cpe_fits<CFG>(STEP_F[s], w - STEP_F[s])
                          ? fgc_units::cpe_pairs(w) : 0;
    // trip sum_i ceil((w + 1 - i) / 2), II 1, depth of a move
    for (int t = 0, i = 0, c = 0; t < pairs; ++t) {
#pragma HLS LOOP_TRIPCOUNT max=MAX_PAIRS
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=HA inter false
        const int odd_c = c & 1;  // column c in bank 1: the pair's even column is c + 1
        const int e = (c + odd_c) >> 1, o = c >> 1;  // the even column's and the odd one's word
        const T v0 = HA[lane][i][e][0], v1 = HA[lane][i][o][1];
        HA[lane][i][e][0] = T(0);
        HA[lane][i][o][1] = T(0);
        const fgc_units::cpe_pair<T> p = {odd_c ? v1 : v0, odd_c ? v0 : v1};
        out.write(p);
        if (c + 2 > w) {
            ++i;
            c = i;
        } else {
            c += 2;
        }
    }
    FGC_CYCLES("assemble", 0, "source", pairs, CFG::MOVE_II, CFG::MOVE_DEPTH);
    if (next >= 0) cholesky_assemble_first<CFG>(next, kid_lane);
    cholesky_assemble_adds<CFG>(next, kids, rd, odd, nfr, kid_lane);
}

// The cascade's process of the cholesky_overlap region: step s factored from the stream, the
// conditional straight into COND and the update matrix into nfw (the cascade's drain).
template <class CFG>
void cholesky_cascade(int s, typename CFG::T mu,
                      hls::stream<fgc_units::cpe_pair<typename CFG::T> >& src,
                      typename CFG::T nfw[CFG::N_NF], bool* not_pd, bool* singular) {
    FGC_BRANCH();
    if (s < 0) return;  // a region of the assembler alone: nothing to factor
    const int w = STEP_W[s], f = STEP_F[s];
    fgc_units::cpe_step<CFG>(src, HF, f, w - f, mu, COND, STEP_COND_OFF[s], nfw, STEP_NF_OFF[s],
                             not_pd, singular);
}

// One DATAFLOW region: step s streamed from HA[lane] through the cascade (its update matrix
// into nfw) while the assembler puts step `next`'s factor Grams into the other lane and adds
// step kids's children that nfr holds (cholesky_assembler). nfr and nfw are the two NF lanes:
// the assembler reads one while the drain writes the other.
template <class CFG>
void cholesky_overlap(int s, int lane, int next, int kids, int kid_lane, int rd,
                      typename CFG::T mu, const bool odd[N_STEPS],
                      const typename CFG::T nfr[CFG::N_NF], typename CFG::T nfw[CFG::N_NF],
                      bool* not_pd, bool* singular) {
#pragma HLS DATAFLOW
    // deep enough that the assembler never waits for the feed (it writes a pair a cycle, the
    // feed reads a word a cycle): half a step's pairs and the feed's start
    enum { DEPTH = CFG::MAX_W * (CFG::MAX_W + 4) / 8 + CFG::ADD_LAT + 8 };
    hls::stream<fgc_units::cpe_pair<typename CFG::T> > frontal;
#pragma HLS STREAM variable=frontal depth=DEPTH
    cholesky_assembler<CFG>(s, lane, next, kids, kid_lane, rd, odd, nfr, frontal);
    cholesky_cascade<CFG>(s, mu, frontal, nfw, not_pd, singular);
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
//     NF[1 - t % 2].
// Every step runs even after one fails (a lane must not be left holding a step's words); false
// if any step was not positive definite or had a pivot too small.
template <class CFG>
bool cholesky_eliminate_all(typename CFG::T mu) {
#pragma HLS ARRAY_PARTITION variable=HA complete dim=4
#pragma HLS ARRAY_PARTITION variable=NF complete dim=1
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
    for (int j = 0; j <= 2 * N_STEPS; ++j) {
        const int i = (j - 1) >> 1;  // the step (position) of the pass, -1 for the first
        const bool region = j > 0 && (j & 1) == 0;  // its cascade; else the assembler alone
        const int lane = i >= 0 ? (i & 1) : 1, rd = 1 - lane;
        const int step = i >= 0 ? LEVEL_STEPS[i] : -1;
        const int next = i + 1 < N_STEPS ? LEVEL_STEPS[i + 1] : -1;
        const int s = region ? step : -1;
        const int grams = region || j == 0 ? next : -1;
        const int kids = region || j == 0 ? next : step, kid_lane = region || j == 0 ? rd : lane;
        FGC_PHASE(region ? "cholesky" : "assemble");
        bool not_pd = false, singular = false;
        if (rd == 1) {
            cholesky_overlap<CFG>(s, lane, grams, kids, kid_lane, 1, mu, odd, NF[1], NF[0],
                                  &not_pd, &singular);
        } else {
            cholesky_overlap<CFG>(s, lane, grams, kids, kid_lane, 0, mu, odd, NF[0], NF[1],
                                  &not_pd, &singular);
        }
        FGC_JOIN();
        ok = ok && !singular;
    }
    return ok;
}
#endif  // FGC_ELIMINATE_CHOLESKY

#ifdef FGC_ELIMINATE_QR
// Stack step s into a unit set's banks: every entry of its rows, zeros included. The zeroing
// writes a word of all N_UNITS banks a cycle, the rows PORTS words a cycle (AB's or NF's two
// ports, into any banks: each bank has two ports too), the damping rows a word a cycle; counted
// as the plan's stack_loops price them.
template <class CFG>
void qr_stack(int s, typename CFG::T root_mu,
              typename CFG::T bank[CFG::N_UNITS][CFG::MAX_ROWS][CFG::LOCAL_COLS]) {
    typedef typename CFG::T T;
    FGC_PHASE("qr_stack");
    const int w = STEP_W[s], f = STEP_F[s], m = STEP_ROWS[s];
    for (int e = 0, i = 0, c = 0; e < m * CFG::LOCAL_COLS; ++e) {
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
    FGC_CYCLES("stack", 0, "zero", m * CFG::LOCAL_COLS, CFG::FILL_II, CFG::FILL_DEPTH);
    int row = 0;
    for (int e = STEP_FACTOR_BEGIN[s]; e < STEP_FACTOR_BEGIN[s + 1]; ++e) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_STEP_FACTORS
        const int fac = STEP_FACTORS[e];
        const int cb = FACTOR_COLMAP_BEGIN[fac];
        const int d = FACTOR_COLMAP_BEGIN[fac + 1] - cb;
        const int a0 = FACTOR_A_OFF[fac];
        const int words = FACTOR_A_OFF[fac + 1] - a0;  // its rows x (d + 1)
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
        const int sc = STEP_W[c] - STEP_F[c];
        const int mb = STEP_SEPMAP_BEGIN[c];
        const int n0 = STEP_NF_OFF[c];
        const int words = STEP_NF_ROWS[c] * (sc + 1);
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
        FGC_CYCLES("stack", 0, "child_rows", (words + PORTS - 1) / PORTS, CFG::MOVE_II,
                   CFG::MOVE_DEPTH);
        row = row + STEP_NF_ROWS[c];
    }
    if (CFG::LM) {  // Gauss-Newton: no damping rows
        for (int j = 0; j < f; ++j) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_F
#pragma HLS PIPELINE II=1
            bank[j % CFG::N_UNITS][row + j][j / CFG::N_UNITS] = root_mu;
        }
        FGC_CYCLES("stack", 0, "damping", f, CFG::FILL_II, CFG::FILL_DEPTH);
    }
}

// A unit set's result for step s into COND and NF, PORTS words a cycle.
template <class CFG>
void qr_commit(int s, const typename CFG::T cond[CFG::MAX_F * CFG::MAX_COLS],
               const typename CFG::T update[CFG::MAX_COLS * CFG::MAX_COLS]) {
    FGC_PHASE("qr_commit");
    const int w = STEP_W[s], f = STEP_F[s], sw = w - f;
    const int c0 = STEP_COND_OFF[s], n0 = STEP_NF_OFF[s];
    const int nc = f * (w + 1), nu = STEP_NF_ROWS[s] * (sw + 1);
    for (int i = 0; i < nc; i += PORTS) {  // PORTS words a cycle
#pragma HLS LOOP_TRIPCOUNT max=CFG::TRIP_COND
#pragma HLS PIPELINE II=1
        for (int h = 0; h < PORTS; ++h) {
            if (i + h < nc) COND[c0 + i + h] = cond[i + h];
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

// Eliminate every step, level by level: a level's steps are independent, the unit sets take
// them CFG::UNIT_SETS at a time (stack each, the sets' DATAFLOW region, commit each). False if
// rank deficient.
template <class CFG, class SETS>
bool qr_eliminate_all(typename CFG::T mu) {
    typedef typename CFG::T T;
    FGC_EVENT("solve");
    FGC_PHASE("qr_stack");
    const T root_mu = fgc_sqrt(mu);
    FGC_CYCLES("stack", 0, "root_mu", 1, CFG::ROOT_II, CFG::ROOT_DEPTH);
    bool ok = true;
    for (int l = 0; l < N_LEVELS; ++l) {
        for (int i = LEVEL_BEGIN[l]; i < LEVEL_BEGIN[l + 1]; i += CFG::UNIT_SETS) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_LEVEL_WIDTH
            bool has[CFG::UNIT_SETS], bad[CFG::UNIT_SETS];
            int s[CFG::UNIT_SETS];
#pragma HLS ARRAY_PARTITION variable=has complete
#pragma HLS ARRAY_PARTITION variable=bad complete
#pragma HLS ARRAY_PARTITION variable=s complete
            for (int u = 0; u < CFG::UNIT_SETS; ++u) {  // set by set, as the sets' banks fill
#pragma HLS UNROLL
                has[u] = i + u < LEVEL_BEGIN[l + 1];
                s[u] = has[u] ? LEVEL_STEPS[i + u] : 0;
                if (has[u]) SETS::stack(u, s[u], root_mu);
                bad[u] = false;
            }
            FGC_PHASE("qr");
            SETS::level(has, s, bad);
            FGC_JOIN();
            for (int u = 0; u < CFG::UNIT_SETS; ++u) {
#pragma HLS UNROLL
                if (has[u]) {
                    ok = ok && !bad[u];
                    SETS::commit(u, s[u]);
                }
            }
        }
    }
    return ok;
}

// The on-chip window's marginalisation: step s (slot 0's) once more, at mu = 0, on unit set 0
// (the other sets idle); its conditional and the new factor it passes on into COND and NF.
// False if rank deficient.
template <class CFG, class SETS>
bool qr_eliminate_leaf(int s) {
    typedef typename CFG::T T;
    FGC_EVENT("marginal_solve");
    SETS::stack(0, s, T(0));
    bool bad = false;
    FGC_PHASE("qr");
    SETS::leaf(s, &bad);  // unit set 0 alone (its copy: the other sets are not instantiated)
    FGC_JOIN();
    SETS::commit(0, s);
    return !bad;
}
#endif  // FGC_ELIMINATE_QR


#endif  // FGC_ELIMINATE_H
