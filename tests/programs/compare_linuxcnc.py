#!/usr/bin/env python3
"""Side-by-side test of `nckit moves --json` against LinuxCNC's standalone interpreter `rs274`.

For every program (`NN_name.ngc`) it runs `rs274 -g` and `nckit moves --json`, turns rs274's
canonical calls into absolute machine positions in mm, and compares the motions in order: kind,
end point on every axis both sides have (X Y Z, and A B C on machines that have them), each arc's
centre on the two plane axes and its direction, the feed rate of feeds and arcs (mm/min; under
G95 mm/rev x the commanded rpm; not under G96, where it follows X), and the source line of each
motion. Dwells, I/O events and the feed of rapids are not compared.

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

Comments in a program's first 5 lines can set up the run:
- `( nckit-machine: lathe.toml )`: the nckit machine file, resolved against examples/machines/;
- `( nckit-block-delete: on )`: skip `/` blocks (rs274 -b, nckit --block-delete); both skip
  nothing by default;
- `( nckit-tools: tool.tbl )`: a LinuxCNC tool table in mm beside the program: nckit gets
  `--tools` with it, rs274 `-t` with a copy scaled by 1/25.4 (standalone rs274 reads its tool
  table as inches whatever the program's units). USE_TOOL_LENGTH_OFFSET then adds to Z.

Expand mode (`--expand`), for programs rs274 cannot read (Fanuc Custom Macro B: `NN_name.nc` as
well as `NN_name.ngc`): `nckit expand PROGRAM -o expanded.ngc` writes the program out as plain
G-code (one move per block, absolute machine coordinates in mm, radius mode G8 on a diameter-mode
lathe); rs274 runs that as the reference, and `nckit moves --json` runs the ORIGINAL program.
Kinds, end points, arc centres and directions, and feeds are compared as above; source lines are
not (the expanded program's lines are not the original's: each of its blocks names the source
line in a comment, which the messages show). Called programs are looked up in `--library DIR`
(default: the programs folder's `library/` when there is one); retained variables #500-#999 are
kept in a scratch file, never beside the machine file. rs274 gets a tool table of the tools the
expanded program selects, all offsets zero (alone it knows only low tool numbers: a lathe's T0101
comes out as T101).

Exit status: 0 when every program matches, 1 otherwise (and when rs274 or nckit is missing).
"""

from __future__ import annotations

import argparse
import json
import math
import os
import re
import shutil
import subprocess
import sys
import tempfile
from dataclasses import dataclass, field
from pathlib import Path

try:
    import tomllib
except ModuleNotFoundError:  # Python < 3.11: machine files are then read from nckit's output only
    tomllib = None

REPO = Path(__file__).resolve().parents[2]
DEFAULT_NCKIT = REPO / "build" / "release" / "src" / "nckit"
DEFAULT_MACHINES = REPO / "examples" / "machines"

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
DEFAULT_MILL = {"axes": {"X": (-500.0, 500.0), "Y": (-500.0, 500.0), "Z": (-500.0, 500.0)},
                "diameter_mode": False}

CALL_RE = re.compile(r"^\s*\d+\s+N(\S*)\s+([A-Z_][A-Z0-9_]*)\((.*)\)\s*$")
DIRECTIVE_RE = re.compile(r"nckit-(machine|block-delete|tools)\s*:\s*([^\s)]+)", re.IGNORECASE)


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
# Machine files

def _axis_travel(table: dict) -> tuple[float, float] | None:
    """Travel limits from an axis table, whatever the key spelling."""
    for lo, hi in (("min", "max"), ("travel_min", "travel_max"), ("min_mm", "max_mm"),
                   ("min_deg", "max_deg"), ("travel_min_mm", "travel_max_mm")):
        if isinstance(table.get(lo), (int, float)) and isinstance(table.get(hi), (int, float)):
            return float(table[lo]), float(table[hi])
    for key in ("travel", "travel_mm", "limits", "range"):
        v = table.get(key)
        if isinstance(v, list) and len(v) == 2 and all(isinstance(x, (int, float)) for x in v):
            return float(v[0]), float(v[1])
        if isinstance(v, dict):
            t = _axis_travel(v)
            if t:
                return t
    return None


def _find_key(doc, key):
    if isinstance(doc, dict):
        if key in doc:
            return doc[key]
        for v in doc.values():
            found = _find_key(v, key)
            if found is not None:
                return found
    return None


def load_machine(path: Path) -> dict:
    """{'axes': {letter: (min, max) or None}, 'diameter_mode': bool}, best effort; axes may be
    empty when the schema is not understood (nckit's own output then says which axes exist)."""
    info = {"axes": {}, "diameter_mode": False}
    if tomllib is None:
        return info
    with open(path, "rb") as f:
        doc = tomllib.load(f)
    info["diameter_mode"] = bool(_find_key(doc, "diameter_mode") or False)
    axes = doc.get("axes", doc.get("axis"))
    if isinstance(axes, list):
        for t in axes:
            if not isinstance(t, dict):
                continue
            name = next((t[k] for k in ("name", "axis", "letter", "id")
                         if isinstance(t.get(k), str)), None)
            if name and name.upper() in ALL_AXES and len(name) == 1:
                info["axes"][name.upper()] = _axis_travel(t)
    elif isinstance(axes, dict):
        for name, t in axes.items():
            if name.upper() in ALL_AXES and len(name) == 1 and isinstance(t, dict):
                info["axes"][name.upper()] = _axis_travel(t)
    else:
        for name, t in doc.items():
            if len(name) == 1 and name.upper() in ALL_AXES and isinstance(t, dict):
                info["axes"][name.upper()] = _axis_travel(t)
    return info


@dataclass
class Setup:
    machine_file: Path | None = None   # None: nckit's built-in mill
    block_delete: bool = False
    tools_file: Path | None = None     # a tool.tbl in mm beside the program


def setup_of(program: Path, machines_dir: Path) -> Setup:
    """What the `nckit-...:` comments in a program's first lines ask for."""
    setup = Setup()
    with open(program, encoding="utf-8", errors="replace") as f:
        for _, text in zip(range(5), f):
            for key, value in DIRECTIVE_RE.findall(text):
                if key.lower() == "machine":
                    setup.machine_file = machines_dir / value
                elif key.lower() == "tools":
                    setup.tools_file = program.parent / value
                elif value.lower() in ("on", "off"):
                    setup.block_delete = value.lower() == "on"
                else:
                    raise ProgramError(f"nckit-block-delete: {value!r} is neither on nor off")
    return setup


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


# ----------------------------------------------------------------------------------------------
# nckit

def run_nckit(nckit: str, program: Path, setup: Setup, workdir: Path,
              timeout: float, extra: list[str] | None = None) -> list[dict]:
    cmd = [nckit, "moves", str(program), "--json"]
    if setup.machine_file is not None:
        cmd += ["--machine", str(setup.machine_file)]
    if setup.block_delete:
        cmd.append("--block-delete")
    if setup.tools_file is not None:
        cmd += ["--tools", str(setup.tools_file)]
    cmd += extra or []
    proc = subprocess.run(cmd, cwd=workdir, stdin=subprocess.DEVNULL, capture_output=True,
                          text=True, timeout=timeout)
    if proc.returncode != 0:
        err = " | ".join(proc.stderr.strip().splitlines()[:3]) or "(no message)"
        raise AssertionError(f"nckit exit status {proc.returncode}: {err}")
    records = []
    for n, text in enumerate(proc.stdout.splitlines(), start=1):
        if not text.strip():
            continue
        try:
            rec = json.loads(text)
        except json.JSONDecodeError as e:
            raise AssertionError(f"nckit output line {n} is not JSON ({e}): {text[:120]}") from None
        if not isinstance(rec, dict) or rec.get("kind") not in KNOWN_KINDS:
            raise AssertionError(f"nckit output line {n}: unknown record {text[:120]}")
        records.append(rec)
    return records


def nckit_motion(rec: dict, index: int) -> Motion:
    def axes_of(key):
        obj = rec.get(key)
        if not isinstance(obj, dict) or not all(isinstance(v, (int, float)) for v in obj.values()):
            raise AssertionError(f"nckit motion {index}: `{key}` is not an object of numbers: "
                                 f"{json.dumps(rec)[:160]}")
        return {k.upper(): float(v) for k, v in obj.items()}

    kind = rec["kind"]
    mo = Motion(kind, axes_of("end"), rec.get("line"), text=json.dumps(rec))
    if isinstance(rec.get("feed_mm_min"), (int, float)):
        mo.feed_mm_min = float(rec["feed_mm_min"])
    if kind == "arc":
        mo.center = axes_of("center")
        mo.direction = rec.get("dir")
        if mo.direction not in ("cw", "ccw"):
            raise AssertionError(f"nckit motion {index}: arc `dir` is {mo.direction!r}")
    return mo


# ----------------------------------------------------------------------------------------------
# Comparison

def source_line(lines: list[str], number) -> str:
    if isinstance(number, int) and 1 <= number <= len(lines):
        return f"line {number} `{lines[number - 1].strip()}`"
    return f"line {number}"


def compare(ref: list[Motion], got: list[Motion], machine_axes: set[str],
            src: list[str], check_lines: bool, check_feed: bool,
            got_src: list[str] | None = None) -> str | None:
    """The first difference, or None. `src` holds the lines of the program rs274 ran, `got_src`
    those of the one nckit ran when it is another (expand mode)."""
    if got_src is None:
        got_src = src
    compared = [a for a in COMPARED_AXES if a in machine_axes]
    for i, (r, g) in enumerate(zip(ref, got), start=1):
        where = f"motion {i} of {len(ref)}, " + (source_line(src, r.line) if r.line
                                                 else source_line(got_src, g.line))
        both = f"\n    nckit:  {g.text}\n    rs274:  {r.text}"
        if set(g.end) != machine_axes:
            return (f"{where}: nckit `end` has axes {sorted(g.end)}, "
                    f"machine has {sorted(machine_axes)}")
        if r.kind != g.kind:
            return f"{where}: kind nckit {g.kind} vs rs274 {r.kind}{both}"
        for a in compared:
            if abs(g.end[a] - r.end[a]) > r.tol[a]:
                return (f"{where}: end {a} nckit {g.end[a]:.6f} vs rs274 {r.end[a]:.6f} "
                        f"(diff {g.end[a] - r.end[a]:+.6f}, tol {r.tol[a]:.6f}){both}")
        for a in COMPARED_AXES:
            if a not in machine_axes and abs(r.end[a]) > r.tol[a]:
                return (f"{where}: rs274 moves {a} to {r.end[a]:.4f} but the nckit machine has no "
                        f"{a} axis (program bug){both}")
        if r.kind == "arc":
            for a in r.plane:
                if a not in g.center:
                    return f"{where}: nckit arc centre lacks {a}{both}"
                if abs(g.center[a] - r.center[a]) > r.tol[a]:
                    return (f"{where}: arc centre {a} nckit {g.center[a]:.6f} vs rs274 "
                            f"{r.center[a]:.6f} (diff {g.center[a] - r.center[a]:+.6f}){both}")
            if g.direction != r.direction:
                return f"{where}: arc dir nckit {g.direction} vs rs274 {r.direction}{both}"
        if check_feed and r.feed_mm_min is not None and (
                g.feed_mm_min is None or abs(g.feed_mm_min - r.feed_mm_min) > r.feed_tol):
            return (f"{where}: feed_mm_min nckit {g.feed_mm_min} vs rs274 "
                    f"{r.feed_mm_min:.4f}{both}")
        if check_lines and r.line is not None and g.line != r.line:
            return f"{where}: source line nckit {g.line} vs rs274 {r.line}{both}"
    if len(ref) != len(got):
        more, name = (ref, "rs274") if len(ref) > len(got) else (got, "nckit")
        extra = more[min(len(ref), len(got))]
        return (f"motion count nckit {len(got)} vs rs274 {len(ref)}; first extra {name} motion "
                f"({source_line(src if more is ref else got_src, extra.line)}): {extra.text}")
    return None


def drop_zero_length(motions: list[Motion], tol: float = 1e-6) -> list[Motion]:
    """Straight moves that go nowhere (e.g. G91 G28 Z0's intermediate point); arcs stay (full
    circles end where they start)."""
    out, prev = [], None
    for mo in motions:
        if (mo.kind != "arc" and prev is not None
                and all(abs(mo.end[a] - prev[a]) <= tol for a in mo.end if a in prev)):
            continue
        out.append(mo)
        prev = mo.end
    return out


@dataclass
class Reference:
    motions: list[Motion]
    machine: dict
    setup: Setup


def reference(program: Path, rs274: str, machines_dir: Path, workdir: Path,
              timeout: float, setup: Setup | None = None, radius_program: bool = False,
              block_delete: bool | None = None, tools: bool = False) -> Reference:
    """rs274's motions for a program. `setup` defaults to the program's own `nckit-...:`
    comments; `block_delete` (default: the setup's) is what rs274 gets; `radius_program`: see
    parse_rs274; `tools`: rs274 gets a tool table of the tools the program selects."""
    if setup is None:
        setup = setup_of(program, machines_dir)
    if block_delete is None:
        block_delete = setup.block_delete
    if setup.machine_file is not None and not setup.machine_file.is_file():
        raise ProgramError(f"machine file {setup.machine_file} does not exist")
    machine = load_machine(setup.machine_file) if setup.machine_file else DEFAULT_MILL
    table = tool_table_for(program, workdir) if tools else None
    if setup.tools_file is not None:
        table = inch_tool_table(setup.tools_file, workdir)
    plain = run_rs274(rs274, program, block_delete, workdir, timeout, table)
    tagged_path = workdir / ("tagged_" + program.name)
    tagged_path.write_text(annotate(program.read_text(encoding="utf-8", errors="replace")))
    if setup.tools_file is not None:
        table = inch_tool_table(setup.tools_file, workdir)  # rs274 rewrites its tool table at exit
    elif table is not None:
        table = tool_table_for(program, workdir)
    tagged = run_rs274(rs274, tagged_path, block_delete, workdir, timeout, table)
    motions = parse_rs274(tagged, machine["diameter_mode"], radius_program)
    untagged = parse_rs274(plain, machine["diameter_mode"], radius_program)
    if [(m.kind, m.end, m.center, m.direction) for m in motions] != \
       [(m.kind, m.end, m.center, m.direction) for m in untagged]:
        raise ProgramError("harness: the line-number comments changed rs274's motions")
    check_reference(motions, machine)
    return Reference(motions, machine, setup)


def expected_json(ref: Reference) -> str:
    """rs274's motions written the way `nckit moves --json` should write them."""
    axes = list(ref.machine["axes"]) or list(COMPARED_AXES)
    rows = []
    for mo in ref.motions:
        rec = {"line": mo.line, "kind": mo.kind,
               "end": {a: round(mo.end[a], 6) for a in axes if a in mo.end}}
        if mo.kind == "arc":
            rec["center"] = {a: round(mo.center[a], 6) for a in mo.plane}
            rec["dir"] = mo.direction
        rows.append(json.dumps(rec))
    return "\n".join(rows)


def run_program(program: Path, args, workdir: Path) -> tuple[bool, str]:
    if args.expand:
        return run_expanded_program(program, args, workdir)
    try:
        ref = reference(program, args.rs274, args.machines, workdir, args.timeout)
    except ProgramError as e:
        return False, f"FAIL {program.stem}: program: {e}"
    except subprocess.TimeoutExpired:
        return False, f"FAIL {program.stem}: rs274 timed out"
    src = program.read_text(encoding="utf-8", errors="replace").splitlines()
    return compare_program(program, ref, program, src, args, workdir, not args.ignore_lines)


def compare_program(program: Path, ref: Reference, reference_program: Path, src: list[str], args,
                    workdir: Path, check_lines: bool,
                    extra: list[str] | None = None) -> tuple[bool, str]:
    """`nckit moves --json` of `program` against the rs274 motions `ref` (of
    `reference_program`, whose lines are `src`); `extra`: more nckit options."""
    try:
        records = run_nckit(args.nckit, program, ref.setup, workdir, args.timeout, extra)
        got = [nckit_motion(r, i) for i, r in enumerate(records, start=1)
               if r["kind"] in COMPARED_KINDS]
    except AssertionError as e:
        return False, f"FAIL {program.stem}: {e}"
    except subprocess.TimeoutExpired:
        return False, f"FAIL {program.stem}: nckit timed out"
    machine_axes = set(ref.machine["axes"]) or (set(got[0].end) if got else {"X", "Y", "Z"})
    motions = ref.motions
    if args.skip_zero_length:
        motions, got = drop_zero_length(motions), drop_zero_length(got)
    got_src = None
    if reference_program != program:
        got_src = program.read_text(encoding="utf-8", errors="replace").splitlines()
    diff = compare(motions, got, machine_axes, src, check_lines, args.feed, got_src)
    if diff:
        if len(motions) != len(got) and not diff.startswith("motion count"):
            diff += f"\n    (motion count nckit {len(got)} vs rs274 {len(motions)})"
        if reference_program != program:
            diff += (f"\n    (rs274 ran {reference_program.name}, the expanded program: its "
                     f"lines end in a comment naming the source line)")
        return False, f"FAIL {program.stem}: {diff}"
    return True, f"ok {program.stem} ({len(motions)} moves)"


# ----------------------------------------------------------------------------------------------
# Expand mode: rs274 runs what `nckit expand` wrote, nckit the original program

def nckit_extra(args, workdir: Path, purpose: str) -> list[str]:
    """Options both `nckit expand` and `nckit moves` get in expand mode: the library folder, and
    a scratch file for retained variables (one per run, so that neither run sees what the other
    left, and nothing is written beside the machine file)."""
    extra = ["--vars", str(workdir / f"{purpose}.vars")]
    if args.library is not None:
        extra += ["--library", str(args.library)]
    if args.max_blocks is not None:
        extra += ["--max-blocks", str(args.max_blocks)]
    return extra


def expand_program(program: Path, setup: Setup, args, workdir: Path) -> Path:
    """`nckit expand` of the program into workdir/expanded.ngc (AssertionError when it fails)."""
    out = workdir / "expanded.ngc"
    cmd = [args.nckit, "expand", str(program)]
    if setup.machine_file is not None:
        cmd += ["--machine", str(setup.machine_file)]
    if setup.block_delete:
        cmd.append("--block-delete")
    cmd += nckit_extra(args, workdir, "expand") + ["-o", str(out)]
    proc = subprocess.run(cmd, cwd=workdir, stdin=subprocess.DEVNULL, capture_output=True,
                          text=True, timeout=args.timeout)
    if proc.returncode != 0:
        err = " | ".join(proc.stderr.strip().splitlines()[:3]) or "(no message)"
        raise AssertionError(f"nckit expand exit status {proc.returncode}: {err}")
    if not out.is_file():
        raise AssertionError(f"nckit expand exited 0 but wrote no {out.name}")
    return out


def expanded_reference(program: Path, args, workdir: Path) -> tuple[Reference, Path]:
    """rs274's motions for the expanded program. ProgramError: the original program's setup is
    wrong; AssertionError: nckit expand failed or rs274 rejects what it wrote."""
    setup = setup_of(program, args.machines)
    if setup.machine_file is not None and not setup.machine_file.is_file():
        raise ProgramError(f"machine file {setup.machine_file} does not exist")
    expanded = expand_program(program, setup, args, workdir)
    try:
        # The expanded program has no deleted blocks left, and writes X as a radius (G8).
        ref = reference(expanded, args.rs274, args.machines, workdir, args.timeout, setup=setup,
                        radius_program=True, block_delete=False, tools=True)
    except ProgramError as e:
        raise AssertionError(f"rs274 on the expanded program: {e}") from None
    return ref, expanded


def run_expanded_program(program: Path, args, workdir: Path) -> tuple[bool, str]:
    try:
        ref, expanded = expanded_reference(program, args, workdir)
    except ProgramError as e:
        return False, f"FAIL {program.stem}: program: {e}"
    except AssertionError as e:
        return False, f"FAIL {program.stem}: {e}"
    except subprocess.TimeoutExpired:
        return False, f"FAIL {program.stem}: nckit expand or rs274 timed out"
    if args.keep_expanded is not None:
        args.keep_expanded.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(expanded, args.keep_expanded / (program.stem + ".ngc"))
    # Source lines are not compared: rs274's are the expanded program's, nckit's the original's.
    src = expanded.read_text(encoding="utf-8", errors="replace").splitlines()
    return compare_program(program, ref, expanded, src, args, workdir, False,
                           nckit_extra(args, workdir, "moves"))


def select_programs(directory: Path, names: list[str], patterns=("*.ngc",)) -> list[Path]:
    programs = sorted({p for pattern in patterns for p in directory.glob(pattern)})
    if not names:
        return programs
    chosen = []
    for name in names:
        hits = [p for p in programs if p.name == name or p.stem == name
                or p.stem.startswith(name + "_")]
        if not hits:
            sys.exit(f"error: no program {name!r} in {directory}")
        chosen += [h for h in hits if h not in chosen]
    return chosen


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("names", nargs="*", help="programs to run (file name, stem or NN prefix)")
    ap.add_argument("--nckit", default=str(DEFAULT_NCKIT), help="nckit binary (%(default)s)")
    ap.add_argument("--rs274", default=None, help="LinuxCNC rs274 binary (default: from PATH)")
    ap.add_argument("--programs", type=Path, default=Path(__file__).resolve().parent,
                    help="folder of NN_name.ngc programs (NN_name.nc too with --expand; "
                         "default: this script's folder)")
    ap.add_argument("--machines", type=Path, default=DEFAULT_MACHINES,
                    help="folder the nckit-machine comments refer to (%(default)s)")
    ap.add_argument("--expected", action="store_true",
                    help="print rs274's motions as nckit-style JSON lines instead of comparing")
    ap.add_argument("--ignore-lines", action="store_true", help="do not compare source lines")
    ap.add_argument("--no-feed", dest="feed", action="store_false",
                    help="do not compare feed_mm_min of feeds and arcs (G95: mm/rev x rpm)")
    ap.add_argument("--skip-zero-length", action="store_true",
                    help="drop straight moves of zero length on both sides before comparing")
    ap.add_argument("--timeout", type=float, default=300.0, help="seconds per run (%(default)s)")
    ap.add_argument("--expand", action="store_true",
                    help="rs274 runs `nckit expand PROGRAM` (macro programs: *.nc and *.ngc), "
                         "nckit the original; source lines are not compared")
    ap.add_argument("--library", type=Path, default=None,
                    help="expand mode: folder of called programs (default: PROGRAMS/library "
                         "when it exists)")
    ap.add_argument("--max-blocks", type=int, default=None,
                    help="expand mode: nckit's --max-blocks (default: nckit's own budget)")
    ap.add_argument("--keep-expanded", type=Path, default=None, metavar="DIR",
                    help="expand mode: keep each expanded program as DIR/STEM.ngc")
    args = ap.parse_args()

    rs274 = args.rs274 or shutil.which("rs274")
    if not rs274 or not os.access(rs274, os.X_OK):
        print(f"error: LinuxCNC's rs274 not found ({args.rs274 or 'not on PATH'}); "
              f"run scripts/deps.sh to install linuxcnc-uspace", file=sys.stderr)
        return 1
    args.rs274 = rs274
    # nckit and rs274 run in scratch folders: every path handed to them must be absolute.
    args.programs, args.machines = args.programs.resolve(), args.machines.resolve()
    if os.sep in args.nckit:
        args.nckit = str(Path(args.nckit).resolve())
    else:
        args.nckit = shutil.which(args.nckit) or args.nckit
    if args.expand:
        if args.library is None and (args.programs / "library").is_dir():
            args.library = args.programs / "library"
        if args.library is not None:
            args.library = args.library.resolve()
            if not args.library.is_dir():
                print(f"error: library folder {args.library} does not exist", file=sys.stderr)
                return 1
        if args.keep_expanded is not None:
            args.keep_expanded = args.keep_expanded.resolve()
    if (args.expand or not args.expected) and not os.access(args.nckit, os.X_OK):
        print(f"error: nckit binary {args.nckit} not found or not executable; build it first "
              f"(make build) or pass --nckit", file=sys.stderr)
        return 1
    patterns = ("*.nc", "*.ngc") if args.expand else ("*.ngc",)
    programs = select_programs(args.programs, args.names, patterns)
    if not programs:
        print(f"error: no {' or '.join(patterns)} programs in {args.programs}", file=sys.stderr)
        return 1

    passed = failed = 0
    with tempfile.TemporaryDirectory(prefix="nckit-linuxcnc-") as tmp:
        for program in programs:
            workdir = Path(tempfile.mkdtemp(dir=tmp))
            if args.expected:
                try:
                    if args.expand:
                        ref, _ = expanded_reference(program, args, workdir)
                    else:
                        ref = reference(program, args.rs274, args.machines, workdir,
                                        args.timeout)
                except ProgramError as e:
                    print(f"FAIL {program.stem}: program: {e}", file=sys.stderr)
                    failed += 1
                    continue
                except AssertionError as e:
                    print(f"FAIL {program.stem}: {e}", file=sys.stderr)
                    failed += 1
                    continue
                print(f"# {program.name}")
                print(expected_json(ref))
                passed += 1
                continue
            ok, message = run_program(program, args, workdir)
            print(message, flush=True)
            passed, failed = passed + ok, failed + (not ok)
    print(f"{passed} passed, {failed} failed", file=sys.stderr if args.expected else sys.stdout)
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
