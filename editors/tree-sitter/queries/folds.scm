; Folds of AIDL (CAD): a structure's, template's, loop's or branch's block, a call, list or
; parameter list written over several lines, and a block comment (`/* ... */`). Captured as
; @fold (Neovim's vim.treesitter.foldexpr and nvim-treesitter; the plugin in editors/nvim
; folds by it on Neovim 0.7 too). A region that starts and ends on one line folds nothing.

[
  (block)
  (parameters)
  (argument_list)
  (list)
  (list_comprehension)
  (tuple)
  (comment)
] @fold
