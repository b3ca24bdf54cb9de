"""What every stage reports with and is bounded by: :mod:`.diagnostics` (spans, diagnostics,
``EvalError``), :mod:`.codes` (the text of every diagnostic code), :mod:`.limits` (what one
program may build, the budget), :mod:`.records` (value records as plain classes with slots),
:mod:`.memory` (the garbage collector paused). Imports nothing of aidl_lang outside it.
"""
