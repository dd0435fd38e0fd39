-- Pandoc filter for the reproduction report.
--
-- ```{.tsv file="core_weights.tsv" columns="name:weight,norm,order_k:k" caption="..."}
-- ```
-- becomes a table read from data/<profile>/<file> (the `datadir` metadata), followed by a
-- provenance line (program, git revision, date, wall time) from the file's `# key = value`
-- header.  A referenced data file or image that does not exist stops the build: the
-- report never shows a stale or missing result silently.

local datadir = "data/quick"

local function fail(msg)
  io.stderr:write("report: error: " .. msg .. "\n")
  os.exit(1)
end

local function exists(path)
  local f = io.open(path, "r")
  if f then f:close() return true end
  return false
end

local function split(s, sep)
  local out = {}
  for field in (s .. sep):gmatch("(.-)" .. sep) do table.insert(out, field) end
  return out
end

local function read_tsv(path)
  local f = io.open(path, "r")
  if not f then fail("data file missing: " .. path) end
  local meta, header, rows = {}, nil, {}
  for line in f:lines() do
    if line:sub(1, 2) == "# " then
      local k, v = line:match("^# (.-) = (.*)$")
      if k then meta[k] = v end
    elseif line ~= "" then
      local cells = split(line, "\t")
      if not header then header = cells else table.insert(rows, cells) end
    end
  end
  f:close()
  if not header then fail("data file has no header: " .. path) end
  return meta, header, rows
end

local function fmtnum(s, digits)
  local n = tonumber(s)
  if not n or not digits or s:match("^%-?%d+$") then return s end
  return string.format("%." .. digits .. "g", n)
end

local function tsv_block(el)
  local file = el.attributes["file"]
  if not file then fail("tsv block without file= attribute") end
  local path = file:sub(1, 1) == "/" and file or (datadir .. "/" .. file)
  local meta, header, rows = read_tsv(path)
  local digits = el.attributes["digits"]
  -- Column selection with optional renaming "name:Header".
  local cols = {}
  if el.attributes["columns"] then
    for _, spec in ipairs(split(el.attributes["columns"], ",")) do
      local name, label = spec:match("^([^:]+):(.*)$")
      name = name or spec
      local idx
      for i, h in ipairs(header) do if h == name then idx = i end end
      if not idx then fail("column '" .. name .. "' not in " .. path) end
      table.insert(cols, {idx = idx, label = label or name})
    end
  else
    for i, h in ipairs(header) do table.insert(cols, {idx = i, label = h}) end
  end
  -- Optional row filter: filter="column=value".
  local fcol, fval
  if el.attributes["filter"] then
    fcol, fval = el.attributes["filter"]:match("^([^=]+)=(.*)$")
  end
  local fidx
  if fcol then
    for i, h in ipairs(header) do if h == fcol then fidx = i end end
    if not fidx then fail("filter column '" .. fcol .. "' not in " .. path) end
  end
  local heads, aligns, widths, body = {}, {}, {}, {}
  for _, c in ipairs(cols) do
    table.insert(heads, {pandoc.Plain(pandoc.Str(c.label))})
    table.insert(aligns, pandoc.AlignDefault)
    table.insert(widths, 0)
  end
  for _, r in ipairs(rows) do
    if not fidx or r[fidx] == fval then
      local cells = {}
      for _, c in ipairs(cols) do
        table.insert(cells, {pandoc.Plain(pandoc.Str(fmtnum(r[c.idx] or "", digits)))})
      end
      table.insert(body, cells)
    end
  end
  local caption = el.attributes["caption"] or ""
  local simple = pandoc.SimpleTable({pandoc.Str(caption)}, aligns, widths, heads, body)
  local prov = string.format("Data: %s — program %s, profile %s, git %s, written %s%s.",
    path, meta["program"] or "?", meta["profile"] or "?", meta["git_revision"] or "?",
    meta["written_utc"] or "?",
    (meta["wall_time_s"] or meta["wall_s"]) and (", wall time " .. fmtnum(meta["wall_time_s"] or meta["wall_s"], 3) .. " s") or "")
  return {pandoc.utils.from_simple_table(simple),
          pandoc.Para({pandoc.Emph({pandoc.Str(prov)})})}
end

return {
  {
    Meta = function(m)
      if m.datadir then datadir = pandoc.utils.stringify(m.datadir) end
    end
  },
  {
    CodeBlock = function(el)
      if el.classes:includes("tsv") then return tsv_block(el) end
    end,
    Image = function(el)
      if not exists(el.src) then fail("figure missing: " .. el.src) end
    end
  }
}
