/* wall_pacer.c: keeping simulated time in step with the host's clock, for the
   devices that are asked to (the KW11-L's SET CLK REALTIME and SET CPU IDLE,
   kw11l.c; the LAB device's SPEED, lab.c). The only code of the project that
   reads the host's clock; what it decides is only when the host sleeps, never
   what happens in simulated time.

   A pacer holds a reference point (host seconds, simulated seconds). At each
   call it sleeps while simulated time, scaled by `speed`, is ahead of the host
   since that point. More than `slack_s` behind (the machine was stopped at
   sim>, or the host was slow) it drops the point and takes a new one, so no
   burst follows to catch up. wall_pacer_drop makes the next call take a new
   point (after a pause, or when pacing stops). */
#include "devices.h"
#include <time.h>

#define SLEEP_MIN_S 0.001               /* less ahead than this: not worth a sleep */
#define SLEEP_MAX_S 1.0                 /* one sleep at the most, so ^E stays quick */

double wall_seconds (void)
{
    struct timespec ts;
    clock_gettime (CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + ts.tv_nsec * 1e-9;
}

void wall_pacer_drop (wall_pacer *p)
{
    p->held = 0;
}

void wall_pacer_pace (wall_pacer *p, double speed, double slack_s)
{
    double now = wall_seconds (), ahead;
    if (p->held) {
        ahead = p->wall0 + (clock_time () - p->sim0) / speed - now;
        if (ahead >= SLEEP_MIN_S) {
            double s = ahead > SLEEP_MAX_S ? SLEEP_MAX_S : ahead;
            struct timespec ts = { (time_t) s, (long) ((s - (time_t) s) * 1e9) };
            nanosleep (&ts, NULL);
            return;
        }
        if (ahead > -slack_s)
            return;
    }
    p->held = 1;                                  /* a new reference point: now */
    p->wall0 = now;
    p->sim0 = clock_time ();
}
