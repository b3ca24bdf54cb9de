"""The studio as operators run it (issue 62): shared state in a real Redis, compiles on a real
Dask cluster, two studio processes (started by the image's entry script) behind a real nginx,
/healthz and /metrics.  Redis and nginx are Debian's programs: without them the tests that need
them skip (.ci/run installs them in its second pass)."""
from __future__ import annotations

import os
import signal
import threading
import time
from pathlib import Path

import pytest

pytest.importorskip("starlette")
pytest.importorskip("redis")
pytest.importorskip("prometheus_client")
from prometheus_client.parser import text_string_to_metric_families  # noqa: E402
from starlette.testclient import TestClient  # noqa: E402

from aidl_lang.studio.app import Settings, create_app  # noqa: E402
from aidl_lang.studio.sessions import MAX_FILES  # noqa: E402
from benchmarks.serve.studio_cluster import (free_port, get, nginx, nginx_path, post,  # noqa: E402
                                       redis_server, redis_server_path, studio_processes)

ROOT = Path(__file__).resolve().parent.parent
BRACKET = (ROOT / "examples" / "bracket.aidl").read_text()
BOARD = (ROOT / "examples" / "parts" / "pcb_board.dxf").read_bytes()
USES_BOARD = ('units mm\nsolid s {\n    d = Drawing2D("board.dxf", layer="Edge.Cuts")\n'
              '    Fixed(d.origin)\n}\n')
SLOW = ("units mm\nsolid plate {\n    body = Rectangle(center=(0, 0), width=40, height=20)\n"
        "    for i in range(3000) { hole h { c = Circle(center=(i * 0.001, 0), radius=1) } }\n}\n")

# a program that runs until its wall limit on any machine: 100,000,000 loop iterations (a
# few minutes of evaluation; the budget's 100,000,000 steps at --budget 400), stopped at LIMIT
SPIN = ("units mm\nsolid plate {\n    body = Rectangle(center=(0, 0), width=40, height=20)\n"
        "    for i in range(10000) { for j in range(10000) { k = i * j } }\n}\n")
SPIN_BUDGET = 400
LIMIT = 3.0             # s: the wall limit set for SPIN (kill_after), far below its minutes


def until(ready, request: threading.Thread) -> None:
    """Wait for ``ready()`` while ``request`` (the thread sending the request that makes it
    so) still runs: no clock, so a loaded machine cannot fail it; the request itself ends
    at the studio's wall limit, so neither can it hang."""
    while not ready():
        assert request.is_alive(), "the request ended before it was in flight"
        time.sleep(0.02)


needs_redis = pytest.mark.skipif(redis_server_path() is None,
                                 reason="needs Debian's redis-server (apt-get install redis-server)")


def metrics(c) -> dict:
    """``{(name, labels as a sorted tuple): value}`` of a /metrics answer."""
    r = c.get("/metrics")
    assert r.status_code == 200 and r.headers["content-type"].startswith("text/plain")
    out = {}
    for fam in text_string_to_metric_families(r.text):
        for s in fam.samples:
            out[(s.name, tuple(sorted(s.labels.items())))] = s.value
    return out


@needs_redis
def test_two_studios_share_one_redis_and_report_health_and_metrics(tmp_path):
    with redis_server() as (url, redis_proc):
        _two_studios_one_redis(url, redis_proc, tmp_path)


def _two_studios_one_redis(url, redis_proc, tmp_path):
    apps = [create_app(Settings(data=str(tmp_path / n), compilers=1, store=url,
                                rate="1000/minute")) for n in "ab"]
    with TestClient(apps[0]) as a, TestClient(apps[1]) as b:
        assert b.get("/healthz?probe=live").json() == {"live": True}
        first = b.get("/healthz")          # no compile worker yet: this probe starts one
        assert first.status_code == 503 and first.json()["checks"] == {
            "store": "ok", "compilers": "starting"}
        sid = a.post("/api/session").json()["sid"]
        assert a.post(f"/api/upload?sid={sid}&name=board.dxf", content=BOARD).status_code == 200
        # the other process sees it, and its compile reads it from its own mirror
        assert b.get(f"/api/files?sid={sid}").json() == {
            "files": [{"name": "board.dxf", "bytes": len(BOARD)}]}
        mirror = tmp_path / "b" / sid / "board.dxf"
        assert not mirror.exists()
        # the probe's worker start, awaited: no wall deadline (a busy machine starts it
        # later); the pool's own limit (READY_SECONDS) ends a start that hangs
        for t in threading.enumerate():
            if t.name == "aidl-studio-warm-up":
                t.join()
        h = b.get("/healthz")
        assert h.json() == {"live": True, "ready": True,
                            "checks": {"store": "ok", "compilers": "ok"}}
        v = b.post("/api/view", json={"sid": sid, "source": USES_BOARD, "values": {}}).json()
        assert v["ok"], v
        assert mirror.read_bytes() == BOARD
        # the per-session limit counts the files of both processes (checked in Redis)
        for i in range(MAX_FILES - 1):
            c = (a, b)[i % 2]
            assert c.post(f"/api/upload?sid={sid}&name=f{i}.svg",
                          content=b"<svg/>").status_code == 200
        r = a.post(f"/api/upload?sid={sid}&name=one-more.svg", content=b"<svg/>")
        assert r.status_code == 400 and f"at most {MAX_FILES} files" in r.json()["error"]
        # deleted in one, gone from the other (and from its mirror at its next compile)
        assert b.post("/api/delete", json={"sid": sid, "name": "board.dxf"}).status_code == 200
        assert "board.dxf" not in {f["name"] for f in a.get(f"/api/files?sid={sid}").json()["files"]}
        v = b.post("/api/view", json={"sid": sid, "source": USES_BOARD, "values": {}}).json()
        assert not v["ok"] and v["diagnostics"][0]["code"] == "E0130"
        assert not mirror.exists()
        a.post("/api/close", json={"sid": sid})
        assert b.get(f"/api/files?sid={sid}").json() == {"files": []}
        # what b's /metrics says of the two compiles
        m = metrics(b)
        view = ("aidl_studio_requests_total", (("method", "POST"), ("route", "/api/view"),
                                               ("status", "200")))
        assert m[view] == 2
        assert m[("aidl_studio_request_seconds_count", (("route", "/api/view"),))] == 2
        assert m[("aidl_studio_compile_seconds_count", (("kind", "view"),))] == 2
        assert m[("aidl_studio_compile_seconds_sum", (("kind", "view"),))] > 0
        assert m[("aidl_studio_queue_length", ())] == 0
        assert m[("aidl_studio_worker_restarts_total", ())] == 0
        assert m[("aidl_studio_worker_resident_bytes", (("worker", "0"),))] > 20e6
        assert m[("process_resident_memory_bytes", ())] > 20e6

        # one rate for both: 5 a minute, 3 through one process and 2 through the other
        url1 = url.rsplit("/", 1)[0] + "/1"
        apps = [create_app(Settings(data=str(tmp_path / n), compilers=1, store=url1,
                                    rate="5/minute")) for n in "cd"]
        with TestClient(apps[0]) as c, TestClient(apps[1]) as d:
            # (what compiles or opens a session pays; browsing, /api/docs, costs none: issue 104)
            codes = [x.post("/api/session").status_code for x in (c, d, c, d, c)]
            assert codes == [200] * 5
            assert d.get("/api/docs?name=Circle").status_code == 200
            r = d.post("/api/session")
            assert r.status_code == 429 and int(r.headers["Retry-After"]) >= 1
            m = metrics(d)
            assert m[("aidl_studio_rate_limited_total", ())] == 1
            for status, n in (("429", 1), ("200", 2)):
                assert m[("aidl_studio_requests_total", (
                    ("method", "POST"), ("route", "/api/session"), ("status", status)))] == n

        # Redis gone: not ready, and a request is a 503 to retry, not a traceback
        redis_proc.kill()
        redis_proc.wait()
        h = b.get("/healthz")
        assert h.status_code == 503 and h.json()["checks"]["compilers"] == "ok"
        assert "Redis" in h.json()["checks"]["store"]
        r = b.post("/api/view", json={"sid": sid, "source": BRACKET})
        assert r.status_code == 503 and r.headers["Retry-After"] == "5"
        assert "try again" in r.json()["error"]


@pytest.fixture(scope="module")
def cluster(tmp_path_factory):
    """A Dask cluster of one single-threaded worker process (its compile process is warm
    after the first test that compiles on it; its sessions' folders in a temporary folder)."""
    distributed = pytest.importorskip("distributed")
    import logging
    mp = pytest.MonkeyPatch()
    mp.setenv("TMPDIR", str(tmp_path_factory.mktemp("dask")))    # read by the new worker
    try:
        with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=True,
                                      dashboard_address="127.0.0.1:0",
                                      silence_logs=logging.ERROR) as c:
            mp.undo()
            yield c.scheduler_address
    finally:
        mp.undo()


@needs_redis
@pytest.mark.skipif(nginx_path() is None, reason="needs Debian's nginx (apt-get install nginx)")
def test_two_studio_processes_behind_nginx_one_redis_one_dask_one_killed(cluster):
    """The deployment of docs/studio.md: nginx, two studio processes (the image's entry
    script) sharing one Redis and compiling on one Dask cluster; one process is killed and
    every later request is answered, the upload still there."""
    ports = [free_port(), free_port()]
    with redis_server() as (url, _redis), \
            studio_processes(ports, {"AIDL_STUDIO_STORE": url,
                                     "AIDL_STUDIO_SCHEDULER": cluster}) as (one, _two), \
            nginx(free_port(), ports) as front:
        direct = [f"http://127.0.0.1:{p}/" for p in ports]
        status, doc = post(front + "api/session")
        assert status == 200
        sid = doc["sid"]
        # uploaded to one process, compiled for the other (on the cluster, the file sent along)
        assert post(direct[0] + f"api/upload?sid={sid}&name=board.dxf", data=BOARD)[0] == 200
        status, v = post(direct[1] + "api/view", {"sid": sid, "source": USES_BOARD})
        assert status == 200 and v["ok"], v
        assert "aidl-studio" not in str(v)                  # no server's folder in the answer
        assert get(front + "metrics")[0] == 404             # the proxy hides it
        # through nginx, round robin over both; then one process is killed
        for _ in range(2):
            status, v = post(front + "api/view", {"sid": sid, "source": USES_BOARD})
            assert status == 200 and v["ok"]
        os.killpg(one.pid, signal.SIGKILL)
        one.wait()
        for _ in range(4):                                  # every request answered
            status, v = post(front + "api/view", {"sid": sid, "source": USES_BOARD})
            assert status == 200 and v["ok"], v
        assert get(front + f"api/files?sid={sid}")[1] == (
            b'{"files":[{"name":"board.dxf","bytes":%d}]}' % len(BOARD))


@pytest.mark.timing
def test_compiles_on_dask_keep_the_wall_limit_and_refuse_when_full(cluster, tmp_path):
    """One compile runs past its wall limit on the cluster and is stopped, one waits for the
    cluster's only thread, a third finds the queue full and is refused at once.  Nothing here
    depends on the machine's speed (it did: at load 4-6 on 2 cores the warm-up compile of
    the bracket ran past the 1.5 s limit this test had): the warm-up runs under the default
    limit, the short one (LIMIT) is set for the slow program alone, which runs until it on
    any machine (SPIN, minutes of evaluation steps within its budget), and each request is
    sent once the one before it is in flight, not after a sleep."""
    app = create_app(Settings(data=str(tmp_path / "e"), scheduler=cluster, budget=SPIN_BUDGET,
                              wait=0.5, queue=1))
    studio = app.state.studio
    pool = studio.pool
    with TestClient(app) as c:
        assert c.get("/healthz").json()["checks"]["compilers"] == "ok"
        sid = c.post("/api/session").json()["sid"]
        assert c.post("/api/view", json={"sid": sid, "source": BRACKET}).json()["ok"]  # warm
        studio.settings.kill_after = LIMIT     # a compile's limit: LIMIT
        answers = {}

        def ask(name, source):
            # a session of its own: one session's previews are compiled one at a time (a
            # newer one supersedes those waiting), and this test is about the cluster's queue
            own = c.post("/api/session").json()["sid"]
            answers[name] = c.post("/api/view", json={"sid": own, "source": source})
        # one compile runs past its time, one waits for the cluster's only thread, a third
        # finds the queue full
        runs = [threading.Thread(target=ask, args=("slow", SPIN)),
                threading.Thread(target=ask, args=("waits", BRACKET))]
        for k, t in enumerate(runs, 1):
            t.start()
            until(lambda: pool.inflight >= k, t)
        ask("refused", BRACKET)
        assert "slow" not in answers            # at once: while the slow one still runs
        for t in runs:
            t.join(300)                          # a hang guard
        r = answers["refused"]
        assert r.status_code == 503 and r.headers["Retry-After"] == "5"
        r = answers["waits"]        # compiled once the slow one was stopped, or "busy" past the wait
        assert (r.status_code, r.json().get("ok")) == (200, True) or \
            (r.status_code == 503 and "busy" in r.json()["error"])
        waited_out = r.status_code == 503
        r = answers["slow"]
        assert f"longer than {LIMIT:g} s" in r.json()["error"]    # the wall limit, on the cluster
        m = metrics(c)
        assert m[("aidl_studio_busy_total", ())] == 1 + waited_out
        assert m[("aidl_studio_compile_timeouts_total", ())] == 1
        assert m[("aidl_studio_worker_restarts_total", ())] == 1


def test_the_containerfile_copies_what_exists_runs_as_a_user_on_one_port():
    """The image is not built here (no registry for its base image: docs/studio.md); what it
    says is checked against the tree: every COPY source exists, the entry point is the
    script the nginx test starts, a non-root user, one port."""
    import re
    text = (ROOT / "deploy" / "studio" / "Containerfile").read_text()
    lines = [ln.strip() for ln in re.sub(r"\\\n", " ", text).splitlines()
             if ln.strip() and not ln.lstrip().startswith("#")]
    copies = [ln.split()[1:] for ln in lines if ln.startswith("COPY ")]
    assert copies
    for args in copies:
        for src in [a for a in args if not a.startswith("--")][:-1]:
            assert (ROOT / src).exists(), src
    users = [ln.split()[1] for ln in lines if ln.startswith("USER ")]
    assert users and users[-1] not in ("0", "root")
    assert [ln for ln in lines if ln.startswith("EXPOSE ")] == ["EXPOSE 8780"]
    entry = [ln for ln in lines if ln.startswith("ENTRYPOINT ")]
    assert entry == ['ENTRYPOINT ["/usr/local/bin/aidl-studio-entrypoint"]']
    assert "COPY --chmod=0555 deploy/studio/entrypoint.sh /usr/local/bin/aidl-studio-entrypoint" \
        in lines
    assert any("/healthz" in ln for ln in lines if ln.startswith("HEALTHCHECK"))


@pytest.mark.parametrize("env, message", [
    ({"PORT": "80a"}, "PORT must be a port number, got '80a'"),
    ({"PORT": "8780", "AIDL_STUDIO_COMPILERS": "two"},
     "AIDL_STUDIO_COMPILERS must be a number, got 'two'")])
def test_the_entry_script_refuses_a_bad_setting_in_one_line(env, message):
    import subprocess
    r = subprocess.run(["/bin/sh", str(ROOT / "deploy" / "studio" / "entrypoint.sh")],
                       env={"PATH": "/usr/bin:/bin", **env}, capture_output=True, text=True,
                       timeout=10)
    assert r.returncode == 2 and r.stderr.strip() == f"aidl-studio: {message}"


def test_a_store_that_does_not_answer_stops_the_start_with_one_line(capsys):
    from aidl_lang.studio import studio
    assert studio(port=0, store="redis://127.0.0.1:1/0") == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("aidl: error: cannot reach the store at redis://127.0.0.1:1/0: ")
    assert err.endswith("; start Redis or correct --store") and len(err.splitlines()) == 1
