-- The textbook's figures in the gallery (issue 24): every figure number of the book (the
-- digest's list; the book has no Fig. 1.15, and its "3.10"/"3.11" are figures of §2.8.5) is
-- cited by a script of its own in examples/buimov/, as examples/render_gallery.sh reads it: the
-- first "Fig. N" of the opening comment. Then the vanishing points the perspective figures
-- draw, by the same maps.
local check = dofile(arg[0]:match("^(.-)[^/]*$") .. "check.lua")
local eq, near = check.eq, check.near
local root = arg[0]:match("^(.-)tests/lua/[^/]*$") or "./"

local scripts = {
  ["1.1"] = "f1_01_x_stretch", ["1.2"] = "f1_02_x_reflect_stretch", ["1.3"] = "f1_03_nonuniform_scale",
  ["1.4"] = "f1_04_reflect_origin", ["1.5"] = "f1_05_y_shear", ["1.6"] = "f1_06_x_shear",
  ["1.7"] = "f1_07_segment_shear", ["1.8"] = "f1_08_intersecting_lines", ["1.9"] = "f1_09_rotation_90",
  ["1.10"] = "f1_10_reflections", ["1.11"] = "f1_11_uniform_scale", ["1.12"] = "f1_12_unit_square",
  ["1.13"] = "f1_13_square_rotation", ["1.14"] = "f1_14_overall_scale", ["1.16"] = "f1_16_central_projection",
  ["2.1"] = "f2_01_scale_to_cube", ["2.2"] = "f2_02_rotations", ["2.3"] = "f2_03_direction_cosines",
  ["2.4"] = "f2_04_axis_rotation", ["2.5"] = "f2_05_projectors", ["2.6"] = "f2_06_top_view",
  ["2.7"] = "f2_07_dimetric", ["2.8"] = "f2_08_isometric", ["2.9"] = "f2_09_perspective_geometry",
  ["3.10"] = "f2_09a_uncentred_perspective", ["3.11"] = "f2_09b_centred_perspective",
  ["2.10"] = "f2_10_one_point_p", ["2.11"] = "f2_11_two_point", ["2.12"] = "f2_12_rotated_two_point",
  ["3.1"] = "f3_01_circle_slopes", ["3.2"] = "f3_02_circle_points", ["3.3"] = "f3_03_ellipse",
  ["3.4"] = "f3_04_ellipse_points", ["3.5"] = "f3_05_parabola", ["3.6"] = "f3_06_hyperbola",
  ["4.1"] = "f4_01_physical_spline", ["4.2"] = "f4_02_hermite_segment", ["4.3"] = "f4_03_tangent_lengths",
  ["4.4"] = "f4_04_bezier", ["4.5"] = "f4_05_bezier_shapes", ["4.6"] = "f4_06_g1_joint",
  ["4.7"] = "f4_07_bspline_orders", ["4.8"] = "f4_08_multiple_vertex", ["4.9"] = "f4_09_local_control",
  ["5.1"] = "f5_01_sphere", ["5.2"] = "f5_02_sphere_patch", ["5.3"] = "f5_03_bilinear",
  ["5.4"] = "f5_04_ruled", ["5.5"] = "f5_05_coons", ["5.6"] = "f5_06_bezier_patch",
  ["5.7"] = "f5_07_bezier_5x3",
}
-- the figure a script cites: the first "Fig. N" (or "Figs. N") of its opening comment
local function cited(name)
  local f = assert(io.open(root .. "examples/buimov/" .. name .. ".lua"))
  local head = {}
  for line in f:lines() do
    if not line:match("^%-%-") then break end
    head[#head + 1] = line:gsub("^%-%- *", "")
  end
  f:close()
  return table.concat(head, " "):match("Figs?%.? (%d+%.%d+)")
end
local count = 0
for fig, name in pairs(scripts) do
  eq(cited(name), fig, name .. ".lua cites Fig. " .. fig)
  count = count + 1
end
eq(count, 51, "every figure number of the book: 1.1-1.14, 1.16, 2.1-2.12, 3.10, 3.11, 3.1-3.6, 4.1-4.9, 5.1-5.7")
eq(cited("f2_06a_three_views"), nil, "the extra sections' scripts cite no figure of another")

-- the vanishing points the perspective figures label, by the scripts' maps
local pz, O = map.orthographic("z"), P(0, 0, 0)
local vx, vy, vz = (pz * map.perspective_pqr(0, 0, 0.5)):vanishing_points()
eq(vx, nil, "Fig. 3.10: x stays at infinity"); eq(vy, nil, "and y")
near(dist(vz, P(0, 0)), 0, 1e-12, "Fig. 3.10: V_z = [0 0 1/r 1] projects to (0, 0)")
vx = (pz * map.perspective_pqr(0.5, 0, 0)):vanishing_points()
near(dist(vx, P(2, 0)), 0, 1e-12, "Fig. 2.10 a: V_x = (1/p, 0)")
local two = pz * map.perspective_pqr(0, 0, 0.5) * map.translate(V(0, -0.5, 0)) * map.rotate(O, V(0, 1, 0), math.pi / 3)
vx, vy, vz = two:vanishing_points()
near(vx.x, -1.154701, 1e-6, "Fig. 2.12: V_x = -k cot theta"); near(vz.x, 3.464102, 1e-6, "V_z = k tan theta")
near(vx.y, 0, 1e-12, "both on the eye's level y = 0, the cube moved below it by m"); eq(vy, nil, "the y edges stay parallel")
local fx, fy, fz = map.foreshortening(map.axonometric(math.rad(30), math.rad(40)))
near(fx, 0.923739, 1e-6, "the trimetric figure: fx"); near(fy, 0.766044, 1e-6, "fy"); near(fz, 0.748253, 1e-6, "fz")
check.done()
