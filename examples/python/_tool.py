"""The `flexure` tool for the example scripts: $FLEXURE_BINARY, else build/flexure of this
checkout, else `flexure` on the PATH. Each call raises with the tool's message on failure."""
import os
import shutil
import subprocess

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def binary():
    candidates = [os.environ.get("FLEXURE_BINARY"), os.path.join(ROOT, "build", "flexure"),
                  shutil.which("flexure")]
    for c in candidates:
        if c and os.access(c, os.X_OK):
            return c
    raise SystemExit("the flexure tool is not found: build it (cmake --build build) or set "
                     "FLEXURE_BINARY")


def flexure(*args):
    """Runs `flexure ARGS...`; returns its stdout."""
    p = subprocess.run([binary(), *args], capture_output=True, text=True)
    if p.returncode != 0:
        raise SystemExit(f"flexure {' '.join(args)}: exit {p.returncode}: {p.stderr.strip()}")
    return p.stdout
