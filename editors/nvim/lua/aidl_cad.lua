-- The AIDL (CAD) language server for Neovim 0.7+: `require('aidl_cad').start(bufnr)` starts
-- `aidl lsp --stdio` for the buffer's project (the folder holding .git, else the current
-- directory) and attaches the buffer; ftplugin/aidl-cad.vim calls it for every `aidl-cad` buffer.
--
-- The server is found like Python tooling finds it: `vim.g.aidl_server_path`; else the
-- project's .venv/bin/aidl or venv/bin/aidl; else $VIRTUAL_ENV or $CONDA_PREFIX; else PATH.
-- If none is there, one message names every place tried.
local M = {}

local uv = vim.loop

local function is_dir(p)
  local st = uv.fs_stat(p)
  return st ~= nil and st.type == 'directory'
end

--- The project root of a buffer: the nearest folder above it holding .git, else the cwd.
function M.root_dir(bufnr)
  local name = vim.api.nvim_buf_get_name(bufnr)
  local dir = name ~= '' and vim.fn.fnamemodify(name, ':p:h') or vim.fn.getcwd()
  while dir and dir ~= '' do
    if uv.fs_stat(dir .. '/.git') then
      return dir
    end
    local parent = vim.fn.fnamemodify(dir, ':h')
    if parent == dir then
      break
    end
    dir = parent
  end
  return vim.fn.getcwd()
end

--- The `aidl` command for a project root, and the list of places looked at.
function M.server_cmd(root)
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
  for _, venv in ipairs({ '.venv', 'venv' }) do
    local p = try(root .. '/' .. venv .. '/bin/aidl')
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

--- Start (or reuse) the server for the buffer's project and attach the buffer. Returns the
--- client id, or nil (with one message) when no server was found.
function M.start(bufnr)
  if bufnr == nil or bufnr == 0 then
    bufnr = vim.api.nvim_get_current_buf()
  end
  local root = M.root_dir(bufnr)
  local cmd, tried = M.server_cmd(root)
  if not cmd then
    if not warned then
      warned = true
      vim.notify('aidl-cad: no `aidl` command for the language server; looked at: '
        .. table.concat(tried, ', ')
        .. '. Install it into the project (python3 -m venv .venv && .venv/bin/pip install -e ...)'
        .. ' or set vim.g.aidl_server_path.', vim.log.levels.ERROR)
    end
    return nil
  end
  local config = { name = 'aidl', cmd = { cmd, 'lsp', '--stdio' }, root_dir = root }
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

return M
