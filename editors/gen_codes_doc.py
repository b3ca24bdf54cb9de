#!/usr/bin/env python3
"""Regenerate ``docs/codes.md`` (every diagnostic code and its explanation, the page the
language server's ``codeDescription.href`` links to) from ``aidl_lang/codes.py``:
``python editors/gen_codes_doc.py``; ``--check`` writes nothing and exits 1 if it is stale.
"""
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from aidl_lang.codes import codes_markdown  # noqa: E402

TARGET = ROOT / "docs" / "codes.md"


def main(argv) -> int:
    text = codes_markdown()
    old = TARGET.read_text(encoding="utf-8") if TARGET.exists() else None
    if old == text:
        return 0
    if "--check" in argv:
        print(f"{TARGET.relative_to(ROOT)} is out of date: run python editors/gen_codes_doc.py")
        return 1
    TARGET.write_text(text, encoding="utf-8")
    print(f"wrote {TARGET.relative_to(ROOT)}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
