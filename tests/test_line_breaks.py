"""One definition of a line break (issue 83): CR LF, a lone CR and LF each end a line, as the
Language Server Protocol and every editor count lines (``aidl_lang.base.diagnostics.LINE_BREAK``).

The law: a program written with any mix of the three, in comments and between statements,
compiles to what its LF version compiles to (the same values, the same diagnostics at the same
lines and columns); ``aidl fmt`` formats it to the LF version's layout with one kind of line
ending (the file's first), which checks as the original does; and the language server's
formatting edit, applied as a client applies it (lines split at CR LF, CR and LF, a position's
character clamped to its line), gives exactly ``aidl fmt``'s text.  Before, a lone CR inside a
``#`` comment hid the code after it from the compiler (every editor shows it as its own line),
``aidl fmt`` then made it code, and the formatting edit of a CR-only document covered line 0
only: applied, the document came out twice.
"""
from __future__ import annotations

import re

import pytest
from hypothesis import HealthCheck, given, settings, strategies as st
from lsprotocol import types as T
from pytest_lsp import LanguageClient

import aidl_lang
from aidl_lang.base.diagnostics import LINE_BREAK, as_lf, split_lines
from aidl_lang.editor.fmt import format_file_text, newline_of
from aidl_lang.editor.lsp import analysis as an

BREAKS = ("\n", "\r", "\r\n")


def client_apply(src: str, edits: list[T.TextEdit]) -> str:
    """Apply LSP edits as VS Code does: lines end at CR LF, CR or LF, a line past the end is
    the document's end, a character past its line's end is the line's end."""
    starts = [0] + [m.end() for m in LINE_BREAK.finditer(src)]
    ends = [m.start() for m in LINE_BREAK.finditer(src)] + [len(src)]

    def offset(p: T.Position) -> int:
        if p.line >= len(starts):
            return len(src)
        return min(starts[p.line] + p.character, ends[p.line])
    for e in sorted(edits, key=lambda e: (e.range.start.line, e.range.start.character),
                    reverse=True):
        src = src[:offset(e.range.start)] + e.new_text + src[offset(e.range.end):]
    return src


def lf(text: str) -> str:
    return LINE_BREAK.sub("\n", text)


def compiled(src: str) -> tuple:
    """What a program compiles to: its diagnostics (code, line, column) and solved values."""
    r = aidl_lang.compile(source=src, path="t.aidl")
    diags = [(d.code, d.span.line if d.span else 0, d.span.col if d.span else 0)
             for d in r.diagnostics]
    values = sorted((v.name, v.text()) for v in r.values) if r.ok else []
    return diags, values


def test_the_helpers_count_lines_as_editors_do():
    src = "a\rb\r\nc\nd"
    assert split_lines(src) == ["a", "b", "c", "d"]
    assert as_lf(src) == "a\nb\r\nc\nd" and len(as_lf(src)) == len(src)
    assert newline_of("x = 1\ry = 2\n") == "\r" and newline_of("x = 1") == "\n"
    assert an.position_at(src, src.index("d")) == T.Position(line=3, character=0)
    assert an.offset_at(src, 1, 1) == src.index("b") + 1


def test_a_lone_cr_ends_a_comment_and_the_code_after_it_compiles():
    """The issue's case: `x = 1 # note<CR>y = 2` is two statements, as every editor shows it."""
    src = "x = 1 # note\ry = 2\nsolid s {\n    body = Rectangle(center=(0, 0), width=x, height=y)\n}\n"
    assert compiled(src) == compiled(lf(src))
    diags, values = compiled(src)
    assert not [d for d in diags if d[0].startswith("E")]
    assert ("s.body.height", "s.body.height = 2.000 mm") in values      # y = 2
    # an error after a CR-only line is on the line an editor shows it on
    bad = "x = 1 # c\ry = Circel(center=(0, 0), radius=1)\r"
    assert compiled(bad)[0] == [("E0103", 2, 5)]


def test_fmt_and_lsp_formatting_of_a_cr_only_document():
    src = "x=1\ry=2 # c\rsolid s {\rbody = Rectangle(center=(0, 0), width=x, height=y)\r}\r"
    out = format_file_text(src)
    assert out == "x = 1\ry = 2  # c\rsolid s {\r    body = Rectangle(center=(0, 0), width=x, height=y)\r}\r"
    edits = an.formatting(src, "c.aidl")
    assert [(e.range.end.line, e.range.end.character) for e in edits] == [(5, 0)]
    assert client_apply(src, edits) == out          # was the document twice over


# ------------------------------------------------------------------ the law
STATEMENTS = ["a = 3", "b = a + 2", "param w = 20 mm", "c = b * 2  # double",
              "d = [a, b][1]", "e = 1 if a > 2 else 0", "f = Circel(center=(0, 0), radius=1)"]
COMMENT_WORDS = ["note", "x = 1", "solid", "(", "{", "the end"]


@st.composite
def programs(draw):
    """A program as pieces joined by random line breaks; a comment may hold a line break
    followed by a statement (code on its own line to an editor, and so to the compiler)."""
    pieces = []
    for _ in range(draw(st.integers(1, 6))):
        kind = draw(st.sampled_from(["stmt", "stmt", "comment", "comment_then_code", "blank"]))
        if kind == "stmt":
            pieces.append(draw(st.sampled_from(STATEMENTS)))
        elif kind == "comment":
            pieces.append("# " + draw(st.sampled_from(COMMENT_WORDS)))
        elif kind == "comment_then_code":
            pieces.append("x = 1  # " + draw(st.sampled_from(COMMENT_WORDS))
                          + draw(st.sampled_from(BREAKS)) + draw(st.sampled_from(STATEMENTS)))
        else:
            pieces.append("")
    pieces.append("solid s {" + draw(st.sampled_from(BREAKS))
                  + "    body = Rectangle(center=(0, 0), width=w if false else 10, height=a)"
                  + draw(st.sampled_from(BREAKS)) + "}")
    if "a = 3" not in pieces:
        pieces.insert(0, "a = 3")
    text = ""
    for p in pieces:
        text += p + draw(st.sampled_from(BREAKS))
    return text


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(programs())
def test_any_line_breaks_compile_format_and_lsp_format_as_lf(src):
    ref = lf(src)
    assert compiled(src) == compiled(ref)
    try:
        out_ref = format_file_text(ref)
    except Exception as e:           # noqa: BLE001 - the same refusal for both
        with pytest.raises(type(e)):
            format_file_text(src)
        assert an.formatting(src, "t.aidl") == []
        return
    out = format_file_text(src)
    nl = newline_of(src)
    assert set(LINE_BREAK.findall(out)) <= {nl}             # one kind of line ending
    assert lf(out) == out_ref                               # the LF version's layout
    assert compiled(out) == compiled(out_ref)               # fmt then check: consistent
    assert compiled(out)[1] == compiled(src)[1]
    assert client_apply(src, an.formatting(src, "t.aidl")) == out


# ------------------------------------------------------------------ a real server
# the server of test_lsp_editing: stdio as vscode-languageclient starts it, no debounce
from test_lsp_editing import client  # noqa: E402,F401


@pytest.mark.asyncio(loop_scope="module")
async def test_server_formatting_and_symbols_of_cr_and_mixed_documents(client: LanguageClient,
                                                                       tmp_path):
    docs = {
        "cr.aidl": "x=1\ry=2 # c\rsolid s {\rbody = Rectangle(center=(0, 0), width=x, height=y)\r}\r",
        "mixed.aidl": "x=1 # c\ry=2\r\nsolid s {\nbody = Rectangle(center=(0, 0), width=x, height=y)\r}\n",
        "crlf.aidl": "x=1\r\ny=2\r\nsolid s {\r\nbody = Rectangle(center=(0, 0), width=x, height=y)\r\n}\r\n",
        # no line break to a client (str.splitlines breaks at them: pygls did)
        "ff.aidl": "x=1 # a\x0cb\u2028c\x85d\ny=2\nsolid s {\nbody = Rectangle(center=(0, 0), width=x, height=y)\n}\n",
    }
    for name, src in docs.items():
        uri = (tmp_path / name).as_uri()
        client.text_document_did_open(T.DidOpenTextDocumentParams(
            T.TextDocumentItem(uri=uri, language_id="aidl-cad", version=1, text=src)))
        edits = await client.text_document_formatting_async(T.DocumentFormattingParams(
            text_document=T.TextDocumentIdentifier(uri=uri),
            options=T.FormattingOptions(tab_size=4, insert_spaces=True)))
        assert client_apply(src, edits) == format_file_text(src), name
        syms = await client.text_document_document_symbol_async(T.DocumentSymbolParams(
            text_document=T.TextDocumentIdentifier(uri=uri)))
        where = {s.name: s.selection_range.start.line for s in syms}
        assert where == {"x": 0, "y": 1, "s": 2}, name
        # an edit on the line after a lone CR lands where the client put it
        client.text_document_did_change(T.DidChangeTextDocumentParams(
            text_document=T.VersionedTextDocumentIdentifier(uri=uri, version=2),
            content_changes=[T.TextDocumentContentChangePartial(
                range=T.Range(start=T.Position(1, 0), end=T.Position(1, 1)), text="z")]))
        syms = await client.text_document_document_symbol_async(T.DocumentSymbolParams(
            text_document=T.TextDocumentIdentifier(uri=uri)))
        assert {s.name: s.selection_range.start.line for s in syms} == {"x": 0, "z": 1, "s": 2}
