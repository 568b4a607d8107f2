// generated from template tb.cpp.jinja by fgc 0.1.0 — do not edit
// Testbench of pose_graph_top: reads an fgc data file, runs the accelerator, writes the result.
//
//   tb_pose_graph <data file> <result file>
//
// Exit status: 0 after a run (the result file says whether it converged), 2 on bad arguments or
// a data file that does not fit the compiled structure, 3 if the result cannot be written.
//
// Structure fingerprint aec0bf602da30c22 (design 0d2070957d8ae99f): a data file
// must carry it on its first line, since equal counts do not mean equal factor connectivity. The
// check is host code, here; the kernel reads only numbers.
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "pose_graph.h"

namespace {

using fgc::T;

const char DATA_HEADER[] = "FGCDATA 2";
const char STRUCTURE[] = "aec0bf602da30c22";

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

T x_in[fgc::N_X];
T x_out[fgc::N_X];
T data[fgc::N_DATA];
char line[fgc::MAX_LINE_CHARS];

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
        status = fail(path, n, "expected 'VARIABLES 5'");
    }
    for (int v = 0; v < fgc::N_VARIABLES && status == 0; ++v) {
        const int size = fgc::VAR_X_OFF[v + 1] - fgc::VAR_X_OFF[v];
        if (!next_line(in, &n) || !parse_numbers(size, x_in + fgc::VAR_X_OFF[v])) {
            status = fail(path, n, "malformed variable line (wrong count or numbers)");
        }
    }
    if (status == 0 && (!next_line(in, &n) || !header("FACTORS", fgc::N_FACTORS))) {
        status = fail(path, n, "expected 'FACTORS 7'");
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
    std::fprintf(out, "FGCRESULT 1\nSTATUS %s\nREASON %s\nITERATIONS %d\n", STATUS_NAMES[info[1]],
                 REASON_NAMES[info[2]], info[0]);
    std::fprintf(out, "INITIAL_ERROR %.17g\nFINAL_ERROR %.17g\nVARIABLES %d\n",
                 static_cast<double>(errors[0]), static_cast<double>(errors[1]),
                 fgc::N_VARIABLES);
    for (int v = 0; v < fgc::N_VARIABLES; ++v) {
        std::fprintf(out, "%d", fgc::VAR_X_OFF[v + 1] - fgc::VAR_X_OFF[v]);
        for (int i = fgc::VAR_X_OFF[v]; i < fgc::VAR_X_OFF[v + 1]; ++i) {
            std::fprintf(out, " %.17g", static_cast<double>(x_out[i]));
        }
        std::fprintf(out, "\n");
    }
    return std::fclose(out) == 0 ? 0 : 3;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 3) {
        std::fprintf(stderr, "usage: %s <data file> <result file>\n", argv[0]);
        return 2;
    }
    const int status = read_data(argv[1]);
    if (status != 0) return status;
    T errors[2];
    int info[3];
    pose_graph_top(x_in, data, x_out, errors, info);
    std::printf("pose_graph: %s (%s) after %d iterations, error %.17g -> %.17g\n",
                STATUS_NAMES[info[1]], REASON_NAMES[info[2]], info[0],
                static_cast<double>(errors[0]), static_cast<double>(errors[1]));
    return write_result(argv[2], errors, info);
}
