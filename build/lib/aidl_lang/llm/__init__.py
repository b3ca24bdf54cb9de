"""LLM tooling: the system prompt (:mod:`.prompt`), an OpenAI-compatible chat client
(:mod:`.client`), the validate-until-correct loop (:mod:`.generate`) and the eval harness
(:mod:`.evaluate`).  Independent of :mod:`aidl_lang.editor` (the contract in ``pyproject.toml``).
"""
