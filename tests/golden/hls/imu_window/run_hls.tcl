# generated from template run_hls.tcl.jinja by fgc 0.1.0 — do not edit
# Vitis HLS project of imu_window_top (imu_window).
#   vitis_hls -f run_hls.tcl            C simulation, synthesis, C/RTL co-simulation, and the IP
#                                       exported for Vivado's IP catalog (export_design, under
#                                       imu_window_prj/solution1/impl/; add that folder to
#                                       Vivado's IP repositories)
#   FGC_HLS_STEPS="csim" vitis_hls -f run_hls.tcl      only some steps (any of csim csynth
#                                       cosim export; cosim and export need csynth in the same run)
# The testbench reads data.txt (write it with fgc.ir.datafile.write_data), compares its result with
# reference.txt (the simulator's, written beside the data; exit 4 on a mismatch) and writes
# result.txt. The one include path is include/ (fgc's unit headers: fgc_qr.h, fgc_lm.h, ...);
# Vitis's own ap_fixed.h and hls_stream.h are used (the Makefile's C simulation alone adds the
# stand-ins).
# One clock: 143 MHz, the clock the cost model prices (SolverConfig.clock_mhz).
set cflags "-std=c++14 -Iinclude"
open_project -reset imu_window_prj
set_top imu_window_top
add_files imu_window.cpp -cflags $cflags
add_files -tb tb_imu_window.cpp -cflags $cflags
add_files -tb data.txt
add_files -tb reference.txt
open_solution -reset solution1 -flow_target vivado
set_part {xc7z045ffg900-2}
create_clock -period 6.99301 -name default
if {[info exists ::env(FGC_HLS_STEPS)]} {
  set steps $::env(FGC_HLS_STEPS)
} else {
  set steps "csim csynth cosim export"
}
foreach step $steps {
  if {[lsearch -exact {csim csynth cosim export} $step] < 0} {
    puts stderr "run_hls.tcl: unknown step '$step' in FGC_HLS_STEPS (csim csynth cosim export)"
    exit 2
  }
}
set synthesised [expr {[lsearch -exact $steps csynth] >= 0}]
foreach step {cosim export} {
  if {[lsearch -exact $steps $step] >= 0 && !$synthesised} {
    puts stderr "run_hls.tcl: step '$step' needs csynth in the same run (the project is reset)"
    exit 2
  }
}
if {[lsearch -exact $steps csim] >= 0} {
  csim_design -argv "data.txt result.txt reference.txt"
}
if {$synthesised} {
  csynth_design
}
if {[lsearch -exact $steps cosim] >= 0} {
  cosim_design -argv "data.txt result.txt reference.txt"
}
if {[lsearch -exact $steps export] >= 0} {
  export_design -format ip_catalog -rtl verilog -display_name "fgc imu_window_top"
}
exit
