"""The parser's vocabulary: its limits, the grammar file, the token type and the syntax
errors raised while parsing; also :func:`parse_number` (a number literal with its unit).
Imports nothing of the package."""
from __future__ import annotations

import re
from functools import partial
from pathlib import Path

from ..base.diagnostics import Span

# a Span from a 7-tuple in one C call (no Python __init__): tokens and reduction extents
_new_span = partial(tuple.__new__, Span)

# the package's own grammar (a link to the repository's ``grammar/`` in a checkout), never a
# ``grammar`` folder beside the installed package
GRAMMAR = (Path(__file__).resolve().parent.parent / "grammar" / "aidl.lark").resolve()

MAX_ERRORS = 20
MAX_NESTING = 64           # brackets nested deeper than this are refused (E0003)
MAX_BRACKET_DECISIONS = 64  # closers weighed by look-ahead when locating a bracket problem

UNIT_RE = re.compile(r"^(?P<num>(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?)[ \t]*(?P<unit>[a-z°]+)?$")

TOKEN_NAMES = {
    "_NL": "newline", "LPAR": "`(`", "RPAR": "`)`", "LSQB": "`[`", "RSQB": "`]`",
    "LBRACE": "`{`", "RBRACE": "`}`", "COMMA": "`,`", "EQUAL": "`=`", "COLON": "`:`",
    "SEMICOLON": "`;`", "DOT": "`.`", "NAME": "a name", "NUMBER": "a number",
    "STRING": "a string", "FSTRING": "an f-string", "COMP_OP": "a comparison",
    "ADD_OP": "`+` or `-`", "MUL_OP": "`*` or `/`", "MINUS": "`-`", "PLUS": "`+`",
    "__ANON_0": "`->`", "RARROW": "`->`", "$END": "end of file",
}


class Token(str):
    """A token from the lexer: its text (the ``str`` value), ``type`` (the terminal's name) and
    ``pos``, its :class:`Span` (lines and columns 1-based, offsets 0-based; the program's path
    as ``file``), also readable by the names of Lark's ``Token`` fields."""

    def __new__(cls, type, value, start_pos=None, line=None, column=None, end_line=None,
                end_column=None, end_pos=None, file=""):
        t = str.__new__(cls, value)
        t.type = type
        t.pos = _new_span((file, line, column, end_line, end_column, start_pos, end_pos))
        return t

    line = property(lambda self: self.pos[1])
    column = property(lambda self: self.pos[2])
    end_line = property(lambda self: self.pos[3])
    end_column = property(lambda self: self.pos[4])
    start_pos = property(lambda self: self.pos[5])
    end_pos = property(lambda self: self.pos[6])

    @property
    def value(self) -> str:
        return str(self)

    @classmethod
    def new_borrow_pos(cls, type_: str, value, borrow: "Token") -> "Token":
        """A token of another type and text at ``borrow``'s place."""
        t = str.__new__(cls, value)
        t.type = type_
        t.pos = borrow.pos
        return t


class ParseError(Exception):
    """A syntax error found by the lexer or the LALR table (reported as E0001 / E0002)."""


class UnexpectedToken(ParseError):
    """The LALR table has no action for ``token`` here; ``expected`` holds the terminal names
    that would have been accepted."""

    def __init__(self, token: Token, expected: set):
        super().__init__(f"unexpected {token.type} {str(token)!r}")
        self.token, self.expected = token, expected
        self.pos_in_stream = token.start_pos


class UnexpectedCharacters(ParseError):
    """No terminal of the grammar matches the text at offset ``pos_in_stream``."""

    def __init__(self, text: str, pos: int, line: int, column: int):
        super().__init__(f"no terminal matches at line {line}, column {column}")
        self.pos_in_stream, self.line, self.column = pos, line, column


class _BuildError(ParseError):
    """A reduction could not build its node (an f-string whose expression does not parse)."""


def parse_number(text: str) -> tuple[float, str | None]:
    m = UNIT_RE.match(text.strip())
    if not m:
        return float(text), None
    unit = m.group("unit")
    if unit == "°":
        unit = "deg"
    return float(m.group("num")), unit
