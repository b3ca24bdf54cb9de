-- The AIDL (CAD) language server for Neovim 0.7+: `require('aidl_cad').start(bufnr)` starts
-- `aidl lsp --stdio` for the buffer's project (the folder holding .git, else the current
-- directory) and attaches the buffer; ftplugin/aidl-cad.vim calls it for every `aidl-cad` buffer.
--
-- The server is found like Python tooling finds it: `vim.g.aidl_server_path`; else the
-- nearest .venv/bin/aidl or venv/bin/aidl in or above the project (then the file's folder);
-- else $VIRTUAL_ENV or $CONDA_PREFIX; else PATH. If none is there, one short warning line
-- (no hit-enter prompt); `:AidlInfo` lists every place tried.
--
-- On attach (unless `vim.g.aidl_lsp_keymaps = 0`), buffer-local: `K` hover, `gd` definition,
-- 'omnifunc' (<C-x><C-o> completion), 'formatexpr' (`gq` formats the whole file, as
-- `aidl fmt` does: the server formats whole documents). `:AidlPreview` runs `aidl serve` for
-- the buffer's file and opens the page in the browser (`vim.g.aidl_browser`, else
-- xdg-open/open).
local M = {}

local uv = vim.loop

local function is_dir(p)
  local st = uv.fs_stat(p)
  return st ~= nil and st.type == 'directory'
end

--- fn(dir) for dir and each folder above it, up to the root; the first non-nil result.
--- `seen` (optional, a set) skips the folders already walked and marks the new ones.
local function walk_up(dir, fn, seen)
  while dir and dir ~= '' and not (seen and seen[dir]) do
    if seen then
      seen[dir] = true
    end
    local got = fn(dir)
    if got ~= nil then
      return got
    end
    local parent = vim.fn.fnamemodify(dir, ':h')
    if parent == dir then
      return nil
    end
    dir = parent
  end
end

--- The project root of a buffer: the nearest folder above it holding .git, else the cwd.
function M.root_dir(bufnr)
  local name = vim.api.nvim_buf_get_name(bufnr)
  local dir = name ~= '' and vim.fn.fnamemodify(name, ':p:h') or vim.fn.getcwd()
  return walk_up(dir, function(d)
    return uv.fs_stat(d .. '/.git') and d or nil
  end) or vim.fn.getcwd()
end

--- The `aidl` command for a project root (and a file's folder), and the places looked at.
function M.server_cmd(root, file_dir)
  local tried = {}
  local function try(p)
    table.insert(tried, p)
    if vim.fn.executable(p) == 1 then
      return p
    end
  end
  local setting = vim.g.aidl_server_path
  if setting and setting ~= '' then
    local p = vim.fn.expand(setting)
    if not p:find('/') then
      local found = vim.fn.exepath(p)
      table.insert(tried, p .. ' on PATH')
      return found ~= '' and found or nil, tried
    end
    return try(p), tried
  end
  local seen = {}
  for _, start in ipairs({ root, file_dir }) do
    local p = walk_up(start, function(dir)
      return try(dir .. '/.venv/bin/aidl') or try(dir .. '/venv/bin/aidl')
    end, seen)
    if p then
      return p, tried
    end
  end
  for _, var in ipairs({ 'VIRTUAL_ENV', 'CONDA_PREFIX' }) do
    local prefix = vim.env[var]
    if prefix and prefix ~= '' then
      local p = try(prefix .. '/bin/aidl')
      if p then
        return p, tried
      end
    end
  end
  local found = vim.fn.exepath('aidl')
  table.insert(tried, 'aidl on PATH')
  if found ~= '' then
    return found, tried
  end
  return nil, tried
end

local clients = {}      -- Neovim 0.7: root -> client id
local warned = false
M.tried = {}            -- the places the last unsuccessful search looked at (:AidlInfo)

local function buf_dir(bufnr)
  local name = vim.api.nvim_buf_get_name(bufnr)
  return name ~= '' and vim.fn.fnamemodify(name, ':p:h') or nil
end

--- One warning line that fits the command line (no "Press ENTER" prompt), shown once.
local function warn_missing()
  if warned then
    return
  end
  warned = true
  local msg = 'aidl-cad: no `aidl` found; install it into .venv or set g:aidl_server_path (:AidlInfo)'
  local room = math.max(20, (vim.v.echospace or 80) - 1)
  if #msg > room then
    msg = msg:sub(1, room - 3) .. '...'
  end
  vim.schedule(function()
    vim.api.nvim_echo({ { msg, 'WarningMsg' } }, true, {})
  end)
end

--- Whole-document formatting for 'formatexpr' (`gq`): the server formats whole programs
--- (`aidl fmt`), so any range formats the file. Insert-mode wrapping keeps Vim's own.
function M.formatexpr()
  if vim.tbl_contains({ 'i', 'R', 'ic', 'ix' }, vim.fn.mode()) then
    return 1
  end
  local bufnr = vim.api.nvim_get_current_buf()
  local params = vim.lsp.util.make_formatting_params()
  local results = vim.lsp.buf_request_sync(bufnr, 'textDocument/formatting', params, 5000)
  for id, res in pairs(results or {}) do
    if res.result then
      local client = vim.lsp.get_client_by_id(id)
      vim.lsp.util.apply_text_edits(res.result, bufnr, client and client.offset_encoding or 'utf-16')
      return 0
    end
  end
  return 0
end

--- Buffer-local keymaps and options for an attached buffer.
function M.on_attach(client, bufnr)
  vim.api.nvim_buf_set_option(bufnr, 'omnifunc', 'v:lua.vim.lsp.omnifunc')
  vim.api.nvim_buf_set_option(bufnr, 'formatexpr', "v:lua.require'aidl_cad'.formatexpr()")
  if vim.g.aidl_lsp_keymaps == 0 then
    return
  end
  local opts = { noremap = true, silent = true }
  vim.api.nvim_buf_set_keymap(bufnr, 'n', 'K', '<cmd>lua vim.lsp.buf.hover()<CR>', opts)
  vim.api.nvim_buf_set_keymap(bufnr, 'n', 'gd', '<cmd>lua vim.lsp.buf.definition()<CR>', opts)
end

--- Start (or reuse) the server for the buffer's project and attach the buffer. Returns the
--- client id, or nil (with one warning line) when no server was found.
function M.start(bufnr)
  if bufnr == nil or bufnr == 0 then
    bufnr = vim.api.nvim_get_current_buf()
  end
  local root = M.root_dir(bufnr)
  local cmd, tried = M.server_cmd(root, buf_dir(bufnr))
  if not cmd then
    M.tried = tried
    warn_missing()
    return nil
  end
  M.cmd = cmd
  local config = { name = 'aidl', cmd = { cmd, 'lsp', '--stdio' }, root_dir = root,
                   on_attach = M.on_attach }
  if vim.lsp.start then                                  -- Neovim 0.8+
    return vim.lsp.start(config, { bufnr = bufnr })
  end
  local id = clients[root]                               -- Neovim 0.7
  if not id or not vim.lsp.get_client_by_id(id) then
    id = vim.lsp.start_client(config)
    clients[root] = id
  end
  if id then
    vim.lsp.buf_attach_client(bufnr, id)
  end
  return id
end

--- :AidlInfo: the server in use, or every place looked at.
function M.info()
  local lines
  if M.cmd then
    lines = { 'aidl-cad: server ' .. M.cmd .. ' lsp --stdio' }
  else
    lines = { 'aidl-cad: no `aidl` command found. Looked at:' }
    for _, p in ipairs(M.tried) do
      table.insert(lines, '  ' .. p)
    end
    table.insert(lines, 'Install it: python3 -m venv .venv && .venv/bin/pip install -e /path/to/aidl,')
    table.insert(lines, 'or :let g:aidl_server_path = "/path/to/aidl"; then :edit the file again.')
  end
  vim.api.nvim_echo({ { table.concat(lines, '\n') } }, true, {})
end

local previews = {}     -- file -> { job = id, url = string }

local function open_url(url)
  local browser = vim.g.aidl_browser
  local cmd
  if browser and browser ~= '' then
    cmd = { browser, url }
  elseif vim.fn.has('mac') == 1 then
    cmd = { 'open', url }
  elseif vim.fn.has('win32') == 1 then
    cmd = { 'cmd.exe', '/c', 'start', '', url }
  else
    cmd = { 'xdg-open', url }
  end
  if vim.fn.jobstart(cmd, { detach = true }) <= 0 then
    vim.api.nvim_echo({ { 'aidl-cad: preview at ' .. url .. ' (could not start ' .. cmd[1] .. ')', 'WarningMsg' } }, true, {})
  end
end

--- :AidlPreview: `aidl serve FILE --port 0` for the buffer (saved first if modified: the
--- page follows the file on each save) and the page opened in the browser; again on the same
--- file just opens the page.
function M.preview(bufnr)
  bufnr = (bufnr == nil or bufnr == 0) and vim.api.nvim_get_current_buf() or bufnr
  local file = vim.api.nvim_buf_get_name(bufnr)
  if file == '' then
    vim.api.nvim_echo({ { 'aidl-cad: save the buffer to a .aidl file first', 'WarningMsg' } }, true, {})
    return
  end
  file = vim.fn.fnamemodify(file, ':p')
  if vim.api.nvim_buf_get_option(bufnr, 'modified') then
    vim.api.nvim_buf_call(bufnr, function() vim.cmd('silent write') end)
  end
  local p = previews[file]
  if p and p.url then
    open_url(p.url)
    return p.url
  end
  local cmd = M.cmd or M.server_cmd(M.root_dir(bufnr), buf_dir(bufnr))
  if not cmd then
    M.tried = select(2, M.server_cmd(M.root_dir(bufnr), buf_dir(bufnr)))
    warned = false
    warn_missing()
    return
  end
  p = { err = {} }
  previews[file] = p
  p.job = vim.fn.jobstart({ cmd, 'serve', file, '--port', '0' }, {
    cwd = vim.fn.fnamemodify(file, ':h'),
    on_stdout = function(_, data)
      for _, line in ipairs(data or {}) do
        local url = line:match('(http://127%.0%.0%.1:%d+/)')
        if url and not p.url then
          p.url = url
          open_url(url)
        end
      end
    end,
    on_stderr = function(_, data)
      for _, line in ipairs(data or {}) do
        if line ~= '' then table.insert(p.err, line) end
      end
    end,
    on_exit = function(_, code)
      previews[file] = nil
      if code ~= 0 and not p.url then
        vim.schedule(function()
          vim.api.nvim_echo({ { 'aidl-cad: aidl serve stopped: ' .. (p.err[1] or ('exit ' .. code)), 'WarningMsg' } }, true, {})
        end)
      end
    end,
  })
  return p.job
end

--- :AidlPreviewStop: stop the buffer's `aidl serve`.
function M.preview_stop(bufnr)
  bufnr = (bufnr == nil or bufnr == 0) and vim.api.nvim_get_current_buf() or bufnr
  local file = vim.fn.fnamemodify(vim.api.nvim_buf_get_name(bufnr), ':p')
  local p = previews[file]
  if p and p.job then
    vim.fn.jobstop(p.job)
  end
  previews[file] = nil
end

M.previews = previews

return M
