#!/usr/bin/env python3
"""MDI through nckit's interpreter plug-in on a simulated LinuxCNC machine, headless: commands are
sent as an operator types them in MDI mode (`linuxcnc.command().mdi`), the way LinuxCNC's task
hands them to the plug-in's execute(command), and the machine's position and LinuxCNC's errors
are checked after each.

  mdi_machine.py --plugin LIB.so --config EXAMPLE.ini --library DIR

The configuration is prepared as run_machine.py prepares it ([TASK] INTERPRETER the plug-in,
RETAINED a scratch file, LIBRARY the folder given). The steps (STEPS below) cover: a plain block;
Macro B assignments and expressions whose variables carry from one command to the next; G91
relative to where the last command left the machine; a jog in manual mode, after which MDI goes
on from the jogged position (the plug-in's synch()); IF ... THEN; a G65 macro call from the
library; a retained variable (#510) that must be in the RETAINED file afterwards; a macro alarm
that LinuxCNC must report without moving, after which MDI works again.

Exit status 0 when every step holds, 1 otherwise (the reason on stderr).
"""

import argparse
import fcntl
import json
import os
import shutil
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import run_machine as rm  # noqa: E402  (configuration, starting LinuxCNC, the lock)

TOL_MM = 1e-6

# Each step: an MDI command or a jog, and what must hold afterwards. "at": X Y Z in mm
# (machine coordinates; the scratch configuration has no work offsets).
STEPS = [
    {"mdi": "G21 G90 G17 G94 G0 X10 Y5 Z2", "at": [10, 5, 2]},
    {"mdi": "#1 = 3"},
    {"mdi": "#2 = [#1 * 2 + 1]"},                     # 7: #1 kept from the command before
    {"mdi": "G1 X#2 F600", "at": [7, 5, 2]},
    {"mdi": "G91 G0 X1", "at": [8, 5, 2]},            # relative to where MDI left it
    {"mdi": "G90"},
    {"jog": [0, 2.5], "at": [10.5, 5, 2]},            # X by hand, in manual mode
    {"mdi": "G91 G1 X1 F600", "at": [11.5, 5, 2]},    # from the jogged position
    {"mdi": "G90"},
    {"mdi": "IF [#1 EQ 3] THEN #3 = 20"},
    {"mdi": "G0 Y#3", "at": [11.5, 20, 2]},
    {"mdi": "G65 P9100 A#1 B4", "at": [12, 20, 2]},   # library macro O9100: X = A * B
    {"mdi": "#510 = [#2 * 6]", "retained": {"510": 42}},
    {"mdi": "G1 Z[#510 / 14] F300", "at": [12, 20, 3]},
    {"mdi": "#3000 = 7 (MDI ALARM)", "error": "alarm 3007", "at": [12, 20, 3]},
    {"mdi": "G0 X1", "at": [1, 20, 3]},               # MDI goes on after the alarm
]


# ---------------------------------------------------------------------------------------------
# The DISPLAY: runs inside LinuxCNC under /usr/bin/python3
# ---------------------------------------------------------------------------------------------

def display_main(argv):
    ini = argv[argv.index("-ini") + 1]
    work = os.path.dirname(os.path.abspath(ini))
    with open(os.path.join(work, "run.json")) as f:
        run = json.load(f)
    result = {"errors": [], "steps": [], "phase": "start"}
    session = None
    try:
        import linuxcnc
        session = rm.lp.DisplaySession(linuxcnc, result, run["run_timeout_s"])
        s, c = session.s, session.c
        session.machine_on_in_auto()

        def mode(m):
            if s.task_mode != m:
                c.mode(m)
                c.wait_complete(5)
                session.wait_for(lambda: s.task_mode == m, f"mode {m}", 10, stop_on_error=False)

        def settled():
            return (s.interp_state == linuxcnc.INTERP_IDLE and s.queue == 0 and s.inpos
                    and s.exec_state == linuxcnc.EXEC_DONE)

        for step in run["steps"]:
            result["phase"] = json.dumps(step)
            before = len(result["errors"])
            if "mdi" in step:
                mode(linuxcnc.MODE_MDI)
                c.mdi(step["mdi"])
                c.wait_complete(5)
            else:
                joint, distance = step["jog"]
                mode(linuxcnc.MODE_MANUAL)
                c.teleop_enable(0)
                c.wait_complete(5)
                c.jog(linuxcnc.JOG_INCREMENT, True, joint, 20.0, distance)
                c.wait_complete(5)
            time.sleep(0.3)
            session.wait_for(settled, "the step to finish", 60, stop_on_error=False)
            time.sleep(0.1)
            session.poll_errors()
            s.poll()
            result["steps"].append({"position": list(s.position[:3]),
                                    "errors": result["errors"][before:]})
        result["phase"] = "done"
    except Exception as ex:
        result["errors"].append(f"{type(ex).__name__}: {ex}")
    finally:
        with open(os.path.join(work, "display_result.json"), "w") as f:
            json.dump(result, f)
    return 0


# ---------------------------------------------------------------------------------------------
# The parent
# ---------------------------------------------------------------------------------------------

def read_retained(path):
    values = {}
    if os.path.exists(path):
        with open(path) as f:
            for line in f:
                if "=" in line and line.startswith("#"):
                    k, v = line[1:].split("=", 1)
                    values[k.strip()] = float(v)
    return values


def check(steps, disp, retained):
    """The first step that does not hold, as text; None when all hold."""
    got = disp.get("steps", [])
    if len(got) != len(steps):
        return f"only {len(got)} of {len(steps)} steps ran (phase {disp.get('phase')}): {disp['errors']}"
    for i, (want, have) in enumerate(zip(steps, got)):
        what = f"step {i + 1} ({want.get('mdi') or 'jog ' + str(want.get('jog'))})"
        if "error" in want:
            if not any(want["error"] in e for e in have["errors"]):
                return f"{what}: LinuxCNC did not report '{want['error']}': {have['errors']}"
        elif have["errors"]:
            return f"{what}: LinuxCNC reported {have['errors']}"
        if "at" in want:
            off = max(abs(a - b) for a, b in zip(have["position"], want["at"]))
            if off > TOL_MM:
                return f"{what}: the machine stands at {have['position']}, not {want['at']}"
        for number, value in want.get("retained", {}).items():
            if abs(retained.get(number, float("nan")) - value) > 1e-9:
                return f"{what}: #{number} in the RETAINED file is {retained.get(number)}, not {value}"
    return None


def parent_main(args):
    args.plugin = os.path.abspath(args.plugin)
    for tool in ("linuxcnc", "script", "halrun"):
        if shutil.which(tool) is None:
            rm.fail(f"'{tool}' not on PATH: install linuxcnc-uspace (scripts/deps.sh)")
    work = tempfile.mkdtemp(prefix="nckit-plugin-mdi-")
    env = dict(os.environ)
    lock = rm.open_lock(rm.LOCKFILE)
    try:
        fcntl.flock(lock, fcntl.LOCK_EX)
        os.chmod(work, 0o755)
        ini_path, _, _ = rm.prepare(args, work, display_script=__file__)
        with open(os.path.join(work, "run.json"), "w") as f:
            json.dump({"steps": STEPS, "run_timeout_s": max(10.0, args.timeout - 30.0)}, f)
        rm.unprivileged(work, env)
        log = rm.run_linuxcnc(args, work, ini_path, env)
        if f"using custom interpreter '{args.plugin}'" not in log:
            rm.fail(f"LinuxCNC did not load the plug-in; log tail:\n{log[-2000:]}")
        result_path = os.path.join(work, "display_result.json")
        if not os.path.exists(result_path):
            rm.fail(f"the display did not run; log tail:\n{log[-2000:]}")
        with open(result_path) as f:
            disp = json.load(f)
        # The retained file as the run left it: each step's own check reads the final file, so
        # only the last value of a variable can be asked for.
        failure = check(STEPS, disp, read_retained(os.path.join(work, "retained.vars")))
        if failure:
            rm.fail(failure)
        print(json.dumps({"steps": len(STEPS), "positions": [s["position"] for s in disp["steps"]]}))
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
    ap.add_argument("--config", required=True, help="example INI (examples/linuxcnc/...)")
    ap.add_argument("--library", required=True, help="[NCKIT] LIBRARY: holds O9100.nc")
    ap.add_argument("--timeout", type=float, default=180.0)
    ap.add_argument("--keep", metavar="DIR", help="keep the configuration and log here")
    return parent_main(ap.parse_args())


if __name__ == "__main__":
    sys.exit(main())
