"""Running a HAL graph in LinuxCNC's halrun for nckit's HAL tests and benchmarks.

halrun starts rtapi_app (uspace, POSIX threads) and runs a .hal file. As root (CI) rtapi_app
wants a fallback user (RTAPI_UID) and a socket path that user can reach (RTAPI_FIFO_PATH, the
socket file itself inside a world-writable folder); as a plain user neither is needed. halrun
is given a terminal through `script`. Only one HAL instance may run on a machine at a time: the
callers hold a lock (CTest RESOURCE_LOCK linuxcnc, or flock /tmp/nckit-linuxcnc.lock).
"""
import os
import shutil
import subprocess
import tempfile
import time

# Another LinuxCNC instance (another test run, a machine) makes halrun refuse to start: wait for
# it, this long at most.
BUSY_WAIT_S = 300


def halrun_env(workdir):
    env = dict(os.environ)
    if os.geteuid() == 0:
        fifo_dir = os.path.join(workdir, "rtapi")
        os.makedirs(fifo_dir, exist_ok=True)
        os.chmod(fifo_dir, 0o1777)
        env["RTAPI_UID"] = "65534"
        env["RTAPI_FIFO_PATH"] = os.path.join(fifo_dir, "rtapi_fifo")
    return env


def realtime_running():
    """Whether an rtapi_app (some HAL instance) is running on this machine."""
    for pid in os.listdir("/proc"):
        if pid.isdigit():
            try:
                with open(f"/proc/{pid}/comm") as f:
                    if f.read().strip() == "rtapi_app":
                        return True
            except OSError:
                pass
    return False


def run_hal(hal_text, workdir, timeout_s=120):
    """Runs `hal_text` with halrun -f, after any other HAL instance has ended (halrun refuses
    to start beside one); returns (exit status, output text)."""
    deadline = time.monotonic() + BUSY_WAIT_S
    while True:
        while realtime_running() and time.monotonic() < deadline:
            time.sleep(1.0)
        status, output = run_hal_once(hal_text, workdir, timeout_s)
        if "Realtime already running" not in output or time.monotonic() >= deadline:
            return status, output
        time.sleep(1.0)


def run_hal_once(hal_text, workdir, timeout_s):
    path = os.path.join(workdir, "test.hal")
    with open(path, "w") as f:
        f.write(hal_text)
    # Files the sampler writes must be writable by the fallback user when run as root.
    os.chmod(workdir, 0o1777)
    command = "halrun -f " + path
    if shutil.which("script"):
        argv = ["script", "-qec", command, "/dev/null"]
    else:
        argv = ["halrun", "-f", path]
    try:
        done = subprocess.run(argv, cwd=workdir, env=halrun_env(workdir), capture_output=True, text=True,
                              timeout=timeout_s, stdin=subprocess.DEVNULL)
    except subprocess.TimeoutExpired as e:
        subprocess.run(["halrun", "-U"], env=halrun_env(workdir), capture_output=True)
        return 124, f"halrun timed out after {timeout_s} s: {e}"
    return done.returncode, done.stdout + done.stderr


def read_samples(path):
    """halsampler -t lines as lists of numbers (the tag first); 'overrun' lines raise."""
    rows = []
    with open(path) as f:
        for line in f:
            line = line.strip()
            if not line:
                continue
            if line == "overrun":
                raise RuntimeError(f"{path}: the sampler overran: samples were lost")
            rows.append([float(x) for x in line.split()])
    return rows


def make_workdir(prefix):
    return tempfile.mkdtemp(prefix=prefix)
