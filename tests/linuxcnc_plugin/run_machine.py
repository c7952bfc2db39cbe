#!/usr/bin/env python3
"""Runs one program on a simulated LinuxCNC machine through nckit's interpreter plug-in, headless,
and checks what the machine did against `nckit moves` of the same program.

Usage: run_machine.py --plugin LIB.so --nckit NCKIT --config EXAMPLE.ini --program FILE
                      (--expect-end | --expect-alarm N) [--spindle-override F] [--timeout S]

The example configuration (examples/linuxcnc/*_plugin/) is copied into a scratch folder with
`[TASK] INTERPRETER` pointing at the plug-in just built (absolute path), its [NCKIT] paths made
absolute, `RETAINED` a scratch file, this very script as the DISPLAY, and a sampler on the
commanded joint positions (the Xpos/Ypos/Zpos signals of the configuration's HAL file), one row
per 1 ms servo period. LinuxCNC is started as bench/linuxcnc_planner.py starts it (a terminal
from `script`; as root RTAPI_UID=65534 and RTAPI_FIFO_PATH in a world-writable folder, since
LinuxCNC refuses to run as root). The display part, under Debian's /usr/bin/python3 with the
`linuxcnc` module, resets the E-stop, switches the machine on, opens the program, runs it with
the spindle override given, and waits until the interpreter is idle and the axes in position,
keeping every error LinuxCNC reports.

Checks:
- LinuxCNC's log says `using custom interpreter '<plug-in>'` (else it ran its own interpreter);
- every sampled position lies on nckit's move path (lines, arcs, spindle-synchronised moves, in
  machine coordinates) within 1e-4 mm, the samples pass along the path in order;
- --expect-end: no error, and the last sample is the end of nckit's last move (program end);
- --expect-call-level N: the highest subroutine level LinuxCNC's status showed (the plug-in's
  call_level(): 0 in the main program, 1 in a called one, 2 in one that calls) is N;
- --expect-alarm N: LinuxCNC reports an error naming `alarm N` and `PROGRAM:LINE:` (the line nckit
  reports), the machine stops at the end of the last move before that block: nothing of the
  block moved.

Exit status 0 when every check holds; 1 otherwise, with the reason on stderr. Only one LinuxCNC can
run on a machine: the run holds an flock on /tmp/nckit-linuxcnc.lock (as manual runs do).
"""

import argparse
import fcntl
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(REPO, "bench"))
import linuxcnc_planner as lp  # noqa: E402  (starting and stopping LinuxCNC, reading samples)
sys.path.insert(0, HERE)
from machine_support import (TOL_MM, check_path, interpolator_bound_mm, open_lock,  # noqa: E402
                             read_ini, read_samples, rewrite_ini)

LOCKFILE = "/tmp/nckit-linuxcnc.lock"  # the flock that keeps nckit's LinuxCNC runs one at a time
SAMPLER_DEPTH = 200000


def fail(msg):
    print(f"run_machine: {msg}", file=sys.stderr)
    sys.exit(1)


# ---------------------------------------------------------------------------------------------
# Configuration
# ---------------------------------------------------------------------------------------------

def prepare(args, work, display_script=None):
    """The scratch copy of the example configuration, with `display_script` (this file when not
    given) run by `--display` as LinuxCNC's DISPLAY and args.library (if any) as [NCKIT] LIBRARY;
    returns (ini path, axis letters, the nckit options of the same machine)."""
    src_dir = os.path.dirname(os.path.abspath(args.config))
    ini = read_ini(args.config)
    for name in os.listdir(src_dir):
        path = os.path.join(src_dir, name)
        if os.path.isfile(path) and name.endswith((".hal", ".tbl")):
            shutil.copyfile(path, os.path.join(work, name))

    def absolute(key):
        v = ini.get(("NCKIT", key))
        return os.path.normpath(os.path.join(src_dir, v[0])) if v else None

    axes = ini[("TRAJ", "COORDINATES")][0].replace(" ", "").upper()
    display = os.path.join(work, "display.sh")
    with open(display, "w") as f:
        f.write("#!/bin/sh\n# LinuxCNC DISPLAY: the --display mode of run_machine.py\n"
                f"exec /usr/bin/python3 '{os.path.abspath(display_script or __file__)}' --display \"$@\"\n")
    os.chmod(display, 0o755)
    replace = {("TASK", "INTERPRETER"): str(args.plugin),
               ("DISPLAY", "DISPLAY"): display,
               ("NCKIT", "RETAINED"): os.path.join(work, "retained.vars"),
               ("RS274NGC", "PARAMETER_FILE"): os.path.join(work, "sim.var")}
    for key in ("MACHINE", "LIBRARY"):
        if absolute(key):
            replace[("NCKIT", key)] = absolute(key)
    if getattr(args, "library", None):
        replace[("NCKIT", "LIBRARY")] = os.path.abspath(args.library)
    append = {"HAL": [f"HALFILE = {os.path.join(work, 'sampler.hal')}"]}
    with open(args.config) as f:
        text = rewrite_ini(f.read(), replace, append)
    ini_path = os.path.join(work, "sim.ini")
    with open(ini_path, "w") as f:
        f.write(text)
    with open(os.path.join(work, "sampler.hal"), "w") as f:
        # The planner's commanded position (axis.L.pos-cmd) and the joints' (motor-pos-cmd, the
        # planner's points through motion's cubic interpolator), one row per servo period.
        f.write(f"# Commanded positions ({' '.join(axes)}): the planner's, then the joints'.\n"
                f"loadrt sampler depth={SAMPLER_DEPTH} cfg={'f' * 2 * len(axes)}\n"
                "addf sampler.0 servo-thread\n"
                + "".join(f"net nckit-planner-{a.lower()} axis.{a.lower()}.pos-cmd => sampler.0.pin.{k}\n"
                          for k, a in enumerate(axes))
                + "".join(f"net {a}pos => sampler.0.pin.{len(axes) + k}\n" for k, a in enumerate(axes)))
    with open(os.path.join(work, "sim.var"), "w") as f:
        f.write("")
    nckit_opts = []
    if absolute("MACHINE"):
        nckit_opts += ["--machine", absolute("MACHINE")]
    if replace.get(("NCKIT", "LIBRARY")):
        nckit_opts += ["--library", replace[("NCKIT", "LIBRARY")]]
    return ini_path, axes, nckit_opts


# ---------------------------------------------------------------------------------------------
# The DISPLAY: runs inside LinuxCNC under /usr/bin/python3
# ---------------------------------------------------------------------------------------------

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
        c.spindleoverride(run["spindle_override"], 0)
        c.wait_complete(5)
        session.open_program(run["program"])
        session.start_sampling(work)
        result["phase"] = "run"
        t0 = time.monotonic()
        c.auto(linuxcnc.AUTO_RUN, 0)
        # An alarm may stop the program at once: errors end the wait, they do not fail it here.
        session.wait_for(lambda: s.interp_state != linuxcnc.INTERP_IDLE or s.queue > 0 or not s.inpos
                         or result["errors"], "the program to start", 10, stop_on_error=False)
        result["max_call_level"] = 0

        def finished():
            # The subroutine level task reports (the plug-in's call_level()), at its highest.
            result["max_call_level"] = max(result["max_call_level"], s.call_level)
            return (s.interp_state == linuxcnc.INTERP_IDLE and s.queue == 0 and s.inpos
                    and s.exec_state == linuxcnc.EXEC_DONE)
        session.wait_for(finished, "the program to finish", run["run_timeout_s"], stop_on_error=False)
        result["wall_s"] = time.monotonic() - t0
        time.sleep(0.3)
        session.poll_errors()
        s.poll()
        result["position"] = list(s.position)
        result["finished"] = True
        result["phase"] = "done"
    except Exception as ex:
        result["errors"].append(f"{type(ex).__name__}: {ex}")
        try:  # where it stood, for the report
            s = session.s
            s.poll()
            result["state"] = {k: getattr(s, k) for k in (
                "task_state", "exec_state", "interp_state", "queue", "inpos", "motion_line",
                "current_line", "read_line", "queue_full", "current_vel")}
            result["state"]["spindle"] = s.spindle[0]
        except Exception:
            pass
        try:
            session.c.abort()
        except Exception:
            pass
    finally:
        lp.finish_run(session, result, work)
    return 0


# ---------------------------------------------------------------------------------------------
# nckit's path
# ---------------------------------------------------------------------------------------------

def nckit_moves(args, nckit_opts, work):
    """(motions in order, the error line nckit stops at or None)."""
    cmd = [args.nckit, "moves", args.program, "--json", "--vars",
           os.path.join(work, "nckit.vars"), *nckit_opts]
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=300)
    motions = [json.loads(l) for l in proc.stdout.splitlines() if l.strip()]
    motions = [m for m in motions if m["kind"] in ("rapid", "linear", "arc", "sync")]
    if proc.returncode == 0:
        return motions, None
    m = re.search(r":(\d+):\d+: error: (.*)", proc.stderr)
    if proc.returncode != 2 or not m:
        fail(f"nckit moves failed: {proc.stderr.strip()[:300]}")
    return motions, (int(m.group(1)), m.group(2))


# ---------------------------------------------------------------------------------------------
# The parent
# ---------------------------------------------------------------------------------------------

def run_linuxcnc(args, work, ini_path, env):
    log_path = os.path.join(work, "linuxcnc.log")
    pidfile = os.path.join(work, "linuxcnc.pid")
    clean = False
    with open(log_path, "w") as log:
        proc = subprocess.Popen(
            ["script", "-qec", f"echo $$ > '{pidfile}'; exec linuxcnc '{ini_path}'", "/dev/null"],
            cwd=work, env=env, stdin=subprocess.DEVNULL, stdout=log, stderr=subprocess.STDOUT,
            start_new_session=True)
        try:
            proc.wait(args.timeout)
            clean = proc.returncode == 0
        except subprocess.TimeoutExpired:
            print(f"run_machine: timed out after {args.timeout} s, stopping LinuxCNC",
                  file=sys.stderr)
            lp.stop_linuxcnc(proc, pidfile, 20)
        finally:
            if proc.poll() is None:
                lp.stop_linuxcnc(proc, pidfile, 20)
        if not clean:
            lp.force_unload(env, log)
    with open(log_path, errors="replace") as f:
        return f.read()


def unprivileged(work, env):
    """As root: LinuxCNC runs as an unprivileged user (it refuses root), with its RTAPI socket and
    files in `work`, which it must be able to write."""
    if os.geteuid() != 0:
        return
    fifo = os.path.join(work, "rtapi_fifo")
    os.makedirs(fifo)
    os.chmod(fifo, 0o1777)
    env["RTAPI_UID"] = "65534"
    env["RTAPI_FIFO_PATH"] = os.path.join(fifo, "rtapi_fifo")
    for name in os.listdir(work):
        path = os.path.join(work, name)
        os.chmod(path, 0o777 if os.path.isdir(path) else 0o666)
    os.chmod(os.path.join(work, "display.sh"), 0o755)


def parent_main(args):
    args.program = os.path.abspath(args.program)
    args.plugin = os.path.abspath(args.plugin)
    args.nckit = os.path.abspath(args.nckit)
    for path in (args.program, args.plugin, args.nckit, args.config):
        if not os.path.isfile(path):
            fail(f"{path} not found")
    for tool in ("linuxcnc", "halsampler", "script", "halrun"):
        if shutil.which(tool) is None:
            fail(f"'{tool}' not on PATH: install linuxcnc-uspace (scripts/deps.sh)")
    work = tempfile.mkdtemp(prefix="nckit-plugin-machine-")
    env = dict(os.environ)
    lock = open_lock(LOCKFILE)
    try:
        fcntl.flock(lock, fcntl.LOCK_EX)  # one LinuxCNC at a time, manual runs included
        os.chmod(work, 0o755)
        ini_path, axes, nckit_opts = prepare(args, work)
        program = os.path.join(work, os.path.basename(args.program))
        shutil.copyfile(args.program, program)
        os.chmod(program, 0o644)
        with open(os.path.join(work, "run.json"), "w") as f:
            json.dump({"program": program, "spindle_override": args.spindle_override,
                       "run_timeout_s": max(10.0, args.timeout - 30.0)}, f)
        unprivileged(work, env)
        t0 = time.monotonic()
        log = run_linuxcnc(args, work, ini_path, env)
        wall = time.monotonic() - t0
        if f"using custom interpreter '{args.plugin}'" not in log:
            fail(f"LinuxCNC did not load the plug-in (no \"using custom interpreter\"); log tail:\n"
                 f"{log[-2000:]}")
        result_path = os.path.join(work, "display_result.json")
        if not os.path.exists(result_path):
            fail(f"LinuxCNC did not run the program; log tail:\n{log[-2000:]}")
        with open(result_path) as f:
            disp = json.load(f)
        both, gaps = read_samples(os.path.join(work, "samples.txt"), 2 * len(axes))
        if gaps:
            fail(f"halsampler lost samples ({gaps} gaps)")
        rows = [r[:len(axes)] for r in both]          # the planner's commanded positions
        joint_rows = [r[len(axes):] for r in both]    # the joints' (after the interpolator)
        joint_bound = interpolator_bound_mm(ini_path, axes)
        motions, error = nckit_moves(args, nckit_opts, work)
        if not rows:
            fail("no samples")
        if not motions:
            fail("nckit moves printed no motion")
        worst, reached, by_kind = check_path(rows, motions, axes)
        joint_worst, _, joint_by_kind = check_path(joint_rows, motions, axes)
        last = dict(zip(axes, rows[-1]))
        end = motions[-1]["end"] if motions else {a: 0.0 for a in axes}
        off = max(abs(last[a] - end.get(a, 0.0)) for a in axes)
        summary = {"program": os.path.basename(args.program), "samples": len(rows),
                   "motions": len(motions), "worst_off_path_mm": worst,
                   "last_sample_from_end_mm": off, "linuxcnc_wall_s": disp.get("wall_s"),
                   "worst_off_path_by_kind_mm": by_kind,
                   "joints_worst_off_path_mm": joint_worst,
                   "joints_worst_off_path_by_kind_mm": joint_by_kind,
                   "joints_interpolator_bound_mm": joint_bound,
                   "max_call_level": disp.get("max_call_level"),
                   "run_s": round(wall, 1), "errors": disp["errors"]}
        if worst > args.tolerance_mm:
            fail(f"a sampled planner position lies {worst * 1000:.4f} um off nckit's path (allowed "
                 f"{args.tolerance_mm * 1000:.4f} um): {json.dumps(summary)}")
        if joint_worst > args.tolerance_mm + joint_bound:
            fail(f"a sampled joint position lies {joint_worst * 1000:.4f} um off nckit's path (allowed "
                 f"{(args.tolerance_mm + joint_bound) * 1000:.4f} um: the path tolerance plus motion's "
                 f"interpolator bound): {json.dumps(summary)}")
        if args.expect_call_level is not None and disp.get("max_call_level") != args.expect_call_level:
            fail(f"LinuxCNC's status showed call level {disp.get('max_call_level')} at most, not "
                 f"{args.expect_call_level}: {json.dumps(summary)}")
        if args.expect_end:
            if disp["errors"] or not disp["finished"]:
                fail(f"LinuxCNC reported errors: {disp['errors']} (phase {disp['phase']})")
            if error is not None:
                fail(f"nckit stops the program at line {error[0]}: {error[1]}")
            if reached != len(motions) - 1 or off > TOL_MM:
                fail(f"the machine stopped at {last}, motion {reached + 1} of {len(motions)}: "
                     f"not at the program's end {end}")
        else:
            if error is None:
                fail("nckit runs the program to its end: no alarm to test")
            line, message = error
            wanted = f"{os.path.basename(args.program)}:{line}:"
            hits = [t for t in disp["errors"] if wanted in t and f"alarm {args.expect_alarm}" in t]
            if not hits:
                fail(f"LinuxCNC did not report alarm {args.expect_alarm} at {wanted} "
                     f"(nckit: line {line}: {message}); it reported {disp['errors']}")
            if off > TOL_MM or reached != len(motions) - 1:
                fail(f"the machine stopped at {last}, not at the end of the last move before "
                     f"the alarm block {end}")
            summary["alarm"] = hits[0]
        print(json.dumps(summary))
        return 0
    finally:
        os.close(lock)
        if args.keep:
            os.makedirs(args.keep, exist_ok=True)
            for name in os.listdir(work):
                src = os.path.join(work, name)
                if os.path.isfile(src) and not name.startswith("rtapi"):
                    shutil.copy2(src, os.path.join(args.keep, name))
        shutil.rmtree(work, ignore_errors=True)


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "--display":
        return display_main(sys.argv[2:])
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--nckit", required=True)
    ap.add_argument("--config", required=True, help="example INI (examples/linuxcnc/...)")
    ap.add_argument("--program", required=True)
    mode = ap.add_mutually_exclusive_group(required=True)
    mode.add_argument("--expect-end", action="store_true")
    mode.add_argument("--expect-alarm", type=int, metavar="N")
    ap.add_argument("--spindle-override", type=float, default=1.0)
    ap.add_argument("--tolerance-mm", type=float, default=TOL_MM,
                    help="largest distance of a sample from nckit's path (default %(default)s)")
    ap.add_argument("--expect-call-level", type=int, metavar="N",
                    help="the highest subroutine level LinuxCNC's status shows during the run")
    ap.add_argument("--library", help="[NCKIT] LIBRARY: the folder of called programs")
    ap.add_argument("--timeout", type=float, default=600.0)
    ap.add_argument("--keep", metavar="DIR", help="keep the configuration, log and samples here")
    return parent_main(ap.parse_args())


if __name__ == "__main__":
    sys.exit(main())
