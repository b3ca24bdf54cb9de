"""The studio's health and metrics for its operator: ``GET /healthz`` and ``GET /metrics``
(issue 62; docs/studio.md, "Health and metrics").

``/healthz`` answers ``200`` when this process is *ready* (its compilers are up: a local
compile process alive, or the Dask cluster reachable with at least one worker; its store
reachable: Redis answers ``PING``), else ``503`` with the reason; either way the JSON says
``"live": true`` (the process answers).  ``/healthz?probe=live`` is the liveness probe alone
(``200`` while the process answers).  A process whose compile workers have not started yet
(they start on the first compile) starts one on the first readiness probe and answers
``503 starting`` until it is up, so a load balancer sends it no visitor before.

``/metrics`` is the Prometheus text format (``prometheus_client``), for *this* process (each
``aidl studio`` process is scraped on its own port; with ``--processes N`` behind one port a
scrape reaches one of them: run one process per port behind the proxy instead):

* ``aidl_studio_requests_total{route,method,status}``, ``aidl_studio_request_seconds{route}``
  (histogram): every HTTP request by route template (``/api/view``, ``/api/gallery/{id:path}``;
  an unknown path is ``other``);
* ``aidl_studio_compile_seconds{kind}`` (histogram): a compile request in a worker (``view``,
  ``download``, ``thumb``, ``sweep``: a sweep worker's range check), the wait for a worker
  included;
* ``aidl_studio_queue_length``: compile requests waiting for a worker;
* ``aidl_studio_busy_total`` (503s), ``aidl_studio_rate_limited_total`` (429s),
  ``aidl_studio_compile_timeouts_total``, ``aidl_studio_worker_restarts_total``;
* ``aidl_studio_worker_resident_bytes{worker}``: each compile process's memory, and
  ``process_resident_memory_bytes`` (this server process, ``prometheus_client``'s process
  collector).
"""
from __future__ import annotations

import threading
import time

from starlette.responses import JSONResponse, Response

BUCKETS = (0.01, 0.025, 0.05, 0.1, 0.25, 0.5, 1.0, 2.5, 5.0, 10.0, 30.0, 60.0)


class Metrics:
    """The Prometheus metrics of one studio (``studio``: :class:`.app.Studio`), in a registry
    of their own (several apps in one process, as the tests make, do not collide)."""

    def __init__(self, studio) -> None:
        from prometheus_client import CollectorRegistry, Counter, Histogram, ProcessCollector
        self.studio = studio
        self.registry = r = CollectorRegistry()
        ProcessCollector(registry=r)
        self.requests = Counter("aidl_studio_requests", "HTTP requests answered",
                                ["route", "method", "status"], registry=r)
        self.latency = Histogram("aidl_studio_request_seconds", "HTTP request latency",
                                 ["route"], buckets=BUCKETS, registry=r)
        self.compiles = Histogram("aidl_studio_compile_seconds",
                                  "compile requests, the wait for a worker included",
                                  ["kind"], buckets=BUCKETS, registry=r)
        r.register(_Live(studio))
        self.warming = False

    def compiled(self, kind: str, seconds: float) -> None:
        self.compiles.labels(kind=str(kind)).observe(seconds)

    def text(self) -> bytes:
        from prometheus_client import generate_latest
        return generate_latest(self.registry)

    # ---- /healthz
    def health(self, live_only: bool = False) -> JSONResponse:
        if live_only:
            return JSONResponse({"live": True})
        st = self.studio
        checks = {}
        try:
            st.folders.ping()
            checks["store"] = "ok"
        except Exception as e:  # noqa: BLE001 - reported, not raised
            checks["store"] = str(e) or type(e).__name__
        pool = st.pool
        if hasattr(pool, "ready"):                      # the Dask cluster
            ok, why = pool.ready()
            checks["compilers"] = "ok" if ok else why
        elif any(w.proc is not None and w.proc.is_alive() for w in pool.workers):
            checks["compilers"] = "ok"
        else:
            checks["compilers"] = "starting"
            self._warm_up()
        ready = all(v == "ok" for v in checks.values())
        return JSONResponse({"live": True, "ready": ready, "checks": checks},
                            status_code=200 if ready else 503,
                            headers={"Cache-Control": "no-store"})

    def _warm_up(self) -> None:
        """Start a compile worker in the background (once at a time)."""
        if self.warming:
            return
        self.warming = True
        pool, seconds = self.studio.pool, self.studio.settings.seconds

        def run():
            try:
                pool.request(("thumb", ""), seconds, 0)   # "" is no entry: answers at once
            except Exception:  # noqa: BLE001 - busy workers are up; a failure shows next probe
                pass
            finally:
                self.warming = False
        threading.Thread(target=run, name="aidl-studio-warm-up", daemon=True).start()

    def response(self) -> Response:
        from prometheus_client import CONTENT_TYPE_LATEST
        return Response(self.text(), media_type=CONTENT_TYPE_LATEST,
                        headers={"Cache-Control": "no-store"})


class RequestMetrics:
    """ASGI middleware: every HTTP request counted and timed by its route's template
    (``Starlette(middleware=[Middleware(RequestMetrics, metrics=..., routes=...)])``)."""

    def __init__(self, app, metrics: Metrics, routes: list) -> None:
        from starlette.routing import Match
        self.app, self.metrics, self.routes, self.none = app, metrics, routes, Match.NONE

    def route(self, scope) -> str:
        for r in self.routes:
            if r.matches(scope)[0] != self.none:
                return r.path
        return "other"

    async def __call__(self, scope, receive, send):
        if scope["type"] != "http":
            return await self.app(scope, receive, send)
        route = self.route(scope)
        status = {"code": 500}

        async def send_counted(message):
            if message["type"] == "http.response.start":
                status["code"] = message["status"]
            await send(message)
        t0 = time.perf_counter()
        try:
            await self.app(scope, receive, send_counted)
        finally:
            m = self.metrics
            m.latency.labels(route=route).observe(time.perf_counter() - t0)
            m.requests.labels(route=route, method=scope.get("method", ""),
                              status=str(status["code"])).inc()


class _Live:
    """The values read when scraped: queue, refusals, restarts, the workers' memory."""

    def __init__(self, studio) -> None:
        self.studio = studio

    def describe(self):
        return []

    def collect(self):
        from prometheus_client.core import CounterMetricFamily, GaugeMetricFamily
        st = self.studio
        pool = st.pool
        yield GaugeMetricFamily("aidl_studio_queue_length",
                                "compile requests waiting for a worker", value=pool.waiting)
        for name, key, about in (("busy", "busy", "busy answers (503)"),
                                 ("rate_limited", "limited", "rate-limited answers (429)"),
                                 ("compile_timeouts", "timeouts", "compiles stopped past time"),
                                 ("superseded", "superseded",
                                  "previews not compiled: a newer one of the session came")):
            yield CounterMetricFamily(f"aidl_studio_{name}", about, value=st.served[key])
        restarts = getattr(pool, "restarts", None)
        if restarts is None:
            restarts = sum(w.restarts for w in pool.workers)
        yield CounterMetricFamily("aidl_studio_worker_restarts",
                                  "compile processes killed or lost", value=restarts)
        mem = GaugeMetricFamily("aidl_studio_worker_resident_bytes",
                                "resident memory of each compile process", labels=["worker"])
        for i, w in enumerate(pool.workers):
            mem.add_metric([str(i)], w.rss())
        yield mem
