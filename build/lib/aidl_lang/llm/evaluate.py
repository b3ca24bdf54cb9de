"""The eval harness (``aidl eval PROMPTS.txt --runs K``): run the generate loop over a prompt
list and report how often and how fast models reach a valid program.

Writes into the output folder: ``programs/`` (each run's program when valid, and its
transcripts), ``report.json`` (per run: valid, valid on first try, rounds used, error codes;
summary: valid on first try, valid within N rounds, mean rounds of valid runs, error code
counts), ``report.md`` and ``index.html`` (a contact sheet: each prompt with every valid
rendering inline beside it).
"""
from __future__ import annotations

import html
import json
from collections import Counter
from dataclasses import dataclass
from pathlib import Path
from typing import Callable

from .generate import Result, generate, save, write_atomic
from .client import ChatClient


@dataclass
class Run:
    prompt_index: int
    run: int
    result: Result
    program: str            # path of the program (written only when valid)
    svg: str | None         # SVG text of the rendering when valid


def read_prompts(path: Path) -> list[str]:
    """One prompt per line; blank lines and lines starting with ``#`` are skipped."""
    lines = path.read_text(encoding="utf-8").splitlines()
    return [ln.strip() for ln in lines if ln.strip() and not ln.lstrip().startswith("#")]


def _render(code: str, path: str) -> str | None:
    from ..pipeline import compile_source
    from ..output import render_model, to_svg
    c = compile_source(code, path)
    if not c.ok:
        return None
    return to_svg(render_model(c.model), title=c.model.root.name)


def run_eval(prompts: list[str], client: ChatClient, out_dir: Path, runs: int = 1,
             max_rounds: int = 5, progress: Callable[[str], None] | None = None,
             warning_rounds: int = 1) -> dict:
    """Run every prompt ``runs`` times; write the report files; return the report dict.

    Raises :class:`aidl_lang.llm.LLMError` if the endpoint fails.
    """
    say = progress or (lambda s: None)
    progs = out_dir / "programs"
    progs.mkdir(parents=True, exist_ok=True)
    all_runs: list[Run] = []
    for i, prompt in enumerate(prompts):
        for k in range(runs):
            out = progs / f"p{i + 1:02d}_r{k + 1}.aidl"
            say(f"[prompt {i + 1}/{len(prompts)}, run {k + 1}/{runs}] {prompt[:60]}")
            res = generate(prompt, client, max_rounds, str(out),
                           progress=lambda s: say("    " + s), warning_rounds=warning_rounds)
            save(res, out)
            svg = None
            if res.ok:
                svg = _render(res.code, str(out))
                if svg is not None:
                    write_atomic(out.with_suffix(".svg"), svg)
            all_runs.append(Run(i, k, res, str(out.relative_to(out_dir)), svg))
    report = _report(prompts, all_runs, client.model, max_rounds)
    write_atomic(out_dir / "report.json", json.dumps(report, indent=2))
    write_atomic(out_dir / "report.md", _markdown(report))
    write_atomic(out_dir / "index.html", _html(report, prompts, all_runs))
    return report


def _report(prompts, runs: list[Run], model: str, max_rounds: int) -> dict:
    n = len(runs)
    valid = [r for r in runs if r.result.ok]
    codes = Counter(c for r in runs for c in r.result.error_codes)
    wcodes = Counter(c for r in runs for c in r.result.warnings)
    clean = [r for r in valid if r.result.clean]
    return {
        "model": model, "max_rounds": max_rounds, "prompts": len(prompts), "runs": n,
        "summary": {
            "valid_first_try": sum(r.result.first_try for r in runs),
            "valid_within_rounds": len(valid),
            "valid_first_try_rate": (sum(r.result.first_try for r in runs) / n) if n else 0.0,
            "valid_rate": (len(valid) / n) if n else 0.0,
            "mean_rounds_valid": (sum(len(r.result.rounds) for r in valid) / len(valid))
            if valid else None,
            "error_codes": dict(codes.most_common()),
            "valid_clean": len(clean),
            "valid_with_warnings": len(valid) - len(clean),
            "warning_codes": dict(wcodes.most_common()),
        },
        "results": [{"prompt": prompts[r.prompt_index], "prompt_index": r.prompt_index + 1,
                     "run": r.run + 1, "ok": r.result.ok, "first_try": r.result.first_try,
                     "rounds_used": len(r.result.rounds), "error_codes": r.result.error_codes,
                     "warnings": r.result.warnings, "clean": r.result.clean,
                     "program": r.program if r.result.ok else None,
                     "svg": str(Path(r.program).with_suffix(".svg")) if r.svg else None}
                    for r in runs],
    }


def _markdown(rep: dict) -> str:
    s = rep["summary"]
    out = [f"# aidl eval: {rep['model']}\n",
           f"- runs: {rep['runs']} ({rep['prompts']} prompts)",
           f"- valid on first try: {s['valid_first_try']} ({s['valid_first_try_rate']:.0%})",
           f"- valid within {rep['max_rounds']} rounds: {s['valid_within_rounds']} "
           f"({s['valid_rate']:.0%})",
           f"- mean rounds of valid runs: "
           f"{'-' if s['mean_rounds_valid'] is None else format(s['mean_rounds_valid'], '.2f')}",
           f"- valid and clean (no warnings): {s['valid_clean']}; valid with warnings: "
           f"{s['valid_with_warnings']}",
           "- error codes seen: " + (", ".join(f"{c} x{k}" for c, k in s["error_codes"].items())
                                     or "none"),
           "- warnings left in valid programs: "
           + (", ".join(f"{c} x{k}" for c, k in s["warning_codes"].items()) or "none") + "\n",
           "| # | run | prompt | valid | first try | rounds | errors | warnings | rendering |",
           "|---|---|---|---|---|---|---|---|---|"]
    for r in rep["results"]:
        pr = r["prompt"].replace("|", "\\|")
        img = f"![]({r['svg']})" if r["svg"] else ""
        out.append(f"| {r['prompt_index']} | {r['run']} | {pr} | {'yes' if r['ok'] else 'no'} | "
                   f"{'yes' if r['first_try'] else 'no'} | {r['rounds_used']} | "
                   f"{', '.join(r['error_codes']) or '-'} | {', '.join(r['warnings']) or '-'} | "
                   f"{img} |")
    return "\n".join(out) + "\n"


def _html(rep: dict, prompts: list[str], runs: list[Run]) -> str:
    s = rep["summary"]
    e = html.escape
    rows = []
    for i, p in enumerate(prompts):
        cells = []
        for r in (r for r in runs if r.prompt_index == i):
            res = r.result
            status = (f"valid in {len(res.rounds)} round{'s' if len(res.rounds) != 1 else ''}"
                      + (f" with warnings {', '.join(res.warnings)}" if res.warnings else "")
                      if res.ok else f"not valid after {len(res.rounds)} rounds: "
                      + ", ".join(sorted(set(res.error_codes))))
            art = r.svg[r.svg.index("<svg"):] if r.svg else "<div class='none'>no rendering</div>"
            cells.append(f"<figure class='{'ok' if res.ok else 'bad'}'>{art}"
                         f"<figcaption>run {r.run + 1}: {e(status)} · "
                         f"<a href='{e(r.program)}'>program</a></figcaption></figure>")
        rows.append(f"<section><h2>{i + 1}. {e(p)}</h2><div class='runs'>{''.join(cells)}</div>"
                    f"</section>")
    mean = "-" if s["mean_rounds_valid"] is None else f"{s['mean_rounds_valid']:.2f}"
    codes = ", ".join(f"{c} ×{k}" for c, k in s["error_codes"].items()) or "none"
    return f"""<!doctype html>
<html><head><meta charset="utf-8"><title>aidl eval: {e(rep['model'])}</title>
<style>
body {{ font-family: sans-serif; margin: 2em; }}
section {{ border-top: 1px solid #ccc; padding: 0.5em 0; }}
h2 {{ font-size: 1em; font-weight: normal; }}
.runs {{ display: flex; flex-wrap: wrap; gap: 1em; }}
figure {{ margin: 0; width: 260px; }}
figure svg {{ width: 260px; height: 200px; border: 1px solid #ddd; }}
figure.bad {{ color: #b71c1c; }}
.none {{ width: 260px; height: 200px; border: 1px dashed #e57373; }}
</style></head><body>
<h1>aidl eval: {e(rep['model'])}</h1>
<p>{rep['runs']} runs over {rep['prompts']} prompts, at most {rep['max_rounds']} rounds each.
Valid on first try: {s['valid_first_try']} ({s['valid_first_try_rate']:.0%}).
Valid within {rep['max_rounds']} rounds: {s['valid_within_rounds']} ({s['valid_rate']:.0%}),
of which clean: {s['valid_clean']}, with warnings: {s['valid_with_warnings']}.
Mean rounds of valid runs: {mean}. Error codes seen: {e(codes)}.</p>
{''.join(rows)}
</body></html>
"""
