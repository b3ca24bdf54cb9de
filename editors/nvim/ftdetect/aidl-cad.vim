" Filetype detection for AIDL (CAD) files: `*.aidl` becomes `aidl-cad` only when the file looks
" like AIDL (CAD) -- a structure, param, def, units or a quoted import -- and not like Android's
" Interface Definition Language (package, interface, parcelable, a dotted import with `;`), which
" keeps Vim's and Neovim's own `aidl` filetype. Works in Vim 8+ and every Neovim.
" A new, empty .aidl file stays as the editor decides: `:set filetype=aidl-cad`, or put
" `# vim: ft=aidl-cad` in the file.

function! s:AidlCadDetect() abort
  let l:cad = 0
  for l:line in getline(1, min([line('$'), 200]))
    if l:line =~# '^\s*\(package\|interface\|parcelable\|oneway\)\>' || l:line =~# '^\s*import\s\+[A-Za-z_][A-Za-z0-9_.]*\s*;'
      return
    endif
    if l:line =~# '^\s*\(solid\|hole\|drawing\|assembly\)\s\+\h\w*\s*{' || l:line =~# '^\s*\(param\|units\)\s\+\h' || l:line =~# '^\s*def\s\+\h\w*\s*(' || l:line =~# '^\s*import\s\+"'
      let l:cad = 1
    endif
  endfor
  if l:cad
    if has('nvim-0.9')
      " the parser `aidl_cad` (when installed) loaded before any FileType handler runs, so one
      " that starts tree-sitter first (nvim-treesitter's) finds it (lua/aidl_cad/treesitter.lua)
      lua pcall(function() local ts = require('aidl_cad.treesitter'); ts.register(); ts.available() end)
    endif
    set filetype=aidl-cad
  endif
endfunction

augroup aidl_cad_ftdetect
  autocmd!
  autocmd BufRead,BufNewFile *.aidl call s:AidlCadDetect()
augroup END
