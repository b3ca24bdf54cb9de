"""What the records' generated methods cost a cold ``aidl check`` (callgrind):

    .venv/bin/python benchmarks/compile/record_methods.py

On Python 3.11 ``dataclasses`` writes each method of a record (``__init__``, ``__repr__``,
``__eq__``, and for ``frozen=True`` ``__hash__``, ``__setattr__`` and ``__delattr__``) as
source text and runs it through Python's parser and compiler at import
(``dataclasses._create_fn``, one ``exec`` per method); a method written in a module is in
its ``.pyc`` and costs nothing of that.  This measures the check's own imports (the
``aidl_lang modules`` stage of ``benchmarks/compile/cold_stages.py``: one fresh process under
callgrind, ended by ``os._exit``) as they are, and with the methods of one kind (then all)
made by a stub instead of compiled: the difference is what compiling them costs.  It also
lists the records and methods per module (a run without callgrind).  ``PYTHONHASHSEED=0``,
one BLAS thread, bytecode compiled first, run from an empty folder, as ``cold_stages.py``.
"""
from __future__ import annotations

import subprocess
import sys

from cold_stages import ENV, ROOT, callgrind

_BASE = "import os, numpy, manifold3d, argparse, json, dataclasses, threading, gettext, copy, zlib\n"
_MODULES = ("import aidl_lang.cli.main, aidl_lang.api, aidl_lang.pipeline, "
            "aidl_lang.solver.diagnosis.diagnose, aidl_lang.output.checks\n")
_STUB = '''
made = dataclasses._create_fn
def stub(name, *args, **kwargs):
    if name not in STUBBED:
        return made(name, *args, **kwargs)
    def fn(*a, **k):
        return None
    fn.__name__ = fn.__qualname__ = name
    return fn
dataclasses._create_fn = stub
'''
_COUNT = '''
import collections
made = dataclasses._create_fn
count = collections.Counter()
records = collections.defaultdict(set)
def spy(name, *args, **kwargs):
    f = sys._getframe(1)
    while f.f_code.co_name != "_process_class":
        f = f.f_back
    cls = f.f_locals["cls"]
    count[cls.__module__] += 1
    records[cls.__module__].add(cls.__name__)
    return made(name, *args, **kwargs)
dataclasses._create_fn = spy
'''
KINDS = [("__init__",), ("__repr__",), ("__eq__",), ("__hash__", "__setattr__", "__delattr__")]


def main() -> None:
    subprocess.run([sys.executable, "-m", "compileall", "-q", str(ROOT / "aidl_lang")],
                   stdout=subprocess.DEVNULL, env=ENV, check=False)
    out = subprocess.run([sys.executable, "-c", "import sys\n" + _BASE + _COUNT + _MODULES
                          + "for m, n in count.most_common(): print(n, len(records[m]), m)"],
                         capture_output=True, text=True, env=ENV, cwd="/", check=True).stdout
    rows = [line.split() for line in out.splitlines()]
    print(f"{sum(int(r[1]) for r in rows)} records, {sum(int(r[0]) for r in rows)} generated "
          "methods on a check's import path:")
    for n, k, m in rows:
        print(f"  {m:<40} {k:>3} records {n:>4} methods")
    floor = callgrind("-c", _BASE + "os._exit(0)")
    whole = callgrind("-c", _BASE + _MODULES + "os._exit(0)")
    print(f"\nthe check's own imports: {whole - floor:.1f} M instructions "
          f"(over Python, NumPy, Manifold and the standard modules: {floor:.1f} M)")
    for kinds in KINDS + [tuple(k for ks in KINDS for k in ks)]:
        stubbed = callgrind("-c", _BASE + f"STUBBED = {kinds!r}\n" + _STUB + _MODULES
                            + "os._exit(0)")
        print(f"  compiling {', '.join(kinds) if len(kinds) < 6 else 'all of them'}: "
              f"{whole - stubbed:.1f} M")


if __name__ == "__main__":
    main()
