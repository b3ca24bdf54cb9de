"""Editor tooling: the language server (:mod:`.lsp`), the formatter (:mod:`.fmt`) and the
highlighters generated from the registry (:mod:`.highlight`, :mod:`.pygments_lexer`).
Independent of :mod:`aidl_lang.llm` (the contract in ``pyproject.toml``).
"""
