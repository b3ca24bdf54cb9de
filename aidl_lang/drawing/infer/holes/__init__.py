"""The holes makers draw (``aidl import --infer``): :mod:`.features` recognises arc slots,
keyholes, D-holes and notches of any shape in a side; :mod:`.bores` double-D holes and
keyways; :mod:`.makers` writes them with their size params; :mod:`.sinks` writes the
countersink and counterbore marks with the holes they are on."""
