"""Parse AIDL source text into the typed AST of :mod:`aidl_lang.ast` (the design card's entry).

Lark LALR(1) over ``grammar/aidl.lark``, a post-lexer that drops newlines inside brackets and
before ``else``, and statement-level error recovery: each syntax error becomes an ``E0001``
diagnostic listing the expected tokens, the offending logical line is blanked (its braces kept)
and the file is parsed again, so one run reports several errors.

This module holds the public names; how it is done lives in :mod:`aidl_lang.parsing`, one room
per idea (tokens, tables, lexing, the LALR loop and AST building, comments, error reports,
bracket diagnostics, recovery, the whole-file entry): see that package's text for the map.
"""
from __future__ import annotations

from .parsing.comments import mask_comments
from .parsing.lalr import parse_expression
from .parsing.program import IMPORTS_KEPT, IMPORTS_KEPT_CHARS, parse, parse_import
from .parsing.tokens import (GRAMMAR, MAX_ERRORS, MAX_NESTING, TOKEN_NAMES, UNIT_RE, ParseError,
                             Token, UnexpectedCharacters, UnexpectedToken, parse_number)

__all__ = ["GRAMMAR", "IMPORTS_KEPT", "IMPORTS_KEPT_CHARS", "MAX_ERRORS", "MAX_NESTING",
           "TOKEN_NAMES", "UNIT_RE", "ParseError", "Token", "UnexpectedCharacters",
           "UnexpectedToken", "mask_comments", "parse", "parse_expression", "parse_import",
           "parse_number"]
