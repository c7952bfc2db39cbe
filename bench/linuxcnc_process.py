"""Starting and stopping a headless LinuxCNC from outside, bounded: waiting for LinuxCNC's own
lock file to go, stopping the process group of the run we started and only it, and unloading HAL
when a run did not shut down cleanly."""

import os
import signal
import subprocess
import time

LOCKFILE = "/tmp/linuxcnc.lock"  # LinuxCNC's own: it exists while a LinuxCNC runs


def wait_for_no_lock(limit_s):
    end = time.monotonic() + limit_s
    while os.path.exists(LOCKFILE):
        if time.monotonic() > end:
            return False
        time.sleep(0.5)
    return True


def kill_group(pgid, sig):
    try:
        os.killpg(pgid, sig)
    except (ProcessLookupError, PermissionError):
        pass


def read_pid(path):
    try:
        with open(path) as f:
            return int(f.read().strip())
    except (OSError, ValueError):
        return None


def stop_linuxcnc(proc, pidfile, grace_s):
    """Stops the run we started, and only it. `script` puts linuxcnc into a session of its own
    (the pty's), so signalling `script`'s group would miss it: the wrapper command records the
    pid of the linuxcnc script, which leads that session's process group. SIGTERM to that group
    (linuxcnc traps it and runs its own Cleanup), then SIGKILL to both groups if they linger."""
    lcnc = read_pid(pidfile)
    if lcnc is not None:
        kill_group(lcnc, signal.SIGTERM)
    kill_group(proc.pid, signal.SIGTERM)
    try:
        proc.wait(grace_s)
    except subprocess.TimeoutExpired:
        pass
    if lcnc is not None:
        kill_group(lcnc, signal.SIGKILL)
    kill_group(proc.pid, signal.SIGKILL)
    try:
        proc.wait(5)
    except subprocess.TimeoutExpired:
        pass


def run_bounded(cmd, env, log, timeout_s):
    """Runs cmd in a session of its own; on timeout kills that whole group (not just cmd)."""
    try:
        p = subprocess.Popen(cmd, env=env, stdout=log, stderr=log, stdin=subprocess.DEVNULL,
                             start_new_session=True)
    except OSError:
        return
    try:
        p.wait(timeout_s)
    except subprocess.TimeoutExpired:
        kill_group(p.pid, signal.SIGKILL)
        p.wait(5)


def force_unload(env, log):
    """Last resort when our LinuxCNC did not shut down cleanly: `halrun -U` stops the realtime
    threads and unloads HAL, as linuxcnc's own Cleanup does; then the lock file goes."""
    run_bounded(["halrun", "-U"], env, log, 30)
    if os.path.exists(LOCKFILE):
        try:
            os.remove(LOCKFILE)
        except OSError:
            pass
