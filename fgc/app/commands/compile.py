"""``fgc compile SPEC --backend B --out DIR``: the backend's project (HLS: also the on-chip
stream design with --window W / --incremental K)."""

from __future__ import annotations

from pathlib import Path

from fgc.app.commands.options import UsageError, streaming_args
from fgc.app.commands.outputs import print_lines
from fgc.app.commands.steps import (
    EXIT_OK,
    backend_help,
    backend_info,
    backend_names,
    compile_spec,
    filename_note,
    hls_config,
    is_streaming,
    load_backend,
    native_config,
    refuse_hls_design,
)
from fgc.app.commands.stream import stream_setup
from fgc.errors import FgcError
from fgc.ir.datafile import write_data
from fgc_backends.cfamily.results import reference_run

NAME = "compile"
HELP = "emit a backend project for a spec"
FAILS = None  # what exit status 1 means (compile has none)
JSON_HELP = None
HARDWARE = "emitted"  # hardware_args: the HLS design this command builds


def add_arguments(p) -> None:
    streaming_args(p)
    p.add_argument("--backend", choices=backend_names(), default="sim",
                   help="backend: " + backend_help())
    p.add_argument("--out", required=True, metavar="DIR", help="output folder")



def cmd_compile(args) -> int:
    window = getattr(args, "window", None) if is_streaming(args) else None
    if is_streaming(args) and backend_info(args.backend).stream_design:
        return _compile_window(args, window)
    if window is not None:
        raise UsageError("fgc compile: --window is a run-time mode of the simulator and the "
                         "native solver (the same build serves every window); pass it to "
                         "simulate, verify or stream, or compile the on-chip window with "
                         "--backend hls")
    _, program, data = compile_spec(args, "float32")
    out = Path(args.out)
    try:
        out.mkdir(parents=True, exist_ok=True)
        (out / "program.json").write_text(program.to_json())
        write_data(data, out / "data.txt")
        backend = load_backend(args.backend)
        if args.backend == "hls":
            project = backend.emit(program, out, hls_config(args, program))
            files = list(project.files)
            # the testbench checks its result against the simulator's (exit 4 on a mismatch)
            files.append(backend.build.write_project_reference(
                project, program, data, reference_run(program, data)))
        elif args.backend == "native":
            files = list(backend.emit(program, out, native_config(args, program)).files)
        else:
            if getattr(args, "scalar", None) or getattr(args, "part", None):
                raise UsageError("fgc compile: --scalar applies to --backend hls or native "
                                 "only, --part to --backend hls only")
            refuse_hls_design(args, args.backend)
            files = backend.emit(program, out)
    except OSError as exc:
        raise FgcError(f"--out {out}: cannot write the project: "
                       f"{exc.strerror or exc}{filename_note(exc)}") from None
    print_lines(args, [f"fgc compile {args.spec}: {len(program.variables)} variables, "
                  f"{len(program.factors)} block instances → {out}/ ({len(files) + 2} files)"])
    return EXIT_OK


def _compile_window(args, window: int | None) -> int:
    """``fgc compile --backend hls --window W | --incremental K``: the on-chip design (the
    backend's ``emit`` of the StreamProgram: its policy, not a loose window, shapes it)."""
    sp, _ = stream_setup(args, "float32")
    program = sp.program
    out = Path(args.out)
    try:
        # the design first: a stream it cannot run is refused before anything is written
        project = load_backend(args.backend).emit(sp, out, hls_config(args, program))
        (out / "program.json").write_text(program.to_json())
    except OSError as exc:
        raise FgcError(f"--out {out}: cannot write the project: "
                       f"{exc.strerror or exc}{filename_note(exc)}") from None
    what = (f"on-chip fixed-lag window of {window} keyframes" if window is not None else
            f"on-chip incremental design, the newest {program.schedule.incremental.window} "
            "keyframes re-eliminated and the kept Bayes net")
    print_lines(args, [f"fgc compile {args.spec}: {what} "
                  f"({len(program.schedule.clusters)} in the stream), top "
                  f"{project.name}_stream → {out}/ ({len(project.files) + 1} files; make && "
                  f"./tb_{project.name} --stream data.txt stream.txt stream_result.txt)"])
    return EXIT_OK
