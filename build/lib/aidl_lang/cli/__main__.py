"""``python -m aidl_lang.cli``: the same as the ``aidl`` command."""
from .main import entry

entry()
