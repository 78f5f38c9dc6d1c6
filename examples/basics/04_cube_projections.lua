-- A cube in isometric projection and in the textbook's two-point perspective
-- Buimov §2.8.4 and §2.8.5 (Fig. 2.12): the unit cube ABCDEFGH drawn through the camera, once
-- isometric (equal foreshortening 0.8165 on all three axes) and once turned 60° about y and seen
-- (moved down by 0.6) by the one-point transform with k = 2: a two-point perspective; its vanishing
-- points lie on the x axis at -k cot 60° = -1.1547 and k tan 60° = 3.4641.
local cube = {A = P(0, 0, 0), E = P(0, 0, 1), B = P(0, 1, 0), F = P(0, 1, 1),
              D = P(1, 0, 0), H = P(1, 0, 1), C = P(1, 1, 0), G = P(1, 1, 1)}
local edges = {"AB", "BC", "CD", "DA", "EF", "FG", "GH", "HE", "AE", "BF", "CG", "DH"}

local function draw_cube(colour, where)
  for _, e in ipairs(edges) do line(cube[e:sub(1, 1)], cube[e:sub(2, 2)], colour) end
  for name in ("ABCDEFGH"):gmatch(".") do label(name, cube[name], where[name] or "ne", 15) end
end

-- left: isometric, 90 pixels to the unit, y up; the view runs along the diagonal DF, so D
-- and F fall on one point
camera(map.translate(V(120, 280)) * map.scale({90, -90}) * map.isometric())
draw_cube(11, {A = "w", B = "w", C = "n", D = "sw", E = "s", F = "ne", G = "e", H = "e"})
camera(nil)
label("isometric", P(120, 440), "c", 7)

-- right: the book's matrix typed as printed (row vectors), then onto the picture plane z = 0
local k, th = 2, math.rad(60)
local l, m, n = 0, -0.6, 0          -- the book's translation: the cube below the eye
local T = map.matrix({{ math.cos(th), 0, -math.sin(th), -math.sin(th) / k},
                      { 0,            1,  0,             0},
                      { math.sin(th), 0,  math.cos(th),  math.cos(th) / k},
                      { l,            m,  n,             n / k + 1}}, "row")
local picture = map.orthographic("z") * T
local screen = map.translate(V(380, 280)) * map.scale({60, -60})
camera(screen * picture)
draw_cube(14, {A = "sw", E = "s", D = "se", H = "se", B = "nw", F = "n", C = "n", G = "ne"})
camera(nil)
-- the vanishing points: the images of the x and z directions (the y edges stay parallel)
local vx, vy, vz = picture:vanishing_points()
for _, v in ipairs{{vx, "Vx"}, {vz, "Vz"}} do
  circle(screen(v[1]), 3, 12)
  label(v[2], screen(v[1]), "s", 12)
end
pen{dash = {3, 3}}
local img = screen * picture
for _, e in ipairs{"D", "C", "H", "G"} do line(img(cube[e]), screen(vx), 8) end   -- x edges
for _, e in ipairs{"E", "F", "G", "H"} do line(img(cube[e]), screen(vz), 8) end   -- z edges
pen()
label("two-point perspective", P(440, 420), "c", 7)
label(string.format("Vx = (%.4f, 0), Vz = (%.4f, 0)", vx.x, vz.x), P(440, 440), "c", 7)
label(vy and "" or "y edges stay parallel (no Vy)", P(440, 460), "c", 7)
