"""The LLM subcommands of ``aidl``: ``prompt``, ``generate`` and ``eval`` (see docs/llm.md).

Exit status: 0 success (``generate``: the program checks; ``eval``: the report is written),
1 no valid program within the rounds / the endpoint failed, 2 a usage error.
"""
from __future__ import annotations

import sys
from pathlib import Path


def add_commands(add) -> None:
    """Register the subcommands: ``add(name, **kwargs)`` is the ``aidl`` subparsers'
    ``add_parser`` (or stands in for it: :func:`aidl_lang.cli.arguments._parser`)."""
    p = add("prompt", help="print the system prompt for an LLM that writes AIDL")
    p.add_argument("--examples", type=int, default=None, metavar="N",
                   help="include the first N example programs (default 2, at most 4; 0: none)")
    p.add_argument("--no-examples", action="store_true",
                   help="leave out the example programs (--examples 0)")
    p.add_argument("--words", action="store_true", help="print the size in words to stderr")
    for name, hlp in (("generate", "ask an LLM for a program until it checks"),
                      ("eval", "run `generate` over a prompt list and write a report")):
        g = add(name, help=hlp)
        if name == "generate":
            g.add_argument("prompt", help="what to design, e.g. \"a wrench with a 10 mm jaw\"")
            g.add_argument("-o", "--output", required=True, help="the .aidl file to write")
            g.add_argument("--visual-rounds", type=int, default=0, metavar="N",
                           help="extra rounds that send the valid program's picture (PNG) to a "
                                "multimodal model, which replies LOOKS RIGHT or a corrected "
                                "program (default 0: off; needs cairosvg)")
        else:
            g.add_argument("prompts", help="text file: one prompt per line (# comments)")
            g.add_argument("--runs", type=int, default=1, help="runs per prompt (default 1)")
            g.add_argument("-o", "--output", default="aidl-eval",
                           help="report folder (default aidl-eval)")
        g.add_argument("--rounds", type=int, default=5, help="at most this many rounds (default 5)")
        g.add_argument("--warning-rounds", type=int, default=1, metavar="N",
                       help="extra rounds that send a valid program's warnings back (default 1; "
                            "0 accepts the first valid program)")
        g.add_argument("--base-url", help="chat-completions endpoint base URL "
                       "(env AIDL_BASE_URL, OPENAI_BASE_URL)")
        g.add_argument("--model", help="model name (env AIDL_MODEL; default gpt-4o)")
        g.add_argument("--api-key", help="API key (env OPENAI_API_KEY)")
        g.add_argument("--temperature", type=float, help="sampling temperature")


def _say(msg: str) -> None:
    print(msg, file=sys.stderr, flush=True)


def _client(args):
    from ..llm.client import client_from
    if args.rounds < 1 or args.warning_rounds < 0 or getattr(args, "visual_rounds", 0) < 0:
        print("aidl: error: --rounds must be at least 1, --warning-rounds and --visual-rounds "
              "at least 0", file=sys.stderr)
        raise SystemExit(2)
    return client_from(args.base_url, args.model, args.api_key, args.temperature)


def cmd_prompt(args) -> int:
    from ..llm.prompt import system_prompt, word_count
    if args.examples is not None and args.examples < 0:
        _say("aidl: error: --examples must be at least 0")
        return 2
    text = system_prompt(examples=0 if args.no_examples else
                         (True if args.examples is None else args.examples))
    sys.stdout.write(text)
    if args.words:
        _say(f"{word_count(text)} words, {len(text)} characters")
    return 0


def cmd_generate(args) -> int:
    from ..llm.generate import generate, save, transcript_paths
    from ..llm.client import LLMError
    client = _client(args)
    out = Path(args.output)
    if not out.parent.resolve().is_dir():
        print(f"aidl: error: folder `{out.parent}` does not exist", file=sys.stderr)
        return 2
    if args.visual_rounds:
        try:
            import cairosvg  # noqa: F401  (the pictures of --visual-rounds)
        except (ImportError, OSError) as e:
            print("aidl: error: --visual-rounds needs cairosvg and the cairo library: pip "
                  f"install 'aidl-lang[png]' ({e})", file=sys.stderr)
            return 2
    try:
        res = generate(args.prompt, client, args.rounds, str(out), progress=_say,
                       warning_rounds=args.warning_rounds, visual_rounds=args.visual_rounds)
    except LLMError as e:
        print(f"aidl: error: {e}", file=sys.stderr)
        return 1
    save(res, out)
    js, md = transcript_paths(out)
    if res.ok:
        warn = f", {len(res.warnings)} warning(s) left" if res.warnings else ""
        if res.visual_rounds:
            warn += (f", {res.visual_rounds} picture(s) checked"
                     + (", LOOKS RIGHT" if res.looks_right else "")
                     + (" (the visual check failed)" if res.visual_error else ""))
        print(f"wrote {out} (valid in round {len(res.rounds)}{warn}); transcript {md}")
        return 0
    print(f"aidl: no valid program in {len(res.rounds)} rounds; {out} not written; "
          f"transcript {md}", file=sys.stderr)
    return 1


def cmd_eval(args) -> int:
    from ..llm.evaluate import read_prompts, run_eval
    from ..llm.client import LLMError
    client = _client(args)
    try:
        prompts = read_prompts(Path(args.prompts))
    except (OSError, UnicodeDecodeError) as e:
        print(f"aidl: error: cannot read `{args.prompts}`: {getattr(e, 'strerror', None) or e}",
              file=sys.stderr)
        return 2
    if not prompts or args.runs < 1:
        print("aidl: error: need at least one prompt and --runs >= 1", file=sys.stderr)
        return 2
    out = Path(args.output)
    try:
        rep = run_eval(prompts, client, out, args.runs, args.rounds, progress=_say,
                       warning_rounds=args.warning_rounds)
    except LLMError as e:
        print(f"aidl: error: {e}", file=sys.stderr)
        return 1
    s = rep["summary"]
    print(f"{rep['runs']} runs: {s['valid_first_try']} valid on first try, "
          f"{s['valid_within_rounds']} within {rep['max_rounds']} rounds "
          f"({s['valid_clean']} clean, {s['valid_with_warnings']} with warnings); "
          f"report {out / 'report.md'}, contact sheet {out / 'index.html'}")
    return 0


COMMANDS = {"prompt": cmd_prompt, "generate": cmd_generate, "eval": cmd_eval}
