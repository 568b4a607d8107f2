// fgc's stand-in for Vitis HLS's <hls_stream.h>, for C simulation with the host compiler only.
//
// Vitis HLS brings its own hls_stream.h; an emitted project puts this folder on the include path
// in its Makefile (make csim) and never in run_hls.tcl, so synthesis and cosim see Xilinx's header
// and the kernel code is the same text in both. It implements the part of hls::stream's interface
// (UG1399, "HLS Stream Library") that fgc's kernels use, with the C-simulation semantics Vitis
// documents: a stream is an unbounded FIFO in software (processes of a DATAFLOW region run one
// after another), and reading an empty stream is an error. Here that error stops the program with
// the stream's name, since in hardware the reader would block for ever.
//
// It also records what a declared depth cannot show in a sequential simulation: how many words a
// stream held at most (max_size()) and how many passed through it (writes()), which the cycle
// counting testbench reads.
#ifndef FGC_CSIM_HLS_STREAM_H
#define FGC_CSIM_HLS_STREAM_H

#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <string>

namespace hls {

template <typename T, int DEPTH = 2>
class stream {
public:
    stream() : name_("stream") {}
    explicit stream(const char* name) : name_(name) {}
    stream(const stream&) = delete;
    stream& operator=(const stream&) = delete;

    void write(const T& value) {
        fifo_.push_back(value);
        ++writes_;
        if (fifo_.size() > max_size_) max_size_ = fifo_.size();
    }
    void operator<<(const T& value) { write(value); }

    T read() {
        if (fifo_.empty()) {
            std::fprintf(stderr, "hls::stream '%s' read while empty: the design would stall\n",
                         name_.c_str());
            std::abort();
        }
        T value = fifo_.front();
        fifo_.pop_front();
        return value;
    }
    void read(T& value) { value = read(); }
    void operator>>(T& value) { value = read(); }

    bool read_nb(T& value) {
        if (fifo_.empty()) return false;
        value = read();
        return true;
    }
    bool write_nb(const T& value) {
        write(value);
        return true;
    }

    bool empty() const { return fifo_.empty(); }
    bool full() const { return false; }
    std::size_t size() const { return fifo_.size(); }

    // csim only: the most words the stream held at once, and how many were written in all
    std::size_t max_size() const { return max_size_; }
    std::size_t writes() const { return writes_; }
    const char* name() const { return name_.c_str(); }

private:
    std::deque<T> fifo_;
    std::string name_;
    std::size_t max_size_ = 0;
    std::size_t writes_ = 0;
};

}  // namespace hls

#endif  // FGC_CSIM_HLS_STREAM_H
