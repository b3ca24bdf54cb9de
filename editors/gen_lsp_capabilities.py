#!/usr/bin/env python3
"""Regenerate ``aidl_lang/editor/lsp/_capabilities.py`` (the ``initialize`` answer that
``aidl lsp`` sends before pygls is loaded, see :mod:`aidl_lang.editor.lsp.boot`) from the
pygls server: ``python editors/gen_lsp_capabilities.py`` after adding or changing a server
feature.  ``--check`` writes nothing and exits 1 if the committed file is out of date.
"""
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from aidl_lang.editor.lsp.boot import capabilities_module  # noqa: E402
from generated import write_or_check  # noqa: E402

TARGET = ROOT / "aidl_lang" / "editor" / "lsp" / "_capabilities.py"


def main(argv) -> int:
    return write_or_check([(TARGET, capabilities_module())], argv, Path(__file__).name)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
