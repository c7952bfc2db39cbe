"""The cutter sizes a program's own text states, for the tool table it runs with.

A shop sets the control's offsets from the program's tool list before it runs a program; the
corpus does the same, by one rule for every program (tests/real_mill/README.md, "Tool data"):

- Each D offset the program uses under G41/G42 takes the diameter of the tool in the spindle at
  that block (the tool of the last M6: `T3 M6`, `M06 T3`, or a `T3` before a lone `M6`), as the
  program's text states that tool's size:
  1. Fusion 360's tool list, `(T8 D=16. CR=0. ...)`: D is the diameter in program units;
  2. otherwise the first comment that names the tool (`T01`, `TOOL 4`, or a comment on the line
     of the T word) and a cutter (`MILL`, `DRILL`, `REAM`, `TAP`) with a size: `1/2"`, `.5`,
     `3/8IN`, `5mm`, `3.`; a size with `"`/`IN`/`INCH` is inches, with `MM` millimetres, a bare
     number is in the program's units (its first G20/G21). A number with neither a fraction, a
     decimal point nor a unit (`3 FLUTES`, `03-0086`) is not a size.
- Fusion 360's Wear compensation: Autodesk's documentation says Wear (and Inverse wear) writes
  G41/G42 on the tool-centre path, so the control's D holds only the wear, while In control
  writes the part contour for the control to offset by the tool radius, and Fusion makes sure
  the control can cut it with the selected tool. A Fusion lead-in arc (the arc right after the
  G41/G42 block) that turns toward the tool (G41 with G3, G42 with G2) with a radius no larger
  than the tool's cannot be cut by offsetting it by that tool: such a block was posted with
  Wear, and its D offset gets diameter 0.
- A D offset whose tool has no stated size keeps the test table's 6.35 mm; a D offset two tools
  of different sizes use keeps the first.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from pathlib import Path

MM_PER_INCH = 25.4

COMMENT_RE = re.compile(r"\(([^()]*)\)")
FUSION_TOOL_RE = re.compile(r"^\s*\(T(\d+)\s+D=([0-9]*\.?[0-9]+)", re.IGNORECASE)
TOOL_IN_COMMENT_RE = re.compile(r"(?<![A-Z0-9])(?:T|TOOL\s*)0*(\d+)(?![0-9])", re.IGNORECASE)
CUTTER_RE = re.compile(r"MILL|DRILL|REAM|TAP", re.IGNORECASE)
# A size: a fraction, a number with a decimal point, or a number with a unit; never part of a
# word (D05., #10) or a part number.
SIZE_RE = re.compile(
    r"(?<![A-Z0-9#.\-])(\d+/\d+|\d*\.\d+|\d+\.(?!\d)|\d+(?=\s*(?:\"|IN\b|INCH|MM)))"
    r"\s*(\"|INCH|IN(?![A-Z])|MM)?", re.IGNORECASE)
WORD_RE = re.compile(r"([A-Z])\s*([-+]?\d*\.?\d+)", re.IGNORECASE)


def words(code: str) -> list[tuple[str, float]]:
    return [(m.group(1).upper(), float(m.group(2))) for m in WORD_RE.finditer(code)]


def has_code(ws: list[tuple[str, float]], letter: str, value: float) -> bool:
    return any(w == letter and abs(v - value) < 1e-9 for w, v in ws)


def size_mm(text: str, inch_program: bool) -> float | None:
    """The first size in a comment, in mm (None: no size)."""
    m = SIZE_RE.search(text)
    if not m:
        return None
    number, unit = m.group(1), (m.group(2) or "").upper()
    value = (float(number.split("/")[0]) / float(number.split("/")[1])) if "/" in number else float(number)
    inches = unit in ('"', "IN", "INCH") or (unit == "" and inch_program)
    return value * MM_PER_INCH if inches else value


@dataclass
class ToolData:
    """What the runner derived for one program."""
    diameters_mm: dict[int, float] = field(default_factory=dict)  # D offset -> diameter
    reasons: dict[int, str] = field(default_factory=dict)         # D offset -> why


def inch_units(lines: list[str]) -> bool:
    for text in lines:
        code = COMMENT_RE.sub(" ", text).upper()
        if re.search(r"G0*20(?![0-9.])", code):
            return True
        if re.search(r"G0*21(?![0-9.])", code):
            return False
    return False


def stated_sizes(lines: list[str], inch_program: bool) -> dict[int, tuple[float, str]]:
    """Tool number -> (diameter mm, the text stating it)."""
    sizes: dict[int, tuple[float, str]] = {}
    for text in lines:
        m = FUSION_TOOL_RE.match(text)
        if m:
            value = float(m.group(2)) * (MM_PER_INCH if inch_program else 1.0)
            sizes.setdefault(int(m.group(1)), (value, text.strip()))
    for text in lines:
        code_tools = [int(v) for w, v in words(COMMENT_RE.sub(" ", text)) if w == "T"]
        for comment in COMMENT_RE.findall(text):
            if not CUTTER_RE.search(comment):
                continue
            named = [int(n) for n in TOOL_IN_COMMENT_RE.findall(comment)] or code_tools
            size = size_mm(TOOL_IN_COMMENT_RE.sub(" ", comment), inch_program)
            if size is None or size <= 0:
                continue
            for tool in named:
                sizes.setdefault(tool, (size, text.strip()))
    return sizes


def lead_in_turns_toward_tool(lines: list[str], index: int, side: int) -> float | None:
    """The radius (program units) of the lead-in arc right after the G41/G42 block at `index`
    when it turns toward the tool; None otherwise."""
    for text in lines[index + 1:index + 4]:
        ws = words(COMMENT_RE.sub(" ", text))
        if not any(w in "XYIJ" for w, _ in ws):
            continue
        turn = 1 if has_code(ws, "G", 3) else -1 if has_code(ws, "G", 2) else 0
        if turn == 0 or turn != side:
            return None
        i = next((v for w, v in ws if w == "I"), 0.0)
        j = next((v for w, v in ws if w == "J"), 0.0)
        return math.hypot(i, j) if (i or j) else None
    return None


def derive(program: Path, fusion: bool) -> ToolData:
    lines = program.read_text(encoding="utf-8", errors="replace").splitlines()
    inch_program = inch_units(lines)
    sizes = stated_sizes(lines, inch_program)
    data = ToolData()
    pending_tool = spindle_tool = None
    d_modal = None
    for index, text in enumerate(lines):
        ws = words(COMMENT_RE.sub(" ", text))
        block_tool = next((int(v) for w, v in ws if w == "T"), None)
        if block_tool is not None:
            pending_tool = block_tool
        if has_code(ws, "M", 6):
            spindle_tool = block_tool if block_tool is not None else pending_tool
        d_word = next((int(v) for w, v in ws if w == "D"), None)
        if d_word is not None:
            d_modal = d_word
        side = 1 if has_code(ws, "G", 41) else -1 if has_code(ws, "G", 42) else 0
        if side == 0 or d_modal is None or d_modal == 0 or d_modal in data.diameters_mm:
            continue
        stated = sizes.get(spindle_tool) if spindle_tool is not None else None
        if stated is None:
            continue
        diameter_mm, source = stated
        if fusion:
            arc = lead_in_turns_toward_tool(lines, index, side)
            radius_program_units = diameter_mm / 2 / (MM_PER_INCH if inch_program else 1.0)
            if arc is not None and arc <= radius_program_units + 1e-9:
                data.diameters_mm[d_modal] = 0.0
                data.reasons[d_modal] = (f"line {index + 2}: lead-in arc radius {arc:g} not larger than the "
                                         f"radius of T{spindle_tool} ({source}): Wear compensation")
                continue
        data.diameters_mm[d_modal] = diameter_mm
        data.reasons[d_modal] = f"T{spindle_tool} at line {index + 1}: {source}"
    return data


def write_table(base: Path, data: ToolData, out: Path) -> Path:
    """A copy of the tool.tbl `base` (mm) with the derived diameters."""
    rows, seen = [], set()
    for text in base.read_text().splitlines():
        m = re.match(r"T(\d+)\s", text)
        if m and int(m.group(1)) in data.diameters_mm:
            number = int(m.group(1))
            seen.add(number)
            text = re.sub(r"D[+-]?[0-9.]+", f"D+{data.diameters_mm[number]:.4f}", text)
        rows.append(text)
    for number in sorted(set(data.diameters_mm) - seen):
        rows.append(f"T{number} P{number} Z+{40 + number:.3f} D+{data.diameters_mm[number]:.4f} ;offset {number}")
    out.write_text("\n".join(rows) + "\n")
    return out
