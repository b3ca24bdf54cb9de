"""``python -m aidl_lang``: the same as the ``aidl`` command (and ``python -m aidl_lang.cli``)."""
from .cli.main import entry

entry()
