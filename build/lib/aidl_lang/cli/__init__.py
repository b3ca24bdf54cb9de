"""The ``aidl`` command line (thin: it parses arguments and calls the stages).

:mod:`.main` holds ``render``, ``check``, ``explain``, ``fmt`` and ``lsp``; :mod:`.llm` adds
``prompt``, ``generate`` and ``eval``.

Before numpy is imported, BLAS is held to one thread unless the user set
``OPENBLAS_NUM_THREADS`` (or ``OMP_``/``MKL_NUM_THREADS``): the matrices here are small
(freedom-count SVDs, Newton steps), and threaded OpenBLAS spun for seconds on a busy 2-core machine where one thread takes
milliseconds (``aidl check --dof examples/gear.aidl``: 0.67-1.99 s wall with threads, 0.46 s
with one).
"""
import os

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

from .main import entry, main  # noqa: E402

__all__ = ["entry", "main"]
