/* gripper.c: stepper-driven two-fingered gripper mechanics (see gripper.h). */
#include "gripper.h"

#include <math.h>
#include <stddef.h>

void gripper_init (gripper *g)
{
    g->steps = GRIPPER_MAX_STEPS;
    g->object_steps = 0;
    g->object_in = 0;
    g->pullout = GRIPPER_PULLOUT;
    g->last_step = -INFINITY;
    g->step_line = g->dir_line = 0;
    g->pulses = g->missed = g->blocked = 0;
    g->part = g->part_steps = 0;
    g->part_at[0] = g->part_at[1] = g->part_at[2] = 0;
}

static int one_step (gripper *g, double t)
{
    int closing = g->dir_line != 0;
    int next = g->steps + (closing ? -1 : 1);
    /* a small tolerance: steps exactly 1/pullout apart are followed */
    if (t - g->last_step < (1.0 - 1e-9) / g->pullout)
        return 0;
    if (next < 0 || next > GRIPPER_MAX_STEPS || (closing && next < g->object_steps))
        return -1;
    g->steps = next;
    g->last_step = t;
    return 1;
}

void gripper_lines (gripper *g, double t, int step, int dir)
{
    int rising = step && !g->step_line;
    g->dir_line = dir != 0;
    g->step_line = step != 0;
    if (!rising)
        return;
    g->pulses++;
    switch (one_step (g, t)) {
    case 0: g->missed++; break;
    case -1: g->blocked++; break;
    default: break;
    }
}

int gripper_contact (const gripper *g)
{
    return g->object_steps > 0 && g->steps <= g->object_steps;
}

double gripper_opening (const gripper *g)
{
    return (double) g->steps / GRIPPER_STEPS_PER_INCH;
}

const char *gripper_set_object (gripper *g, double width)
{
    if (!isfinite (width) || width < 0 || width > (double) GRIPPER_MAX_STEPS / GRIPPER_STEPS_PER_INCH)
        return "OBJECT is a width in inches, 0 (none) to 2";
    /* the object's width rounded up to whole steps: the fingers stop there */
    int s = (int) ceil (width * GRIPPER_STEPS_PER_INCH - 1e-9);
    if (s > g->steps && !g->part)
        return "the fingers are closer than that: open them before placing the object";
    if (g->part && gripper_contact (g))
        return "the fingers hold the part: open them first";
    g->object_steps = g->part ? 0 : s;
    g->part_steps = s;
    g->object_in = width;
    if (s == 0)
        g->part = 0;                               /* no object at all */
    return NULL;
}

const char *gripper_place_part (gripper *g, int axis, double where)
{
    if (axis < 0 || axis > 2 || !isfinite (where) || fabs (where) > 100000)
        return "a part's position is x, y or z in counts";
    if (g->object_in <= 0)
        return "give the part's width first (OBJECT=width)";
    if (gripper_contact (g))
        return "the fingers hold the part: open them first";
    g->part = 1;
    g->part_at[axis] = where;
    g->object_steps = 0;                           /* until the hand is there */
    return NULL;
}

void gripper_hand_at (gripper *g, const double hand[3])
{
    int at = 1;
    if (!g->part)
        return;
    if (gripper_contact (g)) {                     /* held: it goes with the hand */
        for (int i = 0; i < 3; i++)
            g->part_at[i] = hand[i];
        return;
    }
    for (int i = 0; i < 3; i++)
        at &= fabs (hand[i] - g->part_at[i]) <= GRIPPER_CAPTURE;
    g->object_steps = at && g->steps > g->part_steps ? g->part_steps : 0;
}

const char *gripper_set_pullout (gripper *g, double rate)
{
    if (!isfinite (rate) || rate <= 0 || rate > 100000)
        return "PULLOUT is a rate in steps per second, above 0 and at most 100000";
    g->pullout = rate;
    return NULL;
}

const char *gripper_set_opening (gripper *g, double opening)
{
    if (!isfinite (opening) || opening < 0 || opening > (double) GRIPPER_MAX_STEPS / GRIPPER_STEPS_PER_INCH)
        return "OPENING is in inches, 0 to 2";
    int s = (int) lround (opening * GRIPPER_STEPS_PER_INCH);
    if (s < g->object_steps || (g->part && gripper_contact (g)))
        return "the object is wider than that: take it out first (OBJECT=0)";
    g->steps = s;
    return NULL;
}
