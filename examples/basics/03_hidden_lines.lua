-- Hidden lines of wireframe surfaces: left out, dashed, and a sphere in perspective
-- A B-spline profile turned into a vase (surface.revolution) seen in axonometry, its hidden
-- iso-lines left out (left) and dashed (right); above, a sphere seen from the eye (3, 4, 2).
local profile = bspline({P(0, 0, 0), P(.9, 0, 0), P(.4, .6, 0), P(.8, 1.2, 0), P(.5, 1.6, 0), P(.6, 2, 0)}, 3)
local vase = surface.revolution(profile, P(0, 0, 0), V(0, 1, 0))
camera(map.translate(V(160, 400)) * map.scale({100, -100}) * map.axonometric(.4, .5))
vase:wireframe{nu = 12, nv = 16, color = 3, hidden = "hide"}
camera(map.translate(V(480, 400)) * map.scale({100, -100}) * map.axonometric(.4, .5))
vase:wireframe{nu = 12, nv = 16, color = 3, hidden = "dashed"}
local sph = surface(function(u, v) return P(math.cos(u)*math.cos(v), math.sin(u)*math.cos(v), math.sin(v)) end, 0, 2*math.pi, -math.pi/2, math.pi/2)
camera(map.translate(V(320, 110)) * map.scale({90, -90}) * map.perspective(P(3, 4, 2), P(0, 0, 0)))
sph:wireframe{nu = 24, nv = 12, color = 14, hidden = "hide"}
label("hidden = \"hide\"", P(160, 460), "c", 15)
label("hidden = \"dashed\"", P(480, 460), "c", 15)
