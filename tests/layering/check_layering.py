#!/usr/bin/env python3
"""Checks every #include of nckit's sources against the dependency table of
docs/architecture.md ("stage ↓ may include →"), so the page and the code cannot drift.

The table is read from the page itself. A file's stage (its row) is the folder it lives in:
src/<stage>/ and include/nckit/<stage>/, src/process/pattern/ and include/nckit/process/pattern/
are the row `process/pattern`, hal/ is the row `hal`. An include's stage (its column) is found the
same way from the file it names: `nckit/<stage>/...` through include/, a quoted relative include
(`"common.hpp"`, `"../svg_plot.hpp"`) through the including file's folder. Includes that resolve
to nothing in the tree (the standard library, LinuxCNC's `hal.h`) are not nckit's and are skipped.

A cell is empty (forbidden), ✓ (anything of that stage), or a list ending in "only"
(`move.hpp` only; pattern, `svg_plot.hpp` only): each item names a header or a subfolder of the
stage, relative to src/<stage>/ or include/nckit/<stage>/. A file may always include files of
its own row. The stage libraries' link lines (src/CMakeLists.txt's `nckit_stage(... DEPENDS ...)`,
`target_link_libraries` of the nckit command and the LinuxCNC plug-in) are checked against the
same rows. Every refused edge is printed as FILE:LINE: error: ... and the exit status is 1;
a page without the table, or a file in a folder the table has no row for, exits 2.

Usage: check_layering.py [SOURCE_DIR]   (default: the repository this script is in)"""
import os
import re
import sys
from pathlib import Path

TABLE_HEADER = re.compile(r"^\|\s*stage\s*↓\s*may include\s*→\s*\|")
INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]')
SOURCE_SUFFIXES = {".cpp", ".hpp", ".h", ".hh", ".cc", ".c"}
# The folders whose files are checked, relative to the source tree.
SCANNED = ("src", "include/nckit", "hal")
ALLOW_ALL = "✓"


class LayeringError(Exception):
    """The page or the tree cannot be checked at all (exit status 2)."""


def split_row(line: str):
    return [cell.strip() for cell in line.strip().strip("|").split("|")]


def parse_cell(cell: str):
    """None: forbidden; []: everything; [items]: only these headers or subfolders."""
    cell = cell.strip()
    if not cell:
        return None
    if cell == ALLOW_ALL:
        return []
    if not cell.endswith(" only"):
        raise LayeringError(f"cannot read the table cell '{cell}' (✓, empty or '... only')")
    items = re.split(r",|\band\b", cell[: -len(" only")])
    items = [item.strip().strip("`").strip() for item in items]
    if not all(items):
        raise LayeringError(f"an empty item in the table cell '{cell}'")
    return items


def read_table(page: Path):
    """{row stage: {column stage: None | [] | [items]}} and the list of column stages."""
    lines = page.read_text(encoding="utf-8").splitlines()
    start = next((i for i, line in enumerate(lines) if TABLE_HEADER.match(line)), None)
    if start is None:
        raise LayeringError(f"{page}: no table headed '| stage ↓ may include → |'")
    columns = [c.strip("`") for c in split_row(lines[start])[1:]]
    table = {}
    for number, line in enumerate(lines[start + 2:], start=start + 3):
        if not line.startswith("|"):
            break
        cells = split_row(line)
        if len(cells) != len(columns) + 1:
            raise LayeringError(f"{page}:{number}: {len(cells)} cells, the header has {len(columns) + 1}")
        try:
            table[cells[0].strip("`")] = {col: parse_cell(cell) for col, cell in zip(columns, cells[1:])}
        except LayeringError as error:
            raise LayeringError(f"{page}:{number}: {error}") from None
    if not table:
        raise LayeringError(f"{page}:{start + 1}: the table has no rows")
    return table, columns


def stage_of(relative: Path):
    """(stage folder, path inside it) of a file of the tree, or None outside src/, include/, hal/.
    The stage folder is `process/pattern` for pattern files, so it doubles as the row name."""
    parts = relative.parts
    if len(parts) >= 3 and parts[0] == "src":
        inner = parts[1:]
    elif len(parts) >= 4 and parts[:2] == ("include", "nckit"):
        inner = parts[2:]
    elif len(parts) >= 2 and parts[0] == "hal":
        return "hal", Path(*parts[1:])
    else:
        return None
    return inner[0], Path(*inner[1:])


def row_of(relative: Path):
    stage, inner = stage_of(relative)
    if stage == "process" and len(inner.parts) > 1 and inner.parts[0] == "pattern":
        return "process/pattern"
    return stage


def resolve(root: Path, including: Path, bracket: str, name: str):
    """The tree file an include names (relative to root), or None if it is not nckit's."""
    candidates = []
    if bracket == '"':
        candidates.append(including.parent / name)
    candidates.append(Path("include") / name)
    for candidate in candidates:
        # normpath, not resolve(): `..` is folded by name, so a tree of symbolic links (the
        # documentation tests' scratch copy) maps to its own paths.
        candidate = Path(os.path.normpath(candidate))
        if not candidate.parts or candidate.parts[0] == "..":
            continue
        if (root / candidate).is_file():
            return candidate
    if name.startswith("nckit/"):
        # A header of nckit that does not exist: check the edge anyway, the compiler will
        # complain about the file.
        return Path("include") / name
    return None


def allows(cell, inner: Path):
    if cell is None:
        return False
    if not cell:
        return True
    text = inner.as_posix()
    return any(text == item or text.startswith(item.rstrip("/") + "/") for item in cell)


def describe(row_rules):
    allowed = []
    for column, cell in row_rules.items():
        if cell == []:
            allowed.append(column)
        elif cell:
            allowed.append(f"{column} ({', '.join(cell)} only)")
    return ", ".join(allowed) or "nothing"


def source_files(root: Path):
    for folder in SCANNED:
        base = root / folder
        if base.is_dir():
            yield from sorted(p for p in base.rglob("*") if p.suffix in SOURCE_SUFFIXES and p.is_file())


def check(root: Path, page: Path):
    """The refused edges as printable lines, and how many includes were checked."""
    table, columns = read_table(page)
    errors, checked = check_links(root, table, columns), 0
    for path in source_files(root):
        relative = path.relative_to(root)
        row = row_of(relative)
        if row not in table:
            raise LayeringError(f"{relative}: the table of {page.name} has no row '{row}'")
        lines = path.read_text(encoding="utf-8", errors="replace").splitlines()
        for number, line in enumerate(lines, start=1):
            match = INCLUDE.match(line)
            if not match:
                continue
            target = resolve(root, relative, match.group(1), match.group(2))
            if target is None or stage_of(target) is None:
                continue
            checked += 1
            column, inner = stage_of(target)
            if row_of(target) == row:
                continue
            cell = table[row].get(column)
            if column not in columns or not allows(cell, inner):
                errors.append(f"{relative}:{number}: error: {row} may not include {target} "
                              f"(stage {column}); {page.name} lets {row} include: "
                              f"{describe(table[row])}")
    return errors, checked


# The libraries the stages build and the rows they stand for; `nckit_pattern` is the `pattern`
# subfolder of process. Other targets of the build (tests, the HAL modules' nckit_realtime) are
# not stages.
LIBRARY_ROWS = {"nckit": "cli", "nckit_linuxcnc": "linuxcnc_interp", "nckit_pattern": "process/pattern"}
LINK_FILES = ("src/CMakeLists.txt", "src/linuxcnc_interp/CMakeLists.txt")
LINK_CALL = re.compile(r"\b(nckit_stage|target_link_libraries)\s*\(([^()]*)\)", re.S)


def library_column(library: str):
    """(column stage, the subfolder a link stands for or None) of one of nckit's libraries."""
    if library == "nckit_pattern":
        return "process", "pattern"
    return library[len("nckit_"):], None


def check_links(root: Path, table, columns):
    """Each stage library links only libraries of stages its row may include. A cell that allows
    only some headers allows no link (they are header-only), except a subfolder that is a library
    of its own (`pattern`)."""
    errors = []
    for name in LINK_FILES:
        path = root / name
        if not path.is_file():
            continue
        text = path.read_text(encoding="utf-8")
        for call in LINK_CALL.finditer(text):
            words = call.group(2).split()
            if not words:
                continue
            target = words[0] if call.group(1) == "target_link_libraries" else f"nckit_{words[0]}"
            row = LIBRARY_ROWS.get(target, target[len("nckit_"):])
            if not target.startswith("nckit") or row not in table:
                continue
            if call.group(1) == "nckit_stage":
                words = words[words.index("DEPENDS") + 1:] if "DEPENDS" in words else []
            offset = call.start(2)
            for library in words[1:] if call.group(1) == "target_link_libraries" else words:
                if not re.fullmatch(r"nckit_[a-z_]+", library) or library == target:
                    continue
                column, folder = library_column(library)
                cell = table[row].get(column) if column in columns else None
                if cell == [] or (folder is not None and cell is not None and folder in cell):
                    continue
                line = text.count("\n", 0, text.index(library, offset)) + 1
                errors.append(f"{name}:{line}: error: {target} ({row}) may not link {library} "
                              f"(stage {column}); the table lets {row} include: {describe(table[row])}")
    return errors


def main() -> int:
    root = Path(sys.argv[1]) if len(sys.argv) > 1 else Path(__file__).resolve().parents[2]
    page = root / "docs" / "architecture.md"
    try:
        errors, checked = check(root, page)
    except (LayeringError, OSError) as error:
        print(f"check_layering: {error}", file=sys.stderr)
        return 2
    for error in errors:
        print(error, file=sys.stderr)
    if errors:
        print(f"{len(errors)} include(s) break the layering of {page.relative_to(root)}", file=sys.stderr)
        return 1
    if checked == 0:
        print("check_layering: no nckit include found: wrong source folder?", file=sys.stderr)
        return 2
    print(f"layering: {checked} includes and the stage libraries' links follow the table of "
          f"{page.relative_to(root)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
