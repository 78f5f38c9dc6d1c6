-- LuaRocks: `luarocks --lua-version 5.4 make` in the source tree (or in the unpacked tarball of
-- `./build.sh dist`) builds the C module with CMake
-- (Lua and libpng found through pkg-config; the VGA fonts from Debian's console-setup-linux and
-- vgabios) and installs it, so that `lua5.4 -e 'require "pointcalc"'` works. Only the module is built: the
-- pointcalc program, its man page and the examples come with `./build.sh install` or the .deb.
rockspec_format = "3.0"
package = "pointcalc"
version = "0.1.0-1"
source = {
   -- the release tarball `./build.sh dist` writes (build/pointcalc-0.1.0.tar.gz): `luarocks pack`
   -- and `luarocks build` run beside it fetch it from there; `luarocks make` in the unpacked
   -- tree needs no fetching
   url = "pointcalc-0.1.0.tar.gz",
   dir = "pointcalc-0.1.0",
}
description = {
   summary = "Geometry scripting: point calculus and QBasic-style drawing (PNG, SVG, PPM)",
   detailed = [[
Weighted points and vectors, ratios, meets, simplices, projective maps, one curve type
(Bezier, B-spline/NURBS, Hermite, splines, interpolation) and one surface type, and QBasic's
SCREEN 12 drawing statements rendering to PNG, SVG and PPM, as a Lua 5.4 C module:
local pc = require "pointcalc".]],
   license = "MIT",   -- LICENSE
   labels = { "geometry", "graphics", "svg", "png" },
}
dependencies = {
   "lua >= 5.4, < 5.5",
}
external_dependencies = {
   -- found by CMake through pkg-config; listed so that LuaRocks says what is missing
   PNG = { header = "png.h" },
   CAIRO = { header = "cairo/cairo.h" },   -- the print look (libcairo2-dev, libpango1.0-dev)
   PANGO = { header = "pango-1.0/pango/pangocairo.h" },
}
build = {
   type = "cmake",
   variables = {
      CMAKE_BUILD_TYPE = "Release",
      PC_MODULE_ONLY = "ON",
      PC_LUA_CMOD_DIR = "$(LIBDIR)",
      CMAKE_INSTALL_PREFIX = "$(PREFIX)",
   },
}
