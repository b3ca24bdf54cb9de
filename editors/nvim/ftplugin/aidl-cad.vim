" Filetype plugin for AIDL (CAD): the layout `aidl fmt` writes (4 spaces, no tabs), comments,
" `gf` on imports, and (Neovim 0.7+) the language server `aidl lsp` (lua/aidl_cad.lua).
" Set `let g:aidl_lsp = 0` to leave the server to your own configuration (e.g. nvim-lspconfig),
" `let g:aidl_server_path = '/path/to/.venv/bin/aidl'` to choose the server.
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

if has('nvim-0.7') && get(g:, 'aidl_lsp', 1)
  lua require('aidl_cad').start(0)
endif
