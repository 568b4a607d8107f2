// generated from template native.cpp.jinja by fgc 0.1.0 — do not edit
// C entry points of the native build (liblio.so), called through ctypes by
// fgc_backends.native. Allocation-free: a scalar type other than double gets its copies of
// the arrays in static buffers.
#include "lio.h"

namespace {

fgc::T x_in[fgc::N_X];
fgc::T x_out[fgc::N_X];
fgc::T data[fgc::N_DATA];

// The caller's x and factor data in the scalar type, into x_in and data.
void convert_inputs(const double* x, const double* factor_data) {
    for (int i = 0; i < fgc::N_X; ++i) x_in[i] = fgc::T(x[i]);
    for (int i = 0; i < fgc::N_DATA; ++i) data[i] = fgc::T(factor_data[i]);
}

}  // namespace

extern "C" {

// The structure fingerprint this library was compiled for (design 404ca1dd6d239248): the
// caller refuses data of another structure before it reaches the kernel.
const char* fgc_structure() {
    return "d21ec3def9292349";
}

// Set (or with null clear) the function called after each accepted iteration of fgc_run with
// (iteration, cost, damping, relative decrease): fgc's progress display on long solves.
void fgc_set_progress(void (*hook)(int, double, double, double)) {
    fgc::progress_hook = hook;
}

// Sizes the caller's arrays must have: {N_VARIABLES, N_FACTORS, N_X, N_DATA}.
void fgc_sizes(int out[4]) {
    out[0] = fgc::N_VARIABLES;
    out[1] = fgc::N_FACTORS;
    out[2] = fgc::N_X;
    out[3] = fgc::N_DATA;
}

// Run the accelerator on double arrays (converted to the scalar type and back).
void fgc_run(const double* x, const double* factor_data, double* result, double* errors,
             int* info) {
    convert_inputs(x, factor_data);
    fgc::T err[2];
    lio_top(x_in, data, x_out, err, info);
    for (int i = 0; i < fgc::N_X; ++i) result[i] = static_cast<double>(x_out[i]);
    errors[0] = static_cast<double>(err[0]);
    errors[1] = static_cast<double>(err[1]);
}

// The cost at x and its rounding noise (out = {cost, noise}), as the accelerator computes them.
void fgc_probe(const double* x, const double* factor_data, double* out) {
    convert_inputs(x, factor_data);
    fgc::T res[2];
    lio_probe(x_in, data, res);
    out[0] = static_cast<double>(res[0]);
    out[1] = static_cast<double>(res[1]);
}

// The whitened rows [A | b] of every factor instance at x (4821 numbers), block by block.
void fgc_rows(const double* x, const double* factor_data, double* out) {
    convert_inputs(x, factor_data);
    lio_rows(x_in, data, out);
}

}  // extern "C"
