"""HAL graphs for nckit's HAL tests: a spindle from sim_encoder through LinuxCNC's encoder, Z
from the spindle's turns (a carriage fed per revolution, held to a range by limit1), nckit_cam
and nckit_servo in one servo thread, and sampler recording pins every period. One thread keeps
every component in step: each period the encoder, the cam and the axis model run once, in order.
"""

SERVO_PERIOD_NS = 66666  # 15.0002 kHz: one update per spindle degree at 2500 rpm


def spindle_graph(table, counts=360, rev_s=2500 / 60, z_offset_mm=0.0, z_mm_rev=0.0, z_min_mm=-1e9,
                  z_max_mm=1e9, sampled=(), samples=3000, depth=40000, cam_setup="", index_net=None,
                  period_ns=SERVO_PERIOD_NS, sample_file="samples.txt"):
    """The .hal text. `sampled` lists (type letter, pin or "sig:SIGNAL") recorded per period;
    `index_net` (HAL lines) replaces the index wiring; `cam_setup` (HAL lines) comes last before
    start. Anything that must happen at a given time is done in the thread (timedelay), so a
    loaded machine does not move it."""
    if counts % 4:
        raise ValueError("sim_encoder makes 4 counts per pulse: counts must be a multiple of 4")
    cfg = "".join(kind for kind, _ in sampled)
    lines = [
        f"loadrt threads name1=servo period1={period_ns}",
        "loadrt sim_encoder num_chan=1",
        "loadrt encoder num_chan=1",
        "loadrt scale count=1",
        "loadrt limit1 count=1",
        f"loadrt nckit_cam tables={table} counts={counts}",
        "loadrt nckit_servo count=1",
        f"loadrt sampler depth={depth} cfg={cfg}",
        "addf sim-encoder.update-speed servo",
        "addf sim-encoder.make-pulses servo",
        "addf encoder.update-counters servo",
        "addf encoder.capture-position servo",
        "addf scale.0 servo",
        "addf limit1.0 servo",
        "addf nckit-cam.0 servo",
        "addf nckit-servo.0 servo",
        "addf sampler.0 servo",
        f"setp sim-encoder.0.ppr {counts // 4}",
        f"setp sim-encoder.0.speed {rev_s!r}",
        "net spindle-a sim-encoder.0.phase-A => encoder.0.phase-A",
        "net spindle-b sim-encoder.0.phase-B => encoder.0.phase-B",
        f"setp encoder.0.position-scale {counts}",
        "net spindle-counts encoder.0.counts => nckit-cam.0.spindle-counts",
        "net spindle-revs encoder.0.position => scale.0.in",
        f"setp scale.0.gain {z_mm_rev!r}",
        f"setp scale.0.offset {z_offset_mm!r}",
        f"setp limit1.0.min {z_min_mm!r}",
        f"setp limit1.0.max {z_max_mm!r}",
        "net z-raw scale.0.out => limit1.0.in",
        "net z-pos limit1.0.out => nckit-cam.0.z",
        "net fts-cmd nckit-cam.0.command => nckit-servo.0.command",
        "net fts-pos nckit-servo.0.position => nckit-cam.0.feedback",
    ]
    lines += index_net or ["net spindle-index sim-encoder.0.phase-Z => encoder.0.phase-Z nckit-cam.0.spindle-index"]
    lines += cam_setup.strip().splitlines()
    for i, (_, pin) in enumerate(sampled):
        lines.append(f"net sample-{i} {pin} => sampler.0.pin.{i}" if not pin.startswith("sig:")
                     else f"net {pin[4:]} => sampler.0.pin.{i}")
    lines.append("start")
    lines.append(f"loadusr -w halsampler -t -n {samples} {sample_file}")
    lines.append("stop")
    return "\n".join(lines) + "\n"
