"""The gallery's designs swept ahead of time (issue 113): a visitor who opens one sees the
whole judgement of its sliders, never the part a request's budget allowed.

A sweep request (``/api/sweep``) is bounded by one sweep's work budget; on a design of many
sliders that budget judges part of what the scan plans (the tool holder: 51 of 283 values,
its sliders read "clean 16-16"), and such an answer was cached and served to every later
visitor.  The studio now keeps only whole answers (:func:`complete`), and sweeps the gallery's
designs at their own values in the background, in a process of its own at the lowest
priority, with :data:`SCALE` times the budget (a sweep ends when its plan is judged: the
budget bounds it, it is not spent): :class:`Ahead`.  Each answer is kept in the user's cache
beside the gallery's thumbnails, filed under the program's text, the scale and the build
(:func:`aidl_lang.studio.gallery.code_fingerprint`), so a fresh server of one build answers
at once.  ``aidl studio --ahead all`` (the default; ``none``, or gallery ids separated by
commas: ``AIDL_STUDIO_AHEAD``).  Not part of the stable API.
"""
from __future__ import annotations

import hashlib
import json
import os
import tempfile
import threading

SCALE = 16.0                # times one sweep's budget a design swept ahead of time may spend
NICE = 19                   # the process's niceness: it takes what nothing else wants


def complete(answer) -> bool:
    """Whether a sweep answer (:func:`aidl_lang.studio.hatching.sweep_ranges`) judged all it
    planned: it compiled, nothing ``skipped``, no slider with a part ``unjudged``."""
    return isinstance(answer, dict) and bool(answer.get("ok")) and "error" not in answer \
        and not answer.get("skipped") \
        and not any(q.get("unjudged") for q in (answer.get("params") or {}).values())


def wanted(setting: str) -> list:
    """The gallery entries ``setting`` names: ``all``, ``none`` (or empty), or ids separated
    by commas (an id the gallery lacks is left out)."""
    from . import gallery
    text = (setting or "").strip()
    if text in ("", "none"):
        return []
    if text == "all":
        return gallery.entries()
    return [e for e in (gallery.entry(i.strip()) for i in text.split(",")) if e is not None]


def _digest(source: str) -> str:
    return hashlib.sha256(source.encode("utf-8", "surrogatepass")).hexdigest()


def key(source: str) -> str:
    """What a kept answer of ``source`` is filed under: the program's text, :data:`SCALE`
    and the build."""
    from .gallery import code_fingerprint
    return hashlib.sha256(f"{code_fingerprint()}\0sweep\0{SCALE!r}\0{source}".encode(
        "utf-8", "surrogatepass")).hexdigest()


def _path(k: str):
    from .gallery import _thumb_path
    return _thumb_path(k, ".sweep.json")


def kept(source: str) -> dict | None:
    """The whole sweep of ``source`` at its own values kept by this or another server of this
    build, or None."""
    from ..host.cache import read_checked
    k = key(source)
    path = _path(k)
    text = read_checked(path, k) if path is not None else None
    try:
        answer = json.loads(text) if text else None
    except ValueError:
        return None
    return answer if complete(answer) else None


def keep(source: str, answer: dict) -> bool:
    """Keep the whole ``answer`` of ``source`` for :func:`kept`; False when it is not whole or
    the cache cannot be written."""
    from ..host.cache import write_checked
    if not complete(answer):
        return False
    k = key(source)
    path = _path(k)
    return path is not None and write_checked(path, k, json.dumps(answer))


class Ahead:
    """The gallery's sweeps of one server process: ``done`` (the program's digest -> its
    whole answer), filled from the cache at once and by a background thread that sweeps the
    rest, one design at a time, in its own worker process (:data:`NICE`, the compile workers'
    memory cap, :data:`SCALE` times their wall limit).  ``stats``: ``kept``, ``swept``,
    ``partial`` (a design whose sweep was not whole even so: its visitors' requests sweep it
    as any program), ``failed``."""

    def __init__(self, entries: list, budget: float, seconds: float, memory) -> None:
        self.entries = list(entries)
        self.budget, self.seconds, self.memory = budget, seconds, memory
        self.done: dict[str, dict] = {}
        self.stats = {"kept": 0, "swept": 0, "partial": 0, "failed": 0, "left": len(self.entries)}
        self.stopped = threading.Event()
        self.finished = threading.Event()
        self.worker = None
        self.thread = None

    def answer(self, source: str, values: dict | None, uploads: bool) -> dict | None:
        """The whole sweep of a gallery design asked at its own values (no value set, no
        upload in the session), or None."""
        if values or uploads or not self.done:
            return None
        got = self.done.get(_digest(source))
        return None if got is None else {**got, "cached": True, "ahead": True}

    def start(self) -> None:
        if not self.entries:
            self.finished.set()
            return
        self.thread = threading.Thread(target=self._run, name="aidl-studio-ahead", daemon=True)
        self.thread.start()

    def _run(self) -> None:
        from ..host import workers as W
        from . import compiler
        folder = tempfile.mkdtemp(prefix="aidl-ahead-")
        try:
            todo = []
            for e in self.entries:
                got = kept(e.source)
                if got is not None:
                    self.done[_digest(e.source)] = got
                    self.stats["kept"] += 1
                    self.stats["left"] -= 1
                else:
                    todo.append(e)
            # another server process of this machine sweeps the same list: each starts at its
            # own place in it and takes what another kept meanwhile
            k = os.getpid() % len(todo) if todo else 0
            for e in todo[k:] + todo[:k]:
                if self.stopped.is_set():
                    return
                got = kept(e.source)
                if got is not None:
                    self.done[_digest(e.source)] = got
                    self.stats["kept"] += 1
                    self.stats["left"] -= 1
                    continue
                if self.worker is None:
                    self.worker = W.Worker(compiler.handler, (self.budget,), self.memory,
                                           1, compiler.PRELOAD, nice=NICE)
                try:
                    got = self.worker.request(("sweep", "", folder, e.source, {}, SCALE),
                                              self.seconds * SCALE)
                except W.WorkerError:
                    got = None
                if isinstance(got, dict):
                    got.pop("retire", None)
                self.stats["left"] -= 1
                if self.stopped.is_set():
                    return
                if complete(got):
                    self.done[_digest(e.source)] = got
                    keep(e.source, got)
                    self.stats["swept"] += 1
                else:
                    self.stats["partial" if isinstance(got, dict) else "failed"] += 1
        finally:
            if self.worker is not None:
                self.worker.stop()
            try:
                os.rmdir(folder)
            except OSError:
                pass
            self.finished.set()

    def stop(self) -> None:
        self.stopped.set()
        w = self.worker
        if w is not None:
            w.cancel()
            w.stop()                    # (one still starting too)
        if self.thread is not None:
            self.thread.join(timeout=10)
