"""The MCP server's wording of the compiler's messages (issue 48): diagnostics, hints and
refusals are written for the command line (``--set width=40mm``, ``aidl docs NAME``,
``see --dof``, ``--budget 2``); an agent calls tools, so :func:`for_agents` rewrites each known
phrase to name the tool and argument instead (``overrides={"width": "40mm"}``, ``call `docs`
with name="NAME"``, ``call `check` with dof=true``, ``budget=2``).  The command line's and
the API's own text is left as it is: only the MCP tools pass theirs through here.

The phrases are those the compiler writes (grep ``--set``, ``--dof``, ``aidl docs``,
``--budget`` in ``aidl_lang/``); a phrase not listed here reaches the agent unchanged.
"""
from __future__ import annotations

import json
import re


def _override(m: re.Match) -> str:
    """`--set NAME=VALUE` -> `overrides={"NAME": "VALUE"}` (`...` kept as it is)."""
    name, value = m.group(1), m.group(2)
    return f'`overrides={{"{name}": {"..." if value == "..." else json.dumps(value)}}}`'


# (pattern, replacement), applied in order: the specific phrases before the general ones
_PHRASES: list[tuple[re.Pattern, object]] = [(re.compile(p), r) for p, r in [
    # params: `--set NAME=VALUE`
    (r"`--set ([\w.]+)=([^`]*)`", _override),
    (r"`--set`", "`overrides`"),
    # the reference: `aidl docs NAME`
    (r"`aidl docs ([^`]+)` gives its parameters", r'call `docs` with name="\1" for its parameters'),
    (r"`aidl docs` lists every (shape, constraint and standard-library template|topic)",
     r"call `docs` with no name for the list of every \1"),
    (r"^`aidl docs NAME` prints a topic:", 'Call `docs` with name="NAME" for a topic:'),
    (r"(?<=\n)call `docs`", "Call `docs`"),
    (r"\(`aidl docs ([^`]+)`\)", r'(call `docs` with name="\1")'),
    (r"`aidl docs ([^`]+)`", r'`docs` with name="\1"'),
    (r"`aidl docs`", "`docs` with no name"),
    (r"see `aidl explain ([^`]+)`", r'call `explain` with code="\1"'),
    # degrees of freedom
    (r"see --dof", "call `check` with dof=true for the details"),
    # the evaluation budget
    (r"`--budget (\d+)` \(or more\)", r"`budget=\1` (or more, at most 4)"),
    (r"`--budget (\d+)`", r"`budget=\1`, at most 4"),
    (r"`--budget`", "`budget` (at most 4)"),
    # render's options
    (r"--sheet (\w+)\)", r'sheet="\1")'),
    (r"--(sheet|gap)\b", r"`\1`"),
    (r"--rotate any", 'rotate="any"'),
    (r"use a lower --dpi or --png-width", "use a smaller `width`"),
    (r"--(?:png-width|dpi)\b", "`width`"),
    (r"; the minimum is set with --min-wall", ""),
    (r" \(follow_symlinks=True writes the file it points to\)", ""),
    # the prompt's and the docs' mentions of the command line (issue 73): the tools instead
    (r"`aidl render --layout sheet`", '`render` with layout="sheet"'),
    (r"--layout sheet", 'layout="sheet"'),
    (r"`--assembled`", "`render` with assembled=true"),
    (r"`aidl check --describe`", "The `describe` tool"),
    (r"`aidl import --infer ([^`]+)`", r'`import_drawing` with path="\1"'),
    (r"`aidl check --values`", "the `values` tool"),
    (r"`aidl check --sweep`", "`check` with sweep=true"),
    (r"`aidl set f\.aidl NAME=VALUE` changes a param's value in the file\.",
     "`set_params` changes params in a file (path, values: {\"width\": \"50 mm\"}); "
     "`measure` gives the distance, centre distance, angle or clearance between two named "
     "entities (a, b)."),
    # the reference's topics (`docs`)
    (r"`aidl render --set NAME=VALUE`", "the tools' `overrides` ({\"NAME\": VALUE})"),
    (r"`aidl render --kerf ([^`]+)`", r'`render` with kerf="\1"'),
    (r"`aidl render --thickness`", "`render`'s `thickness`"),
    (r"`--machine FILE`", "`machine` (a profile file in the allowed folder)"),
    (r"`--machine (router)` or `(plotter)`", r'`machine="\1"` or `"\2"`'),
    (r"`aidl render FILE --assembled -o ([^`]+)`", r'`render` with assembled=true, output="\1"'),
    (r"`aidl\s+render\s+--assembled`", "`render` with assembled=true"),
    (r"`--page ([^`]+)`", r'`page="\1"`'),
    (r"`--kerf`", "`kerf`"),
    (r" \(force=True replaces it\)", ": write to another name"),
]]


def for_agents(text: str | None) -> str | None:
    """``text`` with the command line's phrases named as MCP tools and arguments (see the
    module text); None stays None."""
    if not text:
        return text
    for pattern, replacement in _PHRASES:
        text = pattern.sub(replacement, text)
    return text


def reword_diagnostics(diagnostics) -> None:
    """Reword each :class:`~aidl_lang.base.diagnostics.Diagnostic` of ``diagnostics`` (message,
    hint, labels) in place with :func:`for_agents`; its rendered text follows."""
    for d in diagnostics:
        d.reword(for_agents)
