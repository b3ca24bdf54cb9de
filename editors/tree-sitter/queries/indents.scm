; Indentation of AIDL (CAD) in nvim-treesitter's names (@indent.begin, @indent.branch,
; @indent.end, @indent.align, @indent.auto): what `aidl fmt` writes, 4 spaces a level inside
; { } and a continuation inside ( ) and [ ] lined up after the bracket when the first item is
; on the bracket's line, else one level in. (Helix's and Zed's names differ:
; editors/helix/queries/aidl-cad/indents.scm, editors/zed/languages/aidl-cad/indents.scm.)

(block) @indent.begin

(block
  "}" @indent.end)

((argument_list) @indent.align
  (#set! indent.open_delimiter "(")
  (#set! indent.close_delimiter ")"))

((parameters) @indent.align
  (#set! indent.open_delimiter "(")
  (#set! indent.close_delimiter ")"))

((tuple) @indent.align
  (#set! indent.open_delimiter "(")
  (#set! indent.close_delimiter ")"))

((parenthesized_expression) @indent.align
  (#set! indent.open_delimiter "(")
  (#set! indent.close_delimiter ")"))

((list) @indent.align
  (#set! indent.open_delimiter "[")
  (#set! indent.close_delimiter "]"))

((list_comprehension) @indent.align
  (#set! indent.open_delimiter "[")
  (#set! indent.close_delimiter "]"))

; a line that starts with a closing bracket goes back to its opening line's level
[
  "}"
  ")"
  "]"
] @indent.branch

; `} else {`, `} elif c {`
[
  (else_clause)
  (elif_clause)
] @indent.branch

; a comment's lines keep the indentation they have
(comment) @indent.auto

(string) @indent.auto
