"""nckit_cam's cost per call in LinuxCNC's halrun, and the example piston with the loop in HAL.

  flock /tmp/nckit-linuxcnc.lock python3 bench/hal_cam_bench.py [--nckit build/release/src/nckit] [--calls 1000000]

Cost: the example's spindle (sim_encoder, encoder, 2500 rpm, 360 counts) and Z feeding per turn
drive nckit-cam.0 in a 66.666 us thread; its `call-ns` pin (the function's own duration by
CPU clocks scaled to ns, the two clock reads included) is sampled every period for --calls periods, once
with the cam alone and once with feedforward and learning on; prints the median, the 99.9th
percentile and the worst. Then runs examples/linuxcnc/piston_lathe/run.sh, with feedforward and
with learning (LEARNING=1). Needs the modules
installed (cmake --build build/release --target hal-install).
"""
import argparse
import json
import os
import subprocess
import sys

here = os.path.dirname(os.path.abspath(__file__))
source = os.path.dirname(here)
sys.path.insert(0, os.path.join(source, "tests", "hal"))
from hal_graph import spindle_graph  # noqa: E402
from halrun_support import make_workdir, run_hal  # noqa: E402


def cost(nckit, calls, setup, label):
    workdir = make_workdir("nckit_hal_bench_")
    table = os.path.join(workdir, "piston_cam.csv")
    subprocess.run([nckit, "piston", os.path.join(source, "examples/linuxcnc/piston_lathe/piston.toml"),
                    "--cam-table", table], check=True, capture_output=True)
    os.chmod(table, 0o644)
    text = spindle_graph(table, z_offset_mm=0.0, z_mm_rev=0.1, sampled=[("s", "nckit-cam.0.call-ns")],
                         samples=calls, depth=200000, cam_setup=setup)
    status, output = run_hal(text, workdir, timeout_s=3600)
    if status != 0:
        sys.exit(f"halrun failed ({status}):\n{output}")
    values = []
    with open(os.path.join(workdir, "samples.txt")) as f:
        for line in f:
            fields = line.split()
            if len(fields) == 2:
                values.append(int(fields[1]))
            elif line.strip() == "overrun":
                sys.exit("the sampler overran")
    values.sort()
    n = len(values)
    result = {"case": label, "calls": n, "median_ns": values[n // 2], "p999_ns": values[int(n * 0.999)],
              "worst_ns": values[-1]}
    print(json.dumps(result))
    return result


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--nckit", default=os.path.join(source, "build/release/src/nckit"))
    parser.add_argument("--calls", type=int, default=1000000)
    parser.add_argument("--skip-example", action="store_true")
    args = parser.parse_args()
    cost(args.nckit, args.calls, "", "cam only")
    cost(args.nckit, args.calls, "setp nckit-cam.0.feedforward-enable 1\nsetp nckit-cam.0.learning-enable 1\n"
         "setp nckit-cam.0.dac-bits 16", "cam + feedforward + learning + DAC")
    if not args.skip_example:
        run = os.path.join(source, "examples/linuxcnc/piston_lathe/run.sh")
        subprocess.run([run, args.nckit], check=True)
        subprocess.run([run, args.nckit], check=True, env=dict(os.environ, LEARNING="1"))


if __name__ == "__main__":
    main()
