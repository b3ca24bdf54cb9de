"""Speed where the user waits (issue 104), the server's part, without a browser: what a slider
move's picture costs a compile worker, counted in requests and compiles, never timed.

* A picture's 3D and its checks wait for the worker that drew it (``Pool.take(stick=)``):
  that worker answers them from the drawing it kept; another worker would compile the
  picture again beside the next move's compile.
* A move the server puts back into its ranges (the tool holder's depth after its rows, the
  planetary's sun onto its step) leaves its
  shape checks for ``/api/checks`` as any move does (``checks: "pending"``), and those checks
  are the ones a single request gives.
* The range sweep's worker runs at a lower priority (``SWEEP_NICE``): a planetary's sweep, 5 s
  of CPU asked at each pause, yields the CPU to the next move's compile.
* A compile worker collects its whole heap when quiet, not between a picture and its 3D.
"""
from __future__ import annotations

import threading
from collections import OrderedDict

from aidl_lang.host.workers import Pool
from aidl_lang.studio import compiler, gallery


class Fake:
    """A stand-in worker: Pool.take only lends and takes back."""


def test_a_sticking_request_waits_for_its_worker_while_another_is_idle():
    a, b = Fake(), Fake()
    pool = Pool([a, b])
    assert pool.take(prefer=a) is a                 # a busy (the picture's worker)
    assert pool.take(1.0, prefer=a) is b            # without stick: the idle one
    pool.give(b)
    got, started = [], threading.Event()

    def ask():
        started.set()
        got.append(pool.take(60.0, prefer=a, stick=60.0))
    t = threading.Thread(target=ask)
    t.start()
    started.wait()
    pool.give(a)                                    # a is back: the sticking request has it
    t.join(60)
    assert got == [a]
    assert pool.idle == [b]
    # a worker that is not the pool's: no wait, the idle one
    assert pool.take(1.0, prefer=Fake(), stick=60.0) is b


def test_a_sticking_request_takes_another_worker_after_its_wait():
    a, b = Fake(), Fake()
    pool = Pool([a, b])
    assert pool.take(prefer=a) is a
    assert pool.take(1.0, prefer=a, stick=0.01) is b    # a stayed busy: b, not Busy


def test_a_move_put_back_into_its_ranges_leaves_its_checks_for_later(tmp_path):
    src = gallery.entry("generator/tool_holder").source
    sessions: OrderedDict = OrderedDict()
    first = compiler.view(sessions, "s", str(tmp_path), src, {}, {}, True)
    assert first["ok"]
    # 4 rows of 16 mm holes need 4 x 20 + 2 x 3 + 0.5 mm: the depth (70 mm) follows them
    moved = compiler.view(sessions, "s", str(tmp_path), src, {"rows": "4"}, {}, True)
    assert moved["ok"] and moved["clamped"] == {"depth": 86.5}
    assert moved["checks"] == "pending"
    assert moved["values"] == {"rows": "4", "depth": "86.5 mm"}
    later = compiler.checks(sessions, "s", str(tmp_path), src, moved["values"])
    assert later["ok"] and later["values"] == moved["values"]
    once = compiler.view(OrderedDict(), "t", str(tmp_path), src, {"rows": "4"}, {}, False)
    assert once["clamped"] == {"depth": 86.5} and "checks" not in once
    assert sorted(d["code"] for d in later["diagnostics"]) == \
        sorted(d["code"] for d in once["diagnostics"])


def _niceness_handler():
    import os
    return lambda request: os.nice(0)


def test_a_sweep_worker_runs_at_a_lower_priority_than_the_compile_workers():
    import os

    from aidl_lang.host.workers import Worker
    from aidl_lang.studio.app import SWEEP_NICE
    assert SWEEP_NICE > 0
    here = os.nice(0)
    background, foreground = Worker(_niceness_handler, nice=SWEEP_NICE), Worker(_niceness_handler)
    try:
        assert foreground.request("niceness", 60) == here
        assert background.request("niceness", 60) == min(19, here + SWEEP_NICE)
    finally:
        background.stop()
        foreground.stop()


def test_the_whole_heap_is_collected_when_the_worker_is_quiet():
    """A compile worker collects the whole heap (0.3-0.5 s after a planetary) when no request
    came right after its answer (``quiet``), not between a picture and its 3D; never more
    than WHOLE_LATEST rhythms late.  Counted by the collector's own callbacks."""
    import gc

    from aidl_lang.studio.compiler import WHOLE_LATEST, collect_garbage
    was, normal = gc.isenabled(), gc.get_threshold()
    full = []

    def seen(phase, info):
        if phase == "stop" and info["generation"] == 2:
            full.append(1)
    gc.disable()                    # only the collections asked for
    gc.collect()
    gc.callbacks.append(seen)
    try:
        rhythm = (700, 10, 4)
        for _ in range(5):          # after each answer: the young objects only
            collect_garbage(rhythm)
        assert full == []
        collect_garbage(rhythm, whole=True)     # quiet, its rhythm reached: the whole heap
        assert len(full) == 1
        for _ in range(4 * WHOLE_LATEST):       # never quiet: at WHOLE_LATEST rhythms
            collect_garbage(rhythm)
        assert len(full) == 2
    finally:
        gc.callbacks.remove(seen)
        gc.set_threshold(*normal)
        if was:
            gc.enable()
