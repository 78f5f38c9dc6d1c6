-- Korotky (2015) Fig. 2c: a generator conic in its plane with its centre, axes, asymptotes
-- In the section y = const of the conic sweep the generator k2 passes through U0, V0 and T
-- and touches the rulings U0 P and V0 Q of the contact surfaces; its tangents meet in W.
-- Here T lies far out towards W (weight w > 1): k2 is a hyperbola.  korotky.conic_elements
-- gives its centre O (beyond W), the principal axes and the asymptotes e1, e2.
local U0, V0, T = P(-3, 0), P(3, 0), P(0, 2.6)
local tU, tV = V(1, 1.2), V(-1, 1.2)
local k2, w, kind = korotky.conic_arc(U0, tU, V0, tV, T)
local el = korotky.conic_elements(k2)
local O = el.center
window(-6, -1.5, 6, 7.5)
-- the tangents from U0 and V0 to W, and the chord
local W = meet(U0, U0 + tU, V0, V0 + tV)
line(U0, W, 8); line(V0, W, 8); line(U0, V0, 8)
-- the asymptotes (dashed) and the axes through the centre
pen{dash = {5, 3}}
for _, a in ipairs(el.asymptotes) do line(O - a * 9, O + a * 9, 12) end
pen{}
for _, a in ipairs(el.axes) do line(O - a * 4.5, O + a * 4.5, 7) end
k2:draw{color = 11}
pset(O, 15); pset(W, 15); pset(T, 14)
label("$U_0$", U0, nil, 15); label("$V_0$", V0, nil, 15); label("T", T, nil, 14)
label("W", W, nil, 15); label("O", O, nil, 15)
for i, a in ipairs(el.asymptotes) do   -- each asymptote named where it crosses y = 0.8
  label("$e_" .. i .. "$", O + a * ((.8 - O.y) / a.y), a.x * a.y > 0 and "nw" or "ne", 12)
end
label("$k_2$", k2(.25), nil, 11)
label(string.format("%s, w = %.3f, centre O at y = %.3f", kind, w, O.y), P(-3.3, -.95), "e", 7)
label(string.format("semi-axes %.3f, %.3f", el.semi[1], el.semi[2]), P(-3.3, -1.3), "e", 7)
