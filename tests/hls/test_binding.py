"""The plan's binding rule (backends/hls/plan/binding.py): operator instances per pipelined
loop at its II, capped by the emitted ALLOCATION, once per copy; II from the memories' ports."""

import pytest

from fgc_backends.hls.plan.binding import (
    BoundLoop,
    bound_unit,
    loop_ii,
    loop_operators,
    sum_operators,
)
from fgc_backends.hls.target import Target


def test_instances_per_loop_at_its_ii():
    # fold_partials<11> inside a PIPELINE II=1 loop: 10 adders and a multiplier
    assert loop_operators({"add": 10, "mul": 1}, 1) == {"add": 10, "mul": 1}
    # the same operations at II 4 share: ceil(10 / 4) adders
    assert loop_operators({"add": 10, "mul": 1}, 4) == {"add": 3, "mul": 1}
    # an ALLOCATION caps; every call site / unrolled copy is its own instance
    assert loop_operators({"add": 10, "mul": 6}, 1, {"mul": 2}, copies=3) == {"add": 30, "mul": 6}
    # sequential code: one instance of each kind it uses
    assert loop_operators({"add": 7, "div": 2, "mul": 0}, 0) == {"add": 1, "div": 1}


def test_operator_ii_from_the_table():
    table = Target("xc7z045", 143.0).ops("float32")
    slow = [k for k in ("add", "mul", "div", "sqrt", "special") if table.op(k).ii > 1]
    for kind in slow:
        ii = table.op(kind).ii
        assert loop_operators({kind: 2}, 1, table=table) == {kind: 2 * ii}


def test_unit_is_the_sum_over_its_loops():
    loops = (BoundLoop("a", (("add", 4), ("mul", 4)), 1),
             BoundLoop("b", (("add", 4),), 2, copies=2),
             BoundLoop("c", (("mul", 9),), 3, allocation=(("mul", 1),)))
    assert sum_operators(loops) == (("add", 8), ("mul", 5))
    unit = bound_unit("u", "test", loops, instances=2)
    assert unit.operators == (("add", 8), ("mul", 5)) and unit.instances == 2


def test_port_limited_ii():
    # 651 words written into one unpartitioned array an iteration: II >= 326
    assert loop_ii([(651, 1)]) == 326
    assert loop_ii([(651, 8), (3, 1)]) == 41
    assert loop_ii([]) == 1


def test_bad_arguments():
    with pytest.raises(ValueError):
        loop_operators({"add": 1}, -1)
