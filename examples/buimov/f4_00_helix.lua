-- The helix x = a cos t, y = a sin t, z = b t
-- Buimov §4.1: the space curve of the chapter's opening, a = 1, b = 0.15, two and a half turns
-- (t from 0 to 5 pi), seen from the azimuth 30°, elevation 20° with z up: the turns behind the
-- axis are hidden by nothing (a curve hides nothing), so the cylinder x^2 + y^2 = a^2 it lies on
-- is drawn as a surface that hides them: the back half of every turn is dashed.

local a, b = 1, 0.15
local h = buimov.helix(a, b, 0, 5 * math.pi)
local top = b * 5 * math.pi
local cyl = surface(function(u, v) return P(a * math.cos(u) * 0.999, a * math.sin(u)
    * 0.999, v) end, 0, 2 * math.pi, 0, top)
camera(map.translate(V(320, 410)) * map.scale({120, -120})
    * map.view{azimuth = 30, elevation = 20}, {hidden = "dashed"})
cyl:wireframe{nu = 0, nv = 0, silhouette = true, color = 8}
h:draw{color = 14}
line(P(0, 0, 0), P(0, 0, top + 0.5), 7)
for _, t in ipairs{0, math.pi, 2 * math.pi} do mark(h(t), "dot", 4, 15) end
label("$t = 0$", h(0), nil, 15)
label("$t = 2\\pi$", h(2 * math.pi), nil, 15)
label("$z$", P(0, 0, top + 0.5), nil, 7)
camera(nil)
caption("a = 1, b = 0.15:  (cos t, sin t, 0.15 t), t in [0, 5 $\\pi$]", "bottom", 7)
