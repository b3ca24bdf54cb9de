"""The AIDL language server (``aidl lsp``): :mod:`.analysis` (pure functions) and :mod:`.server`
(pygls handlers)."""
