"""Garbage collection around the solver's big builds (docs/performance.md): the compile leaves
no reference cycle behind (its walk used to keep every node tuple alive until a cyclic
collection traversed them), and ``gc_paused`` restores the collector and moves what a big
paused block built to the oldest generation, a small block's to none."""
from __future__ import annotations

import gc

import pytest

from aidl_lang.pipeline import compile_source
from aidl_lang.solver import Solver
from aidl_lang.memory import PROMOTE_MIN, gc_paused
from aidl_lang.solver.tape import Tape
from benchmarks.families import hierarchy


@pytest.mark.parametrize("shared", [False, True])
def test_the_compile_leaves_no_cycle_to_collect(shared):
    c = compile_source(hierarchy(20, seed=1).source, "t.aidl", do_solve=False)
    s = Solver(c.model)
    gc.collect()
    was = gc.isenabled()
    gc.disable()
    try:
        t = Tape(s.rows.exprs, s.rows.n_params, shared=shared)
        found = gc.collect()
    finally:
        if was:
            gc.enable()
    assert t.n_nodes > 1000 and found < 50      # before: every node tuple, ~n_nodes


class _Obj:
    pass


def test_gc_paused_promotes_a_big_block_and_restores_the_collector():
    keep = []
    gc.collect()
    with gc_paused():
        assert not gc.isenabled()
        keep += [_Obj() for _ in range(2 * PROMOTE_MIN)]
    assert gc.isenabled() and gc.get_count()[0] < 100
    gen2 = {id(o) for o in gc.get_objects(generation=2)}
    assert all(id(o) in gen2 for o in keep[:: PROMOTE_MIN // 10])
    small = []
    with gc_paused():
        small += [_Obj() for _ in range(50)]
    young = {id(o) for o in gc.get_objects(generation=0)}
    assert all(id(o) in young for o in small)


def test_gc_paused_restores_a_disabled_collector_and_survives_errors():
    gc.disable()
    try:
        with gc_paused():
            pass
        assert not gc.isenabled()
    finally:
        gc.enable()
    with pytest.raises(ZeroDivisionError):
        with gc_paused():
            1 / 0
    assert gc.isenabled()
