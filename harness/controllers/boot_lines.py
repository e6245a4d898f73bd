"""The lines each machine's console receives to start its part (the contract
between the FORTH side and the lock-step side of issue 21; the FORTH side owns
this file's content, docs/controllers.md says why these lines).

axis_boot_lines(axis) -> the lines typed at the 11/03 of `axis` (0 x .. 3 t)
MAIN_BOOT_LINES       -> the lines that give the 11/23 its words for the links
"""

AXIS_LINES = ("1080 LOAD", "{axis} Axis.Run")
MAIN_BOOT_LINES = ("1200 LOAD",)   # 1090-1096: issue 18's disassembler; 1100: the user's


def axis_boot_lines(axis):
    return [line.format(axis=axis) for line in AXIS_LINES]
