"""Garbage collection around the solver's big builds (docs/dev/performance.md): the compile leaves
no reference cycle behind (its walk used to keep every node tuple alive until a cyclic
collection traversed them), ``gc_paused`` restores the collector, and a process that compiles
again and again does not pile up dead models."""
from __future__ import annotations

import gc

import pytest

from aidl_lang.pipeline import compile_source
from aidl_lang.solver import Solver
from aidl_lang.base.memory import gc_paused
from aidl_lang.solver.core.tape import Tape
from benchmarks.solver.families import hierarchy


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
    # before: every node tuple, ~n_nodes.  Not a fixed 50: another thread of the test
    # worker (a server an earlier test started) may leave its own garbage meanwhile (66 once)
    assert t.n_nodes > 1000 and found < t.n_nodes / 10


class _Obj:
    pass


def test_repeated_compiles_do_not_pile_up_dead_models():
    """A compile's model is cyclic garbage once dropped (structures point at their parents)
    and waits for a full collection.  ``gc_paused`` moved everything a big compile built
    straight to the oldest generation, which hid it from the count that starts a full
    collection: compiling again and again (the fuzzer, the language server, ``aidl serve``)
    kept every dead model and its arrays (1.5 GB after 224 fuzz programs, then
    ``SystemError`` from C code out of memory): 40 models alive after 40 compiles.  Now the
    collector's own full collections take them (about 10-17 alive, as the heuristic goes)."""
    from aidl_lang.geometry.core.model import Structure
    src = hierarchy(120, seed=3).source
    gc.collect()
    # what earlier tests of this worker keep (their cached compiles: 3,337 alive once, in a
    # worker that ran the gear laws first) is not this loop's: only new structures count
    before = {id(o) for o in gc.get_objects() if isinstance(o, Structure)}
    # and the collector's own rhythm (CPython's thresholds), whatever an earlier test left set
    was = gc.get_threshold()
    gc.set_threshold(700, 10, 10)
    try:
        for _ in range(40):
            c = compile_source(src, "t.aidl", do_solve=False)
    finally:
        gc.set_threshold(*was)
    def count(s):
        return 1 + sum(count(k) for k in s.children.values())
    per_model = count(c.model.root)
    alive = sum(1 for o in gc.get_objects() if isinstance(o, Structure) and id(o) not in before)
    assert per_model > 100 and alive < 25 * per_model, (alive, per_model)


class _Obj:
    pass


def test_gc_paused_disables_the_collector_and_leaves_objects_young():
    gc.collect()
    with gc_paused():
        assert not gc.isenabled()
        small = [_Obj() for _ in range(50)]
    assert gc.isenabled()
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
