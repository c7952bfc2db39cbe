"""How a test program asks to be run, and what the machine file it names allows: the
`nckit-...:` comments of its first lines and the travel of the machine's axes.

Comments in a program's first 5 lines can set up the run:
- `( nckit-machine: lathe.toml )`: the nckit machine file, resolved against examples/machines/;
- `( nckit-block-delete: on )`: skip `/` blocks (rs274 -b, nckit --block-delete); both skip
  nothing by default;
- `( nckit-tools: tool.tbl )`: a LinuxCNC tool table in mm beside the program: nckit gets
  `--tools` with it, rs274 `-t` with a copy scaled by 1/25.4 (standalone rs274 reads its tool
  table as inches whatever the program's units). USE_TOOL_LENGTH_OFFSET then adds to Z.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from pathlib import Path

from rs274_output import ALL_AXES, ProgramError

try:
    import tomllib
except ModuleNotFoundError:  # Python < 3.11: machine files are then read from nckit's output only
    tomllib = None

DEFAULT_MILL = {"axes": {"X": (-500.0, 500.0), "Y": (-500.0, 500.0), "Z": (-500.0, 500.0)},
                "diameter_mode": False}
DIRECTIVE_RE = re.compile(r"nckit-(machine|block-delete|tools)\s*:\s*([^\s)]+)", re.IGNORECASE)

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
