-- Example 11 — Stamnos (antique vase) outline
-- A closed white outline (one pixel per sample) of a Greek vase, symmetric about x = 320: flat
-- base, a small foot ring, the belly widest at y = 200, the neck and an out-turned lip under a
-- flat top. The right half is Example 10's one-stroke curve (§H block 8, `stroke`) through eight
-- nodes: 0 and 7 the ends on the axis, 3 and 4 the extremes of x, 5 an inflection, 2 a kink,
-- 1 and 6 where the curve changes character. Each sample is also plotted mirrored,
-- x -> 2 x0 - x (§H block 10). The offsets a1..a4 and heights h1..h5 vary the shape.
-- Reconstructed, as in the cleaned listing: the article prints only the node part and the
-- incoming angles; the other parameters are those of the same stamnos in Example 32 (with its
-- missing 8th kink value 0), and the nodes are not marked.
-- 1001 samples per piece, as QBasic (qb = true).

screen(12)
local a1, a2, a3, a4 = 90, 205, 105, 135             -- horizontal offsets from the axis
local h1, h2, h3, h4, h5 = 10, 210, 300, 320, 330     -- heights above the base
local x0, y0 = 320, 410                               -- the axis and the base line
local x = {x0, x0 + a1, x0 + a1, x0 + a2, x0 + a3, x0 + a4, x0 + a4, x0}
local y = {y0, y0, y0 - h1, y0 - h2, y0 - h3, y0 - h4, y0 - h5, y0 - h5}

local half = stroke{x = x, y = y,
  uin  = {0, 0, .5, .25, .25, 0, .5, .5},             -- incoming tangent angles, turns
  kink = {0, 0, -.25, 0, 0, 0, 0, 0},                 -- the kink at node 2
  rin  = {20, 20, 20, 150, 150, 20, 20, 20},
  rout = {20, 20, 150, 150, 20, 20, 20, 20},
  n    = {2, 4, 2, 2, 2, 2, 2, 2},
  m    = {2, 4, 2, 2, 2, 2, 2, 2},
  t0   = .5}
half:draw{t = {0, 1, .001}, qb = true,
          brush = function(px, py) pset(px, py); pset(2*x0 - px, py) end}
