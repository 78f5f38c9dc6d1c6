#!/bin/sh
# A notebook cell that draws a typical gallery figure, through the Jupyter kernel: cell sent to
# figure received (bench/notebook.py).  sh bench/notebook.sh POINTCALC
pc=${1:-build/pointcalc}
here=$(dirname "$0")
if ! /usr/bin/python3 -c 'import ipykernel, jupyter_client' 2>/dev/null; then
    echo "notebook: python3-ipykernel and python3-jupyter-client are needed (setup.sh)"
    exit 0
fi
exec /usr/bin/python3 -Xfrozen_modules=off "$here/notebook.py" "$pc" "$here/.."
