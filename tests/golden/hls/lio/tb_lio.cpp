// generated from template tb.cpp.jinja by fgc 0.1.0 — do not edit
// Testbench of lio_top: reads an fgc data file, runs the accelerator, writes the result and
// checks it against the reference fgc wrote beside the data (the simulator's float64 run).
//
//   tb_lio <data file> <result file> [<reference file>]
//
// Exit status: 0 after a run that matches the reference (the result file says whether it
// converged), or after any run when the reference file is absent (it says so); 2 on bad
// arguments, a data or reference file that does not fit the compiled structure; 3 if the result
// cannot be written; 4 if the result differs from the reference (the worst entry is printed).
//
// Tolerances (T = float, linear solver float):
// - float: against the float64 optimum, each rotation (Rot2/Pose2 cos-sin, Rot3/Pose3 matrix)
//   within 1e-3 rad (angle of R_ref^T R), every other entry (positions in m, velocities,
//   biases) within 1e-2 absolute (1 cm), and the final error within 1e-2 x
//   max(1, reference error) + 10.0 x the reference's ERROR_FLOOR (what rounding the
//   float64 optimum to float adds to its cost: a float state cannot rest exactly at the
//   float64 optimum). The status is printed, not compared (float may stop on another criterion).
//
// Structure fingerprint d21ec3def9292349 (design 404ca1dd6d239248): a data file
// must carry it on its first line, since equal counts do not mean equal factor connectivity. The
// check is host code, here; the kernel reads only numbers.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "lio.h"

namespace {

using fgc::T;

const char DATA_HEADER[] = "FGCDATA 2";
const char STRUCTURE[] = "d21ec3def9292349";

const char* const STATUS_NAMES[fgc::N_STATUSES] = {
    "converged",
    "max_iterations",
    "failed",
};
const char* const REASON_NAMES[fgc::N_REASONS] = {
    "gradient",
    "step",
    "predicted_decrease",
    "absolute_error",
    "relative_decrease",
    "max_iterations",
    "non_finite",
    "singular",
    "cost_increased",
    "lambda_limit",
};

// each variable's key token (fgc_backends.cfamily.names.key_tokens: integer keys as digits, other
// keys sanitised) and where its rotation is stored: kind 0 none, 2 cos-sin, 3 a 3x3 matrix
const char* const KEY_TOKENS[fgc::N_VARIABLES] = {
    "x0",
    "v0",
    "b0",
    "x1",
    "v1",
    "b1",
    "x2",
    "v2",
    "b2",
    "x3",
    "v3",
    "b3",
    "x4",
    "v4",
    "b4",
    "x5",
    "v5",
    "b5",
    "x6",
    "v6",
    "b6",
    "x7",
    "v7",
    "b7",
};
const int ROT_KIND[fgc::N_VARIABLES] = {
3, 0, 0, 3, 0, 0, 3, 0, 0, 3, 0, 0, 3, 0, 0, 3,
0, 0, 3, 0, 0, 3, 0, 0,
};
const int ROT_OFF[fgc::N_VARIABLES] = {
0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
0, 0, 0, 0, 0, 0, 0, 0,
};
const char REFERENCE_HEADER[] = "FGCREFERENCE 2";
const bool DOUBLE_TOLERANCE = false;
const double TOL_REL = 1e-9;
const double TOL_ROT = 1e-3;
const double TOL_VEC = 1e-2;
const double TOL_ERROR = 1e-2;
const double ERROR_FLOOR_FACTOR = 10.0;

T x_in[fgc::N_X];
T x_out[fgc::N_X];
T data[fgc::N_DATA];
char line[fgc::MAX_LINE_CHARS];
double x_ref[fgc::N_X];

int fail(const char* path, int line_number, const char* what) {
    std::fprintf(stderr, "%s:%d: %s\n", path, line_number, what);
    return 2;
}

// Read one line into `line`; false at end of file or if the line is longer than the buffer.
bool next_line(std::FILE* in, int* line_number) {
    ++*line_number;
    if (!std::fgets(line, sizeof line, in)) return false;
    return std::strchr(line, '\n') != nullptr || std::feof(in);
}

// Parse "<count> v1 v2 …" into out[0 … expected) (numbers as written by Python's repr).
bool parse_numbers(int expected, T* out) {
    char* pos = line;
    char* end = nullptr;
    const long count = std::strtol(pos, &end, 10);
    if (end == pos || count != expected) return false;
    for (int i = 0; i < expected; ++i) {
        pos = end;
        const double value = std::strtod(pos, &end);
        if (end == pos) return false;
        out[i] = T(value);
    }
    pos = end;
    while (*pos == ' ' || *pos == '\t' || *pos == '\r' || *pos == '\n') ++pos;
    return *pos == '\0';
}

bool header(const char* name, int expected) {
    char word[32];
    int count = -1;
    return std::sscanf(line, "%31s %d", word, &count) == 2 && std::strcmp(word, name) == 0 &&
           count == expected;
}

// The first line: the magic words, then the structure fingerprint this testbench was compiled
// for (a mismatch names both fingerprints).
int check_header(const char* path) {
    char magic[16];
    char version[16];
    char structure[64];
    const int fields = std::sscanf(line, "%15s %15s %63s", magic, version, structure);
    char words[40];
    std::snprintf(words, sizeof words, "%s %s", magic, version);
    if (fields < 2 || std::strcmp(words, DATA_HEADER) != 0) {
        return fail(path, 1, "not an fgc data file (expected 'FGCDATA 2 <fingerprint>')");
    }
    if (fields != 3 || std::strcmp(structure, STRUCTURE) != 0) {
        std::fprintf(stderr, "%s:1: the data file is for another structure: structure "
                     "fingerprint %s, this testbench was compiled for %s\n", path,
                     fields == 3 ? structure : "(none)", STRUCTURE);
        return 2;
    }
    return 0;
}

int read_data(const char* path) {
    std::FILE* in = std::fopen(path, "r");
    if (!in) return fail(path, 0, "cannot open the data file");
    int n = 0;
    int status = 0;
    if (!next_line(in, &n)) {
        status = fail(path, n, "not an fgc data file");
    } else {
        status = check_header(path);
    }
    if (status == 0 && (!next_line(in, &n) || !header("VARIABLES", fgc::N_VARIABLES))) {
        status = fail(path, n, "expected 'VARIABLES 24'");
    }
    for (int v = 0; v < fgc::N_VARIABLES && status == 0; ++v) {
        const int size = fgc::VAR_X_OFF[v + 1] - fgc::VAR_X_OFF[v];
        if (!next_line(in, &n) || !parse_numbers(size, x_in + fgc::VAR_X_OFF[v])) {
            status = fail(path, n, "malformed variable line (wrong count or numbers)");
        }
    }
    if (status == 0 && (!next_line(in, &n) || !header("FACTORS", fgc::N_FACTORS))) {
        status = fail(path, n, "expected 'FACTORS 18'");
    }
    for (int f = 0; f < fgc::N_FACTORS && status == 0; ++f) {
        const int size = fgc::FACTOR_DATA_OFF[f + 1] - fgc::FACTOR_DATA_OFF[f];
        if (!next_line(in, &n) || !parse_numbers(size, data + fgc::FACTOR_DATA_OFF[f])) {
            status = fail(path, n, "malformed factor line (wrong count or numbers)");
        }
    }
    std::fclose(in);
    return status;
}

int write_result(const char* path, const T errors[2], const int info[3]) {
    std::FILE* out = std::fopen(path, "w");
    if (!out) return 3;
    std::fprintf(out, "FGCRESULT 2\nSTATUS %s\nREASON %s\nITERATIONS %d\n", STATUS_NAMES[info[1]],
                 REASON_NAMES[info[2]], info[0]);
    std::fprintf(out, "INITIAL_ERROR %.17g\nFINAL_ERROR %.17g\nVARIABLES %d\n",
                 static_cast<double>(errors[0]), static_cast<double>(errors[1]),
                 fgc::N_VARIABLES);
    for (int v = 0; v < fgc::N_VARIABLES; ++v) {
        std::fprintf(out, "%s %d", KEY_TOKENS[v], fgc::VAR_X_OFF[v + 1] - fgc::VAR_X_OFF[v]);
        for (int i = fgc::VAR_X_OFF[v]; i < fgc::VAR_X_OFF[v + 1]; ++i) {
            std::fprintf(out, " %.17g", static_cast<double>(x_out[i]));
        }
        std::fprintf(out, "\n");
    }
    return std::fclose(out) == 0 ? 0 : 3;
}

// Parse "<word> <count> v1 v2 …" (a keyed line) into out[0 … expected); false unless the word
// is `token` and the count and numbers are right.
bool parse_keyed(const char* token, int expected, double* out) {
    const std::size_t length = std::strlen(token);
    if (std::strncmp(line, token, length) != 0 || line[length] != ' ') return false;
    char* pos = line + length;
    char* end = nullptr;
    const long count = std::strtol(pos, &end, 10);
    if (end == pos || count != expected) return false;
    for (int i = 0; i < expected; ++i) {
        pos = end;
        out[i] = std::strtod(pos, &end);
        if (end == pos) return false;
    }
    pos = end;
    while (*pos == ' ' || *pos == '\t' || *pos == '\r' || *pos == '\n') ++pos;
    return *pos == '\0';
}

// The reference: -1 if the file does not exist, 0 once read, 2 if it is malformed or for another
// structure (the message names the file and line).
int read_reference(const char* path, int* ref_status, double* ref_error, double* ref_floor) {
    std::FILE* in = std::fopen(path, "r");
    if (!in) return -1;
    int n = 0;
    int status = 0;
    char magic[32];
    char version[16];
    char structure[64];
    char words[48];
    if (!next_line(in, &n) ||
        std::sscanf(line, "%31s %15s %63s", magic, version, structure) != 3 ||
        std::snprintf(words, sizeof words, "%s %s", magic, version) < 0 ||
        std::strcmp(words, REFERENCE_HEADER) != 0 || std::strcmp(structure, STRUCTURE) != 0) {
        status = fail(path, n, "not a reference file of this structure (expected "
                      "'FGCREFERENCE 2 d21ec3def9292349')");
    }
    char word[32];
    *ref_status = -1;
    if (status == 0 && next_line(in, &n) && std::sscanf(line, "STATUS %31s", word) == 1) {
        for (int s = 0; s < fgc::N_STATUSES; ++s) {
            if (std::strcmp(word, STATUS_NAMES[s]) == 0) *ref_status = s;
        }
    }
    if (status == 0 && *ref_status < 0) status = fail(path, n, "expected 'STATUS <status>'");
    if (status == 0 && (!next_line(in, &n) || std::strncmp(line, "FINAL_ERROR ", 12) != 0)) {
        status = fail(path, n, "expected 'FINAL_ERROR <error>'");
    }
    if (status == 0) *ref_error = std::strtod(line + 12, nullptr);
    if (status == 0 && (!next_line(in, &n) || std::strncmp(line, "ERROR_FLOOR ", 12) != 0)) {
        status = fail(path, n, "expected 'ERROR_FLOOR <error>'");
    }
    if (status == 0) {
        char* end = nullptr;
        *ref_floor = std::strtod(line + 12, &end);
        if (end == line + 12 || !(*ref_floor >= 0) || std::isinf(*ref_floor)) {
            status = fail(path, n, "expected 'ERROR_FLOOR <error>', a finite number >= 0");
        }
    }
    if (status == 0 && (!next_line(in, &n) || !header("VARIABLES", fgc::N_VARIABLES))) {
        status = fail(path, n, "expected 'VARIABLES 24'");
    }
    for (int v = 0; v < fgc::N_VARIABLES && status == 0; ++v) {
        const int size = fgc::VAR_X_OFF[v + 1] - fgc::VAR_X_OFF[v];
        if (!next_line(in, &n) || !parse_keyed(KEY_TOKENS[v], size, x_ref + fgc::VAR_X_OFF[v])) {
            std::fprintf(stderr, "%s:%d: expected '%s %d <numbers>'\n", path, n, KEY_TOKENS[v],
                         size);
            status = 2;
        }
    }
    std::fclose(in);
    return status;
}

// Angle between the reference rotation and ours (kind 2: cos-sin at off, 3: row-major 3x3).
// A 3x3 angle comes from the chordal distance |R - R_ref|_F = 2 sqrt(2) sin(angle / 2), not from
// acos((trace(R_ref^T R) - 1) / 2): near angle 0 acos turns a float matrix's orthonormality
// rounding e (|R^T R - I| ~ 1e-7 after a few float retractions, 1.4e-6 after 84) into an angle
// of about sqrt(e) (0.4 and 1 mrad where the rotations agree to 1e-7 and 0.27 mrad); the chord
// moves by about e, and a matrix that is no rotation at all still reads far off.
double rotation_angle(int kind, int off) {
    if (kind == 2) {
        const double c = static_cast<double>(x_out[off]);
        const double s = static_cast<double>(x_out[off + 1]);
        return std::fabs(std::atan2(x_ref[off] * s - x_ref[off + 1] * c,
                                    x_ref[off] * c + x_ref[off + 1] * s));
    }
    double chord = 0;  // |R - R_ref|_F^2
    for (int i = 0; i < 9; ++i) {
        const double d = static_cast<double>(x_out[off + i]) - x_ref[off + i];
        chord += d * d;
    }
    const double half = std::sqrt(chord / 8);  // sin(angle / 2); NaN stays NaN
    return 2 * std::asin(half > 1 ? 1 : half);
}

// 0 if x_out, errors and info match the reference within the tolerances; else prints the worst
// entry (as a multiple of its tolerance) and returns 4.
int compare(int ref_status, double ref_error, double ref_floor, const T errors[2],
            const int info[3]) {
    double worst = 0;  // |difference| / tolerance of the worst entry
    int worst_v = -1;
    int worst_i = -1;
    double worst_diff = 0;
    for (int v = 0; v < fgc::N_VARIABLES; ++v) {
        const int lo = fgc::VAR_X_OFF[v];
        const int hi = fgc::VAR_X_OFF[v + 1];
        double scale = 1;
        for (int i = lo; i < hi; ++i) scale = std::fmax(scale, std::fabs(x_ref[i]));
        const int rot_lo = ROT_KIND[v] == 0 ? hi : lo + ROT_OFF[v];
        const int rot_hi = ROT_KIND[v] == 0 ? hi : rot_lo + (ROT_KIND[v] == 2 ? 2 : 9);
        for (int i = lo; i < hi; ++i) {
            const double diff = std::fabs(static_cast<double>(x_out[i]) - x_ref[i]);
            const bool rotation = !DOUBLE_TOLERANCE && i >= rot_lo && i < rot_hi;
            const double tol = DOUBLE_TOLERANCE ? TOL_REL * scale : TOL_VEC;
            const double ratio = rotation ? 0 : (std::isnan(diff) ? HUGE_VAL : diff / tol);
            if (ratio > worst) {
                worst = ratio;
                worst_v = v;
                worst_i = i - lo;
                worst_diff = diff;
            }
        }
        if (!DOUBLE_TOLERANCE && ROT_KIND[v] != 0) {
            const double angle = rotation_angle(ROT_KIND[v], rot_lo);
            const double ratio = std::isnan(angle) ? HUGE_VAL : angle / TOL_ROT;
            if (ratio > worst) {
                worst = ratio;
                worst_v = v;
                worst_i = -1;
                worst_diff = angle;
            }
        }
    }
    int status = 0;
    if (worst > 1) {
        if (worst_i < 0) {
            std::fprintf(stderr, "MISMATCH: variable %s: rotation differs from the reference by "
                         "%.3g rad (tolerance %.3g)\n", KEY_TOKENS[worst_v], worst_diff, TOL_ROT);
        } else {
            const int i = fgc::VAR_X_OFF[worst_v] + worst_i;
            std::fprintf(stderr, "MISMATCH: variable %s entry %d: %.17g, reference %.17g "
                         "(difference %.3g, %.3g x its tolerance)\n", KEY_TOKENS[worst_v],
                         worst_i, static_cast<double>(x_out[i]), x_ref[i], worst_diff, worst);
        }
        status = 4;
    }
    const double error = static_cast<double>(errors[1]);
    const double error_tol = (DOUBLE_TOLERANCE ? TOL_REL : TOL_ERROR) * std::fmax(1, std::fabs(ref_error))
                             + (DOUBLE_TOLERANCE ? 0 : ERROR_FLOOR_FACTOR * ref_floor);
    if (!std::isnan(ref_error) && !(std::fabs(error - ref_error) <= error_tol)) {
        std::fprintf(stderr, "MISMATCH: final error %.17g, reference %.17g (tolerance %.3g)\n",
                     error, ref_error, error_tol);
        status = 4;
    }
    if (DOUBLE_TOLERANCE && info[1] != ref_status) {
        std::fprintf(stderr, "MISMATCH: status %s, reference %s\n", STATUS_NAMES[info[1]],
                     STATUS_NAMES[ref_status]);
        status = 4;
    }
    if (status == 0) {
        std::printf("lio: matches the reference (worst entry %.3g x its tolerance)\n",
                    worst);
    }
    return status;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3 && argc != 4) {
        std::fprintf(stderr, "usage: %s <data file> <result file> [<reference file>]\n",
                     argv[0]);
        return 2;
    }
    const int status = read_data(argv[1]);
    if (status != 0) return status;
    int ref_status = -1;
    double ref_error = 0, ref_floor = 0;
    const int reference = argc == 4 ? read_reference(argv[3], &ref_status, &ref_error, &ref_floor)
                                    : -1;
    if (reference > 0) return reference;
    T errors[2];
    int info[3];
    lio_top(x_in, data, x_out, errors, info);
    std::printf("lio: %s (%s) after %d iterations, error %.17g -> %.17g\n",
                STATUS_NAMES[info[1]], REASON_NAMES[info[2]], info[0],
                static_cast<double>(errors[0]), static_cast<double>(errors[1]));
    const int written = write_result(argv[2], errors, info);
    if (written != 0) return written;
    if (reference < 0) {
        std::printf("lio: no reference file%s%s: the result is not checked\n",
                    argc == 4 ? " " : "", argc == 4 ? argv[3] : "");
        return 0;
    }
    return compare(ref_status, ref_error, ref_floor, errors, info);
}
