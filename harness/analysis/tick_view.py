"""One 60 Hz tick at a time: the 1983 servo's arrays, the counters and the DACs.

After the set-up lines (default: load the blocks and Set.Up.Robot) the arrays'
addresses are read (the FORTH's ' and >BODY); then the lines to watch are typed
(default: a move of x by one inch, which returns at once) and the machine stops at the entry of the code vector 100 holds (Interrupt.Servo)
each time the clock interrupts; between two stops exactly one tick of simulated
time has passed and the servo has run once. Simulated time stands still while
the table is read, so the plant waits too: a class can walk the servo tick by
tick. Per axis: Desire.Pos, the counter (what INBUF returns now), Velocity,
0-Vel, State, Command.Status (the appendix's arrays, block 1000) and the DAC
code the servo last wrote."""
from harness.machine.plant_rows import AXES
from harness.machine.robot import Robot, numbers

ARRAYS = ("Desire.Pos", "Velocity", "0-Vel", "State", "Command.Status")
SETUP = ("1000 LOAD", "Set.Up.Robot")
WATCH = ("800 0 0 0 Abs.Move",)
VECTOR = 0o100


class TickView:
    def __init__(self, robot, setup=SETUP, watch=WATCH):
        self.robot = robot
        for line in setup:
            robot.send(line)
        where = numbers(robot.send(" ".join(f"' {a} >BODY U." for a in ARRAYS)))
        self.arrays = dict(zip(ARRAYS, where))
        for line in watch:
            robot.send(line)
        self.servo = robot.examine(VECTOR)

    def step(self):
        """Run to the next tick's servo entry; the table (a string)."""
        answer = self.robot.run_to(self.servo, limit=1.0)
        if not answer.stopped.startswith("Breakpoint"):
            raise RuntimeError("the servo did not run within a simulated second: is it "
                               f"installed (Set.Up.Robot)? {answer.stopped}")
        return self.table()

    def cells(self, array):
        return [_signed(self.robot.examine(self.arrays[array] + 2 * i)) for i in range(len(AXES))]

    def table(self):
        clock = self.robot.simh("show clk")
        plant = self.robot.plant()
        ticks = clock.split(" ticks")[0].split()[-1]
        time_s = clock.split("time=")[1].split("s")[0]
        columns = {a: self.cells(a) for a in ARRAYS}
        head = (f"tick {ticks}, t = {time_s} s\n"
                f"axis {'Desire.Pos':>10} {'counter':>8} {'Velocity':>8} {'0-Vel':>6} "
                f"{'State':>5} {'Command.Status':>14} {'DAC':>5}")
        rows = [f"  {a}  {columns['Desire.Pos'][i]:10d} {plant[a]['counter']:8d} "
                f"{columns['Velocity'][i]:8d} {columns['0-Vel'][i]:6d} "
                f"{columns['State'][i]:5d} {columns['Command.Status'][i]:14d} "
                f"{plant[a]['dac']:5d}" for i, a in enumerate(AXES)]
        return "\n".join([head] + rows)


def _signed(word):
    return word - 0o200000 if word & 0o100000 else word


def open_view(disk, setup=SETUP, watch=WATCH):
    """(robot, view): a Robot on `disk` (a copy of build/robot.dsk), set up."""
    robot = Robot(disk=disk)
    try:
        return robot, TickView(robot, setup, watch)
    except Exception:
        robot.close()
        raise
