#!/usr/bin/env python3
"""Regenerate the highlighting files from the registry: ``python editors/gen_grammar.py``.

Writes ``editors/vscode/syntaxes/aidl.tmLanguage.json`` (the VS Code TextMate grammar) and
``editors/nvim/syntax/aidl-cad.vim`` (Vim/Neovim), see :mod:`aidl_lang.editor.highlight`.
``--check`` writes nothing and exits 1 if a committed file is out of date.
"""
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from aidl_lang.editor.highlight import tmlanguage_json, vim_syntax  # noqa: E402
from generated import write_or_check  # noqa: E402

TARGET = ROOT / "editors" / "vscode" / "syntaxes" / "aidl.tmLanguage.json"
VIM = ROOT / "editors" / "nvim" / "syntax" / "aidl-cad.vim"


def main(argv) -> int:
    return write_or_check([(TARGET, tmlanguage_json()), (VIM, vim_syntax())], argv, Path(__file__).name)


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
