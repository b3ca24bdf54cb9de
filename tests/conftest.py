import collections
import os
import pathlib
import sys

import pytest
from hypothesis import HealthCheck as _HealthCheck, settings as _hypothesis

# pytest's assertion-rewritten test modules are cached (tests/__pycache__/*-pytest-*.pyc) even
# where PYTHONDONTWRITEBYTECODE is set (this machine, CI): without the cache every pytest
# process (each xdist worker) rewrote all 235 test files on each run, 23 s of CPU a process
# to collect the suite; with it 4 s.  Nothing else changes: the package and the benchmarks
# are byte-compiled before the workers start (_compile_bytecode), and subprocesses keep the
# environment's setting.
sys.dont_write_bytecode = False

# One BLAS thread, as the `aidl` command uses (aidl_lang/cli/__init__.py): the matrices are
# small, and threaded OpenBLAS spun on a busy 2-core machine (one example's dense solves took
# 64 ms each instead of ~2 ms).  Set before anything imports NumPy.
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")

ROOT = pathlib.Path(__file__).resolve().parent.parent
EXAMPLES = sorted((ROOT / "examples").glob("*.aidl"))

# ------------------------------------------------------------------ one answer on every machine
# Every property test draws the same cases on every machine and every run (issue 109, law 6:
# a fresh machine drew a T-bracket no other machine had drawn, and the README's command
# failed there): the profile "aidl" derandomizes Hypothesis (each test's cases follow from its
# own source), keeps no example database (nothing carried from one run to the next), and has
# no deadline and no too_slow health check (both read the wall clock; no test asserts speed).
# A test's own `@settings(max_examples=...)` is made from the loaded profile, so it keeps
# these; it must not say `derandomize=` or `database=` itself (tests/test_conventions.py).
# To look for what is latent, the profile "random" draws afresh: `--hypothesis-seed=N` loads
# it (a seed picks the cases: seed 2 draws the same on every machine), as does
# AIDL_HYPOTHESIS_PROFILE=random (new cases every run).  docs/dev/testing.md.
HYPOTHESIS_PROFILE = "AIDL_HYPOTHESIS_PROFILE"
_hypothesis.register_profile("aidl", derandomize=True, database=None, deadline=None,
                             suppress_health_check=[_HealthCheck.too_slow])
_hypothesis.register_profile("random", _hypothesis.get_profile("aidl"), derandomize=False)
# Hypothesis loads its own profile "ci" where the environment says CI (CI=1, GITHUB_ACTIONS...):
# ours replaces it too, so CI and a laptop run the same profile (it failed CI once: 'ci' != 'aidl').
if _hypothesis.get_current_profile_name() in ("default", "ci"):   # (before any test module)
    _hypothesis.load_profile(os.environ.get(HYPOTHESIS_PROFILE) or "aidl")


@pytest.fixture
def compile_text(tmp_path):
    from aidl_lang.pipeline import compile_source

    def run(src: str, name: str = "t.aidl", **kw):
        p = tmp_path / name
        p.write_text(src)
        return compile_source(src, str(p), **kw)
    return run


@pytest.fixture
def cpu_clock(monkeypatch):
    """The compile's clock (``time.monotonic``) counts this process's CPU seconds for the
    test (tests/cpu_clock.py): a budget, a checks' share or a deadline is reached after the
    same work however busy the machine is.  Returns ``time.process_time``, for the figure."""
    import time
    from cpu_clock import make_clock
    monkeypatch.setattr(time, "monotonic", make_clock())
    return time.process_time


# ------------------------------------------------------------------ one studio per process
# The studio's browser test files (test_studio_browser, _page, _values_browser, _views) share
# one `aidl studio` per test process (the maker's has its own: its rate limit of 30 per 5 s is
# what it tests): under `--dist loadfile` the files a worker runs meet one server (a start costs
# a file about 5 s), and its caches (the gallery's thumbnails, the sweeps) are made once.
# Chromium is launched per module: a sync Playwright that lives on marks the thread's asyncio
# loop as running, and the next file's asyncio tests and sync Playwright could not start.
BROWSER_TESTS = "AIDL_BROWSER_TESTS"


def skip_without_chromium() -> None:
    """Skip the calling test (or module) unless the browser tests were asked for and Debian's
    Chromium and Playwright are here.  The Chromium tests (about 250 s of the suite) run when
    ``AIDL_BROWSER_TESTS=1`` is set, as ``.ci/run`` does in its step 3 (the tests that skipped
    in step 1, run again once the system programs are installed): the README's command runs
    the same tests on every machine, Chromium installed or not, and stays under 10 minutes."""
    if os.environ.get(BROWSER_TESTS) != "1":
        pytest.skip(f"a Chromium test: runs with {BROWSER_TESTS}=1 (.ci/run's step 3; README.md)",
                    allow_module_level=True)
    pytest.importorskip("playwright")
    if not pathlib.Path("/usr/bin/chromium").exists():
        pytest.skip("needs Debian's chromium (apt-get install chromium; .ci/run installs it)",
                    allow_module_level=True)


@pytest.fixture(scope="module")
def chromium_browser():
    """Debian's Chromium, headless, through Playwright's sync API (one per module; each test
    or module opens its own context); skips without them (:func:`skip_without_chromium`)."""
    skip_without_chromium()
    from benchmarks.serve.serve_latency import CHROMIUM_ARGS, CHROMIUM
    from playwright.sync_api import sync_playwright
    with sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=CHROMIUM, headless=True, args=CHROMIUM_ARGS)
        try:
            yield browser
        finally:
            browser.close()


@pytest.fixture(scope="session")
def studio_url():
    """``aidl studio --port 0`` as a visitor meets it (two compile workers, one sweep worker,
    the default rate) with no model endpoint: its URL.  (Its first design's sweep made here
    once, 29 s of CPU, cost more than it saved: a tab's sweep stops when the tab closes.)
    Only the browser tests use it: it skips as they do, before starting anything."""
    skip_without_chromium()
    pytest.importorskip("starlette")
    from benchmarks.serve.studio_server import studio
    with studio(env={"AIDL_STUDIO_MODEL_URL": ""}) as (url, _proc):
        yield url


@pytest.fixture(scope="module")
def studio_page(studio_url, chromium_browser):
    """A desktop tab (1280 x 800) of :func:`studio_url`, its first design shown and the
    gallery closed (the gallery's thumbnails never asked: they are not what these tests
    read), one per module."""
    ctx = chromium_browser.new_context(viewport={"width": 1280, "height": 800})
    try:
        ctx.route("**/api/thumb/**", lambda r: r.abort())
        page = ctx.new_page()
        page.goto(studio_url)
        page.wait_for_function("() => window.studio && window.studio.ready && window.studio.view"
                               " && window.studio.view.ok", timeout=120_000)
        page.keyboard.press("Escape")
        yield page
    finally:
        ctx.close()


# ------------------------------------------------------------------ no process left behind
# A test that starts workers, servers or pools stops them (in its fixture's `finally`).  At
# the end of the session every child process of this pytest process must have ended (after a
# short grace period): one still running fails the run, naming it and the first test after
# which it was seen.  Orphans count too: this process is made the *child subreaper* of its
# descendants (Linux prctl PR_SET_CHILD_SUBREAPER), so a worker whose parent (a server the
# test started) died without stopping it is re-parented here instead of to init, and is seen.
# Children are read from /proc/self/task/*/children (or the ppid in /proc/*/stat): Linux only;
# elsewhere the check is off.
# seconds for children to finish exiting at the session's end (waited only while some are
# still running; 5 s before: a process that is ending on a loaded machine may take longer)
_LEFT_GRACE = float(os.environ.get("AIDL_TEST_LEFT_GRACE", "30"))
# multiprocessing's own helpers live as long as the process that started them, by design, and
# end when it does (their pipe closes): not a test's leftovers; a forkserver's children are
# (the compile workers, aidl_lang.host.workers.context, are forked from it)
_HELPERS = ("multiprocessing.resource_tracker", "multiprocessing.forkserver")
_first_seen: dict[int, str] = {}        # pid -> the test after which it was first seen
_left: list[str] = []


def _proc_text(pid: int, name: str) -> str:
    try:
        with open(f"/proc/{pid}/{name}", "rb") as f:
            return f.read().decode(errors="replace")
    except OSError:
        return ""


def _state(pid: int) -> str:
    """One letter of /proc/PID/stat (R, S, D, Z, ...); '' when the process is gone."""
    stat = _proc_text(pid, "stat")
    return stat[stat.rfind(")") + 2:][:1] if stat else ""


def _children() -> set[int]:
    """The live (not zombie) child processes of this one, helpers excluded but not a
    helper's own children (a forkserver's workers)."""
    out: set[int] = set()
    for p in _child_pids(os.getpid()):
        if _state(p) in ("", "Z"):
            continue
        if any(h in _proc_text(p, "cmdline") for h in _HELPERS):
            out.update(c for c in _child_pids(p) if _state(c) not in ("", "Z"))
        else:
            out.add(p)
    return out


def _child_pids(me: int) -> set[int]:
    pids: set[int] = set()
    tasks = pathlib.Path(f"/proc/{me}/task")
    files = list(tasks.glob("*/children")) if tasks.is_dir() else []
    if files:
        for f in files:
            try:
                pids.update(int(p) for p in f.read_text().split())
            except OSError:
                pass
    else:
        for d in pathlib.Path("/proc").iterdir():
            if d.name.isdigit():
                stat = _proc_text(int(d.name), "stat")
                if stat and int(stat[stat.rfind(")") + 2:].split()[1]) == me:
                    pids.add(int(d.name))
    return pids


def _reap() -> None:
    """Collect the exit status of orphans re-parented here (zombies), so they vanish."""
    for p in _children_any_state():
        if _state(p) == "Z":
            try:
                os.waitpid(p, os.WNOHANG)
            except ChildProcessError:
                pass


def _children_any_state() -> set[int]:
    out: set[int] = set()
    for f in pathlib.Path(f"/proc/{os.getpid()}/task").glob("*/children"):
        try:
            out.update(int(p) for p in f.read_text().split())
        except OSError:
            pass
    return out


_CHECK = pathlib.Path("/proc/self/stat").exists()


def pytest_configure(config):
    if (config.getoption("--hypothesis-seed", None) is not None
            and not config.getoption("--hypothesis-profile", None)
            and not os.environ.get(HYPOTHESIS_PROFILE)):
        _hypothesis.load_profile("random")      # a seed given is a seed used (not derandomized)
    if not _worker(config):
        _compile_bytecode()
    if _CHECK:
        try:
            import ctypes
            ctypes.CDLL(None, use_errno=True).prctl(36, 1, 0, 0, 0)   # PR_SET_CHILD_SUBREAPER
        except (OSError, AttributeError):
            pass


def _compile_bytecode() -> None:
    """Byte-compile the package and the benchmarks once, before the workers start: the suite
    starts hundreds of Python processes (the CLI, studio and language servers, batch
    workers), and where ``PYTHONDONTWRITEBYTECODE`` is set (this machine, CI) none of them
    writes what it compiles, so each compiled every module it imports from source again:
    0.25-1 s of CPU a process (test_cli + test_render_cli + test_lsp: 19.1 -> 10.9 s CPU).
    Python reads the files written here whatever that variable says; 0.7 s."""
    import compileall
    for folder in ("aidl_lang", "benchmarks"):
        compileall.compile_dir(ROOT / folder, quiet=1)


@pytest.hookimpl(trylast=True)
def pytest_runtest_logfinish(nodeid, location):
    if _CHECK:
        for p in _children():
            _first_seen.setdefault(p, nodeid)


_skipped: list[str] = []


def pytest_runtest_logreport(report):
    if report.skipped and not hasattr(report, "wasxfail") and report.nodeid not in _skipped:
        _skipped.append(report.nodeid)
    _file_seconds[report.nodeid.split("::")[0]] += report.duration


# ------------------------------------------------------------------ the order of the files
# pytest-xdist (--dist loadfile --no-loadscope-reorder, pyproject.toml) hands the files to its
# workers in collection order: the slowest of the last run first (their seconds kept in
# pytest's cache, aidl/file_seconds), so the run ends on small files and both workers end
# together; files the cache does not know (a fresh clone: all of them) by the seconds of a
# measured run kept in tests/file_seconds.json (a newcomer's first run would otherwise start
# the 40 s packaging test last, a file of few tests, and one worker would wait for it alone;
# `python tests/file_seconds.py` writes it anew from the cache of a whole run), then by their
# count of tests, most first (xdist's own order).  The controller reads the figures once and
# gives both workers the same (their collections must match).
_file_seconds: collections.Counter = collections.Counter()
_SECONDS_KEY = "aidl/file_seconds"
MEASURED_SECONDS = ROOT / "tests" / "file_seconds.json"


def _seconds_of_files(config) -> dict:
    """Seconds a file took: this checkout's last run (pytest's cache) over the committed table."""
    import json
    try:
        seconds = json.loads(MEASURED_SECONDS.read_text())
    except (OSError, ValueError):
        seconds = {}
    cache = getattr(config, "cache", None)
    seconds.update(cache.get(_SECONDS_KEY, {}) if cache else {})
    return seconds


@pytest.hookimpl(optionalhook=True)
def pytest_configure_node(node):
    node.workerinput["aidl_file_seconds"] = _seconds_of_files(node.config)


def pytest_collection_modifyitems(session, config, items):
    if _worker(config):
        seconds = config.workerinput.get("aidl_file_seconds", {})
    else:
        seconds = _seconds_of_files(config)
    count = collections.Counter(item.nodeid.split("::")[0] for item in items)
    rank = {f: i for i, f in enumerate(sorted(count, key=lambda f: (-seconds.get(f, 0.0),
                                                                     -count[f], f)))}
    items.sort(key=lambda item: rank[item.nodeid.split("::")[0]])     # stable within a file


def _keep_file_seconds(config) -> None:
    cache = getattr(config, "cache", None)
    if cache is not None and _file_seconds:
        kept = cache.get(_SECONDS_KEY, {})
        kept.update({f: round(t, 2) for f, t in _file_seconds.items()})
        cache.set(_SECONDS_KEY, kept)


def _worker(config) -> bool:
    """True in a pytest-xdist worker (the suite runs on ``-n auto`` workers, pyproject.toml)."""
    return hasattr(config, "workerinput")


@pytest.hookimpl(optionalhook=True)
def pytest_testnodedown(node, error):
    # a worker's leftover processes, reported in the controller (pytest-xdist hook)
    _left.extend(getattr(node, "workeroutput", {}).get("aidl_left", ()))


def pytest_sessionfinish(session, exitstatus):
    # the tests that skipped (most for want of a program from outside Python: Chromium,
    # Neovim, Inkscape, cairo): .ci/run runs them again once it has installed those, after
    # the README's command ran as written (pytest's cache: .pytest_cache/v/aidl/skipped).
    # Under pytest-xdist the controller sees every worker's reports and writes the list.
    cache = getattr(session.config, "cache", None)
    if cache is not None and not _worker(session.config):
        cache.set("aidl/skipped", _skipped)
        _keep_file_seconds(session.config)
    if not _CHECK:
        return
    import time
    deadline = time.monotonic() + _LEFT_GRACE
    # in the controller of an xdist run the children are the workers, which end after this
    # hook: each worker checks its own children and hands what it found to the controller
    controller = session.config.pluginmanager.hasplugin("dsession")
    if not controller:
        while (left := _children()) and time.monotonic() < deadline:
            time.sleep(0.1)
        _reap()
        for p in sorted(left):
            cmd = _proc_text(p, "cmdline").replace("\0", " ").strip()[:200]
            _left.append(f"pid {p} ({cmd or _proc_text(p, 'comm').strip()}), first seen after "
                         f"{_first_seen.get(p, 'the last test')}")
    if _worker(session.config):
        session.config.workeroutput["aidl_left"] = list(_left)
    if _left and session.exitstatus == 0:
        session.exitstatus = pytest.ExitCode.TESTS_FAILED


def pytest_terminal_summary(terminalreporter):
    if _left:
        terminalreporter.section("processes left running", sep="=", red=True, bold=True)
        terminalreporter.line(f"{len(_left)} child process(es) of the test run still running "
                              f"{_LEFT_GRACE:g} s after the last test (a test or fixture must "
                              "stop what it starts):", red=True)
        for line in _left:
            terminalreporter.line("  " + line)
