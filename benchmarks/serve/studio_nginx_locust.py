"""The simulated visitor of benchmarks/serve/studio_nginx_load.py (a Locust file): the person of
benchmarks/serve/studio_locust.py (a session, a gallery design, a slider moved every 2-6 s, one
action in ten a download), who also uploads a drawing at the start and, now and then, checks
that it is still there (``GET /api/files``): with the studio processes sharing one Redis, no
upload may vanish when the process that took it is killed.  Answers ``503`` (busy) are
counted apart (the page shows them and retries); the counts go to the JSON file named by
``AIDL_LOAD_OUT`` when the run stops."""
from __future__ import annotations

import json
import os
import sys
from pathlib import Path

from locust import events, task

sys.path.insert(0, str(Path(__file__).resolve().parent))
import studio_locust as base  # noqa: E402

BOARD = (Path(__file__).resolve().parents[2] / "examples" / "parts" /
         "pcb_board.dxf").read_bytes()
LOST = {"count": 0}


@events.test_stop.add_listener
def _write(environment, **kw):
    out = os.environ.get("AIDL_LOAD_OUT")
    if out:
        Path(out).write_text(json.dumps({"busy": base.BUSY["count"], "lost": LOST["count"]}))


class Visitor(base.Maker):
    def on_start(self):
        super().on_start()
        with self.client.post(f"/api/upload?sid={self.sid}&name=board.dxf", data=BOARD,
                              name="/api/upload", catch_response=True) as r:
            if r.status_code == 503:
                r.success()
            elif r.status_code != 200:
                r.failure(f"HTTP {r.status_code}: {r.text[:120]}")

    @task(1)
    def check_upload(self):
        with self.client.get(f"/api/files?sid={self.sid}", name="/api/files",
                             catch_response=True) as r:
            if r.status_code == 503:
                r.success()
            elif r.status_code != 200:
                r.failure(f"HTTP {r.status_code}: {r.text[:120]}")
            elif [f["name"] for f in r.json()["files"]] != ["board.dxf"]:
                LOST["count"] += 1
                r.failure(f"the upload is gone: {r.text[:120]}")
