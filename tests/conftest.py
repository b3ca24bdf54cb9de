import os
import pathlib

import pytest

# One BLAS thread, as the `aidl` command uses (aidl_lang/cli/__init__.py): the matrices are
# small, and threaded OpenBLAS spun on a busy 2-core machine (one example's dense solves took
# 64 ms each instead of ~2 ms).  Set before anything imports NumPy.
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

ROOT = pathlib.Path(__file__).resolve().parent.parent
EXAMPLES = sorted((ROOT / "examples").glob("*.aidl"))


@pytest.fixture
def compile_text(tmp_path):
    from aidl_lang.pipeline import compile_source

    def run(src: str, name: str = "t.aidl", **kw):
        p = tmp_path / name
        p.write_text(src)
        return compile_source(src, str(p), **kw)
    return run
