"""`nckit moves --json`: running it on a program and reading its records as motions, for tests
that compare nckit with LinuxCNC's rs274 (rs274_output.py reads the other side)."""

from __future__ import annotations

import json
import subprocess
from pathlib import Path

from program_setup import Setup
from rs274_output import KNOWN_KINDS, Motion


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
