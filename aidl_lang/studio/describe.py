""""Describe the part" in ``aidl studio``: the validate-until-correct loop run for a browser.

The user types a description; :func:`describe` runs :func:`aidl_lang.llm.generate.generate`
(the loop of ``aidl generate``: ask the model for a program, compile it, feed the diagnostics
back, until it checks or the rounds run out) against the OpenAI-compatible endpoint the
operator configured, and yields JSON-ready events as the rounds happen.  Source: the AIDL
paper's validate-until-correct generation (arXiv:2502.09819, its LLM-generation experiments:
the model is prompted with the language's description and example programs, writes AIDL, and
the compiler's errors go back to it for up to 5 rounds until the program is valid; docs/llm.md
describes ``aidl generate``, which packages that loop and which this runs unchanged).

Configuration (:func:`model_config`, read from the environment by the operator):

* ``AIDL_STUDIO_MODEL_URL``: the endpoint's base URL (``https://host/v1``; ``/chat/completions``
  is appended).  Unset or empty: :func:`model_config` returns None and the page offers no
  description box.
* ``AIDL_STUDIO_MODEL_KEY``: the API key (optional; sent as ``Authorization: Bearer``).
* ``AIDL_STUDIO_MODEL``: the model name (default ``gpt-4o``, as ``aidl generate``).
* ``AIDL_STUDIO_MODEL_ROUNDS``: rounds of error feedback, default 4, clamped to 1..8 (not a
  whole number: the default).  As in ``aidl generate``, a program that checks with warnings
  gets one more round, so a description costs at most ROUNDS + 1 requests.

Only ``config.public()`` (``{"model": name}``) may go to a browser: the URL and the key stay
on the server, and event messages name "the model endpoint" instead of the URL.

Events (:func:`describe`), each a dict ready for ``json.dumps``:

* ``{"type": "round", "n": 1, "code": str | None, "ok": bool, "diagnostics": [...],
  "more_diagnostics": int, "svg": str | None}`` once per round, in order, as soon as that
  round is compiled.  ``code``: the program in the model's reply (None: the reply had no
  ```aidl block, diagnostic ``E0000``).  ``ok``: it checks (warnings allowed).
  ``diagnostics``: at most 8 (errors first), each ``{"code", "severity", "message", "line",
  "col", "rendered"}``; ``line``/``col`` are 1-based in ``code`` (None for ``E0000``),
  ``rendered`` is the text ``aidl check`` prints, with file names relative to the folder
  (``main.aidl:9:76``); ``more_diagnostics`` counts those left out.  ``svg``: the round's
  drawing when it checks (:meth:`aidl_lang.api.Result.to_svg`: millimetres, the parts flat,
  ``<path>`` elements), else None.
* ``{"type": "done", "ok": bool, "code": str | None, "rounds": int, "warnings": [codes],
  "message": str}`` last, when the loop ended: ``code`` is the best program that checks (the
  one with the fewest warnings, the latest of equals; None when none did).
* ``{"type": "error", "message": str}`` last instead, when the description is not a string
  of 1..2,000 characters, no endpoint is configured, the endpoint failed (unreachable, an HTTP
  error, a reply that is not a chat completion: :class:`aidl_lang.llm.client.LLMError`) or the
  deadline passed.  Round events already sent stay valid: a page may keep the last round
  with ``ok`` true.  Never an exception for those.

Units: lengths in the programs and the SVG are millimetres unless the program says
otherwise; ``deadline_s`` is seconds of wall time.

Layering: this package sits above :mod:`aidl_lang.llm` and :mod:`aidl_lang.api`; neither
imports it.
"""
from __future__ import annotations

import logging
import math
import os
import queue
import threading
import time
from collections.abc import Iterator, Mapping
from dataclasses import dataclass, field

from ..llm.client import DEFAULT_MODEL, ChatClient, LLMError
from ..llm.generate import Round, generate

log = logging.getLogger(__name__)

MAX_DESCRIPTION = 2000          # characters of a description
MAX_DIAGNOSTICS = 8             # diagnostics of a round in its event
DEFAULT_ROUNDS = 4
MIN_ROUNDS, MAX_ROUNDS = 1, 8
PROGRAM_NAME = "main.aidl"      # the program's file name inside the folder
ENDPOINT = "the model endpoint"

ENV_URL = "AIDL_STUDIO_MODEL_URL"
ENV_KEY = "AIDL_STUDIO_MODEL_KEY"
ENV_MODEL = "AIDL_STUDIO_MODEL"
ENV_ROUNDS = "AIDL_STUDIO_MODEL_ROUNDS"


class ModelConfig(dict):
    """The operator's endpoint: a dict ``{"url", "key", "model", "rounds"}`` (``key`` may be
    None).  It holds the API key: give a browser only :meth:`public`.  Its ``repr`` hides the
    key (the dict itself, e.g. through ``json.dumps``, does not)."""

    def public(self) -> dict:
        """What a browser may see: ``{"model": name}``."""
        return {"model": self["model"]}

    def __repr__(self) -> str:
        shown = dict(self, key="***" if self.get("key") else None)
        return f"ModelConfig({shown!r})"


def model_config(env: Mapping[str, str] = os.environ) -> ModelConfig | None:
    """The endpoint configured in ``env`` (see the module docstring), or None when
    ``AIDL_STUDIO_MODEL_URL`` is unset or blank.  Never raises: a rounds value that is not a
    whole number is the default, one out of range is clamped to 1..8."""
    url = (env.get(ENV_URL) or "").strip()
    if not url:
        return None
    key = (env.get(ENV_KEY) or "").strip() or None
    model = (env.get(ENV_MODEL) or "").strip() or DEFAULT_MODEL
    try:
        rounds = int((env.get(ENV_ROUNDS) or "").strip() or DEFAULT_ROUNDS)
    except ValueError:
        log.warning("%s=%r is not a whole number; using %d", ENV_ROUNDS, env.get(ENV_ROUNDS),
                    DEFAULT_ROUNDS)
        rounds = DEFAULT_ROUNDS
    return ModelConfig(url=url, key=key, model=model,
                       rounds=min(MAX_ROUNDS, max(MIN_ROUNDS, rounds)))


class _Stopped(Exception):
    """The caller stopped waiting (deadline, or the generator was closed): end the loop."""


@dataclass
class _Client(ChatClient):
    """A :class:`ChatClient` whose every request waits at most until the deadline and is not
    made once the caller has stopped waiting."""

    deadline: float = math.inf                      # time.monotonic() value
    stop: threading.Event = field(default_factory=threading.Event)

    def complete(self, messages: list[dict]) -> str:
        if self.stop.is_set():
            raise _Stopped
        self.timeout = max(0.5, min(self.timeout, self.deadline - time.monotonic() + 0.5))
        return super().complete(messages)


def _error(message: str) -> dict:
    return {"type": "error", "message": message}


def _check_description(description) -> str | None:
    """Why ``description`` cannot be sent (None: it can)."""
    if not isinstance(description, str):
        return "the description must be text"
    text = description.strip()
    if not text:
        return "the description is empty: describe the part to draw"
    if len(text) > MAX_DESCRIPTION:
        return (f"the description has {len(text):,} characters; at most {MAX_DESCRIPTION:,} "
                "are allowed")
    return None


class _Scrub:
    """Takes server-side names out of text bound for a browser: the folder (file names become
    relative to it), the endpoint's URL and the key."""

    def __init__(self, folder: str, config: Mapping, client: ChatClient):
        self.pairs = [(folder + os.sep, "")]
        real = os.path.realpath(folder)
        if real != folder:
            self.pairs.append((real + os.sep, ""))
        from ..library.sources import STDLIB
        self.pairs.append((str(STDLIB.resolve()) + os.sep, "std/"))
        self.pairs += [(client.url, ENDPOINT), (str(config["url"]).strip(), ENDPOINT)]
        if config.get("key"):
            self.pairs.append((str(config["key"]), "***"))

    def __call__(self, text: str | None) -> str | None:
        if not text:
            return text
        for old, new in self.pairs:
            if old:
                text = text.replace(old, new)
        return text


def _diagnostic(d: dict, scrub: _Scrub) -> dict:
    span = d.get("span") or {}
    return {"code": d.get("code"), "severity": d.get("severity"),
            "message": scrub(d.get("message")), "line": span.get("line"),
            "col": span.get("column"), "rendered": scrub(d.get("rendered") or d.get("message"))}


def _svg(code: str, path: str) -> str | None:
    """The drawing of ``code`` compiled as ``path`` (imports resolved in its folder and the
    standard library only), or None when it does not compile or cannot be drawn."""
    from ..api import compile as compile_program
    try:
        res = compile_program(source=code, path=path)
        return res.to_svg() if res.ok else None
    except Exception:                   # a picture is a bonus: never lose the round for it
        log.exception("aidl studio: the SVG of a round that checks could not be made")
        return None


def round_event(r: Round, path: str, scrub: _Scrub) -> dict:
    """The ``round`` event of ``r`` (the module docstring), its SVG compiled as ``path``."""
    diags = sorted(r.diagnostics, key=lambda d: d.get("severity") != "error")
    return {"type": "round", "n": r.number, "code": r.code, "ok": r.ok,
            "diagnostics": [_diagnostic(d, scrub) for d in diags[:MAX_DIAGNOSTICS]],
            "more_diagnostics": max(0, len(diags) - MAX_DIAGNOSTICS),
            "svg": _svg(r.code, path) if r.ok and r.code else None}


def _done_message(res) -> str:
    n = len(res.rounds)
    rounds = f"{n} round{'s' if n != 1 else ''}"
    if res.ok:
        best = next((r.number for r in reversed(res.rounds) if r.code == res.code), n)
        warn = (f", with warnings {', '.join(sorted(set(res.warnings)))}" if res.warnings
                else "")
        return f"the program checks{warn} (round {best} of {rounds})"
    codes = res.rounds[-1].error_codes if res.rounds else []
    return (f"no program checked within {rounds}"
            + (f"; the last one had errors {', '.join(sorted(set(codes)))}" if codes else ""))


def describe(description: str, config: Mapping, folder: str | os.PathLike,
             deadline_s: float = 120.0) -> Iterator[dict]:
    """Run the loop for ``description`` with the endpoint ``config`` (:func:`model_config`);
    yield a ``round`` event per round as it is compiled, then one ``done`` or ``error`` event
    (shapes in the module docstring).  The program is compiled as ``FOLDER/main.aidl``: its
    imports and drawings resolve inside ``folder`` and the standard library only.

    The loop runs on a helper thread; this generator waits for its rounds in the calling
    thread for at most ``deadline_s`` seconds in all, then yields an ``error`` event and tells
    the loop to stop (it ends at its next request or round: a request in flight is given up
    at the deadline).  Closing the generator stops the loop the same way.  Raises
    :class:`ValueError` only for a ``deadline_s`` that is not a positive number (a mistake in
    the call); everything else is an event."""
    if not isinstance(deadline_s, (int, float)) or not deadline_s > 0 or math.isinf(deadline_s):
        raise ValueError(f"deadline_s must be a positive number of seconds, got {deadline_s!r}")
    start = time.monotonic()
    why = _check_description(description)
    if why:
        yield _error(why)
        return
    if not config or not str(config.get("url") or "").strip():
        yield _error(f"no model endpoint is configured (set {ENV_URL})")
        return
    url = str(config["url"]).strip()
    if not url.lower().startswith(("http://", "https://")):
        yield _error(f"{ENV_URL} must be an http:// or https:// URL")
        return
    folder = os.path.abspath(os.fspath(folder))
    path = os.path.join(folder, PROGRAM_NAME)
    rounds = int(config.get("rounds") or DEFAULT_ROUNDS)
    rounds = min(MAX_ROUNDS, max(MIN_ROUNDS, rounds))
    end = start + float(deadline_s)
    client = _Client(base_url=url, model=str(config.get("model") or DEFAULT_MODEL),
                     api_key=config.get("key") or None, deadline=end)
    stop = client.stop
    scrub = _Scrub(folder, config, client)
    events: queue.Queue = queue.Queue()

    def on_round(r: Round) -> None:
        if stop.is_set():
            raise _Stopped
        events.put(round_event(r, path, scrub))
        if stop.is_set():
            raise _Stopped

    def run() -> None:
        try:
            res = generate(description.strip(), client, max_rounds=rounds, path=path,
                           on_round=on_round)
        except _Stopped:
            return
        except LLMError as e:
            events.put(_error(scrub(str(e))))
        except Exception as e:                  # a bug, not the user's: logged, reported short
            log.exception("aidl studio: the model loop failed")
            events.put(_error(f"the model loop failed ({type(e).__name__}); see the server log"))
        else:
            events.put({"type": "done", "ok": res.ok, "code": res.code,
                        "rounds": len(res.rounds), "warnings": list(res.warnings),
                        "message": _done_message(res)})

    worker = threading.Thread(target=run, name="aidl-studio-describe", daemon=True)
    worker.start()
    seen = 0
    try:
        while True:
            left = end - time.monotonic()
            try:
                if left <= 0:
                    raise queue.Empty
                event = events.get(timeout=left)
            except queue.Empty:
                stop.set()
                yield _error(f"the model did not finish within {deadline_s:g} s "
                             f"({seen} round{'s' if seen != 1 else ''} done); stopped")
                return
            if event["type"] == "round":
                seen += 1
            yield event
            if event["type"] != "round":
                return
    finally:
        stop.set()
