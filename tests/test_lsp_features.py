"""`aidl lsp` as a CAD workbench: the start-up front (boot.py), solved values in the code
(inlay hints, DOF code lenses), folding, highlight, document links, workspace symbols, code
links and `aidl/explain` -- over stdio with a real client (pytest-lsp) and the pure functions."""
import asyncio
import io
import json
import subprocess
import sys
import time

import pytest
import pytest_lsp
from lsprotocol import converters
from lsprotocol import types as T
from pytest_lsp import ClientServerConfig, LanguageClient

from aidl_lang.editor.lsp import boot, hints, navigate, plain
from aidl_lang.editor.lsp import analysis as an
from aidl_lang.parser import parse
from aidl_lang.base.diagnostics import DiagnosticSink

from conftest import ROOT
from lsp_published import keep, published

PLATE = """\
param w = 40 mm

// a plate
// with a hole
solid plate {
    body = Rectangle(center=(0, 0), width=w, height=20)
    hole bore {
        c = Circle(center=(5, 0), radius=3)
    }
}
"""

FIXED = """\
solid part {
    body = Rectangle(center=(0, 0), width=30, height=10)
    Fixed(body)
}
"""


def _pos(src: str, needle: str, k: int = 0) -> tuple[int, int]:
    p = an.position_at(src, src.index(needle) + k)
    return p.line, p.character


def _frame(msg: dict) -> bytes:
    b = json.dumps(msg).encode()
    return b"Content-Length: %d\r\n\r\n" % len(b) + b


def _messages(data: bytes) -> list[dict]:
    out, s = [], io.BytesIO(data)
    while (body := boot.read_message(s)) is not None:
        out.append(json.loads(body))
    return out


# ------------------------------------------------------------------ the start-up front
CLIENTS = [None, "visual-studio-code", "neovim@0.11", "neovim@0.6", "emacs"]


@pytest.mark.parametrize("name", CLIENTS)
def test_boot_initialize_answer_equals_what_pygls_computes(name):
    caps = {} if name is None else converters.get_converter().unstructure(
        pytest_lsp.client_capabilities(name))
    assert boot.initialize_result({"capabilities": caps}) == boot.pygls_initialize_result(caps)


def test_generated_files_are_up_to_date():
    for script in ("gen_lsp_capabilities.py", "gen_codes_doc.py"):
        r = subprocess.run([sys.executable, str(ROOT / "editors" / script), "--check"],
                           capture_output=True, text=True)
        assert r.returncode == 0, r.stdout

    gen = ROOT / "editors" / "gen_grammar.py"          # stale: --check names it, writes nothing
    vim = ROOT / "editors" / "nvim" / "syntax" / "aidl-cad.vim"
    text = vim.read_text(encoding="utf-8")
    try:
        vim.write_text(text + "\n", encoding="utf-8")
        r = subprocess.run([sys.executable, str(gen), "--check"], capture_output=True, text=True)
        assert r.returncode == 1 and "aidl-cad.vim is out of date" in r.stdout, r.stdout
        assert vim.read_text(encoding="utf-8") == text + "\n"
        r = subprocess.run([sys.executable, str(gen)], capture_output=True, text=True)
        assert r.returncode == 0 and "wrote editors/nvim/syntax/aidl-cad.vim" in r.stdout, r.stdout
        assert vim.read_text(encoding="utf-8") == text
    finally:
        vim.write_text(text, encoding="utf-8")


BOOT_RUN = """
import io, json, sys
from aidl_lang.editor.lsp import boot
src = sys.stdin.buffer.read()
out = io.BytesIO()
b = boot.Boot(io.BytesIO(src), boot.Writer(out), boot.Feed())
b.run()
heavy = [m for m in ("pygls.lsp", "pygls.protocol", "lsprotocol", "cattrs", "numpy", "scipy")
         if m in sys.modules]
sys.stdout.write(json.dumps({"out": out.getvalue().decode(), "heavy": heavy,
                             "replay": b.feed.read(-1).decode()}))
"""


def test_boot_answers_and_publishes_before_loading_pygls(tmp_path):
    """The front answers `initialize` and publishes the first document's parse-and-check
    diagnostics with the standard library, the parser and the checker only, and hands every
    message on, in order, for pygls."""
    uri = (tmp_path / "a.aidl").as_uri()
    broken = PLATE.replace("Circle(", "Circel(")
    msgs = [{"jsonrpc": "2.0", "id": 7, "method": "initialize", "params": {"capabilities": {}}},
            {"jsonrpc": "2.0", "method": "initialized", "params": {}},
            {"jsonrpc": "2.0", "method": "workspace/didChangeConfiguration",
             "params": {"settings": {"aidl": {}}}},          # as VS Code sends it, before opening
            {"jsonrpc": "2.0", "method": "textDocument/didOpen", "params": {"textDocument": {
                "uri": uri, "languageId": "aidl-cad", "version": 3, "text": broken}}},
            {"jsonrpc": "2.0", "method": "textDocument/didOpen", "params": {"textDocument": {
                "uri": uri + "2", "languageId": "aidl-cad", "version": 1, "text": "x = (\n"}}}]
    data = b"".join(_frame(m) for m in msgs)
    r = subprocess.run([sys.executable, "-c", BOOT_RUN], input=data, capture_output=True,
                       check=True, cwd=ROOT)
    got = json.loads(r.stdout)
    assert got["heavy"] == []
    answer, published, second = _messages(got["out"].encode())
    assert second["params"]["uri"] == uri + "2"          # a second tab restored meanwhile
    assert [d["code"] for d in second["params"]["diagnostics"]] == ["E0001"]
    assert answer["id"] == 7 and "hoverProvider" in answer["result"]["capabilities"]
    assert published["method"] == "textDocument/publishDiagnostics"
    p = published["params"]
    assert p["uri"] == uri and p["version"] == 3
    (d,) = p["diagnostics"]
    assert d["code"] == "E0103" and d["range"] == {"start": {"line": 7, "character": 12},
                                                   "end": {"line": 7, "character": 18}}
    assert d["data"]["fixes"][0]["newText"] == "Circle"
    assert [m.get("method") for m in _messages(got["replay"].encode())] == \
        ["initialize", "initialized", "workspace/didChangeConfiguration", "textDocument/didOpen",
         "textDocument/didOpen"]


def test_quick_diagnostics_equal_the_pipeline_when_they_hold_an_error():
    for bad in (PLATE.replace("Circle(", "Circel("), PLATE.replace("radius=3)", "radius=3"),
                PLATE.replace("width=w", "width=ww")):
        quick = plain.quick_diagnostics(bad, "p.aidl", "file:///p.aidl")
        full = an.diagnostics_json(bad, "p.aidl", uri="file:///p.aidl")
        assert quick and quick == full


def test_writer_drops_only_pygls_copy_of_the_initialize_answer():
    out = io.BytesIO()
    w = boot.Writer(out)
    w.send({"jsonrpc": "2.0", "id": 1, "result": {"capabilities": {}}})
    w.drop_id = 1
    w.write(_frame({"jsonrpc": "2.0", "id": 1, "result": {"capabilities": {"x": 1}}}))
    w.write(_frame({"jsonrpc": "2.0", "id": 1, "result": None}))      # a later id 1: kept
    got = _messages(out.getvalue())
    assert [m["result"] for m in got] == [{"capabilities": {}}, None]


def test_feed_gives_lines_and_exact_reads_across_puts():
    f = boot.Feed()
    f.put(b"Content-Length: 5\r\n")
    f.put(b"\r\nab")
    f.put(b"cde")
    f.close()
    assert f.readline() == b"Content-Length: 5\r\n"
    assert f.readline() == b"\r\n"
    assert f.read(5) == b"abcde"
    assert f.readline() == b""


@pytest.mark.timing
def test_cold_start_publishes_first_diagnostics_then_the_solved_ones(tmp_path):
    """A real `aidl lsp`: the first publish is the parse-and-check one, the second (same
    version) the solved one with the error only the solver finds."""
    text = FIXED.replace("Fixed(body)", "Fixed(body)\n    Distance(body.top_left, body.top_right, 50)")
    uri = (tmp_path / "c.aidl").as_uri()
    p = subprocess.Popen([sys.executable, "-m", "aidl_lang.cli", "lsp"], stdin=subprocess.PIPE,
                         stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, cwd=ROOT)
    try:
        t0 = time.perf_counter()
        p.stdin.write(_frame({"jsonrpc": "2.0", "id": 1, "method": "initialize",
                              "params": {"capabilities": {}}}))
        p.stdin.flush()
        assert json.loads(boot.read_message(p.stdout))["id"] == 1
        for m in ({"jsonrpc": "2.0", "method": "initialized", "params": {}},
                  {"jsonrpc": "2.0", "method": "textDocument/didOpen", "params": {"textDocument": {
                      "uri": uri, "languageId": "aidl-cad", "version": 1, "text": text}}}):
            p.stdin.write(_frame(m))
        p.stdin.flush()
        first = json.loads(boot.read_message(p.stdout))
        assert first["method"] == "textDocument/publishDiagnostics"
        assert first["params"]["diagnostics"] == []
        second = json.loads(boot.read_message(p.stdout))
        assert second["params"]["version"] == 1
        assert [d["code"] for d in second["params"]["diagnostics"]] == ["E0401"]
        assert time.perf_counter() - t0 < 60
        # pygls answers from here on; the document is known to it (the replayed didOpen)
        p.stdin.write(_frame({"jsonrpc": "2.0", "id": 9, "method": "textDocument/documentSymbol",
                              "params": {"textDocument": {"uri": uri}}}))
        p.stdin.flush()
        while (m := json.loads(boot.read_message(p.stdout))).get("id") != 9:
            assert m.get("method") == "textDocument/publishDiagnostics"   # the server's own pass
        assert [s["name"] for s in m["result"]] == ["part"]
        p.stdin.write(_frame({"jsonrpc": "2.0", "id": 2, "method": "shutdown"}))
        p.stdin.write(_frame({"jsonrpc": "2.0", "method": "exit"}))
        p.stdin.flush()
        assert p.wait(20) == 0
    finally:
        if p.poll() is None:
            p.kill()


# ------------------------------------------------------------------ pure functions
def test_solved_facts_and_their_places():
    import aidl_lang
    r = aidl_lang.compile(source=PLATE, path="p.aidl")
    facts = hints.solved_facts(r)
    assert facts["geometry"]["plate.body"] == "40 × 20 mm @ (0, 0)"
    assert facts["geometry"]["plate.bore.c"] == "r=3 mm @ (5, 0)"
    dof = {s["structure"]: s["dof"] for s in r.freedom(detail=True)["structures"]}
    assert facts["structures"]["plate"] == f"{dof['plate']} DOF: body, bore (position)"
    # the circle moving inside the hole is the hole moving: counted once, in the plate
    assert facts["structures"]["plate.bore"] == "fully constrained"
    assert dof["plate"] > 0 and dof["plate.bore"] == 0
    prog = parse(PLATE, "p.aidl", DiagnosticSink())
    got = {h["label"]: (h["position"]["line"], h["position"]["character"])
           for h in hints.inlay_hints(PLATE, prog, facts)}
    assert got["40 × 20 mm @ (0, 0)"] == (5, len(PLATE.split("\n")[5]))
    assert got["r=3 mm @ (5, 0)"] == (7, len(PLATE.split("\n")[7]))
    lenses = {L["command"]["title"]: L["range"]["start"]["line"]
              for L in hints.code_lenses(PLATE, prog, facts)}
    assert lenses[facts["structures"]["plate"]] == 4
    assert lenses[facts["structures"]["plate.bore"]] == 6


def test_fully_constrained_lens():
    import aidl_lang
    r = aidl_lang.compile(source=FIXED, path="f.aidl")
    assert hints.solved_facts(r)["structures"]["part"] == "fully constrained"


def test_folding_ranges_blocks_and_comment_runs():
    got = {(f.start_line, f.end_line, f.kind) for f in navigate.folding_ranges(PLATE)}
    assert (4, 8, None) in got                                   # solid plate { ... }
    assert (6, 7, None) in got                                   # hole bore { ... }
    assert (2, 3, T.FoldingRangeKind.Comment) in got
    assert len(got) == 3
    # braces in strings and comments do not count; a block comment folds
    src = 'x = "{"\n/* a\n b { */\nsolid s {\n  c = 1\n}\n'
    got = {(f.start_line, f.end_line, f.kind) for f in navigate.folding_ranges(src)}
    assert got == {(1, 2, T.FoldingRangeKind.Comment), (3, 4, None)}


def test_highlight_respects_scopes():
    src = "solid a {\n    c = Circle(center=(0, 0), radius=1)\n    d = c.radius\n}\n" \
          "solid b {\n    c = Circle(center=(0, 0), radius=2)\n}\n"
    hl = navigate.highlights(src, *_pos(src, "c = C"))
    assert [(h.range.start.line, h.kind) for h in hl] == \
        [(1, T.DocumentHighlightKind.Write), (2, T.DocumentHighlightKind.Read)]
    hl = navigate.highlights(src, *_pos(src, "Circle"))
    assert [h.range.start.line for h in hl] == [1, 5]
    assert all(h.kind == T.DocumentHighlightKind.Text for h in hl)


def test_document_links_resolve_imports(tmp_path):
    (tmp_path / "lib").mkdir()
    (tmp_path / "lib" / "parts.aidl").write_text("def peg(r) -> solid { c = Circle(center=(0, 0), radius=r) }\n")
    main = tmp_path / "main.aidl"
    src = 'import "lib/parts.aidl"\nimport "missing.aidl"\n'
    (link,) = navigate.document_links(src, str(main))
    assert link.target == (tmp_path / "lib" / "parts.aidl").resolve().as_uri()
    assert (link.range.start.character, link.range.end.character) == (8, 22)


def test_workspace_symbols_from_open_documents_and_files(tmp_path):
    (tmp_path / "a.aidl").write_text("param size = 3 mm\ndef knob(r) -> solid { c = Circle(center=(0, 0), radius=r) }\n")
    (tmp_path / ".git").mkdir()
    (tmp_path / ".git" / "x.aidl").write_text("param hidden = 1\n")
    opened = {"file:///open.aidl": ("/open.aidl", PLATE)}
    syms = navigate.workspace_symbols("", opened, [str(tmp_path)])
    names = {(s.name, s.container_name) for s in syms}
    assert {("w", None), ("plate", None), ("bore", "plate"), ("c", "plate.bore"),
            ("size", None), ("knob", None)} <= names
    assert not any(s.name == "hidden" for s in syms)
    assert [s.name for s in navigate.workspace_symbols("kn", opened, [str(tmp_path)])] == ["knob"]
    assert {s.name for s in navigate.workspace_symbols("bor", opened, [str(tmp_path)])} == {"bore"}


def test_code_description_links_to_the_code_anchor():
    (d,) = plain.quick_diagnostics(PLATE.replace("Circle(", "Circel("), "p.aidl")
    href = d["codeDescription"]["href"]
    assert href.endswith("/docs/codes.md#e0103")
    assert "\n## E0103\n" in (ROOT / "docs" / "codes.md").read_text()


# ------------------------------------------------------------------ over stdio
@pytest_lsp.fixture(scope="module", config=ClientServerConfig(
    server_command=[sys.executable, "-m", "aidl_lang.cli", "lsp", "--stdio"]))
async def client(lsp_client: LanguageClient):
    keep(lsp_client)
    lsp_client.refreshes = []

    @lsp_client.feature(T.WORKSPACE_INLAY_HINT_REFRESH)
    def inlay_refresh(params):
        lsp_client.refreshes.append("inlayHint")

    @lsp_client.feature(T.WORKSPACE_CODE_LENS_REFRESH)
    def lens_refresh(params):
        lsp_client.refreshes.append("codeLens")

    lsp_client.init_result = await lsp_client.initialize_session(T.InitializeParams(
        capabilities=pytest_lsp.client_capabilities("neovim@0.11"),
        initialization_options={"debounce": 0}))
    yield
    await lsp_client.shutdown_session()


def _open(client: LanguageClient, uri: str, text: str) -> None:
    client.text_document_did_open(T.DidOpenTextDocumentParams(
        text_document=T.TextDocumentItem(uri=uri, language_id="aidl-cad", version=1, text=text)))


async def _until(fn, timeout=60.0):
    end = time.monotonic() + timeout
    while True:
        got = await fn()
        if got:
            return got
        assert time.monotonic() < end, "timed out"
        await asyncio.sleep(0.1)


@pytest.mark.asyncio(loop_scope="module")
async def test_server_inlay_hints_code_lens_and_toggle(client: LanguageClient, tmp_path):
    uri = (tmp_path / "plate.aidl").as_uri()
    _open(client, uri, PLATE)
    whole = T.Range(start=T.Position(line=0, character=0), end=T.Position(line=20, character=0))

    async def hints_now():
        return await client.text_document_inlay_hint_async(T.InlayHintParams(
            text_document=T.TextDocumentIdentifier(uri=uri), range=whole))
    got = await _until(hints_now)
    labels = {h.label: h.position.line for h in got}
    assert "inlayHint" in client.refreshes            # asked for after the analysis
    assert labels == {"40 × 20 mm @ (0, 0)": 5, "r=3 mm @ (5, 0)": 7}
    lenses = await client.text_document_code_lens_async(T.CodeLensParams(
        text_document=T.TextDocumentIdentifier(uri=uri)))
    titles = {L.range.start.line: L.command.title for L in lenses}
    # the circle moving inside the hole is the hole moving, counted in the plate (issue 38)
    assert titles[6] == "fully constrained"
    assert titles[4] == "4 DOF: body, bore (position)"
    line, ch = _pos(PLATE, "plate {")
    h = await client.text_document_hover_async(T.HoverParams(
        text_document=T.TextDocumentIdentifier(uri=uri), position=T.Position(line=line, character=ch + 2)))
    assert f"degrees of freedom: **{titles[4]}**" in h.contents.value
    assert "plate.origin = (0.000, 0.000) mm" in h.contents.value       # and its solved values
    client.workspace_did_change_configuration(T.DidChangeConfigurationParams(
        settings={"aidl": {"inlayHints": {"enabled": False}}}))
    assert not await hints_now()
    client.workspace_did_change_configuration(T.DidChangeConfigurationParams(
        settings={"aidl": {"inlayHints": {"enabled": True}}}))
    assert len(await hints_now()) == 2
    # a change that does not solve (typing): the last solved hints stay
    client.text_document_did_change(T.DidChangeTextDocumentParams(
        text_document=T.VersionedTextDocumentIdentifier(uri=uri, version=2),
        content_changes=[T.TextDocumentContentChangeWholeDocument(text=PLATE.replace("Circle(", "Circel("))]))
    diags = await published(client, uri, 2)
    assert [d.code for d in diags] == ["E0103"]
    assert {h.label for h in await hints_now()} == set(labels)


@pytest.mark.asyncio(loop_scope="module")
async def test_server_folding_highlight_links_symbols_explain(client: LanguageClient, tmp_path):
    (tmp_path / "lib.aidl").write_text("def peg(r) -> solid { c = Circle(center=(0, 0), radius=r) }\n")
    src = 'import "lib.aidl"\n' + PLATE
    uri = (tmp_path / "main.aidl").as_uri()
    _open(client, uri, src)
    doc = T.TextDocumentIdentifier(uri=uri)
    folds = await client.text_document_folding_range_async(T.FoldingRangeParams(text_document=doc))
    assert (5, 9) in {(f.start_line, f.end_line) for f in folds}
    line, ch = _pos(src, "w,")
    hl = await client.text_document_document_highlight_async(T.DocumentHighlightParams(
        text_document=doc, position=T.Position(line=line, character=ch)))
    assert sorted(h.range.start.line for h in hl) == [1, 6]
    (link,) = await client.text_document_document_link_async(T.DocumentLinkParams(text_document=doc))
    assert link.target == (tmp_path / "lib.aidl").resolve().as_uri()
    syms = await client.workspace_symbol_async(T.WorkspaceSymbolParams(query="bore"))
    assert ("bore", uri) in [(s.name, s.location.uri) for s in syms]
    assert {s.name for s in syms} == {"bore"}
    ex = await client.protocol.send_request_async("aidl/explain", {"code": "e0103"})
    assert ex.code == "E0103" and ex.title.startswith("unknown function")
    assert ex.href.endswith("codes.md#e0103")
    with pytest.raises(Exception, match="codes near it: E0101, E0102, E0103"):
        await client.protocol.send_request_async("aidl/explain", {"code": "E0140"})


@pytest.mark.asyncio(loop_scope="module")
async def test_server_positions_are_utf16_even_for_a_utf8_client(client: LanguageClient):
    """Neovim 0.11 offers UTF-8 first; the server answers UTF-16, the unit it counts in."""
    assert client.init_result.capabilities.position_encoding == T.PositionEncodingKind.Utf16


def test_param_hints_in_file_units_and_instance_lenses():
    import aidl_lang
    src = ("units cm\nparam w = 40 mm\nparam r = w / 4\nparam k = 2\n"
           "def peg(rad) -> solid {\n    c = Circle(center=(0, 0), radius=rad)\n}\n"
           "solid board {\n    a = peg(r)\n    Fixed(a.c)\n}\n")
    r = aidl_lang.compile(source=src, path="p.aidl")
    facts = hints.solved_facts(r)
    prog = parse(src, "p.aidl", DiagnosticSink())
    got = {h["position"]["line"]: h["label"] for h in hints.inlay_hints(src, prog, facts)}
    assert got[1] == "= 4 cm" and got[2] == "= 1 cm"
    assert 3 not in got                         # `param k = 2` says it already
    lenses = {L["range"]["start"]["line"]: L["command"]["title"]
              for L in hints.code_lenses(src, prog, facts)}
    assert lenses[8] == facts["structures"]["board.a"]      # the template instance `a = peg(r)`
    assert lenses[7] == facts["structures"]["board"]


def test_the_analysis_worker_imports_no_lsprotocol():
    """The worker's diagnostics, values and facts are plain JSON: it starts without the ~0.4 s
    of lsprotocol (and pygls)."""
    code = ("import sys; from aidl_lang.editor.lsp.worker import diagnostics_json; "
            "v, e = {}, {}; d = diagnostics_json(open('examples/telephone.aidl').read(), "
            "'t.aidl', values=v, extra=e); "
            "print(len(v) > 50, bool(e['structures']), "
            "[m for m in ('lsprotocol', 'pygls', 'cattrs') if m in sys.modules])")
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT,
                       check=True)
    assert r.stdout.split() == ["True", "True", "[]"]
