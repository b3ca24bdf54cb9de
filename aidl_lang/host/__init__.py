"""The machine the compiler runs on: :mod:`.cache` (the user's owner-only cache folder),
:mod:`.files` (a file opened once, without following a link it did not check), :mod:`.workers`
(warm worker processes with a time limit and a memory cap). Imports only :mod:`aidl_lang.base`.
"""
