"""The 3D view's GLB of every gallery entry, before and after issue 62 (docs/studio.md, "The 3D
view keeps up"): bytes and server time of the GLB download path (a fresh compile and the exact
writer, what the page loaded before) and of the view path (``("glb", ...)`` after the
entry's ``view``, as the page asks now: the picture's own outlines, ``to_view_glb``).

    python benchmarks/serve/studio_glb.py            # the slowest three of each, and the totals
"""
from __future__ import annotations

import gzip
import tempfile
import time
from collections import OrderedDict


def main() -> None:
    from aidl_lang.output.writers.mesh import _trimesh
    from aidl_lang.studio import compiler, gallery
    _trimesh()                              # the workers import it when they start
    folder = tempfile.mkdtemp(prefix="aidl-glb-")
    sessions: OrderedDict = OrderedDict()
    before, after = [], []
    for i, e in enumerate(gallery.entries()):
        t0 = time.perf_counter()
        got = compiler.download(folder, e.source, {}, "glb", {"assembled": True, "layout": False})
        t1 = time.perf_counter()
        if not isinstance(got, dict):
            before.append((t1 - t0, e.id, len(got[0]), None))
        compiler.view(sessions, f"s{i}", folder, e.source, {})
        t2 = time.perf_counter()
        got = compiler.view_glb(sessions, f"s{i}", folder, e.source, {}, {})
        t3 = time.perf_counter()
        if not isinstance(got, dict):
            after.append((t3 - t2, e.id, len(got[0]), len(gzip.compress(got[0], 6))))
    for name, rows in (("before (compile + exact GLB)", before),
                       ("after (the picture's outlines, view GLB)", after)):
        rows.sort(reverse=True)
        print(name)
        for s, eid, size, gz in rows[:3]:
            print(f"  {eid:32s} {size:>9,} B{f' (gzip {gz:,})' if gz else ''}  {1000 * s:7.0f} ms")
        gz = sum(r[3] or 0 for r in rows)
        print(f"  all {len(rows)}: {sum(r[2] for r in rows):,} B{f' (gzip {gz:,})' if gz else ''}, "
              f"{sum(r[0] for r in rows):.1f} s")


if __name__ == "__main__":
    main()
