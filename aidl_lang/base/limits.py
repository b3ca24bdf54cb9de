"""What one program may build: the per-construct limits and the one evaluation budget of a
compile (docs/language.md §8.1 "Limits").

The per-construct limits (``MAX_ITER``, ``MAX_TEMPLATE_DEPTH``...) are the first line: each
stops one construct that is too large by itself.  The :class:`Budget` bounds the product: every
loop iteration, comprehension element, call and template instance is one *step*; geometry
points, geometry objects, structures and constraints share one *object* count; every string or list a program
builds is limited in size; and CPU seconds are the last resort (:func:`now`, the budget's clock: this
process's CPU time, so a program gets the same answer on a quiet machine and a busy one), with wall
time only as an outer guard at :data:`WALL_GUARD` times the seconds.  A program that goes past any of
them gets one located diagnostic (``E0304``) naming the loops and template instances on the
stack (after the solve: the structure and the stage, :class:`OutOfBudget`), never a hang, a
crash or unbounded memory.  ``aidl check/render --budget K`` multiplies
every budget figure by ``K``.
"""
from __future__ import annotations

import time

from .records import Frozen

MAX_ITER = 10_000            # iterations of one loop or comprehension (Budget.items)
MAX_GEOMETRY = 50_000        # geometry objects in one model (Budget.geometry)
MAX_TEMPLATE_DEPTH = 16      # nested template instances
MAX_EXTENT = 1e6             # |coordinate|, size or length in mm a model may reach (1 km)
# mm: the least positive minimum wall (`min_wall`, --min-wall): 1 um, below what any laser or
# router holds; under it the wall checks measured their own rounding (the chords of a gear's
# teeth as 0.00 mm walls at 1e-5 mm) and at 1e-300 mm the opening vanished (a traceback)
MIN_WALL_LEAST = 1e-3


def min_wall_problem(mm: float) -> str | None:
    """Why ``mm`` cannot be a minimum wall (``min_wall``, ``--min-wall``), or None when it
    can: 0 (the wall checks off) or a finite length from :data:`MIN_WALL_LEAST` to
    :data:`MAX_EXTENT` mm; the words name the allowed range."""
    if mm == 0 or MIN_WALL_LEAST <= mm <= MAX_EXTENT:     # (NaN fails both)
        return None
    what = ("not a number" if mm != mm else "negative" if mm < 0 else
            "not finite" if mm in (float("inf"), float("-inf")) else
            "too small" if mm < MIN_WALL_LEAST else "too large")
    return (f"{mm:g} mm is {what}: a minimum wall is a length from {MIN_WALL_LEAST:g} to "
            f"{MAX_EXTENT:g} mm, or 0 (no wall checks)")


def min_wall_argument(text: str) -> float:
    """``--min-wall MM`` of ``aidl check``, ``render`` and ``batch`` (an argparse ``type``):
    the length in mm, or :class:`argparse.ArgumentTypeError` with :func:`min_wall_problem`'s
    words (a usage error, exit 2): NaN, infinities, negatives and lengths below
    :data:`MIN_WALL_LEAST` are refused, as the ``min_wall`` statement refuses them (E0109)."""
    import argparse
    try:
        mm = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected a number of mm, got `{text}`") from None
    why = min_wall_problem(mm)
    if why is not None:
        raise argparse.ArgumentTypeError(why)
    return mm


class Budget(Frozen):
    """The evaluation budget of one compile.  Defaults (docs/language.md §8.1):

    - ``steps``: 250 000 loop iterations, comprehension elements, calls and template
      instances (about 2 s of interpretation);
    - ``objects``: 120 000 points, geometry objects, structures and constraints together;
    - ``size``: 1 000 000 characters of one string / items of one list;
    - ``seconds``: 15 s of CPU time (:func:`now`) for the whole compile: interpreting,
      solving, the booleans and the shape checks (and, in ``aidl render``, the writers; in
      ``aidl parts`` the parts list; in ``aidl check --describe`` the description); wall
      time is an outer guard at :data:`WALL_GUARD` x that (150 s);
    - ``vertices``: 3 000 000 vertices of the tessellated outlines handed to the booleans
      (counted before they are made: a circle of radius ``r`` needs
      :func:`~aidl_lang.geometry.shapes.tessellate.segments_for` ``(r)``; a perforated sheet of
      50 000 holes of r 2 mm needs 2 250 000, checked in about 830 MB);
    - ``items``: :data:`MAX_ITER` (10 000) items of one loop, ``range`` or comprehension
      (``E0301``);
    - ``geometry``: :data:`MAX_GEOMETRY` (50 000) geometry objects in one model (``E0303``).
    """
    __slots__ = ("steps", "objects", "size", "seconds", "vertices", "items", "geometry")

    def __init__(self, steps: int = 250_000, objects: int = 120_000, size: int = 1_000_000,
                 seconds: float = 15.0, vertices: int = 3_000_000, items: int = MAX_ITER,
                 geometry: int = MAX_GEOMETRY):
        object.__setattr__(self, "steps", steps)
        object.__setattr__(self, "objects", objects)
        object.__setattr__(self, "size", size)
        object.__setattr__(self, "seconds", seconds)
        object.__setattr__(self, "vertices", vertices)
        object.__setattr__(self, "items", items)
        object.__setattr__(self, "geometry", geometry)

    def scaled(self, k: float) -> "Budget":
        """Every figure multiplied by ``k`` (``--budget K``); ``k`` > 0."""
        return Budget(int(self.steps * k), int(self.objects * k), int(self.size * k),
                      self.seconds * k, int(self.vertices * k), int(self.items * k),
                      int(self.geometry * k))


DEFAULT_BUDGET = Budget()
# bytes of one program file or imported file (E0004); `aidl import` refuses to write more
MAX_SOURCE_BYTES = 1_000_000


class OutOfBudget(Exception):
    """The budget ran out after the solve: in the booleans, the shape checks or a writer.
    ``what``: which figure (``more than 15 s of CPU time``); ``stage``: where (``the
    booleans``); ``where``: the structure being worked on (with ``path`` and ``span``), or
    ``None``; ``hint``: the fix when it is not "build less or raise ``--budget``" (a bound
    that no budget raises).  :func:`aidl_lang.pipeline.after_solve` turns it into one located
    ``E0304``."""

    def __init__(self, what: str, stage: str, where=None, hint: str | None = None):
        super().__init__(what)
        self.what, self.stage, self.where, self.hint = what, stage, where, hint


class OutOfMemory(OutOfBudget):
    """A ``MemoryError`` (or the ``SystemError`` C code raises for a failed allocation) in a
    stage after the solve: the booleans, the shape checks, the exact outlines, a writer.
    Raised by the code that caught it, once the failed stage's frames are gone (so their
    arrays are freed), and reported like any :class:`OutOfBudget`: one located ``E0304``
    (:func:`aidl_lang.pipeline.report_out_of_budget`) at ``where``, the structure being
    worked on."""

    def __init__(self, stage: str, where=None):
        super().__init__(memory_text(), stage, where, hint=MEMORY_HINT + memory_fix())


MEMORY_HINT = ("build less (fewer loop iterations, template instances, copies or circles), or "
               "look for a template that instantiates itself more than once per level")


def is_out_of_memory(ex: BaseException) -> bool:
    """True when ``ex`` is running out of memory: a :class:`MemoryError`, or the
    :class:`SystemError` that C code raises when an allocation failed and the MemoryError got
    lost (``error return without exception set``, or one with a MemoryError as its cause or
    context; issue 37)."""
    seen = 0
    e: BaseException | None = ex
    while e is not None and seen < 20:
        if isinstance(e, MemoryError):
            return True
        if isinstance(e, SystemError) and "without exception set" in str(e):
            return True
        e = e.__cause__ or e.__context__
        seen += 1
    return False


def memory_text() -> str:
    """What ran out, for ``E0304``: the process's address-space cap when it has one
    (``aidl check --memory``, a server's worker), else the machine's memory."""
    from .memory import memory_cap
    cap, _ = memory_cap()
    if cap:
        return f"it needs more memory than this compile may use ({size_text(cap)})"
    return "it needs more memory than this machine can hold"


def memory_fix() -> str:
    """``; or raise the memory cap ... with `--memory 16G``` when the cap was set by a command
    whose user can raise it (:func:`aidl_lang.base.memory.limit_memory`'s ``raise_with``)."""
    from .memory import memory_cap
    cap, how = memory_cap()
    return f"; or raise the memory cap ({size_text(cap)}) with `{how}`" if cap and how else ""


def size_text(n: int) -> str:
    """Bytes as ``12.5 GB`` / ``600 MB`` (powers of 1024)."""
    if n >= 1 << 30:
        return f"{n / (1 << 30):.3g} GB"
    return f"{n / (1 << 20):.0f} MB"


# The wall-time guard of a budget: a compile also ends once WALL_GUARD x its seconds of wall time
# have passed, whatever CPU it got (a machine that gives it less than a tenth of a core, or a
# stage that waits); the servers kill a worker's request at this multiple too (issue 83)
WALL_GUARD = 10.0
# s past the wall guard before a server kills the worker running a compile (the compile's own
# guard ends it first, with its located E0304, unless it is stuck in one call into C code)
WALL_GRACE = 10.0


def wall_limit(seconds: float) -> float:
    """The wall-time limit (s) after which a server (``aidl mcp``, ``aidl studio``, ``aidl
    batch``, the LSP) kills the worker process of a compile whose budget is ``seconds`` of CPU
    time: :data:`WALL_GUARD` x ``seconds`` + :data:`WALL_GRACE` (160 s for the default 15 s)."""
    return WALL_GUARD * seconds + WALL_GRACE


def now() -> float:
    """The budget's clock, in seconds: this process's CPU time (``time.process_time()``, every
    thread of the process: the compile's own and the libraries' it calls).  A compile's
    ``deadline`` floats and :attr:`Deadline.at` are values of this clock, so the same program
    reaches its budget after the same work on a quiet machine and on one where every core is
    busy (issue 83: the 20,000-hole panel was E0304 at load 10 and ``ok`` at load 0).  A process
    runs one compile at a time (every front end compiles in its own worker process or thread
    joined before the next), so its CPU time is that compile's."""
    return time.process_time()


class Deadline:
    """The end of one compile on the budget's clock (:func:`now`: CPU seconds) and the budget
    it comes from, with its wall-time guard (``wall_at``, ``time.monotonic()`` seconds;
    by default :data:`WALL_GUARD` times the CPU seconds left when it is made); :meth:`check`
    raises :class:`OutOfBudget` once either has passed."""

    __slots__ = ("at", "budget", "wall_at")

    def __init__(self, at: float, budget: Budget = DEFAULT_BUDGET, wall_at: float | None = None):
        self.at, self.budget = at, budget
        self.wall_at = (wall_at if wall_at is not None
                        else time.monotonic() + WALL_GUARD * max(at - now(), 0.0))

    @classmethod
    def starting(cls, budget: Budget = DEFAULT_BUDGET) -> "Deadline":
        """The deadline of a compile that starts now with ``budget``: ``budget.seconds`` CPU
        seconds from :func:`now`, and :data:`WALL_GUARD` times that of wall time."""
        return cls(now() + budget.seconds, budget)

    def check(self, stage: str, where=None, ahead: float = 0.0) -> None:
        """Raise :class:`OutOfBudget` once the deadline has passed (its CPU seconds, or the wall
        guard), or when a step expected to take ``ahead`` CPU seconds (a single call into
        Manifold that cannot be interrupted) would end past it: refused before it starts."""
        t = now()
        if t > self.at:
            raise OutOfBudget(cpu_text(self.budget.seconds), stage, where)
        if time.monotonic() > self.wall_at:
            raise OutOfBudget(wall_text(self.budget.seconds), stage, where)
        if t + ahead > self.at:
            raise OutOfBudget(f"about {ahead:.3g} s more would end past the "
                              f"{self.budget.seconds:g} s of CPU time", stage, where)


def cpu_text(seconds: float) -> str:
    """What ran out, for ``E0304``, when a compile used its ``seconds`` of CPU time."""
    return f"more than {seconds:g} s of CPU time"


def wall_text(seconds: float) -> str:
    """What ran out, for ``E0304``, when the wall-time guard of a ``seconds`` budget passed."""
    return (f"more than {WALL_GUARD * seconds:g} s of wall time ({WALL_GUARD:g} x its "
            f"{seconds:g} s of CPU time: this machine gave the compile less than "
            f"{1 / WALL_GUARD:.0%} of a core)")
