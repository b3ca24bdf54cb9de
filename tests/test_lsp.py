"""`aidl lsp`: a real client over stdio (pytest-lsp), and the pure analysis functions."""
import sys

import pytest
import pytest_lsp
from lsprotocol import types as T
from pytest_lsp import ClientServerConfig, LanguageClient

from aidl_lang.editor.lsp import analysis as an

from conftest import EXAMPLES, ROOT
from lsp_published import keep, published

TELEPHONE = (ROOT / "examples" / "telephone.aidl").read_text()

BROKEN = """\
param w = 10 mm

solid plate {
    body = Rectangle(center=(0, 0), width=w, height=20)
    hole bore {
        c = Circel(center=(0, 0), radius=3)
    }
}
"""

GOOD = """\
param w = 10 mm

solid plate {
    body = Rectangle(center=(0, 0), width=w, height=20)
    hole bore {
        c = Circle(center=(0, 0), radius=3)
    }
    CenterInside(bore, self)
}
"""


def pos(src: str, needle: str, k: int = 0, nth: int = 0) -> tuple[int, int]:
    """LSP (line, character) of the k-th character of the nth occurrence of needle."""
    i = -1
    for _ in range(nth + 1):
        i = src.index(needle, i + 1)
    p = an.position_at(src, i + k)
    return p.line, p.character


# ------------------------------------------------------------------ over stdio
# one server for the module's two tests (each opens its own documents): one start-up saved
@pytest_lsp.fixture(scope="module", config=ClientServerConfig(
    server_command=[sys.executable, "-m", "aidl_lang.cli", "lsp"]))
async def client(lsp_client: LanguageClient):
    keep(lsp_client)
    # VS Code refreshes inlay hints and code lenses when the server asks (after each analysis)
    lsp_client.feature(T.WORKSPACE_INLAY_HINT_REFRESH)(lambda params: None)
    lsp_client.feature(T.WORKSPACE_CODE_LENS_REFRESH)(lambda params: None)
    await lsp_client.initialize_session(T.InitializeParams(
        capabilities=pytest_lsp.client_capabilities("visual-studio-code")))
    yield
    await lsp_client.shutdown_session()


def _open(client: LanguageClient, uri: str, text: str, version: int = 1) -> None:
    client.text_document_did_open(T.DidOpenTextDocumentParams(
        text_document=T.TextDocumentItem(uri=uri, language_id="aidl-cad", version=version,
                                         text=text)))


async def _diagnostics(client: LanguageClient, uri: str, version: int | None = None):
    """The next diagnostics published for ``uri`` (of ``version`` if given: a version may be
    published more than once, parse-and-check first at start-up)."""
    return await published(client, uri, version)


@pytest.mark.asyncio(loop_scope="module")
async def test_server_diagnostics_hover_completion_definition(client: LanguageClient, tmp_path):
    uri = (tmp_path / "plate.aidl").as_uri()
    _open(client, uri, BROKEN)
    diags = await _diagnostics(client, uri)
    assert [d.code for d in diags] == ["E0103"]
    r = diags[0].range                       # exactly the misspelt `Circel`, 0-based
    assert (r.start.line, r.start.character, r.end.line, r.end.character) == (5, 12, 5, 18)
    assert "did you mean `Circle`" in diags[0].message

    # fix it: the diagnostics go away (debounced, solve included)
    client.text_document_did_change(T.DidChangeTextDocumentParams(
        text_document=T.VersionedTextDocumentIdentifier(uri=uri, version=2),
        content_changes=[T.TextDocumentContentChangeWholeDocument(text=GOOD)]))
    assert list(await _diagnostics(client, uri, version=2)) == []

    h = await client.text_document_hover_async(T.HoverParams(
        text_document=T.TextDocumentIdentifier(uri=uri), position=T.Position(*pos(GOOD, "Rectangle", 2))))
    assert "Rectangle(center: point, width: length" in h.contents.value
    # the file solves: hover on a name shows its solved values too
    h = await client.text_document_hover_async(T.HoverParams(
        text_document=T.TextDocumentIdentifier(uri=uri), position=T.Position(*pos(GOOD, "c = Circle"))))
    assert "plate.bore.c.center = (0.000, 0.000) mm" in h.contents.value
    assert "plate.bore.c.radius = 3.000 mm" in h.contents.value
    h = await client.text_document_hover_async(T.HoverParams(
        text_document=T.TextDocumentIdentifier(uri=uri), position=T.Position(*pos(GOOD, "body =", 1))))
    assert "plate.body.width = 10.000 mm" in h.contents.value

    # type `body.` on a new line inside the structure: members of a Rectangle
    typed = GOOD.replace("    CenterInside", "    body.\n    CenterInside")
    client.text_document_did_change(T.DidChangeTextDocumentParams(
        text_document=T.VersionedTextDocumentIdentifier(uri=uri, version=3),
        content_changes=[T.TextDocumentContentChangeWholeDocument(text=typed)]))
    line, ch = pos(typed, "body.\n", 5)
    res = await client.text_document_completion_async(T.CompletionParams(
        text_document=T.TextDocumentIdentifier(uri=uri), position=T.Position(line, ch)))
    labels = {i.label for i in (res.items if isinstance(res, T.CompletionList) else res)}
    assert {"top_left", "width", "bb", "center"} <= labels
    assert "Circle" not in labels

    loc = await client.text_document_definition_async(T.DefinitionParams(
        text_document=T.TextDocumentIdentifier(uri=uri), position=T.Position(*pos(typed, "bore, self"))))
    assert loc.range.start == T.Position(*pos(typed, "bore {"))

    syms = await client.text_document_document_symbol_async(T.DocumentSymbolParams(
        text_document=T.TextDocumentIdentifier(uri=uri)))
    assert [s.name for s in syms] == ["w", "plate"]
    assert [c.name for c in syms[1].children] == ["body", "bore"]


@pytest.mark.asyncio(loop_scope="module")
async def test_server_survives_garbage_and_formats(client: LanguageClient, tmp_path):
    uri = (tmp_path / "junk.aidl").as_uri()
    garbage = 'solid {{ ( ] "unterminated\n\x00 é😀 f"{" // -> ** else elif\n' + TELEPHONE[:700]
    _open(client, uri, garbage)
    diags = await _diagnostics(client, uri)
    assert diags and all(d.source == "aidl" for d in diags)
    for line in range(0, 6):
        for ch in (0, 3, 9, 40):
            p = T.Position(line, ch)
            doc = T.TextDocumentIdentifier(uri=uri)
            await client.text_document_hover_async(T.HoverParams(text_document=doc, position=p))
            await client.text_document_completion_async(T.CompletionParams(text_document=doc, position=p))
            await client.text_document_references_async(T.ReferenceParams(
                text_document=doc, position=p, context=T.ReferenceContext(include_declaration=True)))
    edits = await client.text_document_formatting_async(T.DocumentFormattingParams(
        text_document=T.TextDocumentIdentifier(uri=uri),
        options=T.FormattingOptions(tab_size=4, insert_spaces=True)))
    assert not edits                         # syntax errors: the formatter refuses
    # the server still works on a good document
    uri2 = (tmp_path / "ok.aidl").as_uri()
    _open(client, uri2, "x=1;y=( x+2 )\n")
    edits = await client.text_document_formatting_async(T.DocumentFormattingParams(
        text_document=T.TextDocumentIdentifier(uri=uri2),
        options=T.FormattingOptions(tab_size=4, insert_spaces=True)))
    assert [e.new_text for e in edits] == ["x = 1\ny = (x + 2)\n"]


# ------------------------------------------------------------------ analysis functions
def test_diagnostic_range_of_a_syntax_error():
    src = "solid a {\n    c = Circle(center=(0, 0), radius=)\n}\n"
    (d,) = an.diagnostics(src, "t.aidl")
    assert d.code == "E0001" and d.severity == T.DiagnosticSeverity.Error
    assert (d.range.start.line, d.range.start.character) == (1, 37)


def test_diagnostic_columns_are_utf16():
    src = 'drawing d {\n    t = Text("😀😀", (0, 0)) ; q = nope\n}\n'
    (d,) = an.diagnostics(src, "t.aidl", solve=False)
    assert d.code == "E0101"
    line = src.split("\n")[1]
    assert d.range.start.character == len(line[:line.index("nope")].encode("utf-16-le")) // 2


def test_hover_primitive_constraint_template_and_member():
    h = an.hover(TELEPHONE, *pos(TELEPHONE, "Polygon("))
    assert "Polygon(points: points" in h.contents.value and "members" in h.contents.value
    h = an.hover(TELEPHONE, *pos(TELEPHONE, "Concentric("))
    assert "Concentric(a: centered, b: centered)" in h.contents.value
    h = an.hover(TELEPHONE, *pos(TELEPHONE, "body.center.x", 6))
    assert "center: point" in h.contents.value
    gears = (ROOT / "examples" / "parts" / "gears.aidl").read_text()
    h = an.hover(gears, *pos(gears, "spur_gear"))
    assert h.contents.value.startswith("```aidl_cad\ndef spur_gear(teeth=12")
    assert "spur gear" in h.contents.value           # the comment above the def
    h = an.hover(TELEPHONE, *pos(TELEPHONE, "dial_r * cos"))
    assert "param dial_r = 34 mm" in h.contents.value


@pytest.mark.parametrize("typed,expected", [
    ("    r = Rectangle(center=(0, 0), width=2, height=3)\n    r.", {"top_left", "width", "bb"}),
    ("    r = Rectangle(center=(0, 0), width=2, height=3)\n    r.top.", {"start", "end", "length"}),
    ("    q = base.", {"body", "finger_holes", "dial", "foot", "bb"}),
    ("    q = base.body.bb.", {"top_left", "center_x", "width"}),
    ("    q = self.", {"base", "cradle", "handset", "bb"}),
    ("    q = cradle.prong[0].", {"top_left", "width"}),
])
def test_completion_after_a_dot(typed, expected):
    src = TELEPHONE.replace("    # stack: cradle", typed + "\n    # stack: cradle")
    line, ch = pos(src, typed.split("\n")[-1], len(typed.split("\n")[-1]))
    labels = {c.label for c in an.completions(src, line, ch)}
    assert expected <= labels and "Circle" not in labels


def test_completion_in_scope_and_vocabulary():
    line, ch = pos(TELEPHONE, "        AlignBottom")
    labels = {c.label for c in an.completions(TELEPHONE, line, ch)}
    assert {"prong", "base_w", "telephone", "Rectangle", "Coincident", "OnTopOf", "sqrt", "solid",
            "param", "self"} <= labels
    assert "finger_holes" not in labels          # a child of another structure


def test_definition_and_references():
    uri = "file:///t.aidl"
    loc = an.definition(TELEPHONE, *pos(TELEPHONE, "finger_holes.pitch", 14), uri)
    assert loc.range.start == T.Position(*pos(TELEPHONE, "pitch = Circle"))
    refs = an.references(TELEPHONE, *pos(TELEPHONE, "ring_r = "), uri)
    lines = [r.range.start.line for r in refs]
    assert len(refs) == TELEPHONE.count("ring_r") and lines == sorted(lines)
    # a loop variable is local to its loop
    refs = an.references(TELEPHONE, *pos(TELEPHONE, "for k in range(10)", 4), uri)
    first = TELEPHONE.index("for k in range(10)")
    loop = TELEPHONE[first:TELEPHONE.index("}", first)]
    assert len(refs) == loop.count(" k ") == 2       # the definition and one use


def test_document_symbols_are_the_structure_tree():
    syms = an.document_symbols(TELEPHONE)
    desk = next(s for s in syms if s.name == "desk")
    assert desk.detail == "assembly" and [c.name for c in desk.children] == ["telephone", "cord"]
    tel = desk.children[0]
    assert tel.kind == T.SymbolKind.Struct and tel.detail == "solid"
    assert [c.name for c in tel.children] == ["base", "cradle", "handset"]
    base = tel.children[0]
    assert {"body", "foot", "finger_holes", "dial"} <= {c.name for c in base.children}


@pytest.mark.parametrize("path", EXAMPLES[:4], ids=lambda p: p.name)
def test_examples_have_no_diagnostics(path):
    assert an.diagnostics(path.read_text(), str(path)) == []


def test_imported_templates_hover_definition_and_members():
    path = ROOT / "examples" / "gear.aidl"
    src = path.read_text()
    h = an.hover(src, *pos(src, "spur_gear("), path=str(path))
    assert "def spur_gear(teeth=12" in h.contents.value
    loc = an.definition(src, *pos(src, "spur_gear("), "file:///gear.aidl", path=str(path))
    gears = ROOT / "examples" / "parts" / "gears.aidl"
    assert loc.uri == gears.as_uri()
    assert loc.range.start == T.Position(*pos(gears.read_text(), "spur_gear("))
    typed = src.replace("    Fixed(pinion", "    pinion.\n    Fixed(pinion")
    line, ch = pos(typed, "    pinion.\n", len("    pinion."))
    labels = {c.label for c in an.completions(typed, line, ch, path=str(path))}
    assert {"hub", "bore_hole", "bb"} <= labels


def test_value_hover_names_chains_loops_and_the_enclosing_structure():
    src = (ROOT / "examples" / "mounting_plate.aidl").read_text()
    values: dict = {}
    an.diagnostics(src, "mounting_plate.aidl", True, None, values)
    assert values["kit.plate.shaft.boss.radius"] == "kit.plate.shaft.boss.radius = 11.000 mm"
    at_boss = an.value_hover(src, *pos(src, "shaft.boss.center", 7), values)
    assert "kit.plate.shaft.boss.center = (-20.000, 0.000) mm" in at_boss and "radius" in at_boss
    at_center = an.value_hover(src, *pos(src, "shaft.boss.center", 12), values)
    assert "radius" not in at_center
    corners = an.value_hover(src, *pos(src, "hole corner", 6), values)
    assert "kit.plate.corner[3].bbox = (-54.500, 29.500, -49.500, 34.500) mm" in corners
    assert an.value_hover(src, *pos(src, "import", 2), values) is None
    broken: dict = {}
    an.diagnostics(BROKEN, "b.aidl", True, None, broken)
    assert broken == {}
