#!/usr/bin/env python3
"""`nckit notch` streams: its output equals the golden files (made before it streamed), it runs
a long generated program in bounded memory (peak RSS measured by getrusage of the child), and
`nckit notch ... | head -1` ends.

Usage: notch_stream_test.py NCKIT REPO_ROOT"""
import json
import os
import subprocess
import sys
import tempfile

nckit, root = sys.argv[1], sys.argv[2]
golden = os.path.join(root, "tests/process/notch_golden")
machine = os.path.join(root, "examples/machines/notcher.toml")
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL:", what)


def run(args, **kwargs):
    return subprocess.run([nckit, *args], capture_output=True, text=True, cwd=root, **kwargs)


def expected(name):
    with open(os.path.join(golden, name)) as f:
        return f.read()


def peak_rss_mb(args, stdout=subprocess.DEVNULL):
    """Peak resident memory of one run of nckit, by GNU time (its %M: the child's own maximum RSS;
    getrusage from Python would count the forked interpreter's pages): (run, MB)."""
    with tempfile.NamedTemporaryFile(mode="r") as rss:
        r = subprocess.run(["/usr/bin/time", "-f", "%M", "-o", rss.name, nckit, *args], stdout=stdout,
                           stderr=subprocess.PIPE, text=True, cwd=root)
        return r, int(rss.read().split()[-1]) / 1024.0


# 1. The same bytes as the whole-program implementation wrote, on every golden program (the
#    JSON report: the same values, numbers compared exactly, whatever their spelling).
with tempfile.TemporaryDirectory() as tmp:
    rel = "tests/process/notch_golden"
    for program in ["examples/notch/conrod.nc", f"{rel}/multi.nc", f"{rel}/oblique.nc", f"{rel}/macro.nc"]:
        name = os.path.basename(program)[:-3]
        out = os.path.join(tmp, name + ".nc")
        r = run(["notch", program, "--machine", machine, "-o", out])
        check(r.returncode == 0, f"{name}: exit {r.returncode} {r.stderr}")
        check(r.stdout == expected(name + ".txt.expected"), f"{name}: text report differs")
        check(open(out).read() == expected(name + ".notched.nc.expected"), f"{name}: rewritten program differs")
        r = run(["notch", program, "--machine", machine, "--json"])
        check(json.loads(r.stdout) == json.loads(expected(name + ".json.expected")), f"{name}: JSON report differs")
    out = os.path.join(tmp, "stdin.nc")
    with open(os.path.join(golden, "multi.nc")) as f:
        r = run(["notch", "-", "--machine", machine, "-o", out], stdin=f)
    check(r.returncode == 0 and r.stdout == expected("stdin.txt.expected"), "program from standard input: report differs")
    check(open(out).read() == expected("stdin.notched.nc.expected"), "program from standard input: program differs")
    # -o - : the rewritten program, then the report, both on standard output.
    r = run(["notch", "examples/notch/conrod.nc", "--machine", machine, "-o", "-"])
    check(r.stdout == expected("conrod.notched.nc.expected") + expected("conrod.txt.expected"), "-o -: output differs")
    never = os.path.join(tmp, "never.nc")
    r = run(["notch", f"{rel}/crossing.nc", "--machine", machine, "-o", never])
    check(r.returncode == 2 and r.stderr == expected("crossing.err.expected") and r.stdout == "",
          f"crossing: exit {r.returncode}, stderr {r.stderr!r}")
    check(not os.path.exists(never), "crossing: -o written although refused")

    # 2. Long programs. The notches sit 0.5 mm apart along X on a notcher with a long X travel;
    # filler blocks (short moves above the notches) make a program long without adding cuts.
    long_machine = os.path.join(tmp, "long_notcher.toml")
    with open(machine) as f:
        text = f.read()
    with open(long_machine, "w") as f:
        f.write(text.replace("max = 1200.0", "max = 200000.0", 1))

    def write_program(path, notches, fillers_per_notch):
        with open(path, "w") as f:
            f.write("G90 G1 X0 Z40 F3000\n")
            for i in range(notches):
                x = 10 + 0.5 * i
                for k in range(fillers_per_notch):
                    f.write(f"G1 X{x - 0.25:.3f} Z{40 + (k % 2):d} F3000\n")
                f.write(f"G0 X{x:.3f} Z30\nG1 Z20 F4000\nM27\nG1 Z8 F900\nM28\n")
            f.write(f"G0 X{10 + 0.5 * notches + 5:.3f} Z40\nM30\n")

    few = os.path.join(tmp, "few_notches_short.nc")
    few_long = os.path.join(tmp, "few_notches_long.nc")
    thousand = os.path.join(tmp, "thousand_notches.nc")
    many = os.path.join(tmp, "many_notches.nc")
    write_program(few, 30, 1)
    write_program(few_long, 30, 1000)       # 30,000 filler blocks
    write_program(thousand, 500, 0)         # 500 notches, 2,500 blocks
    write_program(many, 2500, 0)            # 2,500 notches, 12,500 blocks
    r, short_mb = peak_rss_mb(["notch", few, "--machine", long_machine, "--json"])
    check(r.returncode == 0, f"short program: {r.stderr}")
    r, long_mb = peak_rss_mb(["notch", few_long, "--machine", long_machine, "--json"])
    check(r.returncode == 0, f"long program: {r.stderr}")
    # The same 30 cuts with 1000 times the blocks: memory does not grow with the blocks (a
    # whole-program hold would add about 3 KB a block, 90 MB here).
    check(long_mb < short_mb + 16, f"peak memory grows with blocks: {short_mb:.1f} MB -> {long_mb:.1f} MB")
    # Flat in the number of cuts: 500 and 2,500 cuts in passes of 100 cuts hold the same
    # records (a record per cut held would add about 1.4 KB x 2,000 = 2.8 MB on about 11 MB).
    per_pass = ["--cuts-per-pass", "100"]
    r, thousand_mb = peak_rss_mb(["notch", thousand, "--machine", long_machine, "--json", *per_pass])
    check(r.returncode == 0, f"500 notches: {r.stderr}")
    out = os.path.join(tmp, "many_out.nc")
    with open(out + ".100.json", "w") as report:
        r, many_mb = peak_rss_mb(["notch", many, "--machine", long_machine, "-o", out + ".100", "--json", *per_pass],
                                 stdout=report)
    check(r.returncode == 0 and r.stderr == "", f"2,500 notches: {r.stderr}")
    check(many_mb < thousand_mb * 1.15,
          f"peak memory grows with cuts: 500 cuts {thousand_mb:.1f} MB, 2,500 cuts {many_mb:.1f} MB")
    # The rewritten program and the report do not depend on the passes (default: 4096 cuts).
    with open(out + ".json", "w") as report:
        r = subprocess.run([nckit, "notch", many, "--machine", long_machine, "-o", out, "--json"], stdout=report,
                           stderr=subprocess.PIPE, text=True)
    check(r.returncode == 0, f"2,500 notches in default passes: {r.stderr}")
    check(open(out).read() == open(out + ".100").read(), "rewritten program differs with --cuts-per-pass 100")
    check(open(out + ".json").read() == open(out + ".100.json").read(), "report differs with --cuts-per-pass 100")
    print(f"peak RSS: 30 cuts {short_mb:.1f} MB, 30 cuts + 30k blocks {long_mb:.1f} MB; in passes of 100: "
          f"500 cuts {thousand_mb:.1f} MB, 2,500 cuts {many_mb:.1f} MB")

    # 3. `| head -1` ends the run: the report's first line comes before the job is done.
    p = subprocess.Popen(f"'{nckit}' notch '{many}' --machine '{long_machine}' | head -1", shell=True,
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    first, _ = p.communicate(timeout=1200)
    check(first == f"{many}: 2500 notch cut(s)\n", f"head -1: {first!r}")

if failures:
    sys.exit(1)
print("ok")
