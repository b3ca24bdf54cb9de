"""The standard library and the docs built from it: :mod:`.sources` (where ``std/`` imports and the
example programs come from), :mod:`.reference` (the topics of ``aidl docs``),
:mod:`.topic_examples` (each topic's example program), :mod:`.details` (what an entry's one-line doc leaves
out). Imports the parser, geometry and below,
never the checker or the interpreter.
"""
