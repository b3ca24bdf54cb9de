"""The parser's error recovery (issue 83): around any number of syntax errors it keeps every
statement that parsed, and the editor's outline (``textDocument/documentSymbol``) lists every
structure that parsed.

Before, a `(` or `[` left open blanked the rest of the file (its logical line ran to the end),
a brace typed inside an expression nested or closed the blocks around it, and an error the
line recovery could not step over (the same place twice, the end of the file) dropped every
statement: with two errors the parse often kept nothing, and the outline dropped every
structure after an unclosed `(`.
"""
from __future__ import annotations


import pytest
from hypothesis import HealthCheck, given, settings, strategies as st
from lsprotocol import types as T
from pytest_lsp import LanguageClient

from aidl_lang import ast as A
from aidl_lang.base.diagnostics import DiagnosticSink
from aidl_lang.editor.lsp import analysis as an
from aidl_lang.parser import parse

KINDS = ["solid", "hole", "drawing", "assembly"]
BODY = ["r{n} = Rectangle(center=(0, 0), width=10 mm, height=5)",
        "c{n} = Circle(center=(1, 2), radius=3)",
        "Fixed(c{n}.center)",
        "for i in range(3) {{\n        p{n} = Circle(center=(i * 5, 0), radius=1)\n    }}",
        "if 2 > 1 {{\n        q{n} = 1\n    }} else {{\n        q{n} = 2\n    }}",
        "s{n} = Slot(start=(0, 0), end=(10, 0), width=2)  # a slot"]
# what a typo adds inside a statement
TYPOS = ["(", ")", "[", "]", "{", "}", "=", "* ", ",", "+ +", "@", '"', "'", "$", "((", "]]"]


@st.composite
def damaged_programs(draw):
    """``(source, untouched)``: a valid program of named structures, then k >= 1 typos put
    into statements of some of them (``untouched``: the names of the others, with how many
    statements each has)."""
    n = draw(st.integers(2, 7))
    structs = []
    for i in range(n):
        name = f"s{i}"
        body = [draw(st.sampled_from(BODY)).format(n=i)
                for _ in range(draw(st.integers(1, 3)))]
        structs.append((name, draw(st.sampled_from(KINDS)), body))
    hit = set(draw(st.lists(st.integers(0, n - 1), min_size=1, max_size=min(3, n - 1),
                            unique=True)))
    parts = ["param w = 10 mm", "units mm"]
    for i, (name, kind, body) in enumerate(structs):
        lines = list(body)
        if i in hit:
            k = draw(st.integers(0, len(lines) - 1))
            line = lines[k].split("\n")[0]
            at = draw(st.integers(1, len(line)))
            typo = draw(st.sampled_from(TYPOS + ["drop )"]))
            if typo == "drop )" and ")" in line:
                j = line.rindex(")")
                line = line[:j] + line[j + 1:]          # a `(` never closed
            else:
                line = line[:at] + typo + line[at:]
            lines[k] = "\n".join([line] + lines[k].split("\n")[1:])
        parts.append(f"{kind} {name} {{\n" + "".join(f"    {b}\n" for b in lines) + "}")
    src = "\n".join(parts) + "\n"
    untouched = {structs[i][0]: len(structs[i][2]) for i in range(n) if i not in hit}
    return src, untouched


def _kept(src: str):
    sink = DiagnosticSink()
    prog = parse(src, "t.aidl", sink)
    return prog, sink


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(damaged_programs())
def test_every_untouched_structure_is_kept_and_outlined(case):
    src, untouched = case
    prog, sink = _kept(src)
    structs = {s.name: s for s in prog.stmts if isinstance(s, A.StructDecl)}
    for name, count in untouched.items():
        assert name in structs, (name, [d.message for d in sink.items])
        assert len(structs[name].body.stmts) == count, name          # all its statements
    outline = {s.name for s in an.document_symbols(src, "t.aidl")}
    assert set(untouched) <= outline
    assert {"w"} <= outline                                          # the param before them


@pytest.mark.parametrize("src, kept", [
    # an unclosed `(`: the structures after it (and the one it is in)
    ("solid a {\n    r = Rectangle(center=(0, 0), width=10, height=5)\n}\n"
     "solid b {\n    c = Circle(center=(0, 0), radius=3\n}\n"
     "solid c {\n    s = Rectangle(center=(0, 0), width=4, height=4)\n}\n", ["a", "b", "c"]),
    # two errors, one of them a brace typed inside a call
    ("solid a {\n    ra = Rectangle(c{enter=(0, 0), width=10, height=5)\n}\n"
     "solid b {\n    rb = Rectangle(center=(0, 0), width=10, height=5)\n}\n"
     "solid c {\n    rc = Rectangle(center=(0, 0), width=1=0, height=5)\n}\n"
     "solid d {\n    rd = Rectangle(center=(0, 0), width=10, height=5)\n}\n", ["a", "b", "c", "d"]),
    # an unclosed `[` in the first structure
    ("solid a {\n    ca = Circle(center=(1, 2),[ radius=3)\n}\n"
     "solid b {\n    cb = Circle(center=(1, 2), radius=3)\n}\n", ["a", "b"]),
])
def test_the_issue_s_cases(src, kept):
    prog, sink = _kept(src)
    assert sink.has_errors
    assert [s.name for s in prog.stmts] == kept
    assert [s.name for s in an.document_symbols(src, "t.aidl")] == kept


# ------------------------------------------------------------------ a real server
# the server of test_lsp_editing: stdio as vscode-languageclient starts it, no debounce
from test_lsp_editing import client  # noqa: E402,F401


@pytest.mark.asyncio(loop_scope="module")
async def test_the_server_outlines_every_structure_after_an_unclosed_paren(client, tmp_path):
    src = ("solid a {\n    r = Rectangle(center=(0, 0), width=10, height=5)\n}\n"
           "solid b {\n    c = Circle(center=(0, 0), radius=3\n}\n"
           "solid c {\n    s = Rectangle(center=(0, 0), width=4, height=4\n}\n"
           "solid d {\n    t = Circle(center=(1, 1), radius=2)\n}\n")
    uri = (tmp_path / "o.aidl").as_uri()
    client.text_document_did_open(T.DidOpenTextDocumentParams(T.TextDocumentItem(
        uri=uri, language_id="aidl-cad", version=1, text=src)))
    syms = await client.text_document_document_symbol_async(T.DocumentSymbolParams(
        text_document=T.TextDocumentIdentifier(uri=uri)))
    assert [(s.name, s.selection_range.start.line) for s in syms] == [
        ("a", 0), ("b", 3), ("c", 6), ("d", 9)]


def _lexed_by_recovery(n: int, monkeypatch) -> int:
    """Characters handed to the LALR run while a file of ``n`` structures, the second with a
    `(` never closed, is parsed (every structure kept)."""
    from aidl_lang.parsing import recovery as P       # where the recovery calls it
    real, seen = P._run_lalr, [0]

    def counted(text, start, lexed=None):
        seen[0] += len(text)
        return real(text, start, lexed)
    monkeypatch.setattr(P, "_run_lalr", counted)
    parts = [f"solid s{i} {{\n    body = Rectangle(center=({i}, 0), width=4, height=2)\n}}\n"
             for i in range(n)]
    parts[1] = "solid s1 {\n    body = Rectangle(center=(1, 0), width=4, height=2\n}\n"
    prog = parse("".join(parts), "big.aidl", DiagnosticSink())
    assert len(prog.stmts) == n
    return seen[0]


def test_the_recovery_by_pieces_grows_linearly_with_the_file(monkeypatch):
    """Each top-level piece was parsed after a blank as long as the text before it: 12,000
    structures with one unclosed `(` took 25 s (the characters lexed grew with the square of
    the file).  Now each piece is tried alone and the file parsed once with the repairs."""
    small, large = _lexed_by_recovery(250, monkeypatch), _lexed_by_recovery(1000, monkeypatch)
    assert large <= 4.6 * small, (small, large)


def test_one_unclosed_paren_is_weighed_once_not_at_every_later_brace(monkeypatch):
    """The `(` left open in one of 3,000 structures made every later line a continuation of
    its expression (blocks cannot be inside one), so each later `}` was weighed against the
    rest of the file (129 look-aheads, and the statement's start found by walking back every
    line: 12,000 structures took 13 s in `_bracket_problems`).  Now the `}` ends it: one
    look-ahead, and the problem is still reported at the `(`'s line with the line to close."""
    from aidl_lang.parsing import brackets as parser
    calls = []
    real = parser._plain_cost

    def counted(toks, i, stack):
        calls.append(len(toks) - i)
        return real(toks, i, stack)
    monkeypatch.setattr(parser, "_plain_cost", counted)
    n = 3000
    parts = [f"solid s{i} {{\n    c = Circle(center=({i}, 0), radius=1)\n}}" for i in range(n)]
    parts[1500] = parts[1500].replace("radius=1)", "radius=1")
    problems = parser._bracket_problems("\n".join(parts) + "\n", "big.aidl")
    assert len(problems) == 1
    (_lo, _hi), code, message, span, hint, _labels = problems[0]
    assert (code, message, span.line) == ("E0001", "`(` is never closed", 3 * 1500 + 2)
    assert hint == f"add `)` at the end of line {3 * 1500 + 2}, where the statement ends " \
                   "(the next line starts a new one)"
    assert len(calls) <= 3, len(calls)
