#!/usr/bin/env python3
"""Every diagnostic code the sources raise is listed in docs/diagnostics.md, and every code the
page lists is still raised somewhere, so the page cannot drift from the code.

A code is the string literal right after the location in a call that makes a diagnostic
(`error_at(where, "travel-limit", ...)`, `sink.error(where, "config-value", ...)`,
`error(column, "bad-arc", ...)`, `warn(column, "dwell-decimal", ...)`), or one assigned to `.code`. The page lists a code in
backquotes in the first column of a table row. Usage: diagnostic_codes_test.py [SOURCE_DIR]"""
import re
import sys
from pathlib import Path

RAISED = re.compile(r'\b(?:error_at|error|fail|warn)\s*\(\s*(?:[^;"]|"[^"\n]*")*?,\s*"([a-z][a-z0-9-]*)"\s*,',
                    re.S)
ASSIGNED = re.compile(r'\.code\s*=\s*"([a-z][a-z0-9-]*)"')
LISTED = re.compile(r"^\|\s*([^|]*)\|", re.M)


def raised_codes(source: Path):
    codes = {}
    for path in sorted(list((source / "src").rglob("*.[ch]pp")) +
                       list((source / "include").rglob("*.hpp"))):
        text = path.read_text(encoding="utf-8", errors="replace")
        for match in list(RAISED.finditer(text)) + list(ASSIGNED.finditer(text)):
            codes.setdefault(match.group(1), path.relative_to(source))
    return codes


def listed_codes(page: Path):
    codes = set()
    for cell in LISTED.findall(page.read_text(encoding="utf-8")):
        codes.update(re.findall(r"`([a-z][a-z0-9]*(?:-[a-z0-9]+)*)`", cell))
    return codes


def main() -> int:
    source = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).resolve().parents[2]
    raised = raised_codes(source)
    listed = listed_codes(source / "docs" / "diagnostics.md")
    if len(raised) < 20:
        print(f"only {len(raised)} codes found in the sources: the pattern no longer matches")
        return 1
    missing = sorted(set(raised) - listed)
    stale = sorted(listed - set(raised))
    for code in missing:
        print(f"docs/diagnostics.md: code '{code}' (raised in {raised[code]}) is not listed")
    for code in stale:
        print(f"docs/diagnostics.md: code '{code}' is listed but raised nowhere")
    print(f"{len(raised)} codes raised, {len(listed)} listed, {len(missing)} missing, "
          f"{len(stale)} stale")
    return 1 if missing or stale else 0


if __name__ == "__main__":
    sys.exit(main())
