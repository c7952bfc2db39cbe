"""What tests/linuxcnc_plugin/run_machine.py and tests/hal/piston_machine_test.py share: LinuxCNC
INI files read and rewritten, halsampler's rows, and the distance of sampled positions from
nckit's move path (lines, arcs and helices, spindle-synchronised moves, in machine coordinates).
"""

import math
import os

TOL_MM = 1e-4


def read_ini(path):
    """{(SECTION, KEY): [values]} of an INI file (LinuxCNC allows a key more than once)."""
    values, section = {}, None
    with open(path) as f:
        for line in f:
            s = line.strip()
            if not s or s[0] in "#;":
                continue
            if s.startswith("["):
                section = s[1:s.index("]")].strip().upper()
            elif "=" in s and section:
                k, v = s.split("=", 1)
                values.setdefault((section, k.strip().upper()), []).append(v.strip())
    return values


def rewrite_ini(text, replace, append):
    """The INI text with `replace` {(SECTION, KEY): value} set (added when missing) and `append`
    {SECTION: [lines]} added at the end of those sections."""
    out, section, done = [], None, set()

    def close_section():
        if section is None:
            return
        for (sec, key), value in replace.items():
            if sec == section and (sec, key) not in done:
                out.append(f"{key} = {value}")
                done.add((sec, key))
        out.extend(append.get(section, []))

    for line in text.splitlines():
        s = line.strip()
        if s.startswith("["):
            close_section()
            section = s[1:s.index("]")].strip().upper()
            out.append(line)
            continue
        if section and "=" in s and not s.startswith(("#", ";")):
            key = s.split("=", 1)[0].strip().upper()
            if (section, key) in replace:
                if (section, key) not in done:
                    out.append(f"{key} = {replace[(section, key)]}")
                    done.add((section, key))
                continue
        out.append(line)
    close_section()
    return "\n".join(out) + "\n"


PLANES = {"xy": ("X", "Y", "Z"), "zx": ("Z", "X", "Y"), "yz": ("Y", "Z", "X")}


def distance(p, mo, axes):
    """Distance in mm of point p (axis -> mm) from motion mo (start and end given)."""
    a, b = mo["start"], mo["end"]
    if mo["kind"] != "arc":
        d = [b.get(x, 0.0) - a.get(x, 0.0) for x in axes]
        w = [p[x] - a.get(x, 0.0) for x in axes]
        dd = sum(v * v for v in d)
        t = 0.0 if dd == 0 else max(0.0, min(1.0, sum(u * v for u, v in zip(d, w)) / dd))
        return math.sqrt(sum((w[i] - t * d[i]) ** 2 for i in range(len(axes))))
    f, s, n = PLANES[mo["plane"]]
    c = mo["center"]
    r = math.hypot(a[f] - c[f], a[s] - c[s])
    ang = lambda q: math.atan2(q[s] - c[s], q[f] - c[f])
    a0, a1, ap = ang(a), ang(b), ang(p)
    ccw = mo["dir"] == "ccw"
    sweep = ((a1 - a0) if ccw else (a0 - a1)) % (2 * math.pi)
    turns = mo.get("turns", 1) or 1
    if sweep < 1e-12:
        sweep = 2 * math.pi
    sweep += 2 * math.pi * (turns - 1)
    at = ((ap - a0) if ccw else (a0 - ap)) % (2 * math.pi)
    best = float("inf")
    k = 0
    while at + 2 * math.pi * k <= sweep + 1e-12:  # every turn of a multi-turn helix
        t = (at + 2 * math.pi * k) / sweep
        dn = p.get(n, 0.0) - (a.get(n, 0.0) + t * (b.get(n, 0.0) - a.get(n, 0.0))) if n in p else 0.0
        best = min(best, math.hypot(abs(math.hypot(p[f] - c[f], p[s] - c[s]) - r), dn))
        k += 1
    ends = [math.sqrt(sum((p[x] - q.get(x, 0.0)) ** 2 for x in axes)) for q in (a, b)]
    return min([best] + ends)


def check_path(rows, motions, axes):
    """Follows the samples along the path in order. Returns (worst distance of a sample from
    nckit's path, mm; index of the last motion reached; {motion kind: worst distance})."""
    index, worst, by_kind = 0, 0.0, {}
    window = 400  # motions looked ahead per sample; a servo tick passes far fewer
    for row in rows:
        p = dict(zip(axes, row))
        best, best_i = float("inf"), index
        # Most samples lie on the current motion or the next: look there first.
        for i in range(index, min(len(motions), index + window)):
            d = distance(p, motions[i], axes)
            if d < best - 1e-12:
                best, best_i = d, i
            if best <= TOL_MM / 10 or (i >= index + 2 and best <= TOL_MM):
                break
        kind = motions[best_i]["kind"]
        by_kind[kind] = max(by_kind.get(kind, 0.0), best)
        worst = max(worst, best)
        index = best_i
    return worst, index, by_kind


def interpolator_bound_mm(ini_path, axes):
    """How far LinuxCNC's joint interpolator may put a joint off the planner's path, mm.

    Motion hands each planner point to a cubic interpolator per joint whose waypoint at period k
    is (x[k-1] + 4 x[k] + x[k+1]) / 6: the planner's point moved by its second difference / 6,
    at most a T^2 / 6 on an axis whose acceleration is limited to a (T the servo period). On
    trivkins joints are axes; the distance bound is the norm over the axes."""
    ini = read_ini(ini_path)
    period_s = float(ini[("EMCMOT", "SERVO_PERIOD")][0]) * 1e-9
    return math.sqrt(sum((float(ini[(f"AXIS_{a}", "MAX_ACCELERATION")][0]) * period_s ** 2 / 6) ** 2
                         for a in axes))


def read_samples(path, n):
    rows, last_tag, gaps = [], None, 0
    with open(path) as f:
        for line in f:
            parts = line.split()
            if len(parts) != 1 + n:
                if line.strip() == "overrun":
                    gaps += 1
                continue
            tag = int(parts[0])
            if last_tag is not None and tag != last_tag + 1:
                gaps += 1
            last_tag = tag
            rows.append(tuple(float(v) for v in parts[1:]))
    return rows, gaps


def open_lock(path):
    """The lock file, opened for flock by any user: read-only, so that a file another user made
    (root's 0644, say) serves a plain user too; created when missing."""
    return os.open(path, os.O_RDONLY | os.O_CREAT, 0o666)
