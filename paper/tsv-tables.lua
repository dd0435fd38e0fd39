-- Pandoc filter for the reproduction report.
--
-- ```{.tsv file="core_weights.tsv" columns="name:weight,norm,order_k:k" caption="..."}
-- ```
-- becomes a table read from data/<profile>/<file> (the `datadir` metadata), followed by a
-- provenance line (program, git revision, date, wall time) from the file's `# key = value`
-- header.  A referenced data file or image that does not exist stops the build: the
-- report never shows a stale or missing result silently.
--
-- Every figure figures/out/<name>.svg gets a provenance line under it: the make command
-- that regenerates it, and for each data file it plots (its `data="a.tsv,b.tsv"` attribute,
-- else the `datadir.'/x.tsv'` names found in figures/<name>.gp and the scripts it loads)
-- the program, its command line, profile, seed, git revision and wall time.
--
-- Numbers in the prose are read from data files too, never typed:
--   []{.datum file="store_score.tsv" where="table=total,slice=as printed" column="agrees"}
-- becomes the value of that cell (column may be "a-b" or "a+b" of two columns; sum="yes"
-- adds the column over every matching row; count="yes" gives the number of matching rows,
-- which may be 0; a where value "~PATTERN" is a Lua pattern), and
--   []{.counts file=... where=... columns="agrees:agree,unexplained:unexplained" total="rates"}
-- becomes "18 agree, 31 unexplained …": the listed columns that are not zero, which must add
-- up to the total column, so that no category is left out unnoticed.
-- A Div of class page-one (title page: abstract and verdict table) is set before the table
-- of contents (pandoc's abstract slot).  A raw caret in text (2^-8, h^2, (x)^{1/5}) is set as
-- a superscript, and a table cell that is nan must have its word: the block's nan attribute,
-- "what failed" for every column or "column=what failed,…" per column.

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

local tsv_cache = {}
local function read_tsv_cached(path)
  if not tsv_cache[path] then
    local meta, header, rows = read_tsv(path)
    tsv_cache[path] = {meta = meta, header = header, rows = rows}
  end
  return tsv_cache[path]
end

local function column_index(t, name, path)
  for i, h in ipairs(t.header) do if h == name then return i end end
  fail("column '" .. name .. "' not in " .. path)
end

-- The rows of a data file that satisfy where="col=value,col=~pattern".
-- The values a condition "column=a|b" allows, as a set: a datum's where= and a table's
-- filter= read alternatives the same way.
local function alternatives(val)
  local allowed = {}
  for v in val:gmatch("[^|]+") do allowed[v] = true end
  return allowed
end

local function matching_rows(el)
  local file = el.attributes["file"] or fail("datum without file= attribute")
  local path = file:sub(1, 1) == "/" and file or (datadir .. "/" .. file)
  local t = read_tsv_cached(path)
  local conds = {}
  for _, c in ipairs(split(el.attributes["where"] or "", ",")) do
    local k, v = c:match("^([^=]+)=(.*)$")
    if k then
      table.insert(conds, {idx = column_index(t, k, path), val = v,
                           allowed = v == "" and {[""] = true} or v:sub(1, 1) ~= "~" and alternatives(v) or nil})
    end
  end
  local out = {}
  for _, r in ipairs(t.rows) do
    local ok = true
    for _, c in ipairs(conds) do
      local cell = r[c.idx] or ""
      if c.allowed then ok = ok and c.allowed[cell] == true
      else ok = ok and cell:match("^" .. c.val:sub(2) .. "$") ~= nil end
    end
    if ok then table.insert(out, r) end
  end
  if #out == 0 and el.attributes["count"] ~= "yes" then
    fail("no row of " .. path .. " where " .. (el.attributes["where"] or ""))
  end
  return t, path, out
end

-- The number in column spec ("name", "a-b" or "a+b") of row r.
local function column_value(t, path, r, spec)
  local a, op, b = spec:match("^([%w_]+)([%+%-])([%w_]+)$")
  local function num(name)
    local v = tonumber(r[column_index(t, name, path)])
    if not v then fail("column '" .. name .. "' of " .. path .. " is not a number") end
    return v
  end
  if a then return op == "+" and num(a) + num(b) or num(a) - num(b) end
  return r[column_index(t, spec, path)]
end

-- meta="key": a header line's value instead of a cell; map="value=words;value=words": the
-- words the prose gives for each value the data may hold, a value being a Lua pattern
-- ("h15.*") or the value itself (a value without words stops the build).
local function datum_words(el, v)
  local map = el.attributes["map"]
  if not map then return pandoc.Str(tostring(v)) end
  for _, e in ipairs(split(map, ";")) do
    local k, words = e:match("^([^=]+)=(.*)$")
    if k == v or tostring(v):match("^" .. k .. "$") then return pandoc.Str(words) end
  end
  fail("datum value '" .. tostring(v) .. "' has no words in the map of " .. (el.attributes["file"] or "?"))
end

local function datum(el)
  if el.attributes["meta"] then
    local file = el.attributes["file"] or fail("datum without file= attribute")
    local t = read_tsv_cached(datadir .. "/" .. file)
    local v = t.meta[el.attributes["meta"]] or fail("no header line '" .. el.attributes["meta"] .. "' in " .. file)
    return datum_words(el, v)
  end
  local t, path, rows = matching_rows(el)
  -- count="yes": how many rows match (none is an answer too: "0 of 8 cases").
  if el.attributes["count"] == "yes" then return datum_words(el, string.format("%d", #rows)) end
  local spec = el.attributes["column"] or fail("datum without column= attribute")
  local v
  if el.attributes["sum"] == "yes" then
    v = 0
    for _, r in ipairs(rows) do v = v + tonumber(column_value(t, path, r, spec)) end
  else
    if #rows > 1 then fail(#rows .. " rows of " .. path .. " where " .. el.attributes["where"] .. ": a datum needs one") end
    v = column_value(t, path, rows[1], spec)
  end
  -- scale="100": the number times a factor (a fraction read as per cent).
  local scale = tonumber(el.attributes["scale"] or "")
  if scale then
    v = tonumber(v) or fail("datum scale= on a value that is not a number in " .. path)
    v = v * scale
  end
  if type(v) == "number" and v == math.floor(v) then v = string.format("%d", v) end
  -- digits="2": significant digits of a number read from the data (a ratio, a rate).
  local digits = el.attributes["digits"]
  if digits and tonumber(v) then v = string.format("%." .. digits .. "g", tonumber(v)) end
  return datum_words(el, v)
end

local function counts(el)
  local t, path, rows = matching_rows(el)
  if #rows > 1 then fail(#rows .. " rows of " .. path .. " where " .. el.attributes["where"] .. ": counts need one") end
  local r, parts, sum = rows[1], {}, 0
  for _, spec in ipairs(split(el.attributes["columns"] or fail("counts without columns="), ",")) do
    local name, word = spec:match("^([^:]+):(.*)$")
    local v = tonumber(column_value(t, path, r, name or spec)) or fail("column '" .. spec .. "' of " .. path .. " is not a number")
    sum = sum + v
    if v ~= 0 then table.insert(parts, string.format("%d %s", v, word or spec)) end
  end
  local total = tonumber(column_value(t, path, r, el.attributes["total"] or fail("counts without total=")))
  if sum ~= total then
    fail(string.format("counts of %s add up to %d, not %s = %d: a category is missing", path, sum, el.attributes["total"], total))
  end
  local text = #parts > 1 and (table.concat(parts, ", ", 1, #parts - 1) .. " and " .. parts[#parts]) or (parts[1] or "none")
  return pandoc.Str(text)
end

-- "nan" in a table cell: the word the block gives for its column (nan="word" or
-- nan="col=word,col=word"); without one the build stops.
local function nan_word(el, column, path)
  local spec = el.attributes["nan"]
  if spec then
    if not spec:find("=") then return spec end
    for _, e in ipairs(split(spec, ",")) do
      local k, v = e:match("^([^=]+)=(.*)$")
      if k == column then return v end
    end
  end
  fail("a nan cell in column '" .. column .. "' of " .. path .. " without a word saying what failed (nan= attribute)")
end

local function fmtnum(s, digits)
  local n = tonumber(s)
  if not n or not digits or s:match("^%-?%d+$") then return s end
  return string.format("%." .. digits .. "g", n)
end

local profile = "quick"
local part = "whole"  -- "paper", "supplement", "docs" (the companion) or "whole" (everything)
local LONG_TABLE_ROWS = 15  -- a table longer than this is a supplement table (keep="paper" aside)

-- "program P, command `C`, profile, seed, git, written, wall time" of one data file.
local function describe(path, meta)
  local wall = meta["wall_time_s"] or meta["wall_s"]
  local parts = {
    "program " .. (meta["program"] or "?"),
    -- A file without a profile header (a rate table, a figure's coordinates, a report
    -- script's table) belongs to the folder it was written to: data/<profile>, or the store.
    "profile " .. (meta["profile"] or (path:match("^results/paper/") and "paper (result store)")
                   or (path:match("^data/paper/") and "paper") or profile .. " (its folder)"),
    "seed " .. (meta["seed"] or "none"),
    "git " .. (meta["git_revision"] or "?"),
    "written " .. (meta["written_utc"] or "?"),
  }
  if wall then
    table.insert(parts, "wall time of the writing run " .. fmtnum(wall, 3) .. " s")
  end
  local inl = {pandoc.Code(path), pandoc.Str(": " .. table.concat(parts, ", "))}
  if meta["command"] then
    table.insert(inl, pandoc.Str(", command "))
    table.insert(inl, pandoc.Code(meta["command"]))
  end
  if meta["sources"] then  -- a derived file (atlas, rate table): what it was derived from
    table.insert(inl, pandoc.Str(", derived from "))
    table.insert(inl, pandoc.Code(meta["sources"]))
    if meta["source_git_revisions"] then
      table.insert(inl, pandoc.Str(" (git " .. meta["source_git_revisions"] .. ")"))
    end
  end
  return inl
end

-- The provenance paragraph: how to regenerate, then one description per data file.
function provenance(path_or_list, meta_or_nil, make_cmd)
  local items = {}
  if type(path_or_list) == "string" then
    items = {{path = path_or_list, meta = meta_or_nil}}
  else
    items = path_or_list
  end
  local inl = {pandoc.Str("Regenerate: "), pandoc.Code(make_cmd), pandoc.Str(". Data ")}
  for i, it in ipairs(items) do
    if i > 1 then table.insert(inl, pandoc.Str("; ")) end
    for _, x in ipairs(describe(it.path, it.meta)) do table.insert(inl, x) end
  end
  table.insert(inl, pandoc.Str("."))
  local paths = {}
  for _, it in ipairs(items) do table.insert(paths, it.path) end
  return pandoc.Div({pandoc.Para(inl)},
                    pandoc.Attr("", {"provenance"}, {files = table.concat(paths, ",")}))
end

-- Data files a figure plots: explicit data= attribute, else its side file (below), else the
-- names its gnuplot script (and the scripts it loads, except the style) spell out as
-- datadir.'/name.tsv'.
local function figure_data(img)
  local names, seen = {}, {}
  local function add(n) if not seen[n] then seen[n] = true; table.insert(names, n) end end
  if img.attributes["data"] then
    for _, n in ipairs(split(img.attributes["data"], ",")) do add(n) end
    return names
  end
  -- A figure whose data file is chosen when it is drawn (figures/store_heat.sh: the store file
  -- of the identified reading) names it in a side file, <figure>.svg.data, one path per line.
  local side = io.open(img.src .. ".data", "r")
  if side then
    for l in side:lines() do if l ~= "" then add(l) end end
    side:close()
    return names
  end
  local function scan(script, depth)
    local f = io.open(script, "r")
    if not f or depth > 3 then return end
    local text = f:read("a")
    f:close()
    for n in text:gmatch("datadir%s*%.%s*['\"]/([%w_%-%.]+%.tsv)['\"]") do add(n) end
    for l in text:gmatch("load%s+['\"](figures/[%w_%-]+%.gp)['\"]") do
      if l ~= "figures/style.gp" then scan(l, depth + 1) end
    end
  end
  local base = img.src:match("figures/out/([%w_%-]+)%.svg$")
  if base then scan("figures/" .. base .. ".gp", 0) end
  return names
end

-- A caption may only name what its data hold: a file name (x.tsv) must exist in the data
-- folder or the result store, and the ends of a level range "2^-a … 2^-b" must be levels of
-- the figure's data files (their level column).
local function check_caption(img, items)
  local text = pandoc.utils.stringify(img.caption or {}):gsub("%^", ""):gsub("−", "-")
  for f in text:gmatch("[%w_%-]+%.tsv") do
    if not (exists(datadir .. "/" .. f) or exists("results/paper/" .. f)) then
      fail("figure " .. img.src .. ": its caption names " .. f .. ", which is not in " .. datadir .. " or the result store")
    end
  end
  for a, b in text:gmatch("2%-(%d+)%s*…%s*2%-(%d+)") do
    local have, any = {}, false
    for _, it in ipairs(items) do
      local t = read_tsv_cached(it.path)
      for i, h in ipairs(t.header) do
        if h == "level" then
          any = true
          for _, r in ipairs(t.rows) do have[r[i]] = true end
        end
      end
    end
    for _, l in ipairs({a, b}) do
      if not any or not have[l] then
        fail("figure " .. img.src .. ": its caption names level 2^-" .. l .. ", which its data (" ..
             (items[1] and items[1].path or "none") .. ") do not hold")
      end
    end
  end
end

local function figure_provenance(img)
  local base = img.src:match("figures/out/([%w_%-]+)%.svg$")
  if not base then return nil end
  local items = {}
  for _, n in ipairs(figure_data(img)) do
    -- data="results/paper/x.tsv": a figure drawn from the result store, whatever the profile.
    local path = n:match("^results/") and n or (datadir .. "/" .. n)
    local meta = read_tsv(path)
    table.insert(items, {path = path, meta = meta})
  end
  check_caption(img, items)
  local cmd = "make " .. img.src .. (img.src:match("/store_") and "" or (" PROFILE=" .. profile))
  if #items == 0 then
    return pandoc.Div({pandoc.Para({pandoc.Str("Regenerate: "), pandoc.Code(cmd),
      pandoc.Str(" (data files: see figures/" .. base .. ".gp).")})}, pandoc.Attr("", {"provenance"}))
  end
  return provenance(items, nil, cmd)
end

-- A cell's text as inlines that wrap between words only: a browser also breaks after a
-- hyphen, a slash or a bar ("other-|levels", "1.5e-|16", "|(1"), so a piece holding one is kept on one
-- line (class nobr, paper/style.css).  An identifier (thesis_table4_5_h15) is code on one line
-- (human_names first), a long formula may wrap after a plus (a zero-width space marks it).
-- The plain-text math of data files ("V_i = rho_i/m_i", "lambda0", "sin 2pi(x+y)", "eps_grad")
-- as the reader should see it: Greek names as letters, a one-letter subscript as a subscript
-- character, dx and dt as Δx and Δt.  Whole words only (never inside "piecewise" or
-- "thesis_table4_4"), and never in a command line or a file name, which must stay typable.
local GREEK = {alpha = "α", beta = "β", gamma = "γ", delta = "δ", eps = "ε", epsilon = "ε",
               theta = "θ", kappa = "κ", lambda = "λ", mu = "μ", nu = "ν", pi = "π", rho = "ρ",
               sigma = "σ", tau = "τ", phi = "φ", omega = "ω", Omega = "Ω", Delta = "Δ"}
local SUBSCRIPT = {a = "ₐ", e = "ₑ", h = "ₕ", i = "ᵢ", j = "ⱼ", k = "ₖ", l = "ₗ", m = "ₘ", n = "ₙ",
                   o = "ₒ", p = "ₚ", r = "ᵣ", s = "ₛ", t = "ₜ", u = "ᵤ", v = "ᵥ", x = "ₓ",
                   ["0"] = "₀", ["1"] = "₁", ["2"] = "₂", ["3"] = "₃", ["4"] = "₄", ["5"] = "₅",
                   ["6"] = "₆", ["7"] = "₇", ["8"] = "₈", ["9"] = "₉"}
-- A subscript letter Unicode lacks (c, w, …) is marked and set as a real subscript by
-- cell_inlines (r_c: r with a subscript c).
local SUB_MARK = "\u{E000}"
local function subscript(sub) return SUBSCRIPT[sub] or (SUB_MARK .. sub) end
-- A command line or a file name: its text must stay typable, so no cell rewrite touches it.
local function literal(v)
  return v:find("--", 1, true) or v:find("%.%a%a%a?$") or v:find("%.%a%a%a?[%s,;)]")
end

local function ascii_math(v)
  if literal(v) then return v end
  v = v:gsub("%f[%a]eps_grad%f[%A]", "ε∇")
  v = v:gsub("%f[%a](%a+)(%d*)_?(%w?)%f[%W]", function(word, digits, sub)
    local g = GREEK[word]
    if not g then return nil end
    if sub ~= "" and digits == "" then
      return g .. subscript(sub)
    end
    if sub ~= "" then return nil end
    return g .. digits
  end)
  v = v:gsub("%f[%w](%a)_(%w)%f[%W]", function(x, sub) return x .. subscript(sub) end)
  v = v:gsub("%f[%a]d([xt])%f[%A]", "Δ%1")
  return v
end

-- A piece of a cell as inlines: the marked subscripts (SUB_MARK) as Subscript elements.
local function piece_inlines(piece)
  local out = {}
  local rest = piece
  while true do
    local at = rest:find(SUB_MARK, 1, true)
    if not at then break end
    if at > 1 then table.insert(out, pandoc.Str(rest:sub(1, at - 1))) end
    local sub = rest:sub(at + #SUB_MARK, at + #SUB_MARK)
    table.insert(out, pandoc.Subscript({pandoc.Str(sub)}))
    rest = rest:sub(at + #SUB_MARK + 1)
  end
  if rest ~= "" then table.insert(out, pandoc.Str(rest)) end
  return out
end

-- A number printed with more digits than anyone reads (a double's 17: "0.004158723777973314"),
-- in a cell whose block sets no digits=, is shown to 6 significant digits; never in a command
-- line or a file name.
local function long_numbers(v)
  if literal(v) then return v end
  return (v:gsub("%f[%w.]%d+%.%d+%f[^%d.]", function(n)
    local significant = n:gsub("%.", ""):gsub("^0+", "")
    if #significant <= 10 then return nil end
    return string.format("%.6g", tonumber(n))
  end))
end

-- The data files' identifiers as a reader names them (issue 60: no raw identifier on a page):
-- weights, tables and the readings of a table's set-up (h rule · volumes · time step · solver ·
-- seed; "h15_cell_exact" is h15 · Δx² · Δt₀).  Whole tokens only, never in a command line or a
-- file name; an identifier not named here (a program, a store file, a benchmark variant) is
-- set as code by cell_inlines: a name to type, not prose.
local HUMAN = {quartic_polynomial = "quartic", piecewise_cubic_polynomial = "pw. cubic",
               piecewise_quintic_polynomial = "pw. quintic", cubic_spike = "cubic spike",
               quadratic_spike = "quadratic spike", cubic_bspline = "cubic B-spline",
               quintic_bspline = "quintic B-spline", matrix_free = "matrix-free",
               not_positive_definite = "not positive definite", no_convergence = "no convergence",
               imoto_table1 = "Imoto Table 1", printed_voronoi = "printed h · Voronoi",
               scaled_voronoi = "scaled h · Voronoi", printed_uniform = "printed h · |Ω" .. SUB_MARK .. "H|/N",
               scaled_uniform = "scaled h · |Ω" .. SUB_MARK .. "H|/N", box_laplacian = "box Laplacian",
               laplacian_with_c8 = "Laplacian with c₈", error_printed = "error (printed)"}
local READING_PART = {cell = "Δx²", exact = "Δt₀", tau = "τ-PCG"}
local function human_token(t)
  if HUMAN[t] then return HUMAN[t] end
  local n = t:match("^thesis_table4_(%d)$") or t:match("^thesis4_(%d)$")
  if n then return "Table 4." .. n end
  local rule, rest = t:match("^(h1[05])(_[%w_]*)$")
  if not rule then return nil end
  local out = {rule}
  for word in rest:gmatch("[^_]+") do
    local seed = word:match("^seed(%d+)$")
    if seed then table.insert(out, "seed " .. seed)
    elseif READING_PART[word] then table.insert(out, READING_PART[word])
    else return nil end
  end
  return table.concat(out, " · ")
end
local function human_names(v)
  if literal(v) then return v end
  -- (a token joined to another by ':' — kernel_l1:thesis4_1 — is one identifier, left whole)
  return (v:gsub("%f[%w_:][%w]+_[%w_]*%f[^%w_:]", function(t) return human_token(t) end))
end

local function cell_inlines(v)
  v = long_numbers(ascii_math(human_names(v)))
  -- The author's name as a word (a program's label "imoto §5 (Π1)"), not inside a file name,
  -- an identifier or a command line, is set capitalized.
  if not v:find(" --", 1, true) then v = v:gsub("%f[%w_/%-]imoto%f[^%w_%-]", "Imoto") end
  local lit = literal(v)
  local out = {}
  for word, space in v:gmatch("(%S+)(%s*)") do
    local pre, core, post = word:match("^([%(%[]*)(.-)([,;:%.%)%]]*)$")
    if not lit and core:find("%w_%w") then
      -- An identifier no human name covers: code, kept on one line (a name to type).
      if pre ~= "" then table.insert(out, pandoc.Str(pre)) end
      table.insert(out, pandoc.Code(core))
      if post ~= "" then table.insert(out, pandoc.Str(post)) end
    else
      word = word:gsub("_", "_\u{200B}")
      if #word > 20 then word = word:gsub("%+", "+\u{200B}") end
      local parts = {}
      for piece in (word .. "\u{200B}"):gmatch("(.-)\u{200B}") do table.insert(parts, piece) end
      for i, piece in ipairs(parts) do
        if i > 1 then table.insert(out, pandoc.Str("\u{200B}")) end
        if piece:find("[-/|]") or piece:find("–", 1, true) or piece:find("−", 1, true) then
          table.insert(out, pandoc.Span(piece_inlines(piece), pandoc.Attr("", {"nobr"})))
        elseif piece ~= "" then
          for _, x in ipairs(piece_inlines(piece)) do table.insert(out, x) end
        end
      end
    end
    if space ~= "" then table.insert(out, pandoc.Space()) end
  end
  return out
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
  -- Optional row filter: filter="column=value,column=a|b": every condition holds, a value
  -- may list alternatives.
  local conds = {}
  for cond in (el.attributes["filter"] or ""):gmatch("[^,]+") do
    local fcol, fval = cond:match("^([^=]+)=(.*)$")
    if not fcol then fail("filter '" .. cond .. "' is not column=value") end
    local fidx
    for i, h in ipairs(header) do if h == fcol then fidx = i end end
    if not fidx then fail("filter column '" .. fcol .. "' not in " .. path) end
    table.insert(conds, {idx = fidx, allowed = alternatives(fval)})
  end
  local function kept(r)
    for _, c in ipairs(conds) do if not c.allowed[r[c.idx] or ""] then return false end end
    return true
  end
  local heads, aligns, widths, body = {}, {}, {}, {}
  for _, c in ipairs(cols) do
    table.insert(heads, {pandoc.Plain(cell_inlines(c.label))})
    table.insert(aligns, pandoc.AlignDefault)
    table.insert(widths, 0)
  end
  for _, r in ipairs(rows) do
    if kept(r) then
      local cells = {}
      for _, c in ipairs(cols) do
        local v = fmtnum(r[c.idx] or "", digits)
        if v:lower():match("^[%-%+]?nan$") then v = nan_word(el, header[c.idx], path) end
        table.insert(cells, {pandoc.Plain(cell_inlines(v))})
      end
      table.insert(body, cells)
    end
  end
  local caption = el.attributes["caption"] or ""
  local prov = provenance(path, meta, "make " .. path .. " PROFILE=" .. profile)
  local simple = pandoc.SimpleTable({pandoc.Str(caption)}, aligns, widths, heads, body)
  local tbl = pandoc.utils.from_simple_table(simple)
  -- A long table belongs to the supplement (split_parts), unless the block says keep="paper".
  if #body > LONG_TABLE_ROWS and el.attributes["keep"] ~= "paper" then
    tbl = pandoc.Div({tbl}, pandoc.Attr("", {"long-table"}, {caption = caption, rows = tostring(#body)}))
  end
  return {tbl, prov}
end

-- A raw caret in text, "2^-8", "h^2", "10^-(m-1)", "(x)^{1/5}": the exponent as a superscript (with a
-- true minus sign), so that no source or data file's plain-text notation reaches the page.
local function caret_inlines(text)
  if not text:find("^", 1, true) then return nil end
  local out, pos = {}, 1
  while true do
    local s, e, exp = text:find("%^{([^}]*)}", pos)
    local s2, e2, exp2 = text:find("%^(%-?%b())", pos)
    if not s2 then s2, e2, exp2 = text:find("%^(%-?[%w%.]+)", pos) end
    if s2 and (not s or s2 < s) then s, e, exp = s2, e2, exp2 end
    if not s then break end
    if s > pos then table.insert(out, pandoc.Str(text:sub(pos, s - 1))) end
    table.insert(out, pandoc.Superscript({pandoc.Str((exp:gsub("%-", "−")))}))
    pos = e + 1
  end
  if #out == 0 then return nil end
  if pos <= #text then table.insert(out, pandoc.Str(text:sub(pos))) end
  return out
end

-- Page one: the blocks of the page-one Div go to the abstract slot, before the table of
-- contents; the provenance of its tables is kept for the appendix.
local function lift_page_one(doc)
  local out, prov = {}, {}
  for _, b in ipairs(doc.blocks) do
    if b.t == "Div" and b.classes:includes("page-one") then
      local kept = {}
      for _, x in ipairs(b.content) do
        if x.t == "Div" and x.classes:includes("provenance") then table.insert(prov, x)
        else table.insert(kept, x) end
      end
      doc.meta.abstract = pandoc.MetaBlocks(kept)
      doc.meta["abstract-title"] = pandoc.MetaInlines({pandoc.Str("Abstract")})
    else
      table.insert(out, b)
    end
  end
  -- Its provenance heads the first chapter's, so that the appendix still lists every table.
  local i = 1
  while i <= #out and not (out[i].t == "Header" and out[i].level == 1) do i = i + 1 end
  for k = #prov, 1, -1 do table.insert(out, i + 1, prov[k]) end
  doc.blocks = out
  return doc
end

-- The paper and its supplement, from the same sources.  The paper keeps the chapters and
-- puts a one-line pointer where a long table stood; the supplement keeps the appendices
-- (chapters titled "Appendix …"), every long table and every section whose heading carries
-- the class supplement ({.supplement}) under its chapter's title, and the provenance appendix.
-- Long tables are numbered S1, S2, … and moved sections Section S1, S2, … in source order.
-- A long table's caption, set as its table's caption was (raw carets as superscripts).
local function caption_inlines(div)
  local text = div.attributes["caption"]
  return pandoc.List(caret_inlines(text) or {pandoc.Str(text)})
end

local function split_parts(doc)
  if part == "whole" then return doc end
  local out, n, m = {}, 0, 0
  -- chapter: the paper chapter being read; marked: its title has been set down in the
  -- supplement (a chapter-mark for the provenance appendix); titled: its "Supplement to"
  -- heading too.  moving: the level of a section marked {.supplement} being read (it runs
  -- to the next heading of that level or above), nil outside one.
  local appendix, chapter, marked, titled, moving = false, nil, false, false, nil
  local function mark()
    if part == "supplement" and not appendix and not marked then
      table.insert(out, pandoc.Div({chapter}, pandoc.Attr("", {"chapter-mark"})))
      marked = true
    end
  end
  local function title()  -- the supplement's heading over what it holds of this chapter
    mark()
    if not appendix and not titled then
      table.insert(out, pandoc.Header(1, {pandoc.Str("Supplement to: ")} .. chapter.content,
                                      pandoc.Attr("s-" .. (chapter.identifier or ""))))
      titled = true
    end
  end
  -- companion: the chapter being read is marked {.docs} (performance, cost model, atlas: they
  -- support no reproduction claim), so it goes to the third document, whole and in place (its
  -- long tables and marked sections too), and to neither other.  side: the level of a section
  -- marked {.docs} being read in another chapter (a quick-profile table, a cost): it moves to
  -- the companion as Section C1, C2, … under "Companion to: <its chapter>", and the paper keeps
  -- a one-line pointer where it stood, as for the supplement.
  local companion, side, side_titled, c = false, nil, false, 0
  for _, b in ipairs(doc.blocks) do
    if b.t == "Header" and moving and b.level <= moving then moving = nil end
    if b.t == "Header" and side and b.level <= side then side = nil end
    if b.t == "Header" and b.level == 1 then
      companion, side_titled = b.classes:includes("docs"), false
      if not companion then chapter = b end
    elseif b.t == "Header" and b.classes:includes("docs") and not companion and not moving then
      c, side = c + 1, b.level
      local label = "Section C" .. c
      if part == "paper" then
        table.insert(out, pandoc.Para(pandoc.List({pandoc.Emph({pandoc.Str(label)}),
          pandoc.Str(" (companion): ")}) .. b.content))
      elseif part == "docs" then
        if not side_titled then
          table.insert(out, pandoc.Header(1, {pandoc.Str("Companion to: ")} .. chapter.content,
                                          pandoc.Attr("c-" .. (chapter.identifier or ""))))
          side_titled = true
        end
        table.insert(out, pandoc.Header(2, pandoc.List({pandoc.Str(label .. "."), pandoc.Space()}) ..
                                        b.content, b.attr))
      end
      goto next_block
    end
    if part == "docs" or companion or side then
      if part == "docs" and (companion or side) then
        table.insert(out, (b.t == "Div" and b.classes:includes("long-table")) and b.content[1] or b)
      end
      goto next_block
    end
    if b.t == "Header" and b.level == 1 then
      appendix = pandoc.utils.stringify(b.content):match("^Appendix") ~= nil
      chapter, marked, titled = b, false, false
      if (part == "paper") ~= appendix then table.insert(out, b) end
    elseif b.t == "Header" and b.classes:includes("supplement") and not appendix then
      -- A section the paper leaves to the supplement: a one-line pointer where it stood.
      m = m + 1
      moving = b.level
      local label = "Section S" .. m
      if part == "paper" then
        table.insert(out, pandoc.Para(pandoc.List({pandoc.Emph({pandoc.Str(label)}),
          pandoc.Str(" (supplement): ")}) .. b.content))
      else
        title()
        table.insert(out, pandoc.Header(2, pandoc.List({pandoc.Str(label .. "."), pandoc.Space()}) ..
                                        b.content, b.attr))
      end
    elseif b.t == "Div" and b.classes:includes("long-table") then
      n = n + 1
      local label = "Table S" .. n
      if part == "paper" then
        if not appendix and not moving then
          table.insert(out, pandoc.Para(pandoc.List({pandoc.Emph({pandoc.Str(label)}),
            pandoc.Str(" (supplement, " .. b.attributes["rows"] .. " rows): ")}) .. caption_inlines(b)))
        end
      else
        title()
        local tbl = b.content[1]
        tbl.caption.long = {pandoc.Plain(pandoc.List({pandoc.Strong({pandoc.Str(label .. ".")}), pandoc.Space()}) ..
                                         caption_inlines(b))}
        table.insert(out, tbl)
      end
    elseif b.t == "Div" and b.classes:includes("provenance") then
      -- gather_provenance turns them into the paper's chapter lines and the supplement's
      -- appendix, filed under the chapter-mark of their chapter.
      mark()
      table.insert(out, b)
    elseif (part == "paper") ~= (appendix or moving ~= nil) then
      table.insert(out, b)
    end
    ::next_block::
  end
  -- Each of the two other documents says in one paragraph what it is and where the others are.
  local function note(text)
    doc.meta["abstract-title"] = pandoc.MetaInlines({pandoc.Str("About this document")})
    return pandoc.MetaBlocks({pandoc.Para(pandoc.Inlines(text))})
  end
  if part == "docs" then
    doc.meta.abstract = note("The companion of the paper (paper/report.pdf) and its supplement " ..
      "(paper/supplement.pdf): the kernel's performance against this machine's limits, the cost " ..
      "model, an atlas of accuracy against cost and every quick-profile table. Nothing here " ..
      "supports a reproduction claim; the verdicts are the paper's.")
    doc.meta.title = pandoc.MetaInlines(pandoc.List({pandoc.Str("Companion: ")}) ..
                                        pandoc.List(doc.meta.title or {pandoc.Str("the report")}))
  end
  if part == "supplement" then
    doc.meta.abstract = note("The supplement of the paper (paper/report.pdf): its long tables " ..
      "(Table S1, S2, …) and sections (Section S1, S2, …), each named where it would stand in the " ..
      "paper, the software environment and the provenance of every table and figure. What " ..
      "supports no reproduction claim (performance, cost model, atlas, quick-profile tables) is " ..
      "in the companion, docs/companion.pdf.")
    doc.meta.title = pandoc.MetaInlines(pandoc.List({pandoc.Str("Supplement: ")}) ..
                                        pandoc.List(doc.meta.title or {pandoc.Str("the report")}))
  end
  doc.blocks = out
  return doc
end

-- Every figure numbered in its document's order (the paper: Figure 1, 2, …; the supplement:
-- Figure S1, S2, …), so that none is left without a number; a caption that names one of the
-- documents' own figures ("the thesis' Figure 4.8") keeps that name after the number.
local function number_figures(doc)
  local n = 0
  local prefix = part == "supplement" and "S" or part == "docs" and "C" or ""
  doc.blocks = doc.blocks:walk({
    Image = function(el)
      if el.title:match("^fig:") then
        n = n + 1
        local label = pandoc.Strong({pandoc.Str("Figure " .. prefix .. n .. ".")})
        el.caption = pandoc.List({label, pandoc.Space()}) .. el.caption
        return el
      end
    end
  })
  return doc
end

-- The reader's order: one short line per chapter naming its data files, and every table's
-- and figure's full provenance (regenerate command; program, command, profile, seed, git
-- revision, date and wall time of each data file) in a last appendix, grouped by chapter.
local function gather_provenance(doc)
  local out, appendix = {}, {}
  local chapter, files, seen, pending = nil, {}, {}, nil
  local function flush()
    if #files > 0 then
      -- The paper names only how many files and where they are listed (a list of file names
      -- is a supplement's matter: in the paper it filled pages of its own).
      local inl
      if part == "paper" then
        inl = {pandoc.Str(string.format("Data of this chapter: %d file%s, each listed with how it was made " ..
          "(program, command, profile, seed, git revision, date, wall time) and the command that regenerates " ..
          "each table and figure in the supplement's last appendix, under this chapter's title.",
          #files, #files == 1 and "" or "s"))}
      else
        inl = {pandoc.Str("Data of this chapter: ")}
        for i, f in ipairs(files) do
          if i > 1 then table.insert(inl, pandoc.Str(", ")) end
          table.insert(inl, pandoc.Code(f))
        end
        table.insert(inl, pandoc.Str(". How each file was made (program, command, profile, seed, " ..
          "git revision, date, wall time) and the command that regenerates each table and figure: " ..
          "the last appendix, under this chapter's title."))
      end
      -- The supplement lists everything in its appendix; its own chapters need no line.
      if part ~= "supplement" then
        table.insert(out, pandoc.Div({pandoc.Para(inl)}, pandoc.Attr("", {"provenance"})))
      end
    end
    files, seen = {}, {}
  end
  local function open(h)  -- a chapter whose provenance follows under its title
    flush()
    chapter = h
    pending = pandoc.Header(2, h.content, pandoc.Attr("provenance-" .. (h.identifier or "")))
  end
  for _, b in ipairs(doc.blocks) do
    if b.t == "Div" and b.classes:includes("chapter-mark") then
      open(b.content[1])
    elseif b.t == "Header" and b.level == 1 and (b.identifier or ""):match("^s%-") then
      table.insert(out, b)  -- a supplement heading of a chapter already marked
    elseif b.t == "Header" and b.level == 1 then
      open(b)
      table.insert(out, b)
    elseif b.t == "Div" and b.classes:includes("provenance") then
      for f in (b.attributes["files"] or ""):gmatch("[^,]+") do
        if not seen[f] then seen[f] = true; table.insert(files, f) end
      end
      if pending then table.insert(appendix, pending); pending = nil end
      table.insert(appendix, b)
    else
      table.insert(out, b)
    end
  end
  flush()
  if #appendix > 0 and part ~= "paper" then
    table.insert(out, pandoc.Header(1, (part == "docs" and "Appendix" or "Appendix B") ..
                                    ". Provenance of every table and figure",
                                    pandoc.Attr("appendix-provenance")))
    for _, b in ipairs(appendix) do table.insert(out, b) end
  end
  return pandoc.Pandoc(out, doc.meta)
end

return {
  {
    Meta = function(m)
      if m.datadir then datadir = pandoc.utils.stringify(m.datadir) end
      if m.profile then profile = pandoc.utils.stringify(m.profile) end
      if m.part then part = pandoc.utils.stringify(m.part) end
    end
  },
  {
    CodeBlock = function(el)
      if el.classes:includes("tsv") then return tsv_block(el) end
    end,
    Span = function(el)
      if el.classes:includes("datum") then return datum(el) end
      if el.classes:includes("counts") then return counts(el) end
    end,
    Image = function(el)
      if not exists(el.src) then fail("figure missing: " .. el.src) end
      -- The figure's name survives --self-contained (as data-figure), for the browser check.
      local base = el.src:match("([%w_%-]+)%.svg$")
      if base then el.attributes["figure"] = base; return el end
    end,
    -- A figure (an image alone in its paragraph) is followed by its provenance line.
    Para = function(el)
      if #el.content == 1 and el.content[1].t == "Image" then
        local prov = figure_provenance(el.content[1])
        if prov then return {el, prov} end
      end
    end
  },
  { Str = function(el) return caret_inlines(el.text) end },
  { Pandoc = lift_page_one },
  { Pandoc = split_parts },
  { Pandoc = number_figures },
  { Pandoc = gather_provenance }
}
