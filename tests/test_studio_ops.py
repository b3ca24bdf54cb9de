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
from benchmarks.studio_cluster import (free_port, get, nginx, nginx_path, post,  # noqa: E402
                                       redis_server, redis_server_path, studio_processes)

ROOT = Path(__file__).resolve().parent.parent
BRACKET = (ROOT / "examples" / "bracket.aidl").read_text()
BOARD = (ROOT / "examples" / "parts" / "pcb_board.dxf").read_bytes()
USES_BOARD = ('units mm\nsolid s {\n    d = Drawing2D("board.dxf", layer="Edge.Cuts")\n'
              '    Fixed(d.origin)\n}\n')
SLOW = ("units mm\nsolid plate {\n    body = Rectangle(center=(0, 0), width=40, height=20)\n"
        "    for i in range(3000) { hole h { c = Circle(center=(i * 0.001, 0), radius=1) } }\n}\n")

needs_redis = pytest.mark.skipif(redis_server_path() is None,
                                 reason="needs Debian's redis-server (apt-get install redis-server)")


@pytest.fixture(scope="module")
def redis_url():
    if redis_server_path() is None:
        pytest.skip("needs Debian's redis-server (apt-get install redis-server)")
    with redis_server() as (url, _proc):
        yield url


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
def test_two_studios_share_uploads_limits_and_rate_in_one_redis(redis_url, tmp_path):
    a_app = create_app(Settings(data=str(tmp_path / "a"), compilers=1, store=redis_url,
                                rate="1000/minute"))
    b_app = create_app(Settings(data=str(tmp_path / "b"), compilers=1, store=redis_url,
                                rate="1000/minute"))
    with TestClient(a_app) as a, TestClient(b_app) as b:
        sid = a.post("/api/session").json()["sid"]
        assert a.post(f"/api/upload?sid={sid}&name=board.dxf", content=BOARD).status_code == 200
        # the other process sees it, and its compile reads it from its own mirror
        assert b.get(f"/api/files?sid={sid}").json() == {
            "files": [{"name": "board.dxf", "bytes": len(BOARD)}]}
        mirror = tmp_path / "b" / sid / "board.dxf"
        assert not mirror.exists()
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

    # one rate for both: 5 a minute, 3 through one process and 2 through the other
    url1 = redis_url.rsplit("/", 1)[0] + "/1"
    apps = [create_app(Settings(data=str(tmp_path / n), compilers=1, store=url1,
                                rate="5/minute")) for n in "cd"]
    with TestClient(apps[0]) as c, TestClient(apps[1]) as d:
        codes = [x.get("/api/docs?name=Circle").status_code for x in (c, d, c, d, c)]
        assert codes == [200] * 5
        r = d.get("/api/docs?name=Circle")
        assert r.status_code == 429 and int(r.headers["Retry-After"]) >= 1
        m = metrics(d)
        assert m[("aidl_studio_rate_limited_total", ())] == 1
        assert m[("aidl_studio_requests_total", (("method", "GET"), ("route", "/api/docs"),
                                                 ("status", "429")))] == 1
        assert m[("aidl_studio_requests_total", (("method", "GET"), ("route", "/api/docs"),
                                                 ("status", "200")))] == 2


@needs_redis
def test_healthz_and_metrics_follow_the_compilers_and_the_store(tmp_path):
    with redis_server() as (url, proc):
        app = create_app(Settings(data=str(tmp_path / "d"), compilers=1, store=url))
        with TestClient(app) as c:
            assert c.get("/healthz?probe=live").json() == {"live": True}
            first = c.get("/healthz")          # no compile worker yet: it starts one
            assert first.status_code == 503 and first.json()["checks"] == {
                "store": "ok", "compilers": "starting"}
            deadline = time.monotonic() + 60
            while (h := c.get("/healthz")).status_code != 200:
                assert time.monotonic() < deadline, h.json()
                time.sleep(0.1)
            assert h.json() == {"live": True, "ready": True,
                                "checks": {"store": "ok", "compilers": "ok"}}
            sid = c.post("/api/session").json()["sid"]
            for _ in range(2):
                assert c.post("/api/view", json={"sid": sid, "source": BRACKET}).status_code == 200
            m = metrics(c)
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
            # Redis gone: not ready, and a request is a 503 to retry, not a traceback
            proc.kill()
            proc.wait()
            h = c.get("/healthz")
            assert h.status_code == 503 and h.json()["checks"]["compilers"] == "ok"
            assert "Redis" in h.json()["checks"]["store"]
            t0 = time.monotonic()
            r = c.post("/api/view", json={"sid": sid, "source": BRACKET})
            assert r.status_code == 503 and r.headers["Retry-After"] == "5"
            assert "try again" in r.json()["error"] and time.monotonic() - t0 < 10


@needs_redis
@pytest.mark.skipif(nginx_path() is None, reason="needs Debian's nginx (apt-get install nginx)")
def test_two_studio_processes_behind_nginx_one_killed_no_design_lost():
    ports = [free_port(), free_port()]
    with redis_server() as (url, _redis), \
            studio_processes(ports, {"AIDL_STUDIO_STORE": url,
                                     "AIDL_STUDIO_COMPILERS": "1"}) as (one, _two), \
            nginx(free_port(), ports) as front:
        direct = [f"http://127.0.0.1:{p}/" for p in ports]
        status, doc = post(front + "api/session")
        assert status == 200
        sid = doc["sid"]
        # uploaded to one process, compiled by the other
        assert post(direct[0] + f"api/upload?sid={sid}&name=board.dxf", data=BOARD)[0] == 200
        status, v = post(direct[1] + "api/view", {"sid": sid, "source": USES_BOARD})
        assert status == 200 and v["ok"], v
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


def test_compiles_on_a_dask_cluster_with_the_same_limits(tmp_path):
    distributed = pytest.importorskip("distributed")
    import logging
    with distributed.LocalCluster(n_workers=1, threads_per_worker=1, processes=True,
                                  dashboard_address="127.0.0.1:0",
                                  silence_logs=logging.ERROR) as cluster:
        address = cluster.scheduler_address
        with TestClient(create_app(Settings(data=str(tmp_path / "d"), scheduler=address))) as c:
            h = c.get("/healthz").json()
            assert h["checks"]["compilers"] == "ok", h
            sid = c.post("/api/session").json()["sid"]
            assert c.post(f"/api/upload?sid={sid}&name=board.dxf", content=BOARD).status_code == 200
            v = c.post("/api/view", json={"sid": sid, "source": USES_BOARD}).json()
            assert v.get("ok"), v                            # the upload went with the task
            assert str(tmp_path) not in str(v) and "aidl-studio-dask" not in str(v)
            assert c.post("/api/view", json={"sid": sid, "source": BRACKET}).json()["ok"]
        # the Dask worker's compile process is warm now; here a compile may run 0.1 x 15 s
        # = 1.5 s (SLOW takes ~9 s), and one may wait
        app = create_app(Settings(data=str(tmp_path / "e"), scheduler=address, wall_factor=0.1,
                                  wait=0.5, queue=1))
        with TestClient(app) as c:
            sid = c.post("/api/session").json()["sid"]
            answers = {}

            def ask(name, source):
                t0 = time.monotonic()
                answers[name] = (c.post("/api/view", json={"sid": sid, "source": source}),
                                 time.monotonic() - t0)
            # one compile runs past its time, one waits for the cluster's only thread, a
            # third finds the queue full
            runs = [threading.Thread(target=ask, args=("slow", SLOW)),
                    threading.Thread(target=ask, args=("waits", BRACKET))]
            for t in runs:
                t.start()
                time.sleep(0.15)
            ask("refused", BRACKET)
            for t in runs:
                t.join(60)
            r, took = answers["refused"]
            assert r.status_code == 503 and r.headers["Retry-After"] == "5" and took < 1.0
            r, took = answers["waits"]      # compiled once the slow one was stopped, or given
            assert took < 0.5 + 1.5 + 1.5   # up past wait + wall: never a hang
            assert (r.status_code, r.json().get("ok")) == (200, True) or \
                (r.status_code == 503 and "busy" in r.json()["error"])
            waited_out = r.status_code == 503
            r, _ = answers["slow"]
            assert "longer than 1.5 s" in r.json()["error"]  # the wall limit, on the cluster
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
     "AIDL_STUDIO_COMPILERS must be a number, got 'two'"),
    ({"PORT": "0", "AIDL_STUDIO_STORE": "redis://127.0.0.1:1/0"},
     "cannot reach the store at redis://127.0.0.1:1/0: ")])
def test_the_entry_script_refuses_a_bad_setting_in_one_line(env, message):
    import subprocess
    import sys
    path = os.pathsep.join((str(Path(sys.executable).parent), "/usr/bin", "/bin"))
    r = subprocess.run(["/bin/sh", str(ROOT / "deploy" / "studio" / "entrypoint.sh")],
                       env={"PATH": path, **env}, capture_output=True, text=True, timeout=60)
    assert r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1, r.stderr
    assert r.stderr.startswith(("aidl-studio: " if "STORE" not in str(env) else "aidl: error: ")
                               + message), r.stderr
