#!/usr/bin/env python3
"""Checks run_doc_commands.py itself on a small tree of pages: which commands it finds, how it
joins lines, what the markers do, and that a failing command, a wrong exit status and a stray
marker fail the run. Usage: run_doc_commands_test.py NCKIT"""
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))
import run_doc_commands as docs  # noqa: E402

PAGE = """# page

```sh
# a comment line is not a command
nckit --version
nckit moves examples/x.ngc \\
    --summary
for n in 1 2; do
  echo $n
done
```

<!-- doc-test: skip needs a browser -->
```bash
xdg-open page.html
```

<!-- doc-test: exit 2 -->
```console
$ nckit moves missing.ngc
missing.ngc:0:0: error: cannot open
```

```toml
[machine]
```
"""

failures = 0


def check(what, ok):
    global failures
    print(("ok   " if ok else "FAIL ") + what)
    failures += 0 if ok else 1


def run(tree: Path, nckit: str):
    done = subprocess.run([sys.executable, str(HERE / "run_doc_commands.py"), "--nckit", nckit,
                           "--source", str(tree)], capture_output=True, text=True, timeout=120)
    return done.returncode, done.stdout


def main() -> int:
    nckit = sys.argv[1]
    with tempfile.TemporaryDirectory() as scratch:
        tree = Path(scratch)
        (tree / "docs").mkdir()
        (tree / "examples").mkdir()
        (tree / "examples" / "x.ngc").write_text("G0 X1\nM30\n")
        (tree / "README.md").write_text(PAGE)
        blocks, problems = docs.parse_page(tree / "README.md", "README.md")
        check("three shell blocks, the toml block left out", len(blocks) == 3)
        check("no marker problems", problems == [])
        first = [c for _, c in blocks[0].commands]
        check("comments dropped, backslash lines joined, a loop kept whole",
              first == ["nckit --version", "nckit moves examples/x.ngc      --summary",
                        "for n in 1 2; do\n  echo $n\ndone"])
        check("skip marker keeps its reason", blocks[1].skip_reason == "needs a browser")
        check("exit marker and console prompt",
              blocks[2].expected_exit == 2 and [c for _, c in blocks[2].commands]
              == ["nckit moves missing.ngc"])
        status, out = run(tree, nckit)
        check("the page passes (4 run, 1 skipped)",
              status == 0 and "4 commands run, 1 skipped, 0 failed" in out)

        (tree / "docs" / "bad.md").write_text(
            "```sh\nnckit moves missing.ngc\n```\n\n<!-- doc-test: exit 2 -->\n"
            "```sh\nnckit --version\n```\n\n<!-- doc-test: skip -->\nprose\n")
        status, out = run(tree, nckit)
        check("a failing command, a wrong exit status and a stray marker fail the run",
              status == 1 and "3 failed" in out and "FAIL docs/bad.md:2" in out
              and "FAIL docs/bad.md:7" in out and "MARKER docs/bad.md:10" in out)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
