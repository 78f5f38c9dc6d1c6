#!/bin/sh
# The Jupyter kernel (interp/jupyter): installed with the build into a prefix, listed by
# `jupyter kernelspec list`, then driven through jupyter_client by notebook_kernel.py (a drawing
# cell's SVG, an error's line, completion and inspection from the registry, an interrupt).
# The example notebook runs cell by cell without errors.
here=$(cd "$(dirname "$0")" && pwd)
. "$here/lib.sh"
: "${PC_SOURCE_DIR:?PC_SOURCE_DIR must name the source tree}"
py=/usr/bin/python3
if ! $py -c 'import ipykernel, jupyter_client' 2>/dev/null; then
    echo "skip: python3-ipykernel and python3-jupyter-client are not installed (setup.sh installs them)"
    exit 77
fi
if [ "$PC_SANITIZE" = 1 ]; then
    echo "skip: the kernel is checked with the plain build"
    exit 77
fi
build=$(dirname "$POINTCALC")
run cmake --install "$build" --prefix "$WORK/prefix"
expect_rc 0 "cmake --install"
for f in kernel.json kernel.lua pointcalc_kernel.py; do
    expect_file "$WORK/prefix/share/jupyter/kernels/pointcalc/$f" "the kernelspec"
done
export JUPYTER_PATH="$WORK/prefix/share/jupyter" HOME="$WORK" PYDEVD_DISABLE_FILE_VALIDATION=1
if command -v jupyter-kernelspec >/dev/null; then
    run jupyter kernelspec list
    expect_in out.txt "$WORK/prefix/share/jupyter/kernels/pointcalc" "jupyter kernelspec list shows pointcalc"
else
    fail "jupyter kernelspec is not installed (setup.sh installs the Debian package jupyter-client)"
fi
run $py -c 'from jupyter_client.kernelspec import KernelSpecManager as K
s = K().get_kernel_spec("pointcalc"); print(s.display_name, s.language, s.interrupt_mode)'
expect_eq "$(cat out.txt)" "pointcalc (Lua 5.4) lua signal" "the kernelspec: $(tail -2 err.txt)"

# the kernel finds the prefix's own program (no POINTCALC, nothing of the build on PATH)
env -u POINTCALC PATH=/usr/bin:/bin timeout 180 $py -Xfrozen_modules=off "$here/notebook_kernel.py" >out.txt 2>err.txt
rc=$?
cat out.txt
expect_rc 0 "the kernel through jupyter_client: $(grep FAIL out.txt | head -5) $(grep -v '^0.0' err.txt | tail -3)"
checks=$((checks + $(grep -c '^ok' out.txt)))

# the example notebook: every code cell runs, the drawing ones show a figure
env -u POINTCALC PATH=/usr/bin:/bin timeout 120 $py -Xfrozen_modules=off - "$PC_SOURCE_DIR/examples/notebooks/oval.ipynb" >nb.txt 2>nberr.txt <<'PY'
import json, sys
from jupyter_client.manager import start_new_kernel
nb = json.load(open(sys.argv[1]))
km, kc = start_new_kernel(kernel_name="pointcalc", startup_timeout=60)
figures = errors = 0
for cell in nb["cells"]:
    if cell["cell_type"] != "code":
        continue
    msg_id = kc.execute("".join(cell["source"]))
    while True:
        m = kc.get_iopub_msg(timeout=30)
        if m["parent_header"].get("msg_id") != msg_id:
            continue
        if m["msg_type"] == "display_data":
            figures += 1
        if m["msg_type"] == "error":
            errors += 1
            print("error:", m["content"]["evalue"])
        if m["msg_type"] == "status" and m["content"]["execution_state"] == "idle":
            break
print("figures", figures, "errors", errors)
km.shutdown_kernel(now=True)
PY
expect_eq "$(tail -1 nb.txt)" "figures 3 errors 0" "the example notebook: $(head -3 nb.txt) $(grep -v '^0.0' nberr.txt | tail -2)"
finish
