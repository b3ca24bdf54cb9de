"""What the checks report as data and text: :mod:`.describe` (``aidl check --describe``),
:mod:`.inventory` (``aidl parts``). Imports the part and fabrication stages only.
"""
