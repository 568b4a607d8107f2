// fgc_stream.h: the streaming designs' on-chip state (fgc_backends/hls/window.py), the
// fixed-lag window and the incremental design's kept Bayes net, around the kernel's LM:
//
//   FGC_STREAM_WINDOW    update_start<CFG>(...) every slot down one (X and DATA_BUF keep the window)
//                                               and the call's keyframe into slot m: the moves on
//                                               X beside those on DATA_BUF (one DATAFLOW region)
//   FGC_STREAM_MARGINAL  marginalize<CFG>(ok)   slot 0's elimination at the optimum -> tau, the
//                        tau_and_keep<CFG>(c)   factor written into slot 1's prior (write_tau<CFG>:
//                                               a batch step's), beside the kept conditional
//   FGC_STREAM_KEPT      reexpress<CFG>(c, x0), keep_points<CFG>(c), kept_walk<CFG>(first, x0): the kept
//                        conditionals, re-expressed, stored and walked back from the window
//                        (kept_matvec<CFG>, kept_conditional<CFG> inside). window_and_kept<CFG>:
//                        the window's process (window_task: LM's solve, the marginal on LM's
//                        units) beside the kept net's (kept_task: the re-expression the update
//                        before left pending, KEPT_PENDING), one DATAFLOW region: the kept
//                        net's work is off the update's path. The walk, which gives the kept
//                        keyframes' estimates, runs in the same kept process when the host
//                        asks for them (op 3) or a batch step starts from them, and only if an
//                        update left them stale
//   FGC_STREAM_BATCH     batch_step<CFG>(j, first, errors, info): a batch step through the batch
//                        kernel (its own file), the kept net rebuilt from its conditionals
//   FGC_STREAM_SWEEP     (instead, the one-step policy) a batch step as a sweep through the window:
//                        update_start keeps each keyframe's storage and words as they came as it
//                        moves them into the window (sweep_store<CFG> before a sweep's passes),
//                        sweep_gather<CFG> the estimates; stream_call then runs one pass per
//                        keyframe 0 … j, each keyframe in again and, once the window is full,
//                        its slot 0 leaving at the estimates (the marginal's step at mu = 0, tau,
//                        keep), the last pass keyframe j's update: one set of units
//   FGC_STREAM_WINDOW    stream_call<CFG>(op, x_in, data, x_out, [x_kept,] errors, info): the
//                        streaming top's whole body (reset, keyframe in, solve, marginal, kept
//                        net, window out); the generated top holds only its interface pragmas
//   FGC_STREAM_BATCH_KERNEL  batch_kernel_reset / batch_kernel_in / batch_kernel_solve<CFG>: the
//                        batch kernel's entries (its file's <name>_batch_* call them)
//
// The memories of the stream section are declared here (the window's call counters; kept: the
// kept conditionals KEPT_R / KEPT_S / KEPT_D, their points KEPT_LIN / KEPT_NEXT, X_KEPT,
// KEPT_PENDING / KEPT_PENDING_X; batch: BATCH_X / BATCH_COND / BATCH_TAU; sweep: SWEEP_X /
// SWEEP_WORDS), sized by the kernel's constants (STREAM_*, KEPT_MAX, BATCH_SLOTS, SWEEP_SLOTS,
// SWEEP_MAX_NEW). The kernel keeps the tables (data), the Log kernels (its variable kinds) and the wiring: StreamConfig's constants
// and hooks (lm_solve, linearize, leaf_step, batch_reset / batch_in / batch_solve; the batch
// kernel's eliminate).
//
// One RTL instance per kernel function: every call site of a function not inlined is its own
// copy, so the functions that call a kernel function again after LM hold LM's body
// (lm_solve: INLINE, fgc_lm::optimize_inline) and an ALLOCATION function ... limit=1 for
// linearize_all, eliminate_all, back_substitute_at (window_task, batch_kernel_solve): the
// marginal's QR step is eliminate_all's (fgc_eliminate.h's qr_eliminate_all with a leaf), on
// LM's unit set 0; kept_task holds reexpress and kept_walk (INLINE) and one keyframe_local,
// keyframe_retract and kept_matvec. What stays a copy (write_tau's two call sites, the kept
// net's datapaths) is priced by the plan
// (WindowUpdateModel.stream_units in fgc_backends/hls/plan/stream.py).
//
// Define the parts the design has, then include this file inside the kernel's namespace after
// its tables and memories, which the functions name (the window's X, DATA_BUF, COND, NF, the
// schedule's STEP_* and the stream's SLOT_X, NEW_DEST, X_MOVES, N_X_MOVES, START_OPS,
// START_BANKS, START_ROW_BITS, N_START, STREAM_* constants; KEPT_*, X_KEPT, BATCH_* where kept / batch), with the problem's
// kernels: linearize_all and, kept, keyframe_local / keyframe_retract (each variable's Log and
// retraction). T and L are the kernel's scalars. CFG is the kernel's StreamConfig: the plan's
// (II, depth) of T's move / max / retract / div and L's acc / div / scatter loops, MV_II (the kept
// matrix-vector product's), MAX_NEW and TRIP_BATCH_X (trip counts), and the hooks
// lm_solve(errors, info, live) (the batch kernel's: (errors, info)), linearize(live) (INLINE: slot 0's step's factors at X; live: less
// those that hold nothing once keyframe 0 has left), leaf_step(live) (slot 0's step once more
// at mu = 0, the same rows), at_linearisation(info) (LM stopped where it last linearised: AB holds
// the rows at X), ONE_STEP and took_step(info) (the one-step policy, one Gauss-Newton step an
// update: the update took its step, so its solve's COND / NF, at mu = 0 at the call's starting
// X, are the store) and batch_solve(...) (the batch kernel's entry); kept:
// KF_FLAT_S (per tangent direction of a keyframe its storage word if its variable is a vector)
// and the kernel's T_ADD_LAT. Cycles to FGC_CYCLES as the plan prices them.
#ifndef FGC_STREAM_H
#define FGC_STREAM_H

// X's word i as the call reads it out after the window's region: the one-step policy's step
// taken is still in X_TRIAL where `held` (out_task)
#ifdef FGC_SPEC_MARGINAL
#define FGC_X_OUT(held, i) ((held) ? X_TRIAL[i] : X[i])
#else
#define FGC_X_OUT(held, i) X[i]
#endif

#if defined(FGC_STREAM_WINDOW) || defined(FGC_STREAM_BATCH_KERNEL)
// A keyframe's words into slot m: its storage (SLOT_X), then its factors' and its prior's words
// (NEW_DEST). The batch kernel's (batch_kernel_in) move the
// same words; BATCH says whose cycles they are (csim counting only). (The window's
// update moves them in update_start's two processes.)
template <class CFG, bool BATCH>
void keyframe_in(int m, const T x_in[STREAM_KF_X], const T data[N_DATA]) {
    for (int k = 0; k < STREAM_KF_X; ++k) {
#pragma HLS PIPELINE II=1
        X[SLOT_X[m * STREAM_KF_X + k]] = x_in[k];
    }
    FGC_CYCLES(BATCH ? "batch" : "top", 0, "keyframe_x_in", STREAM_KF_X, CFG::T_MOVE_II,
               CFG::T_MOVE_DEPTH);
    const int b = STREAM_NEW_BEGIN[m], n = STREAM_NEW_BEGIN[m + 1] - b;
    for (int k = 0; k < n; ++k) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_NEW
#pragma HLS PIPELINE II=1
        DATA_BUF[NEW_DEST[b + k]] = data[k];
    }
    FGC_CYCLES(BATCH ? "batch" : "top", 0, "keyframe_data_in", n, CFG::T_MOVE_II,
               CFG::T_MOVE_DEPTH);
}
#endif

#ifdef FGC_STREAM_WINDOW
int STREAM_COUNT = 0;  // keyframes since the reset call (saturates at STREAM_SLOTS)
#ifdef FGC_STREAM_KEPT
// the kept Bayes net (incremental mode): keyframe c < first (the window's oldest) is kept as its
// conditional R_c d_c + S_c d_c+1 = d_c, linearised at KEPT_LIN[c] with its parent at
// KEPT_NEXT[c], its estimate in X_KEPT[c], walked back from the window when asked for (op 3) or
// before a batch step, x_c = lin_c (+) R_c^-1 (d_c - S_c Log(next_c^-1 x_c+1)).
L KEPT_R[KEPT_MAX * STREAM_KF_T * STREAM_KF_T];  // R_c, row-major (upper triangular)
L KEPT_S[KEPT_MAX * STREAM_KF_T * STREAM_KF_T];  // S_c, row-major
L KEPT_D[KEPT_MAX * STREAM_KF_T];
T KEPT_LIN[KEPT_MAX * STREAM_KF_X];
T KEPT_NEXT[KEPT_MAX * STREAM_KF_X];
T X_KEPT[KEPT_MAX * STREAM_KF_X];
int STREAM_TOTAL = 0;  // keyframes since the reset call
// X_KEPT is not the walk of the kept net as it stands: an incremental update re-expressed the
// newest kept conditional (and kept another) without walking (op 3 or a batch step walks)
bool KEPT_STALE = false;
// the newest kept conditional's re-expression an update left for the next call's region (-1:
// none), at its parent's estimate as that update left it
int KEPT_PENDING = -1;
T KEPT_PENDING_X[STREAM_KF_X];
#endif
#ifdef FGC_STREAM_SWEEP
// batch steps as sweeps through the window (one set of units): keyframes 0 … SWEEP_SLOTS - 1 as
// they came (row c: its storage, then a sweep's linearisation point; its words as the window
// took them), the keyframes past the last batch step one shared row SWEEP_SLOTS
T SWEEP_X[(SWEEP_SLOTS + 1) * STREAM_KF_X];
T SWEEP_WORDS[(SWEEP_SLOTS + 1) * SWEEP_MAX_NEW];
#endif
#ifdef FGC_STREAM_BATCH
T BATCH_X[BATCH_SLOTS * STREAM_KF_X];  // keyframes 0 … j to and from the batch kernel
L BATCH_COND[BATCH_SLOTS * STREAM_KF_T * (2 * STREAM_KF_T + 1)];  // their conditionals
L BATCH_TAU[STREAM_KF_T * (STREAM_KF_T + 1)];  // the factor passed into the next window's oldest
#endif

// The call's `data` port (an m_axi bundle of its own): a word a beat, or (FGC_DATA_BEAT,
// HlsConfig.data_width 64) DATA_BEAT float words a beat, accel.h's DataBeat (the host packs the
// call's word k into beat k / DATA_BEAT, lane k % DATA_BEAT; a last beat's lanes past the words
// are padding no one reads)
#ifdef FGC_DATA_BEAT
typedef DataBeat DataIn;
const int DATA_IN_N = STREAM_IN_BEATS;
#if defined(FGC_STREAM_BATCH)
#error "a data port of DATA_BEAT words a beat is not built for the batch kernel's entries"
#endif
#else
typedef T DataIn;
const int DATA_IN_N = STREAM_IN_DATA;
#endif

// The update's start as one DATAFLOW region of two processes, each on its own memories: the
// moves on X (start_x_task: the leaving keyframe's estimate into X_KEPT where `leave`, the
// shift's variables where `shift`, the keyframe's storage into slot m, and slots 0 and 1 into
// lin01 where `points`) beside the moves on DATA_BUF (start_data_task: the shift's words and
// the keyframe's factors' and prior's words in one loop over DATA_BUF's START_BANKS banks, a
// read and a write of each an iteration, by the table START_OPS (window.py's _start_tables);
// while the window fills, the keyframe's words alone). Each loop of a process keeps its memory's
// ports to itself (X: the shift a read and a write an iteration, the keyframe a write, the
// points a read), the two processes share no memory and have no operator (moves and muxes):
// the region takes the longer of the two. `row` / `from_row` (batch steps as sweeps): the
// pass's keyframe from its row of the sweep's memory (a sweep pass, the row sweep_store or an
// earlier call left), else from the call's input, each word also kept in row `row` as it passes
// (one read, two writes to different memories an iteration: SWEEP_X / SWEEP_WORDS see at most
// one read and one write an iteration, the source a mux).
template <class CFG>
void start_x_task(bool leave, int kept, bool shift, int m, int row, bool from_row,
                  const T x_in[STREAM_KF_X], bool points, T lin01[2 * STREAM_KF_X]) {
    FGC_TASK();
    FGC_PHASE("setup");
#if defined(FGC_STREAM_KEPT) && (defined(FGC_STREAM_BATCH) || defined(FGC_STREAM_SWEEP))
    if (leave) {  // slot 0 (keyframe kept) leaves: its estimate kept (a batch step starts from it)
        for (int k = 0; k < STREAM_KF_X; ++k) {
#pragma HLS PIPELINE II=1
            X_KEPT[kept * STREAM_KF_X + k] = X[SLOT_X[k]];
        }
        FGC_CYCLES("top", 0, "leave", STREAM_KF_X, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
    }
#else
    (void)leave;
    (void)kept;
#endif
    if (shift) {
        FGC_PHASE("stream_shift");
        for (int k = 0; k < N_X_MOVES; ++k) {
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=X inter false
            X[X_MOVES[2 * k]] = X[X_MOVES[2 * k + 1]];
        }
        FGC_CYCLES("stream", 0, "shift_x", N_X_MOVES, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
    }
    FGC_PHASE("setup");
    for (int k = 0; k < STREAM_KF_X; ++k) {
#pragma HLS PIPELINE II=1
#ifdef FGC_STREAM_SWEEP
        const T v = from_row ? SWEEP_X[row * STREAM_KF_X + k] : x_in[k];
        X[SLOT_X[m * STREAM_KF_X + k]] = v;
        if (!from_row) SWEEP_X[row * STREAM_KF_X + k] = v;
#else
        X[SLOT_X[m * STREAM_KF_X + k]] = x_in[k];
#endif
    }
    FGC_CYCLES("top", 0, "keyframe_x_in", STREAM_KF_X, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
#ifndef FGC_STREAM_SWEEP
    (void)row;
    (void)from_row;
#endif
    if (points) {
        FGC_PHASE("marginal");
        for (int k = 0; k < 2 * STREAM_KF_X; ++k) {
#pragma HLS PIPELINE II=1
            const T v = X[SLOT_X[k]];
            lin01[k] = v;
#if defined(FGC_SPEC_MARGINAL) && defined(FGC_STREAM_KEPT)
            LIN01K[k] = v;  // (spec_keep_task's copy: LIN01 is spec_tau_task's)
#endif
        }
        FGC_CYCLES("marginal", 0, "lin_points", 2 * STREAM_KF_X, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
    }
}

// The call's keyframe words (not a sweep pass's, whose row is on chip) read from `data` in their
// order, a beat a cycle (a burst: a word, or FGC_DATA_BEAT's DATA_BEAT words), into the FIFO
// start_data_task takes them from: its loop takes them at the iterations its table says, so it
// reads no address of `data` itself.
template <class CFG>
void start_in_task(bool shift, int m, bool from_row, const DataIn data[DATA_IN_N],
                   hls::stream<DataIn>& words) {
    FGC_TASK();
    FGC_PHASE("setup");
    // (the window full: all but the newest prior's tail, STREAM_FULL_WORDS)
    const int n = from_row ? 0 : shift ? STREAM_FULL_WORDS : STREAM_NEW_BEGIN[m + 1] - STREAM_NEW_BEGIN[m];
#ifdef FGC_DATA_BEAT
    const int beats = (n + DATA_BEAT - 1) / DATA_BEAT;
    for (int k = 0; k < beats; ++k) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_NEW_BEATS
#pragma HLS PIPELINE II=1
        words.write(data[k]);
    }
    FGC_CYCLES("top", 0, "keyframe_data_read", beats, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
#else
    for (int k = 0; k < n; ++k) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_NEW
#pragma HLS PIPELINE II=1
        words.write(data[k]);
    }
    FGC_CYCLES("top", 0, "keyframe_data_read", n, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
#endif
}

template <class CFG>
void start_data_task(bool shift, int m, int row, bool from_row, hls::stream<DataIn>& words) {
    FGC_TASK();
    // DATA_BUF in START_BANKS cyclic banks: the start loop below takes a read and a write of
    // every bank an iteration (every other access to DATA_BUF, at an address the scheduler
    // cannot place in one bank, takes a port of every bank, as one bank's did)
#pragma HLS ARRAY_PARTITION variable=DATA_BUF cyclic factor=START_BANKS
#pragma HLS ARRAY_PARTITION variable=START_OPS cyclic factor=START_BANKS
#if defined(FGC_DATA_BEAT) && defined(FGC_STREAM_SWEEP)
    // (the keyframe's words kept in SWEEP_WORDS as they come: up to DATA_BEAT writes an
    // iteration, a sweep pass's two reads: both ports of a true dual-port RAM)
#pragma HLS BIND_STORAGE variable=SWEEP_WORDS type=ram_t2p impl=bram
#endif
    const int b = STREAM_NEW_BEGIN[m], n = STREAM_NEW_BEGIN[m + 1] - b;
#ifndef FGC_STREAM_SWEEP
    (void)row;
    (void)from_row;
#endif
    const int mask = (1 << START_ROW_BITS) - 1;
#ifdef FGC_STREAM_SWEEP
#pragma HLS ARRAY_PARTITION variable=START_OPS_SWEEP cyclic factor=START_BANKS
    if (shift && from_row) {  // a sweep pass: its keyframe from its row of SWEEP_WORDS, whose two
        FGC_PHASE("stream_shift");  // read ports give two words an iteration (START_OPS_SWEEP)
        int k = 0;
        for (int i = 0; i < N_START_SWEEP; ++i) {
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=DATA_BUF inter false
            T word[START_BANKS];
#pragma HLS ARRAY_PARTITION variable=word complete
            int in = 0;  // the keyframe's words this iteration: 0, 1 or 2
            for (int c = 0; c < START_BANKS; ++c) {
#pragma HLS UNROLL
                const int op = START_OPS_SWEEP[i * START_BANKS + c];
                word[c] = DATA_BUF[START_BANKS * (op & mask) + c];
                const int src = op >> (2 * START_ROW_BITS);
                if (src == START_BANKS + 1) in = 2;
                else if (src == START_BANKS && in == 0) in = 1;
            }
            const T v0 = in > 0 ? SWEEP_WORDS[row * SWEEP_MAX_NEW + k] : T(0);
            const T v1 = in > 1 ? SWEEP_WORDS[row * SWEEP_MAX_NEW + k + 1] : T(0);
            k += in;
            for (int c = 0; c < START_BANKS; ++c) {
#pragma HLS UNROLL
                const int op = START_OPS_SWEEP[i * START_BANKS + c];
                const int to = ((op >> START_ROW_BITS) & mask) - 1, src = op >> (2 * START_ROW_BITS);
                if (to >= 0) {
                    DATA_BUF[START_BANKS * to + c] = src < START_BANKS ? word[src]
                                                     : src == START_BANKS ? v0
                                                     : src == START_BANKS + 1 ? v1 : T(0);
                }
            }
        }
        FGC_CYCLES("stream", 0, "start_data_sweep", N_START_SWEEP, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
        return;
    }
#endif
#ifdef FGC_DATA_BEAT
    if (shift) {  // (the window full: m is the newest slot) the shift and the keyframe's words,
        FGC_PHASE("stream_shift");  // up to DATA_BEAT of them an iteration (a beat a fetch)
#ifdef FGC_STREAM_SWEEP
        int k = 0;  // the keyframe's next word
#endif
        // a fetched beat's second word not yet written (`have`): an iteration that takes more
        // words than it holds fetches the next beat behind it (at most two words an iteration:
        // at most one left over, a register and a mux)
        T carry = T(0);
        bool have = false;
        for (int i = 0; i < N_START; ++i) {
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=DATA_BUF inter false
            T word[START_BANKS];  // what each bank reads this iteration (its reads before its writes)
#pragma HLS ARRAY_PARTITION variable=word complete
            int in = 0;  // the keyframe's words this iteration (sources START_BANKS + q, q < in)
            for (int c = 0; c < START_BANKS; ++c) {
#pragma HLS UNROLL
                const int op = START_OPS[i * START_BANKS + c];
                word[c] = DATA_BUF[START_BANKS * (op & mask) + c];
                const int src = op >> (2 * START_ROW_BITS);
                if (src >= START_BANKS && src < START_BANKS + DATA_BEAT) ++in;
            }
            const bool fetch = in > (have ? 1 : 0);
            DataBeat beat = {};
            if (fetch) beat = words.read();
            const T b0 = beat.lane_word[0], b1 = beat.lane_word[1];
            // the iteration's words in the call's order, the carried one first
            const T v0 = have ? carry : b0, v1 = have ? b0 : b1;
            if (fetch) {
                carry = b1;
                have = have ? in == 2 : in == 1;
            } else if (in == 1) {
                have = false;
            }
#ifdef FGC_STREAM_SWEEP
            if (in > 0) SWEEP_WORDS[row * SWEEP_MAX_NEW + k] = v0;  // (kept as it came)
            if (in > 1) SWEEP_WORDS[row * SWEEP_MAX_NEW + k + 1] = v1;
            k += in;
#endif
            for (int c = 0; c < START_BANKS; ++c) {
#pragma HLS UNROLL
                const int op = START_OPS[i * START_BANKS + c];
                const int to = ((op >> START_ROW_BITS) & mask) - 1, src = op >> (2 * START_ROW_BITS);
                if (to >= 0) {
                    DATA_BUF[START_BANKS * to + c] = src < START_BANKS ? word[src]
                                                     : src == START_BANKS ? v0
                                                     : src == START_BANKS + 1 ? v1 : T(0);
                }
            }
        }
        FGC_CYCLES("stream", 0, "start_data", N_START, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
        return;
    }
#else
    if (shift) {  // (the window full: m is the newest slot) the shift and the keyframe's words
        FGC_PHASE("stream_shift");
#ifdef FGC_STREAM_SWEEP
        int k = 0;  // the keyframe's next word (the FIFO's, at most one an iteration)
#endif
        for (int i = 0; i < N_START; ++i) {
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=DATA_BUF inter false
            T word[START_BANKS];  // what each bank reads this iteration (its reads before its writes)
#pragma HLS ARRAY_PARTITION variable=word complete
            bool in = false;
            for (int c = 0; c < START_BANKS; ++c) {
#pragma HLS UNROLL
                const int op = START_OPS[i * START_BANKS + c];
                word[c] = DATA_BUF[START_BANKS * (op & mask) + c];
                in = in || (op >> (2 * START_ROW_BITS)) == START_BANKS;
            }
            T v = T(0);
            if (in) {
                v = words.read();
#ifdef FGC_STREAM_SWEEP
                SWEEP_WORDS[row * SWEEP_MAX_NEW + k] = v;  // (not a sweep pass: kept as it came)
                ++k;
#endif
            }
            for (int c = 0; c < START_BANKS; ++c) {
#pragma HLS UNROLL
                const int op = START_OPS[i * START_BANKS + c];
                const int to = ((op >> START_ROW_BITS) & mask) - 1, src = op >> (2 * START_ROW_BITS);
                if (to >= 0) DATA_BUF[START_BANKS * to + c] = src < START_BANKS ? word[src] : src == START_BANKS ? v : T(0);
            }
        }
        FGC_CYCLES("stream", 0, "start_data", N_START, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
        return;
    }
#endif
    FGC_PHASE("setup");
#ifdef FGC_DATA_BEAT
    DataBeat beat = {};  // (the window filling: a word an iteration, a beat every DATA_BEAT words)
    for (int k = 0; k < n; ++k) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_NEW
#pragma HLS PIPELINE II=1
        if (!from_row && k % DATA_BEAT == 0) beat = words.read();
#ifdef FGC_STREAM_SWEEP
        const T v = from_row ? SWEEP_WORDS[row * SWEEP_MAX_NEW + k] : beat.lane_word[k % DATA_BEAT];
        DATA_BUF[NEW_DEST[b + k]] = v;
        if (!from_row) SWEEP_WORDS[row * SWEEP_MAX_NEW + k] = v;
#else
        DATA_BUF[NEW_DEST[b + k]] = beat.lane_word[k % DATA_BEAT];
#endif
    }
#else
    for (int k = 0; k < n; ++k) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_NEW
#pragma HLS PIPELINE II=1
#ifdef FGC_STREAM_SWEEP
        const T v = from_row ? SWEEP_WORDS[row * SWEEP_MAX_NEW + k] : words.read();
        DATA_BUF[NEW_DEST[b + k]] = v;
        if (!from_row) SWEEP_WORDS[row * SWEEP_MAX_NEW + k] = v;
#else
        DATA_BUF[NEW_DEST[b + k]] = words.read();
#endif
    }
#endif
    FGC_CYCLES("top", 0, "keyframe_data_in", n, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
}

// The region (the caller joins it: FGC_TASKS_JOIN): every slot down one where `shift` (slot s
// takes slot s + 1's variables and the words of the factor one keyframe on, zero noise words
// where there is none, slot 0's prior slot 1's, tau; the pairs ordered so each word is read
// before it is overwritten), then the call's (or the sweep pass's) keyframe into slot m: its
// storage, then its factors' and its prior's words.
template <class CFG>
void update_start(bool leave, int kept, bool shift, int m, int row, bool from_row,
                  const T x_in[STREAM_KF_X], const DataIn data[DATA_IN_N], bool points,
                  T lin01[2 * STREAM_KF_X]) {
#pragma HLS DATAFLOW
    hls::stream<DataIn> words("start_words");  // the call's keyframe words (beats), in their order
#pragma HLS STREAM variable=words depth=2
    start_x_task<CFG>(leave, kept, shift, m, row, from_row, x_in, points, lin01);
    start_in_task<CFG>(shift, m, from_row, data, words);
    start_data_task<CFG>(shift, m, row, from_row, words);
}

#ifdef FGC_STREAM_SWEEP
// The call's keyframe (total, entering slot m) kept as it came: its storage and its words, row
// total (SWEEP_SLOTS for every keyframe past the last batch step), a word a cycle.
template <class CFG>
void sweep_store(int total, int m, bool full, const T x_in[STREAM_KF_X],
                 const DataIn data[DATA_IN_N]) {
    FGC_PHASE("setup");
    const int row = total < SWEEP_SLOTS ? total : SWEEP_SLOTS;
    for (int k = 0; k < STREAM_KF_X; ++k) {
#pragma HLS PIPELINE II=1
        SWEEP_X[row * STREAM_KF_X + k] = x_in[k];
    }
    FGC_CYCLES("top", 0, "sweep_x_store", STREAM_KF_X, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
    // (the window full: the call's words but the newest prior's tail, as the start takes them)
    const int n = full ? STREAM_FULL_WORDS : STREAM_NEW_BEGIN[m + 1] - STREAM_NEW_BEGIN[m];
#ifdef FGC_DATA_BEAT
    // a beat a cycle, its two words into SWEEP_WORDS (two writes: its two ports, as
    // start_data_task binds it)
#pragma HLS BIND_STORAGE variable=SWEEP_WORDS type=ram_t2p impl=bram
    const int beats = (n + DATA_BEAT - 1) / DATA_BEAT;
    for (int q = 0; q < beats; ++q) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::MAX_NEW_BEATS
#pragma HLS PIPELINE II=1
        const DataBeat beat = data[q];
        const T b0 = beat.lane_word[0], b1 = beat.lane_word[1];
        SWEEP_WORDS[row * SWEEP_MAX_NEW + 2 * q] = b0;
        if (2 * q + 1 < n) SWEEP_WORDS[row * SWEEP_MAX_NEW + 2 * q + 1] = b1;
    }
    FGC_CYCLES("top", 0, "sweep_words_store", beats, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
#else
    for (int k = 0; k < n; ++k) {
#pragma HLS LOOP_TRIPCOUNT max=SWEEP_MAX_NEW
#pragma HLS PIPELINE II=1
        SWEEP_WORDS[row * SWEEP_MAX_NEW + k] = data[k];
    }
    FGC_CYCLES("top", 0, "sweep_words_store", n, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
#endif
}

// A batch step's linearisation points: keyframes 0 … total - 1's estimates into their rows (the
// kept ones' from X_KEPT, c < first; the window's from X before its shift, slot c - base), a
// word a cycle. Row total holds the call's keyframe as it came.
template <class CFG>
void sweep_gather(int total, int base, int first) {
    FGC_PHASE("sweep");
    for (int e = 0; e < total * STREAM_KF_X; ++e) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::TRIP_SWEEP_X
#pragma HLS PIPELINE II=1
        const int c = e / STREAM_KF_X, k = e % STREAM_KF_X;
        SWEEP_X[e] = c < first ? X_KEPT[e] : X[SLOT_X[(c - base) * STREAM_KF_X + k]];
    }
    FGC_CYCLES("sweep", 0, "gather", total * STREAM_KF_X, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
}
#endif  // FGC_STREAM_SWEEP
#endif  // FGC_STREAM_WINDOW

#ifdef FGC_STREAM_MARGINAL
// tau from the rows [A | b] (KF_T x (KF_T + 1), upper triangular) a step passes to slot 1, in two
// parts: tau_sign signs it to a positive diagonal into `a` and tells whether it is singular
// (false); tau_tail then takes its mean A^-1 b by back-substitution (tau_mean) and writes it with
// its linearisation point (slot 1's estimate, or `lin` where `given`: the one-step policy's,
// where the update linearised it) into slot 1's prior. write_tau: the two one after the other (a
// batch step's); the window's marginal runs tau_mean beside tau_words (the words but the mean's)
// and keep's conditional, then tau_mean_out (tau_and_keep).
template <class CFG>
bool tau_sign(const L rows[STREAM_KF_T * (STREAM_KF_T + 1)], L a[STREAM_KF_T][STREAM_KF_T + 1]) {
    FGC_PHASE("marginal");
    L largest = L(1), smallest = L(0);
    for (int i = 0; i < STREAM_KF_T; ++i) {
        const L sign = rows[i * (STREAM_KF_T + 1) + i] < L(0) ? L(-1) : L(1);
        for (int c = 0; c <= STREAM_KF_T; ++c) {
#pragma HLS PIPELINE II=1
            const L v = sign * rows[i * (STREAM_KF_T + 1) + c];
            a[i][c] = v;
            const L mag = v < L(0) ? L(-v) : v;
            if (c < STREAM_KF_T && mag > largest) largest = mag;
            if (c == i && (i == 0 || v < smallest)) smallest = v;
        }
    }
    FGC_CYCLES("marginal", 0, "sign", STREAM_KF_T * (STREAM_KF_T + 1), CFG::T_MAX_II, CFG::T_MAX_DEPTH);
    return smallest > L(STREAM_SINGULAR) * largest;
}

// tau's mean A^-1 b (a: signed) by columns, last first: x_r = y_r / a_rr (y_r final: its last
// update was the column before's), then y_i -= a_ir x_r for the rows above, one a cycle (II 1:
// each y_i updated once a column) - so the next unknown waits for one divide and its own row's
// update, where the dot product per row ran its whole row at II La first. The same products and
// divides as a row's dot product (the subtractions in the other order); y_i starts as b_i (a mux
// on the first column: no copy)
template <class CFG>
void tau_mean(const L a[STREAM_KF_T][STREAM_KF_T + 1], L mean[STREAM_KF_T]) {
    FGC_PHASE("marginal");
    L y[STREAM_KF_T];
    for (int r = STREAM_KF_T - 1; r >= 0; --r) {
        const bool last = r == STREAM_KF_T - 1;
        const L xr = (last ? a[r][STREAM_KF_T] : y[r]) / a[r][r];
        mean[r] = xr;
        FGC_CYCLES("marginal", 0, "divide", 1, CFG::L_DIV_II, CFG::L_DIV_DEPTH);
        for (int i = r - 1; i >= 0; --i) {
#pragma HLS LOOP_TRIPCOUNT max=STREAM_KF_T
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=y inter false
            y[i] = (last ? a[i][STREAM_KF_T] : y[i]) - a[i][r] * xr;
        }
        FGC_CYCLES("marginal", 0, "column", r, 1, CFG::L_ACC_DEPTH);
    }
}

template <class CFG>
void tau_tail(const L a[STREAM_KF_T][STREAM_KF_T + 1], const T lin[STREAM_KF_X], bool given) {
    L mean[STREAM_KF_T];
    tau_mean<CFG>(a, mean);
    for (int k = 0; k < STREAM_KF_X; ++k) {
#pragma HLS PIPELINE II=1
        DATA_BUF[STREAM_PRIOR1 + k] = given ? lin[k] : X[SLOT_X[STREAM_KF_X + k]];
    }
    for (int i = 0; i < STREAM_KF_T; ++i) {
#pragma HLS PIPELINE II=1
        DATA_BUF[STREAM_PRIOR1 + STREAM_KF_X + i] = T(mean[i]);
    }
    for (int i = 0, w = STREAM_PRIOR1 + STREAM_KF_X + STREAM_KF_T; i < STREAM_KF_T; ++i) {
        for (int c = i; c < STREAM_KF_T; ++c) {
#pragma HLS LOOP_TRIPCOUNT max=STREAM_KF_T
#pragma HLS PIPELINE II=1
            DATA_BUF[w++] = T(a[i][c]);
        }
    }
    DATA_BUF[STREAM_PRIOR1 + STREAM_KF_X + STREAM_KF_T + STREAM_KF_T * (STREAM_KF_T + 1) / 2] = T(0);  // no robust loss
    DATA_BUF[STREAM_PRIOR1 + STREAM_KF_X + STREAM_KF_T + STREAM_KF_T * (STREAM_KF_T + 1) / 2 + 1] = T(0);
    FGC_CYCLES("marginal", 0, "tau_out", STREAM_KF_X + STREAM_KF_T + STREAM_KF_T * (STREAM_KF_T + 1) / 2 + 2, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
}

#ifdef FGC_STREAM_WINDOW
// tau's words but its mean into slot 1's prior (the window's marginal: beside the mean, which
// the words other than the mean's do not wait for): its linearisation point (`lin` where
// `given`, else slot 1's estimate), R from the rows where the step left them (`rows`, NF),
// each row signed by its diagonal (the row's first word of R: a register and a negation, no
// operator; the same words as tau_sign's a, a product by +-1 being exact), no robust loss.
// Then tau_mean_out, after the mean: the mean's words.
template <class CFG>
void tau_words(const L rows[STREAM_KF_T * (STREAM_KF_T + 1)], const T lin[STREAM_KF_X], bool given) {
    FGC_PHASE("marginal");
    for (int k = 0; k < STREAM_KF_X; ++k) {
#pragma HLS PIPELINE II=1
        DATA_BUF[STREAM_PRIOR1 + k] = given ? lin[k] : X[SLOT_X[STREAM_KF_X + k]];
    }
    bool negative = false;
    for (int i = 0, w = STREAM_PRIOR1 + STREAM_KF_X + STREAM_KF_T; i < STREAM_KF_T; ++i) {
        for (int c = i; c < STREAM_KF_T; ++c) {
#pragma HLS LOOP_TRIPCOUNT max=STREAM_KF_T
#pragma HLS PIPELINE II=1
            const L v = rows[i * (STREAM_KF_T + 1) + c];
            if (c == i) negative = v < L(0);
            DATA_BUF[w++] = T(negative ? L(-v) : v);
        }
    }
    DATA_BUF[STREAM_PRIOR1 + STREAM_KF_X + STREAM_KF_T + STREAM_KF_T * (STREAM_KF_T + 1) / 2] = T(0);  // no robust loss
    DATA_BUF[STREAM_PRIOR1 + STREAM_KF_X + STREAM_KF_T + STREAM_KF_T * (STREAM_KF_T + 1) / 2 + 1] = T(0);
    FGC_CYCLES("marginal", 0, "tau_words", STREAM_KF_X + STREAM_KF_T * (STREAM_KF_T + 1) / 2 + 2, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
}

template <class CFG>
void tau_mean_out(const L mean[STREAM_KF_T]) {
    FGC_PHASE("marginal");
    for (int i = 0; i < STREAM_KF_T; ++i) {
#pragma HLS PIPELINE II=1
        DATA_BUF[STREAM_PRIOR1 + STREAM_KF_X + i] = T(mean[i]);
    }
    FGC_CYCLES("marginal", 0, "tau_mean_out", STREAM_KF_T, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
}
#endif

// tau signed, checked, its mean and words one after the other (a batch step's). False, nothing
// written, if it is singular.
template <class CFG>
bool write_tau(const L rows[STREAM_KF_T * (STREAM_KF_T + 1)], const T lin[STREAM_KF_X],
               bool given) {
    L a[STREAM_KF_T][STREAM_KF_T + 1];
    if (!tau_sign<CFG>(rows, a)) return false;
    tau_tail<CFG>(a, lin, given);
    return true;
}

// Keyframe first leaves: tau, the factor slot 0's elimination at the window's optimum passes to
// slot 1 ([A | b], upper triangular from the QR unit, left in NF), made ready for tau_and_keep,
// which runs after the window's region: signed to a positive diagonal, its mean A^-1 b by
// back-substitution, written with slot 1's estimate as its linearisation point into slot 1's
// prior (which the next call's shift moves to slot 0). False if the window is not finite at its
// optimum (`finite` false) or slot 0 is rank deficient (tau_and_keep: or tau is singular). The window's rows (AB) are its linearisation at X, the optimum: stream_call
// computed them again before the region if LM moved after its last linearisation. `reuse` (the
// one-step policy, the step taken): slot 0's step of the update's own solve is the store (its
// NF at mu = 0, at the call's start lin01: slots 0 and 1), no step is run again. `live`
// (keyframe 0 has left the window): slot 0's factors that hold nothing from then on are not
// stacked (CFG::leaf_step's: qr_eliminate_all's leaf step takes LEAF_LIVE_ROWS rows).
template <class CFG>
bool marginalize(bool finite, bool reuse, bool live, const T lin01[2 * STREAM_KF_X]) {
    // INLINE (CFG::leaf_step too): its QR step is LM's eliminate_all, one instance under the
    // caller's ALLOCATION - the marginal has no unit set of its own
#pragma HLS INLINE
    FGC_EVENT("marginal");
    (void)lin01;
    if (!finite) return false;
    return reuse || CFG::leaf_step(live);
}
#endif  // FGC_STREAM_MARGINAL

#ifdef FGC_STREAM_KEPT
// One datapath pass over a keyframe's variables (its Log or its retraction, each variable's
// kernel in turn), priced as one pass through a retraction-sized datapath.
#define FGC_KEPT_PASS(name) FGC_CYCLES("kept", 0, name, 1, CFG::T_RETRACT_II, CFG::T_RETRACT_DEPTH)

// acc[i] = sum_k m[i][k] v[k] (m row-major, KF_T x KF_T) for every row at once: k outer, the rows
// inner, one product a cycle at II STREAM_MV_II (a row's sum comes back to the adder every KF_T
// iterations, so II = ceil(multiply-add depth / KF_T)); each row summed in k order, as a dot
// product adds it.
template <class CFG>
void kept_matvec(const L m[STREAM_KF_T * STREAM_KF_T], const L v[STREAM_KF_T], L acc[STREAM_KF_T]) {
    for (int e = 0; e < STREAM_KF_T * STREAM_KF_T; ++e) {
#pragma HLS PIPELINE II=CFG::MV_II
#pragma HLS DEPENDENCE variable=acc inter false
        const int k = e / STREAM_KF_T, i = e % STREAM_KF_T;
        const L prev = k == 0 ? L(0) : acc[i];
        acc[i] = prev + m[i * STREAM_KF_T + k] * v[k];
    }
    FGC_CYCLES("kept", 0, "matvec", STREAM_KF_T * STREAM_KF_T, CFG::MV_II, CFG::L_ACC_DEPTH);
}

// The newest kept conditional c, re-expressed at its parent's new estimate x (the window's slot 0,
// copied out of X before the call):
// d_c -= S_c Log(next^-1 x), S_c = S_c J with J the derivative of Log(next^-1 (x (+) delta)) by
// central differences of step STREAM_H (the simulator's Chain.local_jacobian); next_c = x. Four
// datapath passes per direction of a variable that is not a vector (KF_FLAT_S), none for a
// vector's.
template <class CFG>
void reexpress(int c, const T x[STREAM_KF_X]) {
    // INLINE into kept_task: its Log / retraction passes share kept_walk's datapaths there
#pragma HLS INLINE
    FGC_PHASE("kept");
    const T h = T(STREAM_H);
    T base[STREAM_KF_T], plus[STREAM_KF_T], minus[STREAM_KF_T], step[STREAM_KF_T];
    T moved[STREAM_KF_X];
    L jt[STREAM_KF_T][STREAM_KF_T];  // J transposed: column k of J in row k
    L local[STREAM_KF_T];
    keyframe_local(KEPT_NEXT + c * STREAM_KF_X, x, base);
    FGC_KEPT_PASS("log");
    for (int i = 0; i < STREAM_KF_T; ++i) {
        const int sv = KF_FLAT_S[i];
        if (sv >= 0) {
            // a direction of a vector variable (retraction x + delta, Log b - a): only its own
            // entry moves, by exactly what the passes below would compute; every other entry of
            // the two passes is the same value, their difference zero
            const T next_s = KEPT_NEXT[c * STREAM_KF_X + sv];
            const T plus_i = (x[sv] + h) - next_s, minus_i = (x[sv] + T(-h)) - next_s;
            for (int k = 0; k < STREAM_KF_T; ++k) {
#pragma HLS PIPELINE II=1
                jt[i][k] = k == i ? L((plus_i - minus_i) / (T(2) * h)) : L(0);
            }
            FGC_CYCLES("kept", 0, "vector_difference", STREAM_KF_T, 1, CFG::T_DIV_DEPTH + 3 * T_ADD_LAT);
            continue;
        }
        for (int k = 0; k < STREAM_KF_T; ++k) step[k] = T(0);
        step[i] = h;
        keyframe_retract(x, step, moved);
        FGC_KEPT_PASS("retract");
        keyframe_local(KEPT_NEXT + c * STREAM_KF_X, moved, plus);
        FGC_KEPT_PASS("log");
        step[i] = T(-h);
        keyframe_retract(x, step, moved);
        FGC_KEPT_PASS("retract");
        keyframe_local(KEPT_NEXT + c * STREAM_KF_X, moved, minus);
        FGC_KEPT_PASS("log");
        for (int k = 0; k < STREAM_KF_T; ++k) {
#pragma HLS PIPELINE II=1
            jt[i][k] = L((plus[k] - minus[k]) / (T(2) * h));
        }
        FGC_CYCLES("kept", 0, "difference", STREAM_KF_T, 1, CFG::T_DIV_DEPTH);
    }
    for (int k = 0; k < STREAM_KF_T; ++k) local[k] = L(base[k]);
    L shift[STREAM_KF_T];
    kept_matvec<CFG>(KEPT_S + c * STREAM_KF_T * STREAM_KF_T, local, shift);  // S Log(next^-1 x)
    for (int i = 0; i < STREAM_KF_T; ++i) {
#pragma HLS PIPELINE II=1
        KEPT_D[c * STREAM_KF_T + i] -= shift[i];
    }
    FGC_CYCLES("kept", 0, "d_update", STREAM_KF_T, CFG::L_SCATTER_II, CFG::L_SCATTER_DEPTH);
    // S J column by column into snew: a direction q of a variable that is not a vector,
    // sum_k S[:, k] J[k][q] over its variable's directions k (KF_BLOCK_T, KF_BLOCK_DIM: J is
    // block-diagonal by variable, the other entries of its column exactly zero) with k outer and
    // the rows inner, one product a cycle (each entry summed in k order, as a dot product adds
    // it); a vector variable's, J[q][q] S[:, q] (its column of J is zero but there: the same sum)
    L snew[STREAM_KF_T][STREAM_KF_T];
    for (int q = 0; q < STREAM_KF_T; ++q) {
        if (KF_FLAT_S[q] < 0) {
            const int k0 = KF_BLOCK_T[q], kn = KF_BLOCK_DIM[q];
            for (int e = 0; e < kn * STREAM_KF_T; ++e) {
#pragma HLS LOOP_TRIPCOUNT max=STREAM_KF_T*STREAM_KF_T
#pragma HLS PIPELINE II=CFG::MV_II
#pragma HLS DEPENDENCE variable=snew inter false
                const int k = k0 + e / STREAM_KF_T, r = e % STREAM_KF_T;
                const L prev = k == k0 ? L(0) : snew[r][q];
                snew[r][q] = prev + jt[q][k] * KEPT_S[(c * STREAM_KF_T + r) * STREAM_KF_T + k];
            }
            FGC_CYCLES("kept", 0, "sj_column", kn * STREAM_KF_T, CFG::MV_II, CFG::L_ACC_DEPTH);
        } else {
            for (int r = 0; r < STREAM_KF_T; ++r) {
#pragma HLS PIPELINE II=1
                snew[r][q] = L(0) + jt[q][q] * KEPT_S[(c * STREAM_KF_T + r) * STREAM_KF_T + q];
            }
            FGC_CYCLES("kept", 0, "sj_vector", STREAM_KF_T, 1, CFG::L_ACC_DEPTH);
        }
    }
    for (int e = 0; e < STREAM_KF_T * STREAM_KF_T; ++e) {
#pragma HLS PIPELINE II=1
        KEPT_S[c * STREAM_KF_T * STREAM_KF_T + e] = snew[e / STREAM_KF_T][e % STREAM_KF_T];
    }
    FGC_CYCLES("kept", 0, "s_out", STREAM_KF_T * STREAM_KF_T, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
    for (int k = 0; k < STREAM_KF_X; ++k) {
#pragma HLS PIPELINE II=1
        KEPT_NEXT[c * STREAM_KF_X + k] = x[k];
    }
    FGC_CYCLES("kept", 0, "next_out", STREAM_KF_X, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
}

// A conditional (R | S | d, row-major KF_T x (2 KF_T + 1): a QR unit's COND block) stored as
// kept keyframe c's, each row scaled by its pivot's reciprocal on the way (R unit-diagonal: the
// walk's back-substitution divides by nothing; the re-expression's S J and d - S Log act on rows
// alike), a word a cycle: kept_reciprocals (the pivots' reciprocals, nothing written to kept
// memory), then kept_scale. kept_conditional: the two one after the other (a batch step's); the
// window's marginal runs each beside a part of tau (tau_and_keep).
template <class CFG>
void kept_reciprocals(const L cond[STREAM_KF_T * (2 * STREAM_KF_T + 1)], L rinv[STREAM_KF_T]) {
    const int cols = 2 * STREAM_KF_T + 1;
    for (int i = 0; i < STREAM_KF_T; ++i) {
#pragma HLS PIPELINE II=CFG::L_DIV_II
        rinv[i] = L(1) / cond[i * cols + i];
    }
    FGC_CYCLES("kept", 0, "reciprocal", STREAM_KF_T, CFG::L_DIV_II, CFG::L_DIV_DEPTH);
}

// A conditional's rows scaled by their pivots' reciprocals, a word a cycle, into R / S / d's rows
// from row0 on (a kept conditional's place in KEPT_*, or the staged one's SPEC_*: each call site
// its own multiplier). `process` names the loop's counting record.
template <class CFG, int NR, int ND>
void scale_rows(const char* process, const L cond[STREAM_KF_T * (2 * STREAM_KF_T + 1)],
                const L rinv[STREAM_KF_T], int row0, L r[NR], L s[NR], L d[ND]) {
    (void)process;  // (read by the counting build's FGC_CYCLES only)
    const int cols = 2 * STREAM_KF_T + 1;
    for (int e = 0; e < STREAM_KF_T * (2 * STREAM_KF_T + 1); ++e) {
#pragma HLS PIPELINE II=1
        const int i = e / cols, k = e % cols;
        const L v = cond[e] * rinv[i];
        if (k < STREAM_KF_T) {
            r[(row0 + i) * STREAM_KF_T + k] = v;
        } else if (k < 2 * STREAM_KF_T) {
            s[(row0 + i) * STREAM_KF_T + k - STREAM_KF_T] = v;
        } else {
            d[row0 + i] = v;
        }
    }
    FGC_CYCLES(process, 0, "conditional", STREAM_KF_T * cols, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH + L_MUL_LAT);
}

template <class CFG>
void kept_scale(int c, const L cond[STREAM_KF_T * (2 * STREAM_KF_T + 1)], const L rinv[STREAM_KF_T]) {
    scale_rows<CFG, KEPT_MAX * STREAM_KF_T * STREAM_KF_T, KEPT_MAX * STREAM_KF_T>(
        "kept", cond, rinv, c * STREAM_KF_T, KEPT_R, KEPT_S, KEPT_D);
}

template <class CFG>
void kept_conditional(int c, const L cond[STREAM_KF_T * (2 * STREAM_KF_T + 1)]) {
    L rinv[STREAM_KF_T];
    kept_reciprocals<CFG>(cond, rinv);
    kept_scale<CFG>(c, cond, rinv);
}

// Slot 0's conditional (COND of its step: R | S | d, row-major f x (w + 1)) kept as keyframe c's
// (kept_reciprocals beside tau's sign loop, kept_scale beside its tail: tau_and_keep), linearised at slot 0's
// estimate with its parent at slot 1's (keep_points, in words_task of that region; `reuse`: at lin01, where
// the one-step update linearised them); a word a cycle.
template <class CFG>
void keep_points(int c, bool reuse, const T lin01[2 * STREAM_KF_X]) {
    FGC_PHASE("kept");
    for (int k = 0; k < STREAM_KF_X; ++k) {
#pragma HLS PIPELINE II=1
        KEPT_LIN[c * STREAM_KF_X + k] = reuse ? lin01[k] : X[SLOT_X[k]];
        KEPT_NEXT[c * STREAM_KF_X + k] = reuse ? lin01[STREAM_KF_X + k] : X[SLOT_X[STREAM_KF_X + k]];
    }
    FGC_CYCLES("kept", 0, "points", STREAM_KF_X, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
}

// Back-substitution through the kept conditionals c = first - 1 ... 0 from the window's slot 0
// (keyframe first, x0: its estimate copied out of X):
// x_c = lin_c (+) R_c^-1 (d_c - S_c Log(next_c^-1 x_c+1)), R_c unit-diagonal (rows scaled as kept).
template <class CFG>
void kept_walk(int first, const T x0[STREAM_KF_X]) {
#pragma HLS INLINE
    FGC_PHASE("kept");
    T parent[STREAM_KF_X], local_t[STREAM_KF_T], out[STREAM_KF_X], delta_t[STREAM_KF_T];
    L local[STREAM_KF_T], delta[STREAM_KF_T], row[STREAM_KF_T];
    for (int k = 0; k < STREAM_KF_X; ++k) {
#pragma HLS PIPELINE II=1
        parent[k] = x0[k];
    }
    FGC_CYCLES("kept", 0, "parent_in", STREAM_KF_X, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
    for (int c = first - 1; c >= 0; --c) {
#pragma HLS LOOP_TRIPCOUNT max=KEPT_MAX
        keyframe_local(KEPT_NEXT + c * STREAM_KF_X, parent, local_t);
        FGC_KEPT_PASS("log");
        for (int k = 0; k < STREAM_KF_T; ++k) local[k] = L(local_t[k]);
        kept_matvec<CFG>(KEPT_S + c * STREAM_KF_T * STREAM_KF_T, local, row);  // S_c Log(next^-1 x_c+1)
        for (int i = 0; i < STREAM_KF_T; ++i) {
#pragma HLS PIPELINE II=1
            delta[i] = KEPT_D[c * STREAM_KF_T + i] - row[i];
        }
        FGC_CYCLES("kept", 0, "rhs", STREAM_KF_T, CFG::L_SCATTER_II, CFG::L_SCATTER_DEPTH);
        // R_c upper triangular with a unit diagonal (kept_conditional scaled its rows), column
        // by column: delta_i final, then taken off the rows above it
        for (int i = STREAM_KF_T - 1; i >= 0; --i) {
            // (delta[r], r < i, each updated once from delta[i], which this loop never writes)
            for (int r = 0; r < i; ++r) {
#pragma HLS LOOP_TRIPCOUNT max=STREAM_KF_T
#pragma HLS PIPELINE II=1
#pragma HLS DEPENDENCE variable=delta inter false
                delta[r] -= KEPT_R[(c * STREAM_KF_T + r) * STREAM_KF_T + i] * delta[i];
            }
            FGC_CYCLES("kept", 0, "column", i, 1, CFG::L_ACC_DEPTH);
        }
        for (int i = 0; i < STREAM_KF_T; ++i) delta_t[i] = T(delta[i]);
        keyframe_retract(KEPT_LIN + c * STREAM_KF_X, delta_t, out);
        FGC_KEPT_PASS("retract");
        for (int k = 0; k < STREAM_KF_X; ++k) {
#pragma HLS PIPELINE II=1
            X_KEPT[c * STREAM_KF_X + k] = out[k];
            parent[k] = out[k];
        }
        FGC_CYCLES("kept", 0, "estimate_out", STREAM_KF_X, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
    }
}
#endif  // FGC_STREAM_KEPT

#ifdef FGC_STREAM_BATCH
// The kept conditionals' points after a batch step at keyframe j: keyframes 0 … j - W's
// linearisation points and their parents' (BATCH_X: the batch step's optimum, or under the
// one-step policy its start).
template <class CFG>
void batch_points(int j) {
    for (int e = 0; e < (j - STREAM_W + 1) * STREAM_KF_X; ++e) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::TRIP_BATCH_X
#pragma HLS PIPELINE II=1
        KEPT_LIN[e] = BATCH_X[e];
        KEPT_NEXT[e] = BATCH_X[e + STREAM_KF_X];
    }
    FGC_CYCLES("batch", 0, "points", (j - STREAM_W + 1) * STREAM_KF_X, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
}

// A batch step at keyframe j: keyframes 0 … j (the kept ones, then the window's) re-solved by the
// batch kernel; their optimum back, and (once the window is full) the kept net rebuilt from its
// conditionals, keyframes 0 … j - W, and tau written for the next window's oldest. Returns the
// marginal code (0 none, 1 tau written, 2 singular or rank deficient).
template <class CFG>
int batch_step(int j, int first, T errors[2], int info[5]) {
    FGC_PHASE("batch_in");
    for (int e = 0; e < (j + 1) * STREAM_KF_X; ++e) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::TRIP_BATCH_X
#pragma HLS PIPELINE II=1
        const int c = e / STREAM_KF_X, k = e % STREAM_KF_X;
        BATCH_X[e] = c < first ? X_KEPT[e] : X[SLOT_X[(c - first) * STREAM_KF_X + k]];
    }
    FGC_CYCLES("batch", 0, "gather", (j + 1) * STREAM_KF_X, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
    // the one-step policy: the kept conditionals and tau are linearised where the batch kernel's
    // one step linearised the chain, these estimates (kept points and tau's point taken here;
    // tau's, a keyframe's words, whatever the policy)
    if (CFG::ONE_STEP && j >= STREAM_W) batch_points<CFG>(j);
    T tau_lin[STREAM_KF_X];
    const int tau_kf = j >= STREAM_W ? j - STREAM_W + 1 : 0;
    for (int k = 0; k < STREAM_KF_X; ++k) {
#pragma HLS PIPELINE II=1
        tau_lin[k] = BATCH_X[tau_kf * STREAM_KF_X + k];
    }
    FGC_CYCLES("batch", 0, "tau_lin", STREAM_KF_X, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
    int binfo[4];
    CFG::batch_solve(j, j >= STREAM_W ? j - STREAM_W : -1, BATCH_X, BATCH_COND, BATCH_TAU, errors,
                      binfo);
    for (int i = 0; i < 3; ++i) info[i] = binfo[i];
    FGC_PHASE("batch_out");
    for (int e = 0; e < (j + 1) * STREAM_KF_X; ++e) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::TRIP_BATCH_X
#pragma HLS PIPELINE II=1
        const int c = e / STREAM_KF_X, k = e % STREAM_KF_X;
        if (c < first) {
            X_KEPT[e] = BATCH_X[e];
        } else {
            X[SLOT_X[(c - first) * STREAM_KF_X + k]] = BATCH_X[e];
        }
    }
    FGC_CYCLES("batch", 0, "scatter", (j + 1) * STREAM_KF_X, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
    if (j < STREAM_W) return binfo[3] ? 0 : 2;
    const int words = STREAM_KF_T * (2 * STREAM_KF_T + 1);
    for (int c = 0; c <= j - STREAM_W; ++c) {  // the conditionals of keyframes 0 … j - W
#pragma HLS LOOP_TRIPCOUNT max=BATCH_SLOTS
        kept_conditional<CFG>(c, BATCH_COND + c * words);
    }
    if (!CFG::ONE_STEP) batch_points<CFG>(j);
    if (!binfo[3]) return 2;
    return write_tau<CFG>(BATCH_TAU, tau_lin, CFG::ONE_STEP) ? 1 : 2;
}
#endif  // FGC_STREAM_BATCH

#ifdef FGC_STREAM_WINDOW
// A pass's two processes, one DATAFLOW region (window_and_kept): the window's (its solve and
// marginal) beside the kept net's (the re-expression the update before left pending, the walk).
// The kept net's work maintains only the kept memory, which the window's solve does not read:
// an update re-expresses the newest kept conditional at slot 0's new estimate after its solve,
// but leaves it pending (KEPT_PENDING, the point copied into KEPT_PENDING_X) for the next call's
// region, where it runs beside that call's solve - or before the walk that needs it (op 3, a
// batch step's pass -1). The arithmetic is the same whenever it runs, so are the estimates.
// Each process on its own memories and datapaths (the window's: X, AB, DATA_BUF, COND, NF, the
// unit sets; the kept net's: the KEPT_* memories, X_KEPT, the keyframe's Log and retraction
// kernels); the leaving keyframe's tau and its conditional kept (tau_and_keep: keep writes kept
// memory) follow the region, tau's tail beside the keep. A design without one of the two runs that process empty (each function has one
// call site whatever the parts: the second reader reads every preprocessor branch).
//
// The window's process: mode 0 nothing (pass -1, op 3), 1 a sweep pass with the window full (the
// window linearised at the estimates), 2 the update's solve (LM, then the window's rows at its
// optimum again if LM moved after its last linearisation); then, slot ms leaving (ms ==
// STREAM_W), the marginal. LM's functions and the marginal's are one RTL instance each (this
// function's ALLOCATION; the hooks and marginalize INLINE): the marginal's QR step is LM's unit
// set 0. out = {marginal code (0 none, 1 tau written, 2 singular), 1 if the one-step solve's own
// factorisation was the store (reuse)}.
template <class CFG>
void window_task(int mode, int ms, bool live, const T lin01[2 * STREAM_KF_X], T errors[2],
                 int info[5], int result[2]) {
#pragma HLS ALLOCATION function instances=linearize_all limit=1
#pragma HLS ALLOCATION function instances=eliminate_all limit=1
#pragma HLS ALLOCATION function instances=back_substitute_at limit=1
    FGC_TASK();
    result[0] = 0;
    result[1] = 0;
    if (mode == 0) return;
    bool finite = true;  // false: the window is not finite where slot 0 leaves
    bool reuse = false;  // the one-step update took its step: its solve's factorisation is the store
    if (mode == 2) {
#ifdef FGC_SPEC_MARGINAL
        // a keyframe leaving: its marginal beside the solve's back-substitution (the one-step
        // policy's: spec_tau_task, spec_keep_task), kept if the step is taken
        SPEC_ARMED = ms == STREAM_W;
        SPEC_RAN = false;
#endif
        CFG::lm_solve(errors, info, live);
#ifdef FGC_SPEC_MARGINAL
        SPEC_ARMED = false;
#endif
        reuse = ms == STREAM_W && CFG::took_step(info);
        // the window's rows at its optimum for a leaving keyframe's marginal: AB holds them if
        // LM stopped where it last linearised (CFG::at_linearisation), else computed again here
        // by LM's own linearisation instance
#ifdef FGC_STREAM_MARGINAL
        if (ms == STREAM_W && !reuse && !CFG::at_linearisation(info)) {
            FGC_EVENT("relinearize");
            finite = CFG::linearize(live);
        }
#endif
    } else {
        // a sweep pass, window full: slot 0 leaves at the estimates (the window linearised
        // there by LM's instance, its step at mu = 0 by LM's unit set 0)
        FGC_EVENT("sweep");
        finite = CFG::linearize(live);
    }
#ifdef FGC_STREAM_MARGINAL
    if (ms == STREAM_W) result[0] = marginalize<CFG>(finite, reuse, live, lin01) ? 1 : 2;
#else
    (void)finite;
    (void)lin01;
#endif
    result[1] = reuse ? 1 : 0;
}

// The kept net's process: conditional `reexp` (-1: none; the one the update before left pending)
// re-expressed at KEPT_PENDING_X, then (walk > 0) the walk back through the kept conditionals
// walk - 1 … 0 from x0 (their estimates into X_KEPT).
template <class CFG>
void kept_task(int reexp, int walk, const T x0[STREAM_KF_X]) {
    // reexpress's passes and the walk's (both INLINE here) run one after another: one datapath
    // module for every Log and retraction (the kernel's keyframe_local and keyframe_retract,
    // INLINE, are its keyframe_pass's two modes) and one matrix-vector product for all of them
#pragma HLS ALLOCATION function instances=keyframe_pass limit=1
#pragma HLS ALLOCATION function instances=kept_matvec<CFG> limit=1
    FGC_TASK();
#ifdef FGC_STREAM_KEPT
    if (reexp >= 0) {
        FGC_EVENT("kept_reexpress");
        reexpress<CFG>(reexp, KEPT_PENDING_X);
    }
    if (walk > 0) {
        FGC_EVENT("kept_walk");
        kept_walk<CFG>(walk, x0);
    }
#else
    (void)reexp;
    (void)walk;
    (void)x0;
#endif
}

template <class CFG>
void window_and_kept(int mode, int ms, bool live, const T lin01[2 * STREAM_KF_X], T errors[2],
                     int info[5], int result[2], int reexp, int walk, const T x0[STREAM_KF_X]) {
#pragma HLS DATAFLOW
    window_task<CFG>(mode, ms, live, lin01, errors, info, result);
    kept_task<CFG>(reexp, walk, x0);
}

#ifdef FGC_STREAM_MARGINAL
// tau_and_keep's two DATAFLOW regions after the window's, each of three processes with no memory
// between them (every port its process's), each on its own operators:
//   sign_beside_reciprocals: tau's sign loop (NF -> a, the singularity test) beside the kept
//     conditional's pivot reciprocals (COND's diagonal -> rinv: nothing written to kept memory,
//     so it may run before the test says whether the conditional is kept);
//   tau_beside_keep: tau's mean (mean_task: a -> mean) beside its other words (words_task: the
//     conditional's points, keep_points: lin01 or X to KEPT_LIN / KEPT_NEXT; then R from NF,
//     signed on the way, and lin or X to DATA_BUF) beside the conditional kept
//     (kept_scale: COND and rinv to KEPT_R / KEPT_S / KEPT_D); the mean's words after it.
//   The first region also reads the call's outputs out of X (out_task: x_out, KEPT_PENDING_X),
//   which nothing after the window's region writes.
// The fixed-lag window (no kept net) runs the keep's processes empty.
template <class CFG>
void sign_task(const L rows[STREAM_KF_T * (STREAM_KF_T + 1)], L a[STREAM_KF_T][STREAM_KF_T + 1], bool ok[1]) {
    FGC_TASK();
    ok[0] = tau_sign<CFG>(rows, a);
}

template <class CFG>
void reciprocal_task(L rinv[STREAM_KF_T]) {
    FGC_TASK();
#ifdef FGC_STREAM_KEPT
    FGC_PHASE("kept");
    kept_reciprocals<CFG>(COND + STEP_COND_OFF[STREAM_LEAF_STEP], rinv);
#else
    (void)rinv;
#endif
}

// The call's outputs read out of X beside them (X is final once the window's region is over: nothing
// after it writes X but this task, below): slot 0's new estimate for the pending re-expression where `pending`, the
// window's storage out where `out` (the update's last pass).
// FGC_SPEC_MARGINAL (the one-step policy): the step taken is still in X_TRIAL (the kernel's
// X_HELD, its LmConfig's accept_trial; `held`): the reads take X_TRIAL's words and write them into
// X as they go (x_out reads every word: X is whole when it ends), so no copy runs of its own.
template <class CFG>
void out_task(bool out, bool pending, bool held, T x_out[N_X]) {
    FGC_TASK();
    (void)held;
#ifdef FGC_STREAM_KEPT
    if (pending) {
        FGC_PHASE("kept");
        for (int k = 0; k < STREAM_KF_X; ++k) {
#pragma HLS PIPELINE II=1
            KEPT_PENDING_X[k] = FGC_X_OUT(held, SLOT_X[k]);
        }
        FGC_CYCLES("kept", 0, "slot0", STREAM_KF_X, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
    }
#else
    (void)pending;
#endif
    if (out) {
        FGC_PHASE("setup");
        for (int i = 0; i < N_X; ++i) {
#pragma HLS PIPELINE II=1
            const T v = FGC_X_OUT(held, i);
            x_out[i] = v;
#ifdef FGC_SPEC_MARGINAL
            if (held) X[i] = v;
#endif
        }
        FGC_CYCLES("top", 0, "x_out", N_X, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
    }
}

template <class CFG>
void sign_beside_reciprocals(const L rows[STREAM_KF_T * (STREAM_KF_T + 1)], L a[STREAM_KF_T][STREAM_KF_T + 1], bool ok[1], L rinv[STREAM_KF_T],
                             bool out, bool pending, bool held, T x_out[N_X]) {
#pragma HLS DATAFLOW
    sign_task<CFG>(rows, a, ok);
    reciprocal_task<CFG>(rinv);
    out_task<CFG>(out, pending, held, x_out);
}

template <class CFG>
void mean_task(const L a[STREAM_KF_T][STREAM_KF_T + 1], L mean[STREAM_KF_T]) {
    FGC_TASK();
    tau_mean<CFG>(a, mean);
}

template <class CFG>
void words_task(int c, const L rows[STREAM_KF_T * (STREAM_KF_T + 1)], const T lin01[2 * STREAM_KF_X],
                bool given) {
    FGC_TASK();
#ifdef FGC_STREAM_KEPT
    keep_points<CFG>(c, given, lin01);
#else
    (void)c;
#endif
    tau_words<CFG>(rows, lin01 + STREAM_KF_X, given);
}

template <class CFG>
void keep_task(int c, const L rinv[STREAM_KF_T]) {
    FGC_TASK();
#ifdef FGC_STREAM_KEPT
    FGC_PHASE("kept");
    kept_scale<CFG>(c, COND + STEP_COND_OFF[STREAM_LEAF_STEP], rinv);
#else
    (void)c;
    (void)rinv;
#endif
}

template <class CFG>
void tau_beside_keep(const L a[STREAM_KF_T][STREAM_KF_T + 1], L mean[STREAM_KF_T],
                     const L rows[STREAM_KF_T * (STREAM_KF_T + 1)], const T lin01[2 * STREAM_KF_X],
                     bool given, int c, const L rinv[STREAM_KF_T]) {
#pragma HLS DATAFLOW
    mean_task<CFG>(a, mean);
    words_task<CFG>(c, rows, lin01, given);
    keep_task<CFG>(c, rinv);
}

// The leaving keyframe's marginal after the window's region (its rows ready in NF: window_task's
// marginalize): tau signed and checked (tau_sign reads the rows where the step left them, each
// word once: no copy first) beside the kept conditional's reciprocals and the call's reads of X
// (out_task: `out`, `pending`, whatever tau's test says); if tau is not singular, tau's mean
// beside its other words (after the conditional's points: keep_points) and the conditional
// kept, the mean's words last. Kept
// keyframe c (the kept net's; unused without one). False, nothing written or kept, if tau is
// singular.
template <class CFG>
bool tau_and_keep(int c, bool reuse, const T lin01[2 * STREAM_KF_X], bool out, bool pending,
                  bool held, T x_out[N_X]) {
    L a[STREAM_KF_T][STREAM_KF_T + 1];
    L rinv[STREAM_KF_T];
    bool ok[1];
    sign_beside_reciprocals<CFG>(NF + STEP_NF_OFF[STREAM_LEAF_STEP], a, ok, rinv, out, pending, held, x_out);
    FGC_TASKS_JOIN();
    if (!ok[0]) return false;
    L mean[STREAM_KF_T];
    tau_beside_keep<CFG>(a, mean, NF + STEP_NF_OFF[STREAM_LEAF_STEP], lin01, reuse, c, rinv);
    FGC_TASKS_JOIN();
    tau_mean_out<CFG>(mean);
    return true;
}

#ifdef FGC_SPEC_MARGINAL
// The one-step policy's marginal beside the update's back-substitution. Under the one-step
// policy the store is the update's own factorisation whenever the step is taken (took_step):
// slot 0's rows in NF and its conditional in COND at mu = 0, at the call's start (lin01), all
// known once the solve's elimination is over, while its back-substitution, the state update
// and the cost at X_TRIAL (which decides whether the step is taken) still run. So the update's
// back_substitute region runs two last processes, spec_tau_task, that forms tau (signed, its
// mean, its words into TAU_BUF), and beside it spec_keep_task, the leaving keyframe's
// conditional (its points, pivots'
// reciprocals, rows scaled into SPEC_R / SPEC_S / SPEC_D) from the same words in the same
// order as tau_and_keep would after the region - the same functions but for where the words
// go: no memory of the region's other processes (COND is the slots' - KEEP_COND is qr_commit's
// second copy of the leaving keyframe's conditional; DATA_BUF the cost pass's; KEPT_* the kept
// task's, beside the window's process) - and no operator of theirs (its own call sites).
// When the step is taken, out_beside_commit moves the words where tau_and_keep writes them
// (TAU_BUF to slot 1's prior in DATA_BUF, the staged conditional into kept memory) beside the
// call's reads of X; when it is not (the cost at X_TRIAL not finite, the step too small or not
// finite), the words are dropped and the update runs the marginal as before (window_task's
// relinearisation, the leaf step, tau_and_keep): nothing of the speculation was written where
// the window or the kept net reads it.
const int SPEC_TAU_WORDS = STREAM_KF_X + STREAM_KF_T + STREAM_KF_T * (STREAM_KF_T + 1) / 2 + 2;

// tau's words into TAU_BUF (slot 1's prior's layout: the linearisation point `lin`, the mean,
// R by rows, no robust loss), as tau_tail writes them into DATA_BUF
template <class CFG>
void tau_buffer(const L a[STREAM_KF_T][STREAM_KF_T + 1], const L mean[STREAM_KF_T], const T lin[STREAM_KF_X]) {
    for (int k = 0; k < STREAM_KF_X; ++k) {
#pragma HLS PIPELINE II=1
        TAU_BUF[k] = lin[k];
    }
    for (int i = 0; i < STREAM_KF_T; ++i) {
#pragma HLS PIPELINE II=1
        TAU_BUF[STREAM_KF_X + i] = T(mean[i]);
    }
    for (int i = 0, w = STREAM_KF_X + STREAM_KF_T; i < STREAM_KF_T; ++i) {
        for (int c = i; c < STREAM_KF_T; ++c) {
#pragma HLS LOOP_TRIPCOUNT max=STREAM_KF_T
#pragma HLS PIPELINE II=1
            TAU_BUF[w++] = T(a[i][c]);
        }
    }
    TAU_BUF[SPEC_TAU_WORDS - 2] = T(0);  // no robust loss
    TAU_BUF[SPEC_TAU_WORDS - 1] = T(0);
    FGC_CYCLES("spec", 0, "tau_out", SPEC_TAU_WORDS, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
}

#ifdef FGC_STREAM_KEPT
// The leaving keyframe's conditional staged: its points (lin01: the one-step update linearised
// there), then its rows scaled by its pivots' reciprocals (kept_reciprocals, then kept_scale's
// loop into SPEC_R / SPEC_S / SPEC_D)
template <class CFG>
void spec_keep(const L cond[STREAM_KF_T * (2 * STREAM_KF_T + 1)], const T lin01[2 * STREAM_KF_X]) {
    for (int k = 0; k < STREAM_KF_X; ++k) {
#pragma HLS PIPELINE II=1
        SPEC_LIN[k] = lin01[k];
        SPEC_NEXT[k] = lin01[STREAM_KF_X + k];
    }
    FGC_CYCLES("spec", 0, "points", STREAM_KF_X, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
    L rinv[STREAM_KF_T];
    kept_reciprocals<CFG>(cond, rinv);
    scale_rows<CFG, STREAM_KF_T * STREAM_KF_T, STREAM_KF_T>("spec", cond, rinv, 0, SPEC_R, SPEC_S, SPEC_D);
}
#endif

// back_substitute's last processes (accel.cpp.jinja's spec_tau and spec_kept, processes of
// trial_cost's region): where `run` (the update's solve with a keyframe leaving, SPEC_ON), tau
// signed and checked, and if it is not singular its mean and words (spec_tau_task); beside it,
// the leaving keyframe's conditional staged (spec_keep_task, above). The two share no memory:
// tau reads NF and LIN01's second half, the conditional KEEP_COND and LIN01K (update_start's
// second copy of LIN01, written in the same cycles); the conditional is staged whether or not
// tau is singular (SPEC_OK, tau's, decides whether anything staged is committed). Each runs its
// loops one after another, beside the region's others and each other (csim counting: an
// FGC_OUTER_BESIDE each; plan/stream.py's _spec_over takes the longer).
template <class CFG>
void spec_tau_task(bool run) {
    FGC_OUTER_BESIDE();  // csim cycle counting only: a process beside back_substitute's others
    if (!run) return;
    FGC_SEQUENTIAL();  // (its loops one after another)
    FGC_EVENT("spec_marginal");
    SPEC_RAN = true;
    L a[STREAM_KF_T][STREAM_KF_T + 1];
    const bool ok = tau_sign<CFG>(NF + STEP_NF_OFF[STREAM_LEAF_STEP], a);
    SPEC_OK = ok;
    if (ok) {
        L mean[STREAM_KF_T];
        tau_mean<CFG>(a, mean);
        tau_buffer<CFG>(a, mean, LIN01 + STREAM_KF_X);
    }
    FGC_PHASE("backsub");
}

#ifdef FGC_STREAM_KEPT
template <class CFG>
void spec_keep_task(bool run) {
    FGC_OUTER_BESIDE();  // csim cycle counting only: a process beside back_substitute's others
    if (!run) return;
    FGC_SEQUENTIAL();  // (its loops one after another)
    spec_keep<CFG>(KEEP_COND, LIN01K);
    FGC_PHASE("backsub");
}
#endif

// The step taken: the speculation's words where tau_and_keep writes them, two a cycle (each
// memory's two ports): tau's into slot 1's prior (tau_commit_task), the staged conditional into
// kept keyframe c's rows (keep_commit_task: R, S, d and the points, each its own memory)
template <class CFG>
void tau_commit_task(bool commit) {
    FGC_TASK();
    if (!commit) return;
    FGC_PHASE("marginal");
    for (int k = 0; k < SPEC_TAU_WORDS; k += 2) {
#pragma HLS PIPELINE II=1
        for (int h = 0; h < 2; ++h) {
            if (k + h < SPEC_TAU_WORDS) DATA_BUF[STREAM_PRIOR1 + k + h] = TAU_BUF[k + h];
        }
    }
    FGC_CYCLES("marginal", 0, "tau_commit", (SPEC_TAU_WORDS + 1) / 2, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
}

template <class CFG>
void keep_commit_task(bool commit, int c) {
    FGC_TASK();
#ifdef FGC_STREAM_KEPT
    if (!commit) return;
    FGC_PHASE("kept");
    const int n = STREAM_KF_T * STREAM_KF_T;
    for (int e = 0; e < STREAM_KF_T * STREAM_KF_T; e += 2) {
#pragma HLS PIPELINE II=1
        for (int h = 0; h < 2; ++h) {
            const int q = e + h;
            if (q < n) {
                KEPT_R[c * n + q] = SPEC_R[q];
                KEPT_S[c * n + q] = SPEC_S[q];
            }
            if (q < STREAM_KF_T) KEPT_D[c * STREAM_KF_T + q] = SPEC_D[q];
            if (q < STREAM_KF_X) {
                KEPT_LIN[c * STREAM_KF_X + q] = SPEC_LIN[q];
                KEPT_NEXT[c * STREAM_KF_X + q] = SPEC_NEXT[q];
            }
        }
    }
    FGC_CYCLES("kept", 0, "keep_commit", (n + 1) / 2, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
#else
    (void)commit;
    (void)c;
#endif
}

// One DATAFLOW region after the window's (the step taken): the two commits beside the call's
// reads of X (out_task), no memory between them
template <class CFG>
void out_beside_commit(bool commit, int c, bool out, bool pending, bool held, T x_out[N_X]) {
#pragma HLS DATAFLOW
    tau_commit_task<CFG>(commit);
    keep_commit_task<CFG>(commit, c);
    out_task<CFG>(out, pending, held, x_out);
}
#endif  // FGC_SPEC_MARGINAL
#endif
#endif  // FGC_STREAM_WINDOW

#ifdef FGC_STREAM_WINDOW
#ifdef FGC_STREAM_KEPT
#define FGC_STREAM_KEPT_ARG , T x_kept[STREAM_KEPT_WORDS]
#else
#define FGC_STREAM_KEPT_ARG
#endif
// The streaming top's body. op 0 resets the window (x_in: every slot's storage, data: every
// factor's words); op 2 (batch steps) resets the batch kernel the same way; op 1 brings the next
// keyframe (x_in: its storage, data: its words, then the batch kernel's) and runs the update:
// the shift once the window is full, LM on the window (or the batch step), the kept conditional's
// re-expression, the marginal tau, the new kept conditional, the window out (x_out).
// errors = {initial, final} of the solve, info = {iterations, status, reason, slot, marginal}.
// op 3 (incremental) asks for the kept keyframes' estimates: walked back from slot 0 if an update
// left them stale, out in x_kept (keyframes 0 … first - 1); nothing else moves. An update does
// not walk (ISAM2's update does not compute its estimates either): a batch step walks them
// first if they are stale, as it starts from them; the estimates are the same whenever walked.
template <class CFG>
void stream_call(int op, const T x_in[STREAM_IN_X], const DataIn data[DATA_IN_N], T x_out[N_X]
                 FGC_STREAM_KEPT_ARG, T errors[2], int info[5]) {
    // LM, the marginal's linearisation and its QR step run in window_task (its ALLOCATION: one
    // RTL instance of each kernel function for all their call sites)
    FGC_EVENT("call");
    if (op == 0) {  // reset: the whole window in (the slots' values, every factor's words)
        FGC_PHASE("setup");
        for (int i = 0; i < N_X; ++i) {
#pragma HLS PIPELINE II=1
            X[i] = x_in[i];
        }
        for (int i = 0; i < N_DATA; ++i) {
#pragma HLS PIPELINE II=1
#ifdef FGC_DATA_BEAT
            DATA_BUF[i] = data[i / DATA_BEAT].lane_word[i % DATA_BEAT];
#else
            DATA_BUF[i] = data[i];
#endif
        }
        FGC_CYCLES("top", 0, "x_in", N_X, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
        FGC_CYCLES("top", 0, "data_in", N_DATA, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
        STREAM_COUNT = 0;
#ifdef FGC_STREAM_KEPT
        STREAM_TOTAL = 0;
        KEPT_STALE = false;
        KEPT_PENDING = -1;
#endif
        errors[0] = T(0);
        errors[1] = T(0);
        for (int i = 0; i < 5; ++i) info[i] = 0;
        return;
    }
#ifdef FGC_STREAM_BATCH
    if (op == 2) {  // the batch kernel's reset: its slots' values, every factor's words
        CFG::batch_reset(x_in, data);
        errors[0] = T(0);
        errors[1] = T(0);
        for (int i = 0; i < 5; ++i) info[i] = 0;
        return;
    }
#endif
    const bool update = op == 1;  // else op 3: the kept keyframes' estimates
    const int j = STREAM_COUNT;
    const int m = j < STREAM_SLOTS - 1 ? j : STREAM_SLOTS - 1;  // the keyframe's slot
#ifdef FGC_STREAM_KEPT
    // this keyframe's index (op 3: the last update's)
    const int total = update ? STREAM_TOTAL : STREAM_TOTAL - 1;
    const int first = total < STREAM_W ? 0 : total - STREAM_W;  // the window's oldest
#else
    if (!update) return;
#endif
#ifdef FGC_STREAM_SWEEP
    // a batch step is a sweep through the window: keyframes 0 … total come in again one a pass,
    // at their estimates (sweep_gather), and once the window is full each pass's slot 0 leaves
    // as after an update, its step at mu = 0 kept and its tau written (no solve); the last pass
    // is the update of keyframe total, its window's oldest prior the sweep's tau, its kept net
    // the sweep's conditionals (not re-expressed: they hold the sweep's points; walked when the
    // estimates are asked for, as after any update)
    // the call's keyframe is kept as it came: by sweep_store before a sweep (its passes read it
    // back), else by update_start as it enters the window (the same words, no cycles of their own)
    bool sweep = false;
    if (update) {
        sweep = IS_BATCH[total] != 0;
        if (sweep) sweep_store<CFG>(total, m, j >= STREAM_SLOTS, x_in, data);
    }
    const int passes = sweep ? total + 1 : 1;
    bool sweep_singular = false;
#else
    const bool sweep = false;
    const int passes = 1;
#endif
#ifdef FGC_STREAM_BATCH
    const bool batch = update && IS_BATCH[total];  // a step of the batch kernel
#else
    const bool batch = false;
#endif
#if defined(FGC_STREAM_KEPT) && (defined(FGC_STREAM_BATCH) || defined(FGC_STREAM_SWEEP))
    // slot 0 (keyframe first - 1) leaves: its estimate kept (a batch step starts from it; a walk
    // rewrites it): before a batch step or a sweep (their pass -1 and the sweep's gather read it
    // back), else in the update's start region beside the words (start_x_task)
    const bool leaves = update && j >= STREAM_SLOTS;
    if (leaves && (sweep || batch)) {
        for (int k = 0; k < STREAM_KF_X; ++k) {
#pragma HLS PIPELINE II=1
            X_KEPT[(first - 1) * STREAM_KF_X + k] = X[SLOT_X[k]];
        }
        FGC_CYCLES("top", 0, "leave", STREAM_KF_X, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
    }
    const bool leave = leaves && !sweep && !batch;
    const int kept = first - 1;
#else
    const bool leave = false;
    const int kept = 0;
#endif
#ifdef FGC_STREAM_KEPT
    // a batch step starts from the kept estimates: pass -1 (the kept process alone) walks them
    // back from the leaving keyframe's estimate first if an update left them stale (the batch
    // kernel's step runs it whatever: its one call site of the region)
    const int p0 = batch || (sweep && KEPT_STALE) ? -1 : 0;
#else
    const int p0 = 0;
    (void)sweep;
    (void)batch;
#endif
    int marginal = 0;  // 0: none left, 1: tau written, 2: singular (not written)
    bool out_read = false, pending_read = false;  // x_out / KEPT_PENDING_X read beside tau
    (void)pending_read;
    for (int p = p0; p < passes; ++p) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::TRIP_PASSES
        const bool solve = update && p >= 0;  // else pass -1 or op 3: the kept process alone
        const bool last = p == passes - 1;
#ifdef FGC_STREAM_KEPT
        const int c = total - passes + 1 + p;  // the pass's keyframe
#endif
        // slots 0 and 1 where the update linearises them: under the one-step policy a leaving
        // keyframe's conditional and tau are kept there once the step is taken (copied whatever
        // the policy, a word a cycle)
#ifdef FGC_SPEC_MARGINAL
        T (&lin01)[2 * STREAM_KF_X] = LIN01;  // (spec_tau_task reads them in the solve)
#else
        T lin01[2 * STREAM_KF_X];
#endif
        int mode = 0;  // the window's process: 0 nothing, 1 a sweep pass's, 2 the update's solve
        bool live = false;  // keyframe 0 has left: slot 0's factors that hold nothing are skipped
        int mc = -1;  // the pass's slot (-1: no marginal)
        if (solve) {
#ifdef FGC_STREAM_SWEEP
            if (sweep && p == 0) sweep_gather<CFG>(total, j >= STREAM_SLOTS ? first - 1 : 0, first);
            const int jc = c < STREAM_SLOTS ? c : STREAM_SLOTS;  // keyframes in the window before it
            const int row = c < SWEEP_SLOTS ? c : SWEEP_SLOTS;
#else
            const int jc = j;
#endif
            const int ms = jc < STREAM_SLOTS - 1 ? jc : STREAM_SLOTS - 1;  // the pass's slot
            live = jc >= STREAM_SLOTS;  // (the window has moved: slot 0's prior is tau)
#ifdef FGC_QR_KEEP_CLASS
            FGC_QR_KEEP_CLASS(jc);  // the QR steps' keep rule: this update's patterns (the kernel's)
#endif
#ifndef FGC_STREAM_SWEEP
            const int row = 0;
#endif
            // the pass goes on to the window's region (not a batch step, not a sweep pass while
            // the window fills): slots 0 and 1 copied in the start region
            const bool points = !batch && (last || ms == STREAM_W);
            update_start<CFG>(leave && p == 0, kept, jc >= STREAM_SLOTS, ms, row, sweep, x_in, data,
                              points, lin01);
            FGC_TASKS_JOIN();
#ifdef FGC_STREAM_BATCH
            // keyframe total's words for the batch kernel follow the window's
            if (total < BATCH_SLOTS) {
                CFG::batch_in(total, x_in, data + (j >= STREAM_SLOTS ? STREAM_FULL_WORDS
                                                   : STREAM_NEW_BEGIN[m + 1] - STREAM_NEW_BEGIN[m]));
            }
            if (batch) {
                marginal = batch_step<CFG>(total, first, errors, info);
                continue;
            }
#endif
            if (!points) continue;  // a sweep pass while the window fills
            mode = last ? 2 : 1;
            mc = ms;
        }
        // the kept net's process (one call site of the region for every op and pass): the
        // re-expression the update before left pending, in the first region after it (beside
        // this update's solve, or before op 3's or pass -1's walk); op 3 walks back from slot 0,
        // pass -1 from the leaving keyframe's estimate (the walk the updates before did not
        // run), each only if the estimates are stale; a sweep's other passes run it empty
        T x0[STREAM_KF_X];  // the walk's parent: slot 0's estimate (pass -1: keyframe first - 1's)
#ifdef FGC_STREAM_KEPT
        const int reexp = KEPT_PENDING;
        const int walk = !KEPT_STALE ? 0 : p < 0 ? first - 1 : update ? 0 : first;
        if (walk > 0) {
            FGC_PHASE("kept");
            const bool from_kept = p < 0;
            const int parent = from_kept ? (first - 1) * STREAM_KF_X : 0;
            for (int k = 0; k < STREAM_KF_X; ++k) {
#pragma HLS PIPELINE II=1
                x0[k] = from_kept ? X_KEPT[parent + k] : X[SLOT_X[k]];
            }
            FGC_CYCLES("kept", 0, "slot0", STREAM_KF_X, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
        }
#else
        const int reexp = -1, walk = 0;
#endif
        int result[2] = {0, 0};  // the window's process: marginal code, reuse
        window_and_kept<CFG>(mode, mc, live, lin01, errors, info, result, reexp, walk, x0);
        FGC_TASKS_JOIN();
#ifdef FGC_STREAM_KEPT
        KEPT_PENDING = -1;
        if (walk > 0) KEPT_STALE = false;
#endif
        if (!solve) continue;
        marginal = result[0];
#ifdef FGC_STREAM_MARGINAL
#ifdef FGC_STREAM_KEPT
        const int kc = c - STREAM_W;  // the kept keyframe (the leaving one)
#else
        const int kc = 0;
#endif
        // tau, and the leaving keyframe's conditional kept beside its tail
#ifdef FGC_SPEC_MARGINAL
        if (mc == STREAM_W && marginal == 1 && SPEC_RAN && result[1] != 0) {
            // the step taken: tau and the conditional as the solve's region formed them, moved
            // where the window and the kept net read them beside the call's reads of X
#ifdef FGC_STREAM_KEPT
            pending_read = last && !sweep && first > 0;
#endif
            out_beside_commit<CFG>(SPEC_OK, kc, last, pending_read, X_HELD, x_out);
            X_HELD = false;  // (X written as x_out was read)
            FGC_TASKS_JOIN();
            marginal = SPEC_OK ? 1 : 2;
            out_read = last;
        } else
#endif
        if (mc == STREAM_W && marginal == 1) {
            // the call's reads of X (its outputs, the pending point) beside tau's sign loop
#ifdef FGC_STREAM_KEPT
            pending_read = last && !sweep && first > 0;
#endif
#ifdef FGC_SPEC_MARGINAL
            const bool held = X_HELD;
            X_HELD = false;  // (X written as x_out is read)
#else
            const bool held = false;
#endif
            marginal = tau_and_keep<CFG>(kc, result[1] != 0, lin01, last, pending_read, held, x_out) ? 1 : 2;
            out_read = last;
        }
#endif
#ifdef FGC_STREAM_SWEEP
        if (!last && marginal != 1) sweep_singular = true;
#endif
#ifdef FGC_STREAM_KEPT
        if (last && !sweep && first > 0) {
            // this update's own re-expression (the newest kept conditional at slot 0's new
            // estimate), left pending for the next call's region: the point copied out of X
            // (beside tau's sign loop where a keyframe left: out_task)
            if (!pending_read) {
                FGC_PHASE("kept");
                for (int k = 0; k < STREAM_KF_X; ++k) {
#pragma HLS PIPELINE II=1
                    // (the step taken may still be in X_TRIAL: X_HELD, out_task's note)
                    KEPT_PENDING_X[k] = FGC_X_OUT(X_HELD, SLOT_X[k]);
                }
                FGC_CYCLES("kept", 0, "slot0", STREAM_KF_X, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
            }
            KEPT_PENDING = first - 1;
        }
#endif
    }
    if (!update) {  // op 3: the kept keyframes' estimates out
#ifdef FGC_STREAM_KEPT
        FGC_PHASE("setup");
        for (int i = 0; i < first * STREAM_KF_X; ++i) {
#pragma HLS LOOP_TRIPCOUNT max=STREAM_KEPT_WORDS
#pragma HLS PIPELINE II=1
            x_kept[i] = X_KEPT[i];
        }
        FGC_CYCLES("top", 0, "x_kept_out", first * STREAM_KF_X, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
#endif
        return;
    }
#ifdef FGC_STREAM_SWEEP
    if (sweep_singular) marginal = 2;
#endif
#ifdef FGC_STREAM_KEPT
    // an incremental update (a sweep's last pass too) leaves the kept estimates stale: the
    // newest conditional re-expressed or the net rebuilt, not walked (the batch kernel's step
    // leaves its optimum there)
    KEPT_STALE = !batch && first > 0;
    STREAM_TOTAL = total + 1;
#endif
    if (!out_read) {  // (else read out beside tau's sign loop: out_task)
        FGC_PHASE("setup");
        for (int i = 0; i < N_X; ++i) {
#pragma HLS PIPELINE II=1
            // (the step taken may still be in X_TRIAL: X_HELD, out_task's note)
            const T v = FGC_X_OUT(X_HELD, i);
            x_out[i] = v;
#ifdef FGC_SPEC_MARGINAL
            if (X_HELD) X[i] = v;
#endif
        }
        FGC_CYCLES("top", 0, "x_out", N_X, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
#ifdef FGC_SPEC_MARGINAL
        X_HELD = false;
#endif
    }
    info[3] = m;
    info[4] = marginal;
    STREAM_COUNT = j < STREAM_SLOTS ? j + 1 : STREAM_SLOTS;
}
#undef FGC_STREAM_KEPT_ARG
#endif  // FGC_STREAM_WINDOW

#ifdef FGC_STREAM_BATCH_KERNEL
// The batch kernel (fgc_backends/hls/window.py, BatchLayout: slot c holds keyframe c, eliminated
// serially oldest first, so each slot's step leaves its conditional on the next slot and passes
// the next its factor). Its reset: every slot's storage, every factor's words (zero information,
// priors held).
template <class CFG>
void batch_kernel_reset(const T x_in[N_X], const T data[N_DATA]) {
    FGC_PHASE("batch_in");
    for (int i = 0; i < N_X; ++i) {
#pragma HLS PIPELINE II=1
        X[i] = x_in[i];
    }
    for (int i = 0; i < N_DATA; ++i) {
#pragma HLS PIPELINE II=1
        DATA_BUF[i] = data[i];
    }
}

// Keyframe c into slot c: its storage, its factors' and its prior's words.
template <class CFG>
void batch_kernel_in(int c, const T x_in[STREAM_KF_X], const T data[N_DATA]) {
    FGC_PHASE("batch_in");
    keyframe_in<CFG, true>(c, x_in, data);
}

// The batch step over keyframes 0 … j: x_io in (their estimates, keyframe c at c * STREAM_KF_X),
// LM from there, x_io out (the optimum); then the chain linearised there and eliminated once more
// at mu = 0: cond_out[c] (c < j) each keyframe's conditional (R | S | d, KF_T x (2 KF_T + 1)),
// tau_out the factor keyframe tau_slot's step passes to the next (KF_T x (KF_T + 1)), if
// tau_slot >= 0. info = {iterations, status, reason, 1 if the elimination was full rank}.
template <class CFG>
void batch_kernel_solve(int j, int tau_slot, T x_io[STREAM_SLOTS * STREAM_KF_X],
                        L cond_out[STREAM_SLOTS * STREAM_KF_T * (2 * STREAM_KF_T + 1)],
                        L tau_out[STREAM_KF_T * (STREAM_KF_T + 1)], T errors[2], int info[4]) {
    // LM (its body inlined here: CFG::lm_solve calls fgc_lm::optimize_inline) and the store's
    // linearisation and elimination after it run one after the other: one RTL instance of
    // each kernel function for all their call sites (the hooks between are INLINE)
#pragma HLS ALLOCATION function instances=linearize_all limit=1
#pragma HLS ALLOCATION function instances=eliminate_all limit=1
#pragma HLS ALLOCATION function instances=back_substitute_at limit=1
    FGC_PHASE("batch_in");
    for (int e = 0; e < (j + 1) * STREAM_KF_X; ++e) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::TRIP_X
#pragma HLS PIPELINE II=1
        X[SLOT_X[e]] = x_io[e];
    }
    FGC_CYCLES("batch", 0, "x_in", (j + 1) * STREAM_KF_X, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
    CFG::lm_solve(errors, info);
    // the chain's rows at the optimum: AB already holds them if LM stopped where it last
    // linearised (CFG::at_linearisation), else they are computed again; the one-step policy's
    // step taken (CFG::took_step): its solve's COND and NF, at mu = 0 at x_io's start, are the
    // store, nothing is eliminated again
    bool ok = true;
    if (!CFG::took_step(info)) {
        if (!CFG::at_linearisation(info)) {
            FGC_EVENT("relinearize");
            ok = CFG::linearize();
        }
        ok = ok && CFG::eliminate();
    }
    info[3] = ok ? 1 : 0;
    FGC_PHASE("batch_out");
    for (int e = 0; e < (j + 1) * STREAM_KF_X; ++e) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::TRIP_X
#pragma HLS PIPELINE II=1
        x_io[e] = X[SLOT_X[e]];
    }
    FGC_CYCLES("batch", 0, "x_out", (j + 1) * STREAM_KF_X, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
    const int words = STREAM_KF_T * (2 * STREAM_KF_T + 1);
    for (int e = 0; e < j * words; ++e) {
#pragma HLS LOOP_TRIPCOUNT max=CFG::TRIP_COND
#pragma HLS PIPELINE II=1
        const int c = e / words;
        cond_out[e] = COND[STEP_COND_OFF[SLOT_STEP[c]] + e - c * words];
    }
    FGC_CYCLES("batch", 0, "conditionals_out", j * words, CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
    if (tau_slot >= 0) {
        const int n0 = STEP_NF_OFF[SLOT_STEP[tau_slot]];
        for (int e = 0; e < STREAM_KF_T * (STREAM_KF_T + 1); ++e) {
#pragma HLS PIPELINE II=1
            tau_out[e] = NF[n0 + e];
        }
        FGC_CYCLES("batch", 0, "tau_out", STREAM_KF_T * (STREAM_KF_T + 1), CFG::T_MOVE_II, CFG::T_MOVE_DEPTH);
    }
}
#endif  // FGC_STREAM_BATCH_KERNEL

#undef FGC_KEPT_PASS
#undef FGC_X_OUT

#endif  // FGC_STREAM_H
