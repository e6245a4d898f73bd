"""make bench-lab (mk/lab.mk): what the lab bench costs (issue 11's goals).

1. Real pace, the page open in headless Chromium, the servo running (1000 LOAD,
   Set.Up.Robot, a move; the axes then hunt round their targets): the CPU time
   the simulator and the lab server take over WINDOW_S of wall time, as a share
   of one core (goal: under 15 %). Chromium's own share is printed apart.
2. Full speed: a compute-bound word (lab_workload.py: 30 million empty LOOPs,
   the servo interrupting at 60 Hz of simulated time) timed from the typed line
   to its ` ok`, in the lab with the page open and on build/pdp11 alone with the
   same kernel, disk and set-up; executed instructions per wall second and per
   CPU second of the simulator (goal: at most 10 % lower), the CPU the server and
   Chromium take meanwhile; and build/pdp11 with the LAB device attached
   (writing to /dev/null) against without: the device's own cost.
Figures depend on the host and on what else runs on it (this one's speed was
seen to drift by a fifth within a minute): each full-speed figure is printed as
the best of lab_workload.REPEATS runs and as the median of the rounds' pairs,
with their spread (paired.py); the goal is judged on the median.
"""
import tempfile
import time
from pathlib import Path

from harness.bench import lab_workload as workload
from harness.bench.paired import per_round
from harness.lab.launch import LabProcess, have_browser, headless_browser
from harness.machine.build import RATE

WINDOW_S = 10.0
DEVICE_ONLY = "attach lab /dev/null\nset lab speed=0\n"


def browser_pids(driver):
    """The chromium processes of this bench's own headless page: those under its
    chromedriver (other sessions' browsers on a shared host are not ours)."""
    parents = {}
    for stat in Path("/proc").glob("[0-9]*/stat"):
        try:
            text = stat.read_text()
        except OSError:
            continue
        parents[int(stat.parent.name)] = (int(text.rsplit(")", 1)[1].split()[1]), "(chromium" in text)
    ours, grew = {driver.service.process.pid}, True
    while grew:
        more = {pid for pid, (parent, _) in parents.items() if parent in ours} - ours
        ours |= more
        grew = bool(more)
    return sorted(pid for pid in ours if parents.get(pid, (0, False))[1])


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


def choose_state(page, state):
    """run or pause, by the page's Pause/Run button."""
    if status(page)["state"] != state:
        page.find_element("css selector", "#pause").click()
    while status(page)["state"] != state:
        time.sleep(0.05)


class Lab:
    """`python -m harness lab` with its page open in headless Chromium, the
    set-up typed and the word defined."""

    def __init__(self, tmp):
        self.process = LabProcess(tmp, speed="full")
        self.page = headless_browser()
        self.page.get(self.process.url)
        while not self.page.execute_script(
                "return window.lab.connected && window.lab.perAxis.length"):
            time.sleep(0.05)
        for line in workload.SETUP + (workload.DEFINE,):
            typed(self.page, line)
        self.server = {"server": [self.process.proc.pid], "chromium": browser_pids(self.page)}
        self.pids = {"simulator": [self.process.simulator_pid()], **self.server}

    def real_pace(self):
        """The shares of one core over WINDOW_S at real pace, the pace, the frame rate."""
        page = self.page
        choose_speed(page, "real")
        time.sleep(2.0)                                  # the pacing settles
        frames, sim_time = page.execute_script("return window.lab.frames"), status(page)["time"]
        run = workload.timed(self.pids, lambda: time.sleep(WINDOW_S))
        real = {name: run.share(name) for name in self.pids}
        real["pace"] = (status(page)["time"] - sim_time) / run.wall
        real["fps"] = (page.execute_script("return window.lab.frames") - frames) / run.wall
        return real

    def hold(self):
        """Paused: the simulator waits, the page gets nothing new to draw."""
        choose_state(self.page, "pause")

    def full_speed_run(self):
        choose_state(self.page, "run")
        choose_speed(self.page, "full")
        time.sleep(1.0)                                  # a few frames at full speed first
        return workload.page_run(self.page, self.pids)

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        try:
            choose_state(self.page, "run")
            self.page.find_element("css selector", "#terminal textarea").send_keys("BYE\n")
            self.process.proc.wait(timeout=60)
        finally:
            self.page.quit()
            self.process.stop()


def rates(instructions, runs):
    """Instructions per wall second and per CPU second of the simulator, each the
    best of the runs (the host's other load only ever slows a run down)."""
    return (instructions / min(r.wall for r in runs),
            instructions / min(r.cpu["simulator"] for r in runs))


def drop(lab, alone):
    return 100 * (1 - lab / alone)


def round_drops(runs, key, base="alone", other="lab"):
    """The rounds' drops of `other` against `base` (key: a Run's seconds, wall or
    the simulator's CPU; fewer seconds for the same instructions is faster):
    'median +4.2 % (-1.0 to +9.8)'."""
    median, low, high = per_round([key(r) for r in runs[base]], [key(r) for r in runs[other]])
    return f"median {drop(median, 1):+.1f} % ({drop(high, 1):+.1f} to {drop(low, 1):+.1f})"


def main():
    if not have_browser():
        print("bench-lab: skipped: Debian's chromium and chromium-driver are not installed "
              "(make lab-browser)")
        return 0
    runs = {"lab": [], "alone": [], "device": []}
    with tempfile.TemporaryDirectory(prefix="bench-lab-") as tmp:
        instructions = workload.instructions(tmp)
        with Lab(tmp) as lab, workload.Bare(tmp, "alone") as alone, \
                workload.Bare(tmp, "device", DEVICE_ONLY) as device:
            real = lab.real_pace()
            for _ in range(workload.REPEATS):          # interleaved: the host's load
                lab.hold()                             # moves all three alike
                runs["alone"].append(alone.run(lab.server))
                runs["device"].append(device.run(lab.server))
                runs["lab"].append(lab.full_speed_run())
    print_real_pace(real)
    print_full_speed(instructions, runs)
    return 0


def print_real_pace(real):
    share = real["simulator"] + real["server"]
    print(f"lab at real pace, page open ({WINDOW_S:.0f} s, servo hunting): simulator "
          f"{100 * real['simulator']:.1f} % + server {100 * real['server']:.1f} % = "
          f"{100 * share:.1f} % of one core (goal < 15 %); headless Chromium "
          f"{100 * real['chromium']:.1f} %; pace {real['pace']:.3f} simulated s per s; "
          f"page {real['fps']:.0f} frames/s")


def print_full_speed(instructions, runs):
    lab, alone = runs["lab"], runs["alone"]
    lab_wall, lab_cpu = rates(instructions, lab)
    alone_wall, alone_cpu = rates(instructions, alone)
    device_wall, device_cpu = rates(instructions, runs["device"])
    with_lab, without = workload.best(lab), workload.best(alone)
    print(f"full speed, {workload.WORK!r} ({instructions / 1e6:.1f} M instructions, "
          f"{instructions / RATE:.0f} simulated s), typed to ok, best of {len(lab)} "
          "(interleaved: alone, device, lab):")
    wall, cpu = (lambda r: r.wall), (lambda r: r.cpu["simulator"])
    print(f"  per wall second: lab + page {lab_wall / 1e6:.1f} M/s, build/pdp11 alone "
          f"{alone_wall / 1e6:.1f} M/s: best against best {drop(lab_wall, alone_wall):+.1f} %, "
          f"round by round {round_drops(runs, wall)} (goal <= 10 %); "
          f"runs {fmt(r.wall for r in lab)} s against {fmt(r.wall for r in alone)} s")
    print(f"  per CPU second of the simulator: {lab_cpu / 1e6:.1f} against "
          f"{alone_cpu / 1e6:.1f} M: best against best {drop(lab_cpu, alone_cpu):+.1f} %, "
          f"round by round {round_drops(runs, cpu)}")
    print(f"  % of one core meanwhile (fastest runs): lab: simulator "
          f"{100 * with_lab.share('simulator'):.0f}, server {100 * with_lab.share('server'):.0f}, "
          f"Chromium {100 * with_lab.share('chromium'):.0f}; alone (the lab paused): simulator "
          f"{100 * without.share('simulator'):.0f}, server {100 * without.share('server'):.0f}, "
          f"Chromium {100 * without.share('chromium'):.0f}")
    print(f"  the LAB device alone (attached, rows to /dev/null, no server or page): "
          f"{device_wall / 1e6:.1f} M/s, {device_cpu / 1e6:.1f} M per CPU second: "
          f"{drop(device_wall, alone_wall):+.1f} % and {drop(device_cpu, alone_cpu):+.1f} %; "
          f"round by round {round_drops(runs, wall, other='device')} and "
          f"{round_drops(runs, cpu, other='device')}")


def fmt(values):
    return "/".join(f"{v:.2f}" for v in values)


if __name__ == "__main__":
    raise SystemExit(main())
