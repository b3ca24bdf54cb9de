; AIDL needs no injections: it embeds no other language. Its f-strings hold AIDL
; expressions, which the grammar parses itself (`interpolation` nodes), and its comments
; and strings are plain text.
