"""The piston's profile error from piston_lathe.hal's samples beside nckit's simulated figure.

  profile_error.py SAMPLES.txt NCKIT.json [LEARNING]

SAMPLES: halsampler -t lines `tag counts z wanted command position error [fault index x]` (from
piston_lathe.hal, or from piston_sampler.hal on the machine of piston_machine.ini). The cut is
every sample while Z is between the crown (its first value) and its end (its largest value);
the error there is the axis position minus where the cam wants it (nckit_cam's error pin): its
peak to valley and RMS in um, as `nckit piston` reports them over the turned surface, beside its
feedforward run (its learning run when LEARNING is 1). Prints one JSON object.
"""
import json
import math
import sys


def main():
    samples, nckit_json = sys.argv[1], sys.argv[2]
    run = "learning" if len(sys.argv) > 3 and sys.argv[3] == "1" else "feedforward"
    rows = []
    with open(samples) as f:
        for line in f:
            fields = line.split()
            if len(fields) < 7:
                if line.strip() == "overrun":
                    sys.exit(f"{samples}: the sampler overran: samples were lost")
                continue
            rows.append((float(fields[2]), float(fields[6])))
    if not rows:
        sys.exit(f"{samples}: no samples")
    first_z, last_z = rows[0][0], max(z for z, _ in rows)
    errors = [error * 1e3 for z, error in rows if first_z < z < last_z]
    if len(errors) < 1000:
        sys.exit(f"{samples}: only {len(errors)} samples of the cut")
    with open(nckit_json) as f:
        simulated = json.load(f)["profile_error_um"][run]
    pv = max(errors) - min(errors)
    rms = math.sqrt(sum(e * e for e in errors) / len(errors))
    print(json.dumps({"run": run, "hal_pv_um": round(pv, 4), "hal_rms_um": round(rms, 4),
                      "nckit_pv_um": round(simulated["pv"], 4), "nckit_rms_um": round(simulated["rms"], 4),
                      "cut_samples": len(errors)}))


if __name__ == "__main__":
    main()
