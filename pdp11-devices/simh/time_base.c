/* time_base.c: simulated time, shared by every device of the project (robot.h).

   Simulated seconds = executed instructions / RATE, RATE instructions per
   simulated second (default 300000, the KDF11-A's typical speed; SET CLK
   RATE=n, kw11l.c, changes it). A change keeps time continuous: the base is
   moved to the present, and every device that registered with
   robot_on_rate_change is told, before (still in the old time: the plant
   integrates up to now) and after (its pending events keep their simulated
   times: robot_rescale). Nothing here reads the host's clock.

   robot_share(n, &acc) gives the intervals, in instructions, of an exact
   series of n events per simulated second: event k comes after floor(k *
   RATE / n) instructions, whatever the remainders. This file calls no device:
   the devices call it, so none of them depends on another for the time. */
#include "robot.h"

#define HOOKS_MAX 8

int32 robot_rate = 300000;
static double base_time_s, base_instr;  /* time base, moved when RATE changes */
static robot_rate_hook before_hooks[HOOKS_MAX], after_hooks[HOOKS_MAX];
static int hooks;

double robot_time (void)
{
    return base_time_s + (sim_gtime () - base_instr) / (double) robot_rate;
}

void robot_rescale (UNIT *uptr, int32 old_rate)
{
    int32 left = sim_is_active (uptr);          /* instructions to go, plus one */
    if (left > 0) {
        double t = (double) (left - 1) * robot_rate / old_rate;
        sim_cancel (uptr);
        sim_activate (uptr, (int32) (t + 0.5));
    }
}

int32 robot_share (int32 per_second, int32 *acc)
{
    int32 n;
    *acc += robot_rate;
    n = *acc / per_second;
    *acc -= n * per_second;
    return n > 0 ? n : 1;
}

void robot_on_rate_change (robot_rate_hook before, robot_rate_hook after)
{
    if (hooks == HOOKS_MAX) {
        fprintf (stderr, "time_base: too many rate hooks (HOOKS_MAX)\n");
        exit (1);
    }
    before_hooks[hooks] = before;
    after_hooks[hooks++] = after;
}

void robot_set_rate (int32 rate)
{
    int32 old = robot_rate;
    for (int i = 0; i < hooks; i++)
        if (before_hooks[i]) before_hooks[i] (old);
    base_time_s = robot_time ();
    base_instr = sim_gtime ();
    robot_rate = rate;
    for (int i = 0; i < hooks; i++)
        if (after_hooks[i]) after_hooks[i] (old);
}
