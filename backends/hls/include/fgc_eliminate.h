// fgc_eliminate.h: the elimination driver of the dataflow kernel, around its linear-solver units
// (fgc_cpe.h's cascade, fgc_qr.h's QR unit): what goes into a step's unit and where its result
// goes. Per step s of the schedule:
//
//   Cholesky: bool cholesky_eliminate<CFG>(s, mu)  [H | g] assembled from the step's factors'
//             Grams and its children's update matrices into HF (which the cascade left
//             zero), factored by the cascade, whose drain writes the conditional into COND
//             and the update matrix into NF; false if singular.
//             bool cholesky_eliminate_all<CFG>(mu)  every step in schedule order.
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
//
// Included by the kernel inside its namespace (fgc::, or fgc::les for the mixed design), after
// its schedule tables and memories, which these functions name: STEP_W, STEP_F, STEP_ROWS,
// STEP_FACTOR_BEGIN, STEP_FACTORS, STEP_CHILD_BEGIN, STEP_CHILDREN, STEP_SEPMAP_BEGIN,
// STEP_SEPMAP, STEP_NF_OFF, STEP_NF_ROWS, STEP_COND_OFF, FACTOR_COLMAP_BEGIN, FACTOR_COLMAP,
// FACTOR_A_OFF, FACTOR_GRAM_OFF, LEVEL_STEPS, LEVEL_BEGIN, N_LEVELS, N_STEPS (tables); AB, GRAM,
// COND, NF, PORTS, fgc_sqrt and, for Cholesky, HF (memories). CFG is the kernel's LesConfig: T
// (the linear solver's scalar), the unit's sizes, LM, the tables' largest trip counts (MAX_STEP_FACTORS,
// MAX_CHILDREN, TRIP_*) and the (II, depth) of the plan's fill, move and scatter loops (QR:
// UNIT_SETS, MAX_LEVEL_WIDTH and the (II, depth) ROOT_II, ROOT_DEPTH of sqrt(mu) too); cycles
// to FGC_CYCLES as the plan prices them. Define FGC_ELIMINATE_CHOLESKY or FGC_ELIMINATE_QR
// first: the other solver's memories do not exist.
#ifndef FGC_ELIMINATE_H
#define FGC_ELIMINATE_H

#ifdef FGC_ELIMINATE_CHOLESKY
// Step s: assemble, factor, store. False if not positive definite or a pivot is too small.
template <class CFG>
bool cholesky_eliminate(int s, typename CFG::T mu) {
    FGC_PHASE("assemble");
    const int w = STEP_W[s], f = STEP_F[s];
    // HF is all zero here: the cascade clears every word it reads (fgc_cpe.h's cpe_feed), and
    // these loops write only words it reads (the upper triangle and the gradient of rows < w)
    // each further factor's packed Gram (H's lower triangle, then its gradient row) and each
    // child's update matrix (upper triangle and reduced g), one entry a cycle += into HF: within one
    // loop every entry goes to its own address (the column maps are one-to-one), so no
    // iteration waits for another's add (II 1); a later loop's entry may meet the same address
    // the step's first factor: HF is all zero, so its packed Gram is stored, not added: two
    // entries a cycle (GRAM's two ports read, HF's two ports written; within one factor every
    // entry has its own address), its column map first copied into registers (two reads of it
    // an entry each)
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
        map[d] = w;  // row d of the packed Gram: the gradient, column w of HF
        FGC_CYCLES("assemble", 0, "map", d, CFG::MOVE_II, CFG::MOVE_DEPTH);
        for (int k = 0, p = 0, q = 0; k < n; k += 2) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::TRIP_PACKED/2
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=HF inter false
            for (int h = 0; h < 2; ++h) {
                if (k + h < n) {
                    const int a = map[p], b = map[q];
                    const int lo = b < a ? b : a, hi = b < a ? a : b;
                    HF[lo][hi] = GRAM[g0 + k + h];
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
    for (int e = STEP_FACTOR_BEGIN[s] + 1; e < STEP_FACTOR_BEGIN[s + 1]; ++e) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_STEP_FACTORS
        const int fac = STEP_FACTORS[e];

        const int cb = FACTOR_COLMAP_BEGIN[fac];
        const int d = FACTOR_COLMAP_BEGIN[fac + 1] - cb;
        const int g0 = FACTOR_GRAM_OFF[fac];
        const int n = d * (d + 1) / 2 + d;  // entry (p, q), q <= p, at p (p + 1) / 2 + q; row d: g
        for (int k = 0, p = 0, q = 0; k < n; ++k) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::TRIP_PACKED
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=HF inter false
            const int a = p < d ? FACTOR_COLMAP[cb + p] : w, b = FACTOR_COLMAP[cb + q];
            const int lo = b < a ? b : a, hi = b < a ? a : b;
            HF[lo][hi] += GRAM[g0 + k];
            if (q == p) {
                q = 0;
                ++p;
            } else {
                ++q;
            }
        }
        FGC_CYCLES("assemble", 0, "gram", n, CFG::SCATTER_II, CFG::SCATTER_DEPTH);
    }
    for (int e = STEP_CHILD_BEGIN[s]; e < STEP_CHILD_BEGIN[s + 1]; ++e) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_CHILDREN
        const int c = STEP_CHILDREN[e];
        const int sc = STEP_W[c] - STEP_F[c];
        const int mb = STEP_SEPMAP_BEGIN[c];
        const int u0 = STEP_NF_OFF[c];
        const int n = sc * (sc + 1) / 2 + sc;  // row a: columns a ... sc - 1, then its g (column sc)
        for (int k = 0, a = 0, b = 0; k < n; ++k) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::TRIP_PACKED
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=HF inter false
            const int ma = STEP_SEPMAP[mb + a], mbb = b < sc ? STEP_SEPMAP[mb + b] : w;
            const int lo = ma < mbb ? ma : mbb, hi = ma < mbb ? mbb : ma;
            HF[lo][hi] += NF[u0 + a * (sc + 1) + b];
            if (b == sc) {
                ++a;
                b = a;
            } else {
                ++b;
            }
        }
        FGC_CYCLES("assemble", 0, "child", n, CFG::SCATTER_II, CFG::SCATTER_DEPTH);
    }
    bool not_pd = false, singular = false;
    FGC_PHASE("cholesky");
    // the conditional straight into COND and the update matrix into NF (the cascade's drain)
    fgc_units::cpe_step<CFG>(HF, f, w - f, mu, COND, STEP_COND_OFF[s], NF, STEP_NF_OFF[s],
                             &not_pd, &singular);
    return !singular;
}

// Eliminate every step in schedule order, level by level.
template <class CFG>
bool cholesky_eliminate_all(typename CFG::T mu) {
    FGC_EVENT("solve");
    bool ok = true;
    for (int i = 0; i < N_STEPS; ++i) {
        if (ok) ok = cholesky_eliminate<CFG>(LEVEL_STEPS[i], mu);
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
    bool has[CFG::UNIT_SETS], bad[CFG::UNIT_SETS];
    int st[CFG::UNIT_SETS];
#pragma HLS ARRAY_PARTITION variable=has complete
#pragma HLS ARRAY_PARTITION variable=bad complete
#pragma HLS ARRAY_PARTITION variable=st complete
    for (int u = 0; u < CFG::UNIT_SETS; ++u) {
#pragma HLS UNROLL
        has[u] = u == 0;
        st[u] = u == 0 ? s : 0;
        bad[u] = false;
    }
    FGC_PHASE("qr");
    SETS::level(has, st, bad);
    FGC_JOIN();
    SETS::commit(0, s);
    return !bad[0];
}
#endif  // FGC_ELIMINATE_QR


#endif  // FGC_ELIMINATE_H
