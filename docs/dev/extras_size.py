"""Installed size of each extra of aidl-lang (README.md, "Extras"): the distributions the
extra adds beyond the core's (its requirements followed transitively with
importlib.metadata), summed over the files each of them installed (their RECORD).

Run in a venv with every extra installed:  .venv/bin/python docs/dev/extras_size.py
"""
from __future__ import annotations

import os
import re
from importlib import metadata as md

from packaging.requirements import Requirement

EXTRAS = ["pdf", "png", "mesh", "step", "layout", "mcp", "batch", "dask", "studio", "notebook"]


def key(n: str) -> str:
    return re.sub(r"[-_.]+", "-", n).lower()


DISTS = {key(d.metadata["Name"]): d for d in md.distributions()}


def size(name: str) -> int:
    total = 0
    for f in DISTS[name].files or []:
        try:
            total += os.path.getsize(f.locate())
        except OSError:
            pass
    return total


def closure(reqs: list[Requirement]) -> set[str]:
    """The installed distributions ``reqs`` pull in, with their own requirements."""
    seen, todo = set(), list(reqs)
    while todo:
        r = todo.pop()
        n = key(r.name)
        if n in seen or n not in DISTS:
            continue
        seen.add(n)
        for text in DISTS[n].requires or []:
            q = Requirement(text)
            if q.marker is None or any(q.marker.evaluate({"extra": e})
                                       for e in ("", *r.extras)):
                todo.append(q)
    return seen


def main() -> None:
    reqs = [Requirement(t) for t in DISTS["aidl-lang"].requires]
    core = closure([r for r in reqs if r.marker is None])
    print(f"core: {len(core)} distributions, {sum(map(size, core)) / 1e6:.0f} MB")

    def of(extra: str) -> list[Requirement]:
        out = []
        for r in reqs:
            if r.marker is not None and r.marker.evaluate({"extra": extra}):
                out += of_all(r)
        return out

    def of_all(r: Requirement) -> list[Requirement]:
        if key(r.name) == "aidl-lang":             # an extra of another extra
            return [q for e in r.extras for q in of(e)]
        return [r]
    for extra in EXTRAS:
        add = closure(of(extra)) - core
        print(f"{extra}: {sum(map(size, add)) / 1e6:.0f} MB ({', '.join(sorted(add))})")


if __name__ == "__main__":
    main()
