/* gripper.h: the robot's two-fingered gripper, driven by a stepper motor
   (the project's continuation of the paper, docs/continuation.md).

   Pure, deterministic mechanics with no SIMH types, tested alone
   (gripper_test.c). Time in simulated seconds, the opening in motor steps
   (GRIPPER_STEPS_PER_INCH per inch of opening between the fingers).

   The stepper translator takes two lines: STEP (a rising edge asks for one
   step) and DIR (1 = close, 0 = open). A requested step is
     - missed when it comes sooner than 1/pullout s after the last step the
       rotor took (the rotor cannot follow: above the pull-out rate),
     - blocked when the fingers are on a stop (0 or 2 inches) or, closing,
       on the object placed between them (the motor stalls, the fingers
       stay),
     - otherwise taken: the opening changes by one step.
   The finger pads carry a contact switch: closed while the fingers touch an
   object (opening within one step of its width); the closed stop keeps the
   pads apart, so closing on nothing never closes it.

   The object is either simply between the fingers wherever the hand is
   (gripper_set_object alone), or a part placed in the workspace
   (gripper_place_part): then it is between the fingers only while the hand
   is within GRIPPER_CAPTURE counts of it on x, y and z and the fingers are
   open wider than it; while the fingers grip it (contact) it moves with the
   hand, and it stays where the fingers let it go; fingers narrower than the
   part when the hand comes (or opening from inside it) never take hold of
   it. Positions are in the axes' counter counts, as the FORTH sees them
   (gripper_hand_at gives the hand's). */
#ifndef GRIPPER_H
#define GRIPPER_H

#define GRIPPER_STEPS_PER_INCH 100
#define GRIPPER_MAX_STEPS      200         /* fully open: 2 inches */
#define GRIPPER_PULLOUT        300.0       /* default pull-out rate, steps/s */

typedef struct {
    int steps;                 /* opening, steps: 0 closed .. GRIPPER_MAX_STEPS */
    int object_steps;          /* 0: nothing between the fingers */
    double object_in;          /* the object's width as set, inches (0: none) */
    double pullout;            /* steps/s the rotor can follow */
    double last_step;          /* when the rotor last took a step */
    int step_line, dir_line;
    unsigned long pulses, missed, blocked;   /* requested; too fast; on a stop/object */
    int part;                  /* the object is a part placed in the workspace */
    int part_steps;            /* its width, steps */
    double part_at[3];         /* its x y z, counts (held: where the hand is) */
} gripper;

#define GRIPPER_CAPTURE 80.0               /* counts (0.1 in): the hand is at the part */

void gripper_init (gripper *g);            /* power-up: fully open, no object */
/* The translator's lines at time t; a rising STEP edge asks for one step. */
void gripper_lines (gripper *g, double t, int step, int dir);
int gripper_contact (const gripper *g);    /* the pads' contact switch */
double gripper_opening (const gripper *g); /* inches */
/* Each returns NULL when accepted, else why not (the gripper unchanged). */
const char *gripper_set_object (gripper *g, double width_in);
const char *gripper_set_pullout (gripper *g, double steps_per_s);
const char *gripper_set_opening (gripper *g, double opening_in);
/* A part of the object's width (gripper_set_object first) at x y z, counts;
   the object is no longer simply between the fingers. */
const char *gripper_place_part (gripper *g, int axis, double where);
/* Where the hand is (x y z, counts): a part between the fingers or carried. */
void gripper_hand_at (gripper *g, const double hand[3]);

#endif
