"""Live-preview latency, measured in a real browser (Chromium driven by Playwright).

For every bundled example with params: start ``aidl serve`` on a copy, open the page, move each
numeric param's slider through ``--moves`` positions (one at a time, waiting for the picture)
and report the time from the slider's ``input`` event to the new picture painted (a task
queued from the animation frame after the SVG was put in the page), median and p95; then save the file (a
comment appended) and report the time from the write to the new picture.

    .venv/bin/python -m benchmarks.serve.serve_latency [--moves 20] [--param NAME] [--rest S] [EXAMPLE.aidl ...]

``--param`` moves only the named params; ``--rest`` lets each slider rest that many seconds
after its picture (a user who lets go and looks; the shape checks and the server's idle-time
collection run then), where the default moves it again at once (a drag).

The helpers :func:`served` and :func:`chromium` are shared with ``tests/test_serve_browser.py``,
:func:`serving` with ``benchmarks/serve/slider_ws.py``.
"""
from __future__ import annotations

import argparse
import contextlib
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
CHROMIUM = "/usr/bin/chromium"
CHROMIUM_ARGS = ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                 "--disable-background-networking", "--disable-component-update", "--disable-sync"]


@contextlib.contextmanager
def launched(argv: list[str], cwd: Path | None = None, env: dict | None = None,
             timeout: float = 30.0):
    """Run ``argv`` (an ``aidl serve`` or ``aidl studio`` command) in a subprocess (``cwd``,
    ``env``); yield the URL it prints and the process; stop it after (SIGTERM, then SIGKILL)."""
    proc = subprocess.Popen(argv, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                            cwd=str(cwd) if cwd is not None else None, env=env)
    try:
        deadline = time.monotonic() + timeout
        url = None
        while time.monotonic() < deadline:
            line = proc.stdout.readline()
            if not line:
                break
            m = re.search(r"(http://[^/\s]+/)", line)
            if m:
                url = m.group(1)
                break
        if url is None:
            raise RuntimeError(f"{' '.join(argv[-4:])} did not start: "
                               f"{proc.stdout.read() if proc.poll() is not None else ''}")
        yield url, proc
    finally:
        proc.terminate()
        try:
            proc.wait(timeout=15)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait()


@contextlib.contextmanager
def serving(cmd: list[str], path: Path, cwd: Path, env: dict | None = None,
            timeout: float = 30.0):
    """Run ``CMD serve PATH --port 0`` in a subprocess (``cwd``, ``env``); yield its URL and
    the process; stop it after."""
    with launched(cmd + ["serve", str(path), "--port", "0"], cwd, env, timeout) as got:
        yield got


@contextlib.contextmanager
def served(path: Path, timeout: float = 30.0):
    """Run ``aidl serve PATH --port 0`` (this environment's) in a subprocess; yield its URL;
    stop it after."""
    exe = Path(sys.executable).with_name("aidl")
    cmd = [str(exe)] if exe.exists() else [sys.executable, "-m", "aidl_lang.cli"]
    with serving(cmd, path, path.parent, timeout=timeout) as (url, _proc):
        yield url


@contextlib.contextmanager
def chromium():
    """Debian's Chromium, headless, with a fresh profile; yields a Playwright browser."""
    from playwright.sync_api import sync_playwright
    with tempfile.TemporaryDirectory(prefix="aidl-chromium-") as profile, sync_playwright() as pw:
        ctx = pw.chromium.launch_persistent_context(
            profile, executable_path=CHROMIUM, headless=True, args=CHROMIUM_ARGS,
            viewport={"width": 1400, "height": 900})
        try:
            yield ctx
        finally:
            ctx.close()


def open_page(ctx, url: str):
    page = ctx.pages[0] if ctx.pages else ctx.new_page()
    page.goto(url)
    page.wait_for_function("window.aidl && window.aidl.ready && document.querySelector('#viewer svg')")
    return page


def move_slider(page, name: str, value: float, timeout: float = 20_000) -> float:
    """Set slider ``name`` to ``value``; wait for the picture; return the page's latency (ms)."""
    n = page.evaluate("window.aidl.sliderMs.length")
    page.locator(f'input[type=range][name="{name}"]').fill(str(value))
    page.wait_for_function(f"window.aidl.sliderMs.length > {n} && !window.aidlBusy()",
                           timeout=timeout)
    return page.evaluate("window.aidl.sliderMs[window.aidl.sliderMs.length - 1]")


def save_latency(page, path: Path, text: str, timeout: float = 20_000) -> float:
    """Write ``text`` to ``path``; return ms from the write to the new version painted."""
    v = page.evaluate("window.aidl.version")
    t0 = time.time() * 1000
    path.write_text(text)
    page.wait_for_function(f"window.aidl.version > {v}", timeout=timeout)
    v2 = page.evaluate("window.aidl.version")
    return page.evaluate(f"window.aidl.drawn[{v2}]") - t0


def p95(xs):
    xs = sorted(xs)
    return xs[min(len(xs) - 1, int(round(0.95 * (len(xs) - 1))))]


def measure(example: Path, ctx, moves: int, only: list[str] | None = None,
            rest: float = 0.0) -> dict:
    with tempfile.TemporaryDirectory() as d:
        tmp = Path(d) / example.name
        shutil.copy(example, tmp)
        if (example.parent / "parts").is_dir():
            shutil.copytree(example.parent / "parts", Path(d) / "parts")
        with served(tmp) as url:
            page = open_page(ctx, url)
            params = [p for p in page.evaluate("window.aidl.state.params")
                      if p["kind"] in ("length", "angle", "number")
                      and (not only or p["name"] in only)]
            lat = []
            for p in params:
                lo, hi = p["value"], p["max"] if p["max"] > p["value"] else p["min"]
                for k in range(1, moves + 1):
                    v = lo + (hi - lo) * 0.3 * k / moves
                    v = round(round(v / p["step"]) * p["step"], 9)
                    lat.append(move_slider(page, p["name"], v))
                    time.sleep(rest)
                move_slider(page, p["name"], p["value"])
            saves = [save_latency(page, tmp, tmp.read_text() + f"\n# saved {i}\n") for i in range(5)]
            warm = page.evaluate("window.aidl.state.view.timing.warm")
            parts = page.evaluate("window.aidl.sliderParts")
            page.close()
    return {"example": example.name, "params": len(params), "moves": len(lat),
            "median": statistics.median(lat) if lat else None, "p95": p95(lat) if lat else None,
            "save_median": statistics.median(saves), "last_warm": warm,
            "server": statistics.median([q["server"] for q in parts]) if parts else None,
            "transport": statistics.median([q["roundTrip"] - q["server"] for q in parts])
            if parts else None,
            "draw": statistics.median([q["drawAndPaint"] for q in parts]) if parts else None}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("examples", nargs="*")
    ap.add_argument("--moves", type=int, default=10, help="slider positions per param")
    ap.add_argument("--param", action="append", help="move only this param (repeatable)")
    ap.add_argument("--rest", type=float, default=0.0,
                    help="seconds the slider rests after each picture (0: a drag)")
    a = ap.parse_args(argv)
    files = [Path(e) for e in a.examples] or sorted((ROOT / "examples").glob("*.aidl"))
    print(f"{'example':22} {'params':>6} {'moves':>5} {'slider median ms':>16} {'p95 ms':>7} "
          f"{'server':>6} {'transport':>9} {'draw':>5} {'save median ms':>14}")
    rows = []
    with chromium() as ctx:
        for f in files:
            r = measure(f, ctx, a.moves, a.param, a.rest)
            rows.append(r)
            med = f"{r['median']:.1f}" if r["median"] is not None else "-"
            p = f"{r['p95']:.1f}" if r["p95"] is not None else "-"
            part = " ".join(f"{r[k]:{w}.1f}" if r[k] is not None else f"{'-':>{w}}"
                            for k, w in (("server", 6), ("transport", 9), ("draw", 5)))
            print(f"{r['example']:22} {r['params']:6d} {r['moves']:5d} {med:>16} {p:>7} {part} "
                  f"{r['save_median']:14.1f}", flush=True)
    allv = [r["p95"] for r in rows if r["p95"] is not None]
    if allv:
        print(f"worst p95: {max(allv):.1f} ms")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
