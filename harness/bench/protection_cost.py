"""What issue 16's protection costs (make bench-forth, make bench-robot print it).

The figures before the protection were measured with the same benchmarks on the
kernel just before issue 16 (main at 14d598f: EXIT 2 instructions, no checks in
>R R> EXECUTE ! C!, no buffer checksums); the benchmarks measure the current
kernel and print the two side by side. Instruction counts repeat exactly; the
servo's share is its KDF11-A time per 60 Hz tick."""

BEFORE = {
    "sieve": 8_945_629,             # BYTE Sieve, 10 x 8190 flags
    "loop": 60_017,                 # 10 000 empty DO LOOP passes
    "fib": 601_998,                 # recursive Fibonacci of 20
    "interpret": 347_259,           # EVALUATE of 64 x '1 DROP'
    "load": 1_874_155,              # 1000 LOAD
    "servo idle": 157.8,            # Interrupt.Servo, instructions per tick, idle
    "servo move": 145.6,            # ... during a move
}


def cost(key, after, unit="instructions"):
    """One line: the figure before issue 16, now, and the change."""
    before = BEFORE[key]
    change = 100 * (after - before) / before
    fmt = "{:,.1f}" if isinstance(before, float) else "{:,}"
    return (f"  protection cost, {key}: {fmt.format(before)} -> {fmt.format(after)} "
            f"{unit} ({change:+.1f} %)")
