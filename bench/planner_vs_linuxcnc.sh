#!/usr/bin/env bash
# Trajectory planner, nckit against LinuxCNC 2.9: cycle time and peak commanded velocity and
# acceleration per axis for the programs in bench/planner_programs/, on the same limits.
#
# Usage: bench/planner_vs_linuxcnc.sh [NCKIT_BINARY]   (default build/release/src/nckit)
#
# LinuxCNC side: bench/linuxcnc_planner.py (headless sim, 1 ms servo, samples every tick), one
# run after another (only one LinuxCNC can run at a time). nckit side: `nckit plan --json
# --profile trapezoid|scurve --machine M.toml`, with a machine file of the same limits; while
# that verb does not exist (or the binary is missing) its columns read "n/a".
# Writes bench/planner_programs/linuxcnc_results.json (override with RESULTS=path) and prints a
# Markdown table. Takes about 3 minutes, almost all of it the 50,000-segment surface.
set -euo pipefail

repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
programs=$repo/bench/planner_programs
nckit=${1:-$repo/build/release/src/nckit}
results=${RESULTS:-$programs/linuxcnc_results.json}
jerk=50000   # mm/s^3 for nckit's S-curve (its built-in mill's value; LinuxCNC 2.9 has no jerk limit)

die() { echo "planner_vs_linuxcnc: $*" >&2; exit 1; }
command -v linuxcnc >/dev/null || die "linuxcnc not on PATH: run scripts/deps.sh (installs linuxcnc-uspace)"

work=$(mktemp -d -t nckit-planner-XXXXXX)
trap 'rm -rf "$work"' EXIT

# nckit plan is usable when the binary exists and lists the verb among its subcommands (an
# unknown verb's --help just prints the top-level help with status 0).
have_nckit=0
if [[ -x $nckit ]] && "$nckit" --help 2>/dev/null | grep -qE '^[[:space:]]+plan([[:space:]]|$)'; then
  have_nckit=1
fi
((have_nckit)) || echo "planner_vs_linuxcnc: '$nckit' has no 'plan' verb yet: nckit columns read n/a" >&2

# case name | program | max velocity mm/s | max acceleration mm/s^2
cases=(
  "square_100|square_100.ngc|100|500"
  "square_100 (issue: F3000, 500 mm/s², vmax = F)|square_100.ngc|50|500"
  "circle_2000|circle_2000.ngc|100|500"
  "surface_50k|surface_50k.ngc|100|500"
  "lathe_contour|lathe_contour.ngc|100|500"
)

[[ -f $programs/surface_50k.ngc ]] || "$repo/bench/planner_programs/gen_surface.py"

machine_file() {  # machine_file VMAX AMAX -> path of an nckit machine file with those limits
  local f=$work/machine_v$1_a$2.toml
  if [[ ! -f $f ]]; then
    {
      printf '[machine]\nname = "planner-bench"\nservo_period_s = 0.001\n\n'
      for ax in X Y Z; do
        printf '[[axis]]\nname = "%s"\nkind = "linear"\nmax_velocity = %s\nmax_acceleration = %s\n' "$ax" "$1" "$2"
        printf 'max_jerk = %s\nmin = -1000.0\nmax = 1000.0\nsteps_per_unit = 1000.0\n\n' "$jerk"
      done
    } > "$f"
  fi
  echo "$f"
}

i=0
for c in "${cases[@]}"; do
  IFS='|' read -r name prog vmax amax <<<"$c"
  echo "planner_vs_linuxcnc: $name (v $vmax mm/s, a $amax mm/s²): LinuxCNC ..." >&2
  printf '%s\n' "$name" > "$work/case$i.name"
  printf '%s %s %s\n' "$prog" "$vmax" "$amax" > "$work/case$i.args"
  if ! python3 "$repo/bench/linuxcnc_planner.py" --max-velocity "$vmax" --max-acceleration "$amax" \
         --program "$programs/$prog" --timeout 900 > "$work/case$i.linuxcnc.json"; then
    echo "planner_vs_linuxcnc: LinuxCNC run of $prog failed" >&2
    rm -f "$work/case$i.linuxcnc.json"
  fi
  for profile in trapezoid scurve; do
    out=$work/case$i.nckit_$profile.json
    if ((have_nckit)) && ! "$nckit" plan "$programs/$prog" --machine "$(machine_file "$vmax" "$amax")" \
           --profile "$profile" --json > "$out" 2>"$work/nckit.err"; then
      echo "planner_vs_linuxcnc: nckit plan --profile $profile failed on $prog:" >&2
      head -3 "$work/nckit.err" >&2
      rm -f "$out"
    fi
  done
  i=$((i + 1))
done

python3 - "$work" "$i" "$results" "$(dpkg-query -W -f='${Version}' linuxcnc-uspace 2>/dev/null || echo unknown)" <<'PY'
import json, os, sys
work, n, results, version = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4]

def load(path):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None

runs = []
for i in range(n):
    name = open(os.path.join(work, f"case{i}.name")).read().strip()
    prog, vmax, amax = open(os.path.join(work, f"case{i}.args")).read().split()
    lc = load(os.path.join(work, f"case{i}.linuxcnc.json"))
    if lc is not None:
        for ax in lc["axes"].values():
            ax["acceleration_over_limit_pct"] = round(
                max(0.0, ax["max_acceleration"] / float(amax) - 1.0) * 100.0, 3)
            ax["velocity_over_limit_pct"] = round(
                max(0.0, ax["max_velocity"] / float(vmax) - 1.0) * 100.0, 3)
    runs.append({"case": name, "program": prog, "max_velocity": float(vmax),
                 "max_acceleration": float(amax), "linuxcnc": lc,
                 "nckit_trapezoid": load(os.path.join(work, f"case{i}.nckit_trapezoid.json")),
                 "nckit_scurve": load(os.path.join(work, f"case{i}.nckit_scurve.json"))})

# Only LinuxCNC's side is recorded: nckit's numbers change with its code, LinuxCNC's do not.
with open(results, "w") as f:
    json.dump({"linuxcnc_version": version, "servo_period_s": 0.001,
               "machine": "XYZ trivkins sim, same limits on every axis and in [TRAJ], no homing",
               "runs": [{k: v for k, v in r.items() if not k.startswith("nckit")} for r in runs]},
              f, indent=2)
    f.write("\n")

def cyc(r):
    return f"{r['cycle_time_s']:.3f}" if r else "n/a"

def per_axis(r, key, fmt):
    if not r:
        return "n/a"
    return " / ".join(fmt.format(r["axes"][a][key]) if a in r["axes"] else "n/a" for a in "XYZ")

print("| program | v, a limits | moves | LinuxCNC cycle (s) | nckit trapezoid (s) | nckit S-curve (s) "
      "| LinuxCNC peak v X / Y / Z (mm/s) | LinuxCNC peak a X / Y / Z (mm/s²) | a over limit |")
print("|---|---|---:|---:|---:|---:|---|---|---|")
for r in runs:
    lc = r["linuxcnc"]
    over = "n/a"
    if lc:
        worst = max(ax["acceleration_over_limit_pct"] for ax in lc["axes"].values())
        over = f"+{worst:.1f} %" if worst > 0.05 else "no"
    print(f"| {r['case']} | {r['max_velocity']:g} mm/s, {r['max_acceleration']:g} mm/s² "
          f"| {lc['moves'] if lc else 'n/a'} | {cyc(lc)} | {cyc(r['nckit_trapezoid'])} "
          f"| {cyc(r['nckit_scurve'])} | {per_axis(lc, 'max_velocity', '{:.2f}')} "
          f"| {per_axis(lc, 'max_acceleration', '{:.1f}')} | {over} |")
PY
