-- Example 12 — Closed "archetype" curve through 2n points by a finite Fourier series
-- 2n = 32 points (white circles of radius 3) on the astroid x = cos^3 u, y = sin^3 u, u = i pi/n,
-- each shifted by up to .3 in x and y by QBasic's RND, and the closed curve through all of them
-- (white thick dots): the trigonometric interpolation of Hamming (§H block 11, `fourier`),
--   a_k = (1/n) sum f(i) cos(pi k i/n),  b_k = (1/n) sum f(i) sin(pi k i/n),
--   f(u) = a_0/2 + sum_(k=1..n-1) (a_k cos ku + b_k sin ku) + (a_n/2) cos nu,
-- for x and for y. It is only a carrier of the points (an archetype): a wobbly four-lobed star,
-- shifted up and right by the noise, that runs off the top of the screen.
-- Mathematical coordinates, scale 200 about (320, 240), y up. The random shifts are QBasic's
-- RND sequence (`qb.rnd`), drawn in the listing's order: 2n + 1 values for x (the last unused),
-- then 2n + 1 for y. QBasic's `for u = 0 to 2*pi step pi/(8*n)` gives 256 dots (qb = true).

screen(12)
local n, pi = 16, math.pi
local dx, dy = {}, {}
for i = 0, 2*n do dx[i] = qb.rnd(1)*.3 end
for i = 0, 2*n do dy[i] = qb.rnd(1)*.3 end
local points = {}
for i = 0, 2*n - 1 do
  local u = i*pi/n
  points[#points + 1] = P(math.cos(u)^3 + dx[i], math.sin(u)^3 + dy[i])
end

local screen_of = screenmap(320, 240, 200)
for _, A in ipairs(points) do circle(P(screen_of(A)), 3) end
fourier(points):draw{t = {0, 2*pi, pi/(8*n)}, qb = true, brush = "dot", map = screen_of}
