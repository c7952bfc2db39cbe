"""The DISPLAY of a headless LinuxCNC run: it runs inside LinuxCNC under Debian's
/usr/bin/python3 (which has the `linuxcnc` module), brings the machine on in auto mode, runs the
program while halsampler records the commanded positions, and leaves its result in
display_result.json beside the INI. bench/linuxcnc_planner.py starts LinuxCNC with it;
tests/linuxcnc_plugin/run_machine.py and tests/hal/piston_machine_test.py drive their runs with
its DisplaySession."""

import json
import os
import signal
import subprocess
import time


class DisplaySession:
    """The display side of a headless run, inside LinuxCNC: its status, command and error
    channels, the errors it reports (appended to result["errors"]), bounded waits, and the
    sampler recording the commanded positions. tests/linuxcnc_plugin/run_machine.py drives its
    runs with it too."""

    def __init__(self, linuxcnc, result, run_timeout_s):
        self.lc = linuxcnc
        self.s, self.c, self.e = linuxcnc.stat(), linuxcnc.command(), linuxcnc.error_channel()
        self.result = result
        self.deadline = time.monotonic() + run_timeout_s
        self.sampler = None
        self.samples_out = None

    def poll_errors(self):
        while True:
            msg = self.e.poll()
            if not msg:
                return
            kind, text = msg
            if kind in (self.lc.NML_ERROR, self.lc.OPERATOR_ERROR):
                self.result["errors"].append(text)

    def wait_for(self, pred, what, limit_s, stop_on_error=True):
        """Polls until pred() holds; an error LinuxCNC reports ends the wait as a failure unless
        stop_on_error is False (then pred decides)."""
        end = min(self.deadline, time.monotonic() + limit_s)
        while time.monotonic() < end:
            self.s.poll()
            self.poll_errors()
            if stop_on_error and self.result["errors"]:
                raise RuntimeError(f"LinuxCNC error while waiting for {what}")
            if pred():
                return
            time.sleep(0.005)
        raise RuntimeError(f"timed out waiting for {what}")

    def machine_on_in_auto(self):
        """Waits for task, resets the E-stop, switches the machine on and selects auto mode."""
        lc, s, c = self.lc, self.s, self.c
        self.result["phase"] = "task up"
        end = time.monotonic() + 30
        while True:
            try:
                s.poll()
                if s.task_state:
                    break
            except lc.error:
                pass
            if time.monotonic() > end:
                raise RuntimeError("task did not come up in 30 s")
            time.sleep(0.05)

        self.result["phase"] = "machine on"
        c.state(lc.STATE_ESTOP_RESET)
        c.wait_complete(5)
        c.state(lc.STATE_ON)
        c.wait_complete(5)
        self.wait_for(lambda: s.task_state == lc.STATE_ON, "machine on", 10)
        c.mode(lc.MODE_AUTO)
        c.wait_complete(5)
        self.wait_for(lambda: s.task_mode == lc.MODE_AUTO, "auto mode", 10)

    def open_program(self, program):
        self.result["phase"] = "open"
        self.c.program_open(program)
        self.c.wait_complete(30)
        self.poll_errors()
        if self.result["errors"]:
            raise RuntimeError("program_open failed")

    def start_sampling(self, work):
        """halsampler drains the sampler into work/samples.txt; idle rows before the motion."""
        self.result["phase"] = "sampling"
        self.samples_out = open(os.path.join(work, "samples.txt"), "w")
        self.sampler = subprocess.Popen(["halsampler", "-t"], stdout=self.samples_out,
                                        stderr=subprocess.DEVNULL)
        time.sleep(0.2)

    def stop_sampling(self):
        if self.sampler is not None:
            self.sampler.send_signal(signal.SIGINT)
            try:
                self.sampler.wait(5)
            except subprocess.TimeoutExpired:
                self.sampler.kill()
                self.sampler.wait(5)
        if self.samples_out is not None:
            self.samples_out.close()


def run_failed(session, result, ex):
    """An exception ended the run: its message goes into the result, and whatever the machine
    is doing is aborted (if LinuxCNC can still be reached)."""
    result["errors"].append(f"{type(ex).__name__}: {ex}")
    try:
        session.c.abort()
    except Exception:
        pass


def finish_run(session, result, work):
    """Stops the sampler and leaves the result in display_result.json beside the INI, where the
    parent reads it."""
    if session is not None:
        session.stop_sampling()
    with open(os.path.join(work, "display_result.json"), "w") as f:
        json.dump(result, f)


def display_main(argv):
    """LinuxCNC runs `DISPLAY -ini FILE`; the run's settings are in run.json beside FILE."""
    ini = argv[argv.index("-ini") + 1]
    work = os.path.dirname(os.path.abspath(ini))
    with open(os.path.join(work, "run.json")) as f:
        run = json.load(f)
    result = {"ok": False, "errors": [], "phase": "start"}
    session = None
    try:
        import linuxcnc
        session = DisplaySession(linuxcnc, result, run["run_timeout_s"])
        s, c = session.s, session.c
        session.machine_on_in_auto()
        session.open_program(run["program"])
        session.start_sampling(work)

        result["phase"] = "run"
        t0 = time.monotonic()
        c.auto(linuxcnc.AUTO_RUN, 0)
        # Running = interpreter busy; finished = idle again, queue empty, in position.
        session.wait_for(lambda: s.interp_state != linuxcnc.INTERP_IDLE or s.queue > 0
                         or not s.inpos, "the program to start", 10)
        session.wait_for(lambda: s.interp_state == linuxcnc.INTERP_IDLE and s.queue == 0
                         and s.inpos and s.exec_state == linuxcnc.EXEC_DONE,
                         "the program to finish", run["run_timeout_s"])
        result["wall_s"] = time.monotonic() - t0
        time.sleep(0.2)  # idle rows after the motion
        result["ok"] = True
        result["phase"] = "done"
    except Exception as ex:  # reported to the parent through display_result.json
        run_failed(session, result, ex)
    finally:
        finish_run(session, result, work)
    # Exiting the display makes the linuxcnc script shut everything down.
    return 0
