#!/usr/bin/env python3
"""Run from line through nckit's interpreter plug-in on a simulated LinuxCNC mill, headless, the way
an operator starts a program at line L (AXIS "Run from line"; `linuxcnc.command().auto(AUTO_RUN,
L)`), and the same run with LinuxCNC's own interpreter for comparison.

  start_line_machine.py --plugin LIB.so --nckit NCKIT --config EXAMPLE.ini --program FILE
                        --start-line L --tool "T2 P2 Z25 D10"

The configuration is prepared as run_machine.py prepares it, with a tool table of the --tool rows
(so that G43 shows in the positions) and the machine file's `restart_safe_mm` set to
--safe-mm (a short retract keeps the run short). What the machine must be in at line L comes
from nckit itself: `nckit restart PROGRAM --line L --json` (the state nckit's restart rebuilds).

Checks (plug-in run):
- LinuxCNC printed `using custom interpreter '<plug-in>'`;
- at the first motion of line L (LinuxCNC's status: motion_line reaches L) the spindle turns in
  the restart's direction at its speed, flood and mist are as the restart has them, the tool in
  the spindle is the restart's, the feed shown is the restart's;
- before the machine reaches the restart point, the axes other than Z move only at the safe
  height (retract, rapid over, feed down: no diagonal plunge);
- the machine reaches the restart point (the end of the last motion before line L, tool length
  offset included) and from there every sampled commanded position lies on nckit's move path
  from line L on, within --tolerance-mm (the G64 tolerance: the feed onto the point blends into
  the first move of line L), and it ends at nckit's last move;
- the first fed motion of line L runs at the restart's feed (finite differences of the samples,
  within 1 %): the F set before L is in force.
Comparison run (no [TASK] INTERPRETER: LinuxCNC's own interpreter): the status at the first motion
of line L is recorded; LinuxCNC's own run from line leaves the spindle stopped there (the calls of
the skipped blocks are dropped), which is checked, so that the documented difference holds.

Exit status 0 when every check holds, 1 otherwise (the reason on stderr). Prints a JSON summary.
"""

import argparse
import fcntl
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import run_machine as rm  # noqa: E402  (configuration, starting LinuxCNC, the lock)
from machine_support import check_path, read_samples  # noqa: E402


def fail(msg):
    print(f"start_line_machine: {msg}", file=sys.stderr)
    sys.exit(1)


# ---------------------------------------------------------------------------------------------
# The DISPLAY: runs inside LinuxCNC under /usr/bin/python3
# ---------------------------------------------------------------------------------------------

def display_main(argv):
    ini = argv[argv.index("-ini") + 1]
    work = os.path.dirname(os.path.abspath(ini))
    with open(os.path.join(work, "run.json")) as f:
        run = json.load(f)
    result = {"finished": False, "errors": [], "phase": "start", "at_start_line": None}
    session = None
    try:
        import linuxcnc
        session = rm.lp.DisplaySession(linuxcnc, result, run["run_timeout_s"])
        s, c = session.s, session.c
        session.machine_on_in_auto()
        session.open_program(run["program"])
        session.start_sampling(work)
        result["phase"] = "run"
        c.auto(linuxcnc.AUTO_RUN, run["start_line"])
        session.wait_for(lambda: s.interp_state != linuxcnc.INTERP_IDLE or s.queue > 0 or not s.inpos
                         or result["errors"], "the program to start", 10, stop_on_error=False)

        def finished():
            if result["at_start_line"] is None and s.motion_line >= run["start_line"]:
                sp = s.spindle[0]
                result["at_start_line"] = {
                    "motion_line": s.motion_line, "spindle_speed": sp["speed"],
                    "spindle_direction": sp["direction"], "flood": s.flood, "mist": s.mist,
                    "tool_in_spindle": s.tool_in_spindle, "feed": s.settings[1],
                    "tool_offset_z": s.tool_offset[2], "position": list(s.position[:3])}
            return (s.interp_state == linuxcnc.INTERP_IDLE and s.queue == 0 and s.inpos
                    and s.exec_state == linuxcnc.EXEC_DONE)
        session.wait_for(finished, "the program to finish", run["run_timeout_s"], stop_on_error=False)
        time.sleep(0.3)
        session.poll_errors()
        result["finished"] = True
        result["phase"] = "done"
    except Exception as ex:
        rm.lp.run_failed(session, result, ex)
    finally:
        rm.lp.finish_run(session, result, work)
    return 0


# ---------------------------------------------------------------------------------------------
# The parent
# ---------------------------------------------------------------------------------------------

def nckit_json(cmd):
    proc = subprocess.run(cmd, capture_output=True, text=True, timeout=120)
    if proc.returncode != 0:
        fail(f"{' '.join(cmd)} failed: {proc.stderr.strip()[:400]}")
    return proc.stdout


def machine_copy(args, work, source):
    """The nckit machine file with restart_safe_mm = --safe-mm in its [machine] table."""
    with open(source) as f:
        text = f.read()
    text = re.sub(r"^\[machine\]\s*$", f"[machine]\nrestart_safe_mm = {args.safe_mm}", text, count=1,
                  flags=re.M)
    path = os.path.join(work, "machine.toml")
    with open(path, "w") as f:
        f.write(text)
    return path


def run_once(args, work, own_interpreter):
    """One LinuxCNC run from the start line; (display result, samples, log)."""
    env = dict(os.environ)
    ini_path, axes, _ = rm.prepare(args, work, display_script=__file__)
    with open(ini_path) as f:
        text = f.read()
    text = re.sub(r"^MACHINE = .*\.toml$", f"MACHINE = {args.machine_copy}", text, flags=re.M)
    if own_interpreter:
        text = re.sub(r"^INTERPRETER = .*$", "", text, flags=re.M)
    with open(ini_path, "w") as f:
        f.write(text)
    with open(os.path.join(work, "tool.tbl"), "w") as f:
        f.write("\n".join(args.tool) + "\n")
    program = os.path.join(work, os.path.basename(args.program))
    shutil.copyfile(args.program, program)
    with open(os.path.join(work, "run.json"), "w") as f:
        json.dump({"program": program, "start_line": args.start_line,
                   "run_timeout_s": max(10.0, args.timeout - 30.0)}, f)
    rm.unprivileged(work, env)
    os.chmod(program, 0o644)
    log = rm.run_linuxcnc(args, work, ini_path, env)
    result_path = os.path.join(work, "display_result.json")
    if not os.path.exists(result_path):
        fail(f"the display did not run; log tail:\n{log[-2000:]}")
    with open(result_path) as f:
        disp = json.load(f)
    both, gaps = read_samples(os.path.join(work, "samples.txt"), 2 * len(axes))
    if gaps:
        fail(f"halsampler lost samples ({gaps} gaps)")
    return disp, [r[:len(axes)] for r in both], axes, log


def check_plugin_run(args, disp, rows, axes, restart, motions):
    if disp["errors"] or not disp["finished"]:
        fail(f"LinuxCNC reported errors: {disp['errors']} (phase {disp['phase']})")
    st = restart["state"]
    at = disp["at_start_line"]
    if at is None:
        fail("LinuxCNC's status never showed a motion of the start line")
    want = {"spindle_direction": {"M3": 1, "M4": -1, "M5": 0}[st["spindle"]],
            "spindle_speed": (st["speed"] or 0.0) if st["spindle"] != "M5" else 0.0,
            "flood": 1 if st["flood"] else 0, "mist": 1 if st["mist"] else 0,
            "tool_in_spindle": st["tool_in_spindle"], "feed": st["feed"]}
    for key, value in want.items():
        if abs(at[key] - value) > 1e-9:
            fail(f"at the first motion of line {args.start_line} LinuxCNC's {key} is {at[key]}, not "
                 f"{value} as nckit restart has it: {json.dumps(at)}")
    # The approach: the other axes move only at the safe height, until the point is reached.
    point = [restart["approach"]["point"][a] for a in axes]
    safe, z = restart["approach"]["safe_mm"], axes.index("Z")
    arrive = next((i for i, r in enumerate(rows)
                   if max(abs(r[k] - point[k]) for k in range(len(axes))) <= 1e-4), None)
    if arrive is None:
        fail(f"the machine never reached the restart point {point}")
    start_xy = [v for k, v in enumerate(rows[0]) if k != z]
    point_xy = [v for k, v in enumerate(point) if k != z]
    for r in rows[:arrive]:
        xy = [v for k, v in enumerate(r) if k != z]
        low = r[z] < safe - 1e-6
        if low and max(abs(a - b) for a, b in zip(xy, start_xy)) > 1e-6 and \
                max(abs(a - b) for a, b in zip(xy, point_xy)) > 1e-6:
            fail(f"the approach moved {axes} to {r} below the safe height {safe}: not retract first")
    # From the point on: nckit's path from line L on.
    first = next(i for i, m in enumerate(motions) if m["line"] >= args.start_line)
    rest = motions[first:]
    worst, reached, _ = check_path(rows[arrive:], rest, axes)
    if worst > args.tolerance_mm:
        fail(f"a sample after the restart point lies {worst * 1000:.4f} um off nckit's path from line "
             f"{args.start_line} (allowed {args.tolerance_mm * 1000:.4f} um)")
    end = [rest[-1]["end"].get(a, 0.0) for a in axes]
    if reached != len(rest) - 1 or max(abs(rows[-1][k] - end[k]) for k in range(len(axes))) > 1e-4:
        fail(f"the machine stopped at {rows[-1]}, not at the end of nckit's last move {end}")
    # The feed of the first fed motion of line L: the F programmed before L.
    fed = next(m for m in rest if m["kind"] == "linear")
    a_, b_ = [fed["start"].get(a, 0.0) for a in axes], [fed["end"].get(a, 0.0) for a in axes]
    length = math.dist(a_, b_)
    on = [i for i in range(arrive, len(rows))
          if math.dist(rows[i], a_) + math.dist(rows[i], b_) <= length + 1e-6]
    speeds = [math.dist(rows[i], rows[i + 1]) / 1e-3 for i in on[:-1] if i + 1 in on]
    feed_mm_s = st["feed"] / 60.0
    top = max(speeds) if speeds else 0.0
    if abs(top - feed_mm_s) > 0.01 * feed_mm_s:
        fail(f"the first fed motion of line {args.start_line} ran at {top:.4f} mm/s, not the "
             f"restart's feed {feed_mm_s:.4f} mm/s")
    return {"worst_off_path_mm": worst, "arrived_at_sample": arrive, "samples": len(rows),
            "first_feed_mm_s": top}


def parent_main(args):
    args.program = os.path.abspath(args.program)
    args.plugin = os.path.abspath(args.plugin)
    args.nckit = os.path.abspath(args.nckit)
    for tool in ("linuxcnc", "halsampler", "script", "halrun"):
        if shutil.which(tool) is None:
            fail(f"'{tool}' not on PATH: install linuxcnc-uspace (scripts/deps.sh)")
    scratch = tempfile.mkdtemp(prefix="nckit-plugin-start-line-")
    lock = rm.open_lock(rm.LOCKFILE)
    try:
        fcntl.flock(lock, fcntl.LOCK_EX)
        os.chmod(scratch, 0o755)
        ini = rm.read_ini(args.config)
        machine = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(args.config)),
                                                ini[("NCKIT", "MACHINE")][0]))
        args.machine_copy = machine_copy(args, scratch, machine)
        os.chmod(args.machine_copy, 0o644)
        tools = os.path.join(scratch, "tools.tbl")
        with open(tools, "w") as f:
            f.write("\n".join(args.tool) + "\n")
        common = ["--machine", args.machine_copy, "--tools", tools, "--vars", os.path.join(scratch, "n.vars")]
        restart = json.loads(nckit_json([args.nckit, "restart", args.program, "--line", str(args.start_line),
                                         "--json", "-o", os.path.join(scratch, "restart.nc"), *common]))
        motions = [json.loads(l) for l in nckit_json([args.nckit, "moves", args.program, "--json",
                                                      *common]).splitlines() if l.strip()]
        motions = [m for m in motions if m["kind"] in ("rapid", "linear", "arc", "sync")]
        summary = {"start_line": args.start_line, "restart_state": restart["state"]}
        t0 = time.monotonic()
        for own in (False, True):
            work = os.path.join(scratch, "own" if own else "plugin")
            os.makedirs(work)
            os.chmod(work, 0o755)
            disp, rows, axes, log = run_once(args, work, own)
            used = f"using custom interpreter '{args.plugin}'" in log
            if used == own:
                fail(f"LinuxCNC {'loaded' if own else 'did not load'} the plug-in in the "
                     f"{'comparison' if own else 'plug-in'} run; log tail:\n{log[-2000:]}")
            if not own:
                summary["plugin"] = {"at_start_line": disp["at_start_line"],
                                     **check_plugin_run(args, disp, rows, axes, restart, motions)}
            else:
                at = disp["at_start_line"]
                summary["linuxcnc_own"] = {"at_start_line": at, "errors": disp["errors"]}
                if at is None or at["spindle_direction"] != 0:
                    fail(f"LinuxCNC's own run from line no longer leaves the spindle stopped at line "
                         f"{args.start_line} ({at}): docs/linuxcnc-plugin.md says it does")
        summary["run_s"] = round(time.monotonic() - t0, 1)
        print(json.dumps(summary))
        return 0
    finally:
        os.close(lock)
        if args.keep:
            shutil.copytree(scratch, args.keep, dirs_exist_ok=True,
                            ignore=shutil.ignore_patterns("rtapi*"))
        shutil.rmtree(scratch, ignore_errors=True)


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "--display":
        return display_main(sys.argv[2:])
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--plugin", required=True)
    ap.add_argument("--nckit", required=True)
    ap.add_argument("--config", required=True, help="example INI (examples/linuxcnc/...)")
    ap.add_argument("--program", required=True)
    ap.add_argument("--start-line", type=int, required=True)
    ap.add_argument("--tool", action="append", required=True, help="a tool table row (LinuxCNC tool.tbl)")
    ap.add_argument("--safe-mm", type=float, default=40.0, help="the machine file's restart_safe_mm")
    ap.add_argument("--tolerance-mm", type=float, default=0.01)
    ap.add_argument("--timeout", type=float, default=120.0)
    ap.add_argument("--keep", metavar="DIR", help="keep configurations, logs and samples here")
    return parent_main(ap.parse_args())


if __name__ == "__main__":
    sys.exit(main())
