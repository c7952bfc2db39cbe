"""What the rs274-driven plug-in tests share (messages.py, ini_errors.py): finding LinuxCNC's
standalone interpreter, running a program through the plug-in (`rs274 -p LIB -g PROGRAM`) or
through LinuxCNC's own interpreter, and the canonical calls it printed.

Every run through the plug-in checks that rs274 printed `using custom interpreter '<plug-in>'`:
when it cannot load a plug-in it says so once and runs its own interpreter instead.
"""

import os
import re
import shutil
import subprocess

# rs274 -g prints each canonical call after its call count and the block's sequence number:
# "   11 N..... STRAIGHT_TRAVERSE(1.0000, ...)".
CALL_PREFIX = re.compile(r"^\s*\d+\s+N\S*\s+")


def find_rs274(given=None):
    """The rs274 executable (given, else on PATH), or None."""
    return given or shutil.which("rs274")


def run_rs274(rs274, program, plugin=None, ini=None, cwd=None, timeout=60):
    """rs274 -g on `program` (absolute paths), through `plugin` when given (else LinuxCNC's own
    interpreter), with `ini` as its -i file. Returns the CompletedProcess (text)."""
    cmd = [rs274]
    if plugin:
        cmd += ["-p", os.path.abspath(plugin)]
    if ini:
        cmd += ["-i", os.path.abspath(ini)]
    cmd += ["-g", os.path.abspath(program)]
    return subprocess.run(cmd, cwd=cwd, stdin=subprocess.DEVNULL, capture_output=True, text=True,
                          timeout=timeout)


def plugin_loaded(proc, plugin):
    """None when rs274 ran the plug-in, else why the run does not count."""
    if f"using custom interpreter '{os.path.abspath(plugin)}'" not in proc.stderr:
        return f"rs274 did not load the plug-in: {proc.stderr.strip()[:300]}"
    return None


def calls(stdout, names):
    """The canonical calls whose name starts with one of `names`, without rs274's counters."""
    out = []
    for line in stdout.splitlines():
        call = CALL_PREFIX.sub("", line).strip()
        if call.startswith(tuple(names)):
            out.append(call)
    return out
