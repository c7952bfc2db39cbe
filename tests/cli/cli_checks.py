"""What the CLI tests beside this file share: counted checks with one closing line, and running
nckit with its output captured and a time limit."""
import subprocess

_failures = []
_checks = 0


def check(condition, what):
    global _checks
    _checks += 1
    if not condition:
        _failures.append(what)
        print(f"FAIL {what}")


def run_nckit(nckit, *args, timeout=120, **kwargs):
    return subprocess.run([nckit, *map(str, args)], capture_output=True, timeout=timeout, **kwargs)


def summary() -> int:
    """Prints 'N passed, M failed' (read by CI) and returns the exit status."""
    print(f"{_checks - len(_failures)} passed, {len(_failures)} failed")
    return 1 if _failures else 0
