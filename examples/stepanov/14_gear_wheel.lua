-- Example 14 — Gear wheel
-- A green gear with 24 teeth, 6 rounded windows between rim and hub (the spokes are the material
-- left between them) and a hub circle, centred at (300, 240).  Every outline is a smooth
-- junction of two "parallels" of the polar system: X = C(r_a, u_a) + k(t) (C(r_b, u_b) - C(r_a, u_a)),
-- with k the symmetric power half-spline of degree 5 (example 7, smooth.power(5)).
-- A tooth falls from the tip circle r0 to the root circle r1 at the same angle, then rises
-- again a half-pitch later.  A window flank runs from the rim circle r2 to the hub circle r3
-- while the angle turns 7 pi/m the other way; the mirror flank turns the opposite way.
-- Since the polar map is linear in r, a tooth flank is simply the curve r = lerp(r0, r1, k(t))
-- of the polar system.  Polar angles are counter-clockwise on the screen (w = y0 - r sin u).
-- The listing's spoke loops read the centre as (x1, y1), never assigned; the cleaned listing
-- (and this script) use the wheel centre.  As in the listing, the loops run i = 0..m and
-- 0..m/4, so the first tooth and window are drawn twice.

screen(12)
local pi, cos, sin = math.pi, math.cos, math.sin
local r0, r1, r2, r3, r4 = 200, 175, 150, 50, 30     -- tip, root, rim, hub, hub circle
local m = 24                                         -- teeth
local k = smooth.power(5)
local t = {0, 1, .001, qb = true}

-- the polar system about the wheel's centre (300, 240), angles counter-clockwise on the screen
local polar = curvilinear(function(r, u) return 300 + r*cos(u), 240 - r*sin(u) end)

-- a tooth: its flanks join the parallels r0 and r1 at the same angle, so each flank is the
-- curve r = r0 + k(t)(r1 - r0) of the polar system, falling and then (half a pitch on) rising
for i = 0, m do
  local ug = 2*pi*i/m
  polar:draw(function(t) return lerp(r0, r1, k(t)), ug + pi*t/m end, {t = t, color = 2})
  ug = ug + pi/m
  polar:draw(function(t) return lerp(r1, r0, k(t)), ug + pi*t/m end, {t = t, color = 2})
end

-- a window: each flank runs from the rim r2 to the hub r3 while the angle turns back by w, the
-- mirror flank the other way: X = C2 + k(t)(C3 - C2) between points of the two parallels
local w = 7*pi/m
for i = 0, m/4 do
  local ug = 2*pi*i/(m/4)
  for _, side in ipairs{1, -1} do
    plot(function(t)
      local du = w*t
      return lerp(polar(r2, ug + side*du), polar(r3, ug + side*(w - du)), k(t))
    end, {t = t, color = 2})
  end
end

circle(300, 240, r4, 2)                              -- the hub
