" `aidl_cad`: the name the language server's hovers give their code blocks (```aidl_cad: a
" fence language must be letters, digits and `_` for Neovim 0.7's markdown), highlighted as
" `aidl-cad` (syntax/aidl-cad.vim, generated).
runtime! syntax/aidl-cad.vim
