"""Where programs come from: the standard library folder that ``import "std/NAME.aidl"``
resolves against (docs/language.md, "Imports")."""
from pathlib import Path

STDLIB = Path(__file__).resolve().parent.parent / "stdlib"
if not STDLIB.exists():
    STDLIB = Path(__file__).resolve().parent / "stdlib"
