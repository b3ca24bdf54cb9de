#!/usr/bin/env python3
"""Regenerate the highlighting files from the registry: ``python editors/gen_grammar.py``.

Writes ``editors/vscode/syntaxes/aidl.tmLanguage.json`` (the VS Code TextMate grammar),
``editors/nvim/syntax/aidl-cad.vim`` (Vim/Neovim), see :mod:`aidl_lang.editor.highlight`, and
``editors/codemirror/src/words.json`` (the word lists of the CodeMirror mode of ``aidl studio``,
bundled by ``editors/codemirror/build.mjs``: rebuild the bundle after it changes).
``--check`` writes nothing and exits 1 if a committed file is out of date.
"""
import json
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from aidl_lang.editor.highlight import PROSE_KW, tmlanguage_json, vim_syntax, vocabulary  # noqa: E402
from generated import write_or_check  # noqa: E402

TARGET = ROOT / "editors" / "vscode" / "syntaxes" / "aidl.tmLanguage.json"
VIM = ROOT / "editors" / "nvim" / "syntax" / "aidl-cad.vim"
CODEMIRROR = ROOT / "editors" / "codemirror" / "src" / "words.json"


def codemirror_words_json() -> str:
    """The word lists of :func:`aidl_lang.editor.highlight.vocabulary` by category (the same
    ones the TextMate grammar is made of), plus ``prose``: the words the `//`-comment rule does
    not count as prose (``highlight.PROSE_KW``). 1-space JSON, final newline."""
    words = {"generated": "by editors/gen_grammar.py from aidl_lang/registry.py and "
                          "grammar/aidl.lark: do not edit by hand"}
    words.update(vocabulary())
    words["prose"] = PROSE_KW.split("|")
    return json.dumps(words, indent=1, ensure_ascii=False) + "\n"


def main(argv) -> int:
    return write_or_check([(TARGET, tmlanguage_json()), (VIM, vim_syntax()),
                           (CODEMIRROR, codemirror_words_json())], argv, Path(__file__).name)


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
