"""The resident memory of a studio compile worker as sessions accumulate (docs/studio.md,
"The picture is the sliders'"): one ``aidl studio --compilers 2``, a new session per gallery
entry (each worker keeps at most ``compiler.MAX_SESSIONS`` warm sessions), then every gallery
picture.  Prints each worker's resident MB (``/api/stats``) after 1, 10, 20 and all entries.

    python benchmarks/serve/studio_memory.py
"""
from __future__ import annotations

import json
import sys
import urllib.request
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parents[2]))

from benchmarks.serve.studio_server import studio  # noqa: E402


def post(url: str, path: str, body: dict) -> dict:
    r = urllib.request.Request(url + path, data=json.dumps(body).encode(),
                               headers={"Content-Type": "application/json"})
    with urllib.request.urlopen(r, timeout=300) as f:
        return json.load(f)


def main() -> None:
    from aidl_lang.studio import gallery
    with studio("--compilers", "2") as (url, _proc):
        url = url.rstrip("/")

        def mb() -> list[int]:
            with urllib.request.urlopen(url + "/api/stats") as f:
                return [round(w["rss"] / 2**20) for w in json.load(f)["workers"]]
        ids = [e.id for e in gallery.entries()]
        for i, eid in enumerate(ids):
            src = gallery.to_json(gallery.entry(eid), with_source=True)["source"]
            sid = post(url, "/api/session", {})["sid"]
            post(url, "/api/view", {"sid": sid, "source": src, "values": {}})
            if i + 1 in (1, 10, 20, len(ids)):
                print(f"{i + 1:3d} sessions, one gallery entry each: workers {mb()} MB", flush=True)
        for eid in ids:
            urllib.request.urlopen(url + f"/api/thumb/{eid}.svg", timeout=300).read()
        print(f"and every gallery picture: workers {mb()} MB (0: not started)")


if __name__ == "__main__":
    main()
