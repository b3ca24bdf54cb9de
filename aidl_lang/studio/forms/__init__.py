"""The studio's forms: the gallery's ``.aidl`` programs whose params' ranges follow each other
(docs/studio.md, "Forms that cannot fail"; read by :mod:`aidl_lang.studio.gallery`) and
:mod:`.choices`, the values a form's text param takes (the page's list)."""
