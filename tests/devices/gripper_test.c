/* gripper_test.c: the gripper mechanics (gripper.c) tested alone. Prints one
   line per check; exits non-zero if any fails. Built by make as
   build/gripper_test, run from tests/devices/test_gripper_unit.py. */
#include "gripper.h"

#include <stdio.h>
#include <string.h>

static int failures, checks;

static void check (int ok, const char *what, double got, double want)
{
    checks++;
    if (!ok) failures++;
    printf ("%s %s: got %g, expected %g\n", ok ? "ok  " : "FAIL", what, got, want);
}

/* n step pulses, one every `interval` s from t0, in direction dir; returns the end time */
static double pulses (gripper *g, double t0, int n, double interval, int dir)
{
    double t = t0;
    for (int k = 0; k < n; k++, t += interval) {
        gripper_lines (g, t, 0, dir);
        gripper_lines (g, t + interval / 2, 1, dir);
    }
    gripper_lines (g, t, 0, dir);
    return t;
}

static void test_steps_below_pullout (void)
{
    gripper g;
    gripper_init (&g);
    check (g.steps == 200 && gripper_opening (&g) == 2.0, "power-up: fully open", gripper_opening (&g), 2.0);
    pulses (&g, 0, 50, 1 / 60.0, 1);
    check (g.steps == 150 && g.missed == 0, "50 steps at 60/s close by 0.5 in", gripper_opening (&g), 1.5);
    pulses (&g, 1, 20, 1 / 60.0, 0);
    check (g.steps == 170, "20 steps open again", g.steps, 170);
    /* DIR changes and falling edges are not steps */
    gripper_lines (&g, 2, 0, 1); gripper_lines (&g, 2.1, 0, 0);
    check (g.pulses == 70 && g.steps == 170, "no edge, no step", g.pulses, 70);
}

static void test_missed_above_pullout (void)
{
    gripper g;
    gripper_init (&g);
    /* back-to-back pulses 20 us apart: only the first of each burst is followed */
    double t = 0;
    for (int tick = 0; tick < 30; tick++, t += 1 / 60.0)
        pulses (&g, t, 3, 20e-6, 1);
    check (g.steps == 170 && g.missed == 60, "3 pulses per tick, bursts: 1 taken, 2 missed",
           g.missed, 60);
    /* a slow motor: pull-out 40 steps/s, driven at 60/s, takes every other step */
    gripper_init (&g);
    int accepted = gripper_set_pullout (&g, 40) == NULL;
    check (accepted && g.pullout == 40, "PULLOUT=40 accepted", g.pullout, 40);
    pulses (&g, 0, 60, 1 / 60.0, 1);
    check (g.steps == 170 && g.missed == 30, "60/s against pull-out 40/s: half missed",
           g.steps, 170);
}

static void test_stops_and_object (void)
{
    gripper g;
    gripper_init (&g);
    pulses (&g, 0, 10, 0.01, 0);
    check (g.steps == 200 && g.blocked == 10, "opening on the open stop: blocked", g.blocked, 10);
    pulses (&g, 1, 220, 0.01, 1);
    check (g.steps == 0 && g.blocked == 30 && !gripper_contact (&g),
           "closing on nothing: closed stop, no contact", g.steps, 0);
    pulses (&g, 5, 200, 0.01, 0);
    int placed = gripper_set_object (&g, 1.005) == NULL;
    check (placed && g.object_steps == 101,
           "a 1.005 in object stops the fingers at 101 steps", g.object_steps, 101);
    check (!gripper_contact (&g), "open: no contact", gripper_contact (&g), 0);
    pulses (&g, 8, 120, 0.01, 1);
    check (g.steps == 101 && gripper_contact (&g) && g.blocked == 30 + 21,
           "closing on the object: stops there, contact", g.steps, 101);
    pulses (&g, 10, 5, 0.01, 0);
    check (g.steps == 106 && !gripper_contact (&g), "opening releases", g.steps, 106);
}

static void test_bad_settings (void)
{
    gripper g;
    gripper_init (&g);
    pulses (&g, 0, 150, 0.01, 1);                 /* opening 0.5 in */
    gripper before = g;
    int rejected = gripper_set_object (&g, 1.0) && gripper_set_object (&g, -1) &&
        gripper_set_object (&g, 3) && gripper_set_pullout (&g, 0) &&
        gripper_set_pullout (&g, -5) && gripper_set_opening (&g, 2.5);
    check (rejected && memcmp (&g, &before, sizeof g) == 0,
           "bad settings rejected, gripper unchanged", rejected, 1);
    check (gripper_set_object (&g, 0.3) == NULL && gripper_set_opening (&g, 0.2) != NULL &&
           g.steps == 50, "OPENING narrower than the object refused", g.steps, 50);
}

/* A part in the workspace: between the fingers only at the hand, carried while
   gripped, left where the fingers let it go. */
static void test_part_in_the_workspace (void)
{
    gripper g;
    double away[3] = { 0, 0, 400 }, at_a[3] = { 830, 770, 400 }, b[3] = { 3200, 2400, 1600 };
    gripper_init (&g);
    int placed = gripper_set_object (&g, 1.0) == NULL && gripper_place_part (&g, 0, 800) == NULL &&
        gripper_place_part (&g, 1, 800) == NULL && gripper_place_part (&g, 2, 400) == NULL;
    gripper_hand_at (&g, away);
    pulses (&g, 0, 220, 0.01, 1);
    check (placed && g.steps == 0 && !gripper_contact (&g),
           "hand away from the part: the fingers close on nothing", g.steps, 0);
    pulses (&g, 3, 220, 0.01, 0);
    gripper_hand_at (&g, at_a);                 /* within 80 counts on each axis */
    pulses (&g, 6, 120, 0.01, 1);
    check (g.steps == 100 && gripper_contact (&g), "at the part: gripped at 1.00 in", g.steps, 100);
    gripper_hand_at (&g, b);
    check (g.part_at[0] == 3200 && g.part_at[2] == 1600, "carried with the hand", g.part_at[0], 3200);
    check (gripper_set_object (&g, 0.5) != NULL && gripper_place_part (&g, 0, 0) != NULL,
           "no moving or resizing a gripped part", g.part_at[0], 3200);
    pulses (&g, 9, 30, 0.01, 0);
    gripper_hand_at (&g, away);
    check (!gripper_contact (&g) && g.part_at[0] == 3200 && g.part_at[1] == 2400,
           "let go: it stays at B", g.part_at[1], 2400);
    check (gripper_place_part (&g, 3, 0) != NULL, "only x, y or z", 0, 0);
}

int main (void)
{
    test_steps_below_pullout ();
    test_missed_above_pullout ();
    test_stops_and_object ();
    test_bad_settings ();
    test_part_in_the_workspace ();
    printf ("%d checks, %d failed\n", checks, failures);
    return failures != 0;
}
