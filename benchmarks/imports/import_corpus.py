"""``aidl import`` over a corpus of real drawings: what imports, what compiles, what is refused.

Run:  .venv/bin/python benchmarks/imports/import_corpus.py FOLDER [FOLDER ...] [--laser FOLDER ...]
      [--full-checks-below N] [-v]

Every ``.dxf``, ``.svg`` (and ``.dxf.gz``/``.svg.gz``) file of the folders is imported as
``aidl import FILE`` does (:func:`aidl_lang.drawing.program.import_drawing`, the default
budget; the folders after ``--laser`` with ``--roles laser``, Boxes.py's colours), and the
program it writes is compiled by the real compiler (:func:`aidl_lang.pipeline.compile_source`).
Every program is compiled with every check, as ``aidl check`` does; ``--full-checks-below N``
compiles a program of more than N segments without the final-part geometry checks (warnings
only, W05xx; ``pipeline._compile(shape_checks=False)``), which were quadratic in the
segments when this benchmark was first written (issue 58; bounded since, and measured in
benchmarks/checks/checks_scaling.py and dense_drawings.py).  A folder may be given both plain and
after ``--laser`` (Boxes.py's SVGs both ways).

Prints one row per folder and a total: files, imported (a program written), compiled with no
error, refused cleanly (a :class:`~aidl_lang.drawing.model.DrawingError`, by code), tracebacks
(any other exception: must be 0), import seconds (total, and the slowest file), compile
seconds.  ``-v`` prints each file that failed to compile with its first errors, and each
traceback.  Exits 1 when a program failed to compile or an import raised.

The corpora measured for issue 58: ezdxf's sample DXFs (tests/data/ezdxf/, MIT) and the
example SVGs of Boxes.py (GPL-3.0, not in this repository: ``git clone
https://github.com/florianfesti/boxes`` and pass its ``static/samples`` folder with ``--laser``).
"""
from __future__ import annotations

import argparse
import collections
import gzip
import pathlib
import re
import sys
import time
import traceback

ROOT = pathlib.Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT))

from aidl_lang.base.diagnostics import DiagnosticSink  # noqa: E402
from aidl_lang.drawing.write.program import import_drawing  # noqa: E402
from aidl_lang.drawing.model import DrawingError  # noqa: E402
from aidl_lang.pipeline import _compile, compile_source, run_deep  # noqa: E402

SEGMENT = re.compile(r"= (?:Line|Arc|Circle|Spline|Bezier|Ellipse|Text)\(")


def files_of(folder: pathlib.Path) -> list[pathlib.Path]:
    return sorted(p for p in folder.iterdir()
                  if re.search(r"\.(dxf|svg)(\.gz)?$", p.name, re.I) and p.is_file())


def read(p: pathlib.Path) -> tuple[bytes, str]:
    """The bytes of ``p`` (unzipped) and the name it is imported under (without ``.gz``)."""
    data = p.read_bytes()
    if p.name.endswith(".gz"):
        return gzip.decompress(data), p.name[:-3]
    return data, p.name


def compile_program(text: str, name: str, full_below: float):
    """The compiled program and whether the final-part checks ran."""
    n = len(SEGMENT.findall(text))
    if n < full_below:
        return compile_source(text, name), True
    sink = DiagnosticSink()
    return run_deep(lambda: _compile(sink, text, name, None, True, shape_checks=False)), False


def run(folder: pathlib.Path, laser: bool, full_below: float, verbose: bool) -> dict:
    row = collections.Counter()
    refused = collections.Counter()
    slowest = (0.0, "")
    for p in files_of(folder):
        row["files"] += 1
        data, name = read(p)
        t0 = time.perf_counter()
        try:
            text, _notes = import_drawing(data, name, roles="laser" if laser else None)
        except DrawingError as ex:
            refused[ex.code] += 1
            row["refused"] += 1
            continue
        except Exception:                                   # noqa: BLE001 - what we count
            row["tracebacks"] += 1
            if verbose:
                print(f"--- {p.name}: traceback\n{traceback.format_exc()}")
            continue
        finally:
            took = time.perf_counter() - t0
            row["import_s"] += took
            slowest = max(slowest, (took, p.name))
        row["imported"] += 1
        t0 = time.perf_counter()
        try:
            c, full = compile_program(text, name.rsplit(".", 1)[0] + ".aidl", full_below)
        except Exception:                                   # noqa: BLE001
            row["compile tracebacks"] += 1
            if verbose:
                print(f"--- {p.name}: compile traceback\n{traceback.format_exc()}")
            continue
        finally:
            row["compile_s"] += time.perf_counter() - t0
        row["unchecked"] += not full
        errors = [d for d in c.sink.items if d.is_error]
        if errors:
            row["failed"] += 1
            if verbose:
                print(f"--- {p.name}: {len(errors)} errors")
                for d in errors[:3]:
                    print(f"    {d.code} {d.message[:160]}")
        else:
            row["compiled"] += 1
    row["slowest"] = slowest
    row["codes"] = refused
    return row


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("folders", nargs="*", type=pathlib.Path)
    ap.add_argument("--laser", nargs="*", type=pathlib.Path, default=[],
                    help="folders imported with --roles laser")
    ap.add_argument("--full-checks-below", type=float, default=float("inf"))
    ap.add_argument("-v", "--verbose", action="store_true")
    a = ap.parse_args(argv)
    rows = [(f, False, run(f, False, a.full_checks_below, a.verbose)) for f in a.folders] + \
           [(f, True, run(f, True, a.full_checks_below, a.verbose)) for f in a.laser]
    head = (f"{'corpus':<28} {'files':>5} {'imported':>8} {'compiled':>8} {'failed':>6} "
            f"{'refused (codes)':<22} {'tracebacks':>10} {'import s':>8} {'compile s':>9}  "
            f"slowest import")
    print(head, flush=True)
    total = collections.Counter()
    codes = collections.Counter()
    for f, laser, r in rows:
        c = ", ".join(f"{k} {v}" for k, v in sorted(r["codes"].items())) or "-"
        tb = r["tracebacks"] + r["compile tracebacks"]
        print(f"{f.name + (' (--roles laser)' if laser else ''):<28} {r['files']:>5} "
              f"{r['imported']:>8} {r['compiled']:>8} {r['failed']:>6} "
              f"{str(r['refused']) + ' (' + c + ')':<22} {tb:>10} {r['import_s']:>8.1f} "
              f"{r['compile_s']:>9.1f}  {r['slowest'][1]} {r['slowest'][0]:.2f} s")
        for k in ("files", "imported", "compiled", "failed", "refused", "tracebacks",
                  "compile tracebacks", "import_s", "compile_s", "unchecked"):
            total[k] += r[k]
        codes.update(r["codes"])
    c = ", ".join(f"{k} {v}" for k, v in sorted(codes.items())) or "-"
    tb = total["tracebacks"] + total["compile tracebacks"]
    print(f"{'total':<28} {total['files']:>5} {total['imported']:>8} {total['compiled']:>8} "
          f"{total['failed']:>6} {str(total['refused']) + ' (' + c + ')':<22} {tb:>10} "
          f"{total['import_s']:>8.1f} {total['compile_s']:>9.1f}")
    if total["unchecked"]:
        print(f"({total['unchecked']} programs of {a.full_checks_below:g} or more segments "
              "compiled without the final-part checks)")
    return 1 if total["failed"] or tb else 0


if __name__ == "__main__":
    sys.exit(main())
