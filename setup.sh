#!/bin/sh
# Install the Debian packages pointcalc needs to build and test.
# As root the missing ones are installed with apt-get; otherwise the exact command is printed.
set -e
PKGS="build-essential cmake pkg-config liblua5.4-dev lua5.4 libcmocka-dev libpng-dev libedit-dev libxml2-utils python3 console-setup-linux"
missing=""
for p in $PKGS; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing="$missing $p"
done
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
