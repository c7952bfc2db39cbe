#!/usr/bin/env python3
"""Outputs that never destroy what they point at, seen from outside: -o to a character device,
a named pipe, a symlink, '-', a missing folder, a folder, a read-only folder; a killed run leaves
no .partial; `nckit moves` writes retained variables only with --save-vars."""
import os
import pathlib
import signal
import stat
import subprocess
import sys
import tempfile
import threading
import time

from cli_checks import check, summary
from cli_checks import run_nckit as run

ROOT = pathlib.Path(__file__).resolve().parents[2]
POCKET = ROOT / "examples" / "01_mill_pocket.ngc"


def main() -> int:
    nckit = sys.argv[1]
    reference = run(nckit, "steps", POCKET).stdout
    check(len(reference) > 0 and len(reference) % 10 == 0, "steps to stdout gives 10-byte records")
    with tempfile.TemporaryDirectory() as tmp_name:
        tmp = pathlib.Path(tmp_name)

        # A character device is written through, never replaced (as root, the old code renamed
        # a regular file over /dev/null). A node of our own is tried first, then /dev/null itself.
        if os.geteuid() == 0:
            null = tmp / "null"
            try:
                os.mknod(null, stat.S_IFCHR | 0o666, os.makedev(1, 3))
                r = run(nckit, "steps", POCKET, "-o", null)
                check(r.returncode == 0 and stat.S_ISCHR(os.stat(null).st_mode), "a device node stays a device")
            except PermissionError:
                pass
            r = run(nckit, "steps", POCKET, "-o", "/dev/null")
            check(r.returncode == 0, f"-o /dev/null exits 0 ({r.stderr.decode().strip()})")
            check(stat.S_ISCHR(os.stat("/dev/null").st_mode), "/dev/null is still a character device")
            check(not os.path.exists("/dev/null.partial"), "no /dev/null.partial")

        # A named pipe's reader gets every byte.
        fifo = tmp / "fifo"
        os.mkfifo(fifo)
        received = []
        reader = threading.Thread(target=lambda: received.append(open(fifo, "rb").read()))
        reader.start()
        r = run(nckit, "steps", POCKET, "-o", fifo)
        reader.join(timeout=60)
        check(r.returncode == 0 and received and received[0] == reference, "a FIFO reader gets the steps")
        check(stat.S_ISFIFO(os.stat(fifo).st_mode), "the FIFO stays a FIFO")

        # A symlink is followed: its target is written, the link stays a link.
        target = tmp / "real.bin"
        target.write_bytes(b"old")
        link = tmp / "link.bin"
        link.symlink_to("real.bin")
        r = run(nckit, "steps", POCKET, "-o", link)
        check(r.returncode == 0 and link.is_symlink() and target.read_bytes() == reference,
              "a symlink's target is written and the link kept")
        check(not (tmp / "link.bin.partial").exists() and not (tmp / "real.bin.partial").exists(), "no .partial left")

        # '-' is standard output, not a file named '-'.
        r = run(nckit, "steps", POCKET, "-o", "-", cwd=tmp)
        check(r.returncode == 0 and r.stdout == reference and not (tmp / "-").exists(), "-o - writes stdout")
        r = run(nckit, "expand", POCKET, "-o", "-", cwd=tmp)
        check(r.returncode == 0 and b"G1" in r.stdout and not (tmp / "-").exists(), "expand -o - writes stdout")

        # Errors that say why, and nothing written.
        r = run(nckit, "steps", POCKET, "-o", tmp / "nofolder" / "x.bin")
        err = r.stderr.decode()
        check(r.returncode == 2 and f"{tmp}/nofolder/x.bin: cannot write: No such file or directory (folder '{tmp}/nofolder' does not exist)" in err,
              f"missing folder message ({err.strip()})")
        r = run(nckit, "steps", POCKET, "-o", tmp)
        check(r.returncode == 2 and "cannot write: Is a directory" in r.stderr.decode(), "a folder is refused")
        locked = tmp / "locked"
        locked.mkdir()
        locked.chmod(0o555)
        as_nobody = (lambda: os.setuid(65534)) if os.geteuid() == 0 else None
        r = subprocess.run([nckit, "steps", str(POCKET), "-o", str(locked / "x.bin")], capture_output=True,
                           timeout=60, preexec_fn=as_nobody)
        check(r.returncode == 2 and "cannot write: Permission denied" in r.stderr.decode(),
              f"a read-only folder is refused ({r.stderr.decode().strip()})")

        # A bad program leaves the old file as it was.
        kept = tmp / "kept.bin"
        kept.write_bytes(b"old")
        bad = tmp / "bad.ngc"
        bad.write_text("G1 X10 F100\nG1 Q5\n")
        r = run(nckit, "steps", bad, "-o", kept)
        check(r.returncode == 2 and kept.read_bytes() == b"old" and not (tmp / "kept.bin.partial").exists(),
              "a bad program keeps the old file")

        # A killed run removes its .partial and leaves the old file.
        long_program = tmp / "long.ngc"
        with open(long_program, "w") as f:
            f.write("G21 G90 G94 F6000\n")
            for i in range(300_000):
                f.write(f"G1 X{i % 200 - 100} Y{(i // 200) % 100}\n")
            f.write("M30\n")
        out = tmp / "killed.bin"
        out.write_bytes(b"old")
        process = subprocess.Popen([nckit, "steps", str(long_program), "-o", str(out), "--quiet"],
                                   stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        partial = tmp / "killed.bin.partial"
        for _ in range(600):
            if partial.exists() or process.poll() is not None:
                break
            time.sleep(0.05)
        time.sleep(0.2)
        process.send_signal(signal.SIGTERM)
        status = process.wait(timeout=60)
        check(status == -signal.SIGTERM, f"SIGTERM ends the run ({status})")
        check(not partial.exists() and out.read_bytes() == b"old", "a killed run removes its .partial")

        # moves writes #500-#999 only with --save-vars.
        vars_program = tmp / "vars.nc"
        vars_program.write_text("#500 = 42\nG1 X1 F100\nM30\n")
        machine = tmp / "mill.toml"
        machine.write_text((ROOT / "examples" / "machines" / "mill.toml").read_text())
        r = run(nckit, "moves", vars_program, "--machine", machine)
        check(r.returncode == 0 and not (tmp / "mill.vars").exists(), "moves leaves the vars file alone")
        r = run(nckit, "moves", vars_program, "--machine", machine, "--save-vars")
        check(r.returncode == 0 and "#500 = 42" in (tmp / "mill.vars").read_text(), "--save-vars writes them")
    return summary()


if __name__ == "__main__":
    sys.exit(main())
