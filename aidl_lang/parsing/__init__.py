"""The parser's rooms: AIDL source text to the typed AST of :mod:`aidl_lang.ast`.
:mod:`aidl_lang.parser` is the entry every other stage imports (its public names); this package
holds how it is done, one idea a module, each importing only those above it in this list:

- :mod:`.tokens`: the limits, the grammar file, the token type and the syntax errors raised;
- :mod:`.tables`: Lark's LALR(1) table and basic lexer as plain data, built with Lark and cached
  as JSON (the only module that imports Lark, and only on a cache miss);
- :mod:`.lexing`: the lexer (one loop with a first-character dispatch) and the post-lexer;
- :mod:`.lalr`: the LALR loop and the AST nodes built inside its reductions;
- :mod:`.comments`: ``//`` as a comment or floor division, before the parse;
- :mod:`.errors`: the E0001/E0002/E0116 reports with what was expected and a hint;
- :mod:`.brackets`: where unbalanced brackets went wrong (issue 28);
- :mod:`.recovery`: statement-level error recovery (blank the line, parse again; then by
  top-level pieces);
- :mod:`.program`: :func:`~.program.parse` and :func:`~.program.parse_import`, tying them
  together.

The import-linter contract in pyproject.toml holds this order.  Speed notes: docs/dev/performance.md
"The parser"; tests/test_parse_table.py checks the result against Lark's own parser.
"""
