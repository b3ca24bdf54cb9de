#!/usr/bin/env python3
"""Regenerate ``docs/codes.md`` (every diagnostic code and its explanation, the page the
language server's ``codeDescription.href`` links to) from ``aidl_lang/base/codes.py``:
``python editors/gen_codes_doc.py``; ``--check`` writes nothing and exits 1 if it is stale.
"""
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from aidl_lang.base.codes import codes_markdown  # noqa: E402
from generated import write_or_check  # noqa: E402

TARGET = ROOT / "docs" / "codes.md"


def main(argv) -> int:
    return write_or_check([(TARGET, codes_markdown())], argv, Path(__file__).name)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
