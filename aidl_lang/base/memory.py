"""Memory: the process's address-space cap, and the cyclic garbage collector held off while a
stage builds a large acyclic structure.

**The cap** (:func:`limit_memory`, :func:`default_cap`): ``aidl check``, ``render``, ``parts``
and ``import`` cap their own address space (Linux ``RLIMIT_AS``), as the servers' workers
do, so that a program needing more memory than the machine has gets a ``MemoryError`` (a
located ``E0304``) instead of taking the machine down (issue 58).  The default is
:data:`DEFAULT_SHARE` of the machine's memory (``MemTotal``, or the cgroup's limit when that is
lower), at least :data:`MIN_CAP`: address space counts what NumPy, OpenBLAS, Manifold and the
compile thread's stack reserve without using (about 1 GB at the start of a render).

**The collector** (:func:`gc_paused`): the parser's AST, the interpreter's model, the solver's
rows and tape each allocate hundreds of thousands of small objects that reference counting
frees, and the collector's passes over them were a quarter to a half of those stages' time
(docs/dev/performance.md: the parser, "The interpreter", the solver's rows and compile).  The
stages after the solve (the booleans and the shape checks, the exact outlines, a writer) are
paused too: each full pass walked the model's structures again (a perforated sheet of 20,000
holes: 861 passes, 0.68 s CPU of its render).
"""
from __future__ import annotations

import gc
import os
from contextlib import contextmanager

DEFAULT_SHARE = 0.5          # of the machine's (or the cgroup's) memory: the default cap
MIN_CAP = 3 << 30            # bytes: the default cap is never below this (reservations)
_raise_with: str | None = None     # how the user raises the cap set last (`--memory SIZE`)


def machine_memory() -> int | None:
    """The memory this process may use in bytes: ``MemTotal`` of /proc/meminfo, or the
    memory limit of its cgroup (v2 ``memory.max``, v1 ``memory.limit_in_bytes``) when that is
    lower; None where neither can be read (not Linux)."""
    total = None
    try:
        with open("/proc/meminfo") as f:
            for line in f:
                if line.startswith("MemTotal:"):
                    total = int(line.split()[1]) * 1024
                    break
    except (OSError, ValueError, IndexError):
        pass
    for limit in _cgroup_limits():
        if total is None or limit < total:
            total = limit
    return total


def _cgroup_limits():
    """The memory limits of this process's cgroups, in bytes (no "max", no v1 "unlimited")."""
    paths = []
    try:
        with open("/proc/self/cgroup") as f:
            for line in f:
                _, ctrl, path = line.rstrip("\n").split(":", 2)
                if ctrl == "":
                    paths.append(f"/sys/fs/cgroup{path}/memory.max")
                elif "memory" in ctrl.split(","):
                    paths.append(f"/sys/fs/cgroup/memory{path}/memory.limit_in_bytes")
    except (OSError, ValueError):
        return
    paths += ["/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes"]
    for p in paths:
        try:
            with open(p) as f:
                v = f.read().strip()
        except OSError:
            continue
        if v.isdigit() and int(v) < 1 << 60:       # v1 says "unlimited" with a huge number
            yield int(v)


def default_cap() -> int | None:
    """The default address-space cap in bytes: :data:`DEFAULT_SHARE` of
    :func:`machine_memory`, at least :data:`MIN_CAP`; None when the memory is unknown."""
    total = machine_memory()
    if total is None:
        return None
    return max(MIN_CAP, int(total * DEFAULT_SHARE))


def parse_size(text: str) -> int | None:
    """``4G``, ``1500M``, ``2.5GB``, ``800MiB``, ``none`` / ``0`` as bytes (None: no cap);
    a bare number is megabytes (as ``aidl studio --memory MB``).  Raises ``ValueError``."""
    t = str(text).strip().lower().replace(" ", "")
    if t in ("none", "off", "0", "unlimited"):
        return None
    units = {"": 1 << 20, "k": 1 << 10, "m": 1 << 20, "g": 1 << 30, "t": 1 << 40}
    for suffix in ("ib", "b"):
        if t.endswith(suffix) and t[:-len(suffix)][-1:] in "kmgt" and len(t) > len(suffix):
            t = t[:-len(suffix)]
            break
    unit = t[-1:] if t[-1:] in "kmgt" else ""
    num = t[:-1] if unit else t
    try:
        v = float(num)
    except ValueError:
        raise ValueError(f"`{text}` is not a size such as 4G, 1500M or none") from None
    if not v > 0 or v != v or v == float("inf"):
        raise ValueError(f"`{text}` is not a size such as 4G, 1500M or none")
    return int(v * units[unit])


def limit_memory(limit: int | None, raise_with: str | None = None) -> None:
    """Cap this process's address space at ``limit`` bytes (Linux ``RLIMIT_AS``; None: no
    cap of its own, the inherited one stays): a program that needs more gets a
    ``MemoryError`` or ends its worker, never the machine's memory.  A cap already lower
    (``ulimit -v``) is kept.  ``raise_with``: how the user raises it (``--memory SIZE``),
    for the ``E0304`` hint."""
    global _raise_with
    if not limit:
        return
    try:
        import resource
        soft, hard = resource.getrlimit(resource.RLIMIT_AS)
        cap = limit if hard == resource.RLIM_INFINITY else min(limit, hard)
        if soft == resource.RLIM_INFINITY or soft > cap:
            resource.setrlimit(resource.RLIMIT_AS, (cap, hard))
            _raise_with = raise_with
    except (ImportError, ValueError, OSError):      # not on this platform
        pass


def memory_cap() -> tuple[int | None, str | None]:
    """This process's address-space cap in bytes (None: none) and how its user raises it
    (the ``raise_with`` of the :func:`limit_memory` that set it, else None)."""
    try:
        import resource
        soft, _ = resource.getrlimit(resource.RLIMIT_AS)
    except (ImportError, ValueError, OSError):
        return None, None
    if soft == resource.RLIM_INFINITY:
        return None, None
    return soft, _raise_with


# of the cap: the interpreter stops (a MemoryError at a point of its own) once its address
# space passes this share of the cap, before an allocation fails inside CPython
GUARD_SHARE = 0.9


def address_space() -> int | None:
    """This process's address space in bytes (``VmSize``: /proc/self/statm's first field),
    None where it cannot be read (not Linux)."""
    try:
        fd = os.open("/proc/self/statm", os.O_RDONLY)
        try:
            pages = int(os.read(fd, 64).split()[0])
        finally:
            os.close(fd)
        return pages * os.sysconf("SC_PAGE_SIZE")
    except (OSError, ValueError, IndexError):
        return None


def guard_limit() -> int | None:
    """The address space (bytes) past which the interpreter raises ``MemoryError`` itself,
    :data:`GUARD_SHARE` of the cap; None without a cap.  An allocation that fails inside
    CPython 3.11 can leave a call site's specialised inline cache broken, so the process's
    next compile crashed (a segmentation fault) or called the wrong function (a TypeError)
    in about half of the runs of tests/test_hostile.py's 600 MB fan of templates; stopped at
    a point of its own, the interpreter unwinds cleanly and the next compile runs."""
    cap, _ = memory_cap()
    return int(cap * GUARD_SHARE) if cap else None


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
