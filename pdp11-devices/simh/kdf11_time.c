/* kdf11_time.c: the KDF11-A's own instruction times as the time base
   (SET CLK TIMED; SET CLK NOTIMED goes back).

   Normally every instruction advances simulated time by one count and RATE
   counts make a simulated second (time_base.c; 300000, the KDF11-A's typical
   speed), so a MUL takes as long as a MOV R,R. Timed, each instruction
   advances time by its KDF11-A execution time (DEC's tables B-4..B-7, MMU
   off, as harness/analysis/kdf11.py prices them: the table kdf11_extra is
   generated from that file, build/gen/kdf11_extra.h), in units of 75 ns, of
   which every figure of the tables is a whole multiple; RATE becomes
   13333333 units a second (1/75 ns is 13333333.3: the second is 2.5e-8
   short). The KW11-L then ticks every real 1/60 s of an 11/23's time, and
   every device's time, the plant's trace, SHOW CLK's time, follow. Time
   spent in WAIT and on interrupt entries still passes one unit a host loop
   and nothing, as SIMH counts them; a scripted run skips WAITs to the next
   event, so that costs nothing there.

   SIMH's CPU loop has no hook for a per-instruction cost: the one line that
   adds it is pdp11_cpu_kdf11_time.patch, applied at build time to a copy of
   pdp11_cpu.c for build/pdp11-timed (mk/devices.mk); with the mode off it adds
   nothing to the count (tests/devices/test_kdf11_time.py runs a program on
   the stock and the patched CPU and compares), but its test costs every
   instruction (5 % on the Sieve), so build/pdp11 keeps SIMH's CPU and says
   so at SET CLK TIMED. */
#include "devices.h"
#include "kdf11_extra.h"                /* build/gen: const uint16 kdf11_extra[65536] */

#define TIMED_RATE 13333333             /* 75 ns units a second */

int32 kdf11_timed = 0;
static int32 rate_before;               /* RATE to return to at NOTIMED */
/* defined by the patch: absent (null) in a simulator whose CPU is SIMH's own */
extern const int32 kdf11_cpu_prices __attribute__ ((weak));

int kdf11_time_possible (void)
{
    return &kdf11_cpu_prices != NULL;
}

t_stat kdf11_time_set (int on)
{
    if (on && !kdf11_time_possible ()) {
        printf ("TIMED needs the CPU that prices instructions: build/pdp11-timed\n");
        return SCPE_NOFNC;
    }
    if (on == kdf11_timed)
        return SCPE_OK;
    if (on)
        rate_before = clock_rate;
    kdf11_timed = on;
    clock_set_rate (on ? TIMED_RATE : rate_before);   /* time stays continuous */
    return SCPE_OK;
}
