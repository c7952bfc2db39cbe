#!/usr/bin/env python3
"""The piston lathe of examples/linuxcnc/piston_lathe/piston_machine.ini as LinuxCNC runs it:
the whole machine (task, motion, the spindle and its encoder, nckit_cam, nckit_servo), headless,
turning piston.ngc.

  piston_machine_test.py --nckit NCKIT --reference CAM_REFERENCE --source SOURCE_DIR
                         [--feed-mm-rev F] [--learning] [--keep DIR]

The example configuration is copied into a scratch folder with the cam table that
`nckit piston piston.toml --cam-table` writes there (the INI names it relative to its folder, as
the example does) and this script as its DISPLAY; the example's own sampler (piston_sampler.hal)
records the spindle's counts and index, Z, the cam's pins and the servo's position. With
--feed-mm-rev the job is the example piston at that Z feed per turn, in piston.toml (for
`nckit piston`) and in piston.ngc's G95 feed alike: the same piston over the same Z range in
fewer turns (CTest runs 1 mm/rev, 50 turns of cut instead of 500). LinuxCNC is started as tests/linuxcnc_plugin/run_machine.py starts it (a
terminal from `script`; as root RTAPI_UID=65534 and RTAPI_FIFO_PATH in a world-writable folder).
The display part (Debian's /usr/bin/python3 with the `linuxcnc` module) resets the E-stop,
switches the machine on, runs piston.ngc and drains the sampler while it runs.

Checks:
- LinuxCNC ran the program to its end without an error, and the carriage reached Z 50;
- no period was lost (halsampler's tags run on) and nckit_cam raised no fault;
- the carriage went over the program's Z range (from its first Z word to its largest);
- the spindle turned at the programmed speed (counts per period from the encoder);
- where the cam wants the servo (its wanted pin) is nckit's cam (cam_reference: the cam table
  evaluated by nckit's library) at the sampled count since the index and Z, within 1e-6 mm;
- over the cut (Z off the crown) the fast tool servo's profile error, its position at the start
  of each period (the sample before) minus nckit's cam at the period's sampled count since the
  index and Z (cam_reference, not the component's own error pin), has a peak to valley within 10 % of the figure `nckit piston --json` simulates for
  the same job (feedforward; with --learning the learning run's figure, within 0.02 um or 50 %,
  as hal_cam_learning allows).

Exit status 0 when every check holds, 1 otherwise (the reason on stdout). One LinuxCNC at a
time: the run holds an flock on /tmp/nckit-linuxcnc.lock.
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
REPO = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, os.path.join(REPO, "bench"))
sys.path.insert(0, os.path.join(REPO, "tests", "linuxcnc_plugin"))
import linuxcnc_planner as lp  # noqa: E402  (the display session, stopping LinuxCNC)
import run_machine as rm  # noqa: E402  (starting LinuxCNC)
from machine_support import open_lock, rewrite_ini  # noqa: E402

EXAMPLE = os.path.join("examples", "linuxcnc", "piston_lathe")
LOCKFILE = "/tmp/nckit-linuxcnc.lock"
# The columns piston_sampler.hal records after halsampler's tag: encoder counts, Z, the cam's
# wanted position, its command, the servo's position, the error, the fault bit, the index, X.
COLUMNS = 9
COUNTS, Z, WANTED, COMMAND, POSITION, ERROR, FAULT, INDEX, X = range(COLUMNS)
POSITION_BEFORE = COLUMNS  # the servo's position at the start of the period (added by check())
TIP = COLUMNS + 1  # X plus POSITION_BEFORE: the tool's tip, the radius it cuts (added by check())
COUNTS_PER_TURN = 360
PROGRAMMED_RPM = 2500.02
SERVO_PERIOD_S = 66666e-9
# halsampler prints 6 decimals (0.5 nm rounding) and the cam table's own bound is 0.07 nm.
CAM_TOLERANCE_MM = 1e-6


def fail(message):
    print(f"FAIL: {message}")
    sys.exit(1)


def program_z_range(program_text):
    """(first Z word, largest Z word) of the program, comments left out."""
    words = [float(v) for v in re.findall(r"Z\s*(-?[0-9.]+)", re.sub(r"\([^)]*\)", "", program_text.upper()))]
    if not words:
        fail("piston.ngc has no Z word")
    return words[0], max(words)


def with_feed(toml_text, program_text, feed_mm_rev):
    """The job and the program at another Z feed per turn (the piston's and the program's own
    feed lines rewritten; fails when either is not found exactly once)."""
    toml_text, n_job = re.subn(r"(?m)^feed_mm_rev\s*=\s*[0-9.]+", f"feed_mm_rev = {feed_mm_rev}", toml_text)
    program_text, n_prog = re.subn(r"(?m)^(G95 G1 [^F\n]*)F[0-9.]+", rf"\g<1>F{feed_mm_rev}", program_text)
    if n_job != 1 or n_prog != 1:
        fail(f"feed lines found: {n_job} in piston.toml, {n_prog} in piston.ngc (want one each)")
    return toml_text, program_text


def prepare(args, work):
    src = os.path.join(args.source, EXAMPLE)
    for name in ("piston_machine.hal", "piston_sampler.hal", "piston_machine.tbl"):
        shutil.copyfile(os.path.join(src, name), os.path.join(work, name))
    with open(os.path.join(src, "piston.toml")) as f:
        toml_text = f.read()
    with open(os.path.join(src, "piston.ngc")) as f:
        program_text = f.read()
    if args.feed_mm_rev is not None:
        toml_text, program_text = with_feed(toml_text, program_text, args.feed_mm_rev)
    for name, text in (("piston.toml", toml_text), ("piston.ngc", program_text)):
        with open(os.path.join(work, name), "w") as f:
            f.write(text)
    args.z_range_mm = program_z_range(program_text)
    table = os.path.join(work, "piston_cam.csv")
    job = subprocess.run([args.nckit, "piston", os.path.join(work, "piston.toml"), "--cam-table", table,
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
        lp.run_failed(session, result, ex)
    finally:
        lp.finish_run(session, result, work)
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


def counts_since_index(rows):
    """The count since the spindle's index at each row, from the sampled counts and index alone:
    the first rising edge is count 0 (before it, the raw count modulo the turn)."""
    zero, previous, out = None, 0, []
    for row in rows:
        counts, index = int(row[COUNTS]), int(row[INDEX])
        if index and not previous and zero is None:
            zero = counts
        previous = index
        out.append((counts - (zero or 0)) % COUNTS_PER_TURN)
    return out


def reference(args, table, work, name, rows, turn, column, centred=True):
    """cam_reference over `rows`: the sampled `column` against nckit's cam at the count since
    the index and Z; `centred`: about the stroke reference at Z (where nckit_cam wants the servo),
    otherwise the drawn radius itself."""
    path = os.path.join(work, name)
    with open(path, "w") as f:
        for row, k in zip(rows, turn):
            f.write(f"{k} {row[Z]!r} {row[column]!r}\n")
    out = subprocess.run([args.reference, table, str(COUNTS_PER_TURN), path] + (["centred"] if centred else []),
                         capture_output=True, text=True, timeout=120)
    if out.returncode != 0:
        fail(f"cam_reference failed: {out.stderr.strip()[:300]}")
    result = json.loads(out.stdout)
    if result["samples"] != len(rows):
        fail(f"cam_reference read {result['samples']} of {len(rows)} samples")
    return result


def check(rows, nckit, args, work, table):
    """The figures of the run, or fail()."""
    z_from, z_to = args.z_range_mm
    z = [r[Z] for r in rows]
    if min(z) > z_from + 1e-6 or max(z) < z_to - 1e-6:
        fail(f"the carriage went over Z {min(z):.4f} to {max(z):.4f} mm, not the program's {z_from} to {z_to}")
    faults = sum(1 for r in rows if r[FAULT] != 0)
    if faults:
        fail(f"nckit_cam raised its fault pin in {faults} periods")
    if not any(r[INDEX] for r in rows):
        fail("no spindle index pulse was sampled")
    turn = counts_since_index(rows)
    # The servo's position at the start of each period (the row before: the sampler runs after
    # nckit_servo has stepped), as nckit's simulation takes the plant's state at each tick against
    # that tick's cam value, and as nckit_cam reads its feedback pin.
    for row, before in zip(rows[1:], rows):
        row.append(before[POSITION])
        row.append(row[X] + before[POSITION])
    cut = [(r, k) for r, k in zip(rows[1:], turn[1:]) if z_from < r[Z] < z_to]
    feed_mm_rev = nckit["feed_mm_rev"]
    turns = (z_to - z_from) / feed_mm_rev
    if len(cut) < 0.9 * turns * COUNTS_PER_TURN:
        fail(f"only {len(cut)} periods of cut sampled ({turns:.0f} turns wanted)")
    cut_rows, cut_turn = [r for r, _ in cut], [k for _, k in cut]
    # Spindle speed from the counts over the cut: counts per period times the periods per second.
    periods = len(cut_rows) - 1
    counts = cut_rows[-1][COUNTS] - cut_rows[0][COUNTS]
    rpm = counts / COUNTS_PER_TURN / (periods * SERVO_PERIOD_S) * 60
    if abs(rpm - PROGRAMMED_RPM) > 0.01 * PROGRAMMED_RPM:
        fail(f"the spindle turned at {rpm:.1f} rpm, not the programmed {PROGRAMMED_RPM}")
    wanted = reference(args, table, work, "wanted.txt", rows, turn, WANTED)
    if not wanted["max_engine_error_mm"] <= CAM_TOLERANCE_MM:
        fail(f"nckit_cam wanted the servo {wanted['max_engine_error_mm']} mm off nckit's cam at counts "
             f"{wanted['at_counts']}, Z {wanted['at_z_mm']}")
    profile = reference(args, table, work, "profile.txt", cut_rows, cut_turn, POSITION_BEFORE)
    pv = (profile["max_signed_engine_mm"] - profile["min_signed_engine_mm"]) * 1e3
    turned = reference(args, table, work, "turned.txt", cut_rows, cut_turn, TIP, centred=False)
    turned_pv = (turned["max_signed_engine_mm"] - turned["min_signed_engine_mm"]) * 1e3
    pin_errors_um = [r[ERROR] * 1e3 for r in cut_rows]
    rms = math.sqrt(sum(e * e for e in pin_errors_um) / len(pin_errors_um))
    run = "learning" if args.learning else "feedforward"
    want = nckit["profile_error_um"][run]["pv"]
    figures = {"run": run, "feed_mm_rev": feed_mm_rev, "hal_pv_um": round(pv, 4),
               "error_pin_pv_um": round(max(pin_errors_um) - min(pin_errors_um), 4), "error_pin_rms_um": round(rms, 4),
               "turned_pv_um": round(turned_pv, 4), "turned_max_um": round(turned["max_engine_error_mm"] * 1e3, 4),
               "nckit_pv_um": round(want, 4), "wanted_vs_cam_mm": wanted["max_engine_error_mm"],
               "cut_periods": len(cut_rows), "z_mm": [round(min(z), 4), round(max(z), 4)], "spindle_rpm": round(rpm, 2)}
    allowed = max(0.02, 0.5 * want) if args.learning else 0.1 * want
    if abs(pv - want) > allowed:
        fail(f"profile error {pv:.4f} um P-V on the machine against nckit's {want:.4f} um "
             f"(allowed +-{allowed:.4f}): {json.dumps(figures)}")
    if abs(turned_pv - want) > allowed:
        fail(f"the turned radius (X + servo) is {turned_pv:.4f} um P-V off the drawing against nckit's "
             f"{want:.4f} um (allowed +-{allowed:.4f}): {json.dumps(figures)}")
    return figures


def parent_main(args):
    args.nckit = os.path.abspath(args.nckit)
    args.reference = os.path.abspath(args.reference)
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
        elif not os.access(env.get("HOME", ""), os.W_OK):
            # LinuxCNC writes its logs and (uspace) its rtapi socket under HOME: a user without
            # one (nobody's /nonexistent) gets the scratch folder.
            env["HOME"] = work
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
        figures = check(rows, nckit, args, work, os.path.join(work, "piston_cam.csv"))
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
    ap.add_argument("--reference", required=True, help="tests/hal's cam_reference (nckit's cam evaluation)")
    ap.add_argument("--source", required=True, help="the nckit source folder")
    ap.add_argument("--feed-mm-rev", type=float, help="the job at this Z feed per turn (default: the example's)")
    ap.add_argument("--learning", action="store_true", help="learning across revolutions on")
    ap.add_argument("--timeout", type=float, default=300.0)
    ap.add_argument("--keep", metavar="DIR", help="keep the configuration, log and samples here")
    return parent_main(ap.parse_args())


if __name__ == "__main__":
    sys.exit(main())
