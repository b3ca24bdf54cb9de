"""The interpreter's parts, assembled into one class by :mod:`aidl_lang.interp`:
:mod:`.statements`, :mod:`.calls`, :mod:`.expressions`, and :mod:`.common` (scopes, helpers)."""
