"""What the hierarchical solve (:mod:`.hierarchy`) tried and where it failed: one
:class:`Attempt` per Newton solve of a row set for a set of unknowns, a :class:`Failure` per
structure it could not solve, and the :class:`Trace` of a whole solve (its attempts, failures,
Newton steps and the limits hit), which the diagnostics and ``aidl explain`` read."""
from __future__ import annotations

import numpy as np

from ...base.records import Compared, Record
from ...geometry.core.model import Structure

class Attempt(Compared):
    """One Newton solve of a row set for a set of unknowns."""
    __slots__ = ("stage", "depth", "rows", "cols", "ok", "iterations", "rounds", "order", "x_end",
                 "max_iter")

    def __init__(self, stage: str, depth: int, rows: np.ndarray, cols: np.ndarray,
                 ok: bool = False, iterations: int = 0, rounds: int = 0, order: int = 0,
                 x_end: np.ndarray | None = None, max_iter: int | None = None):
        self.stage = stage  # "local", "translate", "deform", "flat", "features" or "shapes"
        self.depth = depth
        self.rows = rows
        self.cols = cols
        self.ok = ok
        self.iterations = iterations
        self.rounds = rounds
        self.order = order  # post-order position of its structure (trace order)
        self.x_end = x_end  # x[cols] where it ended (a failure restores it)
        # Newton steps per round, when fewer than the solver's (a stage that only finishes
        # what the one before nearly met: it ends in a few steps or is not the way)
        self.max_iter = max_iter


class Failure(Record):
    """A structure whose solve failed, with the attempt that failed."""
    __slots__ = ("structure", "attempt")

    def __init__(self, structure: Structure, attempt: Attempt):
        self.structure = structure
        self.attempt = attempt


class Trace(Record):
    """What the hierarchical solve did: its attempts, failures, iterations and limits hit."""
    __slots__ = ("attempts", "failures", "iterations", "budget_exceeded", "out_of_time")

    def __init__(self, attempts: list | None = None, failures: list | None = None,
                 iterations: int = 0, budget_exceeded: bool = False, out_of_time: bool = False):
        self.attempts = [] if attempts is None else attempts
        self.failures = [] if failures is None else failures
        self.iterations = iterations
        self.budget_exceeded = budget_exceeded
        self.out_of_time = out_of_time
