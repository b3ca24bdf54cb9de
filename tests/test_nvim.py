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
