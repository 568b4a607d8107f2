// fgc_cycles.h: a C-simulation-only count of the cycles the accelerator plan assigns to the loops
// the fixed units execute (backends/hls/plan.py: a loop of `trip` iterations at initiation interval
// `ii` with pipeline depth `depth` takes (trip - 1) * ii + depth cycles, 0 when trip == 0).
//
// Every pipelined (or scalar) loop of fgc_qr.h and fgc_cpe.h reports itself once per execution
// with FGC_CYCLES(process, instance, loop, trip, ii, depth); every entry into a DATAFLOW region
// reports FGC_REGION(name) first. Unless the testbench build defines FGC_COUNT_CYCLES both macros
// expand to nothing, so synthesis and the ordinary C simulation never see them.
//
// With FGC_COUNT_CYCLES the records are kept in the order they happen (fgc_cycles::log()); a
// region's processes run one after another in C simulation, so a record belongs to the last region
// entered, or to no region (region == -1) for the sequential code between regions, which must call
// FGC_SEQUENTIAL() after a region returns; FGC_DRAINED(streams, n) at a region's end checks that
// its n local streams were read empty. fgc_cycles::total() applies the plan's arithmetic:
// sequential records add up; a dataflow region takes its slowest process (the sum of that
// process's loops) plus the fill (the depth of the first loop that runs) of each other process,
// as plan_cost does; and no less than the end of any process's last loop when its loops that
// wait for another's (FGC_WAIT before a loop: it reads the stream that loop of an earlier process
// of the region writes - the QR Evaluate the column the Update unit streams, the Evaluate v_0
// and tau from qr_finish) end no earlier than their depth after the loop they wait for;
// FGC_WAIT_AFTER(..., after): the loop reads that stream in one iteration only, `after` cycles
// (iterations at its II) before its last iteration issues - an Update unit's dot_axpy reads v_0
// and tau inside its loop - so it ends no earlier than after + its depth after that loop.
//
// The kernel's own loops (factor datapaths, gradient / HGC, stacking, commit, assembly, state
// update, LM control, the rounding-noise pass) report themselves the same way. FGC_PHASE(name)
// names the plan phase (group) the following records belong to, and FGC_EVENT(name) counts one
// execution of something the plan prices per execution (a linearisation, a linear solve, a
// retraction, a cost pass, ...); fgc_cycles::phase_totals() applies total()'s arithmetic to each
// run of records of one phase, and fgc_cycles::events() lists the counts.
//
// An outer group (FGC_OUTER_BRANCH at the start of each of its two processes, FGC_OUTER_JOIN
// after both: back_substitute's slot process beside the state update's backsub_retire, the first
// itself holding parallel groups) takes the longer of: the first process (its records as
// span_total prices them), and the second, one pipelined loop whose iterations (a record each)
// issue an II apart, an iteration after the i-th FGC_OUTER_RECEIVE no earlier than the end of
// the first process's records up to its i-th FGC_OUTER_SEND; it ends its depth after its last
// issue - as units/backsub.py's retire_region prices it. A third process (FGC_OUTER_BRANCH
// again: back_substitute's trial_cost) runs pipelined loops one after another, an iteration
// after its k-th FGC_OUTER_ABSORB no earlier than the second's k-th iteration ends
// (units/datapath.py's trial_end); the group ends when the last of the three does. A last
// process with no channel to the others (FGC_OUTER_BESIDE at its start: the on-chip stream's
// spec_tau_task, the one-step update's marginal) runs its records as span_total prices
// them, and the group ends no earlier than it does; further FGC_OUTER_BESIDE marks start
// further such processes (spec_keep_task, the kept conditional staged), each its own span
// from its mark to the next, beside each other: the group ends no earlier than the longest
// (plan/stream.py's _spec_over). Keyed
// marks (FGC_OUTER_SEND_STEP(s) / FGC_OUTER_RECEIVE_STEP(s): back-substitution by columns,
// whose first process is a DATAFLOW region of a loader and two ends run one after the other
// in C simulation) match a receive with the send of the same step, at that send's time on
// its process's own clock (record_ends), not the first process's records up to it.
//
// A span folded into one record (FGC_COLLAPSE_BEGIN ... FGC_COLLAPSE_END(process, instance,
// loop)): a process of a DATAFLOW region that holds regions of its own (a unit set's qr_step as
// a process of lin_level's region) - its records, priced as a parallel group's branch is, are
// replaced by one record (trip 1, depth the span) of the enclosing region, which stays current,
// so the region's rule (its fills, its waits) applies to the process as a whole.
//
// The root step in a wavefront (FGC_WAVE_READY(i) in the fed child's branch after the region
// that finished its passed row i, FGC_WAVE_WAIT(i) in the root's branch before the loop that
// reads it): that loop ends no earlier than its depth after the child's branch reached the mark
// (branch_total; units/qr.py's wave_loops). Inside lin_level (the unit sets' FGC_COLLAPSE
// spans): set 0's span marks READY(i), which its FGC_COLLAPSE_END turns into the region's cycle
// at which row i is final (its start there plus its records up to the mark); set 1's span
// prices its reads against those cycles and FGC_WAVE_WAIT_ON(process, instance, loop)'s (the end
// of that loop of the region: the datapaths' that send the root's own rows), from its own start
// (wave_span; units/qr.py's lin_wave_loops). FGC_WAVE_WAIT_AFTER(i, after): the loop reads the
// value in one iteration, `after` iterations before its last issues (back-substitution's load of
// S as the solving lane's x arrives), so it ends no earlier than after + its depth after the mark.
//
// The HGC beside the elimination (FGC_BESIDE_PRODUCER, FGC_BESIDE_CONSUMER, FGC_BESIDE_END:
// accel.cpp.jinja's linearize_solve, a producer writing a Gram stream beside the elimination
// that reads it) takes the later of the producer's end (its records as span_total prices them,
// or its last instance's Gram if later: the HGC starts only after the datapath's first rows) and
// the consumer's: its records as span_total prices them, except that a pass after
// FGC_BESIDE_GATE(k, depth) (up to the FGC_JOIN that ends it) ends no earlier than `depth`
// after the producer's k-th instance's Gram is complete; the producer reports those times
// (cycles after the region's start) with FGC_BESIDE_READY - as units/cholesky.py's
// beside_cycles prices it.
#ifndef FGC_CYCLES_H
#define FGC_CYCLES_H

#ifdef FGC_COUNT_CYCLES

#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace fgc_cycles {

struct Record {
    long region;  // index of the DATAFLOW region entry, -1 outside any region
    std::string region_name;
    std::string phase;  // the plan phase (FGC_PHASE) the record belongs to
    std::string process;
    int instance;  // unit index (Update unit, CPE), 0 for single processes
    std::string loop;
    long trip, ii, depth;
    // a wait (trip 0): this process's next loop that runs reads the stream of the first loop of
    // (on_process, on_instance) whose name ends with on_loop, so it ends its depth after it
    std::string on_process, on_loop;
    int on_instance;
    long after;  // a wait's cycles from the read to the loop's last issue (FGC_WAIT_AFTER)
    long cycles() const { return trip > 0 ? (trip - 1) * ii + depth : 0; }
};

struct Collapse {
    std::size_t records, marks, beside, gates, ready;
    long region;
    std::string region_name;
};

// The root step in a wavefront inside lin_level (FGC_COLLAPSE spans of its unit sets): the
// cycle of the region at which set 0's passed row i is final (wave_at[i], from its span's
// FGC_WAVE_READY marks) and the cycles FGC_WAVE_WAIT_ON found (wave_ext, keyed -1 - index).
struct WaveTimes {
    std::map<long, long> at;
    std::vector<long> ext;
};

struct State {
    std::vector<Record> records;
    // parallel groups (FGC_BRANCH / FGC_JOIN): (record index, 'b' a branch starts, 'j' the
    // group ends); the processes of an enclosing DATAFLOW region that run side by side
    std::vector<std::pair<std::size_t, char> > marks;
    long regions = 0;
    long current = -1;
    std::string current_name;
    std::string phase;
    std::map<std::string, long> events;
    // the HGC beside the elimination: (record index, 'P' producer, 'C' consumer, 'E' end), the
    // consumer's gates (record index, producer instance, depth) and the producer's instances'
    // ready times (record index, cycles after the region's start)
    std::vector<std::pair<std::size_t, char> > beside;
    std::vector<std::pair<std::size_t, std::pair<long, long> > > gates;
    std::vector<std::pair<std::size_t, long> > ready;
    // keyed outer marks (FGC_OUTER_SEND_STEP / FGC_OUTER_RECEIVE_STEP): mark index -> step
    std::map<std::size_t, long> keys;
    // FGC_WAVE_WAIT_AFTER's marks: mark index -> the loop's iterations after the read
    std::map<std::size_t, long> afters;
    std::vector<Collapse> collapsing;  // the open FGC_COLLAPSE_BEGIN spans
    WaveTimes wave;
};

inline State& state() {
    static State s;
    return s;
}

inline const std::vector<Record>& log() { return state().records; }

inline void reset() { state() = State(); }

inline void region(const char* name) {
    State& s = state();
    s.current = s.regions++;
    s.current_name = name;
}

inline void phase(const char* name) { state().phase = name; }
inline void event(const char* name) { ++state().events[name]; }

inline void branch() { state().marks.push_back(std::make_pair(state().records.size(), 'b')); }
inline void join() { state().marks.push_back(std::make_pair(state().records.size(), 'j')); }
// tasks (FGC_TASK / FGC_TASKS_JOIN): independent processes of one DATAFLOW region with no channel
// between them (the incremental design's marginal beside its kept net), each a span of records
// that may hold parallel groups and regions of its own
inline void task() { state().marks.push_back(std::make_pair(state().records.size(), 'T')); }
inline void tasks_join() { state().marks.push_back(std::make_pair(state().records.size(), 'U')); }
inline void mark(char what) { state().marks.push_back(std::make_pair(state().records.size(), what)); }
inline void keyed_mark(char what, long key) {
    state().keys[state().marks.size()] = key;
    mark(what);
}

// FGC_WAVE_WAIT_AFTER(i, after): FGC_WAVE_WAIT(i) for a loop that reads the mark's value in
// one iteration, `after` iterations (at II 1) before its last issues (back-substitution's load
// of S as the solving lane's x arrives: x_0 read at the last column's first iteration), so it
// ends no earlier than wave_ready(i) + after + its depth (branch_total).
inline void wave_wait_after(long key, long after) {
    state().afters[state().marks.size()] = after;
    keyed_mark('v', key);
}

inline void beside(char what) {
    state().beside.push_back(std::make_pair(state().records.size(), what));
}
inline void gate(long k, long depth) {
    state().gates.push_back(std::make_pair(state().records.size(), std::make_pair(k, depth)));
}
// instance k's Gram of the producer: k II_jac + the datapath's depth + the rows' loop, or STEPS
// iterations of the entries loop after the instance before, whichever is later; complete
// (STEPS - 1) iterations and the entries loop's depth after that (units/cholesky.py's
// beside_ready)
inline void ready_chain(long n, long jac_ii, long jac_depth, long rows, long steps, long ii,
                        long depth) {
    long prev = 0;
    for (long k = 0; k < n; ++k) {
        long start = k * jac_ii + jac_depth + rows;
        if (k > 0 && prev + steps * ii > start) start = prev + steps * ii;
        state().ready.push_back(std::make_pair(state().records.size(), start + (steps - 1) * ii + depth));
        prev = start;
    }
}

inline void sequential() {
    state().current = -1;
    state().current_name.clear();
}

inline long total_range(std::size_t from, std::size_t to);  // below: the plan's arithmetic

// FGC_COLLAPSE_BEGIN ... FGC_COLLAPSE_END (see the top): the span's records priced by
// total_range and replaced by one record of the enclosing region, whose records so stay one
// contiguous run; the marks, keyed marks and beside records made inside it are dropped.

inline std::vector<Collapse>& collapsing() { return state().collapsing; }

inline void collapse_begin() {
    State& s = state();
    collapsing().push_back(Collapse{s.records.size(), s.marks.size(), s.beside.size(),
                                    s.gates.size(), s.ready.size(), s.current, s.current_name});
}

inline bool ends_with(const std::string& text, const std::string& tail);  // below
inline std::vector<long> record_ends(std::size_t from, std::size_t to);  // below: the clocks

// The first record of the region entry whose records end just before `at` (the enclosing
// region of a collapse span), and per record of [that, at) its end (record_ends).
inline std::size_t region_begin(std::size_t at, long region) {
    const std::vector<Record>& r = state().records;
    std::size_t b = at;
    while (b > 0 && r[b - 1].region == region) --b;
    return b;
}

// Where (process, instance)'s clock stands in the enclosing region when the span opened (its
// records there, record_ends: a set's fill and its wait on the datapath loop).
inline long collapse_start(const Collapse& c, const char* process, int instance) {
    if (c.region < 0) return 0;
    const std::size_t b = region_begin(c.records, c.region);
    const std::vector<long> ends = record_ends(b, c.records);
    long start = 0;
    for (std::size_t q = b; q < c.records; ++q)
        if (state().records[q].process == process && state().records[q].instance == instance)
            start = ends[q - b];
    return start;
}

// A collapse span's cycles with the wave's reads (FGC_WAVE_WAIT(i) / FGC_WAVE_WAIT_ON marks
// inside it): total_range's sum, except that the loop after each mark ends no earlier than its
// depth after the region's cycle the mark names (set 0's row i final, wave.at; a datapath loop's
// end, wave.ext), counted from the span's start `start` (units/qr.py's lin_wave_loops).
inline long wave_span(const Collapse& c, std::size_t to, long start) {
    const State& s = state();
    const std::vector<Record>& r = s.records;
    long clock = 0;
    std::size_t at = c.records;
    for (std::size_t mi = c.marks; mi < s.marks.size(); ++mi) {
        const std::pair<std::size_t, char>& m = s.marks[mi];
        if (m.second != 'v' || m.first < at || m.first >= to) continue;
        std::size_t q = m.first;
        while (q < to && r[q].trip <= 0) ++q;  // the read's loop
        if (q >= to) continue;
        clock += total_range(at, q);
        const long key = s.keys.count(mi) ? s.keys.at(mi) : 0;
        long abs = 0;
        if (key >= 0) {
            const auto w = s.wave.at.find(key);
            abs = w != s.wave.at.end() ? w->second : 0;
        } else if (std::size_t(-1 - key) < s.wave.ext.size()) {
            abs = s.wave.ext[std::size_t(-1 - key)];
        }
        const long ready = abs - start + r[q].depth;
        clock += r[q].cycles();
        if (ready > clock) clock = ready;
        at = q + 1;
    }
    return clock + total_range(at, to);
}

// FGC_WAVE_WAIT_ON(process, instance, loop) inside a collapse span: the next loop that runs reads
// the stream that loop of the enclosing region's process writes (the datapaths' bank_root), so
// it ends no earlier than its depth after that loop's end there.
inline void wave_wait_on(const char* process, int instance, const char* loop) {
    State& s = state();
    long abs = 0;
    if (!s.collapsing.empty() && s.collapsing.back().region >= 0) {
        const Collapse& c = s.collapsing.back();
        const std::size_t b = region_begin(c.records, c.region);
        const std::vector<long> ends = record_ends(b, c.records);
        for (std::size_t q = b; q < c.records; ++q) {
            const Record& x = s.records[q];
            if (x.process == process && x.instance == instance && ends_with(x.loop, loop) &&
                x.trip > 0) {
                abs = ends[q - b];
                break;
            }
        }
    }
    s.wave.ext.push_back(abs);
    keyed_mark('v', -long(s.wave.ext.size()));
}

inline void collapse_end(const char* process, int instance, const char* loop) {
    State& s = state();
    const Collapse c = collapsing().back();
    collapsing().pop_back();
    bool waits = false;
    for (std::size_t mi = c.marks; mi < s.marks.size(); ++mi) waits = waits || s.marks[mi].second == 'v';
    const long start = collapse_start(c, process, instance);
    const long span = waits ? wave_span(c, s.records.size(), start)
                            : total_range(c.records, s.records.size());
    // set 0's passed rows: the region's cycle at which each is final (the wave's reads wait)
    for (std::size_t mi = c.marks; mi < s.marks.size(); ++mi)
        if (s.marks[mi].second == 'w' && s.keys.count(mi))
            s.wave.at[s.keys.at(mi)] = start + total_range(c.records, s.marks[mi].first);
    s.records.resize(c.records);
    s.marks.resize(c.marks);
    for (auto k = s.keys.begin(); k != s.keys.end();) {
        if (k->first >= c.marks) k = s.keys.erase(k);
        else ++k;
    }
    s.beside.resize(c.beside);
    s.gates.resize(c.gates);
    s.ready.resize(c.ready);
    s.current = c.region;
    s.current_name = c.region_name;
    s.records.push_back(Record{s.current, s.current_name, s.phase, process, instance, loop, 1, 1,
                               span, "", "", 0, 0});
}

inline void add(const char* process, int instance, const char* loop, long trip, long ii,
                long depth) {
    State& s = state();
    s.records.push_back(Record{s.current, s.current_name, s.phase, process, instance, loop, trip,
                               ii, depth, "", "", 0, 0});
}

inline void wait(const char* process, int instance, const char* on_process, int on_instance,
                 const char* on_loop, long after = 0) {
    State& s = state();
    s.records.push_back(Record{s.current, s.current_name, s.phase, process, instance, "wait", 0,
                               1, 0, on_process, on_loop, on_instance, after});
}

inline bool ends_with(const std::string& text, const std::string& tail) {
    return text.size() >= tail.size() && text.compare(text.size() - tail.size(), tail.size(),
                                                      tail) == 0;
}

inline std::vector<long> record_ends(std::size_t from, std::size_t to);  // below: the clocks

// The plan's arithmetic over records [from, to) of the log: see the comment at the top.
inline long total_range(std::size_t from, std::size_t to) {
    long sum = 0;
    const std::vector<Record>& r = log();
    std::size_t i = from;
    while (i < to) {
        if (r[i].region < 0) {
            sum += r[i].cycles();
            ++i;
            continue;
        }
        // one region entry: per process (name, instance) its cycles and its first loop's depth
        // (fill: the depth of the process's first loop that runs)
        const long id = r[i].region;
        const std::size_t begin = i;
        std::map<std::pair<std::string, int>, std::pair<long, long>> procs;
        std::vector<std::pair<std::string, int>> order;
        for (; i < to && r[i].region == id; ++i) {
            const std::pair<std::string, int> key(r[i].process, r[i].instance);
            if (procs.find(key) == procs.end()) {
                procs[key] = std::make_pair(0L, -1L);
                order.push_back(key);
            }
            procs[key].first += r[i].cycles();
            if (procs[key].second < 0 && r[i].trip > 0) procs[key].second = r[i].depth;
        }
        long slow = 0, fills = 0;
        std::size_t slowest = 0;
        for (std::size_t p = 0; p < order.size(); ++p) {
            if (procs[order[p]].first > slow) {
                slow = procs[order[p]].first;
                slowest = p;
            }
        }
        for (std::size_t p = 0; p < order.size(); ++p)
            if (p != slowest && procs[order[p]].second > 0) fills += procs[order[p]].second;
        long region_cycles = slow + fills;
        // and no earlier than any process's last loop ends on its own clock (record_ends)
        for (const long end : record_ends(begin, i))
            region_cycles = end > region_cycles ? end : region_cycles;
        sum += region_cycles;
    }
    return sum;
}

// The root step in a wavefront (fgc_qr.h's qr_step_io): the fed child's branch marks
// FGC_WAVE_READY(i) when its region that wrote passed row i returns; the root's branch marks
// FGC_WAVE_WAIT(i) before the loop that reads that row. wave_ready: cycles from the fed child's
// FGC_BRANCH to its latest READY(key) before record `before` (its records as total_range prices
// them); 0 if there is none.
inline long wave_ready(long key, std::size_t before) {
    const State& s = state();
    std::size_t at = 0;
    bool found = false;
    for (std::size_t mi = 0; mi < s.marks.size(); ++mi) {
        const std::pair<std::size_t, char>& m = s.marks[mi];
        if (m.second == 'w' && m.first <= before && s.keys.count(mi) && s.keys.at(mi) == key) {
            at = m.first;
            found = true;
        }
    }
    if (!found) return 0;
    std::size_t b = 0;
    for (const auto& m : s.marks)
        if (m.second == 'b' && m.first <= at) b = m.first;
    return total_range(b, at);
}

// One branch of a parallel group, records [from, to): total_range's sum, except that the loop
// after each FGC_WAVE_WAIT(i) ends no earlier than its depth after wave_ready(i) (a stream read
// of the row, as units/qr.py's wave_loops prices it).
inline long branch_total(std::size_t from, std::size_t to) {
    const State& s = state();
    const std::vector<Record>& r = s.records;
    long clock = 0;
    std::size_t at = from;
    for (std::size_t mi = 0; mi < s.marks.size(); ++mi) {
        const std::pair<std::size_t, char>& m = s.marks[mi];
        if (m.second != 'v' || m.first < at || m.first >= to) continue;
        std::size_t q = m.first;
        while (q < to && r[q].trip <= 0) ++q;  // the read's loop
        if (q >= to) continue;
        clock += total_range(at, q);
        const long ready = wave_ready(s.keys.count(mi) ? s.keys.at(mi) : -1, m.first) +
                           (s.afters.count(mi) ? s.afters.at(mi) : 0) + r[q].depth;
        clock += r[q].cycles();
        if (ready > clock) clock = ready;
        at = q + 1;
    }
    return clock + total_range(at, to);
}

// Records [from, to) of the log: sequential stretches add up; a parallel group (branches marked
// by FGC_BRANCH up to FGC_JOIN, e.g. the unit sets of one QR level) takes its slowest branch
// plus the fill (first loop's depth) of each other branch, as plan_cost prices a dataflow phase.
// A branch mark at `from` and a join mark at `to` belong to the span.
inline long span_total(std::size_t from, std::size_t to) {
    const State& s = state();
    const std::vector<Record>& r = s.records;
    long sum = 0, slow = 0, slow_fill = 0, fills = 0;
    std::size_t at = from, start = from;
    bool open = false;
    auto close_branch = [&](std::size_t end) {
        const long c = branch_total(start, end);
        long f = 0;
        for (std::size_t q = start; q < end; ++q) {
            if (r[q].trip > 0) {
                f = r[q].depth;
                break;
            }
        }
        if (c > slow) {
            fills += slow_fill;
            slow = c;
            slow_fill = f;
        } else {
            fills += f;
        }
    };
    for (const auto& m : s.marks) {
        if (m.second != 'b' && m.second != 'j') continue;  // tasks_total's, outer_total's marks
        if (m.second == 'b' ? (m.first < from || m.first >= to) : (m.first <= from || m.first > to))
            continue;
        if (m.second == 'b') {
            if (!open) {
                sum += total_range(at, m.first);
                open = true;
                slow = slow_fill = fills = 0;
            } else {
                close_branch(m.first);
            }
            start = m.first;
        } else if (open) {
            close_branch(m.first);
            sum += slow + fills;
            open = false;
            at = m.first;
        }
    }
    if (open) {  // a group the span ends inside: its branches so far
        close_branch(to);
        return sum + slow + fills;
    }
    return sum + total_range(at, to);
}

// Per record of [from, to) (one DATAFLOW region's records): when it ends on its process's own
// clock (a loop ends its cycles after the one before it, and a loop that waits - FGC_WAIT
// before it: it reads another process's stream as that process's loop writes it - no earlier
// than its depth after the end of that loop, and FGC_WAIT_AFTER's `after` cycles more); a record
// that does not run ends where its process's clock stands. A region (total_range) ends no
// earlier than any of these, and the column design's keyed sends (FGC_OUTER_SEND_STEP) happen at
// these times (units/backsub.py's column_timeline).
inline std::vector<long> record_ends(std::size_t from, std::size_t to) {
    const std::vector<Record>& r = log();
    std::vector<long> ends(to - from, 0);
    std::map<std::pair<std::string, int>, long> clock, pending;
    for (std::size_t q = from; q < to; ++q) {
        const std::pair<std::string, int> key(r[q].process, r[q].instance);
        if (!r[q].on_process.empty()) {
            for (std::size_t x = from; x < q; ++x)
                if (r[x].process == r[q].on_process && r[x].instance == r[q].on_instance &&
                    ends_with(r[x].loop, r[q].on_loop) && r[x].trip > 0) {
                    const long ready = ends[x - from] + r[q].after;
                    if (!pending.count(key) || pending[key] < ready) pending[key] = ready;
                    break;
                }
            ends[q - from] = clock[key];
            continue;
        }
        if (r[q].trip <= 0) {
            ends[q - from] = clock[key];
            continue;
        }
        long end = clock[key] + r[q].cycles();
        if (pending.count(key)) {
            const long waited = pending[key] + r[q].depth;
            end = waited > end ? waited : end;
            pending.erase(key);
        }
        clock[key] = end;
        ends[q - from] = end;
    }
    return ends;
}

// Records [from, to) with their outer groups (FGC_OUTER_*: see the comment at the top); the
// rest priced by span_total. An outer group's first mark at `from` and its join at `to` belong
// to the span.
inline long outer_total(std::size_t from, std::size_t to) {
    const State& s = state();
    long sum = 0;
    std::size_t at = from;
    std::vector<std::size_t> branches, sends, receives, absorbs;
    std::vector<long> send_keys, receive_keys, absorb_keys;  // keyed marks' keys (-1: unkeyed)
    std::size_t beside = to;  // FGC_OUTER_BESIDE: the group's last process, from here (none: to)
    std::vector<std::size_t> beside_at;  // every FGC_OUTER_BESIDE's record index (a process each)
    bool open = false;
    auto close_group = [&](std::size_t group_end) {
        const std::vector<Record>& r = s.records;
        // last processes beside the others (FGC_OUTER_BESIDE: back_substitute's
        // spec_tau_task and spec_keep_task), no channel to them: each its records as
        // span_total prices them
        const bool has_beside = beside < group_end;
        const std::size_t end = has_beside ? beside : group_end;
        long besides = 0;  // the longest of the processes beside (each from its mark to the next)
        for (std::size_t k = 0; k < beside_at.size(); ++k) {
            const std::size_t e = k + 1 < beside_at.size() ? beside_at[k + 1] : group_end;
            const long span = span_total(beside_at[k], e);
            if (span > besides) besides = span;
        }
        const std::size_t a0 = branches[0], b0 = branches.size() > 1 ? branches[1] : end;
        const std::size_t c0 = branches.size() > 2 ? branches[2] : end;
        const std::size_t d0 = branches.size() > 3 ? branches[3] : end;
        const long first = span_total(a0, b0);
        std::vector<long> ends;  // per iteration of the second process: when it ends
        // the second process: one pipelined loop, a record (trip 1) an iteration; each issues
        // its II after the one before, and one after FGC_OUTER_RECEIVE i no earlier than the
        // end of the first process's records up to its i-th FGC_OUTER_SEND
        long issue = 0, last = 0, gate = -1;
        bool any = false;
        std::size_t next = 0;
        std::vector<long> first_ends;  // keyed sends: the first process's records' ends
        for (std::size_t q = b0; q < c0; ++q) {
            for (; next < receives.size() && receives[next] <= q; ++next) {
                if (receive_keys[next] >= 0) {  // the send of the same step, on its clock
                    if (first_ends.empty()) first_ends = record_ends(a0, b0);
                    gate = first;
                    for (std::size_t k = 0; k < sends.size(); ++k)
                        if (send_keys[k] == receive_keys[next] && sends[k] > a0) {
                            gate = first_ends[sends[k] - 1 - a0];
                            break;
                        }
                    continue;
                }
                gate = next < sends.size() ? span_total(a0, sends[next]) : first;
            }
            if (r[q].trip <= 0) continue;
            long at = any ? issue + r[q].ii : 0;
            if (gate > at) at = gate;
            gate = -1;
            issue = at;
            any = true;
            last = at + r[q].depth;
            ends.push_back(last);
        }
        // a third process (back_substitute's trial_cost): pipelined loops one after another
        // (a record an iteration; a loop's first when the one before has drained), an
        // iteration its II after the one before and, after FGC_OUTER_ABSORB's k-th mark, no
        // earlier than the end of the second process's k-th iteration (the word it takes)
        // (keyed, FGC_OUTER_ABSORB_AT(i): no earlier than the second's iteration i ends; a
        // fourth process, FGC_OUTER_BRANCH again - back_substitute's trial_cost_b - the same
        // beside the third)
        auto cost_process = [&](std::size_t lo, std::size_t hi) {
            long free = 0, done = 0, issue3 = 0, gate3 = -1;
            std::size_t taken = 0, absorbed = 0;
            const std::string* loop = nullptr;
            for (std::size_t q = lo; q < hi; ++q) {
                for (; taken < absorbs.size() && absorbs[taken] <= q; ++taken) {
                    if (absorbs[taken] < lo) continue;
                    const long key = absorb_keys[taken];
                    const std::size_t k = key >= 0 ? std::size_t(key) : absorbed++;
                    if (k < ends.size() && ends[k] > gate3) gate3 = ends[k];
                }
                if (r[q].trip <= 0) continue;
                long at = loop && *loop == r[q].loop ? issue3 + r[q].ii : free;
                if (gate3 > at) at = gate3;
                gate3 = -1;
                loop = &r[q].loop;
                issue3 = at;
                free = at + r[q].depth;
                done = free;
            }
            return done;
        };
        const long third = cost_process(c0, d0), fourth = cost_process(d0, end);
        if (third > last) last = third;
        if (fourth > last) last = fourth;
        if (besides > last) last = besides;
        return first > last ? first : last;
    };
    for (std::size_t mi = 0; mi < s.marks.size(); ++mi) {
        const auto& m = s.marks[mi];
        const char w = m.second;
        if (w != 'B' && w != 'S' && w != 'R' && w != 'J' && w != 'A' && w != 'P') continue;
        const long key = s.keys.count(mi) ? s.keys.at(mi) : -1;
        if (w == 'J' ? (m.first <= from || m.first > to) : (m.first < from || m.first >= to))
            continue;
        if (w == 'B') {
            if (!open) {
                sum += span_total(at, m.first);
                open = true;
                branches.clear();
                sends.clear();
                receives.clear();
                absorbs.clear();
                absorb_keys.clear();
                send_keys.clear();
                receive_keys.clear();
                beside = to;
                beside_at.clear();
            }
            branches.push_back(m.first);
        } else if (w == 'P' && open) {
            if (beside_at.empty()) beside = m.first;
            beside_at.push_back(m.first);
        } else if (w == 'S' && open) {
            sends.push_back(m.first);
            send_keys.push_back(key);
        } else if (w == 'R' && open) {
            receives.push_back(m.first);
            receive_keys.push_back(key);
        } else if (w == 'A' && open) {
            absorbs.push_back(m.first);
            absorb_keys.push_back(key);
        } else if (w == 'J' && open) {
            sum += close_group(m.first);
            open = false;
            at = m.first;
        }
    }
    if (open) return sum + close_group(to);
    return sum + span_total(at, to);
}

// Records [from, to) with the HGC beside the elimination (FGC_BESIDE_*: see the comment at the
// top); the rest priced by outer_total.
inline long beside_total(std::size_t from, std::size_t to) {
    const State& s = state();
    std::size_t p = to, c = to, e = to;
    for (const auto& m : s.beside) {
        if (m.first < from || m.first > to) continue;
        if (m.second == 'P' && p == to) p = m.first;
        else if (m.second == 'C' && p < to && c == to) c = m.first;
        else if (m.second == 'E' && c < to && e == to) e = m.first;
    }
    if (p >= to || c >= to) return outer_total(from, to);
    long sum = outer_total(from, p);
    long producer = span_total(p, c);
    std::vector<long> ready;
    for (const auto& r : s.ready) {
        if (r.first < p || r.first > c) continue;
        ready.push_back(r.second);
        if (r.second > producer) producer = r.second;  // its last Gram: no sooner
    }
    long t = 0;
    std::size_t at = c;
    for (const auto& g : s.gates) {
        const std::size_t q = g.first;
        if (q < at || q >= e) continue;
        t += span_total(at, q);
        std::size_t end = e;  // the pass: up to the join that ends it
        for (const auto& m : s.marks)
            if (m.second == 'j' && m.first > q && m.first < end) end = m.first;
        t += span_total(q, end);
        const long k = g.second.first;
        if (k >= 0 && k < static_cast<long>(ready.size()) && ready[k] + g.second.second > t)
            t = ready[k] + g.second.second;
        at = end;
    }
    t += span_total(at, e);
    sum += producer > t ? producer : t;
    return sum + (e < to ? beside_total(e, to) : 0);
}

// Records [from, to) with task groups (FGC_TASK up to FGC_TASKS_JOIN): the stretches between
// groups as beside_total prices them; a group its slowest task (the processes share no channel, so
// the region ends when the slowest one does).
inline long tasks_total(std::size_t from, std::size_t to) {
    const State& s = state();
    long sum = 0, slow = 0;
    std::size_t at = from, start = from;
    bool open = false;
    for (const auto& m : s.marks) {
        if ((m.second != 'T' && m.second != 'U') || m.first < from || m.first > to) continue;
        if (m.second == 'T') {
            if (!open) {
                sum += beside_total(at, m.first);
                open = true;
                slow = 0;
            } else {
                const long c = beside_total(start, m.first);
                slow = c > slow ? c : slow;
            }
            start = m.first;
        } else if (open) {
            const long c = beside_total(start, m.first);
            sum += c > slow ? c : slow;
            open = false;
            at = m.first;
        }
    }
    if (open) {
        const long c = beside_total(start, to);
        return sum + (c > slow ? c : slow);
    }
    return sum + beside_total(at, to);
}

// The whole log.
inline long total() { return tasks_total(0, log().size()); }

// Per phase (FGC_PHASE), the cycles of its records: each run of consecutive records of one
// phase priced as span_total prices it, the runs of a phase added up.
inline std::map<std::string, long> phase_totals() {
    const std::vector<Record>& r = log();
    std::map<std::string, long> out;
    std::size_t i = 0;
    while (i < r.size()) {
        std::size_t j = i;
        while (j < r.size() && r[j].phase == r[i].phase) ++j;
        out[r[i].phase] += beside_total(i, j);
        i = j;
    }
    return out;
}

inline const std::map<std::string, long>& events() { return state().events; }

// One line per record: region, process, instance, loop, trip, II, depth, cycles.
inline void dump(std::FILE* out) {
    for (const Record& x : log())
        std::fprintf(out, "%ld %s %s %d %s %ld %ld %ld %ld\n", x.region,
                     x.region < 0 ? "-" : x.region_name.c_str(), x.process.c_str(), x.instance,
                     x.loop.c_str(), x.trip, x.ii, x.depth, x.cycles());
}

// A region's streams must be empty when it returns: a word left over (or missing, which the
// csim stream reports when read) is a producer/consumer count mismatch, a hang in hardware.
template <class S>
inline void drained(const S* streams, int n, const char* what) {
    for (int i = 0; i < n; ++i) {
        if (!streams[i].empty()) {
            std::fprintf(stderr, "fgc: %s[%d] holds %zu words after its region\n", what, i,
                         streams[i].size());
            std::abort();
        }
    }
}

}  // namespace fgc_cycles

#define FGC_CYCLES(process, instance, loop, trip, ii, depth) \
    ::fgc_cycles::add(process, instance, loop, trip, ii, depth)
#define FGC_REGION(name) ::fgc_cycles::region(name)
#define FGC_SEQUENTIAL() ::fgc_cycles::sequential()
#define FGC_BRANCH() ::fgc_cycles::branch()
#define FGC_JOIN() ::fgc_cycles::join()
#define FGC_TASK() ::fgc_cycles::task()
#define FGC_TASKS_JOIN() ::fgc_cycles::tasks_join()
#define FGC_WAIT(process, instance, on_process, on_instance, on_loop) \
    ::fgc_cycles::wait(process, instance, on_process, on_instance, on_loop)
#define FGC_WAIT_AFTER(process, instance, on_process, on_instance, on_loop, after) \
    ::fgc_cycles::wait(process, instance, on_process, on_instance, on_loop, after)
#define FGC_DRAINED(streams, n) ::fgc_cycles::drained(streams, n, #streams)
#define FGC_COLLAPSE_BEGIN() ::fgc_cycles::collapse_begin()
#define FGC_COLLAPSE_END(process, instance, loop) ::fgc_cycles::collapse_end(process, instance, loop)
#define FGC_OUTER_BRANCH() ::fgc_cycles::mark('B')
#define FGC_OUTER_SEND() ::fgc_cycles::mark('S')
#define FGC_OUTER_RECEIVE() ::fgc_cycles::mark('R')
#define FGC_OUTER_JOIN() ::fgc_cycles::mark('J')
#define FGC_OUTER_BESIDE() ::fgc_cycles::mark('P')
#define FGC_OUTER_ABSORB() ::fgc_cycles::mark('A')
#define FGC_OUTER_ABSORB_AT(i) ::fgc_cycles::keyed_mark('A', i)
#define FGC_OUTER_SEND_STEP(step) ::fgc_cycles::keyed_mark('S', step)
#define FGC_OUTER_RECEIVE_STEP(step) ::fgc_cycles::keyed_mark('R', step)
#define FGC_WAVE_READY(i) ::fgc_cycles::keyed_mark('w', i)
#define FGC_WAVE_WAIT(i) ::fgc_cycles::keyed_mark('v', i)
#define FGC_WAVE_WAIT_AFTER(i, after) ::fgc_cycles::wave_wait_after(i, after)
#define FGC_WAVE_WAIT_ON(process, instance, loop) ::fgc_cycles::wave_wait_on(process, instance, loop)
#define FGC_PHASE(name) ::fgc_cycles::phase(name)
#define FGC_EVENT(name) ::fgc_cycles::event(name)
#define FGC_BESIDE_PRODUCER() ::fgc_cycles::beside('P')
#define FGC_BESIDE_CONSUMER() ::fgc_cycles::beside('C')
#define FGC_BESIDE_END() ::fgc_cycles::beside('E')
#define FGC_BESIDE_GATE(k, depth) ::fgc_cycles::gate(k, depth)
#define FGC_BESIDE_READY(n, jac_ii, jac_depth, rows, steps, ii, depth) \
    ::fgc_cycles::ready_chain(n, jac_ii, jac_depth, rows, steps, ii, depth)

#else

#define FGC_CYCLES(process, instance, loop, trip, ii, depth) ((void)0)
#define FGC_REGION(name) ((void)0)
#define FGC_SEQUENTIAL() ((void)0)
#define FGC_BRANCH() ((void)0)
#define FGC_JOIN() ((void)0)
#define FGC_TASK() ((void)0)
#define FGC_TASKS_JOIN() ((void)0)
#define FGC_WAIT(process, instance, on_process, on_instance, on_loop) ((void)0)
#define FGC_WAIT_AFTER(process, instance, on_process, on_instance, on_loop, after) ((void)0)
#define FGC_DRAINED(streams, n) ((void)0)
#define FGC_COLLAPSE_BEGIN() ((void)0)
#define FGC_COLLAPSE_END(process, instance, loop) ((void)0)
#define FGC_WAVE_READY(i) ((void)0)
#define FGC_WAVE_WAIT(i) ((void)0)
#define FGC_WAVE_WAIT_AFTER(i, after) ((void)0)
#define FGC_WAVE_WAIT_ON(process, instance, loop) ((void)0)
#define FGC_OUTER_BRANCH() ((void)0)
#define FGC_OUTER_SEND() ((void)0)
#define FGC_OUTER_RECEIVE() ((void)0)
#define FGC_OUTER_JOIN() ((void)0)
#define FGC_OUTER_BESIDE() ((void)0)
#define FGC_OUTER_ABSORB() ((void)0)
#define FGC_OUTER_ABSORB_AT(i) ((void)0)
#define FGC_OUTER_SEND_STEP(step) ((void)0)
#define FGC_OUTER_RECEIVE_STEP(step) ((void)0)
#define FGC_PHASE(name) ((void)0)
#define FGC_EVENT(name) ((void)0)
#define FGC_BESIDE_PRODUCER() ((void)0)
#define FGC_BESIDE_CONSUMER() ((void)0)
#define FGC_BESIDE_END() ((void)0)
#define FGC_BESIDE_GATE(k, depth) ((void)0)
#define FGC_BESIDE_READY(n, jac_ii, jac_depth, rows, steps, ii, depth) ((void)0)

#endif  // FGC_COUNT_CYCLES

// Shared helpers of the units (namespace fgc_units), also without FGC_COUNT_CYCLES.
namespace fgc_units {

// ceil(a / b) and ceil(log2 a) for the counters' II and depth (constant expressions, C++14)
constexpr int ceil_div(int a, int b) { return (a + b - 1) / b; }
constexpr int ceil_log2(int a) { return a <= 1 ? 0 : 1 + ceil_log2((a + 1) / 2); }

// A pipelined dot product of `length` terms with `partials` interleaved partial sums (plan.py's
// dot_loop): II = ceil(add latency / k), depth = mul + add * (1 + ceil(log2 k)), k = min(length,
// partials).
inline int dot_ii(int length, int partials, int add_lat) {
    const int k = length < partials ? (length < 1 ? 1 : length) : partials;
    return ceil_div(add_lat, k);
}
inline int dot_depth(int length, int partials, int add_lat, int mul_lat) {
    const int k = length < partials ? (length < 1 ? 1 : length) : partials;
    return mul_lat + add_lat * (1 + ceil_log2(k));
}

// Fold P interleaved partial sums in a binary tree (ceil(log2 P) adds deep), a fixed order; the
// dot products of fgc_qr.h, fgc_cpe.h and fgc_backsub.h end with it.
template <class T, int P>
inline T fold_partials(T part[P]) {
#pragma HLS INLINE
    for (int step = 1; step < P; step *= 2) {
#pragma HLS UNROLL
        for (int i = 0; i < P; i += 2 * step) {
#pragma HLS UNROLL
            if (i + step < P) part[i] += part[i + step];
        }
    }
    return part[0];
}

// Fold P partial maxima in a binary tree (ceil(log2 P) compares deep), a fixed order.
template <class T, int P>
inline T fold_maxima(T part[P]) {
#pragma HLS INLINE
    for (int step = 1; step < P; step *= 2) {
#pragma HLS UNROLL
        for (int i = 0; i < P; i += 2 * step) {
#pragma HLS UNROLL
            if (i + step < P && part[i + step] > part[i]) part[i] = part[i + step];
        }
    }
    return part[0];
}

}  // namespace fgc_units

#endif  // FGC_CYCLES_H
