-- At start-up (Neovim 0.9+): the filetype `aidl-cad` mapped to the tree-sitter parser
-- `aidl_cad`, and, when nvim-treesitter is there, its parser entry for `:TSInstall aidl_cad`
-- (lua/aidl_cad/treesitter.lua). Nothing is loaded until an `aidl-cad` file is opened.
if vim.fn.has('nvim-0.9') == 0 then
  return
end
local ok, ts = pcall(require, 'aidl_cad.treesitter')
if ok then
  ts.register()
  ts.nvim_treesitter()
end
