"""The documentation is tested: every ```aidl block of README.md and docs/*.md is compiled
by the real pipeline (``aidl_lang.compile``: parser, checker, solver, Manifold, the shape
checks) and must give no diagnostic at all, unless the line before its fence (blank lines
skipped) is a marker naming what the block is meant to show:

    <!-- expect: E0201 -->                           exactly these codes (E0201 only)
    <!-- expect: W0505, W0504 -->                    several codes
    <!-- expect: E0401 "held by a constructor" -->   and these texts in the rendered output

A ``# error[CODE]`` or ``# warning[CODE]`` comment inside a block must name an expected code,
so the prose cannot promise a diagnostic the compiler does not give.

The tutorial's ``aidl ...`` command lines run on the program above them (no warning; the
parts list it shows is what ``aidl parts`` prints).

Also: the command table (docs/language.md §10.1) lists every ``aidl`` subcommand of the CLI
parser and only options that the parser has; the code table (§10.4) lists exactly the codes
of :mod:`aidl_lang.base.codes`.  Failure messages name the file, the line of the block's first
code line and what went wrong, so a re-run after a merge says which block to fix.
"""
from __future__ import annotations

import re
import textwrap
from dataclasses import dataclass
from pathlib import Path

import pytest

import aidl_lang
from aidl_lang.base.codes import CODES

ROOT = Path(__file__).resolve().parent.parent
DOCS = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md")),
        *sorted((ROOT / "docs" / "dev").glob("*.md"))]
MARKER = re.compile(r"<!--\s*expect:\s*(?P<body>.*?)\s*-->")
CODE = re.compile(r"\b[EW]\d{4}\b")
INLINE = re.compile(r"#.*?\b(?:error|warning)\[([EW]\d{4})\]")


@dataclass(frozen=True)
class Block:
    file: Path
    line: int                 # 1-based line of the block's first code line
    source: str
    expect: frozenset[str]    # codes the block must give (empty: none at all)
    texts: tuple[str, ...]    # texts the rendered diagnostics must contain

    @property
    def where(self) -> str:
        f = self.file.relative_to(ROOT) if self.file.is_relative_to(ROOT) else self.file
        return f"{f}:{self.line}"


def aidl_blocks(path: Path) -> list[Block]:
    """The ```aidl blocks of a Markdown file, with the ``<!-- expect: ... -->`` marker before
    each (fences may be indented, e.g. inside a list; the block is dedented)."""
    lines = path.read_text(encoding="utf-8").split("\n")
    out, i = [], 0
    while i < len(lines):
        if lines[i].strip() == "```aidl":
            j = i + 1
            while j < len(lines) and lines[j].strip() != "```":
                j += 1
            assert j < len(lines), f"{path}:{i + 1}: unclosed ```aidl fence"
            k = i - 1
            while k >= 0 and not lines[k].strip():
                k -= 1
            m = MARKER.search(lines[k]) if k >= 0 else None
            codes = frozenset(CODE.findall(m["body"])) if m else frozenset()
            texts = tuple(re.findall(r'"([^"]*)"', m["body"])) if m else ()
            if m:
                assert codes, f"{path}:{k + 1}: an expect marker names no code"
            src = textwrap.dedent("\n".join(lines[i + 1:j])) + "\n"
            out.append(Block(path, i + 2, src, codes, texts))
            i = j
        i += 1
    return out


BLOCKS = [b for f in DOCS for b in aidl_blocks(f)]


def test_the_docs_have_aidl_blocks():
    assert len(BLOCKS) >= 35 and {b.file.name for b in BLOCKS} >= {"README.md", "language.md",
                                                                   "tutorial.md"}


@pytest.mark.parametrize("block", BLOCKS, ids=[b.where for b in BLOCKS])
def test_every_aidl_block_compiles_as_documented(block: Block):
    # blank lines in front: the diagnostics' lines are the Markdown file's
    r = aidl_lang.compile(source="\n" * (block.line - 1) + block.source,
                          path=str(block.file))
    got = {d.code for d in r.diagnostics}
    shown = "\n".join(f"{d['code']} line {d['span']['line'] if d['span'] else '-'}: "
                      f"{d['rendered']}" for d in r.diagnostics_json()) or "(none)"
    if not block.expect:
        assert not got, (f"{block.where}: this ```aidl block should compile with no diagnostic "
                         f"but gives {sorted(got)} (fix the example, or mark a deliberate one "
                         f"with <!-- expect: CODE --> before the fence):\n{shown}")
    else:
        assert got == block.expect, (f"{block.where}: the block is marked to give "
                                     f"{sorted(block.expect)} but gives {sorted(got)}:\n{shown}")
    for text in block.texts:
        assert text in shown, f"{block.where}: the diagnostics do not say {text!r}:\n{shown}"
    claimed = set(INLINE.findall(block.source))
    assert claimed <= block.expect, (
        f"{block.where}: a comment in the block promises {sorted(claimed - block.expect)}, which "
        f"the block is not marked to give (<!-- expect: ... -->); the compiler gives "
        f"{sorted(got)}")


def test_the_blocks_compile_without_errors_where_the_result_matters(tmp_path):
    """A marked block with only warnings still builds its drawing (a warning never stops the
    compile); one with errors does not.  Guards the marker logic itself."""
    ok = aidl_lang.compile(source="solid s { c = Circle(center=(0, 0), radius=5) }\n")
    assert ok.ok and not ok.diagnostics
    bad = aidl_lang.compile(source="solid s { c = Circle(center=(0, 0), radius=rdi) }\n")
    assert {d.code for d in bad.diagnostics} == {"E0101"}
    text = ("<!-- expect: E0101 \"unknown name\" -->\n\n   ```aidl\n   solid s { c = Circle("
            "center=(0, 0), radius=rad) }   # error[E0101]\n   ```\n\n```aidl\nunits mm\n```\n")
    scratch = tmp_path / "probe.md"          # a scratch Markdown file proves the extraction
    scratch.write_text(text)
    a, b = aidl_blocks(scratch)
    assert (a.line, a.expect, a.texts) == (4, frozenset({"E0101"}), ("unknown name",))
    assert a.source.startswith("solid s {") and INLINE.findall(a.source) == ["E0101"]
    assert (b.line, b.expect, b.source) == (8, frozenset(), "units mm\n")


# ------------------------------------------------------------------ §10: generated from the code
def _section(title: str) -> str:
    text = (ROOT / "docs" / "language.md").read_text(encoding="utf-8")
    start = text.index(f"\n### {title}")
    end = text.find("\n#", start + 5)
    return text[start:end if end >= 0 else len(text)]


def test_the_command_table_lists_every_subcommand_and_only_real_options():
    """docs/language.md §10.1 has a row for every ``aidl`` subcommand (``SUBCOMMANDS`` of the
    CLI parser), and every ``--option`` a row writes is one that subcommand's parser has."""
    import argparse

    from aidl_lang.cli.arguments import SUBCOMMANDS, _parser
    table = _section("10.1 Commands")
    rows = {}
    for line in table.splitlines():
        m = re.match(r"\| `aidl ([a-z]+)([^`]*)`", line)
        if m:
            rows[m[1]] = m[2]
    missing = [c for c in SUBCOMMANDS if c not in rows]
    assert not missing, f"docs/language.md §10.1 has no row for `aidl {'`, `aidl '.join(missing)}`"
    extra = [c for c in rows if c not in SUBCOMMANDS]
    assert not extra, f"docs/language.md §10.1 lists commands the CLI does not have: {extra}"
    top = _parser()
    (sub,) = [a for a in top._actions if isinstance(a, argparse._SubParsersAction)]
    for name, usage in rows.items():
        known = set(sub.choices[name]._option_string_actions)
        written = set(re.findall(r"(?<![\w-])(--?[a-z][\w-]*)", usage))
        assert written <= known, (f"docs/language.md §10.1, `aidl {name}`: options the parser "
                                  f"does not have: {sorted(written - known)}")


def test_the_code_table_lists_exactly_the_codes_of_the_registry():
    """docs/language.md §10.4 lists every code of ``aidl_lang.base.codes.CODES`` once, and no
    other; ``aidl explain`` knows each."""
    table = _section("10.4 Diagnostic codes")
    listed = re.findall(r"^\| `([EW]\d{4})` \|", table, flags=re.M)
    dupes = sorted({c for c in listed if listed.count(c) > 1})
    assert not dupes, f"docs/language.md §10.4 lists codes twice: {dupes}"
    missing = sorted(set(CODES) - set(listed))
    assert not missing, (f"docs/language.md §10.4 does not list {missing} (aidl_lang/base/codes.py "
                         f"has them: {[CODES[c][0] for c in missing]})")
    unknown = sorted(set(listed) - set(CODES))
    assert not unknown, f"docs/language.md §10.4 lists codes aidl_lang/base/codes.py lacks: {unknown}"
    assert listed == sorted(listed), "docs/language.md §10.4: keep the codes in order"


def test_the_text_example_moves_the_label_onto_the_plate_not_the_plate():
    """docs/language.md §3 Text: `CenterInside(label, plate)` with the plate held must leave
    the plate (and its eye hole) where they are made and center the strokes on it."""
    (block,) = [b for b in BLOCKS if 'Text("AIDL"' in b.source]
    r = aidl_lang.compile(source=block.source)
    assert r.value("tag.plate.center").value == pytest.approx((0, 0), abs=1e-9)
    assert r.value("tag.eye.c.center").value == pytest.approx((-24, 0), abs=1e-9)
    x0, y0, x1, y1 = r.value("tag.label.bbox").value
    assert (x0 + x1) / 2 == pytest.approx(0, abs=1e-6) and (y0 + y1) / 2 == pytest.approx(0, abs=1e-6)


# ------------------------------------------------------------------ the tutorial's commands
def _tutorial_commands():
    """Each ``aidl ...`` line of a ```sh block in docs/tutorial.md, with the ```aidl block
    above it (saved as kit.aidl) and the ```text block that shows its output, if any (after
    the last command of the block: ``aidl check --values``, ``aidl parts``)."""
    path = ROOT / "docs" / "tutorial.md"
    lines = path.read_text(encoding="utf-8").split("\n")
    out, program, i, block = [], None, 0, 0
    while i < len(lines):
        fence = lines[i].strip()
        if fence.startswith("```") and fence != "```":
            j = i + 1
            while lines[j].strip() != "```":
                j += 1
            body = lines[i + 1:j]
            if fence == "```aidl":
                program = "\n".join(body) + "\n"
            elif fence == "```sh":
                block = len(out)
                for k, line in enumerate(body):
                    cmd = line.split("#", 1)[0].strip()
                    if cmd.startswith("aidl "):
                        out.append((f"docs/tutorial.md:{i + 2 + k}", program, cmd))
            elif fence == "```text":         # the output of the last command above (in its
                # block, the `aidl parts` if there is one)
                k = max([n for n in range(block, len(out)) if out[n][2].startswith("aidl parts ")]
                        or [len(out) - 1])
                out[k] = (*out[k][:3], "\n".join(body) + "\n")
            i = j
        i += 1
    return [c if len(c) == 4 else (*c, None) for c in out]


TUTORIAL_COMMANDS = _tutorial_commands()


@pytest.mark.parametrize("where,program,cmd,shown", TUTORIAL_COMMANDS,
                         ids=[c[0] for c in TUTORIAL_COMMANDS])
def test_every_tutorial_command_runs_on_its_program(where, program, cmd, shown, tmp_path,
                                                    monkeypatch, capsys):
    """The commands the tutorial tells a newcomer to type work on the program above them, with
    no warning; a shown output (the parts list) is what the command prints."""
    import shlex

    from aidl_lang.cli.main import main
    assert program is not None, f"{where}: a command with no program above it"
    monkeypatch.chdir(tmp_path)
    (tmp_path / "kit.aidl").write_text(program)
    rc = main(shlex.split(cmd)[1:])
    out, err = capsys.readouterr()
    assert rc == 0, f"{where}: `{cmd}` exits {rc}:\n{err}"
    assert "warning[" not in err, f"{where}: `{cmd}` warns:\n{err}"
    if shown is not None:
        assert out == shown, f"{where}: `{cmd}` prints\n{out}\nnot what the tutorial shows:\n{shown}"


def test_the_tutorial_commands_are_found():
    cmds = [c[2] for c in TUTORIAL_COMMANDS]
    assert len(cmds) >= 8 and any("--layout sheet" in c for c in cmds)
    assert sum(c[3] is not None for c in TUTORIAL_COMMANDS) == 2
    # every one of the ten steps has its command (issue 37, the newcomer's first run)
    text = (ROOT / "docs" / "tutorial.md").read_text(encoding="utf-8")
    steps = re.split(r"\n## \d+ ", text)[1:]
    assert len(steps) == 10 and all("```sh\naidl " in st for st in steps)


LINK = re.compile(r"\]\(([^)\s]+)\)")


def test_every_relative_link_of_the_docs_leads_to_a_file():
    """README.md, docs/*.md and docs/dev/*.md (the engineering notes moved there, issue 37):
    every relative link names a file or folder that exists, and every `#anchor` into a
    Markdown file names one of its headings."""
    def anchors(md: Path) -> set[str]:
        out = set()
        for line in md.read_text(encoding="utf-8").split("\n"):
            if line.startswith("#"):
                title = line.lstrip("#").strip().lower()
                out.add(re.sub(r"[^\w\- ]", "", title).replace(" ", "-"))
        return out
    bad = []
    for md in DOCS:
        for target in LINK.findall(md.read_text(encoding="utf-8")):
            if re.match(r"[a-z]+:", target):
                continue
            path, _, anchor = target.partition("#")
            f = (md.parent / path).resolve() if path else md
            if not f.exists():
                bad.append(f"{md.relative_to(ROOT)}: {target}")
            elif anchor and f.suffix == ".md" and anchor not in anchors(f):
                bad.append(f"{md.relative_to(ROOT)}: {target} (no such heading)")
    assert bad == []


# ------------------------------------------------------------------ issue 37: the newcomer's first run
def _readme() -> str:
    return (ROOT / "README.md").read_text(encoding="utf-8")


def test_the_readme_says_first_what_aidl_is_for_and_who_writes_it():
    """Issue 37: the README's first lines did not say what AIDL is for or who writes it."""
    first = _readme().split("\n\n")[1]          # the paragraph under the title
    assert "flat parts" in first and "sheet material" in first
    for who in ("**people**", "**language models**", "**agents**"):
        assert who in first


def test_the_extras_table_lists_every_extra_with_its_size():
    """Issue 37: one table of the extras, what each adds and its installed size: every extra of
    pyproject.toml that installs something for users (not the empty `serve`, kept for old
    install lines, nor the benchmarks' `bench`) has its row, and every row is an extra."""
    import tomllib
    extras = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"][
        "optional-dependencies"]
    table = _readme().split("### Extras", 1)[1].split("\n\n")[2]
    rows = {m.group(1): m.group(2) for m in
            re.finditer(r"^\| `(\w+)` \| .*? \| ([^|]+) \|$", table, re.M)}
    assert set(rows) == set(extras) - {"serve", "bench"}
    assert all(re.search(r"\d+ MB|—", size) for size in rows.values())


def test_user_docs_and_engineering_notes_are_apart():
    """Issue 37: instruction counts and issue history go under docs/dev/ or the benchmarks:
    no user document quotes millions of instructions (callgrind) but the parse-time note of
    editors.md and solver.md's one comparison, which say what the user waits for."""
    quoted = {md.name for md in (ROOT / "docs").glob("*.md")
              if re.search(r"\d+ M instructions", md.read_text(encoding="utf-8"))}
    assert quoted == set()
    notes = (ROOT / "docs" / "dev" / "performance.md").read_text(encoding="utf-8")
    assert "callgrind" in notes and "instructions" in notes


def test_the_tutorial_says_what_the_dof_count_and_the_origin_line_mean():
    """Issue 37: the tutorial printed a DOF count and `origin` lines without saying what they
    are; every command it shows is run by test_every_tutorial_command_runs_on_its_program."""
    text = (ROOT / "docs" / "tutorial.md").read_text(encoding="utf-8")
    assert "are the **degrees of freedom** (DOF) left" in text
    assert "The **`origin` line** is where the structure's own frame sits" in text


def test_the_docs_agree_on_what_kerf_does_to_stl_3mf_and_step():
    """Issue 37: the docs disagreed on whether the kerf offsets STL/3MF/STEP.  Every sentence
    of the docs that names them beside the kerf says they keep the designed size."""
    said = []
    for md in DOCS:
        prose = re.sub(r"```.*?```", "", md.read_text(encoding="utf-8"), flags=re.S)
        paragraphs = [re.sub(r"\s+", " ", p) for p in re.split(r"\n\s*\n|\n#", prose)]
        for sentence in (s for p in paragraphs for s in re.split(r"(?<=[.;])\s", p)):
            if "kerf" in sentence.lower() and "STL" in sentence and "STEP" in sentence \
                    and "3MF" in sentence:
                said.append((md.name, sentence))
    assert len(said) >= 3
    assert all("keep the designed size" in s for _, s in said), said
