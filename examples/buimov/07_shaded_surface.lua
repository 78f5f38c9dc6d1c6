-- A shaded surface with its mesh: z = 0.5 sin 3x cos 2y over [-1, 1]^2 in 40 x 40 quads
-- Beyond the textbook: Buimov ch. 5 draws its surfaces as iso-line wireframes and has no
-- lighting. Here the surface is cut into 40 x 40 quads, each filled with one flat shade of white
-- by Lambert's cosine law (the cosine of the angle between its normal and the light, with a
-- little ambient light) and drawn farthest first (the painter's method, by the depth of each
-- quad's centre), each quad's outline drawn with it, so only the visible parts of the mesh
-- show. The same figure as Asymptote's `draw(surface(f, (-1,-1), (1,1), nx=40, Spline), white,
-- meshpen=black)`, seen orthographically from the direction (4, 2, 3), z up.
local w = unit(V(4, 2, 3))                      -- towards the viewer
local r = unit(cross(V(0, 0, 1), w))            -- the picture's x axis
local u = cross(w, r)                           -- and its y axis: z up
local view = map.matrix({{r.x, r.y, r.z, 0}, {u.x, u.y, u.z, 0}, {0, 0, 0, 1}})
camera(map.translate(V(320, 250)) * map.scale({170, -170}) * view)

local function f(x, y) return 0.5 * math.sin(3 * x) * math.cos(2 * y) end
local s = surface(function(x, y) return P(x, y, f(x, y)) end, -1, 1, -1, 1)
s:shade{nu = 40, nv = 40, color = "#ffffff", mesh = "#000000", light = V(1, -1, 3), ambient = 0.15}

camera(nil)
label("z = 0.5 sin 3x cos 2y: 40 x 40 shaded quads, painter's order", P(320, 440), "c", 7)
