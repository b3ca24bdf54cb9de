"""The simulated studio user of benchmarks/serve/studio_load.py (a Locust file).

A user opens a session, takes one design from the gallery and edits it as a person would:
every 2-6 s a changed param value (a slider let go), and one action in ten a download.  The
studio's "busy" answer (503 with Retry-After) is counted apart from failures: it is the
designed answer past capacity, which the page shows and retries.
"""
from __future__ import annotations

import random

from locust import HttpUser, between, events, task

DESIGNS = ["example/bracket", "example/name_tag", "example/mounting_plate", "example/key",
           "generator/divider_tray", "example/ruler", "example/wrench"]
BUSY = {"count": 0}


@events.request.add_listener
def _count_busy(request_type, name, response=None, **kw):
    if response is not None and getattr(response, "status_code", 0) == 503:
        BUSY["count"] += 1


class Maker(HttpUser):
    wait_time = between(2, 6)

    def on_start(self):
        self.sid = self.client.post("/api/session").json()["sid"]
        self.design = random.choice(DESIGNS)
        entry = self.client.get(f"/api/gallery/{self.design}", name="/api/gallery/ID").json()
        self.source = entry["source"]
        self.params = [p for p in entry.get("params") or []
                       if p.get("kind") in ("length", "number") and p.get("min") is not None]
        self.view({})

    def view(self, values):
        with self.client.post("/api/view", json={"sid": self.sid, "source": self.source,
                                                 "values": values},
                              catch_response=True) as r:
            if r.status_code == 503:
                r.success()             # the designed busy answer (counted apart)
            elif r.status_code != 200 or "svg" not in r.json():
                r.failure(f"HTTP {r.status_code}: {r.text[:120]}")

    @task(9)
    def move_slider(self):
        values = {}
        if self.params:
            p = random.choice(self.params)
            lo, hi, step = p["min"], p["max"], p.get("step") or 1
            v = lo + round(random.random() * (hi - lo) / step) * step
            values[p["name"]] = f"{v:g}" + ("mm" if p["kind"] == "length" else "")
        self.view(values)

    @task(1)
    def download(self):
        fmt, settings = random.choice([("dxf", {"layout": True}), ("glb", {"assembled": True})])
        with self.client.post(f"/api/download/{fmt}", name=f"/api/download/{fmt}",
                              json={"sid": self.sid, "source": self.source, "values": {},
                                    "settings": settings}, catch_response=True) as r:
            if r.status_code == 503:
                r.success()
            elif r.status_code != 200 or not r.content:
                r.failure(f"HTTP {r.status_code}: {r.text[:120]}")
