/* rack_hint.c: one line at the console when the servo commands a motion that the
   switched-off amplifier rack cannot give (SET PLANT HINT=ON; make run's
   console sets it, harness/machine/console_session.py; the lab has its own,
   harness/lab/rack_hint.py).

   The interactive console boots with the rack off (nothing drifts while the
   blocks load). A move typed before it is switched on sets Command.Status and
   the servo writes the move's velocity to the DACs, but no axis moves, so
   Stop? never clears it and Move.Complete? waits for ever with nothing said.
   The blocks stay as printed; the plant notices instead, at the DAC writes:
   an axis commanded at least HINT_CODES codes away from its zero (2048 plus
   its amplifier's offset: the servo's 0-Vel when it holds still) for
   HINT_AFTER_S simulated seconds with the rack off gets one line, once until
   the commands come back to rest or the rack is switched on. A default move
   commands MaxVel = 300 codes; a still servo a few. Nothing in the machine
   changes: the line is printed between two instructions, from the plant's
   state at a DAC write, at the same instruction on every run. */
#include "devices.h"

#include <math.h>

#define HINT_CODES   100.0              /* codes from the axis's zero: commanding motion */
#define HINT_AFTER_S 2.0                /* simulated seconds before the line */

static int enabled;
static double since[PLANT_AXES] = { -1, -1, -1, -1 };   /* when the axis's command began */
static int said;

static void rest (void)
{
    for (int i = 0; i < PLANT_AXES; i++)
        since[i] = -1;
    said = 0;
}

void rack_hint_enable (int on)
{
    enabled = on;
    rest ();
}

/* At a DAC write of `code` on `axis`: `powered` the rack's switch, `from_zero` the
   code's distance from the axis's zero (its amplifier's offset included); the
   plant device passes both, so this file needs nothing of it. */
void rack_hint_dac (int axis, int code, int powered, double from_zero)
{
    static const char names[] = "XYZT";
    int active = 0;
    if (!enabled || powered) {
        rest ();
        return;
    }
    if (fabs (from_zero) < HINT_CODES)
        since[axis] = -1;
    else if (since[axis] < 0)
        since[axis] = clock_time ();
    for (int i = 0; i < PLANT_AXES; i++)
        active |= since[i] >= 0;
    if (!active)
        said = 0;                       /* back at rest: a later move may be told again */
    else if (!said && since[axis] >= 0 && clock_time () - since[axis] >= HINT_AFTER_S) {
        said = 1;
        printf ("\r\n[plant] The amplifier rack is OFF: the servo has commanded axis %c to move "
                "for %.0f s (DAC %d) but nothing moves, so this move never completes "
                "(Move.Complete? waits for ever). ^C stops the wait; ^E, SET PLANT POWER=ON, "
                "CONT switches the rack on.\r\n", names[axis], HINT_AFTER_S, code);
        fflush (stdout);
    }
}
