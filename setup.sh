#!/bin/sh
# Install the Debian packages pointcalc needs to build and test.
# As root the missing ones are installed with apt-get; otherwise the exact command is printed.
set -e
PKGS="build-essential cmake pkg-config liblua5.4-dev lua5.4 libcmocka-dev libpng-dev libedit-dev libxml2-utils python3 console-setup-linux vgabios libmicrohttpd-dev libcairo2-dev libpango1.0-dev libfontconfig-dev fonts-cmu fonts-dejavu-core"
# what the install, notebook and gallery-page tests use (man -l, luarocks make, cpack's
# dpkg-shlibdeps, completion in bash and zsh, Jupyter's client and kernel libraries, a
# headless browser; the print-look tests: poppler-utils, ghostscript, librsvg2-bin): installed
# as root like the rest; without root a missing one is only noted
TEST_PKGS="man-db luarocks dpkg-dev chromium poppler-utils ghostscript librsvg2-bin bash-completion zsh groff-base python3-ipykernel python3-jupyter-client jupyter-client"
installed() { dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q "ok installed"; }
missing=""
for p in $PKGS; do
    installed "$p" || missing="$missing $p"
done
missing_tests=""
for p in $TEST_PKGS; do
    installed "$p" || missing_tests="$missing_tests $p"
done
if [ "$(id -u)" != 0 ] && [ -n "$missing_tests" ]; then
    echo "setup: for the install and gallery-page tests also: sudo apt-get install -y$missing_tests" >&2
else
    missing="$missing$missing_tests"
fi
[ -z "$missing" ] && exit 0
if [ "$(id -u)" = 0 ]; then
    echo "setup: installing$missing" >&2
    export DEBIAN_FRONTEND=noninteractive
    apt-get update -qq >/dev/null
    apt-get install -y -qq --no-install-recommends $missing >/dev/null
else
    echo "setup: missing packages; run:" >&2
    echo "  sudo apt-get install -y$missing" >&2
    exit 1
fi
