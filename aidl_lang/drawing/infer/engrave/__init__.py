"""What is engraved on a part (``aidl import --infer``): :mod:`.text` (strokes that are a line
of the built-in font's text), :mod:`.engraving` (a part's texts, ticks and engraved shapes as
one ``drawing``) and :mod:`.labels` (where a text is placed from: the hole it names, else
the body's centre line or nearer edge)."""
