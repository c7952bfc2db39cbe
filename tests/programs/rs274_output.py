"""LinuxCNC's standalone interpreter `rs274 -g`: running it and reading its canonical calls as
motions in absolute machine mm (deg), for tests that compare nckit with it.

How rs274's output is read (LinuxCNC 2.9):
- STRAIGHT_TRAVERSE / STRAIGHT_FEED (x, y, z, a, b, c[, u, v, w]) and ARC_FEED (first_end,
  second_end, first_centre, second_centre, rotation, axis_end, a, b, c[, u, v, w]) carry program
  coordinates in the current USE_LENGTH_UNITS; first/second are X,Y (G17), Z,X (G18), Y,Z (G19).
  A negative rotation is G2 (cw), a positive one G3 (ccw).
- Machine = reported + G5x offset + G92 offset; offsets are printed in the units active when they
  are set (G52 is printed as a G92 offset).
- Values are printed with 4 decimals in program units, so the tolerance is 1e-4 mm, widened to the
  printing resolution where that is coarser (inch programs, values summed with offsets).
- rs274 prints no source line numbers: the harness runs it a second time on a copy of the program
  with a `(nckit-line N)` comment at the end of every line, which rs274 echoes as COMMENT() before
  the block's motions. Both runs must give the same motions.
"""

from __future__ import annotations

import math
import re
import subprocess
from dataclasses import dataclass, field
from pathlib import Path

TOL_MM = 1e-4              # required agreement
PRINT_HALF_ULP = 0.5e-4    # rs274 prints %.4f: a printed value is within this of the true one
ALL_AXES = "XYZABCUVW"
COMPARED_AXES = "XYZABC"   # rs274 -g prints U V W only with an INI that configures them
ROTARY = "ABC"
UNITS_MM = {"CANON_UNITS_MM": 1.0, "CANON_UNITS_INCHES": 25.4, "CANON_UNITS_CM": 10.0}
PLANES = {  # canonical plane -> (first axis, second axis, axis normal to the plane)
    "CANON_PLANE_XY": ("X", "Y", "Z"),
    "CANON_PLANE_XZ": ("Z", "X", "Y"),
    "CANON_PLANE_YZ": ("Y", "Z", "X"),
}
COMPARED_KINDS = {"rapid", "linear", "arc", "sync"}
KNOWN_KINDS = COMPARED_KINDS | {"dwell", "io"}
LINE_TAG = "nckit-line"
# Canonical calls that move the machine in ways this harness does not model.
# STRAIGHT_PROBE (G38.x) is a feed to its point: rs274 simulates a probe that never trips.
UNSUPPORTED_CALLS = {"RIGID_TAP", "NURBS_FEED", "NURBS_G5_FEED", "NURBS_G6_FEED"}

CALL_RE = re.compile(r"^\s*\d+\s+N(\S*)\s+([A-Z_][A-Z0-9_]*)\((.*)\)\s*$")


class ProgramError(Exception):
    """The program, not the comparison, is at fault (rs274 rejects it, it leaves travel...)."""


@dataclass
class Motion:
    kind: str                                  # rapid, linear, arc, sync
    end: dict[str, float]                      # axis -> machine position, mm (deg)
    line: int | None = None                    # source line, when known
    center: dict[str, float] | None = None     # arcs: the two plane axes
    direction: str | None = None               # arcs: cw / ccw
    plane: tuple[str, str] | None = None       # arcs (rs274 side): first and second plane axes
    tol: dict[str, float] = field(default_factory=dict)  # axis -> tolerance, mm (deg)
    text: str = ""                             # what produced it, for messages
    feed_mm_min: float | None = None           # feeds and arcs; G95 as mm/rev x rpm
    feed_tol: float = 0.0                      # mm/min


# ----------------------------------------------------------------------------------------------
# rs274

def annotate(source: str) -> str:
    """The program with a `(nckit-line N)` comment at the end of each line: rs274 keeps the last
    parenthesised comment of a block and prints it before the block's motions. It goes before a
    `;` comment, which runs to the end of the line."""
    out = []
    for number, line in enumerate(source.splitlines(), start=1):
        body = line.rstrip("\r\n")
        stripped = body.strip()
        if not stripped or stripped.startswith("%"):
            out.append(body)
            continue
        depth, cut = 0, len(body)
        for i, ch in enumerate(body):
            if ch == "(":
                depth += 1
            elif ch == ")":
                depth = max(0, depth - 1)
            elif ch == ";" and depth == 0:
                cut = i
                break
        out.append(f"{body[:cut]}({LINE_TAG} {number}){body[cut:]}")
    return "\n".join(out) + "\n"


TOOL_RE = re.compile(r"^\s*T\s*(\d+)", re.IGNORECASE)


def tool_table_for(program: Path, workdir: Path) -> Path:
    """A LinuxCNC tool table with every tool a program selects (blocks that start with T, as
    `nckit expand` writes them), all offsets zero: standalone rs274 knows only a few low tool
    numbers and rejects a lathe's T101 (Fanuc T0101: tool 1, offset 1) as "not found"."""
    tools = set()
    for text in program.read_text(encoding="utf-8", errors="replace").splitlines():
        m = TOOL_RE.match(text)
        if m and int(m.group(1)) > 0:
            tools.add(int(m.group(1)))
    path = workdir / "tools.tbl"
    path.write_text("".join(f"T{t} P{i} Z0 D0 ;\n" for i, t in enumerate(sorted(tools), start=1)))
    return path


def inch_tool_table(path: Path, workdir: Path) -> Path:
    """A copy of a mm tool.tbl with every length (X Y Z ... D) divided by 25.4, for rs274."""
    rows = []
    for text in path.read_text().splitlines():
        body, _, comment = text.partition(";")
        words = []
        for word in body.split():
            letter, value = word[0].upper(), word[1:]
            if letter in "XYZABCUVWD":
                value = repr(float(value) / 25.4)
            words.append(letter + value)
        rows.append(" ".join(words) + (" ;" + comment if comment else ""))
    out = workdir / "tools_inch.tbl"
    out.write_text("\n".join(rows) + "\n")
    return out


def run_rs274(rs274: str, program: Path, block_delete: bool, workdir: Path,
              timeout: float, tool_table: Path | None = None) -> str:
    """rs274's canonical calls for a program. It runs in a scratch folder because it rewrites its
    parameter file at exit; `-b` turns block delete on, `-t` names a tool table."""
    cmd = [rs274, *(["-b"] if block_delete else []),
           *(["-t", str(tool_table)] if tool_table is not None else []), "-g", str(program)]
    proc = subprocess.run(cmd, cwd=workdir, stdin=subprocess.DEVNULL, capture_output=True,
                          text=True, timeout=timeout)
    if proc.returncode != 0:
        msg = [l for l in proc.stderr.splitlines() if l.strip() and l.strip() != "executing"]
        raise ProgramError(f"rs274 exit status {proc.returncode}: "
                           f"{' | '.join(msg) or '(no message)'}")
    return proc.stdout


def _numbers(args: str, call: str, count: int) -> list[float]:
    try:
        values = [float(a) for a in args.split(",")]
    except ValueError:
        raise ProgramError(f"cannot read rs274 call {call}({args})") from None
    if len(values) < count:
        raise ProgramError(f"rs274 call {call}({args}) has fewer than {count} arguments")
    return values


def parse_rs274(output: str, diameter_machine: bool, radius_program: bool = False) -> list[Motion]:
    """rs274 canonical calls -> motions in absolute machine mm (deg). On a diameter-mode machine
    a program normally runs in rs274's diameter mode (G7); `radius_program` says it is one that
    writes radii (G8) instead, as `nckit expand` does. rs274 prints radii either way."""
    scale = 1.0                                   # mm per program unit
    g5x = {a: 0.0 for a in ALL_AXES}              # mm (deg)
    g92 = {a: 0.0 for a in ALL_AXES}
    g5x_q = {a: 0.0 for a in ALL_AXES}            # printing resolution of the offset, mm
    g92_q = {a: 0.0 for a in ALL_AXES}
    tlo = {a: 0.0 for a in ALL_AXES}              # tool length offset, mm
    plane = PLANES["CANON_PLANE_XY"]
    line: int | None = None
    diameter = False
    synched = False
    feed, per_rev, rpm = 0.0, False, 0.0          # F as printed, G95, commanded rpm
    css = False                                   # G96: S is a surface speed, rpm follows X
    motions: list[Motion] = []

    def to_mm(axis: str, v: float) -> float:
        return v if axis in ROTARY else v * scale

    def machine(axis: str, v: float) -> float:
        return to_mm(axis, v) + g5x[axis] + g92[axis] + tlo[axis]

    def tolerance(axis: str) -> float:
        q = PRINT_HALF_ULP * (1.0 if axis in ROTARY else scale) + g5x_q[axis] + g92_q[axis]
        return max(TOL_MM, q) + 1e-9

    def set_offsets(target, quant, values):
        for axis, v in zip(ALL_AXES, values):
            target[axis] = to_mm(axis, v)
            quant[axis] = 0.0 if v == 0 else PRINT_HALF_ULP * (1.0 if axis in ROTARY else scale)

    for text in output.splitlines():
        m = CALL_RE.match(text)
        if not m:
            continue
        _, call, args = m.groups()
        where = text.strip()
        if call == "COMMENT":
            body = args.strip().strip('"')
            if body.startswith(LINE_TAG):
                line = int(body[len(LINE_TAG):])
            elif "diameter mode changed to diameter" in body:
                diameter = True
            elif "diameter mode changed to radius" in body:
                diameter = False
        elif call == "USE_LENGTH_UNITS":
            if args.strip() not in UNITS_MM:
                raise ProgramError(f"unknown units {where}")
            scale = UNITS_MM[args.strip()]
        elif call == "SET_G5X_OFFSET":
            set_offsets(g5x, g5x_q, _numbers(args, call, 7)[1:])
        elif call == "SET_G92_OFFSET":
            set_offsets(g92, g92_q, _numbers(args, call, 6))
        elif call == "SELECT_PLANE":
            if args.strip() not in PLANES:
                raise ProgramError(f"plane not compared: {where}")
            plane = PLANES[args.strip()]
        elif call == "SET_FEED_RATE":
            feed = _numbers(args, call, 1)[0]
        elif call == "SET_FEED_MODE":
            per_rev = _numbers(args, call, 2)[1] == 1
        elif call == "SET_SPINDLE_SPEED":
            rpm = _numbers(args, call, 2)[1]
        elif call == "SET_SPINDLE_MODE":
            # "(spindle css_max_rpm)": a maximum above 0 means constant surface speed (G96).
            css = _numbers(",".join(args.replace(",", " ").split()), call, 2)[1] > 0
        elif call in ("START_SPEED_FEED_SYNCH", "START_SPEED_FEED_SYNC"):  # 2.9 prints ..._SYNC
            synched = True
        elif call == "STOP_SPEED_FEED_SYNCH":
            synched = False
        elif call == "SET_XY_ROTATION":
            if _numbers(args, call, 1)[0] != 0:
                raise ProgramError(f"coordinate system rotation is not compared: {where}")
        elif call == "USE_TOOL_LENGTH_OFFSET":
            # LinuxCNC 2.9 prints it as three space-separated triples: "x y z, a b c, u v w".
            values = _numbers(",".join(args.replace(",", " ").split()), call, 9)
            for axis, v in zip("XYZABCUVW", values):
                tlo[axis] = to_mm(axis, v)
        elif call in UNSUPPORTED_CALLS:
            raise ProgramError(f"motion not compared: {where}")
        elif call in ("STRAIGHT_TRAVERSE", "STRAIGHT_FEED", "STRAIGHT_PROBE", "ARC_FEED"):
            if diameter_machine and radius_program and diameter:
                raise ProgramError(f"the program should write X as a radius but rs274 is in "
                                   f"diameter mode (G7) at line {line}")
            if diameter_machine and not radius_program and not diameter:
                raise ProgramError(f"the nckit machine reads X as a diameter but rs274 is in "
                                   f"radius mode at line {line}: put G7 before the first motion")
            if call == "ARC_FEED":
                v = _numbers(args, call, 9)
                first, second, normal = plane
                pos = {first: v[0], second: v[1], normal: v[5], "A": v[6], "B": v[7], "C": v[8]}
                center = {first: machine(first, v[2]), second: machine(second, v[3])}
                kind, direction = "arc", ("cw" if v[4] < 0 else "ccw")
                if v[4] == 0:
                    raise ProgramError(f"arc with zero rotation: {where}")
            else:
                v = _numbers(args, call, 6)
                pos = dict(zip("XYZABC", v[:6]))
                center, direction = None, None
                kind = "rapid" if call == "STRAIGHT_TRAVERSE" else ("sync" if synched else "linear")
            end = {a: machine(a, pos[a]) for a in COMPARED_AXES}
            mo = Motion(kind, end, line, center, direction, plane[:2] if kind == "arc" else None,
                        {a: tolerance(a) for a in COMPARED_AXES}, where)
            if kind in ("linear", "arc"):
                factor = scale * (rpm if per_rev else 1.0)
                if not (per_rev and css):  # G95 under G96: the feed follows X, not compared
                    mo.feed_mm_min = feed * factor
                    mo.feed_tol = PRINT_HALF_ULP * factor + 1e-6 * mo.feed_mm_min + 1e-9
            motions.append(mo)
    return motions


# ----------------------------------------------------------------------------------------------
# Checks on the reference itself

def arc_extent(start: dict, mo: Motion, a1: str, a2: str):
    """Bounding box of an arc on its plane (a1, a2 in the canonical first/second order)."""
    c1, c2 = mo.center[a1], mo.center[a2]
    s = math.atan2(start[a2] - c2, start[a1] - c1)
    e = math.atan2(mo.end[a2] - c2, mo.end[a1] - c1)
    r = math.hypot(start[a1] - c1, start[a2] - c2)
    ccw = mo.direction == "ccw"
    sweep = (e - s) % (2 * math.pi) if ccw else (s - e) % (2 * math.pi)
    if sweep < 1e-12:
        sweep = 2 * math.pi  # a full circle
    pts = [(start[a1], start[a2]), (mo.end[a1], mo.end[a2])]
    for k in range(4):
        ang = k * math.pi / 2
        d = (ang - s) % (2 * math.pi) if ccw else (s - ang) % (2 * math.pi)
        if d <= sweep:
            pts.append((c1 + r * math.cos(ang), c2 + r * math.sin(ang)))
    return ((min(p[0] for p in pts), max(p[0] for p in pts)),
            (min(p[1] for p in pts), max(p[1] for p in pts)))


def check_reference(motions: list[Motion], machine: dict) -> None:
    """The rs274 side must be self-consistent (arc radii) and stay inside the machine's travel."""
    travel = {a: t for a, t in machine["axes"].items() if t is not None}
    pos = {a: 0.0 for a in COMPARED_AXES}  # rs274 starts at the origin of G54 = machine 0 here

    def inside(axis, lo, hi, mo):
        if axis in travel:
            tmin, tmax = travel[axis]
            if lo < tmin - 1e-6 or hi > tmax + 1e-6:
                raise ProgramError(f"line {mo.line}: {axis} reaches {lo:.4f}..{hi:.4f}, outside "
                                   f"the travel {tmin:g}..{tmax:g} ({mo.text})")

    for mo in motions:
        for a in COMPARED_AXES:
            inside(a, mo.end[a], mo.end[a], mo)
        if mo.kind == "arc":
            a1, a2 = mo.plane
            r_start = math.hypot(pos[a1] - mo.center[a1], pos[a2] - mo.center[a2])
            r_end = math.hypot(mo.end[a1] - mo.center[a1], mo.end[a2] - mo.center[a2])
            if abs(r_start - r_end) > 0.01:
                raise ProgramError(f"line {mo.line}: rs274 arc radius {r_start:.4f} at the start, "
                                   f"{r_end:.4f} at the end ({mo.text}): harness or program bug")
            (lo1, hi1), (lo2, hi2) = arc_extent(pos, mo, a1, a2)
            inside(a1, lo1, hi1, mo)
            inside(a2, lo2, hi2, mo)
        pos = dict(mo.end)
