-- Konopatsky §3.4 (Table 3.1): curves of double contact for eleven blending functions, with their curvature
-- M = P(1 - f(v)) + Q f(v) of the arcs (2.97) P (k_p) and Q (k_q) in the simplex A(0,0), B(10,0),
-- C(4,6) (the table gives no coordinates): the curve in green, its curvature graph (s |kappa| over
-- v in [0, 1] along AB) in blue; two (k_p, k_q) pairs per f, as the table lists them.  The book
-- scales the curvature by 10; a panel whose peak would not fit takes the scale s that brings its
-- peak to the top (printed in its corner).  For negative k the arcs pass through infinity and the
-- curve breaks into pieces; f = ln v is taken from v = 0.001 (its limit at 0 is A).
local A, B, C = P(0, 0), P(10, 0), P(4, 6)
local rows = {
  {"0.5", function() return 0.5 end, {0.3, 0.5}, {0.2, 0.8}},
  {"0.5", function() return 0.5 end, {1.3, 0.5}, {1.2, 1.8}},
  {"0.5", function() return 0.5 end, {-0.5, 0.5}, {-1.4, -0.4}},
  {"v^5", function(v) return v ^ 5 end, {0.4, 0.7}, {0.5, 0.3}},
  {"sin v", math.sin, {0.3, 0.5}, {0.7, 0.5}},
  {"sin^2 v", function(v) return math.sin(v) ^ 2 end, {0.3, 0.5}, {0.7, 0.5}},
  {"tg v", math.tan, {0.4, 0.2}, {0.8, 0.5}},
  {"arccos v", math.acos, {0.4, 0.2}, {0.7, 0.8}},
  {"sh v", function(v) return (math.exp(v) - math.exp(-v)) / 2 end, {0.5, 0.3}, {0.6, 0.8}},
  {"ln v", math.log, {0.4, 0.5}, {0.7, 0.8}},
  {"|v|", math.abs, {0.3, 0.5}, {0.4, 0.7}},
}
for i, row in ipairs(rows) do
  for j = 1, 2 do
    local cell = (i - 1) * 2 + (j - 1)
    local col, r = cell % 4, cell // 4
    view(col * 160 + 1, r * 80 + 1, col * 160 + 158, r * 80 + 78)
    window(-2, -7.5, 12, 8)   -- room below the graph for the caption
    local k = row[2 + j]
    path({A, C, B}, {color = 8})
    local M = oneratio.double_contact(A, B, C, k[1], k[2], row[2])
    local v0 = row[1] == "ln v" and 0.001 or 0
    M:sub(v0, 1):draw{color = 10}
    local kap, peak = {}, 0
    for s = 0, 100 do
      local ok, c = pcall(M.curvature, M, v0 + (1 - v0) * s / 100)
      if ok and c == c and math.abs(c) < 1e3 then kap[s] = math.abs(c); peak = math.max(peak, kap[s]) end
    end
    local room = 9.6                        -- from the baseline -3.4 to 6.2, under the scale's corner
    local scale = peak * 10 > room and room / peak or 10
    local graph, seg = {}, {}
    for s = 0, 100 do
      if kap[s] then seg[#seg + 1] = P(10 * (v0 + (1 - v0) * s / 100), scale * kap[s] - 3.4)
      elseif #seg > 0 then graph[#graph + 1], seg = seg, {} end
    end
    if #seg > 1 then graph[#graph + 1] = seg end
    for _, g in ipairs(graph) do if #g > 1 then path(g, {color = 9}) end end
    label(string.format("%s  %.1f %.1f", row[1], k[1], k[2]), P(-1.8, -3.6), "se", 7)
    if scale ~= 10 then label(string.format("s = %.2g", scale), P(11.9, 8), "sw", 9) end
  end
end
