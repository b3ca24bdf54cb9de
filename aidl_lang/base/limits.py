"""What one program may build: the per-construct limits and the one evaluation budget of a
compile (docs/language.md §8.1 "Limits").

The per-construct limits (``MAX_ITER``, ``MAX_TEMPLATE_DEPTH``...) are the first line: each
stops one construct that is too large by itself.  The :class:`Budget` bounds the product: every
loop iteration, comprehension element, call and template instance is one *step*; geometry
points, geometry objects, structures and constraints share one *object* count; every string or list a program
builds is limited in size; and every stage (interpreting, solving, the booleans, the shape checks,
the writers, imports, sweeps) spends *work units* (:class:`Work`) counted from what it walks
(vertices, Newton steps, pairs, entities, points judged): the same program at the same budget
spends the same work and gets the same answer, the same message and the same output on any
machine at any load (issue 101; prior art: Z3's ``rlimit``, wasmtime's fuel, gas).  A unit is
about :data:`UNIT_SECONDS` of CPU on the reference machine.  CPU seconds (:func:`now`) are only
a far backstop at :data:`BACKSTOP` times the budget's seconds, and wall time an outer guard at
:data:`WALL_GUARD` times them.  A program that goes past any of them gets one located
diagnostic (``E0304``) naming the loops and template instances on the stack (after the solve:
the structure and the stage, :class:`OutOfBudget`), never a hang, a crash or unbounded memory.
``aidl check/render --budget K`` multiplies every budget figure by ``K``.
"""
from __future__ import annotations

import math
import os
import time

from .records import Frozen

# CPU seconds of one work unit on the reference machine (the calibration: the sweep's weights,
# aidl_lang/params/sweep_plan.py, fitted over the gallery's compiles: 2.0 / 7.3 / 12.5 us a unit,
# min / median / max per design on 2 cores); the default budget's 15 s are 2,000,000 units
UNIT_SECONDS = 7.5e-6
# the CPU-second backstop: a compile also ends after BACKSTOP x its budget's seconds of CPU time
# (90 s for the default 15 s), far above what its work units take on the reference machine (at
# most 12.5 / 7.5 of the seconds), so that it never decides for a program the work accepts
BACKSTOP = 6.0


# the weights of the work unit for the stages bounded by counts of their own (fitted with the
# sweep's, aidl_lang/params/sweep_plan.py): an interpreter step 1, an object it made
# PER_OBJECT, a Newton step PER_ITERATION, an unknown of the model PER_UNKNOWN
PER_OBJECT = 5
PER_UNKNOWN = 0.25
PER_ITERATION = 80


def interp_work(steps: int, objects: int) -> float:
    """The work units of interpreting: its ``steps`` and ``PER_OBJECT`` x its ``objects``."""
    return steps + PER_OBJECT * objects


def solve_work(iterations: int, unknowns: int) -> float:
    """The work units of a solve: ``PER_ITERATION`` a Newton step, ``PER_UNKNOWN`` an
    unknown."""
    return PER_ITERATION * iterations + PER_UNKNOWN * unknowns


def _cpu_scale() -> float:
    """``AIDL_CPU_SCALE`` (a test hook, default 1): every CPU-time reading the product takes
    (:func:`now`) counts this many times, as on a machine that many times slower; a value that
    is not a positive number is 1."""
    try:
        k = float(os.environ.get("AIDL_CPU_SCALE") or 1.0)
    except ValueError:
        return 1.0
    return k if k > 0 and k == k and k != float("inf") else 1.0


CPU_SCALE = _cpu_scale()

MAX_ITER = 10_000            # iterations of one loop or comprehension (Budget.items)
MAX_GEOMETRY = 50_000        # geometry objects in one model (Budget.geometry)
MAX_TEMPLATE_DEPTH = 16      # nested template instances
MAX_CALL_DEPTH = 64          # nested calls of `def f(x) = ...` functions (and other frames)
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
    - ``seconds``: 15, the budget's size in seconds of the reference machine: its
      :attr:`work`, ``seconds`` / :data:`UNIT_SECONDS` = 2 000 000 work units for the whole
      compile (interpreting, solving, the booleans and the shape checks; in ``aidl render``
      the writers; in ``aidl parts`` the parts list; in ``aidl check --describe`` the
      description; in ``aidl import`` the reading and inference); CPU time (:func:`now`) is a
      backstop at :data:`BACKSTOP` x that (90 s) and wall time an outer guard at
      :data:`WALL_GUARD` x that (150 s);
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

    @property
    def work(self) -> int:
        """The work units (:class:`Work`) of this budget: ``seconds`` / :data:`UNIT_SECONDS`."""
        return int(round(self.seconds / UNIT_SECONDS))

    @property
    def backstop(self) -> float:
        """The CPU seconds after which a compile ends whatever its work: :data:`BACKSTOP` x
        ``seconds``."""
        return BACKSTOP * self.seconds

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

    def __init__(self, what: str, stage: str, where=None, hint: str | None = None,
                 work: float | None = None):
        super().__init__(what)
        self.what, self.stage, self.where, self.hint = what, stage, where, hint
        self.work = work          # the work units spent or needed when it ran out, if known


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
    """The backstop's clock, in seconds: this process's CPU time (``time.process_time()``,
    every thread of the process: the compile's own and the libraries' it calls) times
    :data:`CPU_SCALE` (``AIDL_CPU_SCALE``, a test hook for a slower machine).  A compile's
    ``deadline`` floats and :attr:`Deadline.at` are values of this clock: the backstop
    (:data:`BACKSTOP`), never what decides for a program its work units accept.  A process
    runs one compile at a time (every front end compiles in its own worker process or thread
    joined before the next), so its CPU time is that compile's."""
    return time.process_time() * CPU_SCALE


def budget_factor_text(need: float, budget: "Budget") -> str:
    """The ``--budget K`` whose work covers ``need`` units with 5 % to spare, ``K`` rounded up
    to two significant digits (``--budget 1.5``, ``--budget 0.038``, ``--budget 14``): a
    factor of :data:`DEFAULT_BUDGET`, as ``--budget`` is (``budget``: the one that ran out,
    for its name only)."""
    import math
    k = max(need, 1.0) * 1.05 / max(DEFAULT_BUDGET.work, 1)
    step = 10.0 ** (math.floor(math.log10(k)) - 1)
    nice = math.ceil(round(k / step, 9)) * step
    return f"--budget {float(f'{nice:.2g}'):g}"


class Work:
    """The work meter of one compile (or one import, one sweep): ``spent`` work units of its
    ``limit`` (:attr:`Budget.work`), each stage's share in ``by_stage``.  A stage spends units
    for what it walks *before* it walks it (:meth:`spend`, as gas is paid before a step): the
    step that would pass the limit is refused with :class:`OutOfBudget` naming the stage, the
    units it needs, the budget and the ``--budget`` that would do.  Counted from the program
    alone, so the same on every machine and at any load."""

    __slots__ = ("limit", "spent", "by_stage")

    def __init__(self, limit: float):
        self.limit = float(limit)
        self.spent = 0.0
        self.by_stage: dict[str, float] = {}

    def add(self, units: float, stage: str) -> None:
        """Count ``units`` already spent by ``stage`` (a stage bounded by limits of its own:
        the interpreter's steps, the solver's Newton steps); the next :meth:`spend` refuses
        once the total is past the limit."""
        self.spent += units
        self.by_stage[stage] = self.by_stage.get(stage, 0.0) + units

    def spend(self, units: float, stage: str, where=None) -> None:
        """Pay ``units`` for the next step of ``stage`` (on the structure ``where``), or raise
        :class:`OutOfBudget` when the total would pass the limit (nothing is spent then)."""
        if self.spent + units > self.limit:
            raise OutOfBudget(self.text(units), stage, where,
                              hint=self.hint(units), work=self.spent + units)
        self.add(units, stage)

    def text(self, units: float = 0.0) -> str:
        """What ran out, for ``E0304``: the units needed against the budget."""
        return (f"it needs more than {int(self.spent + units):,} work units, past its budget "
                f"of {int(self.limit):,}")

    def hint(self, units: float = 0.0) -> str:
        """The fix: build less, or the ``--budget`` whose work covers what was needed."""
        need = max(self.spent + units, self.limit)
        return ("build less (fewer or smaller shapes: every circle and arc becomes chords of "
                f"0.005 mm), or raise the budget with `{budget_factor_text(need, DEFAULT_BUDGET)}`"
                " (or more)")

    def __int__(self) -> int:
        return int(self.spent)

    def to_json(self) -> dict:
        """``{"spent": units, "budget": units, "stages": {stage: units}}`` (``--json``'s
        ``work``): whole units, the same on every machine."""
        return {"spent": int(self.spent), "budget": int(self.limit),
                "stages": {k: int(v) for k, v in self.by_stage.items()}}


class Deadline:
    """The budget of one compile after the interpreter: its work meter (``work``, a
    :class:`Work` of the budget's units) and the backstops, its CPU end ``at`` (:func:`now`:
    :attr:`Budget.backstop` CPU seconds from the start) and its wall-time guard (``wall_at``,
    ``time.monotonic()`` seconds; by default :data:`WALL_GUARD` times the budget's seconds).
    :meth:`check` pays a step's work and raises :class:`OutOfBudget` once any of them has
    passed."""

    __slots__ = ("_at", "budget", "wall_at", "work", "started", "_read")

    def __init__(self, at: float, budget: Budget = DEFAULT_BUDGET, wall_at: float | None = None,
                 work: Work | None = None):
        self.at, self.budget = at, budget
        self.started = started()
        self.wall_at = (wall_at if wall_at is not None
                        else time.monotonic() + WALL_GUARD * budget.seconds)
        self.work = work if work is not None else Work(budget.work)
        self._read = -math.inf          # time.monotonic() when the CPU clock was last read

    @property
    def at(self) -> float:
        """The CPU backstop: the :func:`now` value past which the compile ends."""
        return self._at

    @at.setter
    def at(self, value: float) -> None:
        self._at = value
        self._read = -math.inf          # a moved backstop: the next step reads the clock

    @classmethod
    def starting(cls, budget: Budget = DEFAULT_BUDGET, work: Work | None = None) -> "Deadline":
        """The deadline of a compile that starts now with ``budget``: its work units, the
        backstop :attr:`Budget.backstop` CPU seconds from :func:`now`, and :data:`WALL_GUARD`
        times its seconds of wall time."""
        return cls(now() + budget.backstop, budget, work=work)

    def check(self, stage: str, where=None, ahead: float = 0.0) -> None:
        """Pay one work unit and ``ahead`` more (the work units of the next step: a single
        call into Manifold that cannot be interrupted, priced before it starts) for ``stage``;
        raise :class:`OutOfBudget` when that would pass the work budget (refused before it
        starts), or once the CPU backstop or the wall guard has passed."""
        self.work.spend(1.0 + ahead, stage, where)
        self.backstop(stage, where)

    def seconds_left(self) -> float:
        """The work units left, as seconds of the reference machine (:data:`UNIT_SECONDS`):
        what a stage that plans by an estimate in seconds (a union's scan-line work) may
        spend, the same on every machine."""
        return max(self.work.limit - self.work.spent, 0.0) * UNIT_SECONDS

    def backstop(self, stage: str, where=None) -> None:
        """Raise :class:`OutOfBudget` once the CPU backstop or the wall guard has passed.  The
        CPU clock (a system call, 2-5 us: 150,000 steps of a 19,000-hole panel read it for
        0.4-0.7 s) is read once :data:`CPU_READ_EVERY` of wall time has passed since it was
        last read (the first time at once): a process's CPU time grows no faster than the
        wall time times its threads, so the backstop is passed by a few ms at most."""
        t = time.monotonic()
        if t - self._read >= CPU_READ_EVERY or t > self.wall_at:
            self._read = t
            if now() > self.at:
                raise OutOfBudget(cpu_text(self.budget.backstop), stage, where,
                                  work=self.work.spent)
        if t > self.wall_at:
            raise OutOfBudget(wall_text(self.budget.seconds, self.started), stage, where,
                              work=self.work.spent)


# s of wall time between two readings of the CPU clock by :meth:`Deadline.backstop`
CPU_READ_EVERY = 0.002


def seconds_as_work(seconds: float) -> float:
    """An estimate in reference-machine CPU seconds (a Manifold call's, a writer's) as work
    units: ``seconds`` / :data:`UNIT_SECONDS`."""
    return seconds / UNIT_SECONDS


def cpu_text(seconds: float) -> str:
    """What ran out, for ``E0304``, when a compile reached its CPU backstop (``seconds``)."""
    return (f"more than {seconds:g} s of CPU time (the backstop, {BACKSTOP:g} x the budget's "
            "time: a stage that counted too little of its work)")


def started() -> tuple[float, float]:
    """``(CPU seconds, wall seconds)`` now: this process's ``time.process_time()`` and
    ``time.monotonic()``, the start :func:`wall_text` measures from."""
    return time.process_time(), time.monotonic()


def wall_text(seconds: float, start: tuple[float, float] | None = None) -> str:
    """What ran out, for ``E0304``, when the wall-time guard of a ``seconds`` budget passed:
    the guard, and what was measured since ``start`` (:func:`started`): the CPU the compile
    got and its share of a core (issue 110: it said "less than 10% of a core" after 56.8 s
    of CPU in 150 s, 38 %)."""
    out = f"more than {WALL_GUARD * seconds:g} s of wall time ({WALL_GUARD:g} x its {seconds:g} s budget"
    if start is None:
        return out + ")"
    cpu, wall = time.process_time() - start[0], time.monotonic() - start[1]
    return (out + f"), in which the compile got {cpu:.3g} s of CPU ({cpu / max(wall, 1e-9):.0%} "
            "of a core: the machine is busy, or a stage waited)")
