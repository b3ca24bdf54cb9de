"""The ``main`` the ``editors/gen_*.py`` scripts share: write each generated file whose
committed text differs from what the code makes now, or, with ``--check``, write nothing and
exit 1 naming the stale files.
"""
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def write_or_check(targets, argv, script: str) -> int:
    """``targets``: ``(path, text)`` pairs; ``argv``: the script's arguments (``--check`` or
    none); ``script``: its name, for the message. Returns the exit status (0, or 1 when
    ``--check`` found a stale file)."""
    stale = 0
    for target, text in targets:
        old = target.read_text(encoding="utf-8") if target.exists() else None
        if old == text:
            continue
        if "--check" in argv:
            print(f"{target.relative_to(ROOT)} is out of date: run python editors/{script}")
            stale = 1
        else:
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_text(text, encoding="utf-8")
            print(f"wrote {target.relative_to(ROOT)}")
    return stale
