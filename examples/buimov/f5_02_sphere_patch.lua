-- The sphere patch with its corner tangent, twist and normal vectors
-- Buimov §5.1, Fig. 5.2: 0 <= Theta <= pi/2, pi/4 <= Phi <= pi/2, the corners A (0, pi/2),
-- B (0, pi/4), C (pi/2, pi/4), D (pi/2, pi/2). At each corner the tangents S_Theta (red) and
-- S_Phi (green), the twist S_ThetaPhi (magenta; zero at A and D) and the normal
-- N = S_Theta x S_Phi (blue, inwards; N_B = -(e1 + e3)/2, the book prints -(e1 + e2)/2), all at
-- half length; what the patch hides is dashed.

local pi = math.pi
-- the view: azimuth and elevation with z up, scale px per unit, the point `to` at (cx, cy) px
local function view3(az, el, scale, to, cx, cy)
  return map.translate(V(cx or 320, cy or 235)) * map.scale({scale, -scale})
       * map.view{azimuth = az, elevation = el, to = to or P(0, 0, 0)}
end
-- a 3-D point marked and lettered (the letter on its image, so a hidden point keeps its name)
local function dot3(view, p, name, colour)
  mark(view(p), "dot", 4, colour); if name then label(name, view(p), nil, colour) end
end
local v = view3(30, 25, 210, P(0.45, 0.45, 0.4), 330, 230)
camera(v, {hidden = "dashed"})
buimov.sphere(0, pi / 2, pi / 4, pi / 2):wireframe{nu = 6, nv = 4, boundary = true, color = 8}
local corners = {{0, pi / 2, "A"}, {0, pi / 4, "B"}, {pi / 2, pi / 4, "C"}, {pi / 2, pi / 2, "D"}}
local tips = {}
for _, c in ipairs(corners) do
  local S, St, Sp, tw, N = buimov.sphere_frame(c[1], c[2])
  vector(S, St * 0.5, 12); vector(S, Sp * 0.5, 10); vector(S, N * 0.5, 11)
  if dist(tw) > 1e-12 then vector(S, tw * 0.5, 13) end
  tips[#tips + 1] = {S, c[3], St, Sp, tw, N}
end
camera(nil)
for _, t in ipairs(tips) do dot3(v, t[1], "$" .. t[2] .. "$", 15) end
local B = tips[2]
label("$S_\\theta$", v(B[1] + B[3] * 0.5), nil, 12)
label("$S_\\varphi$", v(B[1] + B[4] * 0.5), nil, 10)
label("$S_{\\theta\\varphi}$", v(B[1] + B[5] * 0.5), nil, 13)
label("$N$", v(B[1] + B[6] * 0.5), nil, 11)
caption("N_B = -(e1 + e3)/2;  twist e2/sqrt 2 at B, -e1/sqrt 2 at C, 0 at A, D", "bottom", 7)
