#include "comm/prelude.hpp"

#include <map>
#include <vector>

namespace aster::comm {
namespace {

struct Helper {
  const char* name;
  std::vector<const char*> needs;
  const char* code;
};

// In dependency order: a helper only calls those above it.
const std::vector<Helper>& helpers() {
  static const std::vector<Helper> list = {
      {"py_dictmt", {}, "local py_dictmt = {}"},
      {"py_dict", {"py_dictmt"}, "local function py_dict(t) return setmetatable(t, py_dictmt) end"},
      {"py_slots", {},
       "local function py_slots(n) return setmetatable({}, {__len = function() return n end}) end"},
      {"py_kwargs", {},
       "local function py_kwargs(t, ...) for i = 1, select('#', ...) do for k, v in pairs((select(i, ...))) do "
       "if t[k] ~= nil then error(\"got multiple values for keyword argument '\" .. tostring(k) .. \"'\", 2) end t[k] = v end end return t end"},
      {"py_truth", {},
       "local function py_truth(v) if v == nil or v == false or v == 0 or v == '' then return false end "
       "if type(v) == 'table' and next(v) == nil then return false end return true end"},
      {"py_num", {},
       "local function py_num(x) if math.type(x) == 'integer' then return string.format('%d', x) end "
       "if x ~= x then return 'nan' elseif x == math.huge then return 'inf' elseif x == -math.huge then return '-inf' end "
       "if x == 0 then return 1 / x < 0 and '-0.0' or '0.0' end "
       "local s for p = 0, 16 do s = string.format('%.' .. p .. 'e', x) if tonumber(s) == x then break end end "
       "local m, e = s:match('^(-?[%d%.]+)e([-+]%d+)$') e = tonumber(e) "
       "local sign = '' if m:sub(1, 1) == '-' then sign = '-' m = m:sub(2) end "
       "local d = m:gsub('%.', ''):gsub('0+$', '') if d == '' then d = '0' end "
       "if e >= -4 and e < 16 then if e < 0 then return sign .. '0.' .. string.rep('0', -e - 1) .. d end "
       "if #d <= e + 1 then return sign .. d .. string.rep('0', e + 1 - #d) .. '.0' end "
       "return sign .. d:sub(1, e + 1) .. '.' .. d:sub(e + 2) end "
       "return sign .. d:sub(1, 1) .. (#d > 1 and '.' .. d:sub(2) or '') .. string.format('e%s%02d', e < 0 and '-' or '+', math.abs(e)) end"},
      {"py_repr", {"py_num", "py_dictmt"},
       "local py_repr "
       "local function py_str(v) local t = type(v) if v == nil then return 'None' elseif v == true then return 'True' "
       "elseif v == false then return 'False' elseif t == 'number' then return py_num(v) elseif t == 'string' then return v "
       "elseif t == 'table' then local parts = {} "
       "if getmetatable(v) == py_dictmt then for k, x in pairs(v) do parts[#parts + 1] = py_repr(k) .. ': ' .. py_repr(x) end "
       "return '{' .. table.concat(parts, ', ') .. '}' end "
       "for _, x in ipairs(v) do parts[#parts + 1] = py_repr(x) end return '[' .. table.concat(parts, ', ') .. ']' end "
       "return tostring(v) end "
       "py_repr = function(v) if type(v) == 'string' then return \"'\" .. v:gsub('\\\\', '\\\\\\\\'):gsub(\"'\", \"\\\\'\"):gsub('\\n', '\\\\n') .. \"'\" end return py_str(v) end"},
      {"py_str", {"py_repr"}, ""},
      {"py_print", {"py_str"},
       "local function py_print(...) local parts = {} for i = 1, select('#', ...) do parts[i] = py_str((select(i, ...))) end "
       "print(table.concat(parts, ' ')) end"},
      {"py_int", {},
       "local function py_int(v) if type(v) == 'string' then local n = tonumber(v) "
       "if n == nil or math.type(n) ~= 'integer' then error(\"invalid literal for int(): '\" .. v .. \"'\", 2) end return n end "
       "if v == true then return 1 elseif v == false then return 0 end "
       "if math.type(v) == 'integer' then return v end local t = v >= 0 and math.floor(v) or math.ceil(v) "
       "return math.tointeger(t) or t end"},
      {"py_float", {},
       "local function py_float(v) if type(v) == 'string' then local s = v:lower():match('^%s*(.-)%s*$') "
       "if s == 'inf' or s == '+inf' or s == 'infinity' then return math.huge elseif s == '-inf' or s == '-infinity' then return -math.huge "
       "elseif s == 'nan' then return 0.0 / 0.0 end local n = tonumber(s) "
       "if n == nil then error(\"could not convert string to float: '\" .. v .. \"'\", 2) end return n + 0.0 end "
       "if v == true then return 1.0 elseif v == false then return 0.0 end return v + 0.0 end"},
      {"py_round", {},
       "local function py_round(x, n) if n and n >= 0 then return tonumber(string.format('%.' .. n .. 'f', x)) + 0.0 end "
       "local m = n and 10.0 ^ n or 1 local y = x * m local f = math.floor(y) local d = y - f "
       "if d > 0.5 or (d == 0.5 and f % 2 == 1) then f = f + 1 end "
       "if n == nil then return math.tointeger(f) or f end return f / m end"},
      {"py_len", {"py_dictmt"},
       "local function py_len(v) if type(v) == 'string' then return #v end "
       "if type(v) == 'table' then if getmetatable(v) == py_dictmt then local n = 0 for _ in pairs(v) do n = n + 1 end return n end return #v end "
       "error('object of type ' .. type(v) .. ' has no len()', 2) end"},
      {"py_format", {"py_str", "py_repr", "py_dictmt"},
       "local function py_format(fmt, args) local list, map = args, nil "
       "if type(args) ~= 'table' then list = {args} elseif getmetatable(args) == py_dictmt then map = args list = {} end "
       "local n, out, i = 0, {}, 1 "
       "while true do local a = fmt:find('%', i, true) if not a then out[#out + 1] = fmt:sub(i) break end "
       "out[#out + 1] = fmt:sub(i, a - 1) local j, name = a + 1, nil "
       "if fmt:sub(j, j) == '(' then local c = fmt:find(')', j, true) if not c then error('incomplete format key', 2) end "
       "name = fmt:sub(j + 1, c - 1) j = c + 1 end "
       "local flags, width, prec, conv, e = fmt:match('^([-+ #0]*)(%d*)(%.?%d*)[hlL]?([diouxXeEfFgGcrs%%])()', j) "
       "if not conv then error(\"unsupported format character at '\" .. fmt:sub(a, a + 3) .. \"'\", 2) end i = e "
       "if conv == '%' then out[#out + 1] = '%' else local v "
       "if name then if not map then error('format requires a mapping', 2) end v = map[name] "
       "else n = n + 1 if n > #list then error('not enough arguments for format string', 2) end v = list[n] end "
       "if conv == 'd' or conv == 'i' or conv == 'u' then v = v >= 0 and math.floor(v) or math.ceil(v) "
       "out[#out + 1] = string.format('%' .. flags .. width .. 'd', v) "
       "elseif conv == 'o' or conv == 'x' or conv == 'X' then out[#out + 1] = string.format('%' .. flags .. width .. conv, math.tointeger(v)) "
       "elseif conv == 's' or conv == 'r' or conv == 'c' then "
       "local s = conv == 'r' and py_repr(v) or (conv == 'c' and type(v) == 'number' and utf8.char(v)) or py_str(v) "
       "out[#out + 1] = string.format('%' .. flags:gsub('[^-]', '') .. width .. prec .. 's', s) "
       "else out[#out + 1] = string.format('%' .. flags .. width .. prec .. (conv == 'F' and 'f' or conv), v) end end end "
       "if map == nil and n < #list then error('not all arguments converted during string formatting', 2) end "
       "return table.concat(out) end"},
      {"py_fmt", {"py_str", "py_repr", "py_num"},
       "local function py_fmt(s, args, kw) local n = 0 "
       "local function one(field, conv, spec) local v if field == '' then n = n + 1 v = args[n] elseif field:match('^%d+$') then v = args[tonumber(field) + 1] "
       "else v = kw and kw[field] if v == nil then error(\"format field '\" .. field .. \"' not given\", 4) end end "
       "if conv == '!r' then v = py_repr(v) elseif conv == '!s' then v = py_str(v) end "
       "local fill, align, rest = '', '', spec "
       "if #spec >= 2 and spec:sub(2, 2):match('[<>=^]') then fill, align, rest = spec:sub(1, 1), spec:sub(2, 2), spec:sub(3) "
       "elseif spec:sub(1, 1):match('[<>=^]') then align, rest = spec:sub(1, 1), spec:sub(2) end "
       "local sign, zero, width, prec, ty = rest:match('^([-+ ]?)(0?)(%d*)(%.?%d*)([bcdeEfFgGnosxX%%]?)$') "
       "if sign == nil then error(\"format spec '\" .. spec .. \"' is not supported\", 4) end "
       "local t if ty == 'd' or ty == 'n' then t = string.format('%d', v >= 0 and math.floor(v) or math.ceil(v)) "
       "elseif ty == '%' then t = string.format('%' .. (prec ~= '' and prec or '.6') .. 'f', v * 100) .. '%' "
       "elseif ty == 'x' or ty == 'X' or ty == 'o' then t = string.format('%' .. ty, v) "
       "elseif ty ~= '' and ty ~= 's' then t = string.format('%' .. (prec ~= '' and prec or ((ty == 'g' or ty == 'G') and '' or '.6')) .. (ty == 'F' and 'f' or ty), v) "
       "elseif type(v) == 'number' and prec ~= '' then t = string.format('%' .. prec .. 'g', v) "
       "else t = py_str(v) if prec ~= '' then t = t:sub(1, tonumber(prec:sub(2))) end end "
       "if sign == '+' and type(v) == 'number' and v >= 0 then t = '+' .. t elseif sign == ' ' and type(v) == 'number' and v >= 0 then t = ' ' .. t end "
       "local w = tonumber(width) or 0 if #t >= w then return t end "
       "if zero == '0' and align == '' then local sg = t:match('^[-+ ]') or '' return sg .. string.rep('0', w - #t) .. t:sub(#sg + 1) end "
       "if fill == '' then fill = ' ' end if align == '' then align = type(v) == 'number' and '>' or '<' end "
       "local pad = w - #t if align == '<' then return t .. string.rep(fill, pad) elseif align == '^' then "
       "return string.rep(fill, pad // 2) .. t .. string.rep(fill, pad - pad // 2) end return string.rep(fill, pad) .. t end "
       "return (s:gsub('(%b{})', function(b) if b == '{}' then return one('', '', '') end local inner = b:sub(2, -2) "
       "local field, conv, spec = inner:match('^([%w_]*)(!?[rs]?):?(.*)$') if field == nil then error(\"format field '\" .. inner .. \"' is not supported\", 3) end "
       "return one(field, conv, spec) end):gsub('{{', '{'):gsub('}}', '}')) end"},
      {"py_add", {},
       "local function py_add(a, b) if type(a) == 'string' and type(b) == 'string' then return a .. b end "
       "if type(a) == 'table' and type(b) == 'table' then local r = {} for _, x in ipairs(a) do r[#r + 1] = x end "
       "for _, x in ipairs(b) do r[#r + 1] = x end return r end "
       "if type(a) ~= 'number' or type(b) ~= 'number' then error('unsupported operand types for +: ' .. type(a) .. ' and ' .. type(b), 2) end return a + b end"},
      {"py_mul", {},
       "local function py_mul(a, b) if type(b) == 'string' or type(b) == 'table' then a, b = b, a end "
       "if type(a) == 'string' then return string.rep(a, math.max(b, 0)) end "
       "if type(a) == 'table' then local r = {} for _ = 1, b do for _, x in ipairs(a) do r[#r + 1] = x end end return r end return a * b end"},
      {"py_mod", {"py_format"},
       "local function py_mod(a, b) if type(a) == 'string' then return py_format(a, b) end return a % b end"},
      {"py_pow", {},
       "local function py_pow(a, b) if math.type(a) == 'integer' and math.type(b) == 'integer' and b >= 0 and math.abs(a + 0.0) ^ b < 2 ^ 63 then "
       "local r = 1 for _ = 1, b do r = r * a end return r end return a ^ b end"},
      {"py_eq", {},
       "local function py_eq(a, b) if type(a) ~= 'table' or type(b) ~= 'table' then return a == b end "
       "if #a ~= #b then return false end for i = 1, #a do if not py_eq(a[i], b[i]) then return false end end return true end"},
      {"py_in", {"py_eq", "py_dictmt"},
       "local function py_in(x, c) if type(c) == 'string' then return string.find(c, x, 1, true) ~= nil end "
       "if getmetatable(c) == py_dictmt then return c[x] ~= nil end "
       "for _, y in ipairs(c) do if py_eq(x, y) then return true end end return false end"},
      {"py_index", {"py_dictmt"},
       "local function py_index(t, i) if type(i) ~= 'number' or getmetatable(t) == py_dictmt then return i end "
       "local n = #t if i < 0 then i = i + n end if i < 0 or i >= n then error('index out of range', 3) end return i + 1 end"},
      {"py_get", {"py_index"},
       "local function py_get(t, i) if type(t) == 'string' then local k = py_index(t, i) return t:sub(k, k) end "
       "local v = t[py_index(t, i)] return v end"},
      {"py_set", {"py_index"}, "local function py_set(t, i, v) t[py_index(t, i)] = v end"},
      {"py_slice", {},
       "local function py_slice(t, lo, hi, step) step = step or 1 local n = #t "
       "local function fix(i, d) if i == nil then return d end if i < 0 then i = i + n end "
       "if step > 0 then return math.max(0, math.min(i, n)) end return math.max(-1, math.min(i, n - 1)) end "
       "local a, b if step > 0 then a, b = fix(lo, 0), fix(hi, n) else a, b = fix(lo, n - 1), fix(hi, -1) end "
       "local r = {} local i = a while (step > 0 and i < b) or (step < 0 and i > b) do "
       "if type(t) == 'string' then r[#r + 1] = t:sub(i + 1, i + 1) else r[#r + 1] = t[i + 1] end i = i + step end "
       "if type(t) == 'string' then return table.concat(r) end return r end"},
      {"py_range", {},
       "local function py_range(a, b, s) if b == nil then a, b = 0, a end s = s or 1 "
       "if s == 0 then error('range() arg 3 must not be zero', 2) end local r = {} local i = a "
       "while (s > 0 and i < b) or (s < 0 and i > b) do r[#r + 1] = i i = i + s end return r end"},
      {"py_list", {"py_dictmt"},
       "local function py_list(v) local r = {} if v == nil then return r end "
       "if type(v) == 'string' then for c in v:gmatch('.') do r[#r + 1] = c end return r end "
       "if getmetatable(v) == py_dictmt then error('iteration over a dict is not supported (its order is not kept)', 2) end "
       "for _, x in ipairs(v) do r[#r + 1] = x end return r end"},
      {"py_iter", {"py_list"}, "local function py_iter(v) return ipairs(py_list(v)) end"},
      {"py_enumerate", {"py_list"},
       "local function py_enumerate(v, start) local t = py_list(v) local i = 0 "
       "return function() i = i + 1 if i <= #t then return i - 1 + (start or 0), t[i] end end end"},
      {"py_zip", {"py_list"},
       "local function py_zip(...) local ts = {...} for k = 1, #ts do ts[k] = py_list(ts[k]) end local i = 0 "
       "return function() i = i + 1 local out = {} for k = 1, #ts do if i > #ts[k] then return nil end out[k] = ts[k][i] end "
       "return table.unpack(out) end end"},
      {"py_sorted", {"py_list"},
       "local function py_sorted(v) local r = py_list(v) table.sort(r) return r end"},
      {"py_sum", {"py_list"},
       "local function py_sum(v, s) s = s or 0 for _, x in ipairs(py_list(v)) do s = s + x end return s end"},
      {"py_min", {"py_list"},
       "local function py_min(...) local t = select('#', ...) == 1 and py_list((...)) or {...} local m = t[1] "
       "for i = 2, #t do if t[i] < m then m = t[i] end end return m end"},
      {"py_max", {"py_list"},
       "local function py_max(...) local t = select('#', ...) == 1 and py_list((...)) or {...} local m = t[1] "
       "for i = 2, #t do if t[i] > m then m = t[i] end end return m end"},
      {"py_join", {},
       "local function py_join(sep, t) for _, x in ipairs(t) do if type(x) ~= 'string' then "
       "error('join expects strings, got a ' .. type(x), 2) end end return table.concat(t, sep) end"},
      {"py_split", {},
       "local function py_split(s, sep) local r = {} if sep == nil then for w in s:gmatch('%S+') do r[#r + 1] = w end return r end "
       "local i = 1 while true do local a, b = string.find(s, sep, i, true) if not a then r[#r + 1] = s:sub(i) return r end "
       "r[#r + 1] = s:sub(i, a - 1) i = b + 1 end end"},
      {"py_startswith", {}, "local function py_startswith(s, p) return s:sub(1, #p) == p end"},
      {"py_endswith", {}, "local function py_endswith(s, p) return #p == 0 or s:sub(-#p) == p end"},
      {"py_strip", {}, "local function py_strip(s) return (s:match('^%s*(.-)%s*$')) end"},
      {"py_replace", {},
       "local function py_replace(s, a, b) return (s:gsub(a:gsub('[%^%$%(%)%%%.%[%]%*%+%-%?]', '%%%0'), (b:gsub('%%', '%%%%')))) end"},
      {"py_extend", {"py_list"},
       "local function py_extend(t, v) for _, x in ipairs(py_list(v)) do t[#t + 1] = x end end"},
      {"py_or", {"py_truth"}, "local function py_or(a, b) if py_truth(a) then return a end return b end"},
      {"py_and", {"py_truth"}, "local function py_and(a, b) if not py_truth(a) then return a end return b end"},
      {"py_orf", {"py_truth"}, "local function py_orf(a, f) if py_truth(a) then return a end return f() end"},
      {"py_andf", {"py_truth"}, "local function py_andf(a, f) if not py_truth(a) then return a end return f() end"},
      {"py_fabs", {}, "local function py_fabs(x) return math.abs(x) + 0.0 end"},
      {"py_hypot", {}, "local function py_hypot(a, b) return math.sqrt(a * a + b * b) end"},
      {"py_sinh", {}, "local function py_sinh(x) return (math.exp(x) - math.exp(-x)) / 2 end"},
      {"py_cosh", {}, "local function py_cosh(x) return (math.exp(x) + math.exp(-x)) / 2 end"},
      {"py_tanh", {}, "local function py_tanh(x) local a, b = math.exp(x), math.exp(-x) return (a - b) / (a + b) end"},
  };
  return list;
}

}  // namespace

bool isHelperName(const std::string& name) { return name.rfind("py_", 0) == 0; }

std::string prelude(const std::set<std::string>& used) {
  std::map<std::string, const Helper*> byName;
  for (const auto& h : helpers()) byName[h.name] = &h;
  std::set<std::string> all;
  std::vector<std::string> stack(used.begin(), used.end());
  while (!stack.empty()) {
    const std::string n = stack.back();
    stack.pop_back();
    if (!all.insert(n).second) continue;
    const auto it = byName.find(n);
    if (it != byName.end())
      for (const char* d : it->second->needs) stack.push_back(d);
  }
  std::string out;
  for (const auto& h : helpers()) {
    if (!all.count(h.name) || !*h.code) continue;
    out += h.code;
    out += ' ';
  }
  return out;
}

}  // namespace aster::comm
