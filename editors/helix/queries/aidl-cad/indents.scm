; Indentation of AIDL (CAD) in Helix's names (@indent, @outdent): 4 spaces a level inside
; { }, one level inside ( ) and [ ] written over several lines; a line that starts with a
; closing bracket goes back one level. (nvim-treesitter's names:
; editors/tree-sitter/queries/indents.scm.)

[
  (block)
  (argument_list)
  (parameters)
  (tuple)
  (parenthesized_expression)
  (list)
  (list_comprehension)
] @indent

[
  "}"
  ")"
  "]"
] @outdent
