"""A Pygments lexer for AIDL (``.aidl``), registered as the ``pygments.lexers`` entry point
``aidl`` (aliases ``aidl-cad``, ``aidl``), so Sphinx, MkDocs, ``pygmentize`` and Markdown
renderers built on Pygments highlight AIDL code blocks.

Its word lists (keywords, structure kinds, primitives, constraints and synonyms, functions,
constants, units) are read from :mod:`aidl_lang.highlight` -- i.e. from the registry -- when this
module is imported, so the lexer never drifts from the language.  Note that ``.aidl`` is also
Android's Interface Definition Language: Pygments picks this lexer for ``*.aidl`` only by name.
"""
from __future__ import annotations

import re

from pygments.lexer import RegexLexer, bygroups, include, words
from pygments.token import (Comment, Error, Keyword, Name, Number, Operator, Punctuation,
                            String, Text, Whitespace)

from .highlight import PROSE_KW, vocabulary

_V = vocabulary()
_UNITS = "|".join(re.escape(u) for u in _V["units"])
_NOT_KW = r"(?!(?:" + PROSE_KW + r")\b)"

__all__ = ["AidlLexer"]


class AidlLexer(RegexLexer):
    """Lexer for AIDL, the solver-aided 2D CAD language."""

    name = "AIDL"
    aliases = ["aidl-cad", "aidl"]
    filenames = []               # `.aidl` is also Android IDL: choose this lexer by name
    mimetypes = ["text/x-aidl-cad"]
    url = "https://arxiv.org/abs/2502.09819"
    flags = re.MULTILINE

    tokens = {
        "root": [
            (r"^([ \t]*)(//.*?)$", bygroups(Whitespace, Comment.Single)),
            (r"\n", Whitespace),
            (r"[ \t\f\r]+", Whitespace),
            include("comments"),
            (r"(" + "|".join(_V["structure_kinds"]) + r")(\s+)([A-Za-z_]\w*)",
             bygroups(Keyword.Declaration, Whitespace, Name.Class)),
            (r"(def)(\s+)([A-Za-z_]\w*)", bygroups(Keyword.Declaration, Whitespace, Name.Function)),
            (r"(param)(\s+)([A-Za-z_]\w*)", bygroups(Keyword.Declaration, Whitespace, Name.Constant)),
            include("expression"),
        ],
        "comments": [
            (r"/\*[\s\S]*?\*/", Comment.Multiline),
            (r"#.*?$", Comment.Single),
            (r"//(?=[ \t]*$).*?$", Comment.Single),
            (r"//(?=[^#\n]*?\b" + _NOT_KW + r"[A-Za-z_]\w*[ \t]+" + _NOT_KW + r"[A-Za-z_]).*?$",
             Comment.Single),
            (r"//(?=[^#\n]*?[^\w\s.()\[\]+\-*/%,<>=!#]).*?$", Comment.Single),
        ],
        "expression": [
            (r"[ \t\f\r]+", Whitespace),
            (r'[fF]"', String.Double, "fdq"),
            (r"[fF]'", String.Single, "fsq"),
            (r'"(\\\\|\\[^\\]|[^"\\\n])*"', String.Double),
            (r"'(\\\\|\\[^\\]|[^'\\\n])*'", String.Single),
            (r"((?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)([ \t]*)(" + _UNITS + r")\b",
             bygroups(Number.Float, Whitespace, Keyword.Type)),
            (r"((?:\d+\.?\d*|\.\d+)(?:[eE][+-]?\d+)?)(°)", bygroups(Number.Float, Keyword.Type)),
            (r"(?:\d+\.\d*|\.\d+)(?:[eE][+-]?\d+)?|\d+[eE][+-]?\d+", Number.Float),
            (r"\d+", Number.Integer),
            (words(_V["structure_kinds"], suffix=r"\b"), Keyword.Declaration),
            (words(_V["control"] + _V["declaration"], suffix=r"\b"), Keyword),
            (words(_V["logical"], suffix=r"\b"), Operator.Word),
            (words(_V["self"], suffix=r"\b"), Name.Builtin.Pseudo),
            (words(_V["constants"], suffix=r"\b"), Keyword.Constant),
            (words(_V["primitives"], suffix=r"\b"), Name.Class),
            (words(_V["constraints"], suffix=r"\b"), Name.Builtin),
            (words(_V["functions"], suffix=r"\b"), Name.Builtin),
            (r"[A-Za-z_]\w*", Name),
            (r"->|\*\*|==|!=|<=|>=|//|[-+*/%<>=]", Operator),
            (r"[{}()\[\],.;:]", Punctuation),
            (r"\\\n", Text),
        ],
        "fdq": [
            (r"\{\{|\}\}", String.Escape),
            (r"\{", String.Interpol, "interp"),
            (r"\\.", String.Escape),
            (r'"', String.Double, "#pop"),
            (r"\n", Error, "#pop"),
            (r'[^"{}\\\n]+', String.Double),
            (r"\}", String.Double),
        ],
        "fsq": [
            (r"\{\{|\}\}", String.Escape),
            (r"\{", String.Interpol, "interp"),
            (r"\\.", String.Escape),
            (r"'", String.Single, "#pop"),
            (r"\n", Error, "#pop"),
            (r"[^'{}\\\n]+", String.Single),
            (r"\}", String.Single),
        ],
        "interp": [
            (r"(:[^}\"'\n]*)?\}", String.Interpol, "#pop"),
            include("expression"),
        ],
    }
