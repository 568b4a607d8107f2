"""Shared set-ups of the on-chip stream tests: the tangent-space distance of each update's
estimate from the simulator's, and paper A's small one-step window (LIO N = 7, K = 3, a batch
step at keyframe 4, double) run through the simulator and one design's C simulation."""

from __future__ import annotations

import numpy as np

from fgc.app.specs import example
from fgc.app.streaming import compile_stream, keyframe_result, one_step_solver, run_stream
from fgc.ir.datafile import problem_data
from fgc_backends.hls.streaming import OnChipIncrementalStream


def keyframe_distances(program, records, sim_updates) -> list[float]:
    """Per update record of a C simulation (``records``), the largest tangent-space distance of
    its variables from the simulator's update of the same keyframe; the two must be the same
    update (keyframe, mode, first keyframe) with the same variables."""
    out = []
    for record, expected in zip(records, sim_updates, strict=True):
        update = keyframe_result(program, record)
        assert (update.keyframe, update.mode, update.first) == (
            expected.keyframe, expected.mode, expected.first)
        assert set(update.values) == set(expected.values)
        out.append(max(float(np.linalg.norm(expected.values[k].local(v)))
                       for k, v in update.values.items()))
    assert len(out) == len(sim_updates)
    return out


def lio7_one_step(out_dir, name: str, design=None):
    """LIO N = 7, K = 3, one Gauss-Newton step an update, a batch step at keyframe 4: (graph,
    program, data, the simulator's updates, the double on-chip stream (``design``: its
    DesignOptions, default none), its C simulation's result)."""
    graph = example("lio").build(N=7)
    program = compile_stream(graph, one_step_solver(), incremental=3, batch_every=(4,),
                             name=name)
    data = problem_data(graph, program)
    sim = []
    run_stream(program, data, None, sim.append)
    kwargs = {} if design is None else {"design": design}
    stream = OnChipIncrementalStream(graph, program, "double", out_dir=out_dir, **kwargs)
    return graph, program, data, sim, stream, stream.run(data)
