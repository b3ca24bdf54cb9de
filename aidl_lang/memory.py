"""Python's cyclic garbage collector held off while a stage builds a large acyclic structure:
the parser's AST, the interpreter's model, the solver's rows and tape.

Each of them allocates hundreds of thousands of small objects that reference counting frees,
and the collector's passes over them were a quarter to a half of those stages' time
(docs/dev/performance.md: the parser, "The interpreter", the solver's rows and compile).
"""
from __future__ import annotations

import gc
from contextlib import contextmanager


@contextmanager
def gc_paused():
    """Disable the cyclic garbage collector inside the block (reference counting still frees
    everything acyclic); restores the previous state, also on an exception.  Nested use is
    fine: only the outermost block re-enables it.

    The objects the block built are left to the collector's usual generations.  Moving them
    straight to the oldest generation on leaving (``gc.freeze()`` then ``gc.unfreeze()``, a
    trick that saved 12-18 ms on the 500-structure model) hid them from the count that starts
    a full collection: in a process that compiles again and again (the fuzzer, the language
    server, ``aidl serve``, a batch worker) no full collection ran, so each compile's cyclic
    garbage (a model's structures point at their parents) and the arrays it holds stayed:
    1.5 GB after 224 fuzz programs, then ``SystemError`` from C code out of memory; 0.27 GB
    without the trick (tests/test_memory.py)."""
    was = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if was:
            gc.enable()
