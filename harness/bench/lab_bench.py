"""make bench-lab (mk/lab.mk): what the lab bench costs (issue 11's goals).

1. Real pace, the page open in headless Chromium, the servo running (1000 LOAD,
   Set.Up.Robot, a move; the axes then hunt round their targets): the CPU time
   the simulator and the lab server take over WINDOW_S of wall time, as a share
   of one core (goal: under 15 %). Chromium's own share is printed apart.
2. Full speed: the simulator's instruction rate with the lab and the page open
   (simulated seconds per wall second x RATE) beside build/pdp11 alone running
   the same machine with the same servo (goal: at most 10 % lower); and the
   same per CPU second of the simulator, which the host's other load moves less;
   and build/pdp11 with the LAB device attached (writing to /dev/null) against
   without, both without a browser: the device's own cost.
Figures depend on the host and on what else runs on it: the runs without the lab
are the best of three; the lab's are one window each.
"""
import os
import re
import resource
import shutil
import tempfile
import time
from pathlib import Path

from harness.lab.launch import ROOT, LabProcess, have_browser, headless_browser
from harness.machine import simh
from harness.machine.console_session import KERNEL

RATE = 300_000
WINDOW_S = 10.0
SETUP = ("1000 LOAD", "Set.Up.Robot", "800 800 400 0 Abs.Move")
SETUP_INSTRUCTIONS = 6_000_000        # 20 simulated seconds: the load, the set-up, the move
BASELINE_INSTRUCTIONS = 150_000_000   # 500 simulated seconds: a few host seconds
TICKS_PER_S = os.sysconf("SC_CLK_TCK")


def cpu_seconds(pid):
    """User + system CPU seconds of one process (and its waited-for children)."""
    fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    return sum(int(f) for f in fields[11:15]) / TICKS_PER_S


def browser_pids():
    """Every chromium process (the headless page's renderer, GPU and browser)."""
    pids = []
    for stat in Path("/proc").glob("[0-9]*/stat"):
        try:
            if "(chromium" in stat.read_text():
                pids.append(int(stat.parent.name))
        except OSError:
            pass
    return pids


def typed(page, line):
    before = page.execute_script("return window.lab.screen()").count(" ok")
    page.find_element("css selector", "#terminal textarea").send_keys(line + "\n")
    deadline = time.monotonic() + 120
    while page.execute_script("return window.lab.screen()").count(" ok") <= before:
        if time.monotonic() > deadline:
            raise RuntimeError(f"no answer to {line!r}")
        time.sleep(0.05)


def status(page):
    return page.execute_script("return window.lab.status")


def choose_speed(page, speed):
    page.find_element("css selector", f'#speeds button[data-speed="{speed}"]').click()
    while status(page)["speed"] != speed:
        time.sleep(0.05)


def measure_lab(tmp):
    lab = LabProcess(tmp, speed="full")
    page = headless_browser()
    try:
        page.get(lab.url)
        while not page.execute_script("return window.lab.connected && window.lab.perAxis.length"):
            time.sleep(0.05)
        for line in SETUP:
            typed(page, line)
        choose_speed(page, "real")
        time.sleep(2.0)                                  # the pacing settles
        pids = {"simulator": lab.simulator_pid(), "server": lab.proc.pid}
        chromium = browser_pids()
        before = {k: cpu_seconds(p) for k, p in pids.items()}
        chromium_before = sum(cpu_seconds(p) for p in chromium)
        frames_before, wall = page.execute_script("return window.lab.frames"), time.monotonic()
        sim_before = status(page)["time"]
        time.sleep(WINDOW_S)
        wall = time.monotonic() - wall
        real = {k: (cpu_seconds(p) - before[k]) / wall for k, p in pids.items()}
        real["chromium"] = (sum(cpu_seconds(p) for p in chromium) - chromium_before) / wall
        real["pace"] = (status(page)["time"] - sim_before) / wall
        real["fps"] = (page.execute_script("return window.lab.frames") - frames_before) / wall
        choose_speed(page, "full")
        time.sleep(1.0)
        t0, w0, c0 = status(page)["time"], time.monotonic(), cpu_seconds(pids["simulator"])
        time.sleep(WINDOW_S)
        instructions = (status(page)["time"] - t0) * RATE
        full = (instructions / (time.monotonic() - w0),
                instructions / (cpu_seconds(pids["simulator"]) - c0))
        page.find_element("css selector", "#terminal textarea").send_keys("BYE\n")
        lab.proc.wait(timeout=60)
    finally:
        page.quit()
        lab.stop()
    return real, full


def run_alone(tmp, instructions, extra=""):
    """build/pdp11, no lab, the set-up typed, `instructions` run: wall and CPU seconds."""
    disk = Path(tmp) / "alone.dsk"
    shutil.copyfile(ROOT / "build" / "robot.dsk", disk)
    script = f"attach rl0 {disk}\n{extra}load {KERNEL}\nstep {instructions}\n"
    start, cpu = time.monotonic(), resource.getrusage(resource.RUSAGE_CHILDREN)
    out = simh.run(script, keyboard="\r".join(SETUP) + "\r", timeout=900)
    wall = time.monotonic() - start
    used = resource.getrusage(resource.RUSAGE_CHILDREN)
    if not re.search(r"Abs\.Move\s+ok", out):
        raise RuntimeError("the run without the lab did not take the move:\n" + out[-500:])
    return wall, used.ru_utime + used.ru_stime - cpu.ru_utime - cpu.ru_stime


def measure_alone(tmp, extra="", repeats=3):
    """The rate of build/pdp11 alone over the same phase as the lab's (the servo
    hunting after the move): a run to the end of the set-up, subtracted from a
    run BASELINE_INSTRUCTIONS longer; per wall and per CPU second, the best of
    `repeats` (the host's other load only ever slows a run down)."""
    best_wall = best_cpu = 0.0
    for _ in range(repeats):
        wall0, cpu0 = run_alone(tmp, SETUP_INSTRUCTIONS, extra)
        wall1, cpu1 = run_alone(tmp, SETUP_INSTRUCTIONS + BASELINE_INSTRUCTIONS, extra)
        best_wall = max(best_wall, BASELINE_INSTRUCTIONS / (wall1 - wall0))
        best_cpu = max(best_cpu, BASELINE_INSTRUCTIONS / (cpu1 - cpu0))
    return best_wall, best_cpu


def main():
    if not have_browser():
        print("bench-lab: skipped: Debian's chromium and chromium-driver are not installed "
              "(make lab-browser)")
        return 0
    with tempfile.TemporaryDirectory(prefix="bench-lab-") as tmp:
        real, (lab_rate, lab_cpu) = measure_lab(tmp)
        alone_rate, alone_cpu = measure_alone(tmp)
        _, device_cpu = measure_alone(tmp, "attach lab /dev/null\n")
    share = real["simulator"] + real["server"]
    print(f"lab at real pace, page open ({WINDOW_S:.0f} s, servo hunting): simulator "
          f"{100 * real['simulator']:.1f} % + server {100 * real['server']:.1f} % = "
          f"{100 * share:.1f} % of one core (goal < 15 %); headless Chromium "
          f"{100 * real['chromium']:.1f} %; pace {real['pace']:.3f} simulated s per s; "
          f"page {real['fps']:.0f} frames/s")
    print(f"full speed: with the lab and the page {lab_rate / 1e6:.2f} M instructions/s, "
          f"build/pdp11 alone {alone_rate / 1e6:.2f} M/s: "
          f"{100 * (1 - lab_rate / alone_rate):+.1f} % lower (goal <= 10 %); per CPU second "
          f"of the simulator (what the host's other load does not move): "
          f"{lab_cpu / 1e6:.2f} against {alone_cpu / 1e6:.2f} M, "
          f"{100 * (1 - lab_cpu / alone_cpu):+.1f} %")
    print(f"the LAB device alone (attached, full speed, its rows written), same conditions: "
          f"{device_cpu / 1e6:.2f} against {alone_cpu / 1e6:.2f} M instructions per CPU second, "
          f"{100 * (1 - device_cpu / alone_cpu):+.1f} % (best of three each; on a shared host "
          "runs of the same work differ by 10 % or more)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
