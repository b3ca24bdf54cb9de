"""``aidl batch INPUTS... -o OUT.parquet|OUT.jsonl``: compile many programs, one result row each
(docs/batch.md).  :func:`add_arguments` and :func:`main` are what ``aidl_lang.cli`` registers;
:func:`run_batch` is the same batch for Python callers (tests, benchmarks).

Exit status: 0 the batch finished (whatever its programs' results: they are the rows), 1 it
could not run (the scheduler cannot be reached, OUT cannot be written), 2 a usage error or a
missing optional library, 130 interrupted (every finished row is kept; run the same command
again to go on).
"""
from __future__ import annotations

import argparse
import os
import sys
import time
from collections import Counter
from pathlib import Path

from ..base.limits import DEFAULT_BUDGET, min_wall_argument, wall_limit
from .row import TIMINGS



def default_workers() -> int:
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except (AttributeError, OSError):
        return max(1, os.cpu_count() or 1)


def _positive(kind):
    def parse(text: str):
        try:
            v = kind(text)
        except ValueError:
            v = 0
        if not v > 0:
            raise argparse.ArgumentTypeError(f"expected a positive number, got `{text}`")
        return v
    return parse


def _factor(text: str) -> float:
    try:
        k = float(text)
    except ValueError:
        k = -1.0
    if not 0 < k <= 1000:
        raise argparse.ArgumentTypeError(f"--budget expects a factor between 0 and 1000, "
                                         f"got `{text}`")
    return k


def add_arguments(p) -> None:
    p.add_argument("inputs", nargs="+", metavar="INPUT",
                   help=".aidl files, folders (every *.aidl below) or .jsonl files of "
                        '{"id": ..., "source": ...} rows')
    p.add_argument("-o", "--output", required=True, metavar="OUT",
                   help="the result rows: OUT.parquet or OUT.jsonl (an existing OUT is resumed: "
                        "rows with the same id, source hash and options are not redone)")
    p.add_argument("--render", default="", metavar="FORMATS",
                   help="write each good program in these formats, comma-separated: "
                        "any extension aidl render writes, e.g. svg,dxf (needs --out-dir)")
    p.add_argument("--out-dir", default=None, metavar="DIR",
                   help="the folder for --render's files (DIR/NAME.svg, ...)")
    p.add_argument("--workers", type=_positive(int), default=None, metavar="N",
                   help="worker processes (default: this machine's cores; with "
                        "--scheduler local, the LocalCluster's workers)")
    p.add_argument("--scheduler", default=None, metavar="ADDRESS",
                   help="run on a Dask cluster: tcp://HOST:8786, or `local` for a "
                        "LocalCluster on this machine (needs the dask extra)")
    p.add_argument("--budget", type=_factor, default=1.0, metavar="K",
                   help="multiply each program's evaluation budget by K (docs/language.md §8.1)")
    p.add_argument("--timeout", type=_positive(float), default=None, metavar="SECONDS",
                   help="hard time-out per program: its worker is stopped and the row says "
                        "`timeout` (default: 10 times the budget's CPU seconds and 10 s, "
                        "160 s for K 1)")
    p.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                   help="override a param in every program")
    p.add_argument("--min-wall", type=min_wall_argument, default=None, metavar="MM",
                   help="warn (W0507) about walls thinner than this, in mm (default: the "
                        "program's `min_wall`, else 0.5)")
    p.add_argument("--no-progress", action="store_true", help="no progress bar on stderr")


class UsageError(ValueError):
    pass


def _formats(text: str) -> list[str]:
    from ..output import FORMATS          # the writers' registry (imports the outputs)
    names = [x.strip().lower().lstrip(".") for x in text.split(",") if x.strip()]
    known = [k.lstrip(".") for k in FORMATS]
    bad = [n for n in names if n not in known]
    if bad:
        raise UsageError(f"--render takes {','.join(known)}; got `{bad[0]}`")
    return list(dict.fromkeys("." + n for n in names))


def _check_writers(suffixes: list[str]) -> None:
    """A format whose library is missing is a usage error before anything runs, not an error
    in every row."""
    from ..output import MissingDependency, Output, encode
    for s in suffixes:
        try:
            encode(Output(), s)
        except MissingDependency as e:
            raise UsageError(str(e)) from None
        except Exception:
            pass                     # an empty drawing may not be writable: not the question


def run_batch(inputs: list[str], out: str | Path, *, render: list[str] = (),
              out_dir: str | None = None, workers: int | None = None,
              scheduler: str | None = None, budget: float = 1.0,
              overrides: dict | None = None, timeout: float | None = None,
              min_wall: float | None = None, progress: bool = False, console=None,
              on_row=None) -> dict:
    """Run a batch (``on_row``, if given, is called with each row as it is written); returns ``{"rows": [...] (one per input, in input order), "ran": N,
    "skipped": N, "seconds": wall time, "out": path}``.  Raises :class:`UsageError` (and
    :class:`.inputs.InputError`), the engines' errors, and ``KeyboardInterrupt`` with every
    finished row kept."""
    from .inputs import collect
    from .store import Store, need_arrow
    out = Path(out)
    if out.suffix.lower() not in (".parquet", ".jsonl"):
        raise UsageError(f"-o `{out}`: the output must end in .parquet or .jsonl")
    if out.is_dir():
        raise UsageError(f"-o `{out}` is a directory; give a file name such as {out / 'rows.jsonl'}")
    from ..output.writers.write import not_regular, refusal
    kind = not_regular(out)         # a FIFO, a device: never replaced (the end's write_atomic)
    if kind is not None:
        raise UsageError("-o " + refusal(out, kind))
    if out.suffix.lower() == ".parquet":
        need_arrow()
    if render and not out_dir:
        raise UsageError("--render needs --out-dir DIR (the folder for the files)")
    if render:
        _check_writers(list(render))
    workers = workers or default_workers()
    timeout = timeout or wall_limit(DEFAULT_BUDGET.seconds * budget)
    # absolute: the workers (Dask's too) write there whatever their working folder
    cfg = {"render": list(render), "out_dir": os.path.abspath(out_dir) if render else None,
           "min_wall": min_wall}
    store = Store(out)
    for mine in (out, store.journal):
        if os.path.islink(mine):       # as `aidl render` refuses: the rows would go elsewhere
            raise UsageError(f"-o: `{mine}` is a symbolic link; refusing to write through it "
                             "(give the file it points to, or another name)")
    for item in inputs:
        for mine in (out, store.journal):
            if mine.exists() and Path(item).exists() and os.path.samefile(mine, item):
                raise UsageError(f"-o `{out}` would write over the input `{item}`")
    from .store import check_result
    try:
        check_result(out)
    except Exception as e:             # NotAResult, pyarrow's ArrowInvalid, a read error
        raise UsageError(f"cannot resume from `{out}`: it is not a batch result ({e}); give "
                         "another -o or delete it") from None
    tasks = collect(inputs, overrides or {}, budget, cfg)
    out.parent.mkdir(parents=True, exist_ok=True)
    try:
        done = store.load()
    except Exception as e:             # pyarrow's ArrowInvalid: not a Parquet file
        raise UsageError(f"cannot resume from `{out}`: it is not a batch result "
                         f"({type(e).__name__}: {e}); give another -o or delete it") from None
    todo = [t for t in tasks
            if not (t["id"] in done and done[t["id"]].get("sha256") == t["sha256"]
                    and done[t["id"]].get("options") == t["options"])]
    rows: dict[str, dict] = {t["id"]: done[t["id"]] for t in tasks if t["id"] in done}
    t0 = time.perf_counter()
    bar = _progress(progress, console)
    store.open()
    try:
        with bar:
            job = bar.add_task("compiling", total=len(todo))

            def record(row: dict) -> None:
                store.append(row)
                rows[row["id"]] = row
                bar.advance(job)
                if on_row is not None:
                    on_row(row)

            if todo and scheduler:
                from .cluster import run_dask
                run_dask(todo, cfg, scheduler, workers, timeout, record)
            elif todo:
                from .local import run_local
                run_local(todo, cfg, workers, timeout, record)
    finally:
        store.close()
    store.finish([t["id"] for t in tasks])
    return {"rows": [rows[t["id"]] for t in tasks], "ran": len(todo),
            "skipped": len(tasks) - len(todo), "seconds": time.perf_counter() - t0,
            "out": str(out)}


def _progress(show: bool, console):
    from rich.console import Console
    from rich.progress import (BarColumn, MofNCompleteColumn, Progress, ProgressColumn,
                               TextColumn, TimeElapsedColumn, TimeRemainingColumn)
    from rich.text import Text

    class Rate(ProgressColumn):
        def render(self, task):
            speed = task.finished_speed or task.speed
            return Text("-/s" if speed is None else f"{speed:.1f}/s")

    return Progress(TextColumn("{task.description}"), BarColumn(), MofNCompleteColumn(),
                    Rate(), TimeElapsedColumn(), TextColumn("ETA"), TimeRemainingColumn(),
                    console=console or Console(stderr=True), disable=not show)


def percentile(values: list[float], q: float) -> float:
    """The ``q`` percentile (0-100) by linear interpolation, as ``numpy.percentile``."""
    xs = sorted(values)
    if not xs:
        return float("nan")
    k = (len(xs) - 1) * q / 100
    lo = int(k)
    hi = min(lo + 1, len(xs) - 1)
    return xs[lo] + (xs[hi] - xs[lo]) * (k - lo)


def summary(result: dict, where: str) -> "object":
    """The end-of-batch table (a rich renderable)."""
    from rich.table import Table
    rows = result["rows"]
    status = Counter(r["status"] for r in rows)
    errors = Counter(d["code"] for r in rows for d in r["errors"])
    warnings = Counter(d["code"] for r in rows for d in r["warnings"])
    with_warn = sum(1 for r in rows if r["ok"] and r["warnings"])
    seconds = result["seconds"]
    t = Table(title=f"aidl batch: {len(rows)} programs -> {result['out']}", show_header=False,
              title_justify="left")
    t.add_column(style="bold")
    t.add_column()
    t.add_row("run now", f"{result['ran']} in {seconds:.1f} s "
              f"({result['ran'] / seconds if seconds > 0 else 0:.1f} programs/s, {where})")
    t.add_row("already done", str(result["skipped"]))
    t.add_row("ok", f"{status['ok']} ({with_warn} with warnings)")
    t.add_row("errors", str(status["error"]))
    t.add_row("timed out", str(status["timeout"]))
    t.add_row("crashed", str(status["crashed"]))
    t.add_row("error codes", _codes(errors))
    t.add_row("warning codes", _codes(warnings))
    times = [r["compile_s"] for r in rows if r["compile_s"] is not None
             and r["status"] in ("ok", "error")]
    if times:
        t.add_row("time per program", "  ".join(
            f"p{q} {percentile(times, q) * 1000:.0f} ms" for q in (50, 90, 99))
            + f"  max {max(times) * 1000:.0f} ms")
    return t


def _codes(counts: Counter) -> str:
    return ", ".join(f"{c} x{n}" for c, n in sorted(counts.items(), key=lambda kv: (-kv[1], kv[0]))) or "-"


def _overrides(items: list[str]) -> dict[str, str]:
    out = {}
    for it in items:
        if "=" not in it:
            raise UsageError(f"--set expects NAME=VALUE, got `{it}`")
        k, v = it.split("=", 1)
        out[k.strip()] = v.strip()
    return out


def main(args) -> int:
    """``aidl batch`` (arguments from :func:`add_arguments`)."""
    from .inputs import InputError
    from .store import MissingArrow
    from .cluster import MissingDask
    try:
        try:
            import rich  # noqa: F401
        except ImportError:
            raise UsageError("`aidl batch` needs the batch extra (rich is missing): "
                             "pip install 'aidl-lang[batch]'") from None
        render = _formats(args.render)
        if args.out_dir and not render:
            raise UsageError("--out-dir is for --render's files; give --render svg (or more)")
        if args.scheduler:
            try:
                import dask.distributed  # noqa: F401
            except ImportError as e:
                raise MissingDask(f"--scheduler needs Dask ({e.name} is missing): "
                                  "pip install 'aidl-lang[dask]'") from None
        where = (f"Dask at {args.scheduler}" if args.scheduler and args.scheduler != "local"
                 else f"LocalCluster of {args.workers or default_workers()} workers"
                 if args.scheduler else f"{args.workers or default_workers()} local workers")
        result = run_batch(args.inputs, args.output, render=render, out_dir=args.out_dir,
                           workers=args.workers, scheduler=args.scheduler, budget=args.budget,
                           overrides=_overrides(args.set), timeout=args.timeout,
                           min_wall=args.min_wall,
                           progress=not args.no_progress and sys.stderr.isatty())
    except (UsageError, InputError, MissingArrow, MissingDask) as e:
        print(f"aidl: error: {e}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        from .store import Store
        print(f"aidl: interrupted; every finished row is in {Store(Path(args.output)).journal}: "
              "run the same command again to go on", file=sys.stderr)
        return 130
    except OSError as e:
        print(f"aidl: error: {e.strerror or e}" + (f": `{e.filename}`" if e.filename else ""),
              file=sys.stderr)
        return 1
    from rich.console import Console
    Console().print(summary(result, where))
    return 0


__all__ = ["add_arguments", "main", "run_batch", "summary", "TIMINGS"]
