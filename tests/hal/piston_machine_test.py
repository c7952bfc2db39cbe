#!/usr/bin/env python3
"""The piston lathe of examples/linuxcnc/piston_lathe/piston_machine.ini as LinuxCNC runs it:
the whole machine (task, motion, the spindle and its encoder, nckit_cam, nckit_servo), headless,
turning piston.ngc.

  piston_machine_test.py --nckit NCKIT --source SOURCE_DIR [--learning] [--keep DIR]

The example configuration is copied into a scratch folder with the cam table that
`nckit piston piston.toml --cam-table` writes there (the INI names it relative to its folder, as
the example does) and this script as its DISPLAY; the example's own sampler (piston_sampler.hal)
records the cam's pins. LinuxCNC is started as tests/linuxcnc_plugin/run_machine.py starts it (a
terminal from `script`; as root RTAPI_UID=65534 and RTAPI_FIFO_PATH in a world-writable folder).
The display part (Debian's /usr/bin/python3 with the `linuxcnc` module) resets the E-stop,
switches the machine on, runs piston.ngc and drains the sampler while it runs.

Checks:
- LinuxCNC ran the program to its end without an error, and the carriage reached Z 50;
- no period was lost (halsampler's tags run on) and nckit_cam raised no fault;
- the spindle turned at the programmed speed (counts per period from the encoder);
- over the cut (Z off the crown) the fast tool servo's profile error (nckit_cam's error pin: the
  servo's position minus where the cam wants it) has a peak to valley within 10 % of the figure
  `nckit piston --json` simulates for the same job (feedforward; with --learning the learning
  run's figure, within 0.02 um or 50 %, as hal_cam_learning allows).

Exit status 0 when every check holds, 1 otherwise (the reason on stdout). One LinuxCNC at a
time: the run holds an flock on /tmp/nckit-linuxcnc.lock.
"""
import argparse
import fcntl
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(REPO, "bench"))
sys.path.insert(0, os.path.join(REPO, "tests", "linuxcnc_plugin"))
import linuxcnc_planner as lp  # noqa: E402  (the display session, stopping LinuxCNC)
import run_machine as rm  # noqa: E402  (starting LinuxCNC)
from machine_support import open_lock, rewrite_ini  # noqa: E402

EXAMPLE = os.path.join("examples", "linuxcnc", "piston_lathe")
LOCKFILE = "/tmp/nckit-linuxcnc.lock"
# The columns piston_sampler.hal records after halsampler's tag: encoder counts, Z, the cam's
# wanted position, its command, the servo's position, the error, the fault bit.
COLUMNS = 7
Z_END_MM = 50.0
COUNTS_PER_TURN = 360
PROGRAMMED_RPM = 2500.02


def fail(message):
    print(f"FAIL: {message}")
    sys.exit(1)


def prepare(args, work):
    src = os.path.join(args.source, EXAMPLE)
    for name in ("piston_machine.hal", "piston_sampler.hal", "piston_machine.tbl", "piston.ngc"):
        shutil.copyfile(os.path.join(src, name), os.path.join(work, name))
    table = os.path.join(work, "piston_cam.csv")
    job = subprocess.run([args.nckit, "piston", os.path.join(src, "piston.toml"), "--cam-table", table,
                          "--json"], capture_output=True, text=True, timeout=300)
    if job.returncode != 0:
        fail(f"nckit piston failed: {job.stderr.strip()[:300]}")
    display = os.path.join(work, "display.sh")
    with open(display, "w") as f:
        f.write("#!/bin/sh\n# LinuxCNC DISPLAY: the --display mode of piston_machine_test.py\n"
                f"exec /usr/bin/python3 '{os.path.abspath(__file__)}' --display \"$@\"\n")
    os.chmod(display, 0o755)
    replace = {("DISPLAY", "DISPLAY"): display,
               ("RS274NGC", "PARAMETER_FILE"): os.path.join(work, "piston_machine.var"),
               ("NCKIT_CAM", "LEARNING"): "1" if args.learning else "0"}
    with open(os.path.join(src, "piston_machine.ini")) as f:
        text = rewrite_ini(f.read(), replace, {})
    ini_path = os.path.join(work, "piston_machine.ini")
    with open(ini_path, "w") as f:
        f.write(text)
    with open(os.path.join(work, "piston_machine.var"), "w") as f:
        f.write("")
    with open(os.path.join(work, "run.json"), "w") as f:
        json.dump({"program": os.path.join(work, "piston.ngc"), "run_timeout_s": args.timeout - 30}, f)
    return ini_path, json.loads(job.stdout)


def display_main(argv):
    ini = argv[argv.index("-ini") + 1]
    work = os.path.dirname(os.path.abspath(ini))
    with open(os.path.join(work, "run.json")) as f:
        run = json.load(f)
    result = {"finished": False, "errors": [], "phase": "start"}
    session = None
    try:
        import linuxcnc
        session = lp.DisplaySession(linuxcnc, result, run["run_timeout_s"])
        s, c = session.s, session.c
        session.machine_on_in_auto()
        session.open_program(run["program"])
        session.start_sampling(work)
        result["phase"] = "run"
        t0 = time.monotonic()
        c.auto(linuxcnc.AUTO_RUN, 0)
        session.wait_for(lambda: s.interp_state != linuxcnc.INTERP_IDLE or s.queue > 0 or not s.inpos,
                         "the program to start", 10)
        session.wait_for(lambda: s.interp_state == linuxcnc.INTERP_IDLE and s.queue == 0 and s.inpos
                         and s.exec_state == linuxcnc.EXEC_DONE, "the program to finish", run["run_timeout_s"])
        result["wall_s"] = time.monotonic() - t0
        time.sleep(0.2)
        session.poll_errors()
        s.poll()
        result["position"] = list(s.position)
        result["finished"] = True
        result["phase"] = "done"
    except Exception as ex:
        result["errors"].append(f"{type(ex).__name__}: {ex}")
        try:
            session.c.abort()
        except Exception:
            pass
    finally:
        if session is not None:
            session.stop_sampling()
        with open(os.path.join(work, "display_result.json"), "w") as f:
            json.dump(result, f)
    return 0


def read_rows(path):
    rows, last_tag, gaps = [], None, 0
    with open(path) as f:
        for line in f:
            parts = line.split()
            if line.strip() == "overrun":
                gaps += 1
                continue
            if len(parts) != 1 + COLUMNS:
                continue
            tag = int(parts[0])
            if last_tag is not None and tag != last_tag + 1:
                gaps += 1
            last_tag = tag
            rows.append([float(v) for v in parts[1:]])
    return rows, gaps


def check(rows, nckit, learning):
    """The figures of the run, or fail()."""
    z = [r[1] for r in rows]
    if max(z) < Z_END_MM - 1e-6:
        fail(f"the carriage stopped at Z {max(z):.4f} mm, not at {Z_END_MM}")
    faults = sum(1 for r in rows if r[6] != 0)
    if faults:
        fail(f"nckit_cam raised its fault pin in {faults} periods")
    cut = [r for r in rows if 0.0 < r[1] < Z_END_MM]
    if len(cut) < 100 * COUNTS_PER_TURN:
        fail(f"only {len(cut)} periods of cut sampled")
    # Spindle speed from the counts over the cut: counts per period times the periods per second.
    periods = len(cut) - 1
    counts = cut[-1][0] - cut[0][0]
    rpm = counts / COUNTS_PER_TURN / (periods * 66666e-9) * 60
    if abs(rpm - PROGRAMMED_RPM) > 0.01 * PROGRAMMED_RPM:
        fail(f"the spindle turned at {rpm:.1f} rpm, not the programmed {PROGRAMMED_RPM}")
    errors_um = [r[5] * 1e3 for r in cut]
    pv = max(errors_um) - min(errors_um)
    rms = math.sqrt(sum(e * e for e in errors_um) / len(errors_um))
    run = "learning" if learning else "feedforward"
    want = nckit["profile_error_um"][run]["pv"]
    figures = {"run": run, "hal_pv_um": round(pv, 4), "hal_rms_um": round(rms, 4), "nckit_pv_um": round(want, 4),
               "cut_periods": len(cut), "spindle_rpm": round(rpm, 2)}
    allowed = max(0.02, 0.5 * want) if learning else 0.1 * want
    if abs(pv - want) > allowed:
        fail(f"profile error {pv:.4f} um P-V on the machine against nckit's {want:.4f} um "
             f"(allowed +-{allowed:.4f}): {json.dumps(figures)}")
    return figures


def parent_main(args):
    args.nckit = os.path.abspath(args.nckit)
    for tool in ("linuxcnc", "halsampler", "script"):
        if shutil.which(tool) is None:
            fail(f"'{tool}' not on PATH: install linuxcnc-uspace (scripts/deps.sh)")
    work = tempfile.mkdtemp(prefix="nckit-piston-machine-")
    os.chmod(work, 0o755)
    env = dict(os.environ)
    lock = open_lock(LOCKFILE)
    try:
        fcntl.flock(lock, fcntl.LOCK_EX)
        ini_path, nckit = prepare(args, work)
        if os.geteuid() == 0:
            fifo = os.path.join(work, "rtapi_fifo")
            os.makedirs(fifo)
            env["RTAPI_UID"] = "65534"
            env["RTAPI_FIFO_PATH"] = os.path.join(fifo, "rtapi_fifo")
            for name in os.listdir(work):  # the unprivileged LinuxCNC writes its files here
                path = os.path.join(work, name)
                os.chmod(path, 0o1777 if os.path.isdir(path) else 0o666)
            os.chmod(os.path.join(work, "display.sh"), 0o755)
            os.chmod(work, 0o1777)
        t0 = time.monotonic()
        log = rm.run_linuxcnc(args, work, ini_path, env)
        wall_s = time.monotonic() - t0
        result_path = os.path.join(work, "display_result.json")
        if not os.path.exists(result_path):
            fail(f"LinuxCNC did not run the program; log tail:\n{log[-2000:]}")
        with open(result_path) as f:
            disp = json.load(f)
        if disp["errors"] or not disp["finished"]:
            fail(f"LinuxCNC reported errors: {disp['errors']} (phase {disp['phase']}); log tail:\n{log[-1500:]}")
        rows, gaps = read_rows(os.path.join(work, "samples.txt"))
        if gaps:
            fail(f"halsampler lost samples ({gaps} gaps)")
        figures = check(rows, nckit, args.learning)
        figures["run_s"] = round(wall_s, 1)
        print(json.dumps(figures))
        return 0
    finally:
        os.close(lock)
        if args.keep:
            os.makedirs(args.keep, exist_ok=True)
            for name in os.listdir(work):
                path = os.path.join(work, name)
                if os.path.isfile(path):
                    shutil.copy2(path, os.path.join(args.keep, name))
        shutil.rmtree(work, ignore_errors=True)


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "--display":
        return display_main(sys.argv[2:])
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--nckit", required=True)
    ap.add_argument("--source", required=True, help="the nckit source folder")
    ap.add_argument("--learning", action="store_true", help="learning across revolutions on")
    ap.add_argument("--timeout", type=float, default=300.0)
    ap.add_argument("--keep", metavar="DIR", help="keep the configuration, log and samples here")
    return parent_main(ap.parse_args())


if __name__ == "__main__":
    sys.exit(main())
