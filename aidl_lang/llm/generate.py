"""The validate-until-correct loop (``aidl generate``): ask a model for a program, compile it,
feed the diagnostics back, at most ``max_rounds`` times (paper: 5 rounds).

Each round the reply's ```aidl block is compiled with :func:`aidl_lang.pipeline.compile_source`
(parse, check, interpret, solve).  Errors go back to the model as the same text the command
line prints, with the instruction to fix the program without deleting design intent (the
paper's commonest failure: models silencing errors by removing constraints and structures).
The transcript (every message, every round's code and diagnostics) is kept as JSON and
Markdown next to the output; the output file is written only when the program checks.

Visual rounds (``visual_rounds``, off by default): once a program checks and the warning
rounds are done, its rendering goes to the model as a PNG (an OpenAI-style ``image_url`` part
with a ``data:image/png;base64`` URL) with the request and any warnings; the model replies
``LOOKS RIGHT`` (the loop stops) or a corrected program, compiled like any other round.  The
pictures are kept (``FILE.roundN.png``, written by :func:`save`) and the transcript records
their paths, never their bytes.
"""
from __future__ import annotations

import base64
import json
import re
import struct
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Callable

from ..base.diagnostics import render_texts
from .client import ChatClient, LLMError
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

VISUAL_FEEDBACK = """\
The program compiles. The attached picture is its rendering{which}: the outline that will be
cut, holes and engraving, on a white page. The request was:

{request}
{warnings}
Look at the picture and compare it with the request. Check especially for parts floating
apart that should be joined, shapes overlapping where they should not (or missing an overlap
where they should be joined), text or holes running over an edge, and wrong proportions or
sizes. If the drawing matches the request, reply exactly LOOKS RIGHT and nothing else.
Otherwise reply with the complete corrected program in one ```aidl block. Keep every
structure, shape and constraint that expresses the design intent."""

NO_VERDICT = ("Your reply has neither LOOKS RIGHT nor an ```aidl code block. Reply exactly "
              "LOOKS RIGHT if the picture matches the request, or the complete corrected "
              "program in one ```aidl block.")

LOOKS_RIGHT = "LOOKS RIGHT"
PICTURE_SIDE = 768          # pixels: the longer side of a picture sent to the model

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
    kind: str = "program"     # "visual": the reply answers a picture (the round before it)
    picture: str | None = None   # the PNG sent with this round's feedback (its path)
    verdict: str | None = None   # visual rounds: "looks right" | "revised" | "no verdict"

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
    pictures: dict[str, bytes] = field(default_factory=dict)   # path -> PNG (not in JSON)
    visual_rounds: int = 0            # pictures sent
    looks_right: bool = False         # the model answered LOOKS RIGHT to the last picture
    visual_error: str | None = None   # the endpoint failed on a picture (the program is kept)

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
                "clean": self.clean, "visual_rounds": self.visual_rounds,
                "looks_right": self.looks_right, "visual_error": self.visual_error,
                "pictures": list(self.pictures),
                "rounds": [asdict(r) | {"error_codes": r.error_codes,
                                        "warning_codes": r.warning_codes} for r in self.rounds],
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
    text = "\n\n".join(render_texts(items, compiled.sink.sources, color=False))
    more = len(compiled.sink.items) - len(items)
    if more > 0:
        text += f"\n\n(and {more} more)"
    return (FEEDBACK if not compiled.ok else WARNING_FEEDBACK).format(diagnostics=text)


def png_size(data: bytes) -> tuple[int, int] | None:
    """(width, height) of PNG bytes from the IHDR chunk, or None if ``data`` is not a PNG."""
    if len(data) < 24 or data[:8] != b"\x89PNG\r\n\x1a\n" or data[12:16] != b"IHDR":
        return None
    return struct.unpack(">II", data[16:24])


def render_picture(compiled, side: int = PICTURE_SIDE) -> bytes:
    """The PNG of a compiled program, its longer side ``side`` pixels (the preview style on
    white).  Raises :class:`aidl_lang.output.MissingDependency` without cairosvg and
    :class:`aidl_lang.output.OutputError`."""
    from ..output import Options, build, encode
    out = build(compiled.drawing, compiled.model.root.name)
    png = encode(out, ".png", Options(width=side))
    size = png_size(png)
    if size and size[1] > size[0]:               # taller than wide: fit the height instead
        png = encode(out, ".png", Options(width=max(1, round(side * size[0] / size[1]))))
    return png


def picture_path(path: str, number: int) -> str:
    """``FILE.aidl`` -> ``FILE.roundN.png``: the picture sent after round ``number``."""
    return f"{Path(path).with_suffix('')}.round{number}.png"


def is_looks_right(reply: str) -> bool:
    """The reply is the verdict LOOKS RIGHT (case, quotes, backticks and a full stop aside)."""
    text = reply.strip().strip("`*\"'. \n").upper()
    return text == LOOKS_RIGHT or (text.startswith(LOOKS_RIGHT) and len(text) < 40)


def visual_message(request: str, best: Round, latest: Round, picture: str) -> list[dict]:
    """The user message content of a visual round: the instruction (with the request, the
    pictured program's warnings, and the program itself when it is not the model's last one)
    and the picture as an ``image_url`` part.  ``picture`` is the picture's path: the
    conversation keeps paths, :func:`request_messages` puts the bytes in when sending."""
    warns = [d for d in best.diagnostics if d["severity"] == "warning"]
    text = "\n\n".join(d.get("rendered") or d["message"] for d in warns[:MAX_FEEDBACK_DIAGNOSTICS])
    warnings = (f"\nIt still has {len(warns)} warning(s):\n\n{text}\n" if warns else "")
    which = ("" if best is latest else
             f" (of the program of round {best.number}, the best so far:\n\n```aidl\n"
             f"{best.code.rstrip()}\n```\n)")
    body = VISUAL_FEEDBACK.format(which=which, request=request, warnings=warnings)
    return [{"type": "text", "text": body}, {"type": "image_url", "image_url": {"url": picture}}]


def request_messages(messages: list[dict], pictures: dict[str, bytes]) -> list[dict]:
    """What is sent: ``messages`` with the newest picture as a ``data:image/png;base64`` URL
    and every older one replaced by a line of text (each picture is paid for once)."""
    last = max((i for i, m in enumerate(messages) if isinstance(m.get("content"), list)),
               default=-1)
    out = []
    for i, m in enumerate(messages):
        if isinstance(m.get("content"), list):
            parts = []
            for p in m["content"]:
                if p.get("type") != "image_url":
                    parts.append(p)
                elif i == last:
                    data = base64.b64encode(pictures[p["image_url"]["url"]]).decode("ascii")
                    parts.append({"type": "image_url",
                                  "image_url": {"url": "data:image/png;base64," + data}})
                else:
                    parts.append({"type": "text", "text": "(the picture of this earlier "
                                                          "version is left out)"})
            m = m | {"content": parts}
        out.append(m)
    return out


def generate(prompt: str, client: ChatClient, max_rounds: int = 5, path: str = "generated.aidl",
             progress: Callable[[str], None] | None = None,
             system: str | None = None, warning_rounds: int = 1,
             visual_rounds: int = 0,
             on_round: Callable[[Round], None] | None = None) -> Result:
    """Run the loop for ``prompt``; ``path`` names the program in diagnostics and resolves its
    relative imports.  Errors are fed back for at most ``max_rounds`` rounds; a program that
    compiles with warnings is sent back for up to ``warning_rounds`` extra rounds (each may
    go past ``max_rounds``).  The result keeps the valid program with the fewest warnings
    (the latest of equals).

    ``visual_rounds``: after that, up to this many times, the best program's rendering is
    sent as a picture (:func:`visual_message`); a reply ``LOOKS RIGHT`` ends the loop, a
    program is compiled like any other round (each visual round may go past ``max_rounds``).
    A revision that checks replaces the program (even with more warnings); one that does not
    compile gets the error rounds left, and at least one, and never replaces the earlier
    valid program.  Pictures are kept in ``Result.pictures`` by path
    (:func:`picture_path`), older ones are left out of later requests.

    ``on_round``: called with each :class:`Round` once it is compiled and complete (its code,
    diagnostics, ``ok``, feedback, and the picture sent after it), in order, in the thread
    running the loop, before the next request; what it raises ends the loop and propagates
    (a caller streaming rounds may raise to stop early).

    Raises :class:`aidl_lang.llm.LLMError` if the endpoint fails, except once a picture was
    sent and a program checks: then the loop stops with it (``Result.visual_error``)."""
    say = progress or (lambda s: None)
    messages = [{"role": "system", "content": system if system is not None else system_prompt()},
                {"role": "user", "content": prompt}]
    rounds: list[Round] = []
    best: Round | None = None
    pictures: dict[str, bytes] = {}
    warn_used = visual_used = 0
    expect_visual = looks_right = revising = False
    visual_error = None
    grace = False
    limit = max_rounds
    n = 0
    while n < limit:
        n += 1
        say(f"round {n}/{limit}: asking {client.model} ..."
            + (" (visual check)" if expect_visual else ""))
        try:
            reply = client.complete(request_messages(messages, pictures))
        except LLMError as e:
            if not pictures or best is None:
                raise
            # e.g. a text-only model refusing the image: the valid program is not lost
            visual_error = str(e)
            say(f"round {n}: the visual check failed ({e}); keeping round {best.number}'s "
                "program")
            break
        messages.append({"role": "assistant", "content": reply})
        code = extract_code(reply)
        kind = "visual" if expect_visual else "program"
        compiled = None
        if expect_visual and (is_looks_right(reply) and code is None or code is not None
                              and best is not None and code.strip() == best.code.strip()):
            rounds.append(Round(n, reply, code, True, kind=kind, verdict="looks right"))
            looks_right = True
            say(f"round {n}: LOOKS RIGHT")
            if on_round is not None:
                on_round(rounds[-1])
            break
        if code is None:
            rnd = Round(n, reply, None, False, [{"code": "E0000", "severity": "error",
                                                  "message": "no ```aidl block in the reply"}],
                        NO_VERDICT if expect_visual else NO_CODE, kind=kind,
                        verdict="no verdict" if expect_visual else None)
        else:
            compiled = compile_source(code, path)
            diags = [d.to_json(compiled.sink.sources) for d in compiled.sink.items]
            rnd = Round(n, reply, code, compiled.ok, diags, kind=kind,
                        verdict="revised" if expect_visual else None)
            revising = revising or expect_visual
            if not compiled.ok or (rnd.warning_codes and warn_used < warning_rounds):
                rnd.feedback = feedback_for(compiled)
            expect_visual = False
        if kind == "visual" and not rnd.ok and grace:
            limit = max(limit, n + 1)      # a broken visual reply gets at least one repair
            grace = False                  # (once per picture: a model that never answers
                                           # ends when the rounds run out)
        rounds.append(rnd)
        content: str | list[dict] | None = rnd.feedback
        if rnd.ok:
            # a visual revision (or the repair of one) that checks replaces the program;
            # otherwise the fewest warnings win, the latest of equals
            if best is None or revising or len(rnd.warning_codes) <= len(best.warning_codes):
                best = rnd
            revising = False
            if rnd.feedback is None:
                say(f"round {n}: valid" + (f", {len(rnd.warning_codes)} warning(s)"
                                            if rnd.warning_codes else ""))
                picture = (_picture(best, compiled if best is rnd else None, path, say)
                           if visual_used < visual_rounds else None)
                if picture is None:
                    if on_round is not None:
                        on_round(rnd)
                    break
                visual_used += 1
                rnd.picture = picture_path(path, n)
                pictures[rnd.picture] = picture
                content = visual_message(prompt, best, rnd, rnd.picture)
                rnd.feedback = content[0]["text"]
                expect_visual = grace = True
                limit = max(limit, n + 1)
                w, h = png_size(picture) or (0, 0)
                say(f"round {n}: sending a {w}x{h} picture of round {best.number}'s program "
                    f"(visual round {visual_used}/{visual_rounds})")
            else:
                warn_used += 1
                limit = max(limit, n + 1)
                say(f"round {n}: valid with {len(rnd.warning_codes)} warning(s): "
                    f"{', '.join(sorted(set(rnd.warning_codes)))}; asking again")
        else:
            say(f"round {n}: {len(rnd.error_codes)} error(s): "
                f"{', '.join(sorted(set(rnd.error_codes)))}")
        if on_round is not None:
            on_round(rnd)
        if n < limit:
            messages.append({"role": "user", "content": content})
    if best is None:
        return Result(prompt, client.model, False, rounds, None, messages, pictures=pictures,
                      visual_rounds=visual_used)
    return Result(prompt, client.model, True, rounds, best.code, messages, best.warning_codes,
                  pictures, visual_used, looks_right, visual_error)


def _picture(best: Round, compiled, path: str, say: Callable[[str], None]) -> bytes | None:
    """The PNG of the best program (``compiled``: its compilation, if at hand), or None (said
    on progress) when it cannot be drawn."""
    from ..output import MissingDependency, OutputError
    if compiled is None:
        compiled = compile_source(best.code, path)
    if compiled.drawing is None or compiled.model is None:
        say("no visual round: the program has no drawing")
        return None
    try:
        return render_picture(compiled)
    except (MissingDependency, OutputError) as e:
        say(f"no visual round: {e}")
        return None


def transcript_markdown(res: Result) -> str:
    out = ["# aidl generate transcript\n", f"- prompt: {res.prompt}", f"- model: {res.model}",
           f"- result: {'valid' if res.ok else 'not valid'} after {len(res.rounds)} round(s)\n"]
    if res.visual_rounds:
        out[-1] = out[-1].rstrip("\n")
        out.append(f"- visual rounds: {res.visual_rounds} picture(s) sent; "
                   + ("the model answered LOOKS RIGHT" if res.looks_right
                      else f"the endpoint failed: {res.visual_error}" if res.visual_error
                      else "no LOOKS RIGHT") + "\n")
    for r in res.rounds:
        head = ("valid" + (" with warnings " + ", ".join(r.warning_codes) if r.warning_codes else "")
                if r.ok else "errors " + ", ".join(r.error_codes))
        if r.verdict == "looks right":
            head = "visual check: LOOKS RIGHT"
        elif r.kind == "visual":
            head = f"visual check: {r.verdict}, {head}"
        out.append(f"## Round {r.number}: {head}\n")
        out.append("### Reply\n\n" + r.reply.strip() + "\n")
        if r.feedback:
            out.append("### Feedback\n\n````text\n" + r.feedback.strip() + "\n````\n")
        if r.picture:
            out.append(f"![the picture sent after round {r.number}]({Path(r.picture).name})\n")
    return "\n".join(out)


def write_atomic(path: Path, text: str | bytes) -> None:
    """Write ``text`` (UTF-8) or bytes to a temporary file beside ``path``, then rename it over
    ``path`` (:func:`aidl_lang.output.writers.write.write_atomic`: never over a FIFO, device or
    directory).  Raises :class:`~aidl_lang.output.writers.write.WriteError`."""
    from ..output.writers.write import write_atomic as write
    write(Path(path), text if isinstance(text, bytes) else text.encode("utf-8"))


def transcript_paths(out: Path) -> tuple[Path, Path]:
    """``FILE.aidl`` -> (``FILE.transcript.json``, ``FILE.transcript.md``)."""
    stem = out.with_suffix("")
    return Path(f"{stem}.transcript.json"), Path(f"{stem}.transcript.md")


def save(res: Result, out: Path) -> None:
    """Write the transcripts and the pictures of visual rounds next to ``out``, and ``out``
    itself when the program checks."""
    js, md = transcript_paths(out)
    for name, png in res.pictures.items():
        write_atomic(Path(name), png)
    write_atomic(js, json.dumps(res.to_json(), indent=2))
    write_atomic(md, transcript_markdown(res))
    if res.ok and res.code is not None:
        write_atomic(out, res.code if res.code.endswith("\n") else res.code + "\n")
