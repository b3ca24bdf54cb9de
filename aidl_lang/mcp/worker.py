"""The compiling tools of ``aidl mcp`` (check, render, values, describe) run in warm worker
processes, so that every call ends within its time limit whatever the program does: a thread
cannot be stopped, a process can (issue 37; ``aidl batch`` does the same with its workers).

:class:`Worker` keeps one process (:func:`aidl_lang.host.workers.context`) with its own
:class:`~.tools.Workspace`; a call is sent over a pipe and its answer (or its
:class:`~.tools.Refused`) comes back.  A call that has not answered within
:func:`aidl_lang.base.limits.wall_limit` of its budget (10 x its 15 s x ``budget`` of CPU time, plus
10 s: 160 s by default) kills the process and is refused with a message saying so; the next call
starts a fresh process.  The compile's own deadline
normally ends it first, with a located ``E0304``: this is the last resort for what the
deadline cannot interrupt (one long call into a C library).

:class:`Pool` runs calls side by side in up to :data:`POOL_SIZE` workers (issue 48: one slow
compile made every other call wait): a call takes an idle worker (a warm one first; a
process is started on a worker's first call), and waits for one when all are busy.
"""
from __future__ import annotations

from ..host import workers as W
from ..base.limits import DEFAULT_BUDGET, wall_limit
from . import tools as T

POOL_SIZE = 3               # calls that may run at the same time (each in its own process)
# what the tools import, imported once by the forkserver the workers are forked from
PRELOAD = ("aidl_lang.mcp.worker", "aidl_lang.pipeline", "aidl_lang.output", "ezdxf", "cairosvg",
           "manifold3d", "PIL.Image")
# the tools whose files come back from the worker as ``(answer, files)``, written by the
# server in the order the calls were made (:mod:`.order`)
WRITERS = ("render", "import_drawing", "write_program", "set_params")


def _handler(root: str, budget: float):
    """Run in the worker process: the workspace, and the function answering ``(name, args)``
    with ``(True, result)`` or ``(False, Refused)``."""
    ws = T.Workspace(root, budget)

    def handle(request):
        name, args = request
        if name == "warm":
            return True, T.warm(ws)
        if name not in ("check", "render", "values", "describe", "import_drawing",
                        "write_program", "set_params", "measure"):
            return False, T.Refused(f"unknown tool `{name}`")
        oom = False
        given = program_argument(name, args) == "source"
        try:
            if name in WRITERS:         # the files come back: the server writes them in order
                files: list = []
                got = getattr(T, name)(ws, *args, files=files)
                return True, (T.unrooted(ws, got, given), files)
            return True, T.unrooted(ws, getattr(T, name)(ws, *args), given)
        except T.Refused as e:
            return False, T.Refused(T.unrooted(ws, str(e), given), e.code, e.argument)
        except BaseException as e:      # noqa: BLE001 - answered, never a silent worker
            from ..base.limits import is_out_of_memory
            oom = is_out_of_memory(e)
            if not oom:
                return False, T.Refused(f"internal error: {type(e).__name__}: {e}",
                                        "internal_error", program_argument(name, args))
        return False, out_of_memory(ws, args, program_argument(name, args))   # frames gone
    return handle


def program_argument(name: str, args: tuple) -> str:
    """The argument that gave the program of the call ``name(*args)``: ``source`` or
    ``path`` (the tools that take a file only: ``path``), for the refusals a program causes
    (out of memory, a worker that died, an internal error)."""
    at = {"check": 0, "render": 0, "values": 0, "describe": 0, "measure": 2}.get(name)
    if at is None:
        return "path"
    return "source" if len(args) > at and args[at] is not None else "path"


def out_of_memory(ws, args: tuple, argument: str | None = None):
    """The refusal of a call whose compile ran out of memory anywhere (the checks, the exact
    outlines, a writer): the program's located ``E0304`` (``args``: the tool's ``source``,
    ``path``, ...), as the summary of a failed ``check`` words it."""
    from ..pipeline import out_of_memory_sink
    source = args[0] if args and isinstance(args[0], str) else None
    path = args[1] if len(args) > 1 and isinstance(args[1], str) else None
    name = path or "<source>"
    if source is None and path is not None:
        try:
            real, source = ws.read(path)
        except T.Refused:
            source = None
    sink = out_of_memory_sink(name, source)
    d = sink.items[0]
    return T.Refused(f"{d.code} line {d.span.line if d.span else '-'}: {d.message}; "
                     f"{d.hint}", d.code, argument)


class Worker(W.Worker):
    """One warm process for the compiling tools of the server of ``root`` (default budget
    factor ``budget``); :meth:`call` runs one, one at a time."""

    def __init__(self, root: str, budget: float = 1.0) -> None:
        super().__init__(_handler, (str(root), budget), preload=PRELOAD)
        self.root, self.budget = str(root), budget

    def seconds(self, budget: float | None) -> float:
        """The time limit of a call with ``budget`` (None: the server's)."""
        ok = isinstance(budget, (int, float)) and not isinstance(budget, bool) \
            and 0 < budget <= T.MAX_BUDGET
        k = budget if ok else self.budget        # a bad one is refused by the tool itself
        return wall_limit(DEFAULT_BUDGET.seconds * float(k))

    def call(self, name: str, *args, budget: float | None = None):
        """``tools.NAME(workspace, *args)`` in the worker; its result, or raises
        :class:`~.tools.Refused` (the tool's own refusal, a call past its time limit, or a
        worker that died)."""
        limit = self.seconds(budget)
        try:
            ok, value = self.request((name, args), limit)
        except W.TimedOut:
            raise T.Refused(f"the call took longer than {limit:g} s of wall time (10 times "
                            "its budget's CPU seconds) and was stopped; build less, or give "
                            "a larger `budget` (at most 4)", "timed_out", "budget") from None
        except W.Died:
            raise T.Refused("the compile ended its worker process (out of memory?); "
                            "build less", "worker_died", program_argument(name, args)) from None
        except W.NotReady as e:
            raise T.Refused(str(e), "worker_died", program_argument(name, args)) from None
        if ok:
            return value
        raise value


class Pool(W.Pool):
    """Up to ``size`` workers (:class:`Worker`) for the server of ``root`` (default budget factor
    ``budget``), so that calls run at the same time: a slow call delays only itself.
    :meth:`call` takes an idle worker, the one used last first (its process is warm; a
    worker starts its process on its first call), and waits while all ``size`` are busy."""

    def __init__(self, root: str, budget: float = 1.0, size: int = POOL_SIZE) -> None:
        super().__init__([Worker(root, budget) for _ in range(max(1, size))])

    def warm(self) -> None:
        """Start the worker the first call will take and have it compile and draw a small
        program (:func:`.tools.warm`), in the background: the first call waits for it (it
        holds that worker) instead of paying for a process start, the imports and the first
        compile itself (issue 73: the first render was 2.2-2.5 s)."""
        import threading
        w = self.idle[-1]

        def run() -> None:
            try:
                w.call("warm", budget=T.MAX_BUDGET)
            except Exception:              # noqa: BLE001 - a failed warm-up: a cold call
                pass
        threading.Thread(target=run, name="aidl-mcp-warm", daemon=True).start()

    def call(self, name: str, *args, budget: float | None = None):
        """:meth:`Worker.call` in an idle worker (waiting for one when all are busy)."""
        w = self.take()
        try:
            return w.call(name, *args, budget=budget)
        finally:
            self.give(w)
