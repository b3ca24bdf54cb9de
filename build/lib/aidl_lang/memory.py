"""Python's cyclic garbage collector held off while a stage builds a large acyclic structure:
the parser's AST, the interpreter's model, the solver's rows and tape.

Each of them allocates hundreds of thousands of small objects that reference counting frees,
and the collector's passes over them were a quarter to a half of those stages' time
(docs/performance.md: the parser, "The interpreter", the solver's rows and compile).
"""
from __future__ import annotations

import gc
from contextlib import contextmanager


@contextmanager
def gc_paused():
    """Disable the cyclic garbage collector inside the block (reference counting still frees
    everything acyclic); restores the previous state, also on an exception.  Nested use is
    fine: only the outermost block re-enables it.

    What the block built and kept (a model's rows: tens of thousands of expression nodes) is
    long-lived, so on leaving, the tracked objects are moved straight to the oldest generation
    (``gc.freeze()`` then ``gc.unfreeze()``) instead of being traversed by the next young
    collection and again by a middle one (12-18 ms, and up to ~70 ms, on the 500-structure
    model).  Nothing is kept from the collector: the next full collection sees them all
    (young garbage cycles made elsewhere just before are collected then too, not at the next
    young collection).  Only when the block left at least ``PROMOTE_MIN`` young objects (a
    small compile promotes nothing), and never when someone else holds objects frozen
    (``gc.get_freeze_count()``)."""
    was = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if was:
            if gc.get_count()[0] >= PROMOTE_MIN and not gc.get_freeze_count():
                gc.freeze()
                gc.unfreeze()
            gc.enable()


PROMOTE_MIN = 10_000     # young objects left by a paused block before they are promoted
