# generated from template run_hls.tcl.jinja by fgc 0.1.0 — do not edit
# Vitis HLS project of lio_top (lio).
#   vitis_hls -f run_hls.tcl            C simulation, synthesis and C/RTL co-simulation
# The testbench reads data.txt (write it with fgc.ir.datafile.write_data), compares its result with
# reference.txt (the simulator's, written beside the data; exit 4 on a mismatch) and writes
# result.txt. No include path is given: Vitis's own ap_fixed.h and hls_stream.h are used (the
# Makefile's C simulation alone adds the stand-ins).
# One clock: 143 MHz, the clock the cost model prices (SolverConfig.clock_mhz).
set cflags "-std=c++14"
open_project -reset lio_prj
set_top lio_top
add_files lio.cpp -cflags $cflags
add_files -tb tb_lio.cpp -cflags $cflags
add_files -tb data.txt
add_files -tb reference.txt
open_solution -reset solution1 -flow_target vivado
set_part {xc7z045ffg900-2}
create_clock -period 6.99301 -name default
csim_design -argv "data.txt result.txt reference.txt"
csynth_design
cosim_design -argv "data.txt result.txt reference.txt"
exit
