"""The Neovim/Vim filetype plugin (editors/nvim): `.aidl` is `aidl-cad` only when it looks like
AIDL (CAD), 4-space indentation and `#` comments, the generated syntax file, and (Neovim 0.7+)
the language server attached with diagnostics. Runs the real editor headless; CI installs
Debian's neovim (0.7)."""
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import ROOT

PLUGIN = ROOT / "editors" / "nvim"
NVIM = shutil.which("nvim")

PROBE = r"""
local out = {}
vim.cmd('edit android.aidl')
table.insert(out, 'android=' .. vim.bo.filetype)
vim.cmd('edit empty.aidl')
table.insert(out, 'empty=' .. vim.bo.filetype)
vim.cmd('edit cad.aidl')
table.insert(out, 'cad=' .. vim.bo.filetype)
table.insert(out, 'opts=' .. tostring(vim.bo.expandtab) .. ',' .. vim.bo.shiftwidth .. ','
  .. vim.bo.commentstring .. ',' .. vim.bo.syntax)
local ok = vim.wait(60000, function() return #vim.diagnostic.get(0) > 0 end, 50)
local d = vim.diagnostic.get(0)[1]
table.insert(out, 'diag=' .. (d and (d.lnum .. ':' .. d.col .. ':' .. d.code) or 'none'))
local function syn(l, c) return vim.fn.synIDattr(vim.fn.synID(l, c, 1), 'name') end
table.insert(out, 'syn=' .. syn(1, 13) .. ',' .. syn(2, 1) .. ',' .. syn(3, 24))
table.insert(out, 'errmsg=' .. vim.v.errmsg)
io.stdout:write(table.concat(out, '\n') .. '\n')
vim.cmd('qa!')
"""


@pytest.mark.skipif(NVIM is None, reason="neovim is not installed (.ci/run installs it)")
def test_neovim_detects_sets_options_and_attaches_the_server(tmp_path):
    (tmp_path / ".git").mkdir()
    (tmp_path / "android.aidl").write_text("package com.example;\ninterface IFoo {\n    void f();\n}\n")
    (tmp_path / "empty.aidl").write_text("")
    (tmp_path / "cad.aidl").write_text("param w = 3 mm\nsolid plate {\n    c = Circel(center=(0, 0), radius=w)\n}\n")
    (tmp_path / "probe.lua").write_text(PROBE)
    env = {"PATH": f"{Path(sys.executable).parent}:/usr/bin:/bin", "HOME": str(tmp_path)}
    r = subprocess.run([NVIM, "--headless", "-u", "NONE", "-i", "NONE", "--cmd", f"set rtp^={PLUGIN}",
                        "-c", "filetype plugin on", "-c", "syntax on", "-c", "luafile probe.lua"],
                       cwd=tmp_path, capture_output=True, text=True, timeout=120, env=env)
    got = dict(line.split("=", 1) for line in r.stdout.split("\n") if "=" in line)
    assert got.get("android") == "aidl", r.stdout + r.stderr     # Android's IDL keeps its type
    assert got["empty"] != "aidl-cad"
    assert got["cad"] == "aidl-cad"
    assert got["opts"] == "true,4,# %s,aidl-cad"
    assert got["diag"] == "2:8:E0103"                            # from `aidl lsp`, found on PATH
    assert got["syn"] == "aidlCadUnit,aidlCadStructure,aidlCadNumber"      # mm, solid, 0
    assert got["errmsg"] == ""                                   # no error from the plugin files


def test_vim_syntax_file_is_generated_and_fresh():
    from aidl_lang.editor.highlight import vim_syntax
    text = (PLUGIN / "syntax" / "aidl-cad.vim").read_text(encoding="utf-8")
    assert text == vim_syntax(), "run `python editors/gen_grammar.py` and commit the result"
    assert "syntax keyword aidlCadPrimitive" in text and " Rectangle" in text
    assert "CenterInside" in text


EDITOR_PROBE = r"""
local out = {}
vim.cmd('edit cad.aidl')
local ok = vim.wait(60000, function() return #vim.lsp.buf_get_clients(0) > 0
  and vim.lsp.buf_get_clients(0)[1].initialized end, 50)
table.insert(out, 'attached=' .. tostring(ok))
-- the default maps and options, buffer-local
local k = vim.fn.maparg('K', 'n', false, true)
table.insert(out, 'K=' .. tostring(k.buffer) .. ',' .. (k.rhs or ''))
table.insert(out, 'omnifunc=' .. vim.bo.omnifunc)
table.insert(out, 'formatexpr=' .. vim.bo.formatexpr)
-- hover on `Circle` (line 3), drawn the way K draws it (Neovim 0.7's markdown): the code
-- fence must be understood, so no ``` line is left in the float
local params = vim.lsp.util.make_position_params()
params.position = { line = 2, character = 7 }
local res = vim.lsp.buf_request_sync(0, 'textDocument/hover', params, 30000)
local hover
for _, r in pairs(res or {}) do if r.result then hover = r.result end end
local lines = vim.lsp.util.convert_input_to_markdown_lines(hover.contents)
local buf = vim.api.nvim_create_buf(false, true)
vim.lsp.util.stylize_markdown(buf, lines, {})
local shown = vim.api.nvim_buf_get_lines(buf, 0, -1, false)
local fences = 0
for _, l in ipairs(shown) do if l:match('```') then fences = fences + 1 end end
table.insert(out, 'hover1=' .. shown[1])
table.insert(out, 'fences=' .. fences)
table.insert(out, 'fencesyntax=' .. vim.api.nvim_buf_call(buf, function()
  return vim.fn.synIDattr(vim.fn.synID(1, 1, 1), 'name') end))
-- gq formats the whole file through the server
vim.cmd('normal! gggqG')
table.insert(out, 'formatted=' .. table.concat(vim.api.nvim_buf_get_lines(0, 0, -1, false), '|'))
-- :AidlPreview starts `aidl serve` and opens the page with g:aidl_browser
vim.g.aidl_browser = vim.fn.getcwd() .. '/browser.sh'
vim.cmd('AidlPreview')
local got = vim.wait(60000, function() return vim.fn.filereadable('url.txt') == 1
  and #vim.fn.readfile('url.txt') > 0 end, 50)
table.insert(out, 'url=' .. (got and vim.fn.readfile('url.txt')[1] or 'none'))
table.insert(out, 'errmsg=' .. vim.v.errmsg)
vim.fn.writefile(out, 'out.tmp')
vim.loop.fs_rename('out.tmp', 'out.txt')
vim.wait(120000, function() return vim.fn.filereadable('quit') == 1 end, 50)
vim.cmd('qa!')
"""


def _nvim(tmp_path, probe: str, path: str, wait_for_url: bool = False):
    (tmp_path / "probe.lua").write_text(probe)
    env = {"PATH": path, "HOME": str(tmp_path)}
    args = [NVIM, "--headless", "-u", "NONE", "-i", "NONE", "--cmd", f"set rtp^={PLUGIN}",
            "-c", "filetype plugin on", "-c", "syntax on", "-c", "luafile probe.lua"]
    return subprocess.Popen(args, cwd=tmp_path, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True, env=env)


@pytest.mark.skipif(NVIM is None, reason="neovim is not installed (.ci/run installs it)")
def test_neovim_maps_hover_fence_formatexpr_and_preview(tmp_path):
    import urllib.request
    (tmp_path / ".git").mkdir()
    (tmp_path / "cad.aidl").write_text(
        "param w = 3 mm\nsolid plate {\n  c = Circle(center=(0,0),   radius=w)\n}\n")
    (tmp_path / "browser.sh").write_text('#!/bin/sh\necho "$1" > url.txt\n')
    (tmp_path / "browser.sh").chmod(0o755)
    import time
    p = _nvim(tmp_path, EDITOR_PROBE, f"{Path(sys.executable).parent}:/usr/bin:/bin")
    result = tmp_path / "out.txt"
    try:
        # the probe leaves nvim (and its `aidl serve` job) running: wait for its report, check
        # the page is served, then quit
        deadline = time.monotonic() + 150
        while not result.exists() and time.monotonic() < deadline and p.poll() is None:
            time.sleep(0.1)
        out = result.read_text() if result.exists() else p.communicate(timeout=10)[1]
        got = dict(line.split("=", 1) for line in out.split("\n") if "=" in line)
        assert got.get("attached") == "true", out
        assert got["K"].startswith("1,") and "hover" in got["K"]
        assert got["omnifunc"] == "v:lua.vim.lsp.omnifunc"
        assert got["formatexpr"] == "v:lua.require'aidl_cad'.formatexpr()"
        assert got["fences"] == "0", out                       # the fence was understood
        assert got["hover1"].startswith("Circle(")
        assert got["fencesyntax"] == "aidlCadPrimitive"         # and highlighted as aidl-cad
        assert got["formatted"] == "param w = 3 mm|solid plate {|    c = Circle(center=(0, 0), radius=w)|}"
        url = got["url"]
        assert url.startswith("http://127.0.0.1:"), out
        page = urllib.request.urlopen(url, timeout=30).read().decode()
        assert "<html" in page.lower()
        assert got["errmsg"] == ""
    finally:
        (tmp_path / "quit").write_text("")      # nvim quits, stopping its `aidl serve` job
        try:
            p.communicate(timeout=30)
        except subprocess.TimeoutExpired:
            p.kill()
            p.communicate()


@pytest.mark.skipif(NVIM is None, reason="neovim is not installed (.ci/run installs it)")
def test_neovim_without_aidl_says_so_in_one_line(tmp_path):
    (tmp_path / ".git").mkdir()
    (tmp_path / "cad.aidl").write_text("solid plate {\n    c = Circle(center=(0, 0), radius=3)\n}\n")
    probe = r"""
vim.cmd('edit cad.aidl')
vim.wait(300, function() return false end)
local msgs = vim.api.nvim_exec('messages', true)
io.stdout:write('ft=' .. vim.bo.filetype .. '\n')
io.stdout:write('errmsg=' .. vim.v.errmsg .. '\n')
io.stdout:write('messages=' .. msgs:gsub('\n', '|') .. '\n')
vim.cmd('AidlInfo')
io.stdout:write('info=' .. vim.api.nvim_exec('messages', true):gsub('\n', '|') .. '\n')
vim.cmd('qa!')
"""
    p = _nvim(tmp_path, probe, "/usr/bin:/bin")
    out, err = p.communicate(timeout=60)
    got = dict(line.split("=", 1) for line in out.split("\n") if "=" in line)
    assert got["ft"] == "aidl-cad"
    assert got["errmsg"] == "", out + err                 # a warning, not an error
    msgs = [m for m in got["messages"].split("|") if m]
    assert len(msgs) == 1 and msgs[0].startswith("aidl-cad: no `aidl` found"), msgs
    assert len(msgs[0]) < 80                              # fits the command line: no prompt
    assert "Error detected" not in out + err
    assert ".venv/bin/aidl" in got["info"] and "pip install" in got["info"]


@pytest.mark.skipif(NVIM is None, reason="neovim is not installed (.ci/run installs it)")
def test_neovim_root_and_server_walk_up_the_folders(tmp_path):
    """root_dir: the nearest folder holding .git; server_cmd: the nearest .venv/venv above the
    root, then above the file's folder, each folder tried once (aidl_cad.lua's walk_up)."""
    proj = tmp_path / "proj"
    (proj / "sub" / "deep").mkdir(parents=True)
    (proj / ".git").mkdir()
    (proj / "sub" / "deep" / "cad.aidl").write_text("units mm\n")
    probe = r"""
local m = require('aidl_cad')
vim.cmd('edit proj/sub/deep/cad.aidl')
local root = m.root_dir(0)
local cmd, tried = m.server_cmd(root, vim.fn.expand('%:p:h'))
io.stdout:write('root=' .. root .. '\n' .. 'cmd=' .. tostring(cmd) .. '\n'
  .. 'tried=' .. table.concat(tried, '|') .. '\n')
vim.cmd('qa!')
"""
    venv = tmp_path / "venv" / "bin"
    venv.mkdir(parents=True)
    (venv / "aidl").write_text("#!/bin/sh\n")
    (venv / "aidl").chmod(0o755)
    out, err = _nvim(tmp_path, probe, "/usr/bin:/bin").communicate(timeout=60)
    got = dict(line.split("=", 1) for line in out.split("\n") if "=" in line)
    assert got["root"] == str(proj), out + err
    assert got["cmd"] == str(venv / "aidl")
    assert got["tried"].split("|") == [f"{proj}/.venv/bin/aidl", f"{proj}/venv/bin/aidl",
                                       f"{tmp_path}/.venv/bin/aidl", f"{tmp_path}/venv/bin/aidl"]
    (venv / "aidl").unlink()                  # none: the file's folders are walked up to `proj` only
    out, err = _nvim(tmp_path, probe, "/usr/bin:/bin").communicate(timeout=60)
    got = dict(line.split("=", 1) for line in out.split("\n") if "=" in line)
    tried = got["tried"].split("|")
    assert got["cmd"] == "nil"
    assert tried.count(f"{proj}/.venv/bin/aidl") == 1
    # the root's walk went up to / first; the file's walk stops at `proj` (already tried)
    i = tried.index(f"{proj}/sub/deep/.venv/bin/aidl")
    assert i > tried.index(f"{tmp_path}/venv/bin/aidl")
    assert tried[i:i + 4] == [f"{proj}/sub/deep/.venv/bin/aidl", f"{proj}/sub/deep/venv/bin/aidl",
                              f"{proj}/sub/.venv/bin/aidl", f"{proj}/sub/venv/bin/aidl"]
    assert "/bin/aidl" not in tried[i + 4]
