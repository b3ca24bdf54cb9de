; Indentation of AIDL (CAD) in Zed's names (@indent for the node, @end for the bracket that
; closes it): one level inside { }, ( ) and [ ]. (nvim-treesitter's names:
; editors/tree-sitter/queries/indents.scm.)
(_ "{" "}" @end) @indent
(_ "(" ")" @end) @indent
(_ "[" "]" @end) @indent
