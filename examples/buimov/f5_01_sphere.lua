-- The unit sphere with its latitudes and longitudes
-- Buimov §5.1, Fig. 5.1: x = cos Theta sin Phi, y = sin Theta sin Phi, z = cos Phi (the book
-- prints y = sin Theta cos Phi); a latitude is the cut by the plane z = cos Phi1, a circle of
-- radius sin Phi1, a longitude the cut by the plane x sin Theta0 - y cos Theta0 = 0. Every 30° of
-- Theta and Phi, the outline drawn; what the sphere hides is dashed.

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
local v = view3(-60, 20, 170, P(0, 0, 0), 320, 225)
camera(v, {hidden = "dashed"})
local s = buimov.sphere()
s:wireframe{nu = 12, nv = 6, color = 9, silhouette = true}
for _, ax in ipairs{V(1.5, 0, 0), V(0, 1.5, 0), V(0, 0, 1.4)} do line(P(0, 0, 0), P(0, 0, 0) + ax,
  7) end
-- one latitude Phi1 = 60° and one longitude Theta0 = 30° in colour
local ph1, th0 = pi / 3, pi / 6
curve(function(t) return s(t, ph1) end, 0, 2 * pi):draw{color = 14}
curve(function(t) return s(th0, t) end, 0, pi):draw{color = 10}
camera(nil)
for _, a in ipairs{{P(1.5, 0, 0), "$x$"}, {P(0, 1.5, 0), "$y$"}, {P(0, 0, 1.4),
  "$z$"}} do label(a[2], v(a[1]), nil, 7) end
label("$\\varphi_1 = 60^\\circ$", v(s(pi / 2, ph1)), nil, 14)
label("$\\theta_0 = 30^\\circ$", v(s(th0, 2 * pi / 3)), nil, 10)
caption("latitude z = cos $\\Phi_1$ (yellow), longitude x sin $\\Theta_0$ = y cos $\\Theta_0$ (green)", "bottom", 7)
