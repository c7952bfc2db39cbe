#!/usr/bin/env python3
"""check_layering.py refuses what it must: tiny trees, each with docs/architecture.md's real
table, and one include that is allowed or not. Usage: check_layering_test.py [SOURCE_DIR]"""
import contextlib
import io
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
CHECKER = HERE / "check_layering.py"
sys.dont_write_bytecode = True  # nothing written into the source tree
sys.path.insert(0, str(HERE))
import check_layering  # noqa: E402  (the checker beside this file)
SOURCE = Path(sys.argv[1]) if len(sys.argv) > 1 else HERE.parents[1]
PAGE = (SOURCE / "docs" / "architecture.md").read_text(encoding="utf-8")

# Every tree has these: a header per stage, so includes of them resolve.
BASE = {
    "include/nckit/core/diagnostic.hpp": "#pragma once\n",
    "include/nckit/interp/move.hpp": '#pragma once\n#include "nckit/core/diagnostic.hpp"\n',
    "include/nckit/interp/interpreter.hpp": '#pragma once\n#include "nckit/interp/move.hpp"\n',
    "include/nckit/plan/planner.hpp": '#pragma once\n#include "nckit/interp/move.hpp"\n',
    "include/nckit/drive/step_generator.hpp": '#pragma once\n#include "nckit/plan/planner.hpp"\n',
    "include/nckit/process/pattern/pattern_job.hpp": '#pragma once\n#include "nckit/plan/planner.hpp"\n',
    "src/process/svg_plot.hpp": "#pragma once\n#include <string>\n",
    "src/plan/rates.hpp": "#pragma once\n",
    "src/cli/main.cpp": '#include "nckit/drive/step_generator.hpp"\n#include "common.hpp"\n',
    "src/cli/common.hpp": "#pragma once\n",
    "hal/nckit_servo.cpp": '#include "nckit/drive/step_generator.hpp"\n#include "hal.h"\n',
}

# The link lines of a build that follows the table.
LINKS = """nckit_stage(core SOURCES core/a.cpp DEPENDS fmt::fmt)
nckit_stage(gcode SOURCES gcode/a.cpp DEPENDS nckit_core)
nckit_stage(interp SOURCES interp/a.cpp DEPENDS nckit_gcode nckit_core)
nckit_stage(plan SOURCES plan/a.cpp
  DEPENDS nckit_core)
nckit_stage(drive SOURCES drive/a.cpp DEPENDS nckit_plan nckit_core)
nckit_stage(pattern SOURCES process/pattern/a.cpp DEPENDS nckit_plan nckit_interp ${DXFLIB_LIBRARY})
nckit_stage(report SOURCES report/a.cpp DEPENDS nckit_pattern nckit_plan nckit_core)
add_executable(nckit cli/main.cpp)
target_link_libraries(nckit PRIVATE nckit_report nckit_drive CLI11::CLI11)
"""


def run(extra, page=PAGE):
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(tmp)
        for name, text in {**BASE, **extra, "docs/architecture.md": page}.items():
            path = root / name
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(text, encoding="utf-8")
        # In this process (a Python start per case is slow on a loaded machine), through the
        # checker's own main(), so its exit status and messages are what is tested.
        output = io.StringIO()
        saved_argv = sys.argv
        sys.argv = [str(CHECKER), str(root)]
        try:
            with contextlib.redirect_stdout(output), contextlib.redirect_stderr(output):
                status = check_layering.main()
        finally:
            sys.argv = saved_argv
        return status, output.getvalue()


CASES = [
    # (what, extra files, exit status, text the output must hold[, text it must not hold])
    ("the allowed edges pass", {}, 0, "8 includes and the stage libraries' links follow the table"),
    ("plan may include interp's move.hpp",
     {"src/plan/planner.cpp": '#include "nckit/interp/move.hpp"\n#include "rates.hpp"\n'}, 0, "follow"),
    ("plan may not include the rest of interp",
     {"src/plan/planner.cpp": '// the planner\n#include "nckit/interp/interpreter.hpp"\n'}, 1,
     "src/plan/planner.cpp:2: error: plan may not include include/nckit/interp/interpreter.hpp"),
    ("plan may not include drive, through <>",
     {"include/nckit/plan/trajectory.hpp": "#pragma once\n\n#include <nckit/drive/step_generator.hpp>\n"}, 1,
     "include/nckit/plan/trajectory.hpp:3: error: plan may not include"),
    ("core includes nothing of the stages above it",
     {"src/core/machine_config.cpp": '#include "nckit/plan/planner.hpp"\n'}, 1,
     "src/core/machine_config.cpp:1: error: core may not include"),
    ("a relative include into another stage's private header",
     {"src/drive/servo_model.cpp": '#include "../process/svg_plot.hpp"\n'}, 1,
     "src/drive/servo_model.cpp:1: error: drive may not include src/process/svg_plot.hpp (stage process)"),
    ("pattern may include svg_plot.hpp and pattern, not the rest of process",
     {"src/process/pattern/pattern_svg.cpp": '#include "../svg_plot.hpp"\n#include "nckit/process/pattern/pattern_job.hpp"\n',
      "include/nckit/process/notch/notch.hpp": "#pragma once\n",
      "src/process/pattern/pattern_run.cpp": '#include "nckit/process/notch/notch.hpp"\n'}, 1,
     "src/process/pattern/pattern_run.cpp:1: error: process/pattern may not include include/nckit/process/notch/notch.hpp",
     "pattern_svg.cpp"),
    ("nothing may include the command line's files",
     {"src/report/report_page.cpp": '#include "../cli/common.hpp"\n'}, 1,
     "src/report/report_page.cpp:1: error: report may not include src/cli/common.hpp (stage cli)"),
    ("the stage libraries link what their rows allow",
     {"src/CMakeLists.txt": LINKS}, 0, "follow"),
    ("plan's library may not link interp: move.hpp is header-only",
     {"src/CMakeLists.txt": LINKS.replace("DEPENDS nckit_core)\nnckit_stage(drive", "DEPENDS nckit_interp nckit_core)\nnckit_stage(drive")},
     1, "src/CMakeLists.txt:5: error: nckit_plan (plan) may not link nckit_interp"),
    ("the plug-in may not link drive",
     {"src/CMakeLists.txt": LINKS,
      "src/linuxcnc_interp/CMakeLists.txt": "add_library(nckit_linuxcnc MODULE a.cpp)\n"
                                            "target_link_libraries(nckit_linuxcnc PRIVATE\n  nckit_interp nckit_drive fmt::fmt)\n"},
     1, "src/linuxcnc_interp/CMakeLists.txt:3: error: nckit_linuxcnc (linuxcnc_interp) may not link nckit_drive"),
    ("a stage the table has no row for",
     {"src/robot/arm.cpp": '#include "nckit/core/diagnostic.hpp"\n'}, 2, "has no row 'robot'"),
    ("a page without the table", {}, 2, "no table headed"),
    ("a cell the checker cannot read", {}, 2, "cannot read the table cell"),
]


def page_for(what):
    if what == "a page without the table":
        return "# Architecture\n\nNo table here.\n"
    if what == "a cell the checker cannot read":
        broken = PAGE.replace("| plan | ✓ | | `move.hpp` only |", "| plan | ✓ | | `move.hpp` |", 1)
        assert broken != PAGE, "the plan row of docs/architecture.md changed: update this test"
        return broken
    return PAGE


def main() -> int:
    failures = 0
    # Once as a program, as CTest runs it: a forbidden edge exits 1 and names file and line.
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(tmp)
        for name, text in {**BASE, "docs/architecture.md": PAGE,
                           "src/gcode/parser.cpp": '#include "nckit/interp/move.hpp"\n'}.items():
            (root / name).parent.mkdir(parents=True, exist_ok=True)
            (root / name).write_text(text, encoding="utf-8")
        done = subprocess.run([sys.executable, str(CHECKER), str(root)], capture_output=True, text=True)
        if done.returncode != 1 or "src/gcode/parser.cpp:1: error: gcode may not include" not in done.stderr:
            failures += 1
            print(f"FAIL the checker as a program: exit {done.returncode}\n{done.stdout}{done.stderr}")
        else:
            print("ok   the checker as a program")
    for what, extra, status, text, *absent in CASES:
        got_status, output = run(extra, page_for(what))
        if got_status != status or text not in output or any(a in output for a in absent):
            failures += 1
            print(f"FAIL {what}: exit {got_status} (want {status}), output:\n{output}")
        else:
            print(f"ok   {what}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
