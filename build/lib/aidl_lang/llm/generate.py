"""The validate-until-correct loop (``aidl generate``): ask a model for a program, compile it,
feed the diagnostics back, at most ``max_rounds`` times (paper: 5 rounds).

Each round the reply's ```aidl block is compiled with :func:`aidl_lang.pipeline.compile_source`
(parse, check, interpret, solve).  Errors go back to the model as the same text the command
line prints, with the instruction to fix the program without deleting design intent (the
paper's commonest failure: models silencing errors by removing constraints and structures).
The transcript (every message, every round's code and diagnostics) is kept as JSON and
Markdown next to the output; the output file is written only when the program checks.
"""
from __future__ import annotations

import json
import os
import re
import tempfile
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Callable

from ..diagnostics import render_text
from .client import ChatClient
from ..pipeline import compile_source
from .prompt import system_prompt

MAX_FEEDBACK_DIAGNOSTICS = 8

FEEDBACK = """\
The program does not compile yet. Diagnostics:

{diagnostics}

Fix these errors and reply with the complete corrected program in one ```aidl block.
Keep every structure, shape and constraint that expresses the design intent: correct the
call (its name, arguments, units or the structure it is in) rather than deleting it."""

WARNING_FEEDBACK = """\
The program compiles, but with warnings. A warning means it probably does not draw what you
meant. Diagnostics:

{diagnostics}

Fix what the warnings point at and reply with the complete program in one ```aidl block. If
a warning describes exactly what you intended, reply with the same program unchanged."""

NO_CODE = ("Your reply has no ```aidl code block. Reply with the complete program in one "
           "```aidl block.")


@dataclass
class Round:
    number: int
    reply: str
    code: str | None
    ok: bool
    diagnostics: list[dict] = field(default_factory=list)   # Diagnostic.to_json() items
    feedback: str | None = None

    @property
    def error_codes(self) -> list[str]:
        return [d["code"] for d in self.diagnostics if d["severity"] == "error"]

    @property
    def warning_codes(self) -> list[str]:
        return [d["code"] for d in self.diagnostics if d["severity"] == "warning"]


@dataclass
class Result:
    prompt: str
    model: str
    ok: bool
    rounds: list[Round]
    code: str | None = None           # the program that checks (when ok)
    messages: list[dict] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)   # warning codes of that program

    @property
    def first_try(self) -> bool:
        return bool(self.rounds) and self.rounds[0].ok

    @property
    def error_codes(self) -> list[str]:
        return [c for r in self.rounds for c in r.error_codes]

    @property
    def clean(self) -> bool:
        """Valid and without warnings."""
        return self.ok and not self.warnings

    def to_json(self) -> dict:
        return {"prompt": self.prompt, "model": self.model, "ok": self.ok,
                "first_try": self.first_try, "rounds_used": len(self.rounds),
                "error_codes": self.error_codes, "warnings": self.warnings,
                "clean": self.clean,
                "rounds": [asdict(r) | {"error_codes": r.error_codes} for r in self.rounds],
                "messages": self.messages}


def extract_code(reply: str) -> str | None:
    """The program in a reply: the last ```aidl block, else the last ``` block, else None."""
    blocks = re.findall(r"```[ \t]*aidl[^\n]*\n(.*?)(?:```|\Z)", reply, re.S | re.I)
    if not blocks:
        blocks = re.findall(r"```[^\n]*\n(.*?)(?:```|\Z)", reply, re.S)
    blocks = [b for b in blocks if b.strip()]
    return blocks[-1] if blocks else None


def feedback_for(compiled, limit: int = MAX_FEEDBACK_DIAGNOSTICS) -> str:
    """The message telling the model what is wrong (errors first, as the CLI prints them);
    for a program that compiles, its warnings (any warning diagnostic, from any stage)."""
    items = sorted(compiled.sink.items, key=lambda d: not d.is_error)[:limit]
    text = "\n\n".join(render_text(d, compiled.sink.sources, color=False) for d in items)
    more = len(compiled.sink.items) - len(items)
    if more > 0:
        text += f"\n\n(and {more} more)"
    return (FEEDBACK if not compiled.ok else WARNING_FEEDBACK).format(diagnostics=text)


def generate(prompt: str, client: ChatClient, max_rounds: int = 5, path: str = "generated.aidl",
             progress: Callable[[str], None] | None = None,
             system: str | None = None, warning_rounds: int = 1) -> Result:
    """Run the loop for ``prompt``; ``path`` names the program in diagnostics and resolves its
    relative imports.  Errors are fed back for at most ``max_rounds`` rounds; a program that
    compiles with warnings is sent back for up to ``warning_rounds`` extra rounds (each may
    go past ``max_rounds``).  The result keeps the valid program with the fewest warnings
    (the latest of equals).  Raises :class:`aidl_lang.llm.LLMError` if the endpoint fails."""
    say = progress or (lambda s: None)
    messages = [{"role": "system", "content": system if system is not None else system_prompt()},
                {"role": "user", "content": prompt}]
    rounds: list[Round] = []
    best: Round | None = None
    warn_used = 0
    limit = max_rounds
    n = 0
    while n < limit:
        n += 1
        say(f"round {n}/{limit}: asking {client.model} ...")
        reply = client.complete(messages)
        messages.append({"role": "assistant", "content": reply})
        code = extract_code(reply)
        if code is None:
            rnd = Round(n, reply, None, False, [{"code": "E0000", "severity": "error",
                                                  "message": "no ```aidl block in the reply"}],
                        NO_CODE)
        else:
            compiled = compile_source(code, path)
            diags = [d.to_json(compiled.sink.sources) for d in compiled.sink.items]
            rnd = Round(n, reply, code, compiled.ok, diags)
            if not compiled.ok or (rnd.warning_codes and warn_used < warning_rounds):
                rnd.feedback = feedback_for(compiled)
        rounds.append(rnd)
        if rnd.ok:
            if best is None or len(rnd.warning_codes) <= len(best.warning_codes):
                best = rnd
            if rnd.feedback is None:
                say(f"round {n}: valid" + (f", {len(rnd.warning_codes)} warning(s)"
                                            if rnd.warning_codes else ""))
                break
            warn_used += 1
            limit = max(limit, n + 1)
            say(f"round {n}: valid with {len(rnd.warning_codes)} warning(s): "
                f"{', '.join(sorted(set(rnd.warning_codes)))}; asking again")
        else:
            say(f"round {n}: {len(rnd.error_codes)} error(s): "
                f"{', '.join(sorted(set(rnd.error_codes)))}")
        if n < limit:
            messages.append({"role": "user", "content": rnd.feedback})
    if best is None:
        return Result(prompt, client.model, False, rounds, None, messages)
    return Result(prompt, client.model, True, rounds, best.code, messages, best.warning_codes)


def transcript_markdown(res: Result) -> str:
    out = ["# aidl generate transcript\n", f"- prompt: {res.prompt}", f"- model: {res.model}",
           f"- result: {'valid' if res.ok else 'not valid'} after {len(res.rounds)} round(s)\n"]
    for r in res.rounds:
        head = ("valid" + (" with warnings " + ", ".join(r.warning_codes) if r.warning_codes else "")
                if r.ok else "errors " + ", ".join(r.error_codes))
        out.append(f"## Round {r.number}: {head}\n")
        out.append("### Reply\n\n" + r.reply.strip() + "\n")
        if r.feedback:
            out.append("### Feedback\n\n````text\n" + r.feedback.strip() + "\n````\n")
    return "\n".join(out)


def write_atomic(path: Path, text: str) -> None:
    """Write ``text`` to a temporary file beside ``path``, then rename it over ``path``."""
    fd, tmp = tempfile.mkstemp(suffix=path.suffix, dir=str(path.parent.resolve()))
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as f:
            f.write(text)
        os.replace(tmp, path)
    except BaseException:
        if os.path.exists(tmp):
            os.unlink(tmp)
        raise


def transcript_paths(out: Path) -> tuple[Path, Path]:
    """``FILE.aidl`` -> (``FILE.transcript.json``, ``FILE.transcript.md``)."""
    stem = out.with_suffix("")
    return Path(f"{stem}.transcript.json"), Path(f"{stem}.transcript.md")


def save(res: Result, out: Path) -> None:
    """Write the transcripts next to ``out``, and ``out`` itself when the program checks."""
    js, md = transcript_paths(out)
    write_atomic(js, json.dumps(res.to_json(), indent=2))
    write_atomic(md, transcript_markdown(res))
    if res.ok and res.code is not None:
        write_atomic(out, res.code if res.code.endswith("\n") else res.code + "\n")
