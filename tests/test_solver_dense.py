"""Small systems stay dense and SciPy-free (issue 12): solving every bundled example, the
bracket's 59-row x 8-unknown systems included, imports no SciPy; a large system still uses
the sparse path and gets the same step as the dense one."""
from __future__ import annotations

import pathlib
import subprocess
import sys

import numpy as np

from aidl_lang.solver.core.newton import _Step, dense_enough

ROOT = pathlib.Path(__file__).resolve().parents[1]

_CHILD = """
import pathlib, sys
from aidl_lang.pipeline import compile_source
bad = []
for p in sorted(pathlib.Path(sys.argv[1]).glob('*.aidl')):
    c = compile_source(p.read_text(), str(p))
    if not c.ok or not c.solve.converged:
        bad.append(p.name)
print('scipy' in sys.modules, len(list(pathlib.Path(sys.argv[1]).glob('*.aidl'))), bad)
"""


def test_solving_every_example_imports_no_scipy():
    out = subprocess.run([sys.executable, "-c", _CHILD, str(ROOT / "examples")],
                         capture_output=True, text=True, timeout=120, cwd=ROOT)
    assert out.returncode == 0, out.stderr
    scipy_loaded, n, bad = out.stdout.strip().split(" ", 2)
    assert int(n) >= 10 and bad == "[]"
    assert scipy_loaded == "False"


def test_the_dense_rule():
    assert dense_enough(59, 8)              # the bracket: many rows, few unknowns
    assert dense_enough(48, 192)
    assert not dense_enough(400, 400)
    assert not dense_enough(2000, 10)


def test_sparse_and_dense_steps_agree():
    import scipy.sparse as sp
    rng = np.random.default_rng(3)
    m, n = 300, 420
    J = sp.random(m, n, density=0.01, random_state=4, format="csr") + sp.eye(m, n, format="csr")
    F = rng.normal(size=m)
    assert not dense_enough(m, n)
    sparse = _Step(J.tocsr(), dense=False)
    assert not sparse.dense
    dense = _Step(J.toarray(), dense=True)
    for mu in (1e-12, 1e-3, 10.0):
        a, b = sparse(F, mu), dense(F, mu)
        assert np.allclose(a, b, rtol=1e-9, atol=1e-12)
        assert np.linalg.norm(a) > 0.1
