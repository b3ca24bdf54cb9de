#!/usr/bin/env python3
"""Regenerate the VS Code TextMate grammar from the registry: ``python editors/gen_grammar.py``.

Writes ``editors/vscode/syntaxes/aidl.tmLanguage.json`` (see :mod:`aidl_lang.editor.highlight`).
``--check`` writes nothing and exits 1 if the committed file is out of date.
"""
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from aidl_lang.editor.highlight import tmlanguage_json  # noqa: E402

TARGET = ROOT / "editors" / "vscode" / "syntaxes" / "aidl.tmLanguage.json"


def main(argv) -> int:
    text = tmlanguage_json()
    old = TARGET.read_text(encoding="utf-8") if TARGET.exists() else None
    if "--check" in argv:
        if old != text:
            print(f"{TARGET.relative_to(ROOT)} is out of date: run python editors/gen_grammar.py")
            return 1
        return 0
    if old != text:
        TARGET.write_text(text, encoding="utf-8")
        print(f"wrote {TARGET.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
