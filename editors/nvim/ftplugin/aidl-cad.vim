" Filetype plugin for AIDL (CAD): the layout `aidl fmt` writes (4 spaces, no tabs), comments,
" `gf` on imports, and (Neovim 0.7+) the language server `aidl lsp` (lua/aidl_cad.lua) with
" buffer-local `K` (hover), `gd` (definition), 'omnifunc' (<C-x><C-o>) and 'formatexpr' (`gq`).
" Commands: :AidlPreview (live preview in the browser, `aidl serve`), :AidlPreviewStop,
" :AidlInfo (which `aidl` is used, or where it was looked for).
" Set `let g:aidl_lsp = 0` to leave the server to your own configuration (e.g. nvim-lspconfig),
" `let g:aidl_lsp_keymaps = 0` to keep your own maps, `let g:aidl_server_path =
" '/path/to/.venv/bin/aidl'` to choose the server, `let g:aidl_browser = 'firefox'` the browser.
" Tree-sitter (lua/aidl_cad/treesitter.lua): when the parser `aidl_cad` is installed
" (parser/aidl_cad.so on 'runtimepath', docs/editors.md), it colours the buffer instead of the
" syntax file (`let g:aidl_treesitter = 0` keeps the syntax file) and, with
" `let g:aidl_treesitter_folds = 1`, folds it by the queries in queries/aidl_cad/folds.scm.
if exists('b:did_ftplugin')
  finish
endif
let b:did_ftplugin = 1

setlocal expandtab shiftwidth=4 softtabstop=4
setlocal commentstring=#\ %s
setlocal comments=:#,://
setlocal suffixesadd=.aidl
let b:undo_ftplugin = 'setlocal expandtab< shiftwidth< softtabstop< commentstring< comments< suffixesadd<'

if has('nvim-0.9')
  " the server's semantic token modifier for units (`10 mm`, `30 deg`)
  highlight default link @lsp.mod.unit Special
endif

if has('nvim-0.7')
  if get(g:, 'aidl_treesitter', 1)
    lua require('aidl_cad.treesitter').start(0)
  endif
  command! -buffer AidlPreview lua require('aidl_cad').preview(0)
  command! -buffer AidlPreviewStop lua require('aidl_cad').preview_stop(0)
  command! -buffer AidlInfo lua require('aidl_cad').info()
  if get(g:, 'aidl_lsp', 1)
    lua require('aidl_cad').start(0)
  endif
endif
