"""``python -m aidl_lang.cli``: the same as the ``aidl`` command."""
import sys

from .main import main

sys.exit(main())
