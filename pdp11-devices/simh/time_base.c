/* time_base.c: simulated time, shared by every device of the project (devices.h).

   Simulated seconds = executed instructions / RATE, RATE instructions per
   simulated second (default 300000, the KDF11-A's typical speed; SET CLK
   RATE=n, kw11l.c, changes it). A change keeps time continuous: the base is
   moved to the present, and every device that registered with
   clock_on_rate_change is told, before (still in the old time: the plant
   integrates up to now) and after (its pending events keep their simulated
   times: clock_rescale). Nothing here reads the host's clock.

   clock_share(n, &acc) gives the intervals, in instructions, of an exact
   series of n events per simulated second: event k comes after floor(k *
   RATE / n) instructions, whatever the remainders. This file calls no device:
   the devices call it, so none of them depends on another for the time.

   A clock_series schedules each event from its predecessor's due time, not
   from when that one ran. By the count nothing runs late: an event's count
   ends exactly at an instruction. Timed (SET CLK TIMED, kdf11_time.c) an
   instruction takes many units, so an event runs after the instruction that
   crosses its time, late by what is left of it, and SIMH's queue, which keeps
   each event's time as a delay from the one before, hands that lateness on to
   every event behind it: measured, the KW11-L lost a tick in 4.35 s of `1000
   LOAD` (0.4 %) until its series counted from due times. */
#include "devices.h"

#define HOOKS_MAX 8

int32 clock_rate = 300000;
static double base_time_s, base_instr;  /* time base, moved when RATE changes */
static clock_rate_hook before_hooks[HOOKS_MAX], after_hooks[HOOKS_MAX];
static int hooks;

double clock_time (void)
{
    return base_time_s + (sim_gtime () - base_instr) / (double) clock_rate;
}

void clock_rescale (UNIT *uptr, int32 old_rate)
{
    int32 left = sim_is_active (uptr);          /* instructions to go, plus one */
    if (left > 0) {
        double t = (double) (left - 1) * clock_rate / old_rate;
        sim_cancel (uptr);
        sim_activate (uptr, (int32) (t + 0.5));
    }
}

int32 clock_share (int32 per_second, int32 *acc)
{
    int32 n;
    *acc += clock_rate;
    n = *acc / per_second;
    *acc -= n * per_second;
    return n > 0 ? n : 1;
}

void clock_series_start (clock_series *s)
{
    s->acc = 0;
    s->due = sim_gtime ();
}

void clock_series_activate (UNIT *uptr, clock_series *s, int32 n)
{
    double now = sim_gtime (), left;
    s->due += n;
    left = s->due - now;
    if (left < 1) {                             /* never before the next instruction */
        s->due = now + 1;
        left = 1;
    }
    sim_activate (uptr, (int32) left);
}

void clock_series_next (UNIT *uptr, clock_series *s, int32 per_second)
{
    clock_series_activate (uptr, s, clock_share (per_second, &s->acc));
}

void clock_series_rescale (UNIT *uptr, clock_series *s, int32 old_rate)
{
    int32 left;
    clock_rescale (uptr, old_rate);
    left = sim_is_active (uptr);                /* instructions to go, plus one */
    s->acc = 0;
    s->due = sim_gtime () + (left > 0 ? left - 1 : 0);
}

void clock_on_rate_change (clock_rate_hook before, clock_rate_hook after)
{
    if (hooks == HOOKS_MAX) {
        fprintf (stderr, "time_base: too many rate hooks (HOOKS_MAX)\n");
        exit (1);
    }
    before_hooks[hooks] = before;
    after_hooks[hooks++] = after;
}

void clock_set_rate (int32 rate)
{
    int32 old = clock_rate;
    for (int i = 0; i < hooks; i++)
        if (before_hooks[i]) before_hooks[i] (old);
    base_time_s = clock_time ();
    base_instr = sim_gtime ();
    clock_rate = rate;
    for (int i = 0; i < hooks; i++)
        if (after_hooks[i]) after_hooks[i] (old);
}
