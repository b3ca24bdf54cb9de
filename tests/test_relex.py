"""The recovery's lexing after a blanked line (aidl_lang/parsing/lexing.py `relex_blanked`):
the token lists must be exactly those of lexing the blanked text whole, for every program the
project holds and lines blanked anywhere (the recovery blanks the logical line of each syntax
error and parses again; lexing only from that line to where the old tokens resume halved a
broken file's parse: a deleted brace in stdlib/boxes.aidl, 0.22 -> 0.11 s)."""
from __future__ import annotations

import random
from pathlib import Path

import pytest

from aidl_lang.parsing.lexing import _lex_lists, relex_blanked
from aidl_lang.parsing.recovery import _blank_range

ROOT = Path(__file__).resolve().parent.parent
FILES = sorted({p for d in ("examples", "stdlib", "tests/programs", "docs/figures")
                for p in (ROOT / d).rglob("*.aidl")})


def _same(a, b) -> bool:
    return a[0] == b[0] and list(a[1]) == list(b[1]) and (a[2] is None) == (b[2] is None)


@pytest.mark.parametrize("path", FILES[::3], ids=lambda p: str(p.relative_to(ROOT)))
def test_relexing_a_blanked_line_gives_the_tokens_of_the_whole_text(path):
    text = path.read_text(encoding="utf-8").replace("\r\n", "\n")
    rng = random.Random(str(path.relative_to(ROOT)))
    lexed = _lex_lists(text, False, "f.aidl")
    for _ in range(6):               # blank after blank, as the recovery does
        if len(text) < 2:
            break
        pos = rng.randrange(len(text) - 1)
        start, end, seg = _blank_range(text, pos)
        new = text[:start] + seg + text[end:]
        got = relex_blanked(new, lexed, start, end, "f.aidl")
        want = _lex_lists(new, False, "f.aidl")
        assert _same(got, want), (path.name, pos, start, end)
        text, lexed = new, got


@pytest.mark.parametrize("text", [
    "a = 1\n/* a block\ncomment */ b = 2\nc = 3\n",
    'x = "a string"\ny = [1,\n  2, 3]\nz = 4 # note\n\n\nw = 5\n',
    "solid s {\n    r = Rectangle(center=(0, 0), width=10, height=1e3)\n}\n",
])
def test_every_line_blanked_in_turn(text):
    lexed0 = _lex_lists(text, False, "f.aidl")
    for pos in range(len(text) - 1):
        start, end, seg = _blank_range(text, pos)
        new = text[:start] + seg + text[end:]
        assert _same(relex_blanked(new, lexed0, start, end, "f.aidl"),
                     _lex_lists(new, False, "f.aidl")), (pos, new)
